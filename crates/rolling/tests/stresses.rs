//! Eqs 12 and 13 by quadrature: the pressure integrates to P, its moment to M1 (eq 28), and
//! the shear to Q (eq 27), over fast (l << beta w), intermediate and slow (l >> beta w,
//! boundary layers) cases; the near-elastic stresses are Hertz's and Carter's pointwise.

mod common;
use common::tol;
use std::f64::consts::PI;
use stickslip_quad::{gauss_kronrod, AdaptiveConfig, Tolerance};
use stickslip_rolling::{
    carter, solve, CarterParams, GoryachevaParams, GoryachevaSolution, Regime, StressConfig,
};

/// int_lo^hi f(x) dx with x = mid + half cos(phi), so the endpoint square-root behaviour is
/// smoothed; boundary layers are resolved adaptively.
fn outer(s_f: impl Fn(f64) -> f64, lo: f64, hi: f64, scale: f64) -> (f64, usize) {
    let mid = 0.5 * (lo + hi);
    let half = 0.5 * (hi - lo);
    let cfg = AdaptiveConfig::new(Tolerance::new(1e-14 * scale, 1e-14).unwrap())
        .with_max_subdivisions(4000)
        .unwrap();
    let e = gauss_kronrod(|phi: f64| s_f(mid + half * phi.cos()) * half * phi.sin(), 0.0, PI, &cfg)
        .unwrap();
    (e.value, e.evals)
}

struct Case {
    name: &'static str,
    e: f64,
    nu: f64,
    r: f64,
    p: f64,
    rho: f64,
    delta_frac: f64,
    alpha: f64,
    beta: f64,
    w: f64,
}

const CASES: [Case; 7] = [
    // rubber-like, l_H ~ 8.8 mm
    Case {
        name: "fast",
        e: 5e6,
        nu: 0.49,
        r: 0.05,
        p: 1e3,
        rho: 0.8,
        delta_frac: 0.4,
        alpha: 10.0,
        beta: 1.0,
        w: 1.0,
    },
    Case {
        name: "intermediate",
        e: 5e6,
        nu: 0.49,
        r: 0.05,
        p: 1e3,
        rho: 0.8,
        delta_frac: 0.5,
        alpha: 0.1,
        beta: 0.005,
        w: 1.0,
    },
    Case {
        name: "slow",
        e: 5e6,
        nu: 0.49,
        r: 0.05,
        p: 1e3,
        rho: 0.8,
        delta_frac: 0.3,
        alpha: 1e-3,
        beta: 1e-5,
        w: 1.0,
    },
    Case {
        name: "very slow",
        e: 5e6,
        nu: 0.49,
        r: 0.05,
        p: 1e3,
        rho: 0.8,
        delta_frac: 0.6,
        alpha: 1e-4,
        beta: 1e-6,
        w: 0.01,
    },
    Case {
        name: "large alpha/beta",
        e: 3e9,
        nu: 0.35,
        r: 0.01,
        p: 1e4,
        rho: 0.3,
        delta_frac: 0.5,
        alpha: 1e3,
        beta: 1e-3,
        w: 1.0,
    },
    Case {
        name: "polymer fast",
        e: 3e9,
        nu: 0.35,
        r: 0.01,
        p: 1e4,
        rho: 0.3,
        delta_frac: 0.8,
        alpha: 1e3,
        beta: 1.0,
        w: 10.0,
    },
    Case {
        name: "negative creep",
        e: 5e6,
        nu: 0.49,
        r: 0.05,
        p: 1e3,
        rho: 0.8,
        delta_frac: -0.5,
        alpha: 0.1,
        beta: 0.01,
        w: 0.1,
    },
];

fn build(c: &Case) -> (GoryachevaParams, GoryachevaSolution) {
    // creep chosen as a fraction of the partial-slip range rho (l + 2d)/(2R)
    let p0 = GoryachevaParams::new(c.e, c.nu, c.r, c.p, c.rho, 0.0, c.alpha, c.beta, c.w).unwrap();
    let s0 = solve(&p0).unwrap();
    let delta = c.delta_frac * c.rho * (s0.contact_length + 2.0 * s0.shift) / (2.0 * c.r);
    let p = GoryachevaParams::new(c.e, c.nu, c.r, c.p, c.rho, delta, c.alpha, c.beta, c.w).unwrap();
    (p, solve(&p).unwrap())
}

#[test]
fn resultants_of_eqs_12_and_13() {
    let cfg = StressConfig::default();
    let mut worst = [0.0f64; 3];
    for c in &CASES {
        let (p, s) = build(c);
        assert_eq!(s.regime, Regime::StickSlip);
        let (lo, hi) = (-s.rear, s.front);
        let peak = p.load() / s.contact_length;
        let t0 = std::time::Instant::now();
        let (pint, ev1) = outer(|x| s.pressure(x, &cfg).unwrap().value, lo, hi, p.load());
        let (mint, _) =
            outer(|x| x * s.pressure(x, &cfg).unwrap().value, lo, hi, p.load() * s.contact_length);
        // shear: slip part and stick part separately (tau has a kink at c)
        let c_ = s.stick_start;
        let (q1, _) = outer(|x| s.shear(x, &cfg).unwrap().value, lo, c_, p.load());
        let (q2, ev2) = outer(|x| s.shear(x, &cfg).unwrap().value, c_, hi, p.load());
        let qint = q1 + q2;
        let ep = (pint - p.load()).abs() / p.load();
        let em = (mint - s.moment_m1).abs() / s.moment_m1.abs();
        let eq = (qint - s.tangential_force).abs() / s.tangential_force.abs();
        println!(
            "{:>16}: M1/(P l)={:.1e} x1={:.3e} y1={:.3e} | int sigma/P-1={ep:.2e}  int x sigma/M1-1={em:.2e}  int tau/Q-1={eq:.2e} | outer evals {ev1}+{ev2}, {:.0} ms; sigma(-a+)={:.1e} peak",
            c.name, s.moment_m1 / (p.load() * s.contact_length), s.info.bessel_args[0], s.info.bessel_args[2],
            t0.elapsed().as_secs_f64() * 1e3,
            s.pressure(lo + 1e-9 * s.contact_length, &cfg).unwrap().value / peak
        );
        worst[0] = worst[0].max(ep);
        worst[1] = worst[1].max(em);
        worst[2] = worst[2].max(eq);
    }
    println!("worst: P {:.2e}, M1 {:.2e}, Q {:.2e}", worst[0], worst[1], worst[2]);
    for w in worst {
        assert!(w <= tol::RESULTANT_REL);
    }
}

#[test]
fn near_elastic_stresses_are_hertz_and_carter() {
    let cfg = StressConfig::default();
    let (e, nu, r, load, rho) = (5e6, 0.49, 0.05, 1e3, 0.8);
    let cp = CarterParams::new(e, nu, r, load, rho, 0.0).unwrap();
    let a = cp.half_width();
    let delta = 0.5 * rho * a / r; // half of the saturation creep
    let cs = carter(&CarterParams::new(e, nu, r, load, rho, delta).unwrap());
    let mut worst: f64 = 0.0;
    for &(beta, w) in &[(1e-6, 0.01), (1e-2, 1.0), (1.0, 1.0), (1e3, 100.0)] {
        let alpha = beta * (1.0 + 1e-12);
        let p = GoryachevaParams::new(e, nu, r, load, rho, delta, alpha, beta, w).unwrap();
        let s = solve(&p).unwrap();
        let mut wp: f64 = 0.0;
        let mut wt: f64 = 0.0;
        for i in 1..200 {
            let x = -a + 2.0 * a * f64::from(i) / 200.0;
            let ps = s.pressure(x, &cfg).unwrap().value;
            let ts = s.shear(x, &cfg).unwrap().value;
            wp = wp.max((ps - cs.pressure(x)).abs() / cs.peak_pressure);
            wt = wt.max((ts - cs.shear(x)).abs() / cs.peak_pressure);
        }
        println!("alpha = beta(1+1e-12), beta={beta:e}, w={w}: x1={:.2e}; max |sigma - Hertz|/p0 = {wp:.2e}, max |tau - Carter|/p0 = {wt:.2e}",
            s.info.bessel_args[0]);
        worst = worst.max(wp).max(wt);
    }
    assert!(worst <= tol::POINTWISE_ELASTIC, "worst {worst:e}");
}
