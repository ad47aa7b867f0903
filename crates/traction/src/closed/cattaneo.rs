//! Cattaneo's elliptical contact under a tangential force along an axis (Cattaneo 1938; seed
//! 002 §3.2.2; FORMULAS.md E).

use super::{load_ratio, one_minus_pow};
use crate::error::{positive, Result};
use std::f64::consts::PI;
use stickslip_halfspace::Material;

/// Which axis of the ellipse the tangential force lies along.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoadAxis {
    /// Along the major axis.
    Major,
    /// Along the minor axis.
    Minor,
}

/// The compliance factor $\Lambda$ of Cattaneo's ellipse (FORMULAS.md E), with
/// $e^2 = 1 - b_{\min}^2/a_{\max}^2$ and $K$, $E$ of parameter $m = e^2$:
/// $$\Lambda_{\text{major}} = (1-\nu)K + \nu\frac{K-E}{e^2},\qquad
///   \Lambda_{\text{minor}} = (1-\nu)K + \nu\frac{E-(1-e^2)K}{e^2}.$$
/// Both tend to $\pi(2-\nu)/4$ for a circle (Mindlin). $(K-E)/e^2$ is
/// `stickslip_special::ellipd` (Carlson's $R_D$, no cancellation as $e^2 \to 0$); `e2`
/// must lie in $[0, 1)$.
#[must_use]
pub fn cattaneo_lambda(e2: f64, nu: f64, axis: LoadAxis) -> f64 {
    let k = stickslip_special::ellipk(e2);
    let kme_over_m = stickslip_special::ellipd(e2);
    match axis {
        LoadAxis::Major => (1.0 - nu) * k + nu * kme_over_m,
        // (E - (1-m)K)/m = K - (K-E)/m.
        LoadAxis::Minor => (1.0 - nu) * k + nu * (k - kme_over_m),
    }
}

/// Cattaneo's partial-slip solution for a Hertz ellipse with semi-axis $a$ along the load
/// ($x$) and $b$ along $y$, normal load $P$, tangential force $T \le fP$ along $x$
/// (Cattaneo 1938; seed 002 §3.2.2; FORMULAS.md E).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cattaneo {
    a: f64,
    b: f64,
    normal: f64,
    friction: f64,
    ratio: f64,
}

impl Cattaneo {
    /// Validate $a, b, P, f > 0$ and $0 \le T \le fP$.
    ///
    /// # Errors
    /// [`crate::Error::OutOfDomain`] naming the offending input ($T > fP$ is gross slip).
    pub fn new(a: f64, b: f64, normal: f64, friction: f64, tangential: f64) -> Result<Self> {
        positive("semi-axis a (along the load)", a)?;
        positive("semi-axis b (across the load)", b)?;
        let ratio = load_ratio(normal, friction, tangential)?;
        Ok(Self { a, b, normal, friction, ratio })
    }

    /// Stick-zone scale $a^*/a = b^*/b = (1 - T/fP)^{1/3}$ (Cattaneo 1938; FORMULAS.md E).
    #[must_use]
    pub fn stick_scale(&self) -> f64 {
        (1.0 - self.ratio).max(0.0).cbrt()
    }

    /// Peak Hertz pressure $p_0 = 3P/(2\pi ab)$ (Hertz; FORMULAS.md E, Cattaneo).
    #[must_use]
    pub fn peak_pressure(&self) -> f64 {
        3.0 * self.normal / (2.0 * PI * self.a * self.b)
    }

    /// Shear traction along $x$ at $(x, y)$ (FORMULAS.md E):
    /// $$q = f p_0\sqrt{1-\tfrac{x^2}{a^2}-\tfrac{y^2}{b^2}} -
    ///   \tfrac{a^*}{a} f p_0 \sqrt{1-\tfrac{x^2}{a^{*2}}-\tfrac{y^2}{b^{*2}}}\;
    ///   \text{(second term on the stick zone only)}.$$
    #[must_use]
    pub fn traction(&self, x: f64, y: f64) -> f64 {
        let fp0 = self.friction * self.peak_pressure();
        let outer = 1.0 - (x / self.a).powi(2) - (y / self.b).powi(2);
        if outer <= 0.0 {
            return 0.0;
        }
        let s = self.stick_scale();
        let mut q = fp0 * outer.sqrt();
        if s > 0.0 {
            let inner = 1.0 - (x / (s * self.a)).powi(2) - (y / (s * self.b)).powi(2);
            if inner > 0.0 {
                q -= s * fp0 * inner.sqrt();
            }
        }
        q
    }

    /// Which axis the load lies along.
    #[must_use]
    pub fn load_axis(&self) -> LoadAxis {
        if self.a >= self.b {
            LoadAxis::Major
        } else {
            LoadAxis::Minor
        }
    }

    /// Compliance of ONE body (FORMULAS.md E):
    /// $$\delta = \frac{3fP}{4\pi G a_{\max}}\,\Lambda\,\Big[1-(1-T/fP)^{2/3}\Big],$$
    /// with $\Lambda$ from [`cattaneo_lambda`] for the load axis. Zero for a rigid body.
    #[must_use]
    pub fn compliance_per_body(&self, body: &Material) -> f64 {
        if body.is_rigid() {
            return 0.0;
        }
        let (amax, bmin) = (self.a.max(self.b), self.a.min(self.b));
        let r = bmin / amax;
        let e2 = (1.0 - r) * (1.0 + r);
        let lam = cattaneo_lambda(e2, body.poisson_ratio(), self.load_axis());
        3.0 * self.friction * self.normal / (4.0 * PI * body.shear_modulus() * amax)
            * lam
            * one_minus_pow(self.ratio, 2.0 / 3.0)
    }

    /// Relative displacement of the two bodies: the sum of the per-body compliances,
    /// $\delta = \frac{3fP}{4\pi a_{\max}}\sum_i\frac{\Lambda(\nu_i)}{G_i}\Big[1-(1-T/fP)^{2/3}\Big]$
    /// (FORMULAS.md E; seed 002 §3.2.2).
    #[must_use]
    pub fn compliance_relative(&self, body1: &Material, body2: &Material) -> f64 {
        self.compliance_per_body(body1) + self.compliance_per_body(body2)
    }
}
