//! The subsurface field of an elliptic Hertz contact, $p = p_0\sqrt{1-x^2/a^2-y^2/b^2}$,
//! optionally with a full-sliding shear $q_x = fp$ on the body along $+x$ (Hamilton 1983 for
//! the circle; Sackfield & Hills 1983 for the ellipse). $a = b$ is the sliding sphere.
//!
//! Method (derived in docs/book, "Subsurface fields", and in the header of
//! `scripts/hertz_ellipse_field.py`): Love's (1929) representation writes the stresses of a
//! surface load as derivatives of $\Phi$, the twice $z$-integrated Newtonian potential of the
//! load density. For the Hertz density that potential is one integral over the ellipsoidal
//! coordinate $s$,
//! $$\Phi = \frac{\pi ab}{2}\int_\lambda^\infty \frac{(W-z)^3(3W+z)}{12\,s\sqrt{(a^2+s)(b^2+s)s}}
//! \,ds,\qquad W^2 = s\Big(1-\frac{x^2}{a^2+s}-\frac{y^2}{b^2+s}\Big),$$
//! $\lambda$ the positive root of $x^2/(a^2+\lambda)+y^2/(b^2+\lambda)+z^2/\lambda = 1$ (Love 1929;
//! Johnson, *Contact Mechanics*, eq. 3.52 for $\Phi_{zz}$). Differentiating under the integral
//! (with the end terms at $s = \lambda$, where $W = z$) gives every stress component as
//! $\int_\lambda^\infty J_{ij}(s)\,ds + B_{ij}(\lambda)$; sympy writes $J$ and $B$
//! (`ellipse_field_terms.rs`, generated). The integral is taken by adaptive Gauss–Legendre,
//! all six components together, in $d = s - \lambda$ on geometric panels from
//! $10^{-2}\min(\lambda, z^2)$ to $c = \max(\lambda, a^2, b^2)$ and in $t = \sqrt{c/d}$ beyond.
//!
//! Checks (tests/hertz_load_field.rs; measured worst in brackets): $a = b$ without shear
//! against the closed form [`super::sphere_field::hertz_sphere_stress`] (tolerance
//! $10^{-10}p_0$; $6\times10^{-13}p_0$); the sliding sphere against the Cerruti quadrature
//! [`super::sphere_field::sliding_sphere_stress`] ($10^{-8}p_0$; $7\times10^{-16}p_0$) and
//! [`super::sphere_field::sliding_trailing_edge_tension`]; the ellipse against Boussinesq +
//! Cerruti quadrature over the ellipse and its axis $\sigma_z = -p_0ab/\sqrt{(a^2+z^2)(b^2+z^2)}$.
//! Cost: about 1,200 integrand evaluations, 20–40 µs, per point.

use super::ellipse_field_terms::{normal_end, normal_integrand, shear_end, shear_integrand};
use super::sphere_field::StressEstimate;
use crate::error::{finite, positive, Error};
use crate::{Material, Stress3};
use stickslip_quad::{GaussLegendre, Rule};

/// An elliptic Hertz load on the surface of a half-space: semi-axes $a$ (along $x$) and $b$,
/// peak pressure $p_0$ and a sliding shear $q_x = fp$ along $+x$.
#[derive(Debug, Clone, PartialEq)]
pub struct HertzLoadField {
    a: f64,
    b: f64,
    p0: f64,
    f: f64,
    nu: f64,
    pressure: bool,
    hi: GaussLegendre,
    lo: GaussLegendre,
}

/// Tolerance of the $s$ integral in [`HertzLoadField::stress`]: absolute, in units of $p_0$,
/// summed over the panels (the largest component per panel).
pub const FIELD_TOLERANCE: f64 = 1e-11;

impl HertzLoadField {
    /// The load $p_0\sqrt{1-x^2/a^2-y^2/b^2}$ with shear $fp$ along $+x$ on a body of
    /// Poisson ratio $\nu$.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for $a, b \le 0$, non-finite $p_0$ or $f$, $\nu \notin (-1, 1/2]$.
    pub fn new(a: f64, b: f64, p0: f64, f: f64, nu: f64) -> Result<Self, Error> {
        Material::new(1.0, nu)?;
        positive("a", a)?;
        positive("b", b)?;
        finite("p0", p0)?;
        finite("f", f)?;
        let rule = |n| {
            GaussLegendre::new(n)
                .map_err(|e| Error::Quadrature { what: "Hertz field rule", message: e.to_string() })
        };
        Ok(Self { a, b, p0, f, nu, pressure: true, hi: rule(20)?, lo: rule(10)? })
    }

    /// The shear $fp$ alone, without the pressure (for superposing shears in other
    /// directions).
    #[must_use]
    pub fn without_pressure(mut self) -> Self {
        self.pressure = false;
        self
    }

    /// Stress at $(x, y, z)$, $z > 0$ (module documentation for the method), with the
    /// estimated absolute error of the $s$ integral.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for non-finite coordinates or $z \le 0$;
    /// [`Error::Quadrature`] if the integral does not reach [`FIELD_TOLERANCE`].
    pub fn stress(&self, x: f64, y: f64, z: f64) -> Result<StressEstimate, Error> {
        finite("x", x)?;
        finite("y", y)?;
        if !(z.is_finite() && z > 0.0) {
            return Err(Error::OutOfDomain { name: "z", value: z, allowed: "finite, > 0" });
        }
        let (a, b, nu) = (self.a, self.b, self.nu);
        // Work in units of a: the generated terms are homogeneous.
        let (x, y, z, bb) = (x / a, y / a, z / a, b / a);
        let lam = ellipsoidal_coordinate(x, y, z, bb);
        let (q, pressure) = (self.f, self.pressure);
        // Integrand at s = lam + d, with W^2 = z^2 + d kappa(s) (no cancellation of d against
        // lam: the near-surface features have width ~ z^2, far below lam outside the contact).
        let (a2, b2) = (1.0, bb * bb);
        let integrand = |d: f64| -> [f64; 6] {
            let s = lam + d;
            let kappa =
                1.0 - x * x * a2 / ((a2 + s) * (a2 + lam)) - y * y * b2 / ((b2 + s) * (b2 + lam));
            let w = (z * z + d * kappa).max(0.0).sqrt();
            let n = if pressure { normal_integrand(s, w, x, y, z, 1.0, bb, nu) } else { [0.0; 6] };
            if q == 0.0 {
                return n;
            }
            let t = shear_integrand(s, w, x, y, z, 1.0, bb, nu);
            std::array::from_fn(|k| n[k] + q * t[k])
        };
        let c = lam.max(1.0).max(b2);
        // Near part d in [0, c], geometric panels from 1e-2 min(lam, z^2) up.
        let mut cuts = vec![0.0, c];
        let mut d = 1e-2 * lam.min(z * z);
        while d < c && d > 0.0 {
            cuts.push(d);
            d *= 4.0;
        }
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
        let (near, e_near, n_near) = self.adaptive(&integrand, &cuts)?;
        // Far part d = c / t^2, t in (0, 1], dd = 2c / t^3 dt.
        let far_f = |t: f64| -> [f64; 6] {
            let j = integrand(c / (t * t));
            let w = 2.0 * c / (t * t * t);
            std::array::from_fn(|k| j[k] * w)
        };
        let (far, e_far, n_far) = self.adaptive(&far_f, &[0.0, 0.5, 1.0])?;
        let val: [f64; 6] = std::array::from_fn(|k| near[k] + far[k]);
        let err = e_near + e_far;
        let nend = if pressure { normal_end(lam, x, y, z, 1.0, bb, nu) } else { [0.0; 6] };
        let tend = if q == 0.0 { [0.0; 6] } else { shear_end(lam, x, y, z, 1.0, bb, nu) };
        let out: [f64; 6] = std::array::from_fn(|k| self.p0 * (val[k] + nend[k] + q * tend[k]));
        let [xx, yy, zz, xy, xz, yz] = out;
        Ok(StressEstimate {
            stress: Stress3 { xx, yy, zz, xy, xz, yz },
            error: self.p0.abs() * err,
            evals: n_near + n_far,
        })
    }

    /// Vector adaptive Gauss–Legendre (20 points, error from the 10-point rule) on the panels
    /// between `cuts`, bisecting the worst panel until the summed error is below
    /// [`FIELD_TOLERANCE`] (absolute, per unit $p_0$).
    fn adaptive(
        &self,
        f: &dyn Fn(f64) -> [f64; 6],
        cuts: &[f64],
    ) -> Result<([f64; 6], f64, usize), Error> {
        let evals = std::cell::Cell::new(0usize);
        let panel = |lo: f64, hi: f64| -> ([f64; 6], f64) {
            evals.set(evals.get() + self.hi.len() + self.lo.len());
            let (m, h) = (0.5 * (lo + hi), 0.5 * (hi - lo));
            let apply = |r: &GaussLegendre| {
                let mut acc = [0.0; 6];
                for (xn, wn) in r.nodes().iter().zip(r.weights()) {
                    let v = f(m + h * xn);
                    for (s, vk) in acc.iter_mut().zip(v) {
                        *s += h * wn * vk;
                    }
                }
                acc
            };
            let (hi_v, lo_v) = (apply(&self.hi), apply(&self.lo));
            let e = (0..6).map(|k| (hi_v[k] - lo_v[k]).abs()).fold(0.0, f64::max);
            (hi_v, e)
        };
        let mut panels: Vec<(f64, f64, [f64; 6], f64)> = cuts
            .windows(2)
            .map(|w| {
                let (v, e) = panel(w[0], w[1]);
                (w[0], w[1], v, e)
            })
            .collect();
        for _ in 0..2000 {
            let total: f64 = panels.iter().map(|p| p.3).sum();
            if total < FIELD_TOLERANCE {
                let mut sum = [0.0; 6];
                for p in &panels {
                    for (s, pk) in sum.iter_mut().zip(p.2) {
                        *s += pk;
                    }
                }
                return Ok((sum, total, evals.get()));
            }
            let (i, _) = panels
                .iter()
                .enumerate()
                .max_by(|p, q| p.1 .3.total_cmp(&q.1 .3))
                .expect("at least one panel");
            let (lo, hi, _, _) = panels.swap_remove(i);
            let mid = 0.5 * (lo + hi);
            for (l, h) in [(lo, mid), (mid, hi)] {
                let (v, e) = panel(l, h);
                panels.push((l, h, v, e));
            }
        }
        let total: f64 = panels.iter().map(|p| p.3).sum();
        Err(Error::Quadrature {
            what: "Hertz field s-integral",
            message: format!("error {total:.1e} after 2000 bisections"),
        })
    }
}

/// The positive root $\lambda$ of $x^2/(1+\lambda) + y^2/(b^2+\lambda) + z^2/\lambda = 1$
/// ($z > 0$, lengths in units of $a$) by safeguarded Newton on the decreasing left side.
fn ellipsoidal_coordinate(x: f64, y: f64, z: f64, b: f64) -> f64 {
    let g = |l: f64| x * x / (1.0 + l) + y * y / (b * b + l) + z * z / l - 1.0;
    let dg = |l: f64| {
        -(x * x / ((1.0 + l) * (1.0 + l)) + y * y / ((b * b + l) * (b * b + l)) + z * z / (l * l))
    };
    // g(lo) > 0 > g(hi)
    let mut lo = z * z * 0.5_f64.min(1.0);
    while g(lo) <= 0.0 {
        lo *= 0.5;
    }
    let mut hi = x * x + y * y + z * z + 1.0;
    let mut l = 0.5 * (lo + hi);
    for _ in 0..200 {
        let v = g(l);
        if v == 0.0 {
            return l;
        }
        if v > 0.0 {
            lo = l;
        } else {
            hi = l;
        }
        let step = l - v / dg(l);
        let next = if step >= lo && step <= hi { step } else { 0.5 * (lo + hi) };
        let done = (next - l).abs() <= 2.0 * f64::EPSILON * l;
        l = next;
        if done {
            break;
        }
    }
    l
}
