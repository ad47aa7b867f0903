//! Carter's rolling contact of two elastic cylinders of the same material (plane strain).
//!
//! Sign conventions (shared with [`crate::goryacheva`]): the cylinder moves in $+x$; $x$ is
//! measured from the point below the cylinder's centre; the contact is $(-a, a)$ with the
//! trailing edge at $-a$. The slip zone is at the trailing edge, $(-a, c)$, the stick zone at
//! the leading edge, $(c, a)$. The creep is $\delta = (\omega R - w)/w$ and $\rho$ the
//! coefficient of friction. $p = \sigma_y \ge 0$ is the contact pressure with
//! $\int p\,dx = P$, and $\tau = \tau_{xy}$ the shear on the base, $Q = \int\tau\,dx$; on the
//! slip zone $\tau = -\rho_s p$ with $\rho_s = \rho\,\operatorname{sign}\delta$.
//!
//! Negative creep is supported by the mirror symmetry of the problem: $(\delta, \rho) \to
//! (-\delta, -\rho)$ leaves every equation unchanged, so the stick zone stays at the leading
//! edge, the slip length is $2|\delta|R/\rho$ and all tractions change sign,
//! $Q(-\delta) = -Q(\delta)$. $\delta = 0$ is full stick with $Q = 0$.
//!
//! Source: Carter (1926); as the elastic limit $\alpha = \beta$ of Goryacheva 1973 (seed 001),
//! FORMULAS.md section D, "Elastic limit".

use crate::error::{positive, Error};
use crate::Regime;
use std::f64::consts::PI;

/// Two-body plane-strain compliance of identical materials, $K = \dfrac{4(1-\nu^2)}{\pi E}$
/// \[1/Pa\] (Goryacheva 1973 eq 3; FORMULAS.md section D).
#[must_use]
pub fn compliance(youngs_modulus: f64, poisson_ratio: f64) -> f64 {
    4.0 * (1.0 - poisson_ratio * poisson_ratio) / (PI * youngs_modulus)
}

/// Validate $E > 0$ and $-1 < \nu \le 1/2$.
pub(crate) fn check_material(youngs_modulus: f64, poisson_ratio: f64) -> Result<(), Error> {
    positive("youngs_modulus", youngs_modulus)?;
    if !(poisson_ratio > -1.0 && poisson_ratio <= 0.5) {
        return Err(Error::OutOfDomain {
            name: "poisson_ratio",
            value: poisson_ratio,
            allowed: "-1 < nu <= 0.5",
        });
    }
    Ok(())
}

/// Validated inputs of Carter's problem (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarterParams {
    youngs_modulus: f64,
    poisson_ratio: f64,
    radius: f64,
    load: f64,
    friction: f64,
    creep: f64,
}

impl CarterParams {
    /// Check and store the inputs.
    ///
    /// - `youngs_modulus` $E$ \[Pa\], finite $> 0$; `poisson_ratio` $\nu$ \[-\], $-1 < \nu \le 1/2$
    ///   (both bodies are of this material);
    /// - `radius` $R$ \[m\] of the cylinder, finite $> 0$;
    /// - `load` $P$ \[N/m\], normal force per unit length, finite $> 0$;
    /// - `friction` $\rho$ \[-\], finite $> 0$;
    /// - `creep` $\delta = (\omega R - w)/w$ \[-\], finite, either sign.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] naming the first offending input; [`Error::NonFinite`] if the
    /// half-width $\sqrt{2KRP}$ is not a normal `f64`.
    pub fn new(
        youngs_modulus: f64,
        poisson_ratio: f64,
        radius: f64,
        load: f64,
        friction: f64,
        creep: f64,
    ) -> Result<Self, Error> {
        check_material(youngs_modulus, poisson_ratio)?;
        positive("radius", radius)?;
        positive("load", load)?;
        positive("friction", friction)?;
        if !creep.is_finite() {
            return Err(Error::OutOfDomain { name: "creep", value: creep, allowed: "finite" });
        }
        let p = CarterParams { youngs_modulus, poisson_ratio, radius, load, friction, creep };
        crate::error::normal("half-width a", p.half_width())?;
        Ok(p)
    }

    /// Compliance $K$ \[1/Pa\], see [`compliance`].
    #[must_use]
    pub fn compliance(&self) -> f64 {
        compliance(self.youngs_modulus, self.poisson_ratio)
    }

    /// Hertz half-width $a = \sqrt{2KRP}$ \[m\] (FORMULAS.md D, elastic limit).
    #[must_use]
    pub fn half_width(&self) -> f64 {
        (2.0 * self.compliance() * self.radius * self.load).sqrt()
    }

    /// Radius $R$ \[m\].
    #[must_use]
    pub fn radius(&self) -> f64 {
        self.radius
    }
    /// Load $P$ \[N/m\].
    #[must_use]
    pub fn load(&self) -> f64 {
        self.load
    }
    /// Friction coefficient $\rho$.
    #[must_use]
    pub fn friction(&self) -> f64 {
        self.friction
    }
    /// Creep $\delta$.
    #[must_use]
    pub fn creep(&self) -> f64 {
        self.creep
    }
}

/// Carter's solution: geometry, creep force and the traction distributions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarterSolution {
    /// Half-width $a = \sqrt{2KRP}$ \[m\].
    pub half_width: f64,
    /// Start of the stick zone $c = -a + 2|\delta|R/\rho$ \[m\], clipped to $[-a, a]$ ($c = a$
    /// in full slip: no stick zone).
    pub stick_start: f64,
    /// Stick-zone length $m = a - c$ \[m\].
    pub stick_length: f64,
    /// Peak pressure $p_0 = 2P/(\pi a) = a/(\pi K R)$ \[Pa\].
    pub peak_pressure: f64,
    /// Tangential force $Q = \int \tau\,dx$ \[N/m\], see [`carter_creep_force`].
    pub tangential_force: f64,
    /// Rolling-friction moment $M^* = QR$ \[N\] (the pressure is symmetric: $M_1 = 0$).
    pub rolling_moment: f64,
    /// Which of stick-slip, full slip, full stick.
    pub regime: Regime,
    /// $\rho_s = \rho\,\mathrm{sign}\,\delta$ ($\rho$ when $\delta = 0$).
    pub signed_friction: f64,
    /// $K R$ \[m/Pa\], kept for the traction formulas.
    pub compliance_radius: f64,
}

/// Carter's creep law: the tangential force $Q$ \[N/m\] for creep $\delta$.
///
/// $$Q = -\rho_s P\left[1-\left(1-\frac{|\delta| R}{\rho a}\right)^2\right]
///     = -\rho_s P\, z(2-z),\quad z = \frac{|\delta|R}{\rho a}\le 1,$$
/// and $Q = -\rho_s P$ (full slip) when $z \ge 1$. The factored form $z(2-z)$ has no
/// cancellation at small creep. Goryacheva 1973 (seed 001), elastic limit of eq 27;
/// FORMULAS.md section D.
#[must_use]
pub fn carter_creep_force(
    creep: f64,
    friction: f64,
    load: f64,
    half_width: f64,
    radius: f64,
) -> f64 {
    let z = creep.abs() * radius / (friction * half_width);
    let s = if creep < 0.0 { -1.0 } else { 1.0 };
    if z >= 1.0 {
        -s * friction * load
    } else {
        -s * friction * load * z * (2.0 - z)
    }
}

/// Solve Carter's problem (closed form; cannot fail for validated parameters).
///
/// Contact $(-a, a)$, $a = \sqrt{2KRP}$; slip zone length $2|\delta|R/\rho$ from the trailing
/// edge, so $c = -a + 2|\delta|R/\rho$ (Goryacheva eq 24 at $\alpha=\beta$; FORMULAS.md D).
/// Full slip when $2|\delta|R/\rho \ge 2a$, full stick when $\delta = 0$.
#[must_use]
pub fn carter(p: &CarterParams) -> CarterSolution {
    let a = p.half_width();
    let kr = p.compliance() * p.radius;
    let slip = 2.0 * p.creep.abs() * p.radius / p.friction;
    let (regime, c) = if p.creep == 0.0 {
        (Regime::FullStick, -a)
    } else if slip >= 2.0 * a {
        (Regime::FullSlip, a)
    } else {
        (Regime::StickSlip, -a + slip)
    };
    let q = if p.creep == 0.0 {
        0.0
    } else {
        carter_creep_force(p.creep, p.friction, p.load, a, p.radius)
    };
    let signed_friction = if p.creep < 0.0 { -p.friction } else { p.friction };
    CarterSolution {
        half_width: a,
        stick_start: c,
        stick_length: if regime == Regime::FullSlip { 0.0 } else { 2.0 * a - slip.min(2.0 * a) },
        peak_pressure: a / (PI * kr),
        tangential_force: q,
        rolling_moment: q * p.radius,
        regime,
        signed_friction,
        compliance_radius: kr,
    }
}

impl CarterSolution {
    /// Hertz pressure $p(x) = \dfrac{\sqrt{(a-x)(a+x)}}{\pi K R}$ \[Pa\] for $|x| < a$, zero
    /// outside (Goryacheva 1973, elastic limit of eq 12; FORMULAS.md D).
    #[must_use]
    pub fn pressure(&self, x: f64) -> f64 {
        let a = self.half_width;
        if x <= -a || x >= a {
            return 0.0;
        }
        ((a - x) * (a + x)).sqrt() / (PI * self.compliance_radius)
    }

    /// Carter's shear $\tau(x)$ \[Pa\]:
    /// $$\tau = -\rho_s p(x) \ (-a<x<c),\qquad
    ///   \tau = -\rho_s p(x) + \frac{\rho_s}{\pi K R}\sqrt{(a-x)(x-c)}\ (c<x<a),$$
    /// zero outside the contact (Goryacheva 1973, elastic limit of eq 13, with the OCR's
    /// "p" read as $\rho$; FORMULAS.md D).
    #[must_use]
    pub fn shear(&self, x: f64) -> f64 {
        let a = self.half_width;
        if x <= -a || x >= a {
            return 0.0;
        }
        let mut t = -self.signed_friction * self.pressure(x);
        if x > self.stick_start {
            t += self.signed_friction * ((a - x) * (x - self.stick_start)).sqrt()
                / (PI * self.compliance_radius);
        }
        t
    }
}
