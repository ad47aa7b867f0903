//! Bounded Bessel-ratio quantities used by the scaled Goryacheva equations.
//!
//! Only the ratios $I_1/I_0$ and $K_0/K_1$ from `stickslip_special` enter; the two
//! complements below are the small closed-form helpers that keep the results free of
//! cancellation where a ratio is close to one (large argument) or to its leading term (small
//! argument). FORMULAS.md section D ("Overflow and the fix").

use stickslip_special::{bessel_i1_over_i0, bessel_k0_over_k1};

/// $I_1(x)/I_0(x)$, in $[0, 1)$ for $x \ge 0$.
#[inline]
pub(crate) fn i_ratio(x: f64) -> f64 {
    bessel_i1_over_i0(x)
}

/// $K_0(x)/K_1(x)$, in $(0, 1)$ for $x > 0$; the limit $0$ at $x = 0$.
#[inline]
pub(crate) fn k_ratio(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        bessel_k0_over_k1(x)
    }
}

/// Argument above which [`one_minus_i_ratio`] uses the asymptotic series.
const ASYMPTOTIC_FROM: f64 = 50.0;

/// $1 - I_1(x)/I_0(x)$ without cancellation, $x \ge 0$.
///
/// For $x < 50$ it is $1 - I_1/I_0$ directly (relative rounding $\le 2x\varepsilon \le
/// 100\varepsilon$). For $x \ge 50$ the Hankel expansions (A&S 9.7.1)
/// $I_\nu(x) \simeq \frac{e^x}{\sqrt{2\pi x}}\sum_k (-1)^k a_k(\nu) x^{-k}$,
/// $a_k(\nu) = a_{k-1}(\nu)\,\frac{4\nu^2-(2k-1)^2}{8k}$, give
/// $$1-\frac{I_1}{I_0} = \frac{\sum_{k\ge1}(-1)^k\,[a_k(0)-a_k(1)]\,x^{-k}}
///   {\sum_k (-1)^k a_k(0)\, x^{-k}} = \frac1{2x}+\frac1{8x^2}+\dots,$$
/// whose numerator is summed term by term (no cancellation). With $x \ge 50$ the terms fall
/// by at least $k/(2x)$ each, so 24 terms leave a truncation far below $\varepsilon$.
pub(crate) fn one_minus_i_ratio(x: f64) -> f64 {
    if x < ASYMPTOTIC_FROM {
        return 1.0 - i_ratio(x);
    }
    let inv = 1.0 / x;
    let (mut a0, mut a1) = (1.0_f64, 1.0_f64);
    let mut pw = 1.0;
    let mut num = 0.0;
    let mut den = 1.0;
    for k in 1..=24 {
        let kf = f64::from(k);
        let odd = (2.0 * kf - 1.0) * (2.0 * kf - 1.0);
        a0 *= -odd / (8.0 * kf);
        a1 *= (4.0 - odd) / (8.0 * kf);
        pw *= -inv;
        let t = (a0 - a1) * pw;
        num += t;
        den += a0 * pw;
        if t.abs() < 1e-18 * num.abs() {
            break;
        }
    }
    num / den
}

/// $I_2(x)/I_0(x) = 1 - \frac{2}{x}\frac{I_1(x)}{I_0(x)}$ without cancellation, $x \ge 0$.
///
/// The recurrence $I_0 - I_2 = (2/x) I_1$ (A&S 9.6.26) gives the identity. For $x \le 2$ both
/// power series (A&S 9.6.10) have positive terms and are summed directly,
/// $I_2/I_0 = \sum_k \frac{(x^2/4)^{k+1}}{k!(k+2)!} \big/ \sum_k\frac{(x^2/4)^k}{(k!)^2}$;
/// above 2 the subtraction loses at most a factor 3.4.
pub(crate) fn i2_over_i0(x: f64) -> f64 {
    if x > 2.0 {
        return 1.0 - 2.0 * i_ratio(x) / x;
    }
    let z = 0.25 * x * x;
    // term_k of I0: z^k/(k!)^2 ; term_k of I2: z^(k+1)/(k!(k+2)!)
    let mut t0 = 1.0;
    let mut t2 = 0.5 * z;
    let (mut s0, mut s2) = (t0, t2);
    for k in 1..40 {
        let kf = f64::from(k);
        t0 *= z / (kf * kf);
        t2 *= z / (kf * (kf + 2.0));
        s0 += t0;
        s2 += t2;
        if t0 < 1e-18 * s0 && t2 <= 1e-18 * s2 {
            break;
        }
    }
    s2 / s0
}

/// $\frac{2}{x}\frac{I_1(x)}{I_0(x)} = 1 - I_2/I_0$, in $(0, 1]$, with the limit $1$ at $0$.
pub(crate) fn two_i_ratio_over_x(x: f64) -> f64 {
    if x > 2.0 {
        2.0 * i_ratio(x) / x
    } else {
        1.0 - i2_over_i0(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The asymptotic branch of `one_minus_i_ratio` must agree with the direct subtraction
    /// where both are valid (x in [50, 2000]); the direct one carries 2x eps of rounding.
    #[test]
    fn complement_branches_agree() {
        let mut worst: f64 = 0.0;
        let mut x = 50.0;
        while x < 2000.0 {
            let direct = 1.0 - i_ratio(x);
            let asym = one_minus_i_ratio(x);
            let rel = (asym - direct).abs() / asym;
            worst = worst.max(rel / (2.0 * x * f64::EPSILON));
            x *= 1.07;
        }
        println!("one_minus_i_ratio: worst |asym - direct| / (2 x eps) = {worst:.3}");
        assert!(worst < 4.0);
    }

    /// Power series of I2/I0 against the subtraction at x in [0.5, 2]: the subtraction loses
    /// at most 1/(I2/I0) ~ 33 at x = 0.5.
    #[test]
    fn i2_series_matches_recurrence() {
        let mut worst: f64 = 0.0;
        for i in 0..=30 {
            let x = 0.5 + 1.5 * f64::from(i) / 30.0;
            let series = i2_over_i0(x);
            let direct = 1.0 - 2.0 * i_ratio(x) / x;
            worst = worst.max((series - direct).abs() / series);
        }
        println!("i2_over_i0: worst relative gap to 1 - 2 I1/(x I0) on [0.5, 2] = {worst:e}");
        assert!(worst < 100.0 * f64::EPSILON);
        // leading term x^2/8 at tiny x
        let x = 1e-5;
        assert!((i2_over_i0(x) / (x * x / 8.0) - 1.0).abs() < 1e-9);
    }
}
