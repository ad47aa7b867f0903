//! The `checked_` twins: OutOfDomain for bad input, the plain value otherwise.

use stickslip_special as sp;
use stickslip_special::Error;

fn assert_ood(r: Result<f64, Error>, fname: &str, x: f64) {
    match r {
        Err(Error::OutOfDomain { name, value, allowed }) => {
            assert_eq!(name, fname);
            assert!(value.to_bits() == x.to_bits() || (value.is_nan() && x.is_nan()));
            assert!(!allowed.is_empty());
        }
        other => panic!("{fname}({x:e}) should be OutOfDomain, got {other:?}"),
    }
}

type Pair = (&'static str, fn(f64) -> f64, fn(f64) -> Result<f64, Error>);

#[test]
fn checked_twins_reject_bad_input() {
    let pairs: [(Pair, &[f64]); 15] = [
        (("gamma", sp::gamma, sp::checked_gamma), &[f64::NAN, 0.0, -0.0, -1.0, -170.0, -1e300]),
        (("ln_gamma", sp::ln_gamma, sp::checked_ln_gamma), &[f64::NAN, 0.0, -1.0, -0.5]),
        (("bessel_i0", sp::bessel_i0, sp::checked_bessel_i0), &[f64::NAN]),
        (("bessel_i1", sp::bessel_i1, sp::checked_bessel_i1), &[f64::NAN]),
        (("bessel_i0e", sp::bessel_i0e, sp::checked_bessel_i0e), &[f64::NAN]),
        (("bessel_i1e", sp::bessel_i1e, sp::checked_bessel_i1e), &[f64::NAN]),
        (("bessel_k0", sp::bessel_k0, sp::checked_bessel_k0), &[f64::NAN, 0.0, -1.0]),
        (("bessel_k1", sp::bessel_k1, sp::checked_bessel_k1), &[f64::NAN, 0.0, -1.0]),
        (("bessel_k0e", sp::bessel_k0e, sp::checked_bessel_k0e), &[f64::NAN, 0.0, -1e-300]),
        (("bessel_k1e", sp::bessel_k1e, sp::checked_bessel_k1e), &[f64::NAN, -0.0, -2.0]),
        (("bessel_i1_over_i0", sp::bessel_i1_over_i0, sp::checked_bessel_i1_over_i0), &[f64::NAN]),
        (
            ("bessel_k0_over_k1", sp::bessel_k0_over_k1, sp::checked_bessel_k0_over_k1),
            &[f64::NAN, 0.0, -3.0],
        ),
        (("ellipk", sp::ellipk, sp::checked_ellipk), &[f64::NAN, 1.0, 1.5, f64::INFINITY]),
        (("ellipe", sp::ellipe, sp::checked_ellipe), &[f64::NAN, 1.0 + f64::EPSILON, 2.0]),
        (("ellipd", sp::ellipd, sp::checked_ellipd), &[f64::NAN, 1.0, 1.5, f64::INFINITY]),
    ];
    for ((name, plain, checked), bad) in pairs {
        for &x in bad {
            assert_ood(checked(x), name, x);
            assert!(plain(x).is_nan(), "{name}({x:e}) should be NaN, got {}", plain(x));
        }
        // In-domain values pass through unchanged.
        for x in [0.25, 0.5, 0.75, 1e-10, -0.3, -7.5, 3.0, 42.0] {
            if !plain(x).is_nan() {
                assert_eq!(checked(x).unwrap().to_bits(), plain(x).to_bits(), "{name}({x})");
            }
        }
    }
    // The message names the function and the allowed set.
    let msg = sp::checked_ellipk(2.0).unwrap_err().to_string();
    assert!(msg.contains("ellipk") && msg.contains("m < 1"), "{msg}");
}

/// A finite in-domain argument whose true value exceeds `f64::MAX`: the plain function returns
/// infinity (documented), the checked twin says so with [`sp::Error::Overflow`].
#[test]
fn overflow_is_an_error_in_checked_twins() {
    type F = fn(f64) -> Result<f64, sp::Error>;
    let cases: [(&str, F, f64); 5] = [
        ("gamma", sp::checked_gamma, 171.7),
        ("gamma", sp::checked_gamma, 1e10),
        ("bessel_i0", sp::checked_bessel_i0, 714.0),
        ("bessel_i1", sp::checked_bessel_i1, -800.0),
        ("ln_gamma", sp::checked_ln_gamma, 1e307),
    ];
    for (name, f, x) in cases {
        match f(x) {
            Err(sp::Error::Overflow { name: n, value }) => assert!(n == name && value == x),
            other => panic!("{name}({x:e}) gave {other:?}, expected Overflow"),
        }
    }
    // Just below the thresholds the values are finite and pass.
    assert!(sp::checked_gamma(171.6).unwrap().is_finite());
    assert!(sp::checked_bessel_i0(713.9).unwrap().is_finite());
    // Infinite arguments are limits, not overflow: I0(inf) = inf.
    assert_eq!(sp::checked_bessel_i0(f64::INFINITY), Ok(f64::INFINITY));
    assert_eq!(sp::bessel_i0(f64::NEG_INFINITY), f64::INFINITY);
    assert_eq!(sp::bessel_i1(f64::NEG_INFINITY), f64::NEG_INFINITY);
}
