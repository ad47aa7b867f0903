//! What a sweep point would pay to plan its FFTs afresh, against what it pays to use them
//! (issue 30, item 5: points of equal lattice size share their plans through the lattice
//! crate's process-wide cache, `crates/lattice/src/operator/plans.rs`):
//!
//! ```sh
//! cargo run --release -p stickslip-benches --example plan_cost
//! ```
//!
//! For each transform length n (the padded sides of the lattices the shipped scenes and the
//! wheel-rail patches use, and larger ones): the median time of planning a complex transform
//! of length n with a fresh planner (what a point without the cache pays per plan; an
//! operator on an n x n padded lattice makes four such plans, forward and inverse along each
//! axis), and the median time of one complex 2D transform of n x n (n transforms along each
//! axis) on one thread, the unit an iteration of a lattice solver is made of (a solve makes
//! tens to hundreds of forward-inverse pairs). One line per n.

use rustfft::num_complex::Complex64;
use rustfft::FftPlanner;
use std::time::Instant;

/// Median of `runs` timings of `f`, seconds.
fn median(runs: usize, mut f: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..runs)
        .map(|_| {
            let t0 = Instant::now();
            f();
            t0.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[runs / 2]
}

fn main() {
    println!(
        "n     plan (fresh planner)   four plans   2D transform n x n   four plans / 2D transform"
    );
    for n in [112usize, 128, 224, 256, 512, 1024, 2048] {
        let plan = median(41, || {
            let p = FftPlanner::<f64>::new().plan_fft_forward(n);
            std::hint::black_box(p);
        });
        let fft = FftPlanner::<f64>::new().plan_fft_forward(n);
        let mut data = vec![Complex64::new(1.0, 0.5); n * n];
        let mut scratch = vec![Complex64::new(0.0, 0.0); fft.get_inplace_scratch_len()];
        let runs = if n >= 1024 { 7 } else { 41 };
        let two_d = median(runs, || {
            // Rows, then each column copied out, transformed and copied back.
            for row in data.chunks_exact_mut(n) {
                fft.process_with_scratch(row, &mut scratch);
            }
            let mut col = vec![Complex64::new(0.0, 0.0); n];
            for j in 0..n {
                for (i, c) in col.iter_mut().enumerate() {
                    *c = data[i * n + j];
                }
                fft.process_with_scratch(&mut col, &mut scratch);
                for (i, c) in col.iter().enumerate() {
                    data[i * n + j] = *c;
                }
            }
            std::hint::black_box(&data);
        });
        println!(
            "{n:<5} {:>10.1} us          {:>8.1} us   {:>12.1} us         {:.3}",
            plan * 1e6,
            4.0 * plan * 1e6,
            two_d * 1e6,
            4.0 * plan / two_d
        );
    }
}
