//! Adhesive contact of a sphere: Maugis's solution for the Dugdale cohesive zone (Maugis
//! 1992, *J. Colloid Interface Sci.* 150, 243–269), which joins the JKR and DMT theories.
//!
//! A sphere of radius $R$ (the relative radius of the two bodies) presses an elastic
//! half-space (composite modulus $E^*$). Where the gap lies below the range $h_0$ a constant
//! attraction $\sigma_0 = w/h_0$ acts ($w$ the work of adhesion), outside the contact of
//! radius $a$ out to the radius $c$ of the cohesive zone. With Johnson & Greenwood's
//! dimensionless variables (1997, *J. Colloid Interface Sci.* 192, 326–333), $K = \tfrac43E^*$,
//! $$A = a\Big(\frac{K}{\pi wR^2}\Big)^{1/3},\quad
//!   \bar P = \frac{P}{\pi wR},\quad
//!   \bar\Delta = \delta\Big(\frac{K^2}{\pi^2w^2R}\Big)^{1/3},\quad
//!   \lambda = 2\sigma_0\Big(\frac{R}{\pi wK^2}\Big)^{1/3},$$
//! and, for the ratio $m = c/a > 1$, $s = \sqrt{m^2-1}$, $t = \arctan s$, the contact radius
//! is the positive root of
//! $$\tfrac12\lambda A^2\big[s + (m^2-2)t\big] + \tfrac43\lambda^2A\big[st - m + 1\big] = 1,$$
//! and then
//! $$\bar P = A^3 - \lambda A^2\big[s + m^2t\big],\qquad
//!   \bar\Delta = A^2 - \tfrac43\lambda As.$$
//! The solution is a curve parametrised by $m$: $m \to 1$ is the large contact (where the
//! cohesive zone shrinks to the contact edge), $m \to \infty$ the contact shrinking to a
//! point. $\lambda$ (Maugis's parameter, about Tabor's $\mu$ times 1.16) says which theory
//! applies: above about 5 JKR (pull-off $-\tfrac32\pi wR$), below about 0.1 DMT
//! (pull-off $-2\pi wR$).
//!
//! The pull-off here is the most tensile force along the curve: under force control the
//! load at which the contact separates, under approach control the most tensile force a
//! path passes through (where JKR contacts jump out later, at a smaller force).

use std::f64::consts::PI;

use crate::error::{positive, Error};

/// One state of Maugis's solution, in SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MaugisPoint {
    /// The ratio $m = c/a$ of the cohesive zone's radius to the contact's.
    pub m: f64,
    /// Contact radius $a$ (m).
    pub contact_radius: f64,
    /// Radius of the cohesive zone $c = ma$ (m).
    pub zone_radius: f64,
    /// Normal force $P$ (N; negative when the bodies pull).
    pub force: f64,
    /// Approach $\delta$ of distant points (m; negative when held apart).
    pub approach: f64,
}

/// Maugis's solution for a sphere with a Dugdale cohesive zone (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MaugisSphere {
    radius: f64,
    work: f64,
    lambda: f64,
    /// Scales of a, P and delta.
    scale: [f64; 3],
}

impl MaugisSphere {
    /// The sphere of relative radius `radius` (m) with the work of adhesion `work` (J/m²)
    /// and the range `range` (m) of the attraction $w/h_0$, on composite modulus `e_star`.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] unless every input is finite and positive.
    pub fn new(radius: f64, work: f64, range: f64, e_star: f64) -> Result<Self, Error> {
        positive("radius", radius)?;
        positive("work of adhesion", work)?;
        positive("range", range)?;
        positive("composite modulus", e_star)?;
        let k = 4.0 / 3.0 * e_star;
        let stress = work / range;
        let lambda = 2.0 * stress * (radius / (PI * work * k * k)).cbrt();
        let scale = [
            (PI * work * radius * radius / k).cbrt(),
            PI * work * radius,
            (PI * PI * work * work * radius / (k * k)).cbrt(),
        ];
        Ok(Self { radius, work, lambda, scale })
    }

    /// Maugis's parameter $\lambda$.
    #[must_use]
    pub fn lambda(&self) -> f64 {
        self.lambda
    }

    /// JKR's pull-off $-\tfrac32\pi wR$ (N), the limit of large $\lambda$.
    #[must_use]
    pub fn jkr_pull_off(&self) -> f64 {
        -1.5 * PI * self.work * self.radius
    }

    /// DMT's pull-off $-2\pi wR$ (N), the limit of small $\lambda$.
    #[must_use]
    pub fn dmt_pull_off(&self) -> f64 {
        -2.0 * PI * self.work * self.radius
    }

    /// The dimensionless state $(A, \bar P, \bar\Delta)$ at the ratio `m` > 1.
    #[must_use]
    pub fn dimensionless(&self, m: f64) -> (f64, f64, f64) {
        let l = self.lambda;
        let s = (m * m - 1.0).max(0.0).sqrt();
        let t = s.atan();
        // q2 A^2 + q1 A = 1; the positive root written without cancellation.
        let q2 = 0.5 * l * (s + (m * m - 2.0) * t);
        let q1 = 4.0 / 3.0 * l * l * (s * t - m + 1.0);
        let a = 2.0 / (q1 + (q1 * q1 + 4.0 * q2).sqrt());
        (a, a * a * a - l * a * a * (s + m * m * t), a * a - 4.0 / 3.0 * l * a * s)
    }

    /// The state at the ratio `m` = c/a > 1, in SI.
    #[must_use]
    pub fn at(&self, m: f64) -> MaugisPoint {
        let (a, p, d) = self.dimensionless(m);
        let a = a * self.scale[0];
        MaugisPoint {
            m,
            contact_radius: a,
            zone_radius: m * a,
            force: p * self.scale[1],
            approach: d * self.scale[2],
        }
    }

    /// The curve from the large contact to the vanishing one: `points` states at $m - 1$
    /// spaced geometrically from $10^{-10}$ to $10^{6}$.
    #[must_use]
    pub fn curve(&self, points: usize) -> Vec<MaugisPoint> {
        let n = points.max(2);
        (0..n).map(|i| self.at(1.0 + Self::excess(i as f64 / (n - 1) as f64))).collect()
    }

    /// $m - 1$ at the fraction `u` of the parameter range (geometric, $10^{-10}$ to $10^6$).
    fn excess(u: f64) -> f64 {
        10f64.powf(-10.0 + 16.0 * u)
    }

    /// The pull-off: the state of the most tensile force along the curve (a scan of 4,000
    /// states, refined by golden-section search to about $10^{-12}$ in the parameter).
    #[must_use]
    pub fn pull_off(&self) -> MaugisPoint {
        let n = 4000;
        let force = |u: f64| self.dimensionless(1.0 + Self::excess(u)).1;
        let mut best = 0;
        let mut fbest = f64::INFINITY;
        for i in 0..n {
            let f = force(i as f64 / (n - 1) as f64);
            if f < fbest {
                fbest = f;
                best = i;
            }
        }
        let h = 1.0 / (n - 1) as f64;
        let (mut lo, mut hi) = ((best as f64 - 1.0) * h, (best as f64 + 1.0) * h);
        lo = lo.max(0.0);
        hi = hi.min(1.0);
        let g = (5f64.sqrt() - 1.0) / 2.0;
        while hi - lo > 1e-13 {
            let (u1, u2) = (hi - g * (hi - lo), lo + g * (hi - lo));
            if force(u1) < force(u2) {
                hi = u2;
            } else {
                lo = u1;
            }
        }
        self.at(1.0 + Self::excess(0.5 * (lo + hi)))
    }

    /// The force on the large-contact branch at the approach `delta` (m): the first
    /// crossing of `delta` from the large contact, linearly interpolated on a curve of
    /// 20,000 states; `None` when the branch never reaches it.
    #[must_use]
    pub fn force_at_approach(&self, delta: f64) -> Option<f64> {
        let c = self.curve(20_000);
        c.windows(2).find_map(|w| {
            let (d0, d1) = (w[0].approach, w[1].approach);
            ((d0 - delta) * (d1 - delta) <= 0.0 && d0 != d1).then(|| {
                let t = (delta - d0) / (d1 - d0);
                w[0].force + t * (w[1].force - w[0].force)
            })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sphere(lambda: f64) -> MaugisSphere {
        // R = 1 um, w = 0.05 J/m^2, E* = 1 GPa; the range that gives `lambda`.
        let (r, w, e) = (1e-6, 0.05, 1e9);
        let k = 4.0 / 3.0 * e;
        let stress = lambda / (2.0 * (r / (PI * w * k * k)).cbrt());
        MaugisSphere::new(r, w, w / stress, e).unwrap()
    }

    #[test]
    fn pull_off_tends_to_jkr_and_dmt() {
        let jkr = sphere(1e4);
        let p = jkr.pull_off().force / jkr.jkr_pull_off();
        assert!((p - 1.0).abs() < 2e-3, "JKR limit: {p}");
        let dmt = sphere(1e-4);
        let p = dmt.pull_off().force / dmt.dmt_pull_off();
        assert!((p - 1.0).abs() < 2e-3, "DMT limit: {p}");
        // Between the limits the pull-off moves monotonically from DMT to JKR.
        let mut last = 2.0;
        for l in [0.05, 0.1, 0.3, 1.0, 3.0, 10.0] {
            let s = sphere(l);
            let p = s.pull_off().force / (PI * 0.05 * 1e-6);
            assert!(p < -1.5 && p > -2.0 && -p < last, "lambda {l}: {p}");
            last = -p;
        }
    }

    #[test]
    fn large_lambda_follows_jkr_load_and_approach() {
        // JKR in these variables: P = A^3 - sqrt(6 A^3), Delta = A^2 - (2/3) sqrt(6 A).
        let s = sphere(1e5);
        for m in [1.0 + 1e-7, 1.0 + 1e-6, 1.0 + 1e-5] {
            let (a, p, d) = s.dimensionless(m);
            let pj = a.powi(3) - (6.0 * a.powi(3)).sqrt();
            let dj = a * a - 2.0 / 3.0 * (6.0 * a).sqrt();
            assert!((p - pj).abs() < 1e-2 * (1.0 + pj.abs()), "P at m {m}: {p} vs {pj}");
            assert!((d - dj).abs() < 1e-2 * (1.0 + dj.abs()), "Delta at m {m}: {d} vs {dj}");
        }
    }

    #[test]
    fn small_lambda_follows_dmt_hertz_with_constant_pull() {
        // DMT: a Hertz contact, P = A^3 - 2, Delta = A^2 (checked where A is of order one;
        // the deviation of the approach falls like lambda^(2/3)).
        let s = sphere(1e-6);
        let mut checked = 0;
        for p in s.curve(4000) {
            let a = p.contact_radius / s.scale[0];
            if (0.3..3.0).contains(&a) {
                let (pf, d) = (p.force / s.scale[1], p.approach / s.scale[2]);
                assert!((pf - (a.powi(3) - 2.0)).abs() < 1e-2, "P at A {a}: {pf}");
                assert!((d - a * a).abs() < 1e-2 * (a * a).max(1.0), "Delta at A {a}: {d}");
                checked += 1;
            }
        }
        assert!(checked > 100, "{checked} states checked");
    }

    #[test]
    fn refuses_bad_inputs() {
        assert!(MaugisSphere::new(0.0, 0.05, 1e-9, 1e9).is_err());
        assert!(MaugisSphere::new(1e-6, f64::NAN, 1e-9, 1e9).is_err());
        assert!(MaugisSphere::new(1e-6, 0.05, -1e-9, 1e9).is_err());
    }
}
