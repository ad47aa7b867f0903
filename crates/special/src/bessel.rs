//! Modified Bessel functions of order 0 and 1: plain, exponentially scaled, and stable ratios.
//!
//! The scaled functions are the Chebyshev expansions of Cephes (Moshier), via `spec_math`;
//! the plain ones are built from them so that no intermediate overflows; the ratios use the
//! scaled functions plus small-argument series where those underflow or overflow.
//! Series: A&S 9.6.10-9.6.13 (DLMF 10.25.2, 10.31.1-2).

use crate::error::{no_overflow, out_of_domain, Error};
use spec_math::cephes64 as ceph;

/// Euler's constant $\gamma$.
const EULER: f64 = 0.577_215_664_901_532_9;

/// $e^{x}$ split as $e^{x/2}e^{x/2}$ applied to `s`, so that $s\,e^{x}$ is finite
/// whenever the product is.
fn times_exp(s: f64, x: f64) -> f64 {
    if x == f64::INFINITY {
        // I0 and I1 grow without bound; the scaled value is 0 there and 0 * inf would be NaN.
        return f64::INFINITY;
    }
    if x < 700.0 {
        s * x.exp()
    } else {
        let h = (0.5 * x).exp();
        (s * h) * h
    }
}

/// Exponentially scaled $I_0$: $\;I_0(x)\,e^{-|x|}$.
///
/// $$I_0(x) = \sum_{k\ge0}\frac{(x^2/4)^k}{(k!)^2},\qquad I_0(x)e^{-x}\sim\frac{1}{\sqrt{2\pi x}}.$$
///
/// Domain: all real $x$ (even); NaN for NaN. Finite for every finite $x$.
/// Source: A&S 9.6.10, 9.7.1; Cephes `i0e`. (FORMULAS.md: no special-function section.)
pub fn bessel_i0e(x: f64) -> f64 {
    ceph::i0e(x.abs())
}

/// Exponentially scaled $I_1$: $\;I_1(x)\,e^{-|x|}$ (odd in $x$).
///
/// $$I_1(x) = \frac{x}{2}\sum_{k\ge0}\frac{(x^2/4)^k}{k!\,(k+1)!}.$$
///
/// Domain: all real $x$; NaN for NaN. Source: A&S 9.6.10, 9.7.1; Cephes `i1e`.
pub fn bessel_i1e(x: f64) -> f64 {
    let r = ceph::i1e(x.abs());
    if x < 0.0 {
        -r
    } else {
        r
    }
}

/// Modified Bessel function $I_0(x)$ (even).
///
/// $$I_0(x) = \frac1\pi\int_0^\pi e^{x\cos\theta}\,d\theta.$$
///
/// Domain: all real $x$. Returns $+\infty$ for $|x| \gtrsim 713.98$ where the true value
/// exceeds `f64::MAX`. Computed as $\mathrm{i0e}(x)\,e^{|x|}$ with the exponential split.
/// Source: A&S 9.6.16, 9.6.10.
pub fn bessel_i0(x: f64) -> f64 {
    let a = x.abs();
    times_exp(bessel_i0e(a), a)
}

/// Modified Bessel function $I_1(x)$ (odd).
///
/// $$I_1(x) = \frac1\pi\int_0^\pi e^{x\cos\theta}\cos\theta\,d\theta.$$
///
/// Domain: all real $x$. Returns $\pm\infty$ for $|x|\gtrsim 713.98$ where the true value
/// exceeds `f64::MAX`. Source: A&S 9.6.19, 9.6.10.
pub fn bessel_i1(x: f64) -> f64 {
    let a = x.abs();
    let r = times_exp(bessel_i1e(a), a);
    if x < 0.0 {
        -r
    } else {
        r
    }
}

/// Exponentially scaled $K_0$: $\;K_0(x)\,e^{x}$, for $x > 0$.
///
/// $$K_0(x) = -\left(\ln\frac x2+\gamma\right)I_0(x) + \sum_{k\ge1}\frac{(x^2/4)^k}{(k!)^2}H_k,
///   \qquad K_0(x)e^{x}\sim\sqrt{\frac{\pi}{2x}}.$$
///
/// Domain: $x > 0$ (NaN for $x\le 0$ and NaN). Finite for every finite $x>0$.
/// Source: A&S 9.6.13, 9.7.2; Cephes `k0e`.
pub fn bessel_k0e(x: f64) -> f64 {
    if x.is_nan() || x <= 0.0 {
        return f64::NAN;
    }
    ceph::k0e(x)
}

/// Exponentially scaled $K_1$: $\;K_1(x)\,e^{x}$, for $x > 0$.
///
/// $$K_1(x) = \frac1x + \ln\frac x2\,I_1(x) - \frac x4\sum_{k\ge0}
///   \bigl(\psi(k+1)+\psi(k+2)\bigr)\frac{(x^2/4)^k}{k!\,(k+1)!}.$$
///
/// Domain: $x > 0$. Returns $+\infty$ only for subnormal $x < 5.6\times10^{-309}$, where
/// $1/x$ itself overflows. Source: A&S 9.6.11, 9.7.2; Cephes `k1e`.
pub fn bessel_k1e(x: f64) -> f64 {
    if x.is_nan() || x <= 0.0 {
        return f64::NAN;
    }
    ceph::k1e(x)
}

/// Modified Bessel function $K_0(x)$, $x>0$.
///
/// $$K_0(x) = \int_0^\infty e^{-x\cosh t}\,dt.$$
///
/// Domain: $x>0$ (NaN otherwise). Normal-range results up to $x\approx 705$; beyond, the
/// value is subnormal and then 0, as is the true value. Source: A&S 9.6.24, 9.6.13.
pub fn bessel_k0(x: f64) -> f64 {
    if x.is_nan() || x <= 0.0 {
        return f64::NAN;
    }
    ceph::k0(x)
}

/// Modified Bessel function $K_1(x)$, $x>0$.
///
/// $$K_1(x) = \int_0^\infty e^{-x\cosh t}\cosh t\,dt.$$
///
/// Domain: $x>0$ (NaN otherwise). $+\infty$ only for subnormal $x<5.6\times10^{-309}$.
/// Source: A&S 9.6.24, 9.6.11.
pub fn bessel_k1(x: f64) -> f64 {
    if x.is_nan() || x <= 0.0 {
        return f64::NAN;
    }
    ceph::k1(x)
}

/// Stable ratio $I_1(x)/I_0(x)$ (odd in $x$, defined for all real $x$).
///
/// $$\frac{I_1(x)}{I_0(x)} = \frac{\mathrm{i1e}(x)}{\mathrm{i0e}(x)}
///   = \frac x2 - \frac{x^3}{16} + \frac{x^5}{96} - \dots,\qquad
///   \to 1 - \frac{1}{2x}\ (x\to\infty).$$
///
/// Domain: all real $x$; finite everywhere, in $(-1, 1)$. For $|x|<10^{-5}$ the series is
/// used (also correct for subnormal $x$). Source: A&S 9.6.10, 9.7.1.
pub fn bessel_i1_over_i0(x: f64) -> f64 {
    if x.is_infinite() {
        return x.signum();
    }
    let a = x.abs();
    if a < 1e-5 {
        let x2 = x * x;
        // x/2 (1 - x^2/8 + x^4/48): truncation O(x^6) < 1e-30 relative.
        return 0.5 * x * (1.0 - x2 * (0.125 - x2 / 48.0));
    }
    if a >= RATIO_ASYMPTOTIC {
        // The e^{-2x} (Stokes) part of I_nu is below 1e-800 here.
        let (s0, s1) = hankel_sums(a, -1.0);
        return (s1 / s0).copysign(x);
    }
    bessel_i1e(x) / bessel_i0e(x)
}

/// Stable ratio $K_0(x)/K_1(x)$ for $x > 0$.
///
/// $$\frac{K_0(x)}{K_1(x)} = \frac{\mathrm{k0e}(x)}{\mathrm{k1e}(x)},\qquad
///   \frac{K_0}{K_1}\approx\frac{-x\,L\,(1+x^2/4)+x^3/4}{1+\frac{x^2}{2}\left(L-\frac12\right)},
///   \quad L=\ln\frac x2+\gamma\quad(x<10^{-5}),$$
/// and $\to 1 - \frac{1}{2x}$ as $x\to\infty$.
///
/// Domain: $x>0$ (NaN otherwise); finite for every $x>0$ including subnormals.
/// Source: A&S 9.6.11, 9.6.13, 9.7.2.
pub fn bessel_k0_over_k1(x: f64) -> f64 {
    if x.is_nan() || x <= 0.0 {
        return f64::NAN;
    }
    if x.is_infinite() {
        return 1.0;
    }
    if x < 1e-5 {
        let l = x.ln() - std::f64::consts::LN_2 + EULER;
        let q = 0.25 * x * x;
        let xk0 = x * (-l * (1.0 + q) + q);
        let xk1 = 1.0 + 2.0 * q * (l - 0.5);
        return xk0 / xk1;
    }
    if x >= RATIO_ASYMPTOTIC {
        let (s0, s1) = hankel_sums(x, 1.0);
        return s0 / s1;
    }
    bessel_k0e(x) / bessel_k1e(x)
}

/// Hankel's asymptotic sums $\sum_k (\pm1)^k a_k(\nu)/x^k$ for $\nu = 0, 1$, with
/// $a_k(\nu) = \prod_{j=1}^k(4\nu^2-(2j-1)^2)/(k!\,8^k)$ (DLMF 10.40.1-2), for $x\ge 10^3$,
/// where 12 terms leave a remainder below $10^{-30}$. `sign` is $-1$ for $I$, $+1$ for $K$.
fn hankel_sums(x: f64, sign: f64) -> (f64, f64) {
    let (mut s0, mut s1) = (1.0, 1.0);
    let (mut t0, mut t1) = (1.0, 1.0);
    for k in 1..=12 {
        let kf = f64::from(k);
        let odd = (2.0 * kf - 1.0) * (2.0 * kf - 1.0);
        let step = sign / (kf * 8.0 * x);
        t0 *= -odd * step;
        t1 *= (4.0 - odd) * step;
        s0 += t0;
        s1 += t1;
    }
    (s0, s1)
}

/// Argument above which the ratios use [`hankel_sums`] directly: the quotient of two sums
/// near 1 keeps the ratio below 1, where dividing rounded scaled values may not.
const RATIO_ASYMPTOTIC: f64 = 1e3;

macro_rules! checked_twin {
    ($(#[$m:meta])* $name:ident, $f:ident, $label:literal, $ok:expr, $allowed:literal) => {
        $(#[$m])*
        ///
        /// # Errors
        /// [`Error::OutOfDomain`] when the argument is NaN or outside the domain;
        /// [`Error::Overflow`] when a finite argument's value exceeds `f64::MAX`.
        pub fn $name(x: f64) -> Result<f64, Error> {
            let ok: fn(f64) -> bool = $ok;
            if ok(x) {
                no_overflow($label, x, $f(x))
            } else {
                Err(out_of_domain($label, x, $allowed))
            }
        }
    };
}

checked_twin!(/// Checked [`bessel_i0`]: rejects NaN.
    checked_bessel_i0, bessel_i0, "bessel_i0", |x| !x.is_nan(), "real x, not NaN");
checked_twin!(/// Checked [`bessel_i1`]: rejects NaN.
    checked_bessel_i1, bessel_i1, "bessel_i1", |x| !x.is_nan(), "real x, not NaN");
checked_twin!(/// Checked [`bessel_i0e`]: rejects NaN.
    checked_bessel_i0e, bessel_i0e, "bessel_i0e", |x| !x.is_nan(), "real x, not NaN");
checked_twin!(/// Checked [`bessel_i1e`]: rejects NaN.
    checked_bessel_i1e, bessel_i1e, "bessel_i1e", |x| !x.is_nan(), "real x, not NaN");
checked_twin!(/// Checked [`bessel_k0`]: rejects $x\le0$ and NaN.
    checked_bessel_k0, bessel_k0, "bessel_k0", |x| x > 0.0, "x > 0");
checked_twin!(/// Checked [`bessel_k1`]: rejects $x\le0$ and NaN.
    checked_bessel_k1, bessel_k1, "bessel_k1", |x| x > 0.0, "x > 0");
checked_twin!(/// Checked [`bessel_k0e`]: rejects $x\le0$ and NaN.
    checked_bessel_k0e, bessel_k0e, "bessel_k0e", |x| x > 0.0, "x > 0");
checked_twin!(/// Checked [`bessel_k1e`]: rejects $x\le0$ and NaN.
    checked_bessel_k1e, bessel_k1e, "bessel_k1e", |x| x > 0.0, "x > 0");
checked_twin!(/// Checked [`bessel_i1_over_i0`]: rejects NaN.
    checked_bessel_i1_over_i0, bessel_i1_over_i0, "bessel_i1_over_i0", |x| !x.is_nan(),
    "real x, not NaN");
checked_twin!(/// Checked [`bessel_k0_over_k1`]: rejects $x\le0$ and NaN.
    checked_bessel_k0_over_k1, bessel_k0_over_k1, "bessel_k0_over_k1", |x| x > 0.0, "x > 0");
