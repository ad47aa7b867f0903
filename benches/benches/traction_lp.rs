//! The modified LP of seed 002 (Fig. 3.5) on Hertz circles of about 100, 400 and 1,000
//! elements (Example 1: steel sphere R = 1 in on steel, P = 2160 lbf, T = 144 lbf,
//! f = 0.1), grouped by N. Each size prints its accuracy beside the time: the rigid-body
//! movement per body against Mindlin's closed form (FORMULAS.md E).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;
use std::time::Duration;
use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
use stickslip_traction::closed::Mindlin;
use stickslip_traction::{Load, TractionProblem};

const P: f64 = 2160.0;
const T: f64 = 144.0;
const F: f64 = 0.1;

fn bench(c: &mut Criterion) {
    let steel = Material::new(30e6, 0.3).expect("steel");
    let estar_inv = 2.0 * steel.normal_compliance();
    let a = (3.0 * P * 1.0 * estar_inv / 4.0).cbrt();
    let mindlin = Mindlin::new(a, P, F, T).expect("Mindlin").compliance_per_body(&steel);
    let mut group = c.benchmark_group("traction_lp");
    group.sample_size(10).warm_up_time(Duration::from_millis(200));
    // 12, 24 and 36 elements across: 112, 448 and 1008 elements.
    for n_across in [12usize, 24, 36] {
        let grid = ContactGrid::hertz_circle(a, P, n_across).expect("grid");
        let problem = TractionProblem::new(
            &grid,
            [steel, steel],
            F,
            Load::Force { magnitude: T, angle: 0.0 },
        )
        .expect("problem");
        let sol = problem.solve().expect("solve");
        let rel = sol.rigid_per_body[0] / mindlin - 1.0;
        println!(
            "accuracy traction_lp N = {:5}: rigid movement per body {:.6e} in, Mindlin {:.6e} in, \
             rel {rel:+.3e}; {} pivots, {} refused entries, LP {:.3} s",
            grid.len(),
            sol.rigid_per_body[0],
            mindlin,
            sol.info.iterations,
            sol.info.rejected_entries,
            sol.info.lp_seconds
        );
        if n_across >= 36 {
            group.measurement_time(Duration::from_secs(30));
        }
        group.bench_with_input(BenchmarkId::new("hertz_circle", grid.len()), &problem, |b, p| {
            b.iter(|| black_box(p.solve().expect("solve").rigid))
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
