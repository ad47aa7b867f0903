//! Subsurface stress field (issue 17): a 256 x 256 lattice under the sliding Hertz traction
//! (p Hertz with a = 100 cells, qx = 0.25 p), 64 depth layers z = 0.05 a ... 3.2 a, all six
//! components plus von Mises, Tresca and the largest principal stress. Printed beside the time:
//! the accuracy on the axis, where the shear does not contribute to sigma_z and sigma_r, against
//! the closed forms of Johnson eq. 3.45, and the maximum shear against 0.31 p0 at 0.48 a.
//! Target (issue 17): <= 3 s on 2 cores.

use criterion::{criterion_group, criterion_main, Criterion};
use std::time::Instant;
use stickslip_traction::field::{subsurface_field, FieldConfig, Lattice, SurfaceTraction};

const NU: f64 = 0.3;

fn bench(c: &mut Criterion) {
    let (side, cells) = (256usize, 100usize);
    let a = 1.0;
    let h = a / cells as f64;
    // Cell (128, 128) is centred on the origin.
    let l = Lattice::new(side, side, h, h, -128.0 * h, -128.0 * h).expect("lattice");
    let mut p = vec![0.0; side * side];
    for j in 0..side {
        for i in 0..side {
            let (x, y) = l.centre(i, j);
            p[j * side + i] = (1.0 - (x * x + y * y) / (a * a)).max(0.0).sqrt();
        }
    }
    let qx: Vec<f64> = p.iter().map(|v| 0.25 * v).collect();
    let depths: Vec<f64> = (1..=64).map(|k| 0.05 * a * k as f64).collect();
    let t = SurfaceTraction { p: &p, qx: &qx, ..Default::default() };
    let cfg = FieldConfig::default();

    let t0 = Instant::now();
    let f = subsurface_field(l, NU, &t, &depths, cfg).expect("field");
    let secs = t0.elapsed().as_secs_f64();
    let kc = 128 * side + 128;
    let (mut ez, mut er) = (0.0f64, 0.0f64);
    for layer in &f.layers {
        let zeta = layer.z / a;
        let sz = -1.0 / (1.0 + zeta * zeta);
        let sr = -(1.0 + NU) * (1.0 - zeta * (1.0 / zeta).atan()) + 0.5 / (1.0 + zeta * zeta);
        ez = ez.max((layer.zz[kc] - sz).abs() / sz.abs());
        // sigma_r changes sign near z = 1.6 a: error relative to p0 there.
        er = er.max((layer.xx[kc] - sr).abs() / sr.abs().max(0.05));
    }
    let m = f.maxima();
    println!(
        "accuracy subsurface_field {side}x{side}, 64 layers, p + qx (f = 0.25), a = {cells} cells: \
         axis sigma_z max rel err {ez:.2e}, sigma_r {er:.2e}; max von Mises {:.4} p0 at z = {:.2} a, \
         max Tresca {:.4} p0 at ({:.3}, {:.3}, {:.2}) a, max principal {:.4} p0 at x = {:.3} a; \
         one run {secs:.3} s",
        m.von_mises.value, m.von_mises.z, m.tresca.value, m.tresca.x, m.tresca.y, m.tresca.z,
        m.max_principal.value, m.max_principal.x,
    );
    let mut group = c.benchmark_group("subsurface_field");
    group.sample_size(10);
    group.bench_function("256x256x64 p+qx", |b| {
        b.iter(|| subsurface_field(l, NU, &t, &depths, cfg).expect("field"))
    });
    // All three loads (sliding at 30 degrees: qx = 0.25 p cos 30, qy = 0.25 p sin 30): 18
    // kernels per layer instead of 12.
    let qx3: Vec<f64> = p.iter().map(|v| 0.25 * v * 30f64.to_radians().cos()).collect();
    let qy3: Vec<f64> = p.iter().map(|v| 0.25 * v * 30f64.to_radians().sin()).collect();
    let t3 = SurfaceTraction { p: &p, qx: &qx3, qy: &qy3 };
    group.bench_function("256x256x64 p+qx+qy", |b| {
        b.iter(|| subsurface_field(l, NU, &t3, &depths, cfg).expect("field"))
    });
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().measurement_time(std::time::Duration::from_millis(500)).warm_up_time(std::time::Duration::from_millis(100));
    targets = bench
}
criterion_main!(benches);
