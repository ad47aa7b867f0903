//! Goryacheva rolling: the root solves (eqs 19, 24) and the stress quadratures (eqs 12, 13),
//! beside their accuracy against the mpmath table
//! (`crates/rolling/tests/data/goryacheva_reference.txt`).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use stickslip_benches::data::{goryacheva_rows, GoryachevaRow};
use stickslip_quad::Tolerance;
use stickslip_rolling::{solve, GoryachevaParams, StressConfig};

fn params(r: &GoryachevaRow) -> GoryachevaParams {
    GoryachevaParams::new(r.e, r.nu, r.r, r.p, r.rho, r.delta, r.alpha, r.beta, r.w).expect("row")
}

fn bench(c: &mut Criterion) {
    let rows = goryacheva_rows();
    // one row per decade of the Bessel argument x1 (problem size = how hard the roots are)
    let mut picks: Vec<&GoryachevaRow> = Vec::new();
    for dec in [-4, -2, 0, 2, 4, 6] {
        let lo = 10f64.powi(dec);
        if let Some(r) = rows.iter().find(|r| r.x1 >= lo && r.x1 < 100.0 * lo) {
            picks.push(r);
        }
    }
    let mut group = c.benchmark_group("rolling/solve");
    for r in &picks {
        let s = solve(&params(r)).expect("solve");
        let got =
            [s.contact_length, s.shift, s.stick_length, s.c2, s.tangential_force, s.moment_m1];
        let err = got.iter().zip(&r.want).map(|(g, w)| ((g - w) / w).abs()).fold(0.0, f64::max);
        println!("accuracy rolling solve x1 = {:.1e}: max rel err {err:.2e} vs mpmath", r.x1);
        group.bench_with_input(BenchmarkId::new("x1", format!("{:.0e}", r.x1)), r, |b, r| {
            b.iter(|| solve(&params(r)).expect("solve"))
        });
    }
    group.finish();

    let mut group = c.benchmark_group("rolling/stress");
    for tol in [1e-6, 1e-12] {
        let cfg =
            StressConfig { tol: Tolerance::new(0.0, tol).expect("tol"), ..StressConfig::default() };
        for r in picks.iter().filter(|r| r.x1 > 1e-2 && r.x1 < 1e3) {
            let s = solve(&params(r)).expect("solve");
            let (lo, hi) = (-s.rear, s.front);
            let xs: Vec<f64> = (1..100).map(|i| lo + (hi - lo) * f64::from(i) / 100.0).collect();
            // accuracy: the reported error bounds of the quadratures, relative to P/l
            let scale = r.p / s.contact_length;
            let est = xs
                .iter()
                .map(|&x| s.pressure(x, &cfg).expect("pressure").error / scale)
                .fold(0.0, f64::max);
            println!("accuracy rolling pressure tol {tol:.0e} x1 = {:.1e}: max error estimate {est:.2e} (P/l units)", r.x1);
            group.bench_with_input(
                BenchmarkId::new(
                    format!("pressure+shear/tol={tol:.0e}"),
                    format!("x1={:.0e}", r.x1),
                ),
                &xs,
                |b, xs| {
                    b.iter(|| {
                        xs.iter()
                            .map(|&x| {
                                s.pressure(x, &cfg).expect("p").value
                                    + s.shear(x, &cfg).expect("t").value
                            })
                            .sum::<f64>()
                    })
                },
            );
        }
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench
}
criterion_main!(benches);
