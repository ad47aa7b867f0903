//! 2D Cattaneo–Mindlin partial slip of a Hertz line contact (cylinder on a half-plane,
//! identical materials so that normal and tangential problems uncouple).
//!
//! Under the Hertz pressure $p = p_0\sqrt{1-x^2/a^2}$ ($P = \pi ap_0/2$) a tangential load
//! $0 \le |Q| < fP$ leaves a central stick zone $|x| < c$ and slip zones $c < |x| < a$:
//! $$q(x) = \mathrm{sgn}(Q)\,f p_0\left[\sqrt{1-\frac{x^2}{a^2}} - \frac{c}{a}\sqrt{1 -
//! \frac{x^2}{c^2}}\,H(c-|x|)\right],\qquad \frac ca = \sqrt{1 - \frac{|Q|}{fP}},$$
//! with $\int q\,dx = Q$. The subsurface field is the superposition
//! $\sigma = \sigma_p(a, p_0) + \mathrm{sgn}(Q)\left[\sigma_q(a, fp_0) - \sigma_q(c, fp_0c/a)
//! \right]$ of McEwen fields ([`crate::mcewen`]). Sources: Cattaneo (1938), Mindlin (1949);
//! Johnson, *Contact Mechanics*, §7.2 (eqs 7.28–7.31); FORMULAS.md C. Conventions as the crate:
//! $y$ depth, $q$ acts on the body in $+x$.

use crate::error::{finite, positive, Error};
use crate::mcewen::{ellipse_factor, stress_potential};
use crate::Stress2;
use std::f64::consts::PI;

/// A 2D Cattaneo–Mindlin partial-slip state (validated; see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cattaneo2d {
    a: f64,
    p0: f64,
    friction: f64,
    q: f64,
    /// $|Q|/(fP)$, exactly as given (0 when $Q = 0$).
    ratio: f64,
    c: f64,
}

impl Cattaneo2d {
    /// Partial slip of the Hertz contact of half-width $a$ and peak pressure $p_0$ under the
    /// tangential load $Q$ (per unit length, acting on the body in $+x$; either sign) with
    /// friction coefficient $f \ge 0$.
    ///
    /// Exact limits: $Q = 0$ gives $c = a$ and no traction; $|Q| = fP$ gives $c = 0$
    /// (sliding, $q = fp$).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for $a, p_0$ not finite and positive, $f$ negative or not
    /// finite, $Q$ not finite; [`Error::GrossSlip`] if $|Q| > fP$ (beyond 4 ulp of rounding,
    /// which is taken as $|Q| = fP$).
    pub fn new(a: f64, p0: f64, friction: f64, q: f64) -> Result<Self, Error> {
        positive("a", a)?;
        positive("p0", p0)?;
        finite("q", q)?;
        if !(friction >= 0.0 && friction.is_finite()) {
            return Err(Error::OutOfDomain {
                name: "friction",
                value: friction,
                allowed: "finite, >= 0",
            });
        }
        let limit = friction * PI * a * p0 / 2.0;
        // A Q computed as f P by the caller may differ from our f P in the last bits: treat
        // |Q| within 4 ulp of the limit as exactly sliding (c = 0).
        if q.abs() > limit * (1.0 + 4.0 * f64::EPSILON) {
            return Err(Error::GrossSlip { q, limit });
        }
        let ratio = if q == 0.0 { 0.0 } else { (q.abs() / limit).min(1.0) };
        let c = a * (1.0 - ratio).sqrt();
        Ok(Self { a, p0, friction, q, ratio, c })
    }

    /// Contact half-width $a$.
    #[must_use]
    pub fn half_width(&self) -> f64 {
        self.a
    }

    /// Stick-zone half-width $c = a\sqrt{1 - |Q|/(fP)}$.
    #[must_use]
    pub fn stick_half_width(&self) -> f64 {
        self.c
    }

    /// Normal load per unit length $P = \pi a p_0/2$, the resultant of the Hertz pressure
    /// (FORMULAS.md C, $p_0 = 2P/(\pi a)$; Johnson eqs 4.45, 4.47).
    #[must_use]
    pub fn normal_load(&self) -> f64 {
        PI * self.a * self.p0 / 2.0
    }

    /// Tangential load $Q$.
    #[must_use]
    pub fn tangential_load(&self) -> f64 {
        self.q
    }

    /// Pressure $p(x) = p_0\sqrt{1-x^2/a^2}$ for $|x| < a$, zero outside (Hertz; FORMULAS.md C).
    #[must_use]
    pub fn pressure(&self, x: f64) -> f64 {
        self.p0 * ellipse_factor(x, self.a)
    }

    /// Shear traction $q(x)$ on the body, the module formula (Cattaneo 1938, Mindlin 1949;
    /// Johnson eqs 7.28–7.31; FORMULAS.md C, 2D Cattaneo–Mindlin). In the stick zone it is
    /// evaluated as
    /// $\mathrm{sgn}(Q)\,fp_0\,a\,(|Q|/fP)/\left(\sqrt{a^2-x^2} + \sqrt{c^2-x^2}\right)$,
    /// which avoids the cancellation of the two square roots when $Q$ is small.
    #[must_use]
    pub fn traction(&self, x: f64) -> f64 {
        let sign = if self.q < 0.0 { -1.0 } else { 1.0 };
        let ax = x.abs();
        if ax >= self.a || self.ratio == 0.0 {
            return 0.0;
        }
        let fp0 = self.friction * self.p0;
        if ax < self.c {
            let sa = ((self.a - ax) * (self.a + ax)).sqrt();
            let sc = ((self.c - ax) * (self.c + ax)).sqrt();
            // (a^2 - c^2) = a^2 ratio exactly.
            sign * fp0 * self.a * self.ratio / (sa + sc)
        } else {
            sign * fp0 * ellipse_factor(x, self.a)
        }
    }

    /// Stress at $(x, y)$, $y \ge 0$, by superposition of McEwen fields (FORMULAS.md C):
    /// $\sigma_p(a, p_0) + \mathrm{sgn}(Q)[\sigma_q(a, fp_0) - \sigma_q(c, fp_0c/a)]$, each
    /// term from [`crate::mcewen::stress_potential`].
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for non-finite input or $y < 0$.
    pub fn stress(&self, x: f64, y: f64) -> Result<Stress2, Error> {
        finite("x", x)?;
        if !(y >= 0.0 && y.is_finite()) {
            return Err(Error::OutOfDomain { name: "y", value: y, allowed: "finite, >= 0" });
        }
        let mut s = stress_potential(self.a, self.p0, 0.0, x, y);
        if self.ratio > 0.0 {
            let sign = if self.q < 0.0 { -1.0 } else { 1.0 };
            let q0 = sign * self.friction * self.p0;
            s = s.add_scaled(stress_potential(self.a, 0.0, q0, x, y), 1.0);
            if self.c > 0.0 {
                let qc = q0 * self.c / self.a;
                s = s.add_scaled(stress_potential(self.c, 0.0, qc, x, y), -1.0);
            }
        }
        Ok(s)
    }
}
