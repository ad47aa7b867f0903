//! Hertz contact: 2D cylinders (line contact), spheres (circular contact) and general
//! (elliptic) point contacts of two elastic bodies with composite modulus $E^*$ (see
//! [`crate::material::composite_modulus`]).
//!
//! Sources: Hertz (1882); Johnson, *Contact Mechanics*, §4.2 (eqs 4.22–4.24 sphere), §4.3
//! (eqs 4.45, 4.47 cylinder) and §3.4/§4.2 (eqs 3.39–3.41, 4.40 ellipse); FORMULAS.md B (2D)
//! and E (sphere). Loads are positive, pressures positive in compression.

mod ellipse;
pub mod ellipse_field;
mod ellipse_field_terms;
pub mod sphere_field;
pub mod strip;

pub use ellipse::HertzEllipse;

use crate::error::{positive, Error};
use crate::mcewen::ellipse_factor;
use std::f64::consts::PI;

/// 2D Hertz contact of a cylinder (relative radius $R$) pressed by $P$ per unit length:
/// $$a = \sqrt{\frac{4PR}{\pi E^*}},\qquad p_0 = \frac{2P}{\pi a} = \frac{aE^*}{2R},\qquad
/// p(x) = p_0\sqrt{1-x^2/a^2}$$
/// (Johnson eqs 4.45, 4.47; FORMULAS.md B, the homogeneous limit $a^2 = 4PR/(\pi E^*)$).
/// $1/R = 1/R_1 + 1/R_2$ for two cylinders with parallel axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzLine {
    load: f64,
    radius: f64,
    e_star: f64,
    a: f64,
    p0: f64,
}

impl HertzLine {
    /// Solve the line contact for load per unit length $P$, relative radius $R$ and composite
    /// modulus $E^*$ (all finite, positive).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if an input is not finite and positive.
    pub fn new(load: f64, radius: f64, e_star: f64) -> Result<Self, Error> {
        positive("load", load)?;
        positive("radius", radius)?;
        positive("e_star", e_star)?;
        let a = (4.0 * load * radius / (PI * e_star)).sqrt();
        Ok(Self { load, radius, e_star, a, p0: 2.0 * load / (PI * a) })
    }

    /// The contact that has half-width $a$: $P = \pi a^2E^*/(4R)$, the inverse of
    /// $a^2 = 4PR/(\pi E^*)$ (Johnson eqs 4.45, 4.47; FORMULAS.md B).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if an input is not finite and positive.
    pub fn from_half_width(a: f64, radius: f64, e_star: f64) -> Result<Self, Error> {
        positive("a", a)?;
        positive("radius", radius)?;
        positive("e_star", e_star)?;
        Self::new(PI * a * a * e_star / (4.0 * radius), radius, e_star)
    }

    /// Load per unit length $P$.
    #[must_use]
    pub fn load(&self) -> f64 {
        self.load
    }

    /// Relative radius $R$.
    #[must_use]
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// Composite modulus $E^*$.
    #[must_use]
    pub fn e_star(&self) -> f64 {
        self.e_star
    }

    /// Contact half-width $a$.
    #[must_use]
    pub fn half_width(&self) -> f64 {
        self.a
    }

    /// Peak pressure $p_0 = 2P/(\pi a)$.
    #[must_use]
    pub fn max_pressure(&self) -> f64 {
        self.p0
    }

    /// Pressure $p(x) = p_0\sqrt{1-x^2/a^2}$, zero outside $|x| < a$ (Johnson eqs 4.45, 4.47;
    /// FORMULAS.md B, $p \to p_0\sqrt{1-x^2/a^2}$).
    #[must_use]
    pub fn pressure(&self, x: f64) -> f64 {
        self.p0 * ellipse_factor(x, self.a)
    }

    /// Approach of the two bodies relative to a datum: the mutual approach of the surface
    /// points at $x = 0$ compared with that of the points at $|x| = x_0$,
    /// $\delta(x_0) = [u_y(0) - u_y(x_0)]_{1} + [u_y(0) - u_y(x_0)]_{2}$. In 2D no absolute
    /// approach exists (FORMULAS.md A4, B). From Flamant's kernel,
    /// $u_y(0) - u_y(x_0) = \frac{2}{\pi E^*}\int p(s)\ln\frac{|x_0-s|}{|s|}ds$, which gives
    /// $$\delta = \frac{x_0^2}{2R}\ (\xi \le 1),\qquad
    /// \delta = \frac{a^2}{2R}\left[\frac{\xi}{\xi + \sqrt{\xi^2-1}} + \operatorname{acosh}\xi
    /// \right]\ (\xi \ge 1),\qquad \xi = |x_0|/a,$$
    /// so $\delta \to \frac{a^2}{2R}\left(\ln\frac{2x_0}{a} + \frac12\right)$ for $x_0 \gg a$
    /// (FORMULAS.md A4; the 2D analogue of Johnson §4.3). Checked against
    /// quadrature of Flamant's kernel and an mpmath table.
    #[must_use]
    pub fn approach_relative(&self, x0: f64) -> f64 {
        let xi = (x0 / self.a).abs();
        let c = self.a * self.a / (2.0 * self.radius);
        if xi <= 1.0 {
            c * xi * xi
        } else {
            let s = ((xi - 1.0) * (xi + 1.0)).sqrt();
            c * (xi / (xi + s) + xi.acosh())
        }
    }
}

/// 3D Hertz contact of a sphere (relative radius $R$) under normal load $P$:
/// $$a = \left(\frac{3PR}{4E^*}\right)^{1/3},\qquad p_0 = \frac{3P}{2\pi a^2},\qquad
/// \delta = \frac{a^2}{R},\qquad p(r) = p_0\sqrt{1-r^2/a^2}$$
/// (Johnson eqs 4.22–4.24; FORMULAS.md E). $\delta$ is the approach of distant points of the
/// two bodies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzSphere {
    load: f64,
    radius: f64,
    e_star: f64,
    a: f64,
    p0: f64,
}

impl HertzSphere {
    /// Solve for load $P$, relative radius $R$ ($1/R = 1/R_1 + 1/R_2$) and composite modulus
    /// $E^*$ (finite, positive).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if an input is not finite and positive.
    pub fn new(load: f64, radius: f64, e_star: f64) -> Result<Self, Error> {
        positive("load", load)?;
        positive("radius", radius)?;
        positive("e_star", e_star)?;
        let a = (3.0 * load * radius / (4.0 * e_star)).cbrt();
        Ok(Self { load, radius, e_star, a, p0: 3.0 * load / (2.0 * PI * a * a) })
    }

    /// The load that gives contact radius `a` on a sphere of relative radius `radius` with
    /// composite modulus `e_star`: $P = 4E^*a^3/(3R)$, the inverse of
    /// $a^3 = 3PR/(4E^*)$ (Johnson eq 4.22; FORMULAS.md E).
    #[must_use]
    pub fn load_for_contact_radius(a: f64, radius: f64, e_star: f64) -> f64 {
        4.0 * e_star * a.powi(3) / (3.0 * radius)
    }

    /// Load $P$.
    #[must_use]
    pub fn load(&self) -> f64 {
        self.load
    }

    /// Relative radius $R$.
    #[must_use]
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// Composite modulus $E^*$.
    #[must_use]
    pub fn e_star(&self) -> f64 {
        self.e_star
    }

    /// Contact radius $a$.
    #[must_use]
    pub fn contact_radius(&self) -> f64 {
        self.a
    }

    /// Peak pressure $p_0 = 3P/(2\pi a^2)$.
    #[must_use]
    pub fn max_pressure(&self) -> f64 {
        self.p0
    }

    /// Approach of distant points of the two bodies, $\delta = a^2/R$ (Johnson eqs 4.22–4.24;
    /// FORMULAS.md E).
    #[must_use]
    pub fn approach(&self) -> f64 {
        self.a * self.a / self.radius
    }

    /// Pressure $p(r) = p_0\sqrt{1-r^2/a^2}$, zero outside $r < a$, with
    /// $p_0 = 3P/(2\pi a^2)$ (Johnson eqs 4.22–4.24; FORMULAS.md E).
    #[must_use]
    pub fn pressure(&self, r: f64) -> f64 {
        self.p0 * ellipse_factor(r, self.a)
    }
}
