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

/// Hertz radius of a steel sphere R on a steel flat, a = (3PR/(4E*))^(1/3) (FORMULAS.md E).
pub fn hertz_radius(p: f64, r: f64) -> f64 {
    (3.0 * p * r * 2.0 * steel().normal_compliance() / 4.0).cbrt()
}

/// Hertz pressure of a steel sphere (R = 1) under `p` on a fixed lattice of `n` x `n` cells
/// of side `h` centred at the origin (zero outside the contact; sampled at the cell centres
/// and scaled so that the cell forces sum to `p`, as `ContactGrid::hertz_circle` does).
pub fn hertz_on_lattice(p: f64, n: usize, h: f64) -> Vec<f64> {
    let a = hertz_radius(p, 1.0);
    let half = n as f64 / 2.0;
    let mut pr = vec![0.0; n * n];
    for j in 0..n {
        for i in 0..n {
            let x = (i as f64 + 0.5 - half) * h;
            let y = (j as f64 + 0.5 - half) * h;
            pr[j * n + i] = (1.0 - (x * x + y * y) / (a * a)).max(0.0).sqrt();
        }
    }
    let sum: f64 = pr.iter().sum();
    pr.iter_mut().for_each(|v| *v *= p / (sum * h * h));
    pr
}

/// The whole `n` x `n` lattice of cells of side `h` centred at the origin, every cell an
/// element, with the pressure `pressure` (row by row).
pub fn centred_lattice(n: usize, h: f64, pressure: &[f64]) -> stickslip_lattice::ContactGrid {
    let half = n as f64 / 2.0;
    stickslip_lattice::ContactGrid::from_mask(
        h,
        h,
        (-half * h, -half * h),
        n,
        n,
        &vec![true; n * n],
        pressure,
    )
    .unwrap()
}
