//! Naive reference beside the fast path: eqs 12 and 13 exactly as printed (corrected in
//! FORMULAS.md section D: lower limits -a and c, weight e^{(x-t)/(beta w)} with t <= x),
//! integrated by Gauss-Jacobi rules, against the crate's cancellation-free right-sided form.
//! Only moderate x1 = l/(2 beta w) are usable here: the printed form's weight grows like
//! e^{2 x1} and its terms cancel, which is why the crate does not evaluate it this way.

use std::f64::consts::PI;
use stickslip_quad::{GaussJacobi, Rule};
use stickslip_rolling::{solve, GoryachevaParams, Regime, StressConfig};

/// Agreement relative to the mean pressure P/l: the printed form loses about e^{2 x1} eps.
const LITERAL_REL: f64 = 1e-11;

#[test]
fn printed_eqs_12_13_agree_with_fast_forms() {
    let cfg = StressConfig::default();
    let (e, nu, r, load, rho) = (5e6, 0.49, 0.05, 1e3, 0.8);
    let jac_sig = GaussJacobi::new(80, 0.0, -0.5).unwrap();
    let jac_half = GaussJacobi::new(80, 0.0, 0.5).unwrap();
    let mut worst: f64 = 0.0;
    for &(alpha, beta, w, frac) in &[
        (10.0, 1.0, 1.0, 0.4),
        (0.1, 0.005, 1.0, 0.5),
        (0.1, 0.01, 0.1, 0.7),
        (1e3, 1e-3, 1.0, 0.3),
    ] {
        let s0 = solve(&GoryachevaParams::new(e, nu, r, load, rho, 0.0, alpha, beta, w).unwrap())
            .unwrap();
        let delta = frac * rho * (s0.contact_length + 2.0 * s0.shift) / (2.0 * r);
        let p = GoryachevaParams::new(e, nu, r, load, rho, delta, alpha, beta, w).unwrap();
        let s = solve(&p).unwrap();
        assert_eq!(s.regime, Regime::StickSlip);
        let kr = p.compliance() * r;
        let k = p.compliance();
        let (a, b, c, c2) = (s.rear, s.front, s.stick_start, s.c2);
        let bw = beta * w;
        let f_of = |t: f64| {
            (a + b) * (a + b) / (8.0 * kr) + (t - alpha * w) * (b - a - 2.0 * t) / (2.0 * kr) + load
        };
        let sigma_lit = |x: f64| {
            let g = |t: f64| f_of(t) * ((x - t) / bw).exp() / (b - t).sqrt();
            -jac_sig.integrate(g, -a, x).unwrap().value / (PI * bw)
        };
        let mean = load / s.contact_length;
        let mut wcase: f64 = 0.0;
        for i in 1..20 {
            let x = -a + 0.95 * s.contact_length * f64::from(i) / 20.0;
            let sl = sigma_lit(x);
            let sf = s.pressure(x, &cfg).unwrap().value;
            wcase = wcase.max((sl - sf).abs() / mean);
            let mut tl = -rho * sl;
            if x > c {
                let g1 = |t: f64| {
                    (rho / (2.0 * kr) * (b - c - 2.0 * t + 2.0 * alpha * w) + delta / k)
                        * ((x - t) / bw).exp()
                        / (b - t).sqrt()
                };
                let g2 = |t: f64| ((x - t) / bw).exp() / (b - t).sqrt();
                tl -= jac_half.integrate(g1, c, x).unwrap().value / (PI * bw);
                tl -= c2 * jac_sig.integrate(g2, c, x).unwrap().value / (PI * bw);
            }
            let tf = s.shear(x, &cfg).unwrap().value;
            wcase = wcase.max((tl - tf).abs() / mean);
        }
        println!("alpha={alpha:e} beta={beta:e} w={w}: x1={:.3e}; max |printed - fast|/(P/l) over 19 points = {wcase:.2e}",
            s.info.bessel_args[0]);
        worst = worst.max(wcase);
    }
    assert!(worst <= LITERAL_REL, "worst {worst:e}");
}
