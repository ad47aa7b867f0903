//! Concentrated forces on the surface of an elastic half-space: Boussinesq (normal) and Cerruti
//! (tangential).
//!
//! Coordinates: $x, y$ on the surface, $z \ge 0$ depth; the force acts at the origin.
//! $R = \sqrt{x^2+y^2+z^2}$, $\rho = \sqrt{x^2+y^2}$. The normal force $P$ pushes into the body
//! ($+z$); the tangential force $Q$ acts on the body in $+x$ (for a force along $y$, swap the
//! roles of $x$ and $y$). Displacements are positive along the axes ($u_z > 0$ = into the body).
//! Compression is negative.
//!
//! Sources: Boussinesq (1885) and Cerruti (1882), in the forms of Johnson, *Contact Mechanics*,
//! §3.2 (eqs 3.21, 3.22 normal; eqs 3.86, 3.87 tangential) and Love (1927) §§135–137; surface
//! values and the sign of Cerruti's $u_z$ as in FORMULAS.md F. The crate's tests check the
//! stresses against finite-difference strains of the displacement field through Hooke's law,
//! against the force balance $\iint\sigma_{iz}\,dx\,dy$ over a plane $z = $ const, and the
//! surface against the traction-free condition.

use crate::error::{finite, Error};
use crate::{Displacement3, Material, Stress3};
use std::f64::consts::PI;

fn check_point(what: &'static str, x: f64, y: f64, z: f64) -> Result<(), Error> {
    finite("x", x)?;
    finite("y", y)?;
    finite("z", z)?;
    if z < 0.0 {
        return Err(Error::OutOfDomain { name: "z", value: z, allowed: "z >= 0 (depth)" });
    }
    if x == 0.0 && y == 0.0 && z == 0.0 {
        return Err(Error::Singular { what, x, y });
    }
    Ok(())
}

/// Displacement at $(x, y, z)$ due to a normal force $P$ at the origin (Boussinesq):
/// $$u_x = \frac{P}{4\pi G}\frac{x}{R}\left[\frac{z}{R^2} - \frac{1-2\nu}{R+z}\right],\quad
/// u_y = \frac{P}{4\pi G}\frac{y}{R}\left[\frac{z}{R^2} - \frac{1-2\nu}{R+z}\right],\quad
/// u_z = \frac{P}{4\pi G R}\left[2(1-\nu) + \frac{z^2}{R^2}\right]$$
/// (Johnson eq. 3.22; FORMULAS.md F). On the surface $u_z = (1-\nu)P/(2\pi G\rho)$ and the
/// radial displacement $-(1-2\nu)P/(4\pi G\rho)$ points towards the load. Not finite at the
/// load point (see [`checked_boussinesq_displacement`]). Zero for a rigid body.
#[inline]
#[must_use]
pub fn boussinesq_displacement(m: &Material, p: f64, x: f64, y: f64, z: f64) -> Displacement3 {
    if m.is_rigid() {
        return Displacement3::default();
    }
    let nu = m.poisson_ratio();
    let r = (x * x + y * y + z * z).sqrt();
    let c = p / (4.0 * PI * m.shear_modulus());
    let radial = c / r * (z / (r * r) - (1.0 - 2.0 * nu) / (r + z));
    Displacement3 { x: radial * x, y: radial * y, z: c / r * (2.0 * (1.0 - nu) + z * z / (r * r)) }
}

/// [`boussinesq_displacement`] with its domain checked.
///
/// # Errors
/// [`Error::OutOfDomain`] for non-finite input or $z < 0$; [`Error::Singular`] at the origin.
pub fn checked_boussinesq_displacement(
    m: &Material,
    p: f64,
    x: f64,
    y: f64,
    z: f64,
) -> Result<Displacement3, Error> {
    finite("p", p)?;
    check_point("Boussinesq displacement", x, y, z)?;
    Ok(boussinesq_displacement(m, p, x, y, z))
}

/// Stress at $(x, y, z)$ due to a normal force $P$ at the origin (Boussinesq). With
/// $$\sigma_\theta = -\frac{(1-2\nu)P}{2\pi}\,\frac{\rho^2 - zR}{R^3(R+z)},\qquad
/// D = \frac{P}{2\pi}\left[\frac{(1-2\nu)(2R+z)}{R^3(R+z)^2} - \frac{3z}{R^5}\right]
/// = \frac{\sigma_r - \sigma_\theta}{\rho^2},$$
/// $$\sigma_{xx} = \sigma_\theta + Dx^2,\ \sigma_{yy} = \sigma_\theta + Dy^2,\
/// \sigma_{xy} = Dxy,\ \sigma_{zz} = -\frac{3Pz^3}{2\pi R^5},\
/// \sigma_{xz} = -\frac{3Pxz^2}{2\pi R^5},\ \sigma_{yz} = -\frac{3Pyz^2}{2\pi R^5}.$$
/// This is Johnson eq. 3.21 (polar $\sigma_r, \sigma_\theta, \sigma_z, \tau_{rz}$) rewritten in
/// Cartesian components in a form without cancellation on the axis $\rho = 0$. Only $\nu$ of the
/// material enters. Not finite at the load point. FORMULAS.md F gives only the surface
/// displacements; the stresses are checked by the tests named in the module docs.
#[inline]
#[must_use]
pub fn boussinesq_stress(nu: f64, p: f64, x: f64, y: f64, z: f64) -> Stress3 {
    let rho2 = x * x + y * y;
    let r2 = rho2 + z * z;
    let r = r2.sqrt();
    let r3 = r2 * r;
    let r5 = r3 * r2;
    let rz = r + z;
    let k = p / (2.0 * PI);
    let s_theta = -k * (1.0 - 2.0 * nu) * (rho2 - z * r) / (r3 * rz);
    let d = k * ((1.0 - 2.0 * nu) * (2.0 * r + z) / (r3 * rz * rz) - 3.0 * z / r5);
    let t = -3.0 * k * z * z / r5;
    Stress3 {
        xx: s_theta + d * x * x,
        yy: s_theta + d * y * y,
        zz: t * z,
        xy: d * x * y,
        xz: t * x,
        yz: t * y,
    }
}

/// [`boussinesq_stress`] with its domain checked.
///
/// # Errors
/// [`Error::OutOfDomain`] for non-finite input, $z < 0$ or $\nu \notin (-1, 1/2]$;
/// [`Error::Singular`] at the origin.
pub fn checked_boussinesq_stress(
    nu: f64,
    p: f64,
    x: f64,
    y: f64,
    z: f64,
) -> Result<Stress3, Error> {
    Material::new(1.0, nu)?;
    finite("p", p)?;
    check_point("Boussinesq stress", x, y, z)?;
    Ok(boussinesq_stress(nu, p, x, y, z))
}

/// Displacement at $(x, y, z)$ due to a tangential force $Q$ along $+x$ at the origin
/// (Cerruti):
/// $$u_x = \frac{Q}{4\pi G}\left[\frac1R + \frac{x^2}{R^3} + (1-2\nu)\left(\frac{1}{R+z} -
/// \frac{x^2}{R(R+z)^2}\right)\right],\quad
/// u_y = \frac{Q}{4\pi G}\left[\frac{xy}{R^3} - \frac{(1-2\nu)xy}{R(R+z)^2}\right],$$
/// $$u_z = \frac{Q}{4\pi G}\left[\frac{xz}{R^3} + \frac{(1-2\nu)x}{R(R+z)}\right]$$
/// (Johnson eq. 3.86; FORMULAS.md F). On the surface this is
/// $u_x = \frac{Q}{2\pi G\rho}\left[(1-\nu) + \nu x^2/\rho^2\right]$, $u_y = \frac{Q\nu xy}{2\pi
/// G\rho^3}$, $u_z = +\frac{(1-2\nu)Qx}{4\pi G\rho^2}$: points ahead of the force sink (the sign
/// fixed by Betti reciprocity with Boussinesq in FORMULAS.md F). Zero for a rigid body.
#[inline]
#[must_use]
pub fn cerruti_displacement(m: &Material, q: f64, x: f64, y: f64, z: f64) -> Displacement3 {
    if m.is_rigid() {
        return Displacement3::default();
    }
    let nu = m.poisson_ratio();
    let r2 = x * x + y * y + z * z;
    let r = r2.sqrt();
    let r3 = r2 * r;
    let rz = r + z;
    let c = q / (4.0 * PI * m.shear_modulus());
    let a = 1.0 - 2.0 * nu;
    Displacement3 {
        x: c * (1.0 / r + x * x / r3 + a * (1.0 / rz - x * x / (r * rz * rz))),
        y: c * x * y * (1.0 / r3 - a / (r * rz * rz)),
        z: c * x * (z / r3 + a / (r * rz)),
    }
}

/// [`cerruti_displacement`] with its domain checked.
///
/// # Errors
/// [`Error::OutOfDomain`] for non-finite input or $z < 0$; [`Error::Singular`] at the origin.
pub fn checked_cerruti_displacement(
    m: &Material,
    q: f64,
    x: f64,
    y: f64,
    z: f64,
) -> Result<Displacement3, Error> {
    finite("q", q)?;
    check_point("Cerruti displacement", x, y, z)?;
    Ok(cerruti_displacement(m, q, x, y, z))
}

/// Stress at $(x, y, z)$ due to a tangential force $Q$ along $+x$ at the origin (Cerruti;
/// Johnson eq. 3.87, here with $Q$ acting on the body in $+x$):
/// $$\sigma_{xx} = \frac{Q}{2\pi}\left[-\frac{3x^3}{R^5} + (1-2\nu)\left(\frac{x}{R^3} -
/// \frac{3x}{R(R+z)^2} + \frac{x^3}{R^3(R+z)^2} + \frac{2x^3}{R^2(R+z)^3}\right)\right],$$
/// $$\sigma_{yy} = \frac{Q}{2\pi}\left[-\frac{3xy^2}{R^5} + (1-2\nu)\left(\frac{x}{R^3} -
/// \frac{x}{R(R+z)^2} + \frac{xy^2}{R^3(R+z)^2} + \frac{2xy^2}{R^2(R+z)^3}\right)\right],$$
/// $$\sigma_{xy} = \frac{Q}{2\pi}\left[-\frac{3x^2y}{R^5} + (1-2\nu)\left(-\frac{y}{R(R+z)^2} +
/// \frac{x^2y}{R^3(R+z)^2} + \frac{2x^2y}{R^2(R+z)^3}\right)\right],$$
/// $$\sigma_{zz} = -\frac{3Qxz^2}{2\pi R^5},\quad \sigma_{xz} = -\frac{3Qx^2z}{2\pi R^5},\quad
/// \sigma_{yz} = -\frac{3Qxyz}{2\pi R^5}.$$
/// Only $\nu$ enters. Not finite at the load point. FORMULAS.md F gives only the surface
/// displacements of this force; the stresses are checked by the tests named in the module docs.
#[inline]
#[must_use]
pub fn cerruti_stress(nu: f64, q: f64, x: f64, y: f64, z: f64) -> Stress3 {
    let r2 = x * x + y * y + z * z;
    let r = r2.sqrt();
    let r3 = r2 * r;
    let r5 = r3 * r2;
    let rz = r + z;
    let rz2 = rz * rz;
    let k = q / (2.0 * PI);
    let a = 1.0 - 2.0 * nu;
    // Shared pieces of the (1 - 2 nu) terms.
    let c1 = 1.0 / (r3 * rz2) + 2.0 / (r2 * rz2 * rz);
    let t = -3.0 * k / r5;
    Stress3 {
        xx: k * (-3.0 * x * x * x / r5 + a * (x / r3 - 3.0 * x / (r * rz2) + x * x * x * c1)),
        yy: k * (-3.0 * x * y * y / r5 + a * (x / r3 - x / (r * rz2) + x * y * y * c1)),
        zz: t * x * z * z,
        xy: k * (-3.0 * x * x * y / r5 + a * (-y / (r * rz2) + x * x * y * c1)),
        xz: t * x * x * z,
        yz: t * x * y * z,
    }
}

/// [`cerruti_stress`] with its domain checked.
///
/// # Errors
/// [`Error::OutOfDomain`] for non-finite input, $z < 0$ or $\nu \notin (-1, 1/2]$;
/// [`Error::Singular`] at the origin.
pub fn checked_cerruti_stress(nu: f64, q: f64, x: f64, y: f64, z: f64) -> Result<Stress3, Error> {
    Material::new(1.0, nu)?;
    finite("q", q)?;
    check_point("Cerruti stress", x, y, z)?;
    Ok(cerruti_stress(nu, q, x, y, z))
}
