//! 3D steady rolling (issue 18): the exact theory at about 30,000 contact elements, FASTSIM on
//! 100 x 100, and a 1,000-point creep-force table at 40 x 40 with the exact theory; each with
//! its accuracy beside its time (Kalker's C11 for the exact grid, the force against the exact
//! theory for FASTSIM; `docs/accuracy.md` has the full accuracy sweeps).

use criterion::{criterion_group, criterion_main, Criterion};
use std::time::Instant;
use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
use stickslip_rolling::{
    steady3d::fastsim, steady3d::kalker, steady3d::Creepage, steady3d::SteadyRolling,
};

const G: f64 = 8e10;
const NU: f64 = 0.28;
const F: f64 = 0.3;
const LOAD: f64 = 1e5;

fn ellipse(a: f64, b: f64, nx: usize, ny: usize) -> ContactGrid {
    ContactGrid::hertz_ellipse(a, b, LOAD, nx, ny).expect("grid")
}

fn bench(c: &mut Criterion) {
    let m = Material::new(2.0 * G * (1.0 + NU), NU).expect("material");
    // A wheel-rail ellipse, a/b = 1.33 (radii 460 mm and 300 mm under 100 kN).
    let (a, b) = (7.19e-3, 5.41e-3);
    let p0 = 1.5 * LOAD / (std::f64::consts::PI * a * b);
    let scale = F * p0 / G;
    let creep = Creepage {
        longitudinal: 0.5 * scale,
        lateral: 0.2 * scale,
        spin: 0.3 * scale / (a * b).sqrt(),
    };
    let mut group = c.benchmark_group("rolling3d");
    group.sample_size(10);

    // Exact theory, about 30,000 elements.
    let big = ellipse(a, b, 226, 170);
    let exact =
        SteadyRolling::new(&big, [m, m], F).and_then(|p| p.with_tolerance(1e-8)).expect("problem");
    let t0 = Instant::now();
    let s = exact.solve(&creep).expect("solve");
    let k = kalker::coefficients(a / b, NU).expect("table");
    let lin = exact
        .solve_no_slip(&Creepage { longitudinal: 1e-6, ..Default::default() })
        .expect("linear");
    let c11 = -lin.fx / (G * a * b * 1e-6);
    println!(
        "accuracy rolling3d exact {} elements: {} Newton steps, {} FFT products, residual {:.1e}, stick {:.3}, \
         |F|/fN {:.4}; C11 {c11:.4} vs Kalker {:.4} ({:+.2} %); one solve {:.2} s",
        big.len(),
        s.info.iterations,
        s.info.products,
        s.info.residual,
        s.stick_fraction(),
        s.fx.hypot(s.fy) / (F * LOAD),
        k.c11,
        100.0 * (c11 / k.c11 - 1.0),
        t0.elapsed().as_secs_f64()
    );
    group.bench_function("exact_30k", |bch| bch.iter(|| exact.solve(&creep).expect("solve")));

    // FASTSIM on 100 x 100 cells over the ellipse's box, against the exact theory on that grid.
    let g100 = ellipse(a, b, 100, 100);
    let fs = fastsim::solve(&g100, a, b, G, NU, F, &creep).expect("FASTSIM");
    let ex = SteadyRolling::new(&g100, [m, m], F)
        .and_then(|p| p.with_tolerance(1e-8))
        .expect("problem")
        .solve(&creep)
        .expect("solve");
    println!(
        "accuracy rolling3d FASTSIM 100x100 ({} elements): |F - F_exact|/fN = {:.4}",
        g100.len(),
        (fs.fx - ex.fx).hypot(fs.fy - ex.fy) / (F * LOAD)
    );
    group.bench_function("fastsim_100x100", |bch| {
        bch.iter(|| fastsim::solve(&g100, a, b, G, NU, F, &creep).expect("FASTSIM"))
    });

    // A creep-force table of 1,000 points at 40 x 40 with the exact theory: 10 longitudinal
    // x 10 lateral x 10 spin creepages on one ellipse, timed once.
    let g40 = ellipse(a, b, 40, 40);
    let table =
        SteadyRolling::new(&g40, [m, m], F).and_then(|p| p.with_tolerance(1e-8)).expect("problem");
    let t0 = Instant::now();
    let mut rows = 0;
    let mut worst: f64 = 0.0;
    for i in 0..10 {
        for j in 0..10 {
            for l in 0..10 {
                let cr = Creepage {
                    longitudinal: (i as f64) * 0.4 * scale,
                    lateral: (j as f64) * 0.4 * scale,
                    spin: (l as f64 - 4.5) * 0.2 * scale / (a * b).sqrt(),
                };
                let s = table.solve(&cr).expect("table point");
                worst = worst.max(s.info.residual);
                rows += 1;
            }
        }
    }
    println!(
        "accuracy rolling3d creep-force table: {rows} points at 40x40 ({} elements), exact theory, \
         worst residual {worst:.1e}, {:.1} s in all",
        g40.len(),
        t0.elapsed().as_secs_f64()
    );
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
