//! The full subsurface stress field of the Hertz sphere (circular contact under Hertz pressure,
//! no shear) in closed form: Huber (1904), in the explicit Cartesian form of Hamilton &
//! Goodman (1966) and Hamilton (1983, *Proc. IMechE* 197C, "Explicit equations for the stresses
//! beneath a sliding spherical contact", the $P$ terms).
//!
//! Pressure $p(r) = p_0\sqrt{1 - r^2/a^2}$ on the surface $z = 0$ of the body $z > 0$ (crate
//! conventions: compression negative, $z$ depth). With $r^2 = x^2+y^2$,
//! $$A = r^2+z^2-a^2,\quad S = \sqrt{A^2+4a^2z^2},\quad M = \sqrt{(S+A)/2},\quad
//! N = \sqrt{(S-A)/2},\quad \phi = \arctan(a/M),$$
//! $$G = M^2 - N^2 + zM - aN,\qquad H = 2MN + aM + zN,$$
//! the stresses are, in units of $p_0/a$,
//! $$\sigma_{xx} = (1+\nu)z\phi + \frac{1}{r^2}\left[\frac{y^2-x^2}{r^2}\left((1-\nu)Nz^2 -
//! \frac{1-2\nu}{3}(NS + 2AN + a^3) - \nu Mza\right) - N(x^2 + 2\nu y^2) -
//! \frac{Mx^2za}{S}\right],$$
//! $\sigma_{yy}$ the same with $x \leftrightarrow y$,
//! $$\sigma_{zz} = -N + \frac{azM}{S},\qquad
//! \sigma_{xz} = -z\left(\frac{xN}{S} - \frac{xzH}{G^2+H^2}\right),\qquad
//! \sigma_{yz} = -z\left(\frac{yN}{S} - \frac{yzH}{G^2+H^2}\right),$$
//! $$\sigma_{xy} = \frac{xy(1-2\nu)}{r^4}\left(-Nr^2 + \tfrac23N(S+2A) - z(zN + aM) +
//! \tfrac23a^3\right) + \frac{xyz}{r^4}\left(-\frac{aMr^2}{S} - zN + aM\right).$$
//! On the axis ($r = 0$: $M = z$, $N = a$) these reduce to Johnson, *Contact Mechanics*,
//! eq. 3.45: $\sigma_{zz} = -p_0a^2/(a^2+z^2)$,
//! $\sigma_{xx} = \sigma_{yy} = p_0\left[-(1+\nu)\left(1 - \frac za\arctan\frac az\right) +
//! \frac{a^2}{2(a^2+z^2)}\right]$. FORMULAS.md E states the Hertz pressure and FORMULAS.md F
//! ("Hertz sphere, full field") this form; the tests check it against adaptive quadrature of Boussinesq's point-force stresses over the
//! Hertz pressure and against the axis forms.
//!
//! Accuracy: the $1/r^2$ and $1/r^4$ terms cancel near the axis, costing about
//! $\epsilon\,a^2/r^2$ relative; below $r = 10^{-4}a$ the axis form is used instead (error
//! $O(r^2/a^2)$), so the worst relative error is about $10^{-8}$ in a thin cylinder around the
//! axis and rounding level elsewhere.

use super::HertzSphere;
use crate::error::{finite, Error};
use crate::{Material, Stress3};

/// Stress at $(x, y, z)$, $z > 0$, under the Hertz pressure $p_0\sqrt{1-r^2/a^2}$ of radius $a$
/// (Huber 1904; Hamilton & Goodman 1966; Hamilton 1983, module documentation for the
/// formulas). Unchecked: $z \le 0$ or non-finite input gives meaningless output.
#[must_use]
pub fn hertz_sphere_stress(a: f64, p0: f64, nu: f64, x: f64, y: f64, z: f64) -> Stress3 {
    let r2 = x * x + y * y;
    let k = p0 / a;
    if r2 < 1e-8 * a * a {
        // Axis (Johnson eq. 3.45).
        let zeta2 = z * z + a * a;
        let sr = p0 * (-(1.0 + nu) * (1.0 - z / a * (a / z).atan()) + 0.5 * a * a / zeta2);
        return Stress3 { xx: sr, yy: sr, zz: -p0 * a * a / zeta2, xy: 0.0, xz: 0.0, yz: 0.0 };
    }
    let aa = r2 + z * z - a * a;
    let s = (aa * aa + 4.0 * a * a * z * z).sqrt();
    // M^2 = (S + A)/2, N^2 = (S - A)/2 with M N = a z: take the larger from the sum without
    // cancellation and the other from the product.
    let (m, n) = if aa >= 0.0 {
        let m = (0.5 * (s + aa)).sqrt();
        (m, a * z / m)
    } else {
        let n = (0.5 * (s - aa)).sqrt();
        (a * z / n, n)
    };
    let phi = (a / m).atan();
    let g = m * m - n * n + z * m - a * n;
    let h = 2.0 * m * n + a * m + z * n;
    let (x2, y2) = (x * x, y * y);
    let bracket = (1.0 - nu) * n * z * z
        - (1.0 - 2.0 * nu) / 3.0 * (n * s + 2.0 * aa * n + a * a * a)
        - nu * m * z * a;
    let sxx = (1.0 + nu) * z * phi
        + ((y2 - x2) / r2 * bracket - n * (x2 + 2.0 * nu * y2) - m * x2 * z * a / s) / r2;
    let syy = (1.0 + nu) * z * phi
        + ((x2 - y2) / r2 * bracket - n * (y2 + 2.0 * nu * x2) - m * y2 * z * a / s) / r2;
    let szz = -n + a * z * m / s;
    let r4 = r2 * r2;
    let sxy = x * y * (1.0 - 2.0 * nu) / r4
        * (-n * r2 + 2.0 / 3.0 * n * (s + 2.0 * aa) - z * (z * n + a * m) + 2.0 / 3.0 * a * a * a)
        + x * y * z / r4 * (-a * m * r2 / s - z * n + a * m);
    let t = n / s - z * h / (g * g + h * h);
    Stress3 {
        xx: k * sxx,
        yy: k * syy,
        zz: k * szz,
        xy: k * sxy,
        xz: -k * z * x * t,
        yz: -k * z * y * t,
    }
}

impl HertzSphere {
    /// Subsurface stress at $(x, y, z)$ ($z > 0$, origin at the contact centre) in the body
    /// of Poisson ratio $\nu$, from [`hertz_sphere_stress`] with this contact's $a$ and $p_0$
    /// (Huber 1904; Hamilton 1983; on the axis Johnson eq. 3.45).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for non-finite coordinates, $z \le 0$ or $\nu \notin (-1, 1/2]$.
    pub fn stress(&self, nu: f64, x: f64, y: f64, z: f64) -> Result<Stress3, Error> {
        Material::new(1.0, nu)?;
        finite("x", x)?;
        finite("y", y)?;
        if !(z.is_finite() && z > 0.0) {
            return Err(Error::OutOfDomain { name: "z", value: z, allowed: "finite, > 0" });
        }
        Ok(hertz_sphere_stress(self.contact_radius(), self.max_pressure(), nu, x, y, z))
    }
}

/// The surface tensile peak at the trailing edge $x = -a$ of a sphere sliding with friction
/// coefficient $f$ (shear $q = fp$ on the body along $+x$):
/// $$\sigma_{xx}(-a, 0, 0) = p_0\left[\frac{1-2\nu}{3} + \frac{\pi(4+\nu)}{8}f\right]$$
/// (Hamilton & Goodman 1966; Hamilton 1983; Johnson, *Contact Mechanics*, §7.2): the pressure
/// part is Johnson eq. 3.45 at $r = a$. The subsurface field approaches it like
/// $\sqrt{z/a}$ (the tests check it against quadrature at $z = 10^{-6}a$).
#[must_use]
pub fn sliding_trailing_edge_tension(p0: f64, nu: f64, f: f64) -> f64 {
    p0 * ((1.0 - 2.0 * nu) / 3.0 + std::f64::consts::PI * (4.0 + nu) / 8.0 * f)
}

/// A stress with the quadrature's error estimate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StressEstimate {
    /// The stress.
    pub stress: Stress3,
    /// Estimated absolute error (the largest over the components; inner errors included).
    pub error: f64,
    /// Point-force evaluations spent.
    pub evals: usize,
}

/// Stress at $(x, y, z)$, $z > 0$, under a sliding sphere: Hertz pressure
/// $p = p_0\sqrt{1-r^2/a^2}$ plus the shear $q_x = fp$ on the body along $+x$. The pressure part
/// is the closed form [`hertz_sphere_stress`]; the shear part is **not** Hamilton's (1983)
/// closed form but adaptive Gauss–Kronrod quadrature (relative tolerance `rel_tol`) of
/// Cerruti's point-force stresses (Johnson eq. 3.87) over the traction,
/// $$\sigma^{q} = \int_0^{2\pi}\!\!\int_0^{\pi/2} f p_0\cos u\;\sigma^{\text{Cerruti}}
/// (x - \rho\cos\theta,\ y - \rho\sin\theta,\ z)\ \rho\,a\cos u\ du\,d\theta,\quad
/// \rho = a\sin u,$$
/// which makes the square-root edge smooth; breakpoints at the field point's azimuth and
/// radius. Costs about $10^5$ point evaluations per field point.
///
/// # Errors
/// [`Error::OutOfDomain`] for non-finite input, $a \le 0$, $z \le 0$, $\nu \notin (-1, 1/2]$,
/// `rel_tol` outside $[10^{-13}, 10^{-2}]$; [`Error::Quadrature`] if the integrator fails.
pub fn sliding_sphere_stress(
    a: f64,
    p0: f64,
    f: f64,
    nu: f64,
    (x, y, z): (f64, f64, f64),
    rel_tol: f64,
) -> Result<StressEstimate, Error> {
    use crate::point_load::cerruti_stress;
    use std::f64::consts::PI;
    use stickslip_quad::{gauss_kronrod, AdaptiveConfig, Tolerance};
    Material::new(1.0, nu)?;
    crate::error::positive("a", a)?;
    finite("p0", p0)?;
    finite("f", f)?;
    finite("x", x)?;
    finite("y", y)?;
    if !(z.is_finite() && z > 0.0) {
        return Err(Error::OutOfDomain { name: "z", value: z, allowed: "finite, > 0" });
    }
    if !(1e-13..=1e-2).contains(&rel_tol) {
        return Err(Error::OutOfDomain {
            name: "rel_tol",
            value: rel_tol,
            allowed: "[1e-13, 1e-2]",
        });
    }
    let normal = hertz_sphere_stress(a, p0, nu, x, y, z);
    let q0 = f * p0;
    if q0 == 0.0 {
        return Ok(StressEstimate { stress: normal, error: 0.0, evals: 0 });
    }
    let th0 = y.atan2(x).rem_euclid(2.0 * PI);
    let r = x.hypot(y);
    let u0 = if r < a { (r / a).asin() } else { 0.5 * PI };
    let abs = 1e-3 * rel_tol * q0.abs();
    let cfg = |bp: f64, abs: f64| -> Result<AdaptiveConfig, Error> {
        let q = |e: stickslip_quad::Error| Error::Quadrature {
            what: "sliding sphere shear part",
            message: e.to_string(),
        };
        AdaptiveConfig::new(Tolerance::new(abs, rel_tol).map_err(q)?)
            .with_breakpoints(vec![bp])
            .and_then(|c| c.with_max_subdivisions(5000))
            .map_err(q)
    };
    let inner_cfg = cfg(u0, 0.1 * abs)?;
    let outer_cfg = cfg(th0, abs)?;
    let mut out = [0.0; 6];
    let (mut error, mut evals) = (0.0f64, 0usize);
    for (k, o) in out.iter_mut().enumerate() {
        let mut inner_err = 0.0f64;
        let mut failed: Option<String> = None;
        let outer = gauss_kronrod(
            |th| {
                let (s, c) = th.sin_cos();
                let res = gauss_kronrod(
                    |u| {
                        let rho = a * u.sin();
                        let w = q0 * u.cos() * a * u.cos() * rho;
                        let st = cerruti_stress(nu, 1.0, x - rho * c, y - rho * s, z);
                        w * [st.xx, st.yy, st.zz, st.xy, st.xz, st.yz][k]
                    },
                    0.0,
                    0.5 * PI,
                    &inner_cfg,
                );
                match res {
                    Ok(e) => {
                        inner_err = inner_err.max(e.error);
                        evals += e.evals;
                        e.value
                    }
                    Err(e) => {
                        failed = Some(e.to_string());
                        0.0
                    }
                }
            },
            0.0,
            2.0 * PI,
            &outer_cfg,
        )
        .map_err(|e| Error::Quadrature {
            what: "sliding sphere shear part",
            message: e.to_string(),
        })?;
        if let Some(message) = failed {
            return Err(Error::Quadrature { what: "sliding sphere shear part (inner)", message });
        }
        *o = outer.value;
        error = error.max(outer.error + 2.0 * PI * inner_err);
    }
    let [xx, yy, zz, xy, xz, yz] = out;
    let stress = Stress3 {
        xx: normal.xx + xx,
        yy: normal.yy + yy,
        zz: normal.zz + zz,
        xy: normal.xy + xy,
        xz: normal.xz + xz,
        yz: normal.yz + yz,
    };
    Ok(StressEstimate { stress, error, evals })
}
