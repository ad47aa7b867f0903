//! The one integral behind the stress formulas (12) and (13) of Goryacheva 1973 (seed 001), in
//! the corrected forms of FORMULAS.md section D.
//!
//! With $t = d + L\cos\theta$ on a zone $(d-L, d+L)$ one has
//! $dt/\sqrt{(t-d+L)(d+L-t)} = d\theta$, so the endpoint square roots of eqs 12/13 disappear,
//! and both stresses become
//! $$J(\theta_x) = \int_0^{\theta_x}\left[c_0 + c_1\cos\theta + c_2\sin^2\theta\right]
//!   e^{-\kappa(\cos\theta-\cos\theta_x)}\,d\theta,\qquad \kappa = \frac{L}{\beta w},$$
//! where $\theta_x$ is the angle of the field point. The exponent is $\le 0$ on the whole range
//! and is evaluated as $-2\kappa\sin(\theta_x-\frac u2)\sin\frac u2$ in the variable
//! $u = \theta_x - \theta$, free of cancellation and of the node rounding that $\kappa$ would
//! otherwise magnify. For large $\kappa$ the integrand is a boundary layer at $\theta_x$; the range
//! is cut where the exponent reaches $-60$ (relative truncation $e^{-60}\approx 10^{-26}$),
//! which leaves an interval matched to the layer, and the rest is adaptive Gauss–Kronrod.
//!
//! Integration by parts: $\frac{d}{d\theta}\left[\sin\theta\, e^{-\kappa(\cos\theta-
//! \cos\theta_x)}\right] = (\cos\theta + \kappa\sin^2\theta)\,e^{\dots}$, so
//! $J = c_1\sin\theta_x + \int_0^{\theta_x}[c_0 + (c_2 - \kappa c_1)\sin^2\theta]e^{\dots}d\theta$.
//! This form is used whenever $|c_2-\kappa c_1| \le |c_1|$: it is exact in the elastic limit
//! (where $c_0 = c_2 - \kappa c_1 = 0$) and removes the large $c_1$ term when
//! $\beta w \gg L$. Otherwise the integrand is summed as
//! $f_a\sin^2\frac\theta2 + f_b\cos^2\frac\theta2 + c_2\sin^2\theta$ with the end values
//! $f_a = c_0 - c_1$ (trailing end, $\theta = \pi$) and $f_b = c_0 + c_1$: when
//! $l \gg \beta w$ the trailing-end value $f_a$ is small, $O(\beta w)$, while $c_0$ and $c_1$
//! are $O(\alpha w)$. The caller supplies $c_0, c_1, f_a, f_b$ and $c_2 - \kappa c_1$, each in a
//! cancellation-free form.

use crate::StressConfig;
use std::f64::consts::PI;
use stickslip_quad::{
    gauss_kronrod, AdaptiveConfig, Error as QuadratureError, Estimate, Tolerance,
};

/// Exponent at which the integration range is cut.
const CUT: f64 = 60.0;

/// Coefficients of $J$ for one zone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ExpKernel {
    /// $\kappa = L/(\beta w)$.
    pub kappa: f64,
    /// Constant coefficient.
    pub c0: f64,
    /// Coefficient of $\cos\theta$.
    pub c1: f64,
    /// Value $c_0 - c_1$ of the linear part at $\theta = \pi$.
    pub fa: f64,
    /// Value $c_0 + c_1$ of the linear part at $\theta = 0$.
    pub fb: f64,
    /// Coefficient of $\sin^2\theta$.
    pub c2: f64,
    /// $c_2 - \kappa c_1$, computed by the caller without cancellation.
    pub c2_by_parts: f64,
}

impl ExpKernel {
    /// $J(\theta_x)$ for $\theta_x \in [0, \pi]$, with error estimate and evaluation count.
    pub(crate) fn integrate(
        &self,
        theta_x: f64,
        cfg: &StressConfig,
    ) -> Result<Estimate, QuadratureError> {
        if theta_x <= 0.0 {
            return Ok(Estimate { value: 0.0, error: 0.0, evals: 0 });
        }
        let by_parts = self.c2_by_parts.abs() <= self.c1.abs();
        // integrand = p0 + pa sin^2(t/2) + pb cos^2(t/2) + p2 sin^2 t
        let (boundary, p0, pa, pb, p2) = if by_parts {
            (self.c1 * theta_x.sin(), self.c0, 0.0, 0.0, self.c2_by_parts)
        } else {
            (0.0, 0.0, self.fa, self.fb, self.c2)
        };
        let sh = (0.5 * theta_x).sin();
        let s2cut = sh * sh - CUT / (2.0 * self.kappa);
        let theta_cut = if s2cut > 0.0 { 2.0 * s2cut.sqrt().asin() } else { 0.0 };
        let bound = p0.abs() + pa.abs() + pb.abs() + p2.abs();
        if bound == 0.0 {
            return Ok(Estimate { value: boundary, error: 0.0, evals: 0 });
        }
        // Stress scale for the absolute part of the tolerance: size of the integrand's terms
        // times the effective width of the exponential weight (Laplace estimate, capped by the
        // interval), so that the request is relative to the stress, not to a loose bound.
        let size = |t: f64| {
            let (sh, ch) = (0.5 * t).sin_cos();
            let s = 2.0 * sh * ch;
            p0.abs() + pa.abs() * sh * sh + pb.abs() * ch * ch + p2.abs() * s * s
        };
        let mag = size(theta_x).max(size(theta_cut)).max(size(0.5 * (theta_x + theta_cut)));
        let (sx, cx) = theta_x.sin_cos();
        let linear = 1.0 / (self.kappa * sx);
        let quadratic =
            if cx < 0.0 { (PI / (2.0 * self.kappa * cx.abs())).sqrt() } else { f64::INFINITY };
        let width = (theta_x - theta_cut).min(2.0 * linear.min(quadratic));
        let scale = boundary.abs() + mag * width;
        // Integrate in u = theta_x - theta: the exponent depends on u with full relative
        // precision (nodes in theta itself would carry an absolute rounding of
        // eps * theta_x, magnified by kappa in the exponent).
        let kappa = self.kappa;
        let f = move |u: f64| {
            let t = theta_x - u;
            let (sh, ch) = (0.5 * t).sin_cos();
            let s = 2.0 * sh * ch;
            let expo = -2.0 * kappa * (theta_x - 0.5 * u).sin() * (0.5 * u).sin();
            (p0 + pa * sh * sh + pb * ch * ch + p2 * s * s) * expo.exp()
        };
        let abs = cfg.tol.abs().max(cfg.tol.rel() * scale);
        let tol = Tolerance::new(abs, cfg.tol.rel())?;
        let acfg = AdaptiveConfig::new(tol).with_max_subdivisions(cfg.max_subdivisions)?;
        let est = gauss_kronrod(f, 0.0, theta_x - theta_cut, &acfg)?;
        let truncation = if theta_cut > 0.0 { (-CUT).exp() * bound * theta_cut } else { 0.0 };
        Ok(Estimate {
            value: est.value + boundary,
            error: est.error + truncation,
            evals: est.evals,
        })
    }
}

/// Angle of $x$ on the zone $(\text{lo}, \text{hi})$: $\theta_x = 2\arctan\sqrt{(hi-x)/(x-lo)}$,
/// so that $x = \frac{lo+hi}2 + \frac{hi-lo}2\cos\theta_x$ ($\theta = 0$ at hi, $\pi$ at lo).
pub(crate) fn angle(x: f64, lo: f64, hi: f64) -> f64 {
    2.0 * (hi - x).max(0.0).sqrt().atan2((x - lo).max(0.0).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The by-parts identity: with c0 = 0, c1 = 1, c2 = kappa the integral is sin(theta_x)
    /// exactly, for every kappa; both evaluation paths must give it.
    #[test]
    fn derivative_identity_both_paths() {
        let cfg = StressConfig::default();
        let mut worst: f64 = 0.0;
        for &kappa in &[1e-6, 0.3, 1.0, 7.0, 1e3, 1e7] {
            for &tx in &[1e-6, 0.1, 1.0, 2.0, 3.0, std::f64::consts::PI] {
                // by-parts path (c2 - kappa c1 = 0)
                let k = ExpKernel {
                    kappa,
                    c0: 0.0,
                    c1: 1.0,
                    fa: -1.0,
                    fb: 1.0,
                    c2: kappa,
                    c2_by_parts: 0.0,
                };
                let j = k.integrate(tx, &cfg).unwrap();
                worst = worst.max((j.value - tx.sin()).abs());
                // direct path: pretend c2_by_parts is large so the direct sum is used
                let k2 = ExpKernel { c2_by_parts: 10.0, ..k };
                let j2 = k2.integrate(tx, &cfg).unwrap();
                let err = (j2.value - tx.sin()).abs();
                worst = worst.max(err);
                assert!(err <= 1e-11 * (1.0 + kappa * tx), "kappa {kappa} tx {tx}: {err:e}");
            }
        }
        println!("kernel identity J = sin(theta_x): worst abs error {worst:e}");
    }
}
