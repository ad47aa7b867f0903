//! Halfspace: nanoseconds per exact uniform-rectangle influence coefficient (grouped by grid
//! size), and the elliptic Hertz solve, each beside its accuracy against a closed form or the
//! mpmath table.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use std::hint::black_box;
use stickslip_benches::data;
use stickslip_halfspace::hertz::HertzEllipse;
use stickslip_halfspace::rectangle::{inv_r_integral, pressure_uz, shear_x_ux, Rect};
use stickslip_halfspace::Material;

fn bench(c: &mut Criterion) {
    // accuracy: Love's integral at the corner and centre of a unit square (closed forms)
    let sq = Rect::new(0.0, 1.0, 0.0, 1.0).expect("rect");
    let ln = (1.0 + 2f64.sqrt()).ln();
    let e1 = (inv_r_integral(&sq, 0.0, 0.0) / (2.0 * ln) - 1.0).abs();
    let e2 = (inv_r_integral(&sq, 0.5, 0.5) / (4.0 * ln) - 1.0).abs();
    println!("accuracy rectangle 1/r integral: corner rel err {e1:.1e}, centre {e2:.1e}");
    let comp = Material::new(2.1e11, 0.3).expect("steel").compliance();
    let mut group = c.benchmark_group("halfspace/influence");
    for n in [16usize, 32, 64] {
        let h = 1.0 / n as f64;
        let rect = Rect::centered(0.0, 0.0, 0.5 * h, 0.5 * h).expect("rect");
        let pts: Vec<(f64, f64)> =
            (0..n * n).map(|k| (((k % n) as f64 + 0.5) * h, ((k / n) as f64 + 0.5) * h)).collect();
        group.throughput(Throughput::Elements((2 * n * n) as u64));
        group.bench_with_input(BenchmarkId::new("uz+ux", format!("{n}x{n}")), &pts, |b, pts| {
            b.iter(|| {
                pts.iter()
                    .map(|&(x, y)| {
                        pressure_uz(&comp, &rect, black_box(x), y) + shear_x_ux(&comp, &rect, x, y)
                    })
                    .sum::<f64>()
            })
        });
    }
    group.finish();

    let rows = data::rows(data::HERTZ_ELLIPSE, Some(','), 0);
    let mut group = c.benchmark_group("halfspace/hertz_ellipse");
    for r in rows.iter().filter(|r| [1.0, 2.0, 16.0, 1e4, 1e6].contains(&r[0])) {
        let el = HertzEllipse::new(1.0, 1.0 / r[0], 1.0, 1.0).expect("ellipse");
        let err = [
            (el.semi_axis_x(), r[2]),
            (el.semi_axis_y(), r[3]),
            (el.max_pressure(), r[4]),
            (el.approach(), r[5]),
        ]
        .iter()
        .map(|(g, w)| ((g - w) / w).abs())
        .fold(0.0, f64::max);
        println!(
            "accuracy hertz ellipse ratio {:e}: max rel err {err:.1e} vs mpmath, {} iterations",
            r[0],
            el.iterations()
        );
        group.bench_with_input(BenchmarkId::new("ratio", r[0]), &r[0], |b, &ratio| {
            b.iter(|| HertzEllipse::new(1.0, 1.0 / black_box(ratio), 1.0, 1.0).expect("ellipse"))
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20);
    targets = bench
}
criterion_main!(benches);
