//! The elastic limit: alpha = beta (1 + 1e-12) reproduces Carter to 1e-9, alpha = beta exactly
//! is reported as elastic and solved as Carter (FORMULAS.md section D, elastic limit).

mod common;
use common::tol;
use stickslip_rolling::{carter, solve, CarterParams, GoryachevaParams, Regime, Response};

const MATS: [(f64, f64, f64, f64, f64); 3] =
    [(5e6, 0.49, 0.05, 1e3, 0.8), (3e9, 0.35, 0.01, 1e4, 0.3), (2.1e11, 0.3, 0.5, 1e5, 0.2)];

#[test]
fn near_elastic_reproduces_carter() {
    let mut worst: f64 = 0.0;
    let mut worst_case = String::new();
    for &(e, nu, r, load, rho) in &MATS {
        let a = CarterParams::new(e, nu, r, load, rho, 0.0).unwrap().half_width();
        for &frac in &[0.1, 0.5, 0.9, -0.5] {
            let delta = frac * rho * a / r;
            let cs = carter(&CarterParams::new(e, nu, r, load, rho, delta).unwrap());
            for &beta in &[1e-6, 1e-3, 1.0, 1e3, 1e6] {
                for &w in &[0.01, 1.0, 100.0] {
                    let alpha = beta * (1.0 + 1e-12);
                    let s = solve(
                        &GoryachevaParams::new(e, nu, r, load, rho, delta, alpha, beta, w).unwrap(),
                    )
                    .unwrap();
                    assert_eq!(s.response, Response::Viscoelastic);
                    assert_eq!(s.regime, cs.regime);
                    let scale_q = rho * load;
                    let errs = [
                        (s.contact_length - 2.0 * a).abs() / (2.0 * a),
                        s.shift.abs() / a,
                        (s.stick_length - cs.stick_length).abs() / (2.0 * a),
                        (s.tangential_force - cs.tangential_force).abs()
                            / cs.tangential_force.abs(),
                        s.moment_m1.abs() / (load * a),
                        (s.rolling_moment - cs.rolling_moment).abs() / (scale_q * r),
                        (s.c2
                            + s.stick_length * rho * delta.signum() * alpha * w
                                / (2.0 * p_kr(e, nu, r)))
                        .abs()
                            / s.c2.abs(),
                    ];
                    let m = errs.iter().copied().fold(0.0, f64::max);
                    if m > worst {
                        worst = m;
                        worst_case = format!(
                            "E={e:e} delta frac={frac} beta={beta:e} w={w}: {:?}",
                            errs.map(|x| format!("{x:.2e}"))
                        );
                    }
                }
            }
        }
    }
    println!("alpha = beta(1+1e-12) vs Carter [l, d/a, m, Q, M1/(Pa), M*, C2]: worst {worst:.3e} at {worst_case}");
    assert!(worst <= tol::ELASTIC_LIMIT_REL);
}

fn p_kr(e: f64, nu: f64, r: f64) -> f64 {
    stickslip_rolling::compliance(e, nu) * r
}

#[test]
fn exactly_elastic_is_carter() {
    for &(e, nu, r, load, rho) in &MATS {
        let a = CarterParams::new(e, nu, r, load, rho, 0.0).unwrap().half_width();
        for &frac in &[0.0, 0.3, -0.3, 1.0, 3.0] {
            let delta = frac * rho * a / r;
            let cs = carter(&CarterParams::new(e, nu, r, load, rho, delta).unwrap());
            let s =
                solve(&GoryachevaParams::new(e, nu, r, load, rho, delta, 2.0, 2.0, 1.0).unwrap())
                    .unwrap();
            assert_eq!(s.response, Response::Elastic);
            assert_eq!(s.regime, cs.regime);
            assert!((s.contact_length - 2.0 * a).abs() <= tol::ELASTIC_EXACT_REL * 2.0 * a);
            assert_eq!(s.shift, 0.0);
            assert_eq!(s.tangential_force, cs.tangential_force);
            assert_eq!(s.stick_start, cs.stick_start);
            assert_eq!(s.moment_m1, 0.0);
            let expected = if frac == 0.0 {
                Regime::FullStick
            } else if frac.abs() >= 1.0 {
                Regime::FullSlip
            } else {
                Regime::StickSlip
            };
            assert_eq!(s.regime, expected, "frac {frac}");
        }
    }
    println!("alpha = beta: Response::Elastic, identical to Carter for 3 materials x 5 creeps");
}
