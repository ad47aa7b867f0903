//! Extreme arguments: no spurious overflow, no underflow to zero where a normal value
//! exists, no NaN, for finite in-domain input. Where a closed-form reference exists (leading
//! asymptotic terms whose neglected part is far below 1e-16), accuracy is asserted too.

mod common;
use common::{rel_err, tol};
use std::f64::consts::{LN_2, PI};
use stickslip_special as sp;

const SUB_MIN: f64 = 5e-324; // smallest subnormal
const SUB: f64 = 1e-310; // a subnormal

/// Finite and, unless `may_be_tiny`, at least the smallest normal in magnitude.
fn finite_normal(label: &str, x: f64, v: f64) {
    assert!(v.is_finite(), "{label}({x:e}) = {v:e} is not finite");
    assert!(v == 0.0 || v.abs() >= f64::MIN_POSITIVE, "{label}({x:e}) = {v:e} is subnormal");
    assert!(v != 0.0, "{label}({x:e}) underflowed to zero");
}

fn accurate(label: &str, got: f64, want: f64) {
    let e = rel_err(got, want);
    println!("{label:>22}: got {got:e}, want {want:e}, rel err {e:.2e}");
    assert!(e <= tol::REL, "{label}: {e:e}");
}

#[test]
fn sweep_extreme_inputs_finite() {
    let xs = [1e-300, 1e-30, 1e-8, 0.5, 1.0, 2.0, 30.0, 700.0, 705.0, 713.0, 1e6, 1e300, f64::MAX];
    for &x in &xs {
        for (label, f) in [
            ("i0e", sp::bessel_i0e as fn(f64) -> f64),
            ("i1e", sp::bessel_i1e),
            ("k0e", sp::bessel_k0e),
            ("k1e", sp::bessel_k1e),
            ("i1/i0", sp::bessel_i1_over_i0),
            ("k0/k1", sp::bessel_k0_over_k1),
            ("ln_gamma", sp::ln_gamma),
        ] {
            if label == "ln_gamma" && (x > 2.5e305 || x == 1.0 || x == 2.0) {
                continue; // ln Gamma(x) > f64::MAX there (documented); exact zeros at 1, 2
            }
            finite_normal(label, x, f(x));
            finite_normal(label, -x, if label.starts_with('i') { f(-x) } else { f(x) });
        }
        if x <= 713.0 {
            finite_normal("i0", x, sp::bessel_i0(x));
            finite_normal("i1", x, sp::bessel_i1(x));
            finite_normal("i1", -x, sp::bessel_i1(-x));
        }
        if x <= 705.0 {
            finite_normal("k0", x, sp::bessel_k0(x));
            finite_normal("k1", x, sp::bessel_k1(x));
        }
        if x <= 171.62 {
            finite_normal("gamma", x, sp::gamma(x));
        }
    }
    // I0 and I1 up to 713.9 (true value < f64::MAX), gamma up to its documented threshold.
    finite_normal("i0", 713.9, sp::bessel_i0(713.9));
    finite_normal("i1", -713.9, sp::bessel_i1(-713.9));
    finite_normal("gamma", sp::GAMMA_MAX_ARG, sp::gamma(sp::GAMMA_MAX_ARG));
    finite_normal("gamma", -170.5, sp::gamma(-170.5));
    assert_eq!(sp::gamma(171.7), f64::INFINITY, "true value exceeds f64::MAX");
    assert_eq!(sp::bessel_i0(714.5), f64::INFINITY, "true value exceeds f64::MAX");
    // Elliptic integrals over the whole parameter line.
    for &m in &[-f64::MAX, -1e300, -1e30, -1.0, -SUB_MIN, 0.0, SUB_MIN, 0.5, 1.0 - 2f64.powi(-52)] {
        finite_normal("ellipk", m, sp::ellipk(m));
        finite_normal("ellipe", m, sp::ellipe(m));
    }
    finite_normal("ellipk", 1.0 - 2f64.powi(-53), sp::ellipk(1.0 - 2f64.powi(-53)));
}

#[test]
fn subnormal_and_huge_arguments_with_references() {
    // Gamma(x) = 1/x - gamma_E + O(x): for x = 1e-300 the correction is 1e-300 relative.
    accurate("gamma(1e-300)", sp::gamma(1e-300), 1.0 / 1e-300);
    accurate("gamma(1e-310)", sp::gamma(6e-309), 1.0 / 6e-309);
    assert_eq!(sp::gamma(SUB), f64::INFINITY, "1/x > f64::MAX");
    // ln Gamma(x) = -ln x - gamma_E x + ...: at the smallest subnormal it is 1074 ln 2.
    accurate("ln_gamma(5e-324)", sp::ln_gamma(SUB_MIN), 1074.0 * LN_2);
    // ln Gamma(x) = x (ln x - 1) - ln(x)/2 + ln(2 pi)/2 + 1/(12 x): at 1e300 the last two
    // terms are below 1 ulp of the leading one.
    let x = 1e300;
    accurate("ln_gamma(1e300)", sp::ln_gamma(x), x * (x.ln() - 1.0));
    // K0(x) ~ -ln(x/2) - gamma_E for tiny x; x K1(x) ~ 1.
    let euler = 0.577_215_664_901_532_9;
    accurate("k0(1e-300)", sp::bessel_k0(1e-300), -(1e-300f64.ln() - LN_2) - euler);
    accurate("k0(subnormal)", sp::bessel_k0(SUB), -(SUB.ln() - LN_2) - euler);
    accurate("k1(1e-300)", sp::bessel_k1(1e-300), 1e300);
    // Scaled functions at 1e300: i0e = 1/sqrt(2 pi x) (1 + 1/(8x)), k0e = sqrt(pi/(2x)) (...).
    accurate("i0e(1e300)", sp::bessel_i0e(x), 1.0 / (2.0 * PI * x).sqrt());
    accurate("i1e(1e300)", sp::bessel_i1e(x), 1.0 / (2.0 * PI * x).sqrt());
    accurate("k0e(1e300)", sp::bessel_k0e(x), (PI / (2.0 * x)).sqrt());
    accurate("k1e(1e300)", sp::bessel_k1e(x), (PI / (2.0 * x)).sqrt());
    accurate("i0e(MAX)", sp::bessel_i0e(f64::MAX), 1.0 / (2.0 * PI).sqrt() / f64::MAX.sqrt());
    // Ratios: I1/I0 -> 1 - 1/(2x), K0/K1 -> 1 - 1/(2x); at 1e300 both round to 1.
    accurate("i1/i0(1e300)", sp::bessel_i1_over_i0(x), 1.0);
    accurate("k0/k1(1e300)", sp::bessel_k0_over_k1(x), 1.0);
    accurate("k0/k1(MAX)", sp::bessel_k0_over_k1(f64::MAX), 1.0);
    // Both ratios are below 1 for every finite x > 0 (DLMF 10.37.1 and its I analogue).
    for x in [1e2, 1e3, 1e4, 1e6, 1e10, 1e16, 1e100, 1e300, f64::MAX] {
        assert!(sp::bessel_k0_over_k1(x) <= 1.0, "K0/K1({x:e}) > 1");
        assert!(sp::bessel_i1_over_i0(x) <= 1.0, "I1/I0({x:e}) > 1");
    }
    // Small x: I1/I0 = x/2, K0/K1 = x (-ln(x/2) - gamma_E) to relative O(x^2 ln x).
    accurate("i1/i0(1e-300)", sp::bessel_i1_over_i0(1e-300), 0.5e-300);
    let k = |x: f64| x * (-(x.ln() - LN_2) - euler);
    accurate("k0/k1(1e-300)", sp::bessel_k0_over_k1(1e-300), k(1e-300));
    // Subnormal x: the ratio is subnormal too; judged on the scale of the smallest normal.
    let r = sp::bessel_k0_over_k1(SUB);
    assert!(r > 0.0 && r.is_finite());
    accurate("k0/k1(1e-310)", r, k(SUB));
    // Elliptic integrals at the ends: m -> -inf (DLMF 19.12.1 after 19.7.5):
    // K(m) ~ ln(4 sqrt(1-m)) / sqrt(1-m), E(m) ~ sqrt(1-m), corrections O(ln(-m)/m).
    for m in [-1e300, -f64::MAX] {
        let s = (1.0 - m).sqrt();
        accurate("ellipk(-big)", sp::ellipk(m), (4.0f64.ln() + s.ln()) / s);
        accurate("ellipe(-big)", sp::ellipe(m), s);
    }
    // m -> 1: K ~ ln(4/k'), k' = sqrt(1-m); correction (1-m)/4 (ln(4/k') - 1) < 1e-14.
    let mc = 2f64.powi(-53);
    let lk = (4.0 / mc.sqrt()).ln();
    accurate("ellipk(1-2^-53)", sp::ellipk(1.0 - mc), lk + 0.25 * mc * (lk - 1.0));
    accurate("ellipe(1-2^-53)", sp::ellipe(1.0 - mc), 1.0 + 0.5 * mc * (lk - 0.5));
    // Tiny |m|: K = E = pi/2 to relative m/4.
    accurate("ellipk(-5e-324)", sp::ellipk(-SUB_MIN), PI / 2.0);
    accurate("ellipe(5e-324)", sp::ellipe(SUB_MIN), PI / 2.0);
}
