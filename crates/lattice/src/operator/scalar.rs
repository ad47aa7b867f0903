//! The FFT convolution of a scalar field on a lattice with an even kernel, on a torus: the
//! periodic lattice itself, or a zero-padded one for the aperiodic (free) convolution. The
//! product of the normal operator and of its preconditioner, in double or single precision.
//!
//! A product is one pass of real row transforms (the lattice rows, zero-extended), one pass
//! over blocks of columns that transforms them, multiplies by the kernel's spectrum and
//! transforms back in cache, writing the kept rows back in place, and one pass of inverse row
//! transforms. The only work array is the row spectra, $n_y(M_x/2+1)$ complex numbers. The
//! kernel is even in both offsets, so its spectrum is real and even and half of it is stored,
//! $(M_x/2+1)(M_y/2+1)$ values (the normalisation $1/(M_xM_y)$ folded in).

use rayon::prelude::*;
use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealToComplex};
use rustfft::{Fft, FftNum};
use std::sync::Arc;

/// Columns (of the column pass) or rows (of the inverse row pass) handled together by one
/// task: the transposes then move whole cache lines.
const BLOCK: usize = 16;

/// A floating-point type the transforms run in: `f64`, or `f32` where half the memory
/// traffic matters more than the digits (a preconditioner).
pub trait Precision: FftNum + Into<f64> {
    /// `v` rounded to this precision.
    fn of(v: f64) -> Self;
}

impl Precision for f64 {
    fn of(v: f64) -> Self {
        v
    }
}

impl Precision for f32 {
    #[allow(clippy::cast_possible_truncation)]
    fn of(v: f64) -> Self {
        v as f32
    }
}

/// The planned convolution $u = K * q$ of an $n_x\times n_y$ lattice on an $M_x\times M_y$
/// torus (module docs), transforms in precision `T`.
pub struct ScalarConvolution<T: Precision> {
    nx: usize,
    ny: usize,
    mx: usize,
    my: usize,
    /// $M_x/2 + 1$.
    mxh: usize,
    /// $M_y/2 + 1$.
    myh: usize,
    /// The kernel's spectrum over $M_xM_y$, `[i * myh + j]`, $i \le M_x/2$, $j \le M_y/2$.
    spectrum: Vec<T>,
    r2c: Arc<dyn RealToComplex<T>>,
    c2r: Arc<dyn ComplexToReal<T>>,
    col_fwd: Arc<dyn Fft<T>>,
    col_inv: Arc<dyn Fft<T>>,
}

impl<T: Precision> std::fmt::Debug for ScalarConvolution<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ScalarConvolution")
            .field("lattice", &(self.nx, self.ny))
            .field("fft", &(self.mx, self.my))
            .field("precision", &std::any::type_name::<T>())
            .finish_non_exhaustive()
    }
}

/// Caller-owned work space of [`ScalarConvolution::apply_rows`]: the row spectra.
#[derive(Debug, Clone)]
pub struct ScalarScratch<T>(Vec<Complex<T>>);

impl<T: Precision> ScalarConvolution<T> {
    /// Plans for an `nx` x `ny` lattice on an `mx` x `my` torus (no kernel yet).
    fn plan(nx: usize, ny: usize, mx: usize, my: usize) -> Self {
        assert!(nx >= 1 && ny >= 1 && mx >= nx && my >= ny, "torus smaller than the lattice");
        Self {
            nx,
            ny,
            mx,
            my,
            mxh: mx / 2 + 1,
            myh: my / 2 + 1,
            spectrum: Vec::new(),
            r2c: super::plans::r2c(mx),
            c2r: super::plans::c2r(mx),
            col_fwd: super::plans::forward(my),
            col_inv: super::plans::inverse(my),
        }
    }

    /// The aperiodic convolution with the even kernel whose values for offsets
    /// $0\le d_i<n_x$, $0\le d_j<n_y$ are `quad[dj * nx + di]` ([`even_quadrant`]): the
    /// lattice zero-padded on the torus of the smallest fast sizes $M \ge 2n - 1$, so that the
    /// circular convolution equals the linear one on the lattice (Liu, Wang & Liu 2000,
    /// *Wear* 243, DC-FFT). The spectrum is computed in double precision by real transforms
    /// of the mirrored rows and columns (no padded lattice is formed).
    ///
    /// # Panics
    /// If `quad` has not $n_xn_y$ values.
    #[must_use]
    pub fn padded(nx: usize, ny: usize, quad: &[f64]) -> Self {
        assert_eq!(quad.len(), nx * ny, "kernel quadrant length");
        let mut op = Self::plan(nx, ny, super::fast_size(2 * nx - 1), super::fast_size(2 * ny - 1));
        let (mx, my, mxh, myh) = (op.mx, op.my, op.mxh, op.myh);
        let (row_r2c, col_r2c) = (super::plans::r2c::<f64>(mx), super::plans::r2c::<f64>(my));
        // Rows: the transform of an even real sequence is real.
        let mut rows = vec![0.0; ny * mxh];
        rows.par_chunks_mut(mxh).enumerate().for_each_init(
            || (vec![0.0; mx], vec![Complex::new(0.0, 0.0); mxh], row_r2c.make_scratch_vec()),
            |(row, out, scr), (dj, dst)| {
                mirror(&quad[dj * nx..(dj + 1) * nx], row);
                let _ = row_r2c.process_with_scratch(row, out, scr);
                for (d, o) in dst.iter_mut().zip(out.iter()) {
                    *d = o.re;
                }
            },
        );
        // Columns: the same, for each kept row frequency.
        let scale = 1.0 / (mx as f64 * my as f64);
        let mut spectrum = vec![T::of(0.0); mxh * myh];
        spectrum.par_chunks_mut(myh).enumerate().for_each_init(
            || {
                let c = vec![0.0; ny];
                (c, vec![0.0; my], vec![Complex::new(0.0, 0.0); myh], col_r2c.make_scratch_vec())
            },
            |(c, col, out, scr), (i, dst)| {
                for (dj, v) in c.iter_mut().enumerate() {
                    *v = rows[dj * mxh + i];
                }
                mirror(c, col);
                let _ = col_r2c.process_with_scratch(col, out, scr);
                for (d, o) in dst.iter_mut().zip(out.iter()) {
                    *d = T::of(o.re * scale);
                }
            },
        );
        op.spectrum = spectrum;
        op
    }

    /// The convolution of an `nx` x `ny` lattice on the periodic `mx` x `my` torus of periods
    /// `(lx, ly)` (m; $M \ge n$ per axis, the lattice zero-extended) with the transfer function
    /// `transfer(kx, ky)` at the torus's wave vectors $2\pi(i/L_x, j/L_y)$ (rad/m). The
    /// transfer must be even in both components (as every isotropic one is). With $M = n$
    /// this is the periodic convolution of the lattice.
    #[must_use]
    pub fn torus(
        nx: usize,
        ny: usize,
        (mx, my): (usize, usize),
        (lx, ly): (f64, f64),
        transfer: impl Fn(f64, f64) -> f64 + Sync,
    ) -> Self {
        let mut op = Self::plan(nx, ny, mx, my);
        let (mxh, myh) = (op.mxh, op.myh);
        let scale = 1.0 / (mx as f64 * my as f64);
        let two_pi = 2.0 * std::f64::consts::PI;
        let mut spectrum = vec![T::of(0.0); mxh * myh];
        spectrum.par_chunks_mut(myh).enumerate().for_each(|(i, row)| {
            let kx = two_pi * i as f64 / lx;
            for (j, v) in row.iter_mut().enumerate() {
                *v = T::of(transfer(kx, two_pi * j as f64 / ly) * scale);
            }
        });
        op.spectrum = spectrum;
        op
    }

    /// Lattice $(n_x, n_y)$.
    #[must_use]
    pub fn lattice(&self) -> (usize, usize) {
        (self.nx, self.ny)
    }

    /// Torus (FFT size) $(M_x, M_y)$.
    #[must_use]
    pub fn fft_size(&self) -> (usize, usize) {
        (self.mx, self.my)
    }

    /// Work space for [`ScalarConvolution::apply_rows`] (one complex array of
    /// $n_y(M_x/2+1)$ numbers).
    #[must_use]
    pub fn make_scratch(&self) -> ScalarScratch<T> {
        ScalarScratch(vec![Complex::new(T::of(0.0), T::of(0.0)); self.ny * self.mxh])
    }

    /// $u = K * q$ for `q`, `u` row-major $n_x\times n_y$.
    ///
    /// # Panics
    /// If a length differs from $n_xn_y$, or the scratch is too small.
    pub fn apply(&self, q: &[f64], u: &mut [f64], s: &mut ScalarScratch<T>) {
        let nx = self.nx;
        assert_eq!(q.len(), nx * self.ny, "lattice length");
        assert_eq!(u.len(), nx * self.ny, "lattice length");
        let mut out = vec![T::of(0.0); nx * self.ny];
        self.apply_rows(
            u,
            |j, _, row| {
                for (r, v) in row.iter_mut().zip(&q[j * nx..(j + 1) * nx]) {
                    *r = T::of(*v);
                }
            },
            &mut out,
            |_, u, out| {
                for (u, o) in u.iter_mut().zip(out.iter()) {
                    *u = (*o).into();
                }
            },
            s,
        );
    }

    /// $u = K * q$ with the input and the output handled row by row, so that a caller's
    /// passes over the lattice ride along with the transforms. `fill(j, cells, row)` writes
    /// lattice row $j$ of $q$ into `row[..nx]` (the rest of the slice is zero and must stay
    /// so), with row $j$ of the caller's array `cells` at hand to read and write; `finish(j,
    /// cells, out)` is called on each row of $u$ once it is written (it may change it, e.g.
    /// mask it), again with row $j$ of `cells`. Both results come back in row order, so sums
    /// built from them do not depend on the number of threads. The output is in the
    /// transforms' precision. The scratch may be larger than this convolution needs
    /// (another's, sized for a larger torus).
    ///
    /// # Panics
    /// If `u` or `cells` has not $n_xn_y$ values, or the scratch is too small.
    pub fn apply_rows<C: Send, F: Send, R: Send>(
        &self,
        cells: &mut [C],
        fill: impl Fn(usize, &mut [C], &mut [T]) -> F + Sync,
        u: &mut [T],
        finish: impl Fn(usize, &mut [C], &mut [T]) -> R + Sync,
        s: &mut ScalarScratch<T>,
    ) -> (Vec<F>, Vec<R>) {
        let (nx, ny, mx, mxh) = (self.nx, self.ny, self.mx, self.mxh);
        assert_eq!(u.len(), nx * ny, "lattice length");
        assert_eq!(cells.len(), nx * ny, "cells length");
        assert!(s.0.len() >= ny * mxh, "scratch too small");
        let rowspec = &mut s.0[..ny * mxh];
        let zero = T::of(0.0);
        let mut filled = Vec::with_capacity(ny);
        rowspec
            .par_chunks_mut(mxh)
            .zip(cells.par_chunks_mut(nx))
            .enumerate()
            .map_init(
                || (vec![zero; mx], self.r2c.make_scratch_vec()),
                |(row, scr), (j, (out, c))| {
                    // The fill writes the first nx entries; the padding stays zero.
                    row[nx..].fill(zero);
                    let f = fill(j, c, &mut row[..nx]);
                    // Lengths are consistent by construction; realfft only errs on length.
                    let _ = self.r2c.process_with_scratch(row, out, scr);
                    f
                },
            )
            .collect_into_vec(&mut filled);
        self.columns(rowspec);
        (filled, self.rows_inverse(rowspec, cells, u, finish))
    }

    /// The column pass, in place: each task owns one block of BLOCK columns (their segments of
    /// every row), transforms the zero-padded columns, multiplies by the spectrum, transforms
    /// back and writes the first $n_y$ entries back where they came from.
    fn columns(&self, rowspec: &mut [Complex<T>]) {
        let (my, mxh, myh, ny) = (self.my, self.mxh, self.myh, self.ny);
        // Column stride in the block buffer, padded off a power of two so that the columns
        // written row by row do not all map to the same cache sets.
        let ms = my + 8;
        let z = Complex::new(T::of(0.0), T::of(0.0));
        let mut blocks: Vec<Vec<&mut [Complex<T>]>> =
            (0..mxh.div_ceil(BLOCK)).map(|_| Vec::with_capacity(ny)).collect();
        for row in rowspec.chunks_exact_mut(mxh) {
            for (ib, seg) in row.chunks_mut(BLOCK).enumerate() {
                blocks[ib].push(seg);
            }
        }
        let init = || {
            let scr =
                self.col_fwd.get_inplace_scratch_len().max(self.col_inv.get_inplace_scratch_len());
            (vec![z; BLOCK * ms], vec![z; scr])
        };
        blocks.into_par_iter().enumerate().for_each_init(init, |(buf, scr), (ib, mut segs)| {
            let nb = segs[0].len();
            for (j, src) in segs.iter().enumerate() {
                for (b, v) in src.iter().enumerate() {
                    buf[b * ms + j] = *v;
                }
            }
            for b in 0..nb {
                let col = &mut buf[b * ms..b * ms + my];
                col[ny..].fill(z);
                self.col_fwd.process_with_scratch(col, scr);
                // The spectrum is even in the column frequency: entry my - t is entry t.
                let i = ib * BLOCK + b;
                let kh = &self.spectrum[i * myh..(i + 1) * myh];
                let (lo, hi) = col.split_at_mut(myh);
                for (v, k) in lo.iter_mut().zip(kh) {
                    *v = *v * *k;
                }
                for (v, k) in hi.iter_mut().zip(kh[1..my - myh + 1].iter().rev()) {
                    *v = *v * *k;
                }
                self.col_inv.process_with_scratch(col, scr);
            }
            for (j, dst) in segs.iter_mut().enumerate() {
                for (b, v) in dst.iter_mut().enumerate() {
                    *v = buf[b * ms + j];
                }
            }
        });
    }

    /// Inverse row transforms of the row spectra into `lat` (row-major $n_y\times n_x$;
    /// directly when the torus is the lattice, else through a row of the torus), then
    /// `finish` on each row with the same row of `cells`; its results in row order.
    fn rows_inverse<C: Send, R: Send>(
        &self,
        rowspec: &mut [Complex<T>],
        cells: &mut [C],
        lat: &mut [T],
        finish: impl Fn(usize, &mut [C], &mut [T]) -> R + Sync,
    ) -> Vec<R> {
        let (mx, mxh, nx) = (self.mx, self.mxh, self.nx);
        let zero = T::of(0.0);
        let blocks: Vec<Vec<R>> = rowspec
            .par_chunks_mut(BLOCK * mxh)
            .zip(lat.par_chunks_mut(BLOCK * nx).zip(cells.par_chunks_mut(BLOCK * nx)))
            .enumerate()
            .map_init(
                || (vec![zero; mx], self.c2r.make_scratch_vec()),
                |(row, scr), (jb, (rsb, (outb, cb)))| {
                    let mut done = Vec::with_capacity(BLOCK);
                    let rows = rsb
                        .chunks_exact_mut(mxh)
                        .zip(outb.chunks_exact_mut(nx).zip(cb.chunks_exact_mut(nx)));
                    for (b, (rs, (out, c))) in rows.enumerate() {
                        // The DC and (even sizes) Nyquist bins of a real signal are real;
                        // clear the rounding.
                        rs[0].im = zero;
                        if mx % 2 == 0 {
                            rs[mxh - 1].im = zero;
                        }
                        if mx == nx {
                            let _ = self.c2r.process_with_scratch(rs, out, scr);
                        } else {
                            let _ = self.c2r.process_with_scratch(rs, row, scr);
                            out.copy_from_slice(&row[..nx]);
                        }
                        done.push(finish(jb * BLOCK + b, c, out));
                    }
                    done
                },
            )
            .collect();
        blocks.into_iter().flatten().collect()
    }
}

/// The values `kernel(di, dj)` for $0\le d_i<n_x$, $0\le d_j<n_y$, row-major
/// `[dj * nx + di]` (evaluated in parallel): the quadrant of offsets of an even kernel, for
/// [`ScalarConvolution::padded`].
pub fn even_quadrant(
    nx: usize,
    ny: usize,
    kernel: impl Fn(usize, usize) -> f64 + Sync,
) -> Vec<f64> {
    let mut quad = vec![0.0; nx * ny];
    quad.par_chunks_mut(nx).enumerate().for_each(|(dj, row)| {
        for (di, v) in row.iter_mut().enumerate() {
            *v = kernel(di, dj);
        }
    });
    quad
}

/// `out` (length $M$) = the even sequence of the offsets `half` ($0\dots n-1$) on a circle of
/// $M \ge 2n - 1$: `out[d] = out[M - d] = half[d]`, zero between.
fn mirror(half: &[f64], out: &mut [f64]) {
    let m = out.len();
    out.fill(0.0);
    out[0] = half[0];
    for (d, v) in half.iter().enumerate().skip(1) {
        out[d] = *v;
        out[m - d] = *v;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The padded product against the direct sum, in both precisions.
    #[test]
    fn padded_against_direct_sum() {
        let (nx, ny) = (7, 5);
        let kernel = |di: usize, dj: usize| 1.0 / (1.0 + (di * di + 2 * dj * dj) as f64).sqrt();
        let quad = even_quadrant(nx, ny, kernel);
        let q: Vec<f64> = (0..nx * ny).map(|k| ((k * 37) % 11) as f64 - 4.0).collect();
        let mut direct = vec![0.0; nx * ny];
        for (k, d) in direct.iter_mut().enumerate() {
            let (i, j) = (k % nx, k / nx);
            for (l, v) in q.iter().enumerate() {
                *d += kernel(i.abs_diff(l % nx), j.abs_diff(l / nx)) * v;
            }
        }
        let scale = direct.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        let op = ScalarConvolution::<f64>::padded(nx, ny, &quad);
        let mut u = vec![0.0; nx * ny];
        op.apply(&q, &mut u, &mut op.make_scratch());
        let e = u.iter().zip(&direct).fold(0.0f64, |a, (x, y)| a.max((x - y).abs())) / scale;
        assert!(e < 1e-14, "f64 padded product off by {e:e}");
        let op = ScalarConvolution::<f32>::padded(nx, ny, &quad);
        op.apply(&q, &mut u, &mut op.make_scratch());
        let e = u.iter().zip(&direct).fold(0.0f64, |a, (x, y)| a.max((x - y).abs())) / scale;
        assert!(e < 1e-6, "f32 padded product off by {e:e}");
    }
}
