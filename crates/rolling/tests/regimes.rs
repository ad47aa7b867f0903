//! Regimes are results: full slip (Q = -rho P), full stick (Q = 0), negative creep by
//! mirror symmetry; out-of-domain inputs are errors; optimality conditions of the solution
//! (residuals of the scaled eqs 19 and 24, |tau| <= rho sigma on the stick zone).

use stickslip_rolling::{solve, Error, GoryachevaParams, Regime, StressConfig};

fn params(delta: f64, alpha: f64, beta: f64, w: f64) -> GoryachevaParams {
    GoryachevaParams::new(5e6, 0.49, 0.05, 1e3, 0.8, delta, alpha, beta, w).unwrap()
}

#[test]
fn full_slip_and_full_stick() {
    for &(alpha, beta, w) in
        &[(10.0, 1.0, 1.0), (1e-3, 1e-5, 1.0), (1e6, 1e-6, 0.01), (1e-4, 1e-6, 100.0)]
    {
        let s0 = solve(&params(0.0, alpha, beta, w)).unwrap();
        assert_eq!(s0.regime, Regime::FullStick);
        assert_eq!(s0.tangential_force, 0.0);
        assert_eq!(s0.stick_length, s0.contact_length);
        assert_eq!(s0.stick_start, -s0.rear);
        // saturation creep rho (l + 2d) / (2R): full slip at and beyond it
        let sat = 0.8 * (s0.contact_length + 2.0 * s0.shift) / (2.0 * 0.05);
        for &f in &[1.0, 2.0, 1e9] {
            let s = solve(&params(f * sat, alpha, beta, w)).unwrap();
            assert_eq!(s.regime, Regime::FullSlip, "f={f}");
            assert_eq!(s.tangential_force, -0.8 * 1e3);
            assert_eq!(s.stick_length, 0.0);
            assert_eq!(s.c2, 0.0);
            let sn = solve(&params(-f * sat, alpha, beta, w)).unwrap();
            assert_eq!(sn.tangential_force, 0.8 * 1e3);
        }
        // just below saturation: a tiny stick zone, |Q| just below rho P
        let s = solve(&params(0.999999 * sat, alpha, beta, w)).unwrap();
        assert_eq!(s.regime, Regime::StickSlip);
        assert!(s.stick_length > 0.0 && s.tangential_force > -0.8e3);
        // Q is monotone in the creep and continuous at both ends
        let mut prev = 0.0;
        for i in 1..=50 {
            let q =
                solve(&params(sat * f64::from(i) / 50.0, alpha, beta, w)).unwrap().tangential_force;
            assert!(q < prev, "Q must decrease with creep: {q} !< {prev}");
            prev = q;
        }
        println!("alpha={alpha:e} beta={beta:e} w={w}: saturation creep {sat:.4e}, Q(0.999999 sat)/(rho P) = {:.8}",
            s.tangential_force / 800.0);
    }
}

#[test]
fn negative_creep_is_the_mirror_image() {
    let cfg = StressConfig::default();
    let sp = solve(&params(0.05, 0.1, 0.01, 0.1)).unwrap();
    let sn = solve(&params(-0.05, 0.1, 0.01, 0.1)).unwrap();
    assert_eq!(sp.stick_length, sn.stick_length);
    assert_eq!(sp.tangential_force, -sn.tangential_force);
    assert_eq!(sp.c2, -sn.c2);
    assert_eq!(sp.moment_m1, sn.moment_m1);
    for i in 1..40 {
        let x = -sp.rear + sp.contact_length * f64::from(i) / 40.0;
        let (a, b) = (sp.shear(x, &cfg).unwrap().value, sn.shear(x, &cfg).unwrap().value);
        assert_eq!(a, -b);
    }
}

#[test]
fn residuals_and_friction_cone() {
    let cfg = StressConfig::default();
    let mut worst_cone: f64 = f64::NEG_INFINITY;
    for &(alpha, beta, w, frac) in &[
        (10.0, 1.0, 1.0, 0.5),
        (0.1, 0.005, 1.0, 0.3),
        (1e-3, 1e-5, 1.0, 0.7),
        (1e3, 1e-3, 1.0, 0.5),
    ] {
        let s0 = solve(&params(0.0, alpha, beta, w)).unwrap();
        let sat = 0.8 * (s0.contact_length + 2.0 * s0.shift) / (2.0 * 0.05);
        let s = solve(&params(frac * sat, alpha, beta, w)).unwrap();
        // residuals: scaled eq 19 is O(1); eq 24 is in metres, compared with l
        assert!(s.info.length_residual.abs() <= 1e-14, "{:?}", s.info);
        assert!(s.info.stick_residual.abs() <= 1e-14 * s.contact_length, "{:?}", s.info);
        assert!(s.shift > 0.0, "the contact shifts forward");
        // |tau| <= rho sigma inside the stick zone, sigma >= 0 everywhere
        let peak = 1e3 / s.contact_length;
        for i in 1..400 {
            let x = -s.rear + s.contact_length * f64::from(i) / 400.0;
            let sig = s.pressure(x, &cfg).unwrap().value;
            let tau = s.shear(x, &cfg).unwrap().value;
            assert!(sig >= -1e-9 * peak, "negative pressure {sig} at {x}");
            worst_cone = worst_cone.max((tau.abs() - 0.8 * sig) / peak);
        }
        println!("alpha={alpha:e} beta={beta:e}: info {:?}", s.info);
    }
    println!("max (|tau| - rho sigma)/(P/l) over 4 cases x 399 points: {worst_cone:.3e}");
    assert!(worst_cone <= 1e-9);
}

#[test]
fn out_of_domain_inputs_are_errors() {
    let ok = |d, a, b, w| GoryachevaParams::new(5e6, 0.49, 0.05, 1e3, 0.8, d, a, b, w);
    for r in [
        ok(0.0, 1.0, 2.0, 1.0),
        ok(0.0, 1.0, 0.0, 1.0),
        ok(0.0, 1.0, 1.0, 0.0),
        ok(0.0, 1.0, 1.0, -1.0),
        ok(f64::NAN, 1.0, 1.0, 1.0),
        ok(0.0, f64::INFINITY, 1.0, 1.0),
    ] {
        assert!(matches!(r, Err(Error::OutOfDomain { .. })), "{r:?}");
    }
    // scales that do not fit in f64 are reported
    let r = GoryachevaParams::new(5e6, 0.49, 0.05, 1e3, 0.8, 0.0, 1e300, 1e-300, 1e300);
    assert!(matches!(r, Err(Error::NonFinite { .. })), "{r:?}");
}

#[test]
fn extreme_but_valid_parameters_are_finite() {
    // ratios alpha/beta up to 1e300 and Bessel arguments from 1e-300 to 1e300
    let cases = [
        (1e150, 1e-150, 1.0),
        (1e-150, 1e-300, 1e-5),
        (2e-300, 1e-300, 1e-3),
        (1e300, 1e299, 1e-5),
        (1.0, 1.0 - 1e-16, 1.0),
    ];
    for &(alpha, beta, w) in &cases {
        let p = match GoryachevaParams::new(5e6, 0.49, 0.05, 1e3, 0.8, 0.0, alpha, beta, w) {
            Ok(p) => p,
            Err(e) => {
                println!("alpha={alpha:e} beta={beta:e} w={w:e}: rejected: {e}");
                continue;
            }
        };
        let s0 = solve(&p).unwrap();
        let sat = 0.8 * (s0.contact_length + 2.0 * s0.shift) / 0.1;
        let p =
            GoryachevaParams::new(5e6, 0.49, 0.05, 1e3, 0.8, 0.5 * sat, alpha, beta, w).unwrap();
        let s = solve(&p).unwrap();
        let all = [
            s.contact_length,
            s.shift,
            s.stick_length,
            s.c2,
            s.tangential_force,
            s.moment_m1,
            s.rolling_moment,
        ];
        assert!(all.iter().all(|v| v.is_finite()), "{s:?}");
        assert!(s.contact_length > 0.0);
        println!("alpha={alpha:e} beta={beta:e} w={w:e}: l/l_H={:.6e} d={:.3e} m/l={:.4} Q/(rho P)={:.6} x1={:.2e}",
            s.contact_length / s.hertz_length, s.shift, s.stick_length / s.contact_length,
            s.tangential_force / 800.0, s.info.bessel_args[0]);
    }
}
