//! Polach's closed creep-force law (Polach 2000, *Proc. IMechE F* 214; the version without
//! the adhesion-reduction factors and without spin).
//!
//! With $s = \sqrt{\xi^2 + \eta^2}$, the combined coefficient
//! $C = \sqrt{(C_{11}\xi/s)^2 + (C_{22}\eta/s)^2}$ (Kalker, [`super::kalker`]) and the gradient
//! of the tangential stress in the adhesion area
//! $$\varepsilon = \frac{\pi G a b\,C\,s}{4 fN},$$
//! the creep force is
//! $$F = \frac{2fN}{\pi}\Big(\frac{\varepsilon}{1+\varepsilon^2} + \arctan\varepsilon\Big),
//! \qquad (F_x, F_y) = -F\,(\xi, \eta)/s.$$
//! It reproduces the linear theory ($F \approx GabCs$) for small creepage and saturates at
//! $fN$.

use super::{kalker, Creepage};
use crate::error::{Error, Result};
use std::f64::consts::PI;

/// Creep forces $(F_x, F_y)$ (N) on body 1 for an elliptical contact of semi-axes `a`
/// (rolling direction) and `b`, combined shear modulus `g`, Poisson ratio `nu`, normal force
/// `normal` and friction `friction`.
///
/// # Errors
/// [`Error::OutOfDomain`] for a spin creepage (the law has none), non-positive normal force or
/// modulus, negative friction; as [`kalker::coefficients`].
pub fn forces(
    a: f64,
    b: f64,
    g: f64,
    nu: f64,
    normal: f64,
    friction: f64,
    creep: &Creepage,
) -> Result<(f64, f64)> {
    creep.validate()?;
    if creep.spin != 0.0 {
        return Err(Error::OutOfDomain {
            name: "spin creepage for Polach's law",
            value: creep.spin,
            allowed: "0 (use FASTSIM or the exact theory with spin)",
        });
    }
    for (name, v) in [("normal force", normal), ("shear modulus", g)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(Error::OutOfDomain { name, value: v, allowed: "finite and > 0" });
        }
    }
    if !(friction.is_finite() && friction >= 0.0) {
        return Err(Error::OutOfDomain {
            name: "friction coefficient",
            value: friction,
            allowed: "finite and >= 0",
        });
    }
    let s = creep.longitudinal.hypot(creep.lateral);
    if s == 0.0 || friction == 0.0 {
        return Ok((0.0, 0.0));
    }
    let k = kalker::coefficients(a / b, nu)?;
    let c = (k.c11 * creep.longitudinal / s).hypot(k.c22 * creep.lateral / s);
    let eps = PI * g * a * b * c * s / (4.0 * friction * normal);
    let f = 2.0 * friction * normal / PI * (eps / (1.0 + eps * eps) + eps.atan());
    Ok((-f * creep.longitudinal / s, -f * creep.lateral / s))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_limit_and_saturation() {
        let (a, b, g, nu, n, f) = (6e-3, 4e-3, 8e10, 0.28, 1e5, 0.3);
        let k = kalker::coefficients(a / b, nu).unwrap();
        let tiny = Creepage { longitudinal: 1e-9, ..Default::default() };
        let (fx, fy) = forces(a, b, g, nu, n, f, &tiny).unwrap();
        let linear = -g * a * b * k.c11 * 1e-9;
        assert!((fx / linear - 1.0).abs() < 1e-6 && fy == 0.0, "{fx} vs {linear}");
        let huge = Creepage { lateral: -10.0, ..Default::default() };
        let (_, fy) = forces(a, b, g, nu, n, f, &huge).unwrap();
        assert!((fy / (f * n) - 1.0).abs() < 1e-3, "{fy}");
        let spin = Creepage { spin: 1.0, ..Default::default() };
        assert!(forces(a, b, g, nu, n, f, &spin).is_err());
    }
}
