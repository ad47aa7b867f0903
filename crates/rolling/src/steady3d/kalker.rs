//! Kalker's creepage coefficients $C_{11}, C_{22}, C_{23}$ of linear (no-slip) rolling theory,
//! as tabulated by Kalker (*Three-Dimensional Elastic Bodies in Rolling Contact*, Kluwer 1990,
//! Table E3; first in his 1967 thesis), for semi-axis ratios $a/b$ from 0.1 to 10 ($a$ along
//! the rolling direction) and $\nu = 0, 0.25, 0.5$.
//!
//! In the small-creepage limit the creep forces are (Kalker's normalisation, $G$ and $\nu$ the
//! combined constants of the two bodies, $1/G = \tfrac12(1/G_1 + 1/G_2)$,
//! $\nu/G = \tfrac12(\nu_1/G_1 + \nu_2/G_2)$)
//! $$F_x = -Gab\,C_{11}\,\xi,\qquad F_y = -Gab\,(C_{22}\,\eta + \sqrt{ab}\,C_{23}\,\phi).$$
//!
//! These numbers are a published table, the reference our exact steady-rolling solver is
//! checked against; FASTSIM uses them for its flexibilities, as Kalker's algorithm prescribes.
//! Between the tabulated ratios the coefficients are interpolated linearly in $a/b$, and in
//! $\nu$ by the quadratic through the three tabulated values.

use crate::error::{Error, Result};

/// The tabulated semi-axis ratios $a/b$: 0.1 … 1, then $1/0.9$ … $1/0.1$ (Kalker tabulates
/// $a/b$ below 1 and $b/a$ above).
pub const RATIOS: [f64; 19] = [
    0.1,
    0.2,
    0.3,
    0.4,
    0.5,
    0.6,
    0.7,
    0.8,
    0.9,
    1.0,
    1.0 / 0.9,
    1.0 / 0.8,
    1.0 / 0.7,
    1.0 / 0.6,
    1.0 / 0.5,
    1.0 / 0.4,
    1.0 / 0.3,
    1.0 / 0.2,
    1.0 / 0.1,
];

/// The tabulated Poisson ratios.
pub const POISSON: [f64; 3] = [0.0, 0.25, 0.5];

/// $C_{11}$ per Poisson ratio (rows) and semi-axis ratio (columns, [`RATIOS`]).
pub const C11: [[f64; 19]; 3] = [
    [
        2.51, 2.59, 2.68, 2.78, 2.88, 2.98, 3.09, 3.19, 3.29, 3.40, 3.51, 3.65, 3.82, 4.06, 4.37,
        4.84, 5.57, 6.96, 10.7,
    ],
    [
        3.31, 3.37, 3.44, 3.53, 3.62, 3.72, 3.81, 3.91, 4.01, 4.12, 4.22, 4.36, 4.54, 4.78, 5.10,
        5.57, 6.34, 7.78, 11.7,
    ],
    [
        4.85, 4.81, 4.80, 4.82, 4.83, 4.91, 4.97, 5.05, 5.12, 5.20, 5.30, 5.42, 5.58, 5.80, 6.11,
        6.57, 7.34, 8.82, 12.9,
    ],
];

/// $C_{22}$, laid out as [`C11`].
// Table entries, not approximations of pi.
#[allow(clippy::approx_constant)]
pub const C22: [[f64; 19]; 3] = [
    [
        2.51, 2.59, 2.68, 2.78, 2.88, 2.98, 3.09, 3.19, 3.29, 3.40, 3.51, 3.65, 3.82, 4.06, 4.37,
        4.84, 5.57, 6.96, 10.7,
    ],
    [
        2.52, 2.63, 2.75, 2.88, 3.01, 3.14, 3.28, 3.41, 3.54, 3.67, 3.81, 3.99, 4.21, 4.50, 4.90,
        5.48, 6.40, 8.14, 12.8,
    ],
    [
        2.53, 2.66, 2.81, 2.98, 3.14, 3.31, 3.48, 3.65, 3.82, 3.98, 4.16, 4.39, 4.67, 5.04, 5.56,
        6.31, 7.51, 9.79, 16.0,
    ],
];

/// $C_{23}$, laid out as [`C11`].
pub const C23: [[f64; 19]; 3] = [
    [
        0.334, 0.483, 0.607, 0.720, 0.827, 0.930, 1.03, 1.13, 1.23, 1.33, 1.44, 1.58, 1.76, 2.01,
        2.35, 2.88, 3.79, 5.72, 12.2,
    ],
    [
        0.473, 0.603, 0.715, 0.823, 0.929, 1.03, 1.14, 1.25, 1.36, 1.47, 1.59, 1.75, 1.95, 2.23,
        2.62, 3.24, 4.32, 6.63, 14.6,
    ],
    [
        0.731, 0.809, 0.889, 0.977, 1.07, 1.18, 1.29, 1.40, 1.51, 1.63, 1.77, 1.94, 2.18, 2.50,
        2.96, 3.70, 5.01, 7.89, 18.0,
    ],
];

/// Kalker's three coefficients at one semi-axis ratio and Poisson ratio.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coefficients {
    /// $C_{11}$ (longitudinal).
    pub c11: f64,
    /// $C_{22}$ (lateral).
    pub c22: f64,
    /// $C_{23}$ (lateral force from spin).
    pub c23: f64,
}

fn quadratic_in_nu(rows: &[[f64; 19]; 3], col: usize, nu: f64) -> f64 {
    let mut s = 0.0;
    for (i, (&xi, row)) in POISSON.iter().zip(rows).enumerate() {
        let mut w = 1.0;
        for (j, &xj) in POISSON.iter().enumerate() {
            if j != i {
                w *= (nu - xj) / (xi - xj);
            }
        }
        s += w * row[col];
    }
    s
}

/// The coefficients at `a_over_b` in [0.1, 10] and `nu` in [0, 0.5], interpolated as the
/// module says.
///
/// # Errors
/// [`Error::OutOfDomain`] outside the tabulated ranges (no extrapolation).
pub fn coefficients(a_over_b: f64, nu: f64) -> Result<Coefficients> {
    if !(RATIOS[0]..=RATIOS[18]).contains(&a_over_b) {
        return Err(Error::OutOfDomain {
            name: "semi-axis ratio a/b of Kalker's table",
            value: a_over_b,
            allowed: "0.1 to 10 (a along the rolling direction)",
        });
    }
    if !(0.0..=0.5).contains(&nu) {
        return Err(Error::OutOfDomain {
            name: "Poisson ratio of Kalker's table",
            value: nu,
            allowed: "0 to 0.5",
        });
    }
    let hi = RATIOS.iter().position(|&r| r >= a_over_b).unwrap_or(18).max(1);
    let lo = hi - 1;
    let t = (a_over_b - RATIOS[lo]) / (RATIOS[hi] - RATIOS[lo]);
    let at = |rows: &[[f64; 19]; 3]| {
        let (a, b) = (quadratic_in_nu(rows, lo, nu), quadratic_in_nu(rows, hi, nu));
        a + t * (b - a)
    };
    Ok(Coefficients { c11: at(&C11), c22: at(&C22), c23: at(&C23) })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn interpolation_returns_the_nodes() {
        let c = coefficients(1.0, 0.25).unwrap();
        assert_eq!((c.c11, c.c22, c.c23), (4.12, 3.67, 1.47));
        let c = coefficients(0.1, 0.5).unwrap();
        assert!((c.c11 - 4.85).abs() < 1e-12 && (c.c23 - 0.731).abs() < 1e-12);
        assert!(coefficients(0.05, 0.3).is_err());
        assert!(coefficients(1.0, 0.6).is_err());
    }

    /// Transcription check by two properties of the solution: at nu = 0 the longitudinal and
    /// lateral directions are alike (C11 = C22), and for a/b -> 0 (a contact long across the
    /// rolling direction) C11 -> pi^2/(4(1 - nu)), C22 -> pi^2/4 (Kalker's asymptotics, the
    /// 2D Carter limit); the a/b = 0.1 column is within 3 % of that.
    #[test]
    fn table_properties() {
        assert_eq!(C11[0], C22[0]);
        for (k, nu) in POISSON.iter().enumerate() {
            let c11 = PI * PI / (4.0 * (1.0 - nu));
            assert!((C11[k][0] / c11 - 1.0).abs() < 0.03, "nu {nu}: {} vs {c11}", C11[k][0]);
            assert!((C22[k][0] / (PI * PI / 4.0) - 1.0).abs() < 0.03);
        }
    }
}
