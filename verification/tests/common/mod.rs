//! Tolerances of the verification tests, each with its reason.
#![allow(dead_code)]

/// Tolerances.
pub mod tol {
    /// FORMULAS.md quotes its recomputed values to 6-7 digits: agreement to half a unit of
    /// the 6th significant digit.
    pub const FORMULAS_DIGITS: f64 = 5e-6;
    /// Issue 5: Example 1 at 80 elements within 1.5 % of Mindlin (exact rectangle model).
    pub const EX1_COARSE: f64 = 0.015;
    /// Issue 5: twist within 1 % of Lubkin (448 elements).
    pub const TWIST: f64 = 0.01;
    /// Identities evaluated by two routes of quadrature (about 1e-13 each).
    pub const IDENTITY: f64 = 1e-9;
}
