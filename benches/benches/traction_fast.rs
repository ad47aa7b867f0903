//! Fast partial-slip solver (issue 6): time, Newton and CG iterations against the grid size
//! N on the Cattaneo–Mindlin sphere (seed 002 Example 1 proportions, T/fP = 2/3), each size
//! printed beside its accuracy against Mindlin (FORMULAS.md E): the stick radius and the
//! relative rigid shift. Grids: side x side lattice with the contact radius at 100/256 of the
//! side (issue 6's 256 x 256 with a = 100 cells). The 512 x 512 case runs only with
//! `STICKSLIP_EXTENDED=1`. Per grid it also prints the limit (issue 20): the time of one
//! operator product (two forward and two inverse real FFTs of the padded lattice), the solve
//! time divided by CG iterations x product (the cost of one iteration in products: about
//! 1.3 for the product and the quarter-size preconditioner FFT, plus the vector work), the
//! CPU time and the peak memory of the process so far. The issue's own problem (the contact
//! `n` cells across, T = 0.5 fP, residual 1e-8) is
//! `cargo run --release -p stickslip-benches --example fast_probe -- n`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Instant;
use stickslip_benches::process::{cpu_seconds, peak_rss};
use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
use stickslip_traction::closed::Mindlin;
use stickslip_traction::{ElementState, FastProblem, Load};

const P: f64 = 2160.0;
const F: f64 = 0.1;
const RATIO: f64 = 2.0 / 3.0;

fn steel() -> Material {
    Material::new(30e6, 0.3).expect("steel")
}

/// Hertz pressure of radius `cells` lattice cells on a `side` x `side` lattice, zero outside.
fn grid(side: usize, cells: usize, a: f64) -> ContactGrid {
    let h = a / cells as f64;
    let half = side as f64 / 2.0;
    let mut pr = vec![0.0; side * side];
    for j in 0..side {
        for i in 0..side {
            let x = (i as f64 + 0.5 - half) * h;
            let y = (j as f64 + 0.5 - half) * h;
            pr[j * side + i] = (1.0 - (x * x + y * y) / (a * a)).max(0.0).sqrt();
        }
    }
    let sum: f64 = pr.iter().sum();
    pr.iter_mut().for_each(|v| *v *= P / (sum * h * h));
    ContactGrid::from_mask(h, h, (-half * h, -half * h), side, side, &vec![true; side * side], &pr)
        .expect("grid")
}

fn bench(c: &mut Criterion) {
    let s = steel();
    let a = (3.0 * P * 2.0 * s.normal_compliance() / 4.0).cbrt();
    let mindlin = Mindlin::new(a, P, F, RATIO * F * P).expect("Mindlin");
    let extended = std::env::var("STICKSLIP_EXTENDED").is_ok_and(|v| v == "1");
    let mut group = c.benchmark_group("traction_fast/mindlin");
    group.sample_size(10);
    for side in [64usize, 128, 256, 512] {
        if side == 512 && !extended {
            println!("traction_fast: 512 x 512 skipped (set STICKSLIP_EXTENDED=1)");
            continue;
        }
        let cells = side * 100 / 256;
        let g = grid(side, cells, a);
        let load = Load::polar(RATIO * F * P, 0.0).expect("load");
        let problem = FastProblem::new(&g, [s, s], F, load).expect("problem");
        let (c0, t0) = (cpu_seconds(), Instant::now());
        let sol = problem.solve().expect("solve");
        let secs = t0.elapsed().as_secs_f64();
        let cpu = cpu_seconds() - c0;
        let h = g.hx;
        let n_stick = sol.state.iter().filter(|s| **s == ElementState::Stick).count();
        let r_stick = (n_stick as f64 * h * h / std::f64::consts::PI).sqrt();
        let shift_err = sol.shift.0 / mindlin.compliance_relative(&s, &s) - 1.0;
        // The limit: one operator product (two forward and two inverse real FFTs).
        let op = problem.operator().expect("operator");
        let mut scratch = op.make_scratch();
        let (mut ux, mut uy) = (vec![0.0; g.len()], vec![0.0; g.len()]);
        let q: Vec<f64> = sol.traction.iter().map(|t| t.0).collect();
        let t1 = Instant::now();
        for _ in 0..5 {
            op.apply(&q, &q, &mut ux, &mut uy, &mut scratch);
        }
        let product = t1.elapsed().as_secs_f64() / 5.0;
        println!(
            "accuracy traction_fast {side}x{side} (N = {}, a = {cells} cells, FFT {:?}): \
             {} coarse levels, {} Newton, {} CG, {} products, residual {:.1e}; stick radius \
             {:+.3} cells from Mindlin, shift {:+.3} % from Mindlin; one solve {secs:.3} s wall \
             ({cpu:.2} s CPU), one product {:.2} ms, solve / (CG x product) {:.2}, \
             peak memory {:.0} MiB",
            g.len(),
            sol.info.fft_size,
            sol.info.levels,
            sol.info.iterations,
            sol.info.cg_iterations,
            sol.info.products,
            sol.info.residual,
            (r_stick - mindlin.stick_radius()) / h,
            100.0 * shift_err,
            1e3 * product,
            secs / (sol.info.cg_iterations.max(1) as f64 * product),
            peak_rss() as f64 / (1024.0 * 1024.0),
        );
        group.bench_with_input(BenchmarkId::from_parameter(g.len()), &problem, |b, p| {
            b.iter(|| p.solve().expect("solve"))
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().measurement_time(std::time::Duration::from_millis(500)).warm_up_time(std::time::Duration::from_millis(100));
    targets = bench
}
criterion_main!(benches);
