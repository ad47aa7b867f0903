//! Probe of the fast partial-slip solver at one grid (issue 20's problem): a Cattaneo sphere
//! with the contact `across` cells in diameter (elements inside the circle only), T = 0.5 fP,
//! relative residual 1e-8. Prints the Newton and CG iterations, the time of one operator
//! product (the limit) and of one application of the preconditioner, the solve time and
//! the error against Mindlin, and the solve time in units of one real FFT pair of the
//! padded grid timed in the same run (issue 30's measure).
//!
//! `cargo run --release -p stickslip-benches --example fast_probe -- 512`

use std::time::Instant;
use stickslip_benches::process::{cpu_seconds, peak_rss};
use stickslip_halfspace::Material;
use stickslip_lattice::{ContactGrid, ScalarConvolution, TensorConvolution};
use stickslip_traction::closed::Mindlin;
use stickslip_traction::{ElementState, FastConfig, FastProblem, Load, Tolerance};

fn main() {
    let across: usize = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(256);
    let ratio: f64 = std::env::args().nth(2).and_then(|a| a.parse().ok()).unwrap_or(0.5);
    let (p, f) = (2160.0, 0.1);
    let s = Material::new(30e6, 0.3).expect("material");
    let a = (3.0 * p * 2.0 * s.normal_compliance() / 4.0).cbrt();
    let h = 2.0 * a / across as f64;
    let half = across as f64 / 2.0;
    let mut mask = vec![false; across * across];
    let mut pr = vec![0.0; across * across];
    for j in 0..across {
        for i in 0..across {
            let x = (i as f64 + 0.5 - half) * h;
            let y = (j as f64 + 0.5 - half) * h;
            let r2 = (x * x + y * y) / (a * a);
            if r2 < 1.0 {
                mask[j * across + i] = true;
                pr[j * across + i] = (1.0 - r2).sqrt();
            }
        }
    }
    let sum: f64 = pr.iter().sum();
    pr.iter_mut().for_each(|v| *v *= p / (sum * h * h));
    let g = ContactGrid::from_mask(h, h, (-half * h, -half * h), across, across, &mask, &pr)
        .expect("grid");
    let load = Load::polar(ratio * f * p, 0.0).expect("load");
    let cfg = FastConfig::new(Tolerance::relative(1e-8).expect("tol"), 100).expect("config");
    let problem = FastProblem::new(&g, [s, s], f, load).expect("problem").with_config(cfg);
    let t0 = Instant::now();
    let op = problem.operator().expect("operator");
    let mut scratch = op.make_scratch();
    let setup = t0.elapsed().as_secs_f64();
    let n = g.len();
    let (qx, qy) = (vec![1.0; n], vec![0.5; n]);
    let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
    let reps = 5;
    let t1 = Instant::now();
    for _ in 0..reps {
        op.apply(&qx, &qy, &mut ux, &mut uy, &mut scratch);
    }
    let product = t1.elapsed().as_secs_f64() / reps as f64;
    // The solver's stick-block preconditioner (one unpadded periodic product on the
    // bounding box), applied once per CG step beside the operator's product.
    let prec =
        TensorConvolution::<f64>::inverse_symbol(&g, &problem.compliance(), op.self_term()[0])
            .expect("preconditioner");
    prec.apply(&qx, &qy, &mut ux, &mut uy, &mut scratch);
    let t1 = Instant::now();
    for _ in 0..reps {
        prec.apply(&qx, &qy, &mut ux, &mut uy, &mut scratch);
    }
    let prec_time = t1.elapsed().as_secs_f64() / reps as f64;
    drop(prec);
    // The same preconditioner with its transforms in single precision (not the solver's: it
    // adds a CG step in most of the loads measured, see docs/peers.md "Partial slip").
    let prec =
        TensorConvolution::<f32>::inverse_symbol(&g, &problem.compliance(), op.self_term()[0])
            .expect("preconditioner");
    prec.apply(&qx, &qy, &mut ux, &mut uy, &mut scratch);
    let t1 = Instant::now();
    for _ in 0..reps {
        prec.apply(&qx, &qy, &mut ux, &mut uy, &mut scratch);
    }
    let prec32 = t1.elapsed().as_secs_f64() / reps as f64;
    drop(prec);
    // The bound of issue 30: one real FFT pair (forward and inverse, no padding exploited)
    // of the padded size, timed here in the same run.
    let (mx, my) = op.fft_size();
    let pair_op = ScalarConvolution::<f64>::torus(mx, my, (mx, my), (1.0, 1.0), |_, _| 1.0);
    let field: Vec<f64> = (0..mx * my).map(|k| (k % 7) as f64).collect();
    let mut out = vec![0.0; mx * my];
    let mut ps = pair_op.make_scratch();
    pair_op.apply(&field, &mut out, &mut ps);
    // On rayon's pool, as the solve runs (`FastProblem::solve` moves itself there).
    let pair = stickslip_lattice::on_pool(|| {
        let t1 = Instant::now();
        for _ in 0..reps {
            pair_op.apply(&field, &mut out, &mut ps);
        }
        t1.elapsed().as_secs_f64() / reps as f64
    });
    // The same pair on one core (the unit of the bound quoted in docs/peers.md).
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("pool");
    let pair1 = one.install(|| {
        let t1 = Instant::now();
        for _ in 0..reps {
            pair_op.apply(&field, &mut out, &mut ps);
        }
        t1.elapsed().as_secs_f64() / reps as f64
    });
    drop((pair_op, field, out, ps));
    if std::env::args().nth(3).is_some_and(|a| a == "products") {
        for _ in 0..100 {
            op.apply(&qx, &qy, &mut ux, &mut uy, &mut scratch);
        }
        return;
    }
    let cold = std::env::args().nth(3).is_some_and(|a| a == "cold");
    let c2 = cpu_seconds();
    let t2 = Instant::now();
    let sol = if cold {
        problem.solve_with(&op, &mut scratch).expect("solve")
    } else {
        // `solve` plans its own operator after the coarse levels: release this one first,
        // so that the peak memory is the solve's.
        drop((op, scratch));
        problem.solve().expect("solve")
    };
    let secs = t2.elapsed().as_secs_f64();
    let cpu = cpu_seconds() - c2;
    let mindlin = Mindlin::new(a, p, f, ratio * f * p).expect("Mindlin");
    let n_stick = sol.state.iter().filter(|s| **s == ElementState::Stick).count();
    let r_stick = (n_stick as f64 * h * h / std::f64::consts::PI).sqrt();
    println!(
        "across {across}: N = {n}, FFT {:?}, setup {setup:.2} s, product {:.1} ms, preconditioner {:.1} ms (single precision {:.1} ms); \
         {} levels ({:.2} s), {} Newton, {} CG, {} products, residual {:.1e}; solve {secs:.2} s wall, {cpu:.2} s CPU \
         ({:.0} % in products), peak memory {:.0} MiB; stick radius {:+.2} cells, shift {:+.4} % from Mindlin; \
         one real FFT pair of {mx}x{my} {:.1} ms on 2 threads, {:.1} ms on one: the solve is {:.0} / {:.0} pairs",
        sol.info.fft_size,
        1e3 * product,
        1e3 * prec_time,
        1e3 * prec32,
        sol.info.levels,
        sol.info.coarse_seconds,
        sol.info.iterations,
        sol.info.cg_iterations,
        sol.info.products,
        sol.info.residual,
        100.0 * product * sol.info.products as f64 / secs,
        peak_rss() as f64 / (1024.0 * 1024.0),
        (r_stick - mindlin.stick_radius()) / h,
        100.0 * (sol.shift.0 / mindlin.compliance_relative(&s, &s) - 1.0),
        1e3 * pair,
        1e3 * pair1,
        secs / pair,
        secs / pair1,
    );
}
