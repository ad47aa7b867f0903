//! The tangential influence operator of a contact grid as a zero-padded FFT convolution.
//!
//! On a uniform lattice the in-plane displacement at element $k$ due to uniform traction
//! $\mathbf q_j$ on element $j$ depends only on the lattice offset $(i_k - i_j, j_k - j_j)$:
//! $$u_a(k) = \sum_j K_{ab}(\mathbf i_k - \mathbf i_j)\,q_b(j),\qquad a, b \in \{x, y\},$$
//! with $K$ the exact uniform-rectangle tensor per unit traction (FORMULAS.md F, tensor form
//! and element-to-point formula; [`crate::influence::tensor`] times the element area). The
//! half-space is not periodic, so the kernel is laid out for offsets $-(n-1)\dots n-1$ on a
//! circular array of size $M \ge 2n - 1$ per axis and the traction is zero-padded: the
//! circular convolution of the padded arrays equals the linear one on the lattice
//! (the standard aperiodic FFT convolution, e.g. Liu, Wang & Liu 2000, *Wear* 243, "DC-FFT").
//!
//! $K_{xx}$, $K_{yy}$ are even in both offsets and $K_{xy}$ is odd in both, so all three
//! spectra are real; only their real parts are stored. One product costs two forward and two
//! inverse real 2D FFTs of size $M_x\times M_y$: $O(N\log N)$.

use crate::error::Result;
use crate::grid::ContactGrid;
use crate::influence::{tensor, Compliance, InfluenceModel};
use rayon::prelude::*;
use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealToComplex};
use rustfft::Fft;
use std::sync::Arc;

mod cross;
mod normal;
pub(crate) mod plans;
mod scalar;

pub use cross::CrossOperator;
pub use normal::{NormalOperator, NormalScratch};
pub use scalar::{even_quadrant, Precision, ScalarConvolution, ScalarScratch};

type C64 = Complex<f64>;

/// Columns (forward) or rows (inverse) handled together by one task of the 2D FFTs: the
/// transposes between the row and column passes then move whole cache lines.
const BLOCK: usize = 16;

/// In-place, unnormalised 2D complex FFT of an `nx` × `ny` row-major array (index
/// `j * nx + i`): `row` (length `nx`) along every row, then `col` (length `ny`) along every
/// column; forward or inverse as the plans are. The plain serial transform of the operators
/// that are planned once and applied rarely (the cross terms, roughness synthesis).
pub fn complex_fft2(row: &dyn Fft<f64>, col: &dyn Fft<f64>, nx: usize, ny: usize, a: &mut [C64]) {
    for r in a.chunks_exact_mut(nx) {
        row.process(r);
    }
    let mut c = vec![C64::new(0.0, 0.0); ny];
    for i in 0..nx {
        for j in 0..ny {
            c[j] = a[j * nx + i];
        }
        col.process(&mut c);
        for j in 0..ny {
            a[j * nx + i] = c[j];
        }
    }
}

/// Smallest even 5-smooth integer $\ge n$ (fast FFT sizes for rustfft/realfft).
pub fn fast_size(n: usize) -> usize {
    let mut m = n.max(2);
    loop {
        if m % 2 == 0 {
            let mut r = m;
            for p in [2, 3, 5] {
                while r % p == 0 {
                    r /= p;
                }
            }
            if r == 1 {
                return m;
            }
        }
        m += 1;
    }
}

/// The planned convolution operator $\mathbf u = K * \mathbf q$ of one contact grid.
///
/// Built once per grid and pair of bodies ([`TensorConvolution::new`]); owns the FFT plans and
/// the three kernel spectra. [`TensorConvolution::apply`] takes caller-owned scratch
/// ([`TensorConvolution::make_scratch`]) and allocates only the few-kilobyte per-thread FFT
/// work buffers of the rayon tasks.
pub struct TensorConvolution {
    n: usize,
    nx: usize,
    ny: usize,
    mx: usize,
    my: usize,
    /// $M_x/2 + 1$.
    mxh: usize,
    /// Lattice cell `j * nx + i` of each element.
    cell: Vec<usize>,
    /// The elements of each lattice row, `(i, k)` pairs, rows `row_ptr[j]..row_ptr[j + 1]`.
    row_items: Vec<(usize, usize)>,
    row_ptr: Vec<usize>,
    /// Real spectra of $K_{xx}, K_{xy}, K_{yy}$, layout `[i * my + j]`, $i < M_x/2+1$.
    kxx: Vec<f64>,
    kxy: Vec<f64>,
    kyy: Vec<f64>,
    /// Kernel at zero offset, `[Kxx, Kxy, Kyy]` (per unit traction).
    self_term: [f64; 3],
    r2c: Arc<dyn RealToComplex<f64>>,
    c2r: Arc<dyn ComplexToReal<f64>>,
    col_fwd: Arc<dyn Fft<f64>>,
    col_inv: Arc<dyn Fft<f64>>,
}

impl std::fmt::Debug for TensorConvolution {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TensorConvolution")
            .field("elements", &self.n)
            .field("lattice", &(self.nx, self.ny))
            .field("fft", &(self.mx, self.my))
            .finish_non_exhaustive()
    }
}

/// Caller-owned work space of [`TensorConvolution::apply`].
#[derive(Debug, Clone)]
pub struct ConvScratch {
    lat: [Vec<f64>; 2],
    rowspec: [Vec<C64>; 2],
}

impl TensorConvolution {
    /// Plan the operator of `grid` for the relative compliance `c` of the two bodies
    /// ([`Compliance::pair`]).
    ///
    /// The kernel entries are [`crate::influence::tensor`] (exact rectangle by default, or the
    /// seed's point-load model) times the element area, evaluated for one quadrant of offsets
    /// and completed by the parity of the tensor.
    ///
    /// # Errors
    /// [`crate::Error::EmptyGrid`] for an empty grid; [`crate::Error::OutOfDomain`] if an element centre is
    /// not on the lattice of spacing $(h_x, h_y)$ through the lowest centre, or two elements
    /// share a lattice cell.
    pub fn new(grid: &ContactGrid, c: &Compliance, model: InfluenceModel) -> Result<Self> {
        let (nx, ny, _, _, cell) = grid.lattice_cells()?;
        let mx = fast_size(2 * nx - 1);
        let my = fast_size(2 * ny - 1);
        let mxh = mx / 2 + 1;
        let mut op = Self::on_cells(nx, ny, mx, my, cell);

        // Kernel tensors for offsets (di, dj) >= 0, from a two-element probe grid
        // (field at the offset, source at the origin), times the element area.
        let area = grid.element_area();
        let (hx, hy) = (grid.hx, grid.hy);
        let quad: Vec<[f64; 3]> = (0..ny)
            .into_par_iter()
            .flat_map_iter(|dj| {
                let mut probe = ContactGrid {
                    hx,
                    hy,
                    x: vec![0.0, 0.0],
                    y: vec![dj as f64 * hy, 0.0],
                    pressure: vec![0.0, 0.0],
                    patch: vec![0, 0],
                };
                (0..nx)
                    .map(|di| {
                        probe.x[0] = di as f64 * hx;
                        let (k, j) = if di == 0 && dj == 0 { (1, 1) } else { (0, 1) };
                        let t = tensor(&probe, c, model, k, j);
                        [t[0] * area, t[1] * area, t[2] * area]
                    })
                    .collect::<Vec<_>>()
            })
            .collect();
        op.self_term = quad[0];
        let mut spectra: [Vec<f64>; 3] = [vec![], vec![], vec![]];
        for (comp, out) in spectra.iter_mut().enumerate() {
            // Parity: xx, yy even in both offsets; xy odd in both.
            let odd = comp == 1;
            let mut lat = vec![0.0; mx * my];
            for dj in 0..ny {
                for di in 0..nx {
                    let v = quad[dj * nx + di][comp];
                    for (sj, ej) in [(1.0, dj), (-1.0, (my - dj) % my)] {
                        for (si, ei) in [(1.0, di), (-1.0, (mx - di) % mx)] {
                            let s = if odd { si * sj } else { 1.0 };
                            lat[ej * mx + ei] = s * v;
                        }
                    }
                }
            }
            // Odd kernel: the zero-offset row and column are zero (the mirror writes of
            // di = 0 or dj = 0 overwrite with -v = -0 there; keep them exactly 0).
            if odd {
                lat[..mx].fill(0.0);
                for dj in 0..my {
                    lat[dj * mx] = 0.0;
                }
            }
            let mut rowspec = vec![C64::new(0.0, 0.0); my * mxh];
            let mut spec = vec![C64::new(0.0, 0.0); mxh * my];
            op.forward(
                my,
                |j, row| row.copy_from_slice(&lat[j * mx..(j + 1) * mx]),
                &mut rowspec,
                &mut spec,
            );
            *out = spec.iter().map(|z| z.re).collect();
        }
        let [kxx, kxy, kyy] = spectra;
        op.kxx = kxx;
        op.kxy = kxy;
        op.kyy = kyy;
        Ok(op)
    }

    /// Number of elements $N$.
    #[must_use]
    pub fn len(&self) -> usize {
        self.n
    }

    /// Whether the operator has no element (never true for a constructed operator).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// Lattice box $(n_x, n_y)$ spanned by the elements.
    #[must_use]
    pub fn lattice(&self) -> (usize, usize) {
        (self.nx, self.ny)
    }

    /// Padded FFT size $(M_x, M_y)$, each the smallest even 5-smooth size $\ge 2n - 1$.
    #[must_use]
    pub fn fft_size(&self) -> (usize, usize) {
        (self.mx, self.my)
    }

    /// Kernel at zero offset `[Kxx, Kxy, Kyy]`: displacement at an element's centre per unit
    /// traction on itself (FORMULAS.md F self-term; $K_{xy} = 0$).
    #[must_use]
    pub fn self_term(&self) -> [f64; 3] {
        self.self_term
    }

    /// Work space for [`TensorConvolution::apply`].
    #[must_use]
    pub fn make_scratch(&self) -> ConvScratch {
        let z = C64::new(0.0, 0.0);
        ConvScratch {
            lat: [vec![0.0; self.nx * self.ny], vec![0.0; self.nx * self.ny]],
            rowspec: [vec![z; self.ny * self.mxh], vec![z; self.ny * self.mxh]],
        }
    }

    /// Row FFTs of `rows` real rows (the rest are zero), then column FFTs:
    /// `spec[i * my + j]` is the 2D spectrum.
    fn forward(
        &self,
        rows: usize,
        fill: impl Fn(usize, &mut [f64]) + Sync,
        rowspec: &mut [C64],
        spec: &mut [C64],
    ) {
        let (mx, my, mxh) = (self.mx, self.my, self.mxh);
        rowspec[..rows * mxh].par_chunks_mut(mxh).enumerate().for_each_init(
            || (vec![0.0; mx], self.r2c.make_scratch_vec()),
            |(row, scr), (j, out)| {
                row.fill(0.0);
                fill(j, row);
                // Lengths are consistent by construction; realfft only errs on length.
                let _ = self.r2c.process_with_scratch(row, out, scr);
            },
        );
        // Columns in blocks of BLOCK: each row contributes BLOCK adjacent values per block,
        // so the transpose reads whole cache lines instead of one value per row.
        let rowspec: &[C64] = rowspec;
        spec.par_chunks_mut(BLOCK * my).enumerate().for_each_init(
            || vec![C64::new(0.0, 0.0); self.col_fwd.get_inplace_scratch_len()],
            |scr, (ib, cols)| {
                let i0 = ib * BLOCK;
                let nb = cols.len() / my;
                for j in 0..rows {
                    let src = &rowspec[j * mxh + i0..j * mxh + i0 + nb];
                    for (b, v) in src.iter().enumerate() {
                        cols[b * my + j] = *v;
                    }
                }
                for b in 0..nb {
                    cols[b * my + rows..(b + 1) * my].fill(C64::new(0.0, 0.0));
                }
                for col in cols.chunks_exact_mut(my) {
                    self.col_fwd.process_with_scratch(col, scr);
                }
            },
        );
    }

    /// The fused column pass of a product, in place: for each block of columns of the row
    /// spectra `rows` (one per component, $n_y\times(M_x/2+1)$ row-major), the column FFTs of
    /// the zero-padded columns, the kernel product ([`TensorConvolution::multiply`]) and the
    /// inverse column FFTs, the first $n_y$ entries of each column written back where they
    /// were read. A block stays in cache from the forward to the inverse transform, so the
    /// padded spectrum never goes to memory, and the row spectra are the only work array.
    fn columns(&self, rows: &mut [&mut [C64]]) {
        let (my, mxh, ny) = (self.my, self.mxh, self.ny);
        // Column stride in the block buffer: padded off a power of two so that the BLOCK
        // columns written row by row do not all map to the same cache sets.
        let ms = my + 8;
        let nc = rows.len();
        let z = C64::new(0.0, 0.0);
        // Each task owns one block of BLOCK columns: the row segments of that block, of every
        // row and component (components one after the other), as disjoint slices.
        let mut blocks: Vec<Vec<&mut [C64]>> =
            (0..mxh.div_ceil(BLOCK)).map(|_| Vec::with_capacity(nc * ny)).collect();
        for r in rows.iter_mut() {
            for row in r[..ny * mxh].chunks_exact_mut(mxh) {
                for (ib, seg) in row.chunks_mut(BLOCK).enumerate() {
                    blocks[ib].push(seg);
                }
            }
        }
        let init = || {
            let scr =
                self.col_fwd.get_inplace_scratch_len().max(self.col_inv.get_inplace_scratch_len());
            (vec![z; nc * BLOCK * ms], vec![z; scr])
        };
        blocks.into_par_iter().enumerate().for_each_init(init, |(buf, scr), (ib, mut segs)| {
            let i0 = ib * BLOCK;
            let nb = segs[0].len();
            for c in 0..nc {
                let b0 = &mut buf[c * BLOCK * ms..(c + 1) * BLOCK * ms];
                for (j, src) in segs[c * ny..(c + 1) * ny].iter().enumerate() {
                    for (b, v) in src.iter().enumerate() {
                        b0[b * ms + j] = *v;
                    }
                }
                for b in 0..nb {
                    let col = &mut b0[b * ms..b * ms + my];
                    col[ny..].fill(z);
                    self.col_fwd.process_with_scratch(col, scr);
                }
            }
            for b in 0..nb {
                let k0 = (i0 + b) * my;
                {
                    let (bx, by) = buf.split_at_mut(BLOCK * ms);
                    let cx = &mut bx[b * ms..b * ms + my];
                    let cy = &mut by[b * ms..b * ms + my];
                    let kxx = &self.kxx[k0..k0 + my];
                    let kxy = &self.kxy[k0..k0 + my];
                    let kyy = &self.kyy[k0..k0 + my];
                    for t in 0..my {
                        let (a, e) = (cx[t], cy[t]);
                        cx[t] = a * kxx[t] + e * kxy[t];
                        cy[t] = a * kxy[t] + e * kyy[t];
                    }
                }
            }
            for c in 0..nc {
                let b0 = &mut buf[c * BLOCK * ms..(c + 1) * BLOCK * ms];
                for b in 0..nb {
                    self.col_inv.process_with_scratch(&mut b0[b * ms..b * ms + my], scr);
                }
                for (j, dst) in segs[c * ny..(c + 1) * ny].iter_mut().enumerate() {
                    for (b, v) in dst.iter_mut().enumerate() {
                        *v = b0[b * ms + j];
                    }
                }
            }
        });
    }

    /// Inverse row FFTs of the row spectra `rowspec` (row-major $n_y\times(M_x/2+1)$, as left
    /// by [`TensorConvolution::columns`]; overwritten) into `lat` (row-major
    /// $n_y\times n_x$), scaled by $1/(M_xM_y)$.
    fn rows_inverse(&self, rowspec: &mut [C64], lat: &mut [f64]) {
        let (mx, my, mxh, nx, ny) = (self.mx, self.my, self.mxh, self.nx, self.ny);
        let scale = 1.0 / (mx as f64 * my as f64);
        rowspec[..ny * mxh]
            .par_chunks_mut(BLOCK * mxh)
            .zip(lat.par_chunks_mut(BLOCK * nx))
            .for_each_init(
                || (vec![0.0; mx], self.c2r.make_scratch_vec()),
                |(row, scr), (rsb, outb)| {
                    for (rs, out) in rsb.chunks_exact_mut(mxh).zip(outb.chunks_exact_mut(nx)) {
                        // The DC and (even sizes) Nyquist bins of a real signal are real;
                        // clear the rounding.
                        rs[0].im = 0.0;
                        if mx % 2 == 0 {
                            rs[mxh - 1].im = 0.0;
                        }
                        let _ = self.c2r.process_with_scratch(rs, row, scr);
                        for (o, r) in out.iter_mut().zip(row.iter()) {
                            *o = r * scale;
                        }
                    }
                },
            );
    }

    /// Row FFTs of the $n_y$ lattice rows filled by `fill` into `rowspec`.
    fn rows_forward(&self, fill: impl Fn(usize, &mut [f64]) + Sync, rowspec: &mut [C64]) {
        let (mx, mxh) = (self.mx, self.mxh);
        rowspec[..self.ny * mxh].par_chunks_mut(mxh).enumerate().for_each_init(
            || (vec![0.0; mx], self.r2c.make_scratch_vec()),
            |(row, scr), (j, out)| {
                row.fill(0.0);
                fill(j, row);
                // Lengths are consistent by construction; realfft only errs on length.
                let _ = self.r2c.process_with_scratch(row, out, scr);
            },
        );
    }

    /// $\mathbf u = K * \mathbf q$: in-plane displacement at every element centre due to the
    /// element tractions `(qx, qy)` (element order of the grid; lengths $N$),
    /// $$u_a(k) = \sum_j K_{ab}(\mathbf i_k - \mathbf i_j)\,q_b(j),$$
    /// with $K$ the uniform-rectangle tensor of FORMULAS.md F, computed as the zero-padded
    /// (aperiodic) FFT convolution on circular arrays of size $M \ge 2n-1$ per axis (Liu, Wang &
    /// Liu 2000, *Wear* 243, DC-FFT).
    ///
    /// # Panics
    /// If a slice length differs from $N$.
    pub fn apply(
        &self,
        qx: &[f64],
        qy: &[f64],
        ux: &mut [f64],
        uy: &mut [f64],
        s: &mut ConvScratch,
    ) {
        assert!(qx.len() == self.n && qy.len() == self.n, "traction length");
        assert!(ux.len() == self.n && uy.len() == self.n, "displacement length");
        for (f, q) in [qx, qy].into_iter().enumerate() {
            self.rows_forward(
                |j, row| {
                    for &(i, k) in &self.row_items[self.row_ptr[j]..self.row_ptr[j + 1]] {
                        row[i] = q[k];
                    }
                },
                &mut s.rowspec[f],
            );
        }
        {
            let [rx, ry] = &mut s.rowspec;
            self.columns(&mut [&mut rx[..], &mut ry[..]]);
        }
        for (f, u) in [ux, uy].into_iter().enumerate() {
            self.rows_inverse(&mut s.rowspec[f], &mut s.lat[f]);
            let lat: &[f64] = &s.lat[f];
            u.par_iter_mut().zip(self.cell.par_iter()).for_each(|(o, &c)| *o = lat[c]);
        }
    }
}

/// The lattice of a periodic surface: `cells` = $(n_x, n_y)$ cells per period and `origin`
/// the centre of one lattice cell, so that element centres sit at
/// `origin + (i h_x, j h_y)` for integers $i, j$ (taken modulo the period).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PeriodicLattice {
    /// Cells per period along $x$ and $y$.
    pub cells: (usize, usize),
    /// Centre of one lattice cell (m).
    pub origin: (f64, f64),
}

impl TensorConvolution {
    /// The tangential operator of `grid` on a periodic surface of lattice `lattice`: the
    /// relative displacement of the two bodies under a periodic traction, by the Fourier
    /// transform of Cerruti's solution,
    /// $\hat{\mathbf u}(\mathbf k) = |\mathbf k|^{-1}\,(aI - b\,\hat{\mathbf k}
    /// \hat{\mathbf k}^{\mathsf T})\,\hat{\mathbf q}(\mathbf k)$, $a = \sum 1/G_i$,
    /// $b = \sum \nu_i/G_i$, at the lattice's wave vectors, on the $n_x\times n_y$ torus
    /// (no padding). The mean mode is set to zero: a periodic traction of non-zero mean
    /// moves the surface without bound, so under periodicity the rigid shift is relative to
    /// the mean tangential displacement (as the approach of the periodic normal problem is).
    /// The same continuous transfer as the periodic normal solver (and as tamaas), so the two
    /// stages pose one problem.
    ///
    /// # Errors
    /// [`crate::Error::EmptyGrid`] for an empty grid; [`crate::Error::OutOfDomain`] for a
    /// period of fewer than 2 cells, an element centre off the lattice, or two elements in
    /// one cell of the period.
    pub fn periodic(grid: &ContactGrid, c: &Compliance, lattice: &PeriodicLattice) -> Result<Self> {
        let (nx, ny) = lattice.cells;
        if nx < 2 || ny < 2 {
            return Err(crate::Error::OutOfDomain {
                name: "cells per period",
                value: nx.min(ny) as f64,
                allowed: ">= 2 along x and y",
            });
        }
        if grid.is_empty() {
            return Err(crate::Error::EmptyGrid { reason: "the grid has no element" });
        }
        let (x0, y0) = lattice.origin;
        let mut cell = Vec::with_capacity(grid.len());
        let mut seen = vec![false; nx * ny];
        for k in 0..grid.len() {
            let fi = (grid.x[k] - x0) / grid.hx;
            let fj = (grid.y[k] - y0) / grid.hy;
            let (i, j) = (fi.round(), fj.round());
            if !((fi - i).abs() <= 1e-6 && (fj - j).abs() <= 1e-6) {
                return Err(crate::Error::OutOfDomain {
                    name: "element centre offset from the periodic lattice (cells)",
                    value: (fi - i).abs().max((fj - j).abs()),
                    allowed: "<= 1e-6: all centres on the lattice of the period",
                });
            }
            let c = (j as i64).rem_euclid(ny as i64) as usize * nx
                + (i as i64).rem_euclid(nx as i64) as usize;
            if seen[c] {
                return Err(crate::Error::OutOfDomain {
                    name: "element sharing a cell of the period (index)",
                    value: k as f64,
                    allowed: "one element per cell of the period",
                });
            }
            seen[c] = true;
            cell.push(c);
        }
        let mut op = Self::on_cells(nx, ny, nx, ny, cell);
        let a = c.one_minus_nu + c.nu;
        let b = c.nu;
        let (lx, ly) = (nx as f64 * grid.hx, ny as f64 * grid.hy);
        let two_pi = 2.0 * std::f64::consts::PI;
        let sym = |i: usize, j: usize| -> [f64; 3] {
            let (kx, ky) = (two_pi * signed(i, nx) / lx, two_pi * signed(j, ny) / ly);
            let k = kx.hypot(ky);
            if k == 0.0 {
                return [0.0; 3];
            }
            let (ex, ey) = (kx / k, ky / k);
            [(a - b * ex * ex) / k, -b * ex * ey / k, (a - b * ey * ey) / k]
        };
        // The kernel at zero offset (the mean of the symbol over the whole spectrum): the
        // self-influence the Newton system's diagonal uses.
        op.self_term = op.symbol_mean(&sym);
        op.set_symbol(1.0, &sym);
        Ok(op)
    }
}

impl TensorConvolution {
    /// A preconditioner for the tangential operator of `grid`: the inverse of the half-space's
    /// tangential transfer, $\hat{\mathbf u} = |\mathbf k|^{-1}\,(aI - b\,\hat{\mathbf k}
    /// \hat{\mathbf k}^{\mathsf T})\,\hat{\mathbf q}$ with $a = \sum 1/G_i$, $b = \sum\nu_i/G_i$
    /// (the Fourier transform of Cerruti's solution), on the periodic lattice of the grid's
    /// bounding box (5-smooth size, no padding), with the discrete wave number
    /// $2\sin(kh/2)/h$ per axis; the mean mode gets the smallest non-zero wave number, and
    /// the whole is scaled so that its diagonal equals $1/K_{xx}(0)$ (the Jacobi value).
    pub fn inverse_symbol(grid: &ContactGrid, c: &Compliance, k0xx: f64) -> Result<Self> {
        let (nx, ny, _, _, cell) = grid.lattice_cells()?;
        let (mx, my) = (fast_size(nx), fast_size(ny));
        let mut op = Self::on_cells(nx, ny, mx, my, cell);
        let a = c.one_minus_nu + c.nu;
        let b = c.nu;
        let gamma = 1.0 / (a - b) - 1.0 / a;
        let (hx, hy) = (grid.hx, grid.hy);
        let two_pi = 2.0 * std::f64::consts::PI;
        let kmin = (two_pi / (mx as f64 * hx)).min(two_pi / (my as f64 * hy));
        let sym = |i: usize, j: usize| -> [f64; 3] {
            let kx = 2.0 * (0.5 * two_pi * signed(i, mx) / mx as f64).sin() / hx;
            let ky = 2.0 * (0.5 * two_pi * signed(j, my) / my as f64).sin() / hy;
            let k = kx.hypot(ky);
            if k == 0.0 {
                return [kmin / a, 0.0, kmin / a];
            }
            let (ex, ey) = (kx / k, ky / k);
            [k * (1.0 / a + gamma * ex * ex), k * gamma * ex * ey, k * (1.0 / a + gamma * ey * ey)]
        };
        let scale = 1.0 / (k0xx * op.symbol_mean(&sym)[0]);
        op.set_symbol(scale, &sym);
        Ok(op)
    }

    /// An operator of `mx` x `my` FFTs (no kernel yet) for the elements in the lattice cells
    /// `cell` of an `nx` x `ny` lattice.
    fn on_cells(nx: usize, ny: usize, mx: usize, my: usize, cell: Vec<usize>) -> Self {
        let mut op = Self::plan(nx, ny, mx, my);
        op.n = cell.len();
        let (row_items, row_ptr) = rows_of(&cell, nx, ny);
        op.cell = cell;
        op.row_items = row_items;
        op.row_ptr = row_ptr;
        op
    }

    /// The mean of a tensor symbol `sym(i, j)` over the whole $M_x\times M_y$ spectrum (the
    /// kernel at zero offset).
    fn symbol_mean(&self, sym: &impl Fn(usize, usize) -> [f64; 3]) -> [f64; 3] {
        let mut sum = [0.0; 3];
        for i in 0..self.mx {
            for j in 0..self.my {
                for (a, b) in sum.iter_mut().zip(sym(i, j)) {
                    *a += b;
                }
            }
        }
        sum.map(|v| v / (self.mx * self.my) as f64)
    }

    /// Store `scale * sym(i, j)` as the kernel spectra (the half spectrum of the real FFT).
    fn set_symbol(&mut self, scale: f64, sym: &impl Fn(usize, usize) -> [f64; 3]) {
        let (mxh, my) = (self.mxh, self.my);
        let mut k = [vec![0.0; mxh * my], vec![0.0; mxh * my], vec![0.0; mxh * my]];
        for i in 0..mxh {
            for j in 0..my {
                for (kc, v) in k.iter_mut().zip(sym(i, j)) {
                    kc[i * my + j] = scale * v;
                }
            }
        }
        [self.kxx, self.kxy, self.kyy] = k;
    }
}

/// FFT index `i` of a length-`m` transform as a signed frequency (`i - m` above `m / 2`).
pub fn signed(i: usize, m: usize) -> f64 {
    if 2 * i <= m {
        i as f64
    } else {
        i as f64 - m as f64
    }
}

/// The elements of each lattice row as `(i, k)` pairs in CSR form (`ptr` has `ny + 1`
/// entries), so that the row FFTs read their elements directly.
fn rows_of(cell: &[usize], nx: usize, ny: usize) -> (Vec<(usize, usize)>, Vec<usize>) {
    let mut ptr = vec![0usize; ny + 1];
    for &c in cell {
        ptr[c / nx + 1] += 1;
    }
    for j in 0..ny {
        ptr[j + 1] += ptr[j];
    }
    let mut next = ptr.clone();
    let mut items = vec![(0, 0); cell.len()];
    for (k, &c) in cell.iter().enumerate() {
        let j = c / nx;
        items[next[j]] = (c % nx, k);
        next[j] += 1;
    }
    (items, ptr)
}

impl TensorConvolution {
    /// FFT plans for an `nx` x `ny` lattice on an `mx` x `my` torus (no elements, no kernel).
    fn plan(nx: usize, ny: usize, mx: usize, my: usize) -> Self {
        Self {
            n: nx * ny,
            nx,
            ny,
            mx,
            my,
            mxh: mx / 2 + 1,
            cell: Vec::new(),
            row_items: Vec::new(),
            row_ptr: Vec::new(),
            kxx: Vec::new(),
            kxy: Vec::new(),
            kyy: Vec::new(),
            self_term: [0.0; 3],
            r2c: plans::r2c(mx),
            c2r: plans::c2r(mx),
            col_fwd: plans::forward(my),
            col_inv: plans::inverse(my),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fast_sizes() {
        assert_eq!(fast_size(399), 400);
        assert_eq!(fast_size(3), 4);
        assert_eq!(fast_size(127), 128);
        assert_eq!(fast_size(799), 800);
        assert_eq!(fast_size(13), 16);
    }
}
