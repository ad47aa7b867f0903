//! Subsurface stress field (issue 17): a 256 x 256 lattice under the sliding Hertz traction
//! (p Hertz with a = 100 cells, qx = 0.25 p), 64 depth layers z = 0.05 a ... 3.2 a, all six
//! components plus von Mises, Tresca and the largest principal stress. Printed beside the time:
//! the accuracy on the axis, where the shear does not contribute to sigma_z and sigma_r, against
//! the closed forms of Johnson eq. 3.45, and the maximum shear against 0.31 p0 at 0.48 a.
//! Target (issue 17): <= 3 s on 2 cores.
//!
//! Also the per-point fields of the Hertz loads (`hertz::ellipse_field`: Hamilton's sliding
//! sphere and the Hertz ellipse as one integral in the ellipsoidal coordinate) beside the 2D
//! Cerruti quadrature they replace, with their agreement; and the lattice field above against
//! Hamilton's on the x axis section (the lattice's discretisation error at 200 cells across).

use criterion::{criterion_group, criterion_main, Criterion};
use std::time::Instant;
use stickslip_halfspace::hertz::ellipse_field::HertzLoadField;
use stickslip_halfspace::hertz::sphere_field::sliding_sphere_stress;
use stickslip_lattice::{
    field::subsurface_field, field::FieldConfig, field::Lattice, field::SurfaceTraction,
};

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
    // The lattice against Hamilton's field (same load) on the section y = 0, every 4th cell
    // in x over |x| <= 1.24 a, every 4th layer: the lattice's discretisation error.
    let hamilton = HertzLoadField::new(a, a, 1.0, 0.25, NU).expect("field");
    let mut gap = 0.0f64;
    for layer in f.layers.iter().step_by(4) {
        for i in (128 - 124..=128 + 124).step_by(4) {
            let (x, _) = l.centre(i, 128);
            let s = hamilton.stress(x, 0.0, layer.z).expect("stress").stress;
            let k = 128 * side + i;
            let pairs = [
                (layer.xx[k], s.xx),
                (layer.yy[k], s.yy),
                (layer.zz[k], s.zz),
                (layer.xy[k], s.xy),
                (layer.xz[k], s.xz),
                (layer.yz[k], s.yz),
            ];
            for (u, w) in pairs {
                gap = gap.max((u - w).abs());
            }
        }
    }
    println!(
        "accuracy subsurface_field {side}x{side} lattice vs Hamilton's sliding sphere (f = 0.25) on \
         y = 0, |x| <= 1.24 a, z = 0.05 ... 3.05 a: max |diff| {gap:.2e} p0"
    );
    // Per point: the ellipsoidal-coordinate integral against the 2D Cerruti quadrature.
    let pts = [(0.2, -0.3, 0.4), (-1.0, 0.0, 0.01), (1.3, 0.4, 0.6), (0.0, 0.0, 0.48)];
    let mut agree = 0.0f64;
    let t1 = Instant::now();
    let mut evals = 0usize;
    for &(x, y, z) in &pts {
        let r = sliding_sphere_stress(a, 1.0, 0.25, NU, (x, y, z), 1e-11).expect("quadrature");
        evals += r.evals;
        let s = hamilton.stress(x, y, z).expect("stress").stress;
        let d = [
            s.xx - r.stress.xx,
            s.yy - r.stress.yy,
            s.zz - r.stress.zz,
            s.xy - r.stress.xy,
            s.xz - r.stress.xz,
            s.yz - r.stress.yz,
        ];
        agree = d.iter().fold(agree, |m, v| m.max(v.abs()));
    }
    let quad_secs = t1.elapsed().as_secs_f64() / pts.len() as f64;
    println!(
        "accuracy hertz_point_field: Hamilton's sliding sphere as one s-integral vs 2D Cerruti \
         quadrature (rel tol 1e-11, {} evaluations, {quad_secs:.3} s per point) at {} points: max \
         |diff| {agree:.2e} p0",
        evals / pts.len(),
        pts.len()
    );
    let ellipse = HertzLoadField::new(a, 0.4 * a, 1.0, 0.0, NU).expect("field");
    let mut group = c.benchmark_group("hertz_point_field");
    group.bench_function("sliding sphere, s-integral, 4 points", |b| {
        b.iter(|| pts.map(|(x, y, z)| hamilton.stress(x, y, z).expect("stress").stress.xx))
    });
    group.bench_function("ellipse b/a = 0.4, s-integral, 4 points", |b| {
        b.iter(|| pts.map(|(x, y, z)| ellipse.stress(x, y, z).expect("stress").stress.xx))
    });
    group.finish();
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
