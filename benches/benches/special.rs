//! Special functions: nanoseconds per call, beside the max relative error on the golden
//! tables of `crates/special/tests/data` (mpmath, 60 digits).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;
use stickslip_special as sp;

type F = fn(f64) -> f64;

const FUNCS: [(&str, F); 15] = [
    ("gamma", sp::gamma),
    ("ln_gamma", sp::ln_gamma),
    ("bessel_i0", sp::bessel_i0),
    ("bessel_i1", sp::bessel_i1),
    ("bessel_k0", sp::bessel_k0),
    ("bessel_k1", sp::bessel_k1),
    ("bessel_i0e", sp::bessel_i0e),
    ("bessel_i1e", sp::bessel_i1e),
    ("bessel_k0e", sp::bessel_k0e),
    ("bessel_k1e", sp::bessel_k1e),
    ("bessel_i1_over_i0", sp::bessel_i1_over_i0),
    ("bessel_k0_over_k1", sp::bessel_k0_over_k1),
    ("ellipk", sp::ellipk),
    ("ellipe", sp::ellipe),
    ("ellipd", sp::ellipd),
];

/// Golden rows (x, reference) of one function.
fn table(name: &str) -> Vec<(f64, f64)> {
    let path = format!("{}/../crates/special/tests/data/{name}.tsv", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .filter_map(|l| {
            let mut it = l.split('\t');
            Some((it.next()?.trim().parse().ok()?, it.next()?.trim().parse().ok()?))
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("special");
    for (name, f) in FUNCS {
        let rows = table(name);
        let max_err = rows
            .iter()
            .map(|&(x, want)| {
                if f(x) == want {
                    0.0
                } else {
                    ((f(x) - want) / want.abs().max(f64::MIN_POSITIVE)).abs()
                }
            })
            .fold(0.0_f64, f64::max);
        println!("accuracy {name:<18} max rel err {max_err:.2e} over {} golden points", rows.len());
        let xs: Vec<f64> = rows.iter().map(|r| r.0).collect();
        group.bench_with_input(BenchmarkId::new(name, xs.len()), &xs, |b, xs| {
            b.iter(|| xs.iter().map(|&x| f(black_box(x))).fold(0.0, |a, v| a + v))
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
