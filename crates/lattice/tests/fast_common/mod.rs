//! Helpers and the tolerance of the FFT-operator tests.

use stickslip_halfspace::Material;

/// Tolerances, each with its reason.
pub mod tol {
    /// FFT product versus the dense influence matrix: both use the same kernel entries; the
    /// FFT adds about eps * log2(M) * (sum of |K|) relative to the largest displacement.
    pub const FFT_VS_DENSE: f64 = 1e-12;
}

/// Seed 002 steel (FORMULAS.md E): E = 30e6 psi, nu = 0.3.
pub fn steel() -> Material {
    Material::new(30e6, 0.3).unwrap()
}
