//! Shared test helpers.

/// Tolerances of the tests, each with its reason.
#[allow(dead_code)]
pub mod tol {
    /// The battery's request: relative 1e-12, the project's target for quadrature.
    pub const BATTERY_REL: f64 = 1e-12;
    /// Gauss–Legendre nodes: a few ulps of 1 (measured worst 2.2e-16 up to n = 1000).
    pub const LEGENDRE_NODE_ABS: f64 = 4.0 * f64::EPSILON;
    /// Gauss–Legendre weights, absolute (the brief's target).
    pub const LEGENDRE_WEIGHT_ABS: f64 = 1e-15;
    /// Gauss–Legendre weights, relative: computed from the angle, so relative accuracy holds
    /// even at the ends; the length-n recurrence costs about sqrt(n) ulps in the interior
    /// (measured 1.25e-14 at n = 1000, 3.2e-15 at n = 100).
    pub const LEGENDRE_WEIGHT_REL: f64 = 2e-14;
    /// Gauss–Jacobi nodes: Golub–Welsch plus Newton polish, a few ulps of 1.
    pub const JACOBI_NODE_ABS: f64 = 8.0 * f64::EPSILON;
    /// Gauss–Jacobi weights, relative, scaled by 1/(1-|t|) at the node: they are evaluated at the
    /// rounded node, whose relative distance to the end is known only to eps/(1-|t|).
    pub const JACOBI_WEIGHT_REL: f64 = 1e-14;
    /// Exactness tests on monomials: a sum of O(n) terms of size O(1).
    pub const EXACTNESS_ABS: f64 = 1e-14;
    /// Smallest relative request the singular integrators must meet on `tight.csv`: their
    /// rounding floor is 10 eps = 2.2e-15 of sum |w f| per piece, so 1e-14 leaves room and
    /// 1e-15 (the `Tolerance` minimum) may honestly fail.
    pub const TIGHT_REACHABLE_REL: f64 = 1e-14;
}

/// Parse `tests/data/rules.csv`: (family, n, alpha, beta, index, node, weight).
#[allow(dead_code)]
pub fn rules_data() -> Vec<(String, usize, f64, f64, usize, f64, f64)> {
    let text = include_str!("../data/rules.csv");
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("family"))
        .map(|l| {
            let v: Vec<&str> = l.split(',').collect();
            (
                v[0].to_string(),
                v[1].parse().unwrap(),
                v[2].parse().unwrap(),
                v[3].parse().unwrap(),
                v[4].parse().unwrap(),
                v[5].parse().unwrap(),
                v[6].parse().unwrap(),
            )
        })
        .collect()
}
