//! Speed of load histories (issue 31, item 5): a Mindlin–Deresiewicz cycle on the Hertz
//! sphere (seed 002 Example 1 proportions, T* = fP/2) with the contact `across` cells in
//! diameter (cells inside the circle only), `per` steps between corners of the path
//! 0 -> T* -> -T* -> T* (so one full cycle is `2 per` steps). Prints the steps per second,
//! the mean step against a cold solve of the same lattice (`FastProblem::solve`: operator
//! planning, nested start and iteration), the energy per cycle against the closed form (a
//! fast wrong answer is not a result) and the peak memory.
//!
//! `cargo run --release -p stickslip-benches --example history_speed -- 256 50 [tolerance] [line]`
//! (`line`: tractions along the load, the LP's one-direction assumption).

use std::time::Instant;
use stickslip_benches::history_bench::HistoryBench;
use stickslip_benches::process::{cpu_seconds, peak_rss};
use stickslip_traction::closed::Deresiewicz;
use stickslip_traction::history::{HistoryDirections, HistoryProblem, LoadPath, PathControl};
use stickslip_traction::{Error, FastProblem, Load};

fn main() {
    let arg = |i: usize| std::env::args().nth(i);
    let directions = if arg(4).is_some_and(|a| a == "line") {
        HistoryDirections::Line
    } else {
        HistoryDirections::Free
    };
    let HistoryBench { across, per, tol, p, f, steel: s, a, grid, config } =
        HistoryBench::from_args();
    let ts = 0.5 * f * p;

    // A cold solve of the same lattice at T*, the reference cost.
    let t0 = Instant::now();
    let cold = FastProblem::new(&grid, [s, s], f, Load::polar(ts, 0.0).expect("load"))
        .expect("problem")
        .with_config(config)
        .solve()
        .expect("cold solve");
    let cold_seconds = t0.elapsed().as_secs_f64();

    let path =
        LoadPath::new(PathControl::Force, vec![0.0, ts, -ts, ts], vec![p], per).expect("path");
    let prob = HistoryProblem::new(&grid, [s, s], f)
        .expect("problem")
        .with_config(config)
        .with_directions(directions);
    let pressure = grid.pressure.clone();
    let c0 = cpu_seconds();
    let t1 = Instant::now();
    let out = prob.run(&path, |_| Ok::<_, Error>(pressure.clone())).expect("history");
    let wall = t1.elapsed().as_secs_f64();
    let cpu = cpu_seconds() - c0;
    // Steps after the first (the first is a cold solve from the unloaded state).
    let warm = &out.steps[1..];
    let mean = warm.iter().map(|s| s.seconds).sum::<f64>() / warm.len() as f64;
    let cycle: f64 = out.steps[per + 1..=3 * per].iter().map(|s| s.seconds).sum();
    let products = warm.iter().map(|s| s.products).sum::<usize>() as f64 / warm.len() as f64;
    let newton = warm.iter().map(|s| s.newton_iterations).sum::<usize>() as f64 / warm.len() as f64;
    let md = 2.0 * Deresiewicz::new(a, p, f, ts).expect("M-D").energy_per_cycle(&s);
    let energy = out.loops.first().map_or(f64::NAN, |l| l.energy);
    println!(
        "across {across}: N = {}, tolerance {tol:.0e}, {directions:?} directions; cold solve {cold_seconds:.3} s ({} levels, {} Newton, {} products); \
         history of {} steps: {wall:.2} s wall, {cpu:.2} s CPU, {:.1} steps/s; mean step {mean:.3} s \
         ({newton:.1} Newton, {products:.0} products) = {:.2} of a cold solve; one cycle of {} steps {cycle:.2} s; \
         energy per cycle {:+.3} % from M-D; peak memory {:.0} MiB",
        grid.len(),
        cold.info.levels,
        cold.info.iterations,
        cold.info.products,
        out.steps.len(),
        out.steps.len() as f64 / wall,
        mean / cold_seconds,
        2 * per,
        100.0 * (energy / md - 1.0),
        peak_rss() as f64 / (1024.0 * 1024.0),
    );
}
