//! Flamant's line load on an elastic half-plane (plane strain).
//!
//! A normal load $P$ (force per unit length, pushing into the body) and a tangential load $Q$
//! (acting on the body in $+x$) are applied along the line $x = y = 0$ of the surface $y = 0$;
//! the body is $y > 0$. The stress field is purely radial,
//! $$\sigma_{rr} = -\frac{2P\cos\theta}{\pi r} - \frac{2Q\sin\theta}{\pi r},\qquad
//! \sin\theta = x/r,\ \cos\theta = y/r,$$
//! with $\sigma_{\theta\theta} = \sigma_{r\theta} = 0$ (Flamant 1892; Johnson, *Contact
//! Mechanics*, eqs 2.15 and 2.16; FORMULAS.md B, the $k \to 0$ limit of A2).

use crate::error::{finite, positive, Error};
use crate::{Displacement2, Material, Stress2};
use std::f64::consts::PI;

/// Stress at $(x, y)$, $y \ge 0$, due to the line loads $P$ (normal) and $Q$ (tangential):
/// $$\sigma_{xx} = -\frac{2x^2(Py + Qx)}{\pi r^4},\quad
/// \sigma_{yy} = -\frac{2y^2(Py + Qx)}{\pi r^4},\quad
/// \sigma_{xy} = -\frac{2xy(Py + Qx)}{\pi r^4},$$
/// $r^2 = x^2 + y^2$ (Johnson eqs 2.15, 2.16; FORMULAS.md B). Compression is negative; $Q$ acts on
/// the body in $+x$, so the material ahead of it ($x > 0$) is compressed. On the surface away
/// from the load ($y = 0$, $x \ne 0$) only $\sigma_{xx} = -2Q/(\pi x)$ survives.
///
/// At the load point itself the field is singular and the result is not finite; use
/// [`checked_line_load_stress`] to get an error instead.
#[inline]
#[must_use]
pub fn line_load_stress(p: f64, q: f64, x: f64, y: f64) -> Stress2 {
    let r2 = x * x + y * y;
    // Common factor -2 (P y + Q x) / (pi r^4) = -2 (P cos + Q sin) / (pi r^3).
    let s = -2.0 * (p * y + q * x) / (PI * r2 * r2);
    Stress2 { xx: s * x * x, yy: s * y * y, xy: s * x * y }
}

/// [`line_load_stress`] with its domain checked.
///
/// # Errors
/// [`Error::OutOfDomain`] for non-finite input or $y < 0$; [`Error::Singular`] at the load
/// point $(0, 0)$.
pub fn checked_line_load_stress(p: f64, q: f64, x: f64, y: f64) -> Result<Stress2, Error> {
    finite("p", p)?;
    finite("q", q)?;
    finite("x", x)?;
    finite("y", y)?;
    if y < 0.0 {
        return Err(Error::OutOfDomain { name: "y", value: y, allowed: "y >= 0 (depth)" });
    }
    if x == 0.0 && y == 0.0 {
        return Err(Error::Singular { what: "Flamant stress", x, y });
    }
    Ok(line_load_stress(p, q, x, y))
}

/// Surface displacement of the half-plane at $x \ne 0$ due to the line loads $P$ and $Q$ at the
/// origin (plane strain, one body):
/// $$u_x = -\frac{(1-2\nu)(1+\nu)}{2E}P\,\mathrm{sgn}\,x + \frac{2(1-\nu^2)}{\pi E}
/// Q\ln\frac{x_0}{|x|},\qquad
/// u_y = \frac{2(1-\nu^2)}{\pi E}P\ln\frac{x_0}{|x|} + \frac{(1-2\nu)(1+\nu)}{2E}Q\,
/// \mathrm{sgn}\,x,$$
/// $u_y$ positive into the body (Johnson eqs 2.19, 2.20; FORMULAS.md B).
///
/// **Datum.** In 2D the logarithmic displacements are defined only up to a rigid-body motion.
/// Here the datum is the user-given distance `x0` $> 0$: the log terms vanish at $|x| = x_0$,
/// i.e. $u_y$ due to $P$ and $u_x$ due to $Q$ are measured relative to the surface points at
/// $x = \pm x_0$. The step terms are taken odd in $x$ (zero rigid translation), so the point
/// under the load moves by the mean of the two sides.
///
/// At $x = 0$ the log terms are infinite; use [`checked_surface_displacement`] for an error.
#[inline]
#[must_use]
pub fn surface_displacement(m: &Material, p: f64, q: f64, x: f64, x0: f64) -> Displacement2 {
    let e = m.youngs_modulus();
    let nu = m.poisson_ratio();
    if m.is_rigid() {
        return Displacement2::default();
    }
    let log_coef = 2.0 * (1.0 - nu * nu) / (PI * e) * (x0 / x.abs()).ln();
    let step = (1.0 - 2.0 * nu) * (1.0 + nu) / (2.0 * e) * sgn0(x);
    Displacement2 { x: -step * p + log_coef * q, y: log_coef * p + step * q }
}

/// [`surface_displacement`] with its domain checked.
///
/// # Errors
/// [`Error::OutOfDomain`] for non-finite loads or $x$, or a datum `x0` that is not finite and
/// positive; [`Error::Singular`] at $x = 0$.
pub fn checked_surface_displacement(
    m: &Material,
    p: f64,
    q: f64,
    x: f64,
    x0: f64,
) -> Result<Displacement2, Error> {
    finite("p", p)?;
    finite("q", q)?;
    finite("x", x)?;
    positive("x0", x0)?;
    if x == 0.0 {
        return Err(Error::Singular { what: "Flamant surface displacement", x, y: 0.0 });
    }
    Ok(surface_displacement(m, p, q, x, x0))
}

/// Sign function with $\mathrm{sgn}(0) = 0$.
#[inline]
pub(crate) fn sgn0(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        0.0
    }
}
