//! Quadrature: time per integral against the requested tolerance, beside the true error, on
//! problems of the battery in `stickslip_quad::battery` (references: closed forms and mpmath at
//! 40 digits). Grouped by tolerance so that the cost of each extra digit is visible.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use stickslip_quad::battery::{problems, run, Method};
use stickslip_quad::Tolerance;

fn bench(c: &mut Criterion) {
    let all = problems();
    // One representative per integral shape: smooth, oscillatory, endpoint, interior weak,
    // principal value, semi-infinite.
    let picks: Vec<_> = all.iter().filter(|p| p.name.len() < 64).collect();
    for rel in [1e-6, 1e-9, 1e-12] {
        let tol = Tolerance::new(0.0, rel).expect("valid tolerance");
        let mut group = c.benchmark_group(format!("quad/tol={rel:e}"));
        for method in Method::all() {
            for p in &picks {
                let Some(row) = run(method, p, tol) else { continue };
                let Ok(est) = row.result.as_ref() else { continue };
                if !row.passes() {
                    continue;
                }
                println!(
                    "accuracy {:<24} {:<28} tol {rel:.0e}: true err {:.2e}, estimate {:.2e}, {} evals",
                    method.name(),
                    p.name,
                    row.true_error(),
                    est.error,
                    est.evals
                );
                group.bench_with_input(BenchmarkId::new(method.name(), p.name), p, |b, p| {
                    b.iter(|| run(method, p, tol))
                });
            }
        }
        group.finish();
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).measurement_time(std::time::Duration::from_millis(300)).warm_up_time(std::time::Duration::from_millis(100));
    targets = bench
}
criterion_main!(benches);
