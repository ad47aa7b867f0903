//! The seed's claim $l \approx \sqrt{8KRP\beta/\alpha}$, evaluated over its whole grid.
//!
//! Goryacheva 1973 (seed 001, after eq 25) states that for $\alpha, \beta$ from
//! $10^{-1}$ to $10^{6}$ s and $w$ = 10, 100, 1000 cm/s the contact length was always close to
//! $\sqrt{8KRP\beta/\alpha}$ (the OCR's "$\sqrt{8KRP\beta}/\alpha$" is an erratum), the Hertz
//! length for the instantaneous modulus $H = \alpha E/\beta$. FORMULAS.md section D: this holds
//! when $l \ll 2\beta w$ ($x_1 = l/(2\beta w) \ll 1$); it is not universal. [`claim_sweep`]
//! solves eqs 19/20 on the grid and reports, row by row, how far the claim is off.

use crate::carter::{check_material, compliance};
use crate::error::{normal, positive, Error};
use crate::goryacheva::contact_length;

/// A material and loading for the sweep (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepMaterial {
    /// Label.
    pub name: &'static str,
    /// $E$ \[Pa\].
    pub youngs_modulus: f64,
    /// $\nu$.
    pub poisson_ratio: f64,
    /// $R$ \[m\].
    pub radius: f64,
    /// $P$ \[N/m\].
    pub load: f64,
}

impl SweepMaterial {
    /// Rubber-like: $E$ = 5 MPa, $\nu$ = 0.49, a 5 cm radius roller carrying 1 kN/m
    /// ($l_H \approx 8.8$ mm).
    pub const RUBBER_LIKE: SweepMaterial = SweepMaterial {
        name: "rubber-like",
        youngs_modulus: 5.0e6,
        poisson_ratio: 0.49,
        radius: 0.05,
        load: 1.0e3,
    };
    /// Polymer-like (PMMA-like glassy polymer): $E$ = 3 GPa, $\nu$ = 0.35, a 1 cm radius roller
    /// carrying 10 kN/m ($l_H \approx 0.55$ mm).
    pub const POLYMER_LIKE: SweepMaterial = SweepMaterial {
        name: "polymer-like",
        youngs_modulus: 3.0e9,
        poisson_ratio: 0.35,
        radius: 0.01,
        load: 1.0e4,
    };

    /// Elastic contact length $l_H = \sqrt{8KRP}$ \[m\], $K = 4(1-\nu^2)/(\pi E)$ (Goryacheva
    /// 1973, elastic limit of eqs 19–20; FORMULAS.md section D).
    #[must_use]
    pub fn hertz_length(&self) -> f64 {
        (8.0 * compliance(self.youngs_modulus, self.poisson_ratio) * self.radius * self.load).sqrt()
    }
}

/// One grid point of the sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClaimRow {
    /// $\alpha$ \[s\].
    pub alpha: f64,
    /// $\beta$ \[s\].
    pub beta: f64,
    /// $w$ \[m/s\].
    pub speed: f64,
    /// Solved contact length $l$ \[m\] (eq 19).
    pub length: f64,
    /// $l/l_H$.
    pub length_over_hertz: f64,
    /// The claim $\sqrt{8KRP\beta/\alpha}$ \[m\].
    pub claimed_length: f64,
    /// $l/\sqrt{8KRP\beta/\alpha} - 1$.
    pub claim_error: f64,
    /// Shift $d$ \[m\] (eq 20).
    pub shift: f64,
    /// $x_1 = l/(2\beta w)$: the claim needs $x_1 \ll 1$.
    pub x1: f64,
}

impl ClaimRow {
    /// Whether the claim holds to relative accuracy `tol` on this row.
    #[must_use]
    pub fn claim_holds(&self, tol: f64) -> bool {
        self.claim_error.abs() <= tol
    }
}

/// The grid of the seed: $\alpha, \beta \in [10^{-1}, 10^{6}]$ s log-spaced with
/// `per_decade` points per decade (both ends included), all pairs with $\alpha > \beta$, and
/// $w \in \{0.1, 1, 10\}$ m/s (10, 100, 1000 cm/s).
///
/// Each row solves eq 19 (scaled, bracketed) and eq 20; see [`contact_length`].
///
/// # Errors
/// [`Error::OutOfDomain`] for an invalid material or `per_decade == 0`.
pub fn claim_sweep(mat: &SweepMaterial, per_decade: usize) -> Result<Vec<ClaimRow>, Error> {
    check_material(mat.youngs_modulus, mat.poisson_ratio)?;
    positive("radius", mat.radius)?;
    positive("load", mat.load)?;
    if per_decade == 0 {
        return Err(Error::OutOfDomain { name: "per_decade", value: 0.0, allowed: ">= 1" });
    }
    let lh = normal("Hertz length l_H", mat.hertz_length())?;
    let n = 7 * per_decade + 1;
    let times: Vec<f64> =
        (0..n).map(|i| 10f64.powf(-1.0 + 7.0 * i as f64 / (n - 1) as f64)).collect();
    let mut rows = Vec::with_capacity(3 * n * (n - 1) / 2);
    for &speed in &[0.1, 1.0, 10.0] {
        for (i, &beta) in times.iter().enumerate() {
            for &alpha in &times[i + 1..] {
                let cl = contact_length(alpha, beta, speed, lh)?;
                let claimed = lh * (beta / alpha).sqrt();
                rows.push(ClaimRow {
                    alpha,
                    beta,
                    speed,
                    length: cl.length,
                    length_over_hertz: cl.ratio,
                    claimed_length: claimed,
                    claim_error: cl.length / claimed - 1.0,
                    shift: cl.shift,
                    x1: cl.x1,
                });
            }
        }
    }
    Ok(rows)
}
