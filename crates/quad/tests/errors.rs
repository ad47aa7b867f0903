//! Error reporting: non-finite integrands, non-convergence, invalid input.

use stickslip_quad::{
    algebraic_endpoints, cauchy_pv, gauss_kronrod, tanh_sinh, weakly_singular,
    weakly_singular_weighted, AdaptiveConfig, Error, GaussChebyshev, GaussJacobi, GaussLegendre,
    Rule, Tolerance,
};

fn cfg() -> AdaptiveConfig {
    AdaptiveConfig::new(Tolerance::relative(1e-10).unwrap())
}

/// A NaN at a single point must surface as NonFinite from every method. The poisoned point is
/// chosen so that each method evaluates there: we poison every x in a small band instead of a
/// single float, and also a single exact node for the fixed rules.
#[test]
fn nan_is_reported_by_every_method() {
    let band = |x: f64| if (x - 0.3).abs() < 0.05 { f64::NAN } else { x.cos() };
    let c = cfg();
    let mut results: Vec<(&str, Result<_, Error>)> = vec![
        ("gauss_kronrod", gauss_kronrod(band, 0.0, 1.0, &c)),
        (
            "gauss_kronrod inf",
            gauss_kronrod(
                |x| if x > 2.0 && x < 3.0 { f64::INFINITY } else { (-x).exp() },
                0.0,
                f64::INFINITY,
                &c,
            ),
        ),
        ("tanh_sinh", tanh_sinh(band, 0.0, 1.0, c.tol)),
        ("algebraic_endpoints", algebraic_endpoints(band, 0.0, 1.0, -0.5, 0.5, &c)),
        ("weakly_singular", weakly_singular(band, 0.0, 1.0, 0.7, 0.5, &c)),
        (
            "weakly_singular_weighted",
            weakly_singular_weighted(band, 0.0, 1.0, 0.7, 0.5, 0.5, 0.5, &c),
        ),
        ("cauchy_pv", cauchy_pv(band, 0.0, 1.0, 0.7, &c)),
    ];
    let gl = GaussLegendre::new(9).unwrap();
    let node = gl.nodes()[4]; // 0 exactly, the midpoint
    assert_eq!(node, 0.0);
    results
        .push(("GaussLegendre", gl.integrate(|x| if x == 0.5 { f64::NAN } else { 1.0 }, 0.0, 1.0)));
    let gj = GaussJacobi::new(9, 0.5, 0.5).unwrap();
    results
        .push(("GaussJacobi", gj.integrate(|x| if x == 0.5 { f64::NAN } else { 1.0 }, 0.0, 1.0)));
    let gc = GaussChebyshev::first_kind(9).unwrap();
    results.push((
        "GaussChebyshev",
        gc.integrate(|x| if x == 0.5 { f64::NAN } else { 1.0 }, 0.0, 1.0),
    ));
    results.push((
        "GaussLegendre sum",
        gl.sum(|x| if x == 0.5 { f64::NAN } else { 1.0 }, 0.0, 1.0)
            .map(|v| stickslip_quad::Estimate { value: v, error: 0.0, evals: 0 }),
    ));
    for (name, r) in results {
        println!("{name}: {r:?}");
        assert!(
            matches!(r, Err(Error::NonFinite { .. })),
            "{name} did not report NonFinite: {r:?}"
        );
    }
}

/// A pole inside the range of a plain integral is reported (NonFinite if a node hits it, else
/// NotConverged), never returned as a number.
#[test]
fn unintegrable_is_not_a_number() {
    let r = gauss_kronrod(|x| 1.0 / x, -1.0, 2.0, &cfg());
    println!("1/x on [-1,2]: {r:?}");
    assert!(r.is_err());
}

#[test]
fn not_converged_carries_the_estimate() {
    let c =
        AdaptiveConfig::new(Tolerance::relative(1e-12).unwrap()).with_max_subdivisions(1).unwrap();
    let r = gauss_kronrod(|x| (100.0 * x).sin() / (1.0 + x * x), 0.0, 3.0, &c);
    println!("max_subdivisions = 1: {r:?}");
    match r {
        Err(Error::NotConverged { estimate, requested }) => {
            assert!(estimate.error > requested);
            assert_eq!(estimate.evals, 21);
            assert!(estimate.value.is_finite());
        }
        other => panic!("expected NotConverged, got {other:?}"),
    }
    // the singular integrators too (a Jacobi order cap of 8 and one subinterval)
    let c = c.with_max_order(8).unwrap();
    let r = weakly_singular(|s| (40.0 * s).cos(), -1.0, 1.0, 0.2, 0.9, &c);
    println!("weakly_singular capped: {r:?}");
    assert!(matches!(r, Err(Error::NotConverged { .. })));
    let r = tanh_sinh(|x| x.powf(-0.95), 0.0, 1.0, Tolerance::relative(1e-10).unwrap());
    println!("tanh_sinh x^-0.95: {r:?}");
    assert!(matches!(r, Err(Error::NotConverged { .. })));
}

fn oo<T>(r: Result<T, Error>) -> bool {
    matches!(r, Err(Error::OutOfDomain { .. }))
}

#[test]
fn invalid_input() {
    let c = cfg();
    let bad_iv = |r: Result<stickslip_quad::Estimate, Error>| {
        matches!(r, Err(Error::InvalidInterval { .. }))
    };
    assert!(oo(GaussLegendre::new(0).map(|_| ())));
    assert!(oo(GaussJacobi::new(0, 0.0, 0.0).map(|_| ())));
    assert!(oo(GaussJacobi::new(4, -1.0, 0.0).map(|_| ())));
    assert!(oo(GaussJacobi::new(4, 0.0, -1.5).map(|_| ())));
    assert!(oo(GaussJacobi::new(4, f64::NAN, 0.0).map(|_| ())));
    assert!(oo(GaussChebyshev::first_kind(0).map(|_| ())));
    assert!(oo(Tolerance::new(-1.0, 0.0).map(|_| ())));
    assert!(oo(Tolerance::new(0.0, 0.0).map(|_| ())));
    assert!(oo(Tolerance::new(0.0, f64::NAN).map(|_| ())));
    assert!(oo(AdaptiveConfig::default().with_max_subdivisions(0).map(|_| ())));
    assert!(oo(AdaptiveConfig::default().with_breakpoints(vec![f64::NAN]).map(|_| ())));
    // k >= 1, k < 0, exponents, PV point outside or at an end
    assert!(oo(weakly_singular(|_| 1.0, 0.0, 1.0, 0.5, 1.0, &c)));
    assert!(oo(weakly_singular(|_| 1.0, 0.0, 1.0, 0.5, -0.1, &c)));
    assert!(oo(weakly_singular_weighted(|_| 1.0, 0.0, 1.0, 0.0, 0.5, -0.6, 0.0, &c)));
    assert!(oo(algebraic_endpoints(|_| 1.0, 0.0, 1.0, -1.0, 0.0, &c)));
    assert!(oo(cauchy_pv(|_| 1.0, 0.0, 1.0, 1.5, &c)));
    assert!(oo(cauchy_pv(|_| 1.0, 0.0, 1.0, 0.0, &c)));
    assert!(oo(gauss_kronrod(|_| 1.0, 0.0, 1.0, &c.clone().with_breakpoints(vec![2.0]).unwrap())));
    // intervals: NaN ends everywhere; a > b rejected by weighted methods
    assert!(bad_iv(gauss_kronrod(|_| 1.0, f64::NAN, 1.0, &c)));
    assert!(bad_iv(tanh_sinh(|_| 1.0, 0.0, f64::INFINITY, c.tol)));
    assert!(bad_iv(GaussLegendre::new(3).unwrap().integrate(|_| 1.0, 0.0, f64::INFINITY)));
    assert!(bad_iv(GaussJacobi::new(3, 0.5, 0.5).unwrap().integrate(|_| 1.0, 1.0, 0.0)));
    assert!(bad_iv(algebraic_endpoints(|_| 1.0, 1.0, 0.0, 0.0, 0.0, &c)));
    assert!(bad_iv(cauchy_pv(|_| 1.0, 1.0, 0.0, 0.5, &c)));
    assert!(bad_iv(gauss_kronrod(|_| 1.0, f64::INFINITY, f64::INFINITY, &c)));
}

/// a > b gives minus the integral for the unweighted methods; a = b gives zero at no cost.
#[test]
fn reversed_and_empty_intervals() {
    let c = cfg();
    let f = |x: f64| x.exp();
    let fwd = gauss_kronrod(f, 0.0, 1.0, &c).unwrap().value;
    assert!((gauss_kronrod(f, 1.0, 0.0, &c).unwrap().value + fwd).abs() < 1e-15);
    let ts = tanh_sinh(f, 0.0, 1.0, c.tol).unwrap().value;
    assert_eq!(tanh_sinh(f, 1.0, 0.0, c.tol).unwrap().value, -ts);
    let gl = GaussLegendre::new(12).unwrap();
    assert!((gl.integrate(f, 1.0, 0.0).unwrap().value + fwd).abs() < 1e-15);
    let inf = gauss_kronrod(|x| (-x).exp(), f64::INFINITY, 0.0, &c).unwrap().value;
    assert!((inf + 1.0).abs() < 1e-14);
    for e in [
        gauss_kronrod(f, 2.0, 2.0, &c).unwrap(),
        tanh_sinh(f, 2.0, 2.0, c.tol).unwrap(),
        gl.integrate(f, 2.0, 2.0).unwrap(),
    ] {
        assert_eq!((e.value, e.error, e.evals), (0.0, 0.0, 0));
    }
}

/// Hard cases give accurate finite answers: k = 0.99, x at and very near an end, PV point very
/// near an end, breakpoints, large Jacobi exponents.
#[test]
fn hard_cases() {
    let c = AdaptiveConfig::new(Tolerance::relative(1e-12).unwrap());
    // int_0^1 |x - s|^-0.99 ds at x = 0: 1/(1-k) = 100 (k the double 0.99)
    let k = 0.99;
    let e = weakly_singular(|_| 1.0, 0.0, 1.0, 0.0, k, &c).unwrap();
    let exact = 1.0 / (1.0 - k);
    println!(
        "k=0.99 at end: err {:.2e} est {:.2e} evals {}",
        (e.value - exact).abs(),
        e.error,
        e.evals
    );
    assert!((e.value - exact).abs() <= 1e-12 * exact && e.error >= (e.value - exact).abs());
    // x = 1e-9 inside: int_0^1 |x-s|^-k = (x^(1-k) + (1-x)^(1-k))/(1-k)
    let x = 1.0 / 1024.0 / 1024.0 / 1024.0;
    let e = weakly_singular(|_| 1.0, 0.0, 1.0, x, k, &c).unwrap();
    let exact = (x.powf(1.0 - k) + (1.0 - x).powf(1.0 - k)) / (1.0 - k);
    println!(
        "k=0.99 x=2^-30: err {:.2e} est {:.2e} evals {}",
        (e.value - exact).abs(),
        e.error,
        e.evals
    );
    assert!((e.value - exact).abs() <= 1e-12 * exact);
    // x just outside: int_0^1 (s - x)^-k ds with x = -2^-30
    let e = weakly_singular(|_| 1.0, 0.0, 1.0, -x, k, &c).unwrap();
    let exact = ((1.0 + x).powf(1.0 - k) - x.powf(1.0 - k)) / (1.0 - k);
    println!(
        "k=0.99 x=-2^-30: err {:.2e} est {:.2e} evals {}",
        (e.value - exact).abs(),
        e.error,
        e.evals
    );
    assert!((e.value - exact).abs() <= 1e-12 * exact);
    // PV of 1/(t - x) at x = 1 - 2^-40: ln((1-x)/(x+1)), relative to a large log
    let xp = 1.0 - 2f64.powi(-40);
    let e = cauchy_pv(|_| 1.0, -1.0, 1.0, xp, &c).unwrap();
    let exact = ((1.0 - xp) / (1.0 + xp)).ln();
    println!("PV near end: err {:.2e}", (e.value - exact).abs());
    assert!((e.value - exact).abs() <= 1e-12 * exact.abs());
    // Jacobi with large exponents: int_0^1 x^20 (1-x)^30 dx = B(21, 31)
    let e = algebraic_endpoints(|_| 1.0, 0.0, 1.0, 20.0, 30.0, &c).unwrap();
    // B(21,31) = 20! 30! / 51!
    let lnb: f64 = (1..=20).map(|i| (i as f64).ln()).sum::<f64>()
        + (1..=30).map(|i| (i as f64).ln()).sum::<f64>()
        - (1..=51).map(|i| (i as f64).ln()).sum::<f64>();
    let exact = lnb.exp();
    println!("B(21,31): rel err {:.2e}", (e.value - exact).abs() / exact);
    assert!((e.value - exact).abs() <= 1e-11 * exact);
    // breakpoints: |x - 1/3| on [0, 1] = 5/18
    let cb = c.clone().with_breakpoints(vec![1.0 / 3.0]).unwrap();
    let e = gauss_kronrod(|x| (x - 1.0 / 3.0).abs(), 0.0, 1.0, &cb).unwrap();
    println!(
        "|x-1/3| with breakpoint: err {:.2e}, evals {}",
        (e.value - 5.0 / 18.0).abs(),
        e.evals
    );
    assert_eq!(e.evals, 42);
    assert!((e.value - 5.0 / 18.0).abs() <= 1e-15);
}
