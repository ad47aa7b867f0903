//! The normal-contact benchmark problems of issue 30, shared by the criterion bench
//! `normal`, the example `normal_probe` and the side-by-side script
//! `scripts/compare_aspher.py` (which reads the heights the example writes).
//!
//! * [`rough_heights`]: a periodic self-affine surface that is the *same continuous
//!   surface* on every lattice: a trigonometric polynomial whose modes $(m, l)$,
//!   $k_\text{low} \le |(m, l)| \le k_\text{high}$ cycles per period, have amplitudes
//!   $|(m,l)|^{-(1+H)}$ (power spectrum $\propto k^{-2(1+H)}$) and phases drawn from a
//!   SplitMix64 stream in a fixed order over the band, independent of the lattice. Sampled at
//!   the cell centres of any lattice with more than $2k_\text{high}$ cells a side, it has the
//!   same discrete rms height (Parseval), so refining the lattice refines the discretisation
//!   of one problem: the right test of whether iterations grow with the lattice.
//! * [`hertz_gap`]: a sphere on a free lattice, the Hertz contact radius 0.3 of the side.

use rayon::prelude::*;
use rustfft::num_complex::Complex;
use rustfft::FftPlanner;
use std::f64::consts::PI;
use stickslip_lattice::roughness::SplitMix;

/// The band of the benchmark surface, cycles per period.
pub const K_LOW: usize = 4;
/// See [`K_LOW`].
pub const K_HIGH: usize = 64;
/// Hurst exponent of the benchmark surface.
pub const HURST: f64 = 0.8;

/// Heights of the band-limited self-affine surface (module docs) on an `n` x `n` lattice over
/// one period, row-major `j * n + i`, zero mean, scaled to an rms height of 1 (continuous, and
/// discrete for `n > 2 k_high`). Evaluated by inverse FFTs of the band's coefficients: the
/// $2k_\text{high}+1$ columns of the band along $y$, then every row along $x$.
#[must_use]
pub fn rough_heights(n: usize, k_low: usize, k_high: usize, hurst: f64, seed: u64) -> Vec<f64> {
    let mut rng = SplitMix(seed);
    // Modes of the half plane l > 0, or l = 0 and m > 0, in a fixed order.
    let kh = k_high as i64;
    let mut modes = Vec::new();
    for l in 0..=kh {
        for m in -kh..=kh {
            if l == 0 && m <= 0 {
                continue;
            }
            let k = ((m * m + l * l) as f64).sqrt();
            if k < k_low as f64 || k > k_high as f64 {
                continue;
            }
            let phase = 2.0 * PI * rng.uniform();
            modes.push((m, l, k.powf(-(1.0 + hurst)), phase));
        }
    }
    // rms of sum a cos(...) is sqrt(sum a^2 / 2).
    let rms = (modes.iter().map(|m| m.2 * m.2).sum::<f64>() / 2.0).sqrt();
    assert!(n > 2 * k_high, "the lattice must resolve the band");
    // h(x, y) = Re sum a e^{i phi} e^{2 pi i (m x + l y)} at x = (i + 1/2)/n, y = (j + 1/2)/n,
    // each coefficient shifted by the half cell. Only the 2 k_high + 1 columns m of the band
    // carry modes: transform those along y (one inverse FFT each), then every row along x
    // (one inverse FFT of the row's 2 k_high + 1 coefficients), both passes in parallel;
    // about a hundredth of the work of the full 2D transform.
    let width = 2 * k_high + 1;
    let zero = Complex::new(0.0, 0.0);
    let mut cols = vec![zero; width * n];
    for &(m, l, a, phi) in &modes {
        let shift = PI * (m + l) as f64 / n as f64;
        cols[(m + kh) as usize * n + l as usize] = Complex::from_polar(a / rms, phi + shift);
    }
    let fft = FftPlanner::new().plan_fft_inverse(n);
    cols.par_chunks_mut(n).for_each(|c| fft.process(c));
    let mut h = vec![0.0; n * n];
    h.par_chunks_mut(n).enumerate().for_each_init(
        || (vec![zero; n], vec![zero; fft.get_inplace_scratch_len()]),
        |(row, scratch), (j, out)| {
            row.fill(zero);
            for (c, m) in (-kh..=kh).enumerate() {
                row[m.rem_euclid(n as i64) as usize] = cols[c * n + j];
            }
            fft.process_with_scratch(row, scratch);
            for (o, v) in out.iter_mut().zip(row.iter()) {
                *o = v.re;
            }
        },
    );
    h
}

/// The benchmark's rough problem on `n` x `n` cells: a rigid surface of rms height
/// `RMS_HEIGHT` (m) and period `PERIOD` (m) on a steel half-space, the initial gap
/// $-h$ (shifted to a zero minimum), and the mean pressure that brings about 5 % of the
/// period into contact. Returns (gap, mean pressure, rms slope of the continuous surface).
#[must_use]
pub fn rough_problem(n: usize) -> (Vec<f64>, f64) {
    let h = rough_heights(n, K_LOW, K_HIGH, HURST, 7);
    let max = h.par_iter().copied().reduce(|| f64::NEG_INFINITY, f64::max);
    let gap = h.par_iter().map(|v| (max - v) * RMS_HEIGHT).collect();
    (gap, ROUGH_MEAN_PRESSURE)
}

/// Period of the benchmark rough surface (m).
pub const PERIOD: f64 = 1e-3;
/// Its rms height (m).
pub const RMS_HEIGHT: f64 = 1e-6;
/// Its mean pressure (Pa): about 5 % of the period in contact on steel (E = 210 GPa,
/// nu = 0.3).
pub const ROUGH_MEAN_PRESSURE: f64 = 350e6;

/// A sphere of radius `r` on an `n` x `n` free lattice whose side is `side` (m), centred;
/// row-major gap $(x^2 + y^2)/2r$.
#[must_use]
pub fn hertz_gap(n: usize, side: f64, r: f64) -> Vec<f64> {
    let h = side / n as f64;
    (0..n * n)
        .map(|k| {
            let x = ((k % n) as f64 + 0.5) * h - 0.5 * side;
            let y = ((k / n) as f64 + 0.5) * h - 0.5 * side;
            (x * x + y * y) / (2.0 * r)
        })
        .collect()
}
