//! Carter's closed form: identities (equilibrium, creep law, continuity, friction bound),
//! regimes and the mirror symmetry for negative creep.

mod common;
use common::tol;
use stickslip_quad::{gauss_kronrod, AdaptiveConfig, Tolerance};
use stickslip_rolling::{carter, carter_creep_force, CarterParams, Error, Regime};

fn integrate(f: impl Fn(f64) -> f64, a: f64, b: f64, brk: Vec<f64>) -> f64 {
    let cfg =
        AdaptiveConfig::new(Tolerance::new(0.0, 1e-13).unwrap()).with_breakpoints(brk).unwrap();
    gauss_kronrod(f, a, b, &cfg).unwrap().value
}

#[test]
fn resultants_match_closed_forms() {
    // steel-like: E = 210 GPa, nu = 0.3, R = 0.5 m, P = 1e5 N/m, rho = 0.3
    let mut worst: f64 = 0.0;
    for &delta in &[1e-5, 1e-4, 2.5e-4, -1e-4, 1e-2] {
        let p = CarterParams::new(2.1e11, 0.3, 0.5, 1e5, 0.3, delta).unwrap();
        let s = carter(&p);
        let a = s.half_width;
        let brk =
            if s.stick_start > -a && s.stick_start < a { vec![s.stick_start] } else { vec![] };
        let pint = integrate(|x| s.pressure(x), -a, a, vec![]);
        let qint = integrate(|x| s.shear(x), -a, a, brk);
        let ep = (pint - p.load()).abs() / p.load();
        let eq = (qint - s.tangential_force).abs() / s.tangential_force.abs();
        println!("Carter delta={delta:e}: regime {:?}, a={a:.6e}, c={:.6e}, Q={:.6e}; |int p - P|/P={ep:.2e}, |int tau - Q|/|Q|={eq:.2e}",
            s.regime, s.stick_start, s.tangential_force);
        worst = worst.max(ep).max(eq);
        // moment of the pressure vanishes (symmetric Hertz)
        let cfg = AdaptiveConfig::new(Tolerance::new(1e-14 * p.load() * a, 0.0).unwrap());
        let m1 = gauss_kronrod(|x| x * s.pressure(x), -a, a, &cfg).unwrap().value;
        assert!(m1.abs() <= 1e-12 * p.load() * a);
    }
    assert!(worst <= tol::CARTER_QUAD_REL, "worst {worst:e}");
}

#[test]
fn creep_law_regimes_and_symmetry() {
    let p0 = CarterParams::new(2.1e11, 0.3, 0.5, 1e5, 0.3, 0.0).unwrap();
    let a = p0.half_width();
    let delta_sat = 0.3 * a / 0.5; // rho a / R: full slip from here on
                                   // full stick at zero creep
    let s = carter(&p0);
    assert_eq!(s.regime, Regime::FullStick);
    assert_eq!(s.tangential_force, 0.0);
    assert_eq!(s.stick_start, -a);
    // saturation: Q = -rho P exactly at and beyond delta_sat
    for &f in &[1.0, 1.5, 1e6] {
        let s = carter(&CarterParams::new(2.1e11, 0.3, 0.5, 1e5, 0.3, f * delta_sat).unwrap());
        assert_eq!(s.regime, Regime::FullSlip);
        assert_eq!(s.tangential_force, -0.3 * 1e5);
        let sn = carter(&CarterParams::new(2.1e11, 0.3, 0.5, 1e5, 0.3, -f * delta_sat).unwrap());
        assert_eq!(sn.tangential_force, 0.3 * 1e5);
    }
    // mirror: Q(-delta) = -Q(delta), tau(-delta) = -tau(delta), same stick zone
    for &f in &[1e-9, 0.1, 0.5, 0.99] {
        let sp = carter(&CarterParams::new(2.1e11, 0.3, 0.5, 1e5, 0.3, f * delta_sat).unwrap());
        let sn = carter(&CarterParams::new(2.1e11, 0.3, 0.5, 1e5, 0.3, -f * delta_sat).unwrap());
        assert_eq!(sp.tangential_force, -sn.tangential_force);
        assert_eq!(sp.stick_start, sn.stick_start);
        for i in 1..20 {
            let x = -a + 2.0 * a * f64::from(i) / 20.0;
            assert_eq!(sp.shear(x), -sn.shear(x));
        }
        // small creep: Q ~ -2 rho P z, relative accuracy kept (no cancellation)
        let z = f * delta_sat * 0.5 / (0.3 * a);
        let lin = -0.3 * 1e5 * z * (2.0 - z);
        assert!((sp.tangential_force - lin).abs() <= 4.0 * f64::EPSILON * lin.abs());
    }
    // the free function agrees
    assert_eq!(carter_creep_force(0.0, 0.3, 1e5, a, 0.5), 0.0);
}

#[test]
fn traction_inside_friction_bound_and_continuous() {
    let p = CarterParams::new(7e10, 0.33, 0.1, 2e4, 0.5, 3e-4).unwrap();
    let s = carter(&p);
    assert_eq!(s.regime, Regime::StickSlip);
    let a = s.half_width;
    let mut worst_excess: f64 = 0.0;
    for i in 1..2000 {
        let x = -a + 2.0 * a * f64::from(i) / 2000.0;
        let (pr, t) = (s.pressure(x), s.shear(x));
        worst_excess = worst_excess.max(t.abs() - 0.5 * pr);
        assert!(pr >= 0.0);
    }
    println!("Carter: max(|tau| - rho p) over 2000 points = {worst_excess:e} (<= 0 expected)");
    assert!(worst_excess <= 1e-9 * s.peak_pressure);
    // continuity at c
    let c = s.stick_start;
    let h = 1e-9 * a;
    assert!((s.shear(c - h) - s.shear(c + h)).abs() <= 1e-3 * s.peak_pressure);
}

#[test]
fn invalid_inputs_are_errors() {
    let bad = [
        CarterParams::new(-1.0, 0.3, 0.5, 1e5, 0.3, 0.0),
        CarterParams::new(1e9, 0.6, 0.5, 1e5, 0.3, 0.0),
        CarterParams::new(1e9, 0.3, 0.0, 1e5, 0.3, 0.0),
        CarterParams::new(1e9, 0.3, 0.5, f64::NAN, 0.3, 0.0),
        CarterParams::new(1e9, 0.3, 0.5, 1e5, 0.0, 0.0),
        CarterParams::new(1e9, 0.3, 0.5, 1e5, 0.3, f64::INFINITY),
    ];
    for b in bad {
        assert!(matches!(b, Err(Error::OutOfDomain { .. })), "{b:?}");
    }
    // a half-width that underflows is reported, not returned as 0
    let tiny = CarterParams::new(1e300, 0.3, 1e-300, 1e-300, 0.3, 0.0);
    assert!(matches!(tiny, Err(Error::NonFinite { .. })), "{tiny:?}");
}
