//! Surface displacements of a homogeneous half-plane under semi-elliptical strip loads
//! (plane strain): the pressure of 2D Hertz, and the shear strips of 2D Cattaneo–Mindlin
//! and of full sliding.
//!
//! A strip of half-width $b$ and peak $A$ carries $A\sqrt{1-s^2/b^2}$ on $|s| < b$. By the
//! Flamant kernels (Johnson §2.2, eqs 2.19 and 2.20; FORMULAS.md B), each such strip gives
//! the body's surface point at $x$ two parts:
//!
//! - a step part, $\frac{(1-2\nu)(1+\nu)}{2E}\,[2F(x) - F(b)]$ with $F$ the load between
//!   $-b$ and $x$, absolute (odd in $x$);
//! - a logarithmic part, defined only up to a constant in 2D, here taken relative to the
//!   surface point $x = 0$: $b\,A\,\frac{1-\nu^2}{E}\,G(|x|/b)$ with $G(\xi) = \xi^2$ for
//!   $\xi \le 1$ and $G(\xi) = \xi/(\xi + \sqrt{\xi^2-1}) + \operatorname{acosh}\xi$ beyond
//!   (the per-body form of [`super::HertzLine::approach_relative`], Johnson §4.3).
//!
//! A pressure moves the surface down by its logarithmic part and sideways (towards the
//! centre) by its step part; a shear traction along $+x$ moves it sideways by its
//! logarithmic part and vertically by its step part.

use std::f64::consts::PI;

use crate::Material;

/// A semi-elliptical strip load $A\sqrt{1-s^2/b^2}$ centred on $s = 0$.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Strip {
    /// Half-width $b$ (m).
    pub half_width: f64,
    /// Peak $A$ (Pa), signed.
    pub peak: f64,
}

impl Strip {
    /// The load between $-b$ and $x$, $\tfrac{A b}{2}[t\sqrt{1-t^2} + \arcsin t + \pi/2]$,
    /// $t = x/b$ clipped to $[-1, 1]$.
    #[must_use]
    pub fn cumulative(&self, x: f64) -> f64 {
        let (b, amp) = (self.half_width, self.peak);
        let t = (x / b).clamp(-1.0, 1.0);
        0.5 * amp * b * (t * ((1.0 - t) * (1.0 + t)).sqrt() + t.asin() + 0.5 * PI)
    }

    /// The logarithmic-kernel displacement of body `m` at $x$ relative to $x = 0$,
    /// $b\,A\,\frac{1-\nu^2}{E}\,G(|x|/b)$ (module docs).
    #[must_use]
    pub fn log_relative(&self, x: f64, m: &Material) -> f64 {
        let (b, amp) = (self.half_width, self.peak);
        let xi = (x / b).abs();
        let g = if xi <= 1.0 {
            xi * xi
        } else {
            let s = ((xi - 1.0) * (xi + 1.0)).sqrt();
            xi / (xi + s) + xi.acosh()
        };
        b * amp * m.normal_compliance() * g
    }
}

/// Surface displacement $(u_x, u_y)$ of body `m` at $x$ under the pressure strip `pressure`
/// and the shear strips `shear` (traction on the body along $+x$); $u_y$ is positive into
/// the body. The logarithmic parts are relative to $x = 0$, the step parts absolute.
#[must_use]
pub fn surface_displacement(x: f64, pressure: Strip, shear: &[Strip], m: &Material) -> (f64, f64) {
    let e = m.youngs_modulus();
    let nu = m.poisson_ratio();
    let step = (1.0 - 2.0 * nu) * (1.0 + nu) / (2.0 * e);
    let total = PI * pressure.half_width * pressure.peak / 2.0;
    let mut ux = -step * (2.0 * pressure.cumulative(x) - total);
    let mut uy = -pressure.log_relative(x, m);
    for s in shear {
        ux -= s.log_relative(x, m);
        uy += step * (2.0 * s.cumulative(x) - PI * s.half_width * s.peak / 2.0);
    }
    (ux, uy)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cumulative load reaches the strip's resultant $\pi A b/2$ at $x = b$ and is
    /// half of it at the centre.
    #[test]
    fn cumulative_load_matches_the_resultant() {
        let s = Strip { half_width: 2e-3, peak: 7e8 };
        let total = PI * 2e-3 * 7e8 / 2.0;
        assert!((s.cumulative(2e-3) - total).abs() <= 1e-15 * total);
        assert!((s.cumulative(0.0) - 0.5 * total).abs() <= 1e-15 * total);
        assert_eq!(s.cumulative(-5e-3), 0.0);
    }

    /// Against the Hertz line contact's own relative approach (two identical bodies give
    /// twice one body's log part), beyond and inside the contact.
    #[test]
    fn log_part_is_half_the_hertz_relative_approach_for_identical_bodies() {
        let m = Material::new(2.1e11, 0.3).unwrap();
        let es = crate::material::composite_modulus(&m, &m);
        let h = super::super::HertzLine::new(1e5, 0.05, es).unwrap();
        let s = Strip { half_width: h.half_width(), peak: h.max_pressure() };
        for xi in [0.3, 1.0, 2.5, 10.0] {
            let x = xi * h.half_width();
            let two_bodies = 2.0 * s.log_relative(x, &m);
            let want = h.approach_relative(x);
            assert!(
                (two_bodies - want).abs() <= 1e-12 * want.abs(),
                "x/a = {xi}: {two_bodies} vs {want}"
            );
        }
    }
}
