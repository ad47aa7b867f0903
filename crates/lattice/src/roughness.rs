//! Self-affine random rough surfaces on a lattice by Fourier synthesis, for the
//! normal-contact solver (`stickslip-normal`).
//!
//! The heights are the real inverse discrete Fourier transform of a spectrum with random
//! phases and amplitudes $\sqrt{C(k)}$ from the isotropic power spectrum
//! $$C(k) = \begin{cases} 1 & k_\text{low} \le k \le k_\text{rolloff},\\
//! (k/k_\text{rolloff})^{-2(1+H)} & k_\text{rolloff} < k \le k_\text{high},\\
//! 0 & \text{otherwise,}\end{cases}$$
//! with $H$ the Hurst exponent and $k = |\mathbf q|L_x/2\pi$ the wavenumber in cycles per
//! lattice length along $x$ ($\mathbf q = 2\pi(m/L_x, n/L_y)$ for the lattice mode $(m, n)$,
//! aliased to $|m| \le n_x/2$, $|n| \le n_y/2$). This is the usual model of a rough surface
//! (Persson et al. 2005, *J. Phys.: Condens. Matter* 17 R1; the construction of tamaas and
//! contact.engineering). The spectrum is Hermitian ($F(-\mathbf q) = \overline{F(\mathbf q)}$),
//! so the heights are real; the mean is zero, and the heights are scaled to the requested
//! root-mean-square height, or root-mean-square slope (the slope by central differences on
//! the periodic lattice). The surface is periodic with the lattice. The phases come from a
//! SplitMix64 stream of the seed, so a seed gives the same surface on every machine.

use std::f64::consts::PI;

use rustfft::num_complex::Complex;
use rustfft::FftPlanner;

use crate::error::{Error, Result};

/// What the root-mean-square of a generated surface is scaled to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rms {
    /// Root-mean-square height (m).
    Height(f64),
    /// Root-mean-square slope (dimensionless).
    Slope(f64),
}

/// The spectrum of a self-affine surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SelfAffine {
    /// Hurst exponent H in (0, 1].
    pub hurst: f64,
    /// Smallest wavenumber (cycles per lattice length along x), >= 1.
    pub k_low: f64,
    /// Roll-off wavenumber, k_low <= k_rolloff <= k_high.
    pub k_rolloff: f64,
    /// Largest wavenumber, at most the Nyquist wavenumber min(nx/2, ny Lx/(2 Ly)).
    pub k_high: f64,
    /// The scale of the heights.
    pub rms: Rms,
    /// Seed of the random phases.
    pub seed: u64,
}

fn bad(name: &'static str, value: f64, allowed: &'static str) -> Error {
    Error::OutOfDomain { name, value, allowed }
}

/// SplitMix64 (Steele, Lea & Flood 2014): one 64-bit state, a full-period stream of
/// well-mixed values; uniform in [0, 1) from the top 53 bits. Public so that other
/// synthetic surfaces (the benchmark surfaces of `stickslip-benches`) draw the same stream.
#[derive(Debug, Clone)]
pub struct SplitMix(pub u64);

impl SplitMix {
    /// The next value, uniform in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
}

impl SelfAffine {
    /// The power spectrum at wavenumber `k` (module docs).
    #[must_use]
    pub fn spectrum(&self, k: f64) -> f64 {
        if k < self.k_low || k > self.k_high {
            0.0
        } else if k <= self.k_rolloff {
            1.0
        } else {
            (k / self.k_rolloff).powf(-2.0 * (1.0 + self.hurst))
        }
    }

    /// The heights (m) on an `nx` x `ny` lattice of extent `size` (m), index `j * nx + i`.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a Hurst exponent outside (0, 1], wavenumbers out of order
    /// or above the Nyquist wavenumber, a non-positive rms, or fewer than 4 cells a side.
    pub fn heights(&self, nx: usize, ny: usize, size: [f64; 2]) -> Result<Vec<f64>> {
        if nx < 4 || ny < 4 {
            return Err(bad("lattice cells", nx.min(ny) as f64, "at least 4 a side"));
        }
        if !(self.hurst > 0.0 && self.hurst <= 1.0) {
            return Err(bad("hurst", self.hurst, "0 < H <= 1"));
        }
        let nyquist = (nx as f64 / 2.0).min(ny as f64 * size[0] / (2.0 * size[1]));
        if !(self.k_low >= 1.0 && self.k_low <= self.k_rolloff && self.k_rolloff <= self.k_high) {
            return Err(bad("k_low", self.k_low, "1 <= k_low <= k_rolloff <= k_high"));
        }
        if self.k_high > nyquist {
            return Err(bad("k_high", self.k_high, "at most the lattice's Nyquist wavenumber"));
        }
        let (rms, slope) = match self.rms {
            Rms::Height(h) => (h, false),
            Rms::Slope(s) => (s, true),
        };
        if !(rms.is_finite() && rms > 0.0) {
            return Err(bad("rms", rms, "finite and > 0"));
        }
        let mut rng = SplitMix(self.seed);
        let n = nx * ny;
        let mut f = vec![Complex::new(0.0, 0.0); n];
        let wrap =
            |m: usize, len: usize| if m <= len / 2 { m as f64 } else { m as f64 - len as f64 };
        for j in 0..ny {
            for i in 0..nx {
                let k = j * nx + i;
                let (im, jm) = ((nx - i) % nx, (ny - j) % ny);
                let kc = jm * nx + im;
                if kc < k {
                    continue; // set with its conjugate partner
                }
                let (m, l) = (wrap(i, nx), wrap(j, ny));
                let kk = (m * m + (l * size[0] / size[1]).powi(2)).sqrt();
                let amp = self.spectrum(kk).sqrt();
                let phi = 2.0 * PI * rng.uniform();
                if kc == k {
                    f[k] = Complex::new(amp * phi.cos(), 0.0);
                } else {
                    f[k] = Complex::from_polar(amp, phi);
                    f[kc] = f[k].conj();
                }
            }
        }
        if f.iter().all(|c| c.norm() == 0.0) {
            return Err(bad("k_high", self.k_high, "a band that holds at least one lattice mode"));
        }
        fft2(&mut f, nx, ny, true);
        let mut h: Vec<f64> = f.iter().map(|c| c.re).collect();
        let mean = h.iter().sum::<f64>() / n as f64;
        h.iter_mut().for_each(|v| *v -= mean);
        let measure = if slope { rms_slope(&h, nx, ny, size) } else { rms_of(&h) };
        let scale = rms / measure;
        h.iter_mut().for_each(|v| *v *= scale);
        Ok(h)
    }
}

/// In-place 2D discrete Fourier transform of `f` (index `j * nx + i`), rows then columns,
/// unnormalised; `inverse` for the backward transform.
fn fft2(f: &mut [Complex<f64>], nx: usize, ny: usize, inverse: bool) {
    let mut planner = FftPlanner::new();
    let (row, col) = if inverse {
        (planner.plan_fft_inverse(nx), planner.plan_fft_inverse(ny))
    } else {
        (planner.plan_fft_forward(nx), planner.plan_fft_forward(ny))
    };
    crate::operator::complex_fft2(&*row, &*col, nx, ny, f);
}

fn rms_of(h: &[f64]) -> f64 {
    (h.iter().map(|v| v * v).sum::<f64>() / h.len() as f64).sqrt()
}

/// Root-mean-square of the gradient by central differences on the periodic lattice.
#[must_use]
pub fn rms_slope(h: &[f64], nx: usize, ny: usize, size: [f64; 2]) -> f64 {
    let (hx, hy) = (size[0] / nx as f64, size[1] / ny as f64);
    let mut s = 0.0;
    for j in 0..ny {
        for i in 0..nx {
            let dx = (h[j * nx + (i + 1) % nx] - h[j * nx + (i + nx - 1) % nx]) / (2.0 * hx);
            let dy = (h[((j + 1) % ny) * nx + i] - h[((j + ny - 1) % ny) * nx + i]) / (2.0 * hy);
            s += dx * dx + dy * dy;
        }
    }
    (s / (nx * ny) as f64).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec() -> SelfAffine {
        SelfAffine {
            hurst: 0.8,
            k_low: 2.0,
            k_rolloff: 4.0,
            k_high: 24.0,
            rms: Rms::Height(1e-6),
            seed: 7,
        }
    }

    /// The forward transform of the heights has |F|^2 proportional to C(k) mode by mode
    /// (the same constant in the band, zero outside): an independent check of the synthesis.
    #[test]
    fn the_power_spectrum_is_the_model_mode_by_mode() {
        let (nx, ny) = (64, 64);
        let s = spec();
        let h = s.heights(nx, ny, [1e-3, 1e-3]).unwrap();
        let rms = rms_of(&h);
        assert!((rms - 1e-6).abs() <= 1e-12 * 1e-6, "rms {rms}");
        assert!(h.iter().sum::<f64>().abs() <= 1e-12 * 1e-6 * (nx * ny) as f64);
        let mut f: Vec<Complex<f64>> = h.iter().map(|v| Complex::new(*v, 0.0)).collect();
        fft2(&mut f, nx, ny, false);
        let wrap =
            |m: usize, len: usize| if m <= len / 2 { m as f64 } else { m as f64 - len as f64 };
        let mut ratio: Option<f64> = None;
        for j in 0..ny {
            for i in 0..nx {
                let k = (wrap(i, nx).powi(2) + wrap(j, ny).powi(2)).sqrt();
                let c = s.spectrum(k);
                let p = f[j * nx + i].norm_sqr();
                // self-conjugate modes carry cos(phi)^2 of the power: skip them
                let self_conj = (i == 0 || 2 * i == nx) && (j == 0 || 2 * j == ny);
                if c == 0.0 {
                    assert!(p <= 1e-24 * h.len() as f64, "power {p} outside the band at k = {k}");
                } else if !self_conj {
                    let r = p / c;
                    let want = *ratio.get_or_insert(r);
                    assert!((r - want).abs() <= 1e-9 * want, "k = {k}: {r} vs {want}");
                }
            }
        }
    }

    #[test]
    fn a_seed_gives_one_surface_and_slopes_scale() {
        let small = SelfAffine { k_high: 12.0, ..spec() };
        let a = small.heights(32, 32, [1e-3, 1e-3]).unwrap();
        let b = small.heights(32, 32, [1e-3, 1e-3]).unwrap();
        assert_eq!(a, b);
        let c = SelfAffine { seed: 8, ..small }.heights(32, 32, [1e-3, 1e-3]).unwrap();
        assert_ne!(a, c);
        let s = SelfAffine { rms: Rms::Slope(0.05), k_high: 12.0, ..spec() };
        let h = s.heights(32, 32, [1e-3, 1e-3]).unwrap();
        assert!((rms_slope(&h, 32, 32, [1e-3, 1e-3]) - 0.05).abs() <= 1e-12);
    }

    #[test]
    fn bad_spectra_are_refused() {
        let bad = [
            SelfAffine { hurst: 1.5, ..spec() },
            SelfAffine { k_low: 0.5, ..spec() },
            SelfAffine { k_rolloff: 30.0, ..spec() },
            SelfAffine { k_high: 40.0, ..spec() },
            SelfAffine { rms: Rms::Height(-1.0), ..spec() },
        ];
        for s in bad {
            assert!(s.heights(64, 64, [1e-3, 1e-3]).is_err(), "{s:?}");
        }
    }
}
