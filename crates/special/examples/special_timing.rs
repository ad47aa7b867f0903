//! Rough per-call timings (not a benchmark): `cargo run --release -p stickslip-special --example special_timing`.

use std::hint::black_box;
use std::time::Instant;
use stickslip_special as sp;

fn time(label: &str, f: fn(f64) -> f64, lo: f64, hi: f64) {
    let n = 1_000_000;
    let xs: Vec<f64> = (0..n).map(|i| lo + (hi - lo) * (i as f64 + 0.5) / n as f64).collect();
    let t = Instant::now();
    let mut acc = 0.0;
    for &x in &xs {
        acc += f(black_box(x));
    }
    let ns = t.elapsed().as_secs_f64() * 1e9 / n as f64;
    println!("{label:>18} on [{lo}, {hi}]: {ns:6.1} ns/call (checksum {acc:e})");
}

fn main() {
    time("gamma", sp::gamma, 0.01, 170.0);
    time("gamma (neg)", sp::gamma, -169.99, -0.01);
    time("ln_gamma", sp::ln_gamma, 0.01, 1e3);
    time("bessel_i0", sp::bessel_i0, 0.0, 700.0);
    time("bessel_i1", sp::bessel_i1, 0.0, 700.0);
    time("bessel_k0", sp::bessel_k0, 0.01, 700.0);
    time("bessel_k1", sp::bessel_k1, 0.01, 700.0);
    time("bessel_k0e", sp::bessel_k0e, 0.01, 50.0);
    time("bessel_i1_over_i0", sp::bessel_i1_over_i0, 0.0, 50.0);
    time("bessel_k0_over_k1", sp::bessel_k0_over_k1, 0.01, 50.0);
    time("ellipk", sp::ellipk, -10.0, 0.999);
    time("ellipe", sp::ellipe, -10.0, 1.0);
}
