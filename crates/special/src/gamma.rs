//! Gamma function and its logarithm.
//!
//! Building blocks (all cited from DLMF, chapter 5):
//! - Taylor series of $\ln\Gamma$ about 1 and 2 (DLMF 5.7.3), coefficients from
//!   `scripts/special_coeffs.py`;
//! - Stirling's series (DLMF 5.11.1) for large arguments;
//! - the recurrence $\Gamma(x+1)=x\Gamma(x)$ (DLMF 5.5.1) and the reflection formula
//!   $\Gamma(x)\Gamma(-x) = -\pi/(x\sin\pi x)$ (DLMF 5.5.3).

use crate::error::{no_overflow, out_of_domain, Error};
use crate::gamma_coeffs::{LNGAMMA_AT1, LNGAMMA_AT2, STIRLING};
use std::f64::consts::PI;

/// $\tfrac12\ln(2\pi)$.
const HALF_LN_2PI: f64 = 0.918_938_533_204_672_8;
/// $\sqrt{2\pi}$.
const SQRT_2PI: f64 = 2.506_628_274_631_000_7;
/// Largest argument with $\Gamma(x)\le$ `f64::MAX`, about 171.6243769563027: above it [`gamma`] returns $+\infty$.
pub const GAMMA_MAX_ARG: f64 = 171.624_376_956_302_7;

/// Horner evaluation of $\sum_{k\ge1} c_{k-1} t^k$.
fn series(c: &[f64], t: f64) -> f64 {
    let mut acc = 0.0;
    for &ck in c.iter().rev() {
        acc = acc * t + ck;
    }
    acc * t
}

/// $\ln\Gamma(1+\varepsilon)$ for $\varepsilon\in[-0.25, 1.5]$ with $\varepsilon$ exact.
///
/// Near 0 the Taylor series about 1 is used; further out the series about 2, with
/// $\delta = \varepsilon - 1$. Both converge geometrically on their pieces
/// (ratios at most 1/4 and 3/8).
fn ln_gamma_1p(eps: f64) -> f64 {
    if eps <= 0.25 {
        series(&LNGAMMA_AT1, eps)
    } else {
        series(&LNGAMMA_AT2, eps - 1.0)
    }
}

/// Stirling's correction $S(x)=\sum_k B_{2k}/(2k(2k-1)x^{2k-1})$ for $x\ge 8$.
fn stirling_correction(x: f64) -> f64 {
    let r = 1.0 / x;
    let r2 = r * r;
    let mut acc = 0.0;
    for &c in STIRLING[..10].iter().rev() {
        acc = acc * r2 + c;
    }
    acc * r
}

/// $\ln\Gamma(x)$ for $x>0$ (no checks).
fn ln_gamma_pos(x: f64) -> f64 {
    if x < 0.75 {
        // ln Gamma(x) = ln Gamma(1+x) - ln x; ln Gamma(1+x) is small, ln x dominates.
        ln_gamma_1p(x) - x.ln()
    } else if x <= 2.5 {
        ln_gamma_1p(x - 1.0)
    } else if x < 8.0 {
        // Recurrence down to [1.5, 2.5): x - n is exact.
        let mut y = x;
        let mut prod = 1.0;
        while y >= 2.5 {
            y -= 1.0;
            prod *= y;
        }
        prod.ln() + ln_gamma_1p(y - 1.0)
    } else if x.is_infinite() {
        f64::INFINITY
    } else {
        (x - 0.5) * (x.ln() - 1.0) + (HALF_LN_2PI - 0.5) + stirling_correction(x)
    }
}

/// $\sin(\pi x)$ with exact argument reduction.
pub(crate) fn sin_pi(x: f64) -> f64 {
    let n = x.round();
    let f = x - n; // exact, |f| <= 1/2
    let s = (PI * f).sin();
    if n % 2.0 == 0.0 {
        s
    } else {
        -s
    }
}

/// $\Gamma(x)$ for $x > 0$, finite $x$ (no checks). Returns +inf above [`GAMMA_MAX_ARG`].
fn gamma_pos(x: f64) -> f64 {
    if x < 0.75 {
        ln_gamma_1p(x).exp() / x
    } else if x <= 2.5 {
        ln_gamma_1p(x - 1.0).exp()
    } else if x < 10.0 {
        let mut y = x;
        let mut prod = 1.0;
        while y >= 2.5 {
            y -= 1.0;
            prod *= y;
        }
        prod * ln_gamma_1p(y - 1.0).exp()
    } else if x >= 172.0 {
        f64::INFINITY
    } else {
        let (v, w, c) = stirling_parts(x);
        v * w * c
    }
}

/// Splits $\Gamma(z) = v\,w\,c$ for $z\ge 10$, each factor finite:
/// $v = z^{(z-1/2)/2}$, $w = v e^{-z}$, $c = \sqrt{2\pi}\,e^{S(z)}$.
fn stirling_parts(z: f64) -> (f64, f64, f64) {
    let c = SQRT_2PI * stirling_correction(z).exp();
    if z <= 140.0 {
        // One pow is more accurate than two; no overflow below 140.
        (z.powf(z - 0.5) * (-z).exp(), 1.0, c)
    } else {
        let v = z.powf(0.5 * (z - 0.5));
        (v, v * (-z).exp(), c)
    }
}

/// Gamma function $\Gamma(x)$.
///
/// $$\Gamma(x) = \int_0^\infty t^{x-1}e^{-t}\,dt,\qquad \Gamma(x)\Gamma(-x) = -\frac{\pi}{x\sin \pi x}.$$
///
/// Domain: every real $x$ except the poles $0, -1, -2, \dots$ (and NaN, $-\infty$),
/// where NaN is returned. Returns $+\infty$ for $x > 171.6243769563027$, where the true
/// value exceeds `f64::MAX`; for $x < -171.6$ the result is subnormal or zero, as is the true
/// value. Relative error below $10^{-14}$ on $[-170.5, 171.62]$ (measured, see crate docs).
///
/// Source: DLMF 5.2.1, 5.5.3 (reflection), 5.7.3 (Taylor series), 5.11.1 (Stirling).
/// FORMULAS.md has no special-function section; its Table A1 uses $\Gamma$ for $I_k$, $J_k$.
pub fn gamma(x: f64) -> f64 {
    if x.is_nan() || x == f64::NEG_INFINITY {
        return f64::NAN;
    }
    if x > 0.0 {
        return gamma_pos(x);
    }
    if x == x.floor() {
        return f64::NAN; // pole (including -0.0 and 0.0)
    }
    if x > -0.25 {
        // Gamma(x) = Gamma(1+x)/x with the series in x itself (no rounding of 1+x).
        return ln_gamma_1p(x).exp() / x;
    }
    // Reflection with -x exact: Gamma(x) = -pi / (x sin(pi x) Gamma(-x)).
    let z = -x;
    let s = sin_pi(x);
    if z < 170.0 {
        -PI / (x * s * gamma_pos(z))
    } else if z > 190.0 {
        // |Gamma(x)| < 1e-340: below the smallest subnormal.
        0.0 * (-PI / (x * s)).signum()
    } else {
        // Gamma(z) overflows or nearly: divide the pieces one at a time.
        let (v, w, c) = stirling_parts(z);
        ((-PI / (x * s * c)) / v) / w
    }
}

/// Checked [`gamma`]: rejects NaN, $-\infty$ and the poles $0,-1,-2,\dots$.
///
/// # Errors
/// [`Error::OutOfDomain`] for those arguments.
pub fn checked_gamma(x: f64) -> Result<f64, Error> {
    if x.is_nan() || (x <= 0.0 && x == x.floor()) {
        return Err(out_of_domain("gamma", x, "real x not in {0, -1, -2, ...}, not NaN or -inf"));
    }
    no_overflow("gamma", x, gamma(x))
}

/// Logarithm of the Gamma function, $\ln\Gamma(x)$ for $x > 0$.
///
/// $$\ln\Gamma(x) = \left(x-\tfrac12\right)\ln x - x + \tfrac12\ln(2\pi) +
///   \sum_{k\ge1}\frac{B_{2k}}{2k(2k-1)x^{2k-1}}\quad(x\ge 8),$$
///
/// Taylor series about 1 and 2 on $[0.75, 2.5]$ (so the zeros at 1 and 2 keep full
/// relative accuracy), recurrence in between, and $\ln\Gamma(x)=\ln\Gamma(1+x)-\ln x$ below.
///
/// Domain: $x > 0$ (NaN otherwise). Finite for all finite $x$ up to about $2.55\times10^{305}$,
/// beyond which $\ln\Gamma(x)$ itself exceeds `f64::MAX` and $+\infty$ is returned.
///
/// Source: DLMF 5.7.3, 5.11.1. (FORMULAS.md: no special-function section.)
pub fn ln_gamma(x: f64) -> f64 {
    if x.is_nan() || x <= 0.0 {
        return f64::NAN;
    }
    ln_gamma_pos(x)
}

/// Checked [`ln_gamma`]: rejects $x\le 0$ and NaN.
///
/// # Errors
/// [`Error::OutOfDomain`] for those arguments.
pub fn checked_ln_gamma(x: f64) -> Result<f64, Error> {
    if x.is_nan() || x <= 0.0 {
        return Err(out_of_domain("ln_gamma", x, "x > 0"));
    }
    no_overflow("ln_gamma", x, ln_gamma(x))
}
