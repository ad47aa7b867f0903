//! Normal contact solver (issues 16 and 30): the two problems of issue 30
//! (`stickslip_benches::surfaces`) at 256² and 512² (and 1024² with `STICKSLIP_EXTENDED=1`),
//! tolerance 1e-8, each time beside the accuracy reached:
//!
//! * `normal/rough_periodic`: a rigid periodic band-limited self-affine surface (H = 0.8, 4 to
//!   64 cycles per period, the same continuous surface on every lattice) on steel, about 5 %
//!   of the period in contact; accuracy = the three certified residuals;
//! * `normal/hertz_free`: a rigid sphere on steel, free boundary, the Hertz radius 0.3 of the
//!   side; accuracy = the certified residuals and the peak pressure and approach against
//!   Hertz's closed form (the discretisation error, not the solver's).
//!
//! Each line also gives the fine and coarse iterations (the nested start) and the FFT
//! products. Targets (issue 30, 2 cores): rough 1024² <= 0.6 s, Hertz 1024² <= 2 s, fine
//! iterations not growing with the lattice. The scale table up to 4096² is the example
//! `normal_scale`; the side-by-side with ASPHER is `scripts/compare_aspher.py`.
//! Run: `cargo bench -p stickslip-benches --bench normal`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::f64::consts::PI;
use stickslip_benches::surfaces::{hertz_gap, rough_problem, PERIOD};
use stickslip_halfspace::material::composite_modulus;
use stickslip_halfspace::Material;
use stickslip_normal::{Boundary, NormalLoad, NormalProblem, NormalSolution};
use stickslip_traction::Tolerance;

fn describe(name: &str, n: usize, s: &NormalSolution) -> String {
    let coarse: Vec<String> = s.levels.iter().map(|l| l.iterations.to_string()).collect();
    format!(
        "accuracy {name} {n}x{n}: residuals gap {:.1e} complementarity {:.1e} force {:.1e}; \
         {} fine iterations (coarse {}), {} + {} FFT products; contact {:.4}",
        s.info.gap_residual,
        s.info.complementarity_residual,
        s.info.force_residual,
        s.info.iterations,
        coarse.join(","),
        s.info.products,
        s.info.preconditioner_products,
        s.fraction,
    )
}

fn bench(c: &mut Criterion) {
    let steel = Material::new(210e9, 0.3).expect("steel");
    let rigid = Material::rigid();
    let extended = std::env::var("STICKSLIP_EXTENDED").is_ok_and(|v| v == "1");
    let tol = Tolerance::relative(1e-8).expect("tolerance");
    let sizes: &[usize] = if extended { &[256, 512, 1024] } else { &[256, 512] };

    let mut group = c.benchmark_group("normal/rough_periodic");
    group.sample_size(10);
    for &n in sizes {
        let (gap, pm) = rough_problem(n);
        let h = PERIOD / n as f64;
        let load = NormalLoad::Force(pm * PERIOD * PERIOD);
        let problem = NormalProblem::new(n, n, (h, h), &gap, [steel, rigid], Boundary::Periodic)
            .expect("problem")
            .with_tolerance(tol)
            .with_min_contact_cells(1);
        println!("{}", describe("rough periodic", n, &problem.solve(load).expect("solve")));
        group.bench_with_input(BenchmarkId::from_parameter(n * n), &problem, |b, p| {
            b.iter(|| p.solve(load).expect("solve"))
        });
    }
    group.finish();

    let mut group = c.benchmark_group("normal/hertz_free");
    group.sample_size(10);
    let (side, a, r) = (1e-3, 0.3e-3, 0.01);
    let es = composite_modulus(&steel, &rigid);
    let force = 4.0 * es * a * a * a / (3.0 * r);
    for &n in sizes {
        let gap = hertz_gap(n, side, r);
        let h = side / n as f64;
        let problem = NormalProblem::new(n, n, (h, h), &gap, [steel, rigid], Boundary::Free)
            .expect("problem")
            .with_tolerance(tol);
        let s = problem.solve(NormalLoad::Force(force)).expect("solve");
        let p0 = 3.0 * force / (2.0 * PI * a * a);
        println!(
            "{}; against Hertz: p0 {:+.1e}, approach {:+.1e}",
            describe("hertz free", n, &s),
            s.peak_pressure / p0 - 1.0,
            s.approach / (a * a / r) - 1.0
        );
        group.bench_with_input(BenchmarkId::from_parameter(n * n), &problem, |b, p| {
            b.iter(|| p.solve(NormalLoad::Force(force)).expect("solve"))
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
