//! No NaN, no infinity anywhere: a dense sweep over alpha, beta in [1e-6, 1e6] s (including
//! alpha = beta), w in [0.01, 100] m/s, creep in every regime and both signs, two materials;
//! stresses at interior points for one creep per grid point.

use stickslip_rolling::{solve, GoryachevaParams, Regime, StressConfig};

#[test]
fn everything_finite_on_the_whole_range() {
    let cfg = StressConfig::default();
    let times: Vec<f64> = (0..=36).map(|i| 10f64.powf(-6.0 + f64::from(i) / 3.0)).collect();
    let speeds = [0.01, 0.1, 1.0, 10.0, 100.0];
    let mats = [(5e6, 0.49, 0.05, 1e3, 0.8), (3e9, 0.35, 0.01, 1e4, 0.3)];
    let t0 = std::time::Instant::now();
    let (mut solves, mut stress_evals) = (0usize, 0usize);
    let mut regimes = [0usize; 3];
    let mut max_x1: f64 = 0.0;
    for &(e, nu, r, load, rho) in &mats {
        for (i, &beta) in times.iter().enumerate() {
            for &alpha in &times[i..] {
                for &w in &speeds {
                    let p0 =
                        GoryachevaParams::new(e, nu, r, load, rho, 0.0, alpha, beta, w).unwrap();
                    let s0 = solve(&p0).unwrap();
                    let sat = rho * (s0.contact_length + 2.0 * s0.shift) / (2.0 * r);
                    for &f in &[0.0, 1e-6, 0.3, 0.9, 1.0, 2.0, -0.5] {
                        let p = GoryachevaParams::new(e, nu, r, load, rho, f * sat, alpha, beta, w)
                            .unwrap();
                        let s = solve(&p).unwrap();
                        solves += 1;
                        regimes[match s.regime {
                            Regime::StickSlip => 0,
                            Regime::FullSlip => 1,
                            Regime::FullStick => 2,
                        }] += 1;
                        let vals = [
                            s.contact_length,
                            s.shift,
                            s.rear,
                            s.front,
                            s.stick_length,
                            s.stick_start,
                            s.c2,
                            s.tangential_force,
                            s.moment_m1,
                            s.rolling_moment,
                        ];
                        assert!(
                            vals.iter().all(|v| v.is_finite()),
                            "non-finite at alpha={alpha:e} beta={beta:e} w={w} f={f}: {s:?}"
                        );
                        assert!(s.tangential_force.abs() <= rho * load * (1.0 + 1e-12));
                        assert!(s.stick_length >= 0.0 && s.stick_length <= s.contact_length);
                        max_x1 = max_x1.max(s.info.bessel_args[0]);
                        if f == 0.3 {
                            for k in 1..4 {
                                let x = -s.rear + s.contact_length * f64::from(k) / 4.0;
                                let sig = s.pressure(x, &cfg).unwrap();
                                let tau = s.shear(x, &cfg).unwrap();
                                stress_evals += sig.evals + tau.evals;
                                assert!(sig.value.is_finite() && tau.value.is_finite());
                                assert!(
                                    sig.value >= 0.0,
                                    "negative pressure at alpha={alpha:e} beta={beta:e} w={w}"
                                );
                            }
                        }
                    }
                }
            }
        }
    }
    println!(
        "{solves} solves (stick-slip {}, full slip {}, full stick {}), max x1 = {max_x1:.2e}, {stress_evals} stress-integrand evaluations, {:.2} s: all finite",
        regimes[0], regimes[1], regimes[2], t0.elapsed().as_secs_f64()
    );
}
