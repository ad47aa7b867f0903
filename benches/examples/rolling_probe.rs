//! Time of one 3D steady rolling solve with the exact theory (issue 30, item 4): the
//! wheel–rail ellipse of the `rolling3d` bench (a/b = 1.33) on `nx` x `ny` cells, the
//! creepages of the bench, the solver's default tolerance unless given. Prints the set-up
//! (planning the operator), the solve, Newton steps, FFT products and the time of one
//! product, Kalker's C11 from the no-slip theory against his table (the accuracy beside the
//! time), and the peak memory.
//!
//! `cargo run --release -p stickslip-benches --example rolling_probe -- [nx ny [tolerance]]`
//! (default 226 170: about 30,000 contact elements).

use std::time::Instant;
use stickslip_benches::process::peak_rss;
use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
use stickslip_rolling::steady3d::{kalker, Creepage, SteadyRolling};

fn main() {
    let arg = |i: usize| std::env::args().nth(i);
    let nx: usize = arg(1).and_then(|a| a.parse().ok()).unwrap_or(226);
    let ny: usize = arg(2).and_then(|a| a.parse().ok()).unwrap_or(170);
    let tol: Option<f64> = arg(3).and_then(|a| a.parse().ok());
    let (g, nu, f, load) = (8e10, 0.28, 0.3, 1e5);
    let m = Material::new(2.0 * g * (1.0 + nu), nu).expect("material");
    let (a, b) = (7.19e-3, 5.41e-3);
    let p0 = 1.5 * load / (std::f64::consts::PI * a * b);
    let scale = f * p0 / g;
    let creep = Creepage {
        longitudinal: 0.5 * scale,
        lateral: 0.2 * scale,
        spin: 0.3 * scale / (a * b).sqrt(),
    };
    let grid = ContactGrid::hertz_ellipse(a, b, load, nx, ny).expect("grid");
    let t0 = Instant::now();
    let mut problem = SteadyRolling::new(&grid, [m, m], f).expect("problem");
    if let Some(t) = tol {
        problem = problem.with_tolerance(t).expect("tolerance");
    }
    let setup = t0.elapsed().as_secs_f64();
    let t1 = Instant::now();
    let s = problem.solve(&creep).expect("solve");
    let solve = t1.elapsed().as_secs_f64();
    // One product's time: the no-slip solve's products over its time is not clean (GMRES
    // work), so time the linear theory separately and report C11 with it.
    // The same creepages from the no-slip state on the fine lattice alone: the nesting's
    // gain, and the two answers side by side.
    let t3 = Instant::now();
    let cold = SteadyRolling::new(&grid, [m, m], f).expect("problem").without_nesting();
    let cold = match tol {
        Some(t) => cold.with_tolerance(t).expect("tolerance"),
        None => cold,
    };
    let c = cold.solve(&creep).expect("cold solve");
    let cold_s = t3.elapsed().as_secs_f64();
    let dq =
        s.qx.iter()
            .zip(&s.qy)
            .zip(c.qx.iter().zip(&c.qy))
            .map(|((a, b), (x, y))| (a - x).hypot(b - y))
            .fold(0.0, f64::max)
            / (f * p0);
    println!(
        "without nesting: {cold_s:.3} s ({} Newton, {} products, residual {:.1e}); forces differ by \
         {:.1e} fN, tractions by {dq:.1e} f p0",
        c.info.iterations,
        c.info.products,
        c.info.residual,
        (s.fx - c.fx).hypot(s.fy - c.fy) / (f * load)
    );
    let t2 = Instant::now();
    let lin = problem
        .solve_no_slip(&Creepage { longitudinal: 1e-6, ..Default::default() })
        .expect("linear");
    let lin_s = t2.elapsed().as_secs_f64();
    let k = kalker::coefficients(a / b, nu).expect("table");
    let c11 = -lin.fx / (g * a * b * 1e-6);
    println!(
        "{} elements ({nx} x {ny}): set-up {setup:.3} s, solve {solve:.3} s ({} Newton, {} products, \
         {:.2} ms per product incl. GMRES work), residual {:.1e}, stick {:.3}, |F|/fN {:.4}; \
         no-slip {lin_s:.3} s ({} products), C11 {c11:.4} vs Kalker {:.4} ({:+.2} %); peak {:.0} MiB",
        grid.len(),
        s.info.iterations,
        s.info.products,
        1e3 * solve / s.info.products as f64,
        s.info.residual,
        s.stick_fraction(),
        s.fx.hypot(s.fy) / (f * load),
        lin.info.products,
        k.c11,
        100.0 * (c11 / k.c11 - 1.0),
        peak_rss() as f64 / 1048576.0
    );
}
