//! Graded subsurface fields: points per second on grids of 50^2, 100^2 and 200^2 points
//! (rayon), beside the accuracy of the same `Accuracy` setting against the mpmath table of
//! `crates/graded/tests/data/graded_stress.txt`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use stickslip_benches::data;
use stickslip_graded::{Accuracy, GradedMaterial, StressField, SurfaceLoad};

/// Max component error (floor 1e-3 max|sigma|) over the mpmath table at `acc`.
fn accuracy(acc: Accuracy) -> f64 {
    let mut worst = 0.0f64;
    for r in data::rows(data::GRADED_STRESS, None, 0) {
        let m = GradedMaterial::new(1.0, r[0], r[1]).expect("material");
        let f =
            StressField::new(&m, SurfaceLoad::cylinder(r[3], r[4], r[0], r[2]).expect("load"), acc)
                .expect("field");
        let s = f.stress(r[5], r[6]).expect("point");
        let want = [r[7], r[8], r[9]];
        let big = want.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (g, w) in [s.xx, s.yy, s.xy].iter().zip(&want) {
            worst = worst.max((g - w).abs() / w.abs().max(1e-3 * big));
        }
    }
    worst
}

fn bench(c: &mut Criterion) {
    let m = GradedMaterial::new(1.0, 0.3, 0.3).expect("material");
    for tol in [1e-6, 1e-10] {
        let acc = Accuracy::new(stickslip_graded::Tolerance::relative(tol).expect("tolerance"))
            .expect("accuracy");
        println!(
            "accuracy graded StressField tol {tol:.0e}: max err {:.2e} vs mpmath",
            accuracy(acc)
        );
        let f = StressField::new(&m, SurfaceLoad::cylinder(1.0, 1.0, 0.3, 0.4).expect("load"), acc)
            .expect("field");
        let mut group = c.benchmark_group(format!("graded/stress_grid/tol={tol:.0e}"));
        group.sample_size(10);
        for n in [50usize, 100, 200] {
            let xs: Vec<f64> = (0..n).map(|i| -2.0 + 4.0 * i as f64 / (n - 1) as f64).collect();
            let ys: Vec<f64> = (0..n).map(|j| 0.01 + 2.0 * j as f64 / (n - 1) as f64).collect();
            group.throughput(Throughput::Elements((n * n) as u64));
            group.bench_with_input(BenchmarkId::from_parameter(format!("{n}x{n}")), &n, |b, _| {
                b.iter(|| f.grid(&xs, &ys).expect("grid"))
            });
        }
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
