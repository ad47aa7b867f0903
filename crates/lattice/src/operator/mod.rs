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
//! spectra are real (even, and odd in both frequencies, respectively) and are computed from
//! the quadrant of offsets alone: real transforms of the mirrored rows and columns, no padded
//! lattice formed. One product costs two forward and two inverse real 2D FFTs of size
//! $M_x\times M_y$: $O(N\log N)$.
//!
//! The transforms run in double precision (`TensorConvolution`, the operator) or single
//! (`TensorConvolution<f32>`, for a preconditioner, which only has to be a fixed symmetric
//! positive definite operator); the interface is in double precision either way.

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
use sealed::{Buffers, Tensor};

type C64 = Complex<f64>;

/// The precisions [`TensorConvolution`] runs in, each with its work arrays in
/// [`ConvScratch`] (a trait of this crate only: `f64` and `f32`).
mod sealed {
    use super::{Complex, ConvScratch, Precision};

    /// The work arrays of one product in precision `T`: the lattice values and the row spectra
    /// of the two components.
    #[derive(Debug, Clone, Default)]
    pub struct Buffers<T> {
        pub lat: [Vec<T>; 2],
        pub rowspec: [Vec<Complex<T>>; 2],
    }

    impl<T: Precision> Buffers<T> {
        /// Buffers of at least `lat` lattice values and `spec` row-spectrum values each.
        pub fn ensure(&mut self, lat: usize, spec: usize) {
            let z = Complex::new(T::of(0.0), T::of(0.0));
            for v in &mut self.lat {
                if v.len() < lat {
                    v.resize(lat, T::of(0.0));
                }
            }
            for v in &mut self.rowspec {
                if v.len() < spec {
                    v.resize(spec, z);
                }
            }
        }
    }

    /// A precision of the transforms and where its buffers live in a [`ConvScratch`].
    pub trait Tensor: Precision {
        /// This precision's buffers.
        fn buffers(s: &mut ConvScratch) -> &mut Buffers<Self>;
    }

    impl Tensor for f64 {
        fn buffers(s: &mut ConvScratch) -> &mut Buffers<f64> {
            &mut s.double
        }
    }

    impl Tensor for f32 {
        fn buffers(s: &mut ConvScratch) -> &mut Buffers<f32> {
            &mut s.single
        }
    }
}

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

/// The planned convolution operator $\mathbf u = K * \mathbf q$ of one contact grid, its
/// transforms in precision `T` (`f64`, or `f32` for a preconditioner).
///
/// Built once per grid and pair of bodies ([`TensorConvolution::new`]); owns the FFT plans and
/// the three kernel spectra. [`TensorConvolution::apply`] takes caller-owned scratch
/// ([`TensorConvolution::make_scratch`]) and allocates only the few-kilobyte per-thread FFT
/// work buffers of the rayon tasks.
pub struct TensorConvolution<T: Tensor = f64> {
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
    kxx: Vec<T>,
    kxy: Vec<T>,
    kyy: Vec<T>,
    /// Kernel at zero offset, `[Kxx, Kxy, Kyy]` (per unit traction).
    self_term: [f64; 3],
    r2c: Arc<dyn RealToComplex<T>>,
    c2r: Arc<dyn ComplexToReal<T>>,
    col_fwd: Arc<dyn Fft<T>>,
    col_inv: Arc<dyn Fft<T>>,
}

impl<T: Tensor> std::fmt::Debug for TensorConvolution<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TensorConvolution")
            .field("elements", &self.n)
            .field("lattice", &(self.nx, self.ny))
            .field("fft", &(self.mx, self.my))
            .field("precision", &std::any::type_name::<T>())
            .finish_non_exhaustive()
    }
}

/// Caller-owned work space of [`TensorConvolution::apply`], in either precision: an
/// operator's [`TensorConvolution::make_scratch`] sizes its own precision's arrays, and an
/// operator of the other precision (or a larger lattice) that is handed it adds or grows its
/// own on first use, so that an operator and its preconditioner can share one.
#[derive(Debug, Clone, Default)]
pub struct ConvScratch {
    double: Buffers<f64>,
    single: Buffers<f32>,
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
        let mut op = Self::on_cells(nx, ny, mx, my, cell);
        let quad = kernel_quadrant(grid, c, model, nx, ny);
        op.self_term = quad[0];
        [op.kxx, op.kxy, op.kyy] = padded_spectra(nx, ny, mx, my, &quad);
        Ok(op)
    }

    /// The kernel of [`TensorConvolution::new`] for `grid` (its offsets in one quadrant), to
    /// plan the operators of this grid and of its coarsened lattices from
    /// ([`TensorConvolution::from_kernel`]) without evaluating the influence coefficients
    /// again.
    ///
    /// # Errors
    /// As [`TensorConvolution::new`].
    pub fn kernel(
        grid: &ContactGrid,
        c: &Compliance,
        model: InfluenceModel,
    ) -> Result<TensorKernel> {
        let (nx, ny, _, _, _) = grid.lattice_cells()?;
        let values = kernel_quadrant(grid, c, model, nx, ny);
        Ok(TensorKernel { h: (grid.hx, grid.hy), cells: (nx, ny), values })
    }

    /// The operator of `grid` from the kernel of the same bodies and model on a lattice whose
    /// cells are $2^k$ ($k \ge 0$) times smaller and which spans at least as many cells
    /// (the grid itself, or the finer lattice `grid` was coarsened from,
    /// [`ContactGrid::coarsened`]). The influence coefficients of the uniform-rectangle
    /// tensor (and of the point-load model) are homogeneous of degree 1 in the cell size at
    /// a fixed offset in cells, and scaling by a power of two is exact in floating point at
    /// every step of their evaluation, so the operator is the one [`TensorConvolution::new`]
    /// plans, to the bit, at the cost of the transforms alone. The bodies and model are the
    /// caller's to keep the same.
    ///
    /// # Errors
    /// As [`TensorConvolution::new`]; [`crate::Error::OutOfDomain`] if the cell sizes are not
    /// the kernel's times one power of two, or the lattice spans more cells than the
    /// kernel's.
    pub fn from_kernel(grid: &ContactGrid, kernel: &TensorKernel) -> Result<Self> {
        let (nx, ny, _, _, cell) = grid.lattice_cells()?;
        let scale = grid.hx / kernel.h.0;
        let k = scale.log2().round();
        let power = k >= 0.0 && scale == 2f64.powi(k as i32) && grid.hy == scale * kernel.h.1;
        if !power {
            return Err(crate::Error::OutOfDomain {
                name: "cell size over the kernel's cell size",
                value: scale,
                allowed: "a power of two >= 1, the same along x and y",
            });
        }
        if nx > kernel.cells.0 || ny > kernel.cells.1 {
            return Err(crate::Error::OutOfDomain {
                name: "lattice cells beyond the kernel's",
                value: nx.saturating_sub(kernel.cells.0).max(ny.saturating_sub(kernel.cells.1))
                    as f64,
                allowed: "0: a lattice within the kernel's",
            });
        }
        let (mx, my) = (fast_size(2 * nx - 1), fast_size(2 * ny - 1));
        let mut op = Self::on_cells(nx, ny, mx, my, cell);
        let kx = kernel.cells.0;
        let mut quad = vec![[0.0; 3]; nx * ny];
        quad.par_chunks_mut(nx).enumerate().for_each(|(dj, row)| {
            for (o, v) in row.iter_mut().zip(&kernel.values[dj * kx..dj * kx + nx]) {
                *o = v.map(|t| scale * t);
            }
        });
        op.self_term = quad[0];
        [op.kxx, op.kxy, op.kyy] = padded_spectra(nx, ny, mx, my, &quad);
        Ok(op)
    }
}

/// The influence coefficients of a lattice's tangential operator for the offsets of one
/// quadrant ([`TensorConvolution::kernel`]), from which [`TensorConvolution::from_kernel`]
/// plans the operators of this lattice and of its coarsened lattices.
#[derive(Debug, Clone)]
pub struct TensorKernel {
    /// Cell size $(h_x, h_y)$.
    h: (f64, f64),
    /// Offsets $(n_x, n_y)$ held: $0\le d_i<n_x$, $0\le d_j<n_y$.
    cells: (usize, usize),
    /// $K(d_i, d_j)$ per unit traction, `[dj * nx + di]`, as `[Kxx, Kxy, Kyy]`.
    values: Vec<[f64; 3]>,
}

/// The kernel tensors $K(d_i, d_j)$ of `grid`'s lattice for the offsets $0\le d_i<n_x$,
/// $0\le d_j<n_y$ (row-major `[dj * nx + di]`, per unit traction): [`tensor`] times the
/// element area, from a two-element probe grid (field at the offset, source at the origin),
/// rows in parallel. The other quadrants follow by parity.
fn kernel_quadrant(
    grid: &ContactGrid,
    c: &Compliance,
    model: InfluenceModel,
    nx: usize,
    ny: usize,
) -> Vec<[f64; 3]> {
    let area = grid.element_area();
    let (hx, hy) = (grid.hx, grid.hy);
    let mut quad = vec![[0.0; 3]; nx * ny];
    quad.par_chunks_mut(nx).enumerate().for_each(|(dj, out)| {
        let mut probe = ContactGrid {
            hx,
            hy,
            x: vec![0.0, 0.0],
            y: vec![dj as f64 * hy, 0.0],
            pressure: vec![0.0, 0.0],
            patch: vec![0, 0],
        };
        for (di, o) in out.iter_mut().enumerate() {
            probe.x[0] = di as f64 * hx;
            let (k, j) = if di == 0 && dj == 0 { (1, 1) } else { (0, 1) };
            let t = tensor(&probe, c, model, k, j);
            *o = [t[0] * area, t[1] * area, t[2] * area];
        }
    });
    quad
}

/// `out` (length $M$) = the sequence of the offsets `half(d)`, $0\le d<n$, on a circle of
/// $M \ge 2n - 1$, continued evenly (`out[M - d] = half(d)`) or, when `odd`, oddly
/// (`out[M - d] = -half(d)`, `out[0] = 0`); zero between.
fn mirror(n: usize, half: impl Fn(usize) -> f64, odd: bool, out: &mut [f64]) {
    let m = out.len();
    out.fill(0.0);
    out[0] = if odd { 0.0 } else { half(0) };
    for d in 1..n {
        let v = half(d);
        out[d] = v;
        out[m - d] = if odd { -v } else { v };
    }
}

/// The real spectra of $K_{xx}$, $K_{xy}$, $K_{yy}$ on the $M_x\times M_y$ torus from the
/// quadrant `quad` ([`kernel_quadrant`]), layout `[i * my + j]` for $i\le M_x/2$, every $j$.
///
/// The padded kernel is even in both offsets ($K_{xx}$, $K_{yy}$) or odd in both ($K_{xy}$,
/// with zero row and column at offset 0), so its 2D transform is separable into real
/// transforms of the mirrored quadrant rows (only $n_y$ of the $M_y$ rows: the others are
/// their mirror images or zero) and then of the mirrored columns of the result. An even
/// sequence has a real transform and an odd one an imaginary transform, so the spectrum is
/// $\operatorname{Re}\mathcal F_y[\operatorname{Re}\mathcal F_x K]$ for the even components
/// and $-\operatorname{Im}\mathcal F_y[\operatorname{Im}\mathcal F_x K]$ for $K_{xy}$, even or
/// odd in the column frequency as the kernel is in $d_j$. In double precision; a quarter of
/// the transform work of the full padded lattice's 2D FFT, and no padded lattice in memory.
fn padded_spectra(nx: usize, ny: usize, mx: usize, my: usize, quad: &[[f64; 3]]) -> [Vec<f64>; 3] {
    let (mxh, myh) = (mx / 2 + 1, my / 2 + 1);
    let (row_r2c, col_r2c) = (plans::r2c::<f64>(mx), plans::r2c::<f64>(my));
    let z = C64::new(0.0, 0.0);
    // Row transforms: rows[comp][dj * mxh + i].
    let mut rows = [vec![0.0; ny * mxh], vec![0.0; ny * mxh], vec![0.0; ny * mxh]];
    {
        let [r0, r1, r2] = &mut rows;
        r0.par_chunks_mut(mxh)
            .zip(r1.par_chunks_mut(mxh))
            .zip(r2.par_chunks_mut(mxh))
            .enumerate()
            .for_each_init(
                || (vec![0.0; mx], vec![z; mxh], row_r2c.make_scratch_vec()),
                |(row, out, scr), (dj, ((d0, d1), d2))| {
                    for (comp, dst) in [d0, d1, d2].into_iter().enumerate() {
                        let odd = comp == 1;
                        mirror(nx, |di| quad[dj * nx + di][comp], odd, row);
                        // Lengths are consistent by construction; realfft only errs on length.
                        let _ = row_r2c.process_with_scratch(row, out, scr);
                        for (d, o) in dst.iter_mut().zip(out.iter()) {
                            *d = if odd { o.im } else { o.re };
                        }
                    }
                },
            );
    }
    // Column transforms, one row frequency i at a time: spec[comp][i * my + j].
    let mut spec = [vec![0.0; mxh * my], vec![0.0; mxh * my], vec![0.0; mxh * my]];
    {
        let [s0, s1, s2] = &mut spec;
        s0.par_chunks_mut(my)
            .zip(s1.par_chunks_mut(my))
            .zip(s2.par_chunks_mut(my))
            .enumerate()
            .for_each_init(
                || (vec![0.0; my], vec![z; myh], col_r2c.make_scratch_vec()),
                |(col, out, scr), (i, ((d0, d1), d2))| {
                    for (comp, dst) in [d0, d1, d2].into_iter().enumerate() {
                        let odd = comp == 1;
                        mirror(ny, |dj| rows[comp][dj * mxh + i], odd, col);
                        let _ = col_r2c.process_with_scratch(col, out, scr);
                        for (t, o) in out.iter().enumerate() {
                            let v = if odd { -o.im } else { o.re };
                            dst[t] = v;
                            if t > 0 && my - t != t {
                                dst[my - t] = if odd { -v } else { v };
                            }
                        }
                    }
                },
            );
    }
    spec
}

impl<T: Tensor> TensorConvolution<T> {
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

    /// Work space for [`TensorConvolution::apply`] (this precision's arrays sized for this
    /// operator).
    #[must_use]
    pub fn make_scratch(&self) -> ConvScratch {
        let mut s = ConvScratch::default();
        T::buffers(&mut s).ensure(self.nx * self.ny, self.ny * self.mxh);
        s
    }

    /// The fused column pass of a product, in place: for each block of columns of the row
    /// spectra `rows` (one per component, $n_y\times(M_x/2+1)$ row-major), the column FFTs of
    /// the zero-padded columns, the kernel product ([`TensorConvolution::multiply`]) and the
    /// inverse column FFTs, the first $n_y$ entries of each column written back where they
    /// were read. A block stays in cache from the forward to the inverse transform, so the
    /// padded spectrum never goes to memory, and the row spectra are the only work array.
    fn columns(&self, rows: &mut [&mut [Complex<T>]]) {
        let (my, mxh, ny) = (self.my, self.mxh, self.ny);
        // Column stride in the block buffer: padded off a power of two so that the BLOCK
        // columns written row by row do not all map to the same cache sets.
        let ms = my + 8;
        let nc = rows.len();
        let z = Complex::new(T::of(0.0), T::of(0.0));
        // Each task owns one block of BLOCK columns: the row segments of that block, of every
        // row and component (components one after the other), as disjoint slices.
        let mut blocks: Vec<Vec<&mut [Complex<T>]>> =
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
    fn rows_inverse(&self, rowspec: &mut [Complex<T>], lat: &mut [T]) {
        let (mx, my, mxh, nx, ny) = (self.mx, self.my, self.mxh, self.nx, self.ny);
        let scale = T::of(1.0 / (mx as f64 * my as f64));
        let zero = T::of(0.0);
        rowspec[..ny * mxh]
            .par_chunks_mut(BLOCK * mxh)
            .zip(lat.par_chunks_mut(BLOCK * nx))
            .for_each_init(
                || (vec![zero; mx], self.c2r.make_scratch_vec()),
                |(row, scr), (rsb, outb)| {
                    for (rs, out) in rsb.chunks_exact_mut(mxh).zip(outb.chunks_exact_mut(nx)) {
                        // The DC and (even sizes) Nyquist bins of a real signal are real;
                        // clear the rounding.
                        rs[0].im = zero;
                        if mx % 2 == 0 {
                            rs[mxh - 1].im = zero;
                        }
                        let _ = self.c2r.process_with_scratch(rs, row, scr);
                        for (o, r) in out.iter_mut().zip(row.iter()) {
                            *o = *r * scale;
                        }
                    }
                },
            );
    }

    /// Row FFTs of the $n_y$ lattice rows filled by `fill` into `rowspec`.
    fn rows_forward(&self, fill: impl Fn(usize, &mut [T]) + Sync, rowspec: &mut [Complex<T>]) {
        let (mx, mxh) = (self.mx, self.mxh);
        let zero = T::of(0.0);
        rowspec[..self.ny * mxh].par_chunks_mut(mxh).enumerate().for_each_init(
            || (vec![zero; mx], self.r2c.make_scratch_vec()),
            |(row, scr), (j, out)| {
                row.fill(zero);
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
    /// Liu 2000, *Wear* 243, DC-FFT). The transforms run in precision `T` (the tractions are
    /// rounded to it as they are read, the displacements widened as they are written).
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
        let s = T::buffers(s);
        s.ensure(self.nx * self.ny, self.ny * self.mxh);
        for (f, q) in [qx, qy].into_iter().enumerate() {
            self.rows_forward(
                |j, row| {
                    for &(i, k) in &self.row_items[self.row_ptr[j]..self.row_ptr[j + 1]] {
                        row[i] = T::of(q[k]);
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
            let lat: &[T] = &s.lat[f];
            u.par_iter_mut().zip(self.cell.par_iter()).for_each(|(o, &c)| *o = lat[c].into());
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
        // Wave numbers per axis, formed once (the symbol is read at every (i, j)).
        let kxs: Vec<f64> = (0..nx).map(|i| two_pi * signed(i, nx) / lx).collect();
        let kys: Vec<f64> = (0..ny).map(|j| two_pi * signed(j, ny) / ly).collect();
        let sym = |i: usize, j: usize| -> [f64; 3] {
            let (kx, ky) = (kxs[i], kys[j]);
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

impl<T: Tensor> TensorConvolution<T> {
    /// A preconditioner for the tangential operator of `grid`: the inverse of the half-space's
    /// tangential transfer, $\hat{\mathbf u} = |\mathbf k|^{-1}\,(aI - b\,\hat{\mathbf k}
    /// \hat{\mathbf k}^{\mathsf T})\,\hat{\mathbf q}$ with $a = \sum 1/G_i$, $b = \sum\nu_i/G_i$
    /// (the Fourier transform of Cerruti's solution), on the periodic lattice of the grid's
    /// bounding box (5-smooth size, no padding), with the discrete wave number
    /// $2\sin(kh/2)/h$ per axis; the mean mode gets the smallest non-zero wave number, and
    /// the whole is scaled so that its diagonal equals $1/K_{xx}(0)$ (the Jacobi value).
    ///
    /// The symbol is formed in double precision and stored in precision `T`: in single
    /// precision (`TensorConvolution::<f32>::inverse_symbol`) the transforms cost about half,
    /// and the operator is still symmetric positive definite to the rounding of single
    /// precision, which is all a preconditioner needs.
    ///
    /// # Errors
    /// As [`ContactGrid::lattice_cells`].
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
        // The discrete wave numbers per axis, formed once (the symbol is read at every (i, j)).
        let kxs: Vec<f64> =
            (0..mx).map(|i| 2.0 * (0.5 * two_pi * signed(i, mx) / mx as f64).sin() / hx).collect();
        let kys: Vec<f64> =
            (0..my).map(|j| 2.0 * (0.5 * two_pi * signed(j, my) / my as f64).sin() / hy).collect();
        let sym = |i: usize, j: usize| -> [f64; 3] {
            let (kx, ky) = (kxs[i], kys[j]);
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

    /// Store `scale * sym(i, j)` as the kernel spectra (the half spectrum of the real FFT),
    /// rounded to `T`.
    fn set_symbol(&mut self, scale: f64, sym: &(impl Fn(usize, usize) -> [f64; 3] + Sync)) {
        let (mxh, my) = (self.mxh, self.my);
        let z = T::of(0.0);
        let mut k = [vec![z; mxh * my], vec![z; mxh * my], vec![z; mxh * my]];
        {
            let [k0, k1, k2] = &mut k;
            k0.par_chunks_mut(my)
                .zip(k1.par_chunks_mut(my))
                .zip(k2.par_chunks_mut(my))
                .enumerate()
                .for_each(|(i, ((c0, c1), c2))| {
                    for j in 0..my {
                        let [v0, v1, v2] = sym(i, j);
                        c0[j] = T::of(scale * v0);
                        c1[j] = T::of(scale * v1);
                        c2[j] = T::of(scale * v2);
                    }
                });
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

impl<T: Tensor> TensorConvolution<T> {
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
