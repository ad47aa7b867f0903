//! Lubkin's torsion of a Hertz circle with a slip annulus (Lubkin 1951; FORMULAS.md G, whose
//! G-independent forms are used here).

use crate::error::{positive, Error, Result};
use std::f64::consts::PI;
use stickslip_halfspace::Material;
use stickslip_quad::{gauss_kronrod, AdaptiveConfig, Tolerance};

/// $K(k) - E(k)$ of the modulus $k$ given through the complementary parameter
/// $k'^2 = 1 - k^2 \in [0, 1]$ (so both ends keep relative accuracy):
/// $m\,D(m)$ with $m = k^2$ and $D = (K-E)/m$ from `stickslip_special::ellipd` (no
/// cancellation as $k \to 0$), and the logarithmic expansion
/// $K \approx L + \tfrac{k'^2}{4}(L - 1)$, $E \approx 1 + \tfrac{k'^2}{2}(L - \tfrac12)$,
/// $L = \ln(4/k')$ (DLMF 19.12.1–19.12.2) for $k'^2 < 10^{-6}$, where forming
/// $m = 1 - k'^2$ would lose the digits of $k'^2$. $+\infty$ at $k'^2 = 0$.
#[must_use]
pub fn k_minus_e(kp2: f64) -> f64 {
    if kp2 <= 0.0 {
        return f64::INFINITY;
    }
    if kp2 < 1e-6 {
        let l = (16.0 / kp2).ln() * 0.5;
        let k = l + 0.25 * kp2 * (l - 1.0);
        let e = 1.0 + 0.5 * kp2 * (l - 0.5);
        return k - e;
    }
    let m = 1.0 - kp2;
    m * stickslip_special::ellipd(m)
}

/// $2E(k) - K(k)$ with $k'^2 = 1 - k^2$ given (as [`k_minus_e`]).
fn two_e_minus_k(kp2: f64) -> f64 {
    // 2E - K = E - (K - E); K - E from ellipd keeps its digits as m -> 0.
    let m = 1.0 - kp2;
    stickslip_special::ellipe(m) - m * stickslip_special::ellipd(m)
}

fn quad_cfg() -> AdaptiveConfig {
    AdaptiveConfig {
        tol: Tolerance::new(1e-300, 1e-13).unwrap_or_default(),
        ..AdaptiveConfig::default()
    }
}

/// Lubkin's solution: a Hertz circle (radius $a$, normal load $P$, friction $\mu$) twisted by a
/// moment $M$, with a stick disc $r < c$ and a slip annulus $c < r < a$ (Lubkin 1951;
/// seed 002 §3.4 cites it for the twist case; FORMULAS.md G).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lubkin {
    a: f64,
    normal: f64,
    friction: f64,
    c: f64,
}

impl Lubkin {
    /// Parameters given the stick radius $0 \le c \le a$.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] naming the offending input.
    pub fn from_stick_radius(a: f64, normal: f64, friction: f64, c: f64) -> Result<Self> {
        positive("contact radius a", a)?;
        positive("normal load P", normal)?;
        positive("friction coefficient", friction)?;
        if !(c.is_finite() && (0.0..=a).contains(&c)) {
            return Err(Error::OutOfDomain { name: "stick radius c", value: c, allowed: "[0, a]" });
        }
        Ok(Self { a, normal, friction, c })
    }

    /// Parameters given the moment $0 \le M \le M_{\max} = 3\pi\mu P a/16$: the stick radius
    /// solves $M(c) = M$ ($M$ decreases monotonically in $c$) by bisection to a relative
    /// $10^{-15}$ of $a$, with $M(c)$ of [`Lubkin::moment`] (Lubkin 1951; FORMULAS.md G).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for bad inputs or $M > M_{\max}$ (gross slip: no stick disc).
    pub fn from_moment(a: f64, normal: f64, friction: f64, moment: f64) -> Result<Self> {
        let full = Self::from_stick_radius(a, normal, friction, 0.0)?;
        let mmax = full.gross_slip_moment();
        if !(moment.is_finite() && moment >= 0.0) || moment > mmax * (1.0 + 1e-14) {
            return Err(Error::OutOfDomain {
                name: "twisting moment M",
                value: moment,
                allowed: "[0, 3 pi mu P a / 16]; beyond it the contact spins (gross slip)",
            });
        }
        let (mut lo, mut hi) = (0.0, a);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            let m = Self { c: mid, ..full }.moment()?;
            if m > moment {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Ok(Self { c: 0.5 * (lo + hi), ..full })
    }

    /// Stick radius $c$.
    #[must_use]
    pub fn stick_radius(&self) -> f64 {
        self.c
    }

    /// Moment at gross slip, $M(0) = 3\pi\mu P a/16$ (FORMULAS.md G).
    #[must_use]
    pub fn gross_slip_moment(&self) -> f64 {
        Self::gross_slip_moment_of(self.a, self.normal, self.friction)
    }

    /// The torsional capacity of a Hertz circle of radius `a` under normal load `normal`
    /// with friction coefficient `friction`, $M(0) = 3\pi\mu P a/16$ (FORMULAS.md G): a
    /// larger moment spins the contact. Needs no solver, so a caller can check a load
    /// before building one.
    #[must_use]
    pub fn gross_slip_moment_of(a: f64, normal: f64, friction: f64) -> f64 {
        3.0 * PI * friction * normal * a / 16.0
    }

    /// The twisting moment for stick radius $c$ (FORMULAS.md G), $k_t = \sqrt{1-t^2/a^2}$:
    /// $$M(c) = \frac{4\mu P}{\pi a^2}\Big\{c^3[K(k_c)-E(k_c)] +
    ///   3\int_c^a t^2[K(k_t)-E(k_t)]\,dt\Big\},$$
    /// the integral by adaptive Gauss–Kronrod (`stickslip_quad`, relative $10^{-13}$).
    ///
    /// # Errors
    /// [`Error::Quad`] if the quadrature fails.
    pub fn moment(&self) -> Result<f64> {
        let a = self.a;
        let u0 = self.c / a;
        let boundary = if u0 > 0.0 { u0.powi(3) * k_minus_e(u0 * u0) } else { 0.0 };
        let integral = gauss_kronrod(|u| u * u * k_minus_e(u * u), u0, 1.0, &quad_cfg())
            .map_err(|e| Error::Quad(e.to_string()))?
            .value;
        Ok(4.0 * self.friction * self.normal * a / PI * (boundary + 3.0 * integral))
    }

    /// Rigid rotation of the stick disc of ONE body (FORMULAS.md G):
    /// $$\omega = \frac{3\mu P}{4\pi G a^2}[K(k_c) - E(k_c)]$$
    /// (infinite at $c = 0$, zero for a rigid body).
    #[must_use]
    pub fn rotation_per_body(&self, body: &Material) -> f64 {
        if body.is_rigid() {
            return 0.0;
        }
        let u0 = self.c / self.a;
        3.0 * self.friction * self.normal / (4.0 * PI * body.shear_modulus() * self.a * self.a)
            * k_minus_e(u0 * u0)
    }

    /// Relative rotation of the two bodies (FORMULAS.md G, $1/G \to 1/G_1 + 1/G_2$):
    /// $$\omega = \frac{3\mu P}{4\pi a^2}\Big(\frac1{G_1} + \frac1{G_2}\Big)[K(k_c) - E(k_c)].$$
    #[must_use]
    pub fn rotation_relative(&self, body1: &Material, body2: &Material) -> f64 {
        self.rotation_per_body(body1) + self.rotation_per_body(body2)
    }

    /// Circumferential traction at radius $r$ (FORMULAS.md G): $\mu p(r)$ on the slip
    /// annulus and, on the stick disc $r < c$,
    /// $$\tau(r) = \frac{3\mu P}{\pi^2 a^2 r}\Big[\int_c^a\frac{(2E(k_t)-K(k_t))\,t\,dt}
    ///   {\sqrt{t^2-r^2}} - (K(k_c)-E(k_c))\sqrt{c^2-r^2}\Big],$$
    /// the integral taken in $s = \sqrt{t^2-r^2}$ (smooth) by adaptive Gauss–Kronrod.
    /// $\tau(0) = 0$.
    ///
    /// # Errors
    /// [`Error::Quad`] if the quadrature fails.
    pub fn traction(&self, r: f64) -> Result<f64> {
        let (a, c) = (self.a, self.c);
        let r = r.abs();
        if r >= a {
            return Ok(0.0);
        }
        let k0 = 3.0 * self.friction * self.normal / (2.0 * PI * a.powi(3));
        if r >= c {
            return Ok(k0 * ((a - r) * (a + r)).sqrt());
        }
        if r == 0.0 {
            return Ok(0.0);
        }
        let s0 = ((c - r) * (c + r)).sqrt();
        let s1 = ((a - r) * (a + r)).sqrt();
        let a2 = a * a;
        let integral = gauss_kronrod(
            |s| {
                let kp2 = (r * r + s * s) / a2;
                two_e_minus_k(kp2.min(1.0))
            },
            s0,
            s1,
            &quad_cfg(),
        )
        .map_err(|e| Error::Quad(e.to_string()))?
        .value;
        let u0 = c / a;
        let kme = k_minus_e(u0 * u0);
        Ok(3.0 * self.friction * self.normal / (PI * PI * a2 * r) * (integral - kme * s0))
    }
}
