//! Helpers and the tolerance module of the fast-solver tests.
#![allow(dead_code)]

use stickslip_halfspace::Material;

/// Tolerances, each with its reason.
pub mod tol {
    /// FFT product versus the dense influence matrix: both use the same kernel entries; the
    /// FFT adds about eps * log2(M) * (sum of |K|) relative to the largest displacement.
    pub const FFT_VS_DENSE: f64 = 1e-12;
    /// Issue 6: relative complementarity residual on the 256 x 256 Mindlin case.
    pub const RESIDUAL: f64 = 1e-8;
    /// Optimality conditions of a converged fast solution (relative residual 1e-10 in the
    /// 2-norm over N elements): each element's violation relative to its scale, with room
    /// for the sqrt(N) between the 2-norm and the worst element.
    pub const OPTIMALITY: f64 = 1e-7;
    /// Issue 6: rigid shift within 0.5 % of Mindlin on 256 x 256.
    pub const SHIFT_MINDLIN: f64 = 0.005;
    /// Issue 6: fast solver (one-direction option) versus the LP on the same grid, relative
    /// to the largest element force; both solve the same discrete equations (the LP to about
    /// 1e-11 of its scaled tableau, the fast solver to its residual 1e-12).
    pub const VS_LP: f64 = 1e-6;
    /// Issue 5's twist criterion: M(c) within 1 % of Lubkin at the grid's stick radius;
    /// used here for the area-equivalent stick radius against Lubkin's c.
    pub const TWIST: f64 = 0.01;
}

/// Seed 002 steel (FORMULAS.md E): E = 30e6 psi, nu = 0.3.
pub fn steel() -> Material {
    Material::new(30e6, 0.3).unwrap()
}

/// Whether the slow cases should run.
pub fn extended() -> bool {
    std::env::var("STICKSLIP_EXTENDED").is_ok_and(|v| v == "1")
}
