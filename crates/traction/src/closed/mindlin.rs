//! Mindlin's circular contact under a tangential force (Mindlin 1949; seed 002 eqs 3.1–3.4;
//! FORMULAS.md E).

use super::{load_ratio, one_minus_pow};
use crate::error::{positive, Result};
use std::f64::consts::PI;
use stickslip_halfspace::Material;

/// Mindlin's partial-slip solution for a Hertz circle of radius $a$ under normal load $P$ and
/// tangential force $T \le fP$ along $x$ (Mindlin 1949; seed 002 eqs 3.1–3.4;
/// FORMULAS.md E).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mindlin {
    a: f64,
    normal: f64,
    friction: f64,
    tangential: f64,
    ratio: f64,
}

impl Mindlin {
    /// Validate $a > 0$, $P > 0$, $f > 0$ and $0 \le T \le fP$.
    ///
    /// # Errors
    /// [`crate::Error::OutOfDomain`] naming the offending input; $T > fP$ (gross slip) is
    /// refused because no partial-slip solution exists.
    pub fn new(a: f64, normal: f64, friction: f64, tangential: f64) -> Result<Self> {
        positive("contact radius a", a)?;
        let ratio = load_ratio(normal, friction, tangential)?;
        Ok(Self { a, normal, friction, tangential, ratio })
    }

    /// Contact radius $a$.
    #[must_use]
    pub fn radius(&self) -> f64 {
        self.a
    }

    /// Load ratio $T/(fP)$.
    #[must_use]
    pub fn load_ratio(&self) -> f64 {
        self.ratio
    }

    /// Stick radius $a^* = a\,(1 - T/fP)^{1/3}$ (seed 002 eq. 3.1; FORMULAS.md E).
    #[must_use]
    pub fn stick_radius(&self) -> f64 {
        self.a * (1.0 - self.ratio).max(0.0).cbrt()
    }

    /// Shear traction along $x$ at radius $\rho$ (seed 002 eqs 3.1–3.2; FORMULAS.md E):
    /// $$q(\rho) = \frac{3fP}{2\pi a^3}\Big[\sqrt{a^2-\rho^2} - \sqrt{a^{*2}-\rho^2}\,
    ///   H(a^*-\rho)\Big],$$
    /// zero outside the contact.
    #[must_use]
    pub fn traction(&self, rho: f64) -> f64 {
        let a = self.a;
        let s = self.stick_radius();
        let qh = 3.0 * self.friction * self.normal / (2.0 * PI * a.powi(3));
        let rho = rho.abs();
        if rho >= a {
            return 0.0;
        }
        let outer = ((a - rho) * (a + rho)).sqrt();
        let inner = if rho < s { ((s - rho) * (s + rho)).sqrt() } else { 0.0 };
        qh * (outer - inner)
    }

    /// Compliance of ONE body, the tangential displacement of its stick zone relative to its
    /// remote points (FORMULAS.md E, "per body"; seed 002 eq. 3.3 with $T < fP$):
    /// $$\delta_i = \frac{3(2-\nu_i)fP}{16 G_i a}\Big[1 - (1 - T/fP)^{2/3}\Big].$$
    /// Zero for a rigid body.
    #[must_use]
    pub fn compliance_per_body(&self, body: &Material) -> f64 {
        if body.is_rigid() {
            return 0.0;
        }
        let (g, nu) = (body.shear_modulus(), body.poisson_ratio());
        3.0 * (2.0 - nu) * self.friction * self.normal / (16.0 * g * self.a)
            * one_minus_pow(self.ratio, 2.0 / 3.0)
    }

    /// Relative tangential displacement of the two bodies (FORMULAS.md E, "relative"):
    /// $$\delta = \frac{3fP}{16a}\sum_i\frac{2-\nu_i}{G_i}\Big[1-(1-T/fP)^{2/3}\Big],$$
    /// the sum of [`Mindlin::compliance_per_body`] over both bodies.
    #[must_use]
    pub fn compliance_relative(&self, body1: &Material, body2: &Material) -> f64 {
        self.compliance_per_body(body1) + self.compliance_per_body(body2)
    }

    /// The tangential load $T$.
    #[must_use]
    pub fn tangential_load(&self) -> f64 {
        self.tangential
    }
}
