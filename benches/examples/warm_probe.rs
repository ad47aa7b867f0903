//! Issue 31, item 5's yardstick: a history step against a warm-started steady solve of the
//! same lattice. The Hertz sphere of `history_speed` (seed 002 Example 1 proportions,
//! `across` cells in diameter) is loaded from 0 to T* = fP/2 in `per` equal steps twice:
//!
//! - as a load history (`HistoryProblem`, each step incremental from the one before), and
//! - as a chain of steady (monotonic) solves at the same loads, each started from the
//!   previous load's solution (`FastProblem::solve_from` with `WarmStart`), on an operator
//!   planned once.
//!
//! Prints both per step (products, seconds; the first step of each left out: it starts from
//! zero) and their ratio, beside a cold solve at T*.
//!
//! `cargo run --release -p stickslip-benches --example warm_probe -- 256 50 [tolerance]`

use std::time::Instant;
use stickslip_benches::history_bench::HistoryBench;
use stickslip_traction::history::{HistoryProblem, LoadPath, PathControl};
use stickslip_traction::{Error, FastProblem, Load, WarmStart};

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let HistoryBench { across, per, tol, p, f, steel: s, grid, config, .. } =
        HistoryBench::from_args();
    let ts = 0.5 * f * p;
    let problem = |t: f64| {
        FastProblem::new(&grid, [s, s], f, Load::polar(t, 0.0).expect("load"))
            .expect("problem")
            .with_config(config)
    };

    let t0 = Instant::now();
    let cold = problem(ts).solve().expect("cold solve");
    let cold_seconds = t0.elapsed().as_secs_f64();

    // Steady solves along the loading branch, each warm from the one before.
    let op = problem(ts).operator().expect("operator");
    let mut scratch = op.make_scratch();
    let mut start: Option<WarmStart> = None;
    let (mut warm_products, mut warm_seconds) = (Vec::new(), Vec::new());
    for k in 1..=per {
        let t = ts * k as f64 / per as f64;
        let prob = problem(t);
        let t1 = Instant::now();
        let sol = match &start {
            Some(w) => prob.solve_from(&op, &mut scratch, w).expect("warm solve"),
            None => prob.solve().expect("first solve"),
        };
        let secs = t1.elapsed().as_secs_f64();
        if start.is_some() {
            warm_products.push(sol.info.products as f64);
            warm_seconds.push(secs);
        }
        start = Some(WarmStart::from(&sol));
    }

    // The same loads as a history's first branch.
    let path = LoadPath::new(PathControl::Force, vec![0.0, ts], vec![p], per).expect("path");
    let pressure = grid.pressure.clone();
    let out = HistoryProblem::new(&grid, [s, s], f)
        .expect("problem")
        .with_config(config)
        .run(&path, |_| Ok::<_, Error>(pressure.clone()))
        .expect("history");
    let steps = &out.steps[2..];
    let hist_products: Vec<f64> = steps.iter().map(|s| s.products as f64).collect();
    let hist_seconds: Vec<f64> = steps.iter().map(|s| s.seconds).collect();

    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    println!(
        "{across} across, {per} steps to fP/2, tolerance {tol:.0e}: cold solve {cold_seconds:.3} s \
         ({} products); warm steady solve mean {:.1} products, {:.4} s (median {:.4} s); \
         history step mean {:.1} products, {:.4} s (median {:.4} s); history / warm: products \
         {:.2}, time {:.2} (medians {:.2})",
        cold.info.products,
        mean(&warm_products),
        mean(&warm_seconds),
        median(warm_seconds.clone()),
        mean(&hist_products),
        mean(&hist_seconds),
        median(hist_seconds.clone()),
        mean(&hist_products) / mean(&warm_products),
        mean(&hist_seconds) / mean(&warm_seconds),
        median(hist_seconds.clone()) / median(warm_seconds.clone()),
    );
}
