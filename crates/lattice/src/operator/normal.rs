//! The normal influence operator of a lattice: surface deflection $u_z = Kp$ under
//! piecewise-constant pressure, free (Love's rectangle, zero-padded FFT) or periodic
//! (Fourier transfer $2/(E^*|\mathbf q|)$ on the period), and its spectral preconditioner.

use super::{even_quadrant, fast_size, ScalarConvolution, ScalarScratch};
use crate::Boundary;
use rayon::prelude::*;
use std::time::Instant;
use stickslip_halfspace::rectangle::{pressure_uz, Compliance, Rect};

/// The planned influence operator of a lattice (reusable across loads).
#[derive(Debug)]
pub struct NormalOperator {
    conv: ScalarConvolution<f64>,
    nx: usize,
    ny: usize,
    /// Self-influence $K_{kk}$ (m/Pa).
    self_term: f64,
    /// $K e_0$: the displacement due to unit pressure on cell 0, row-major (free: $K$ at
    /// offsets $(|d_i|, |d_j|)$; periodic: at offsets modulo the period).
    column: Vec<f64>,
    periodic: bool,
    /// What it was planned for: cell sides and $c_1$ of the two bodies.
    planned: (f64, f64, f64),
    /// The preconditioner $M$: the inverse transfer $|\mathbf q|/c_1$ on the lattice's torus,
    /// in single precision.
    inverse: ScalarConvolution<f32>,
    setup_seconds: f64,
}

impl NormalOperator {
    /// Plan the operator of an `nx` × `ny` lattice of cells `cell = (hx, hy)` for the pair
    /// compliance `c` (`Compliance::pair(substrate, indenter)`) on `boundary`.
    #[must_use]
    pub fn new(nx: usize, ny: usize, cell: (f64, f64), c: &Compliance, boundary: Boundary) -> Self {
        let t0 = Instant::now();
        let (hx, hy) = cell;
        let c1 = c.one_minus_nu;
        let (conv, column) = match boundary {
            Boundary::Free => {
                let cell = Rect { x1: -0.5 * hx, x2: 0.5 * hx, y1: -0.5 * hy, y2: 0.5 * hy };
                let quad = even_quadrant(nx, ny, |di, dj| {
                    pressure_uz(c, &cell, di as f64 * hx, dj as f64 * hy)
                });
                // The column K e_0 is the kernel itself, exact.
                (ScalarConvolution::padded(nx, ny, &quad), quad)
            }
            Boundary::Periodic => {
                // u(q) = c1/|q| p(q), c1 = sum (1-nu)/G = 2/E*; the mean mode zero.
                let conv = ScalarConvolution::torus(
                    nx,
                    ny,
                    (nx, ny),
                    (nx as f64 * hx, ny as f64 * hy),
                    |kx, ky| {
                        let q = kx.hypot(ky);
                        if q > 0.0 {
                            c1 / q
                        } else {
                            0.0
                        }
                    },
                );
                // K e_0, the unit pressure on cell 0 written as the product's first row.
                let mut column = vec![0.0; nx * ny];
                conv.apply_rows(
                    &mut vec![(); nx * ny],
                    |j, _, row| {
                        row.fill(0.0);
                        if j == 0 {
                            row[0] = 1.0;
                        }
                    },
                    &mut column,
                    |_, _, _| (),
                    &mut conv.make_scratch(),
                );
                (conv, column)
            }
        };
        // Free: the exact rectangle value; periodic: the kernel's own.
        let self_term = column[0];
        // The preconditioner's torus: the period itself, or (free) the smallest fast FFT
        // box holding the lattice, unpadded.
        let torus = match boundary {
            Boundary::Periodic => (nx, ny),
            Boundary::Free => (fast_size(nx), fast_size(ny)),
        };
        let (lx, ly) = (torus.0 as f64 * hx, torus.1 as f64 * hy);
        let qmin = 2.0 * std::f64::consts::PI / lx.max(ly);
        let inverse = ScalarConvolution::torus(nx, ny, torus, (lx, ly), |kx, ky| {
            let q = kx.hypot(ky);
            if q > 0.0 {
                q / c1
            } else {
                qmin / c1
            }
        });
        Self {
            conv,
            nx,
            ny,
            self_term,
            column,
            periodic: boundary == Boundary::Periodic,
            planned: (hx, hy, c1),
            inverse,
            setup_seconds: t0.elapsed().as_secs_f64(),
        }
    }

    /// $u \mathrel{+}= \sum_c d_c K e_c$ for a few `(cell, value)` pairs, directly
    /// ($O(N)$ each, from the stored column $Ke_0$ shifted to cell $c$).
    pub fn add_columns(&self, changes: &[(usize, f64)], u: &mut [f64]) {
        if changes.is_empty() {
            return;
        }
        let (nx, ny) = (self.nx, self.ny);
        u.par_chunks_mut(nx).enumerate().for_each(|(j, row)| {
            for &(c, d) in changes {
                let (ic, jc) = (c % nx, c / nx);
                let dj = if self.periodic { (j + ny - jc) % ny } else { j.abs_diff(jc) };
                let col = &self.column[dj * nx..(dj + 1) * nx];
                let (left, right) = row.split_at_mut(ic);
                for (v, k) in right.iter_mut().zip(col) {
                    *v += d * k;
                }
                if self.periodic {
                    for (v, k) in left.iter_mut().zip(&col[nx - ic..]) {
                        *v += d * k;
                    }
                } else {
                    for (v, k) in left.iter_mut().rev().zip(&col[1..]) {
                        *v += d * k;
                    }
                }
            }
        });
    }

    /// $u = Kp$ on the lattice (row-major, length $n_xn_y$).
    ///
    /// # Panics
    /// If a length differs from $n_xn_y$.
    pub fn apply(&self, p: &[f64], u: &mut [f64], scratch: &mut NormalScratch) {
        let nx = self.nx;
        assert_eq!(p.len(), nx * self.ny, "lattice length");
        let mut none = vec![(); nx * self.ny];
        self.conv.apply_rows(
            &mut none,
            |j, _, row| row.copy_from_slice(&p[j * nx..(j + 1) * nx]),
            u,
            |_, _, _| (),
            &mut scratch.product,
        );
    }

    /// $u = Kq$ with the rows of $q$ written by `fill(j, cells, row)` (`row[..nx]`) and
    /// `finish(j, cells, row)` called on each finished row of $u$, each with row $j$ of the
    /// caller's array `cells`, their results returned in row order
    /// ([`ScalarConvolution::apply_rows`]): a solver's passes over the lattice ride along
    /// with the transforms instead of reading the arrays again.
    pub fn apply_rows<C: Send, F: Send, R: Send>(
        &self,
        cells: &mut [C],
        fill: impl Fn(usize, &mut [C], &mut [f64]) -> F + Sync,
        u: &mut [f64],
        finish: impl Fn(usize, &mut [C], &mut [f64]) -> R + Sync,
        scratch: &mut NormalScratch,
    ) -> (Vec<F>, Vec<R>) {
        self.conv.apply_rows(cells, fill, u, finish, &mut scratch.product)
    }

    /// $z = Mq$ for the spectral preconditioner $M$, row by row as
    /// [`NormalOperator::apply_rows`], in single precision ($q$'s rows and $z$). $M$ is the
    /// inverse of the half-space's transfer function, $\hat M(\mathbf q) = |\mathbf q|/c_1$
    /// (the transfer of Stanley & Kato 1997; its inverse as a preconditioner as in
    /// Vollebregt 2014, *J. Comput. Phys.* 257), on the lattice's torus: the period itself
    /// (periodic; there $MK = I$ on every mode but the mean), or the smallest fast FFT box
    /// holding the lattice, without padding (free: about a quarter of a padded product). The
    /// mean mode takes the torus's smallest non-zero wave number, so that $M$ is symmetric
    /// positive definite. The transforms run in single precision: a preconditioner needs
    /// its direction, not its digits (the solve's accuracy rests on the products with $K$),
    /// and half the memory traffic makes it nearly twice as fast.
    pub fn precondition_rows<C: Send, F: Send, R: Send>(
        &self,
        cells: &mut [C],
        fill: impl Fn(usize, &mut [C], &mut [f32]) -> F + Sync,
        z: &mut [f32],
        finish: impl Fn(usize, &mut [C], &mut [f32]) -> R + Sync,
        scratch: &mut NormalScratch,
    ) -> (Vec<F>, Vec<R>) {
        self.inverse.apply_rows(cells, fill, z, finish, &mut scratch.inverse)
    }

    /// The preconditioner's FFT size (the torus of [`NormalOperator::precondition_rows`]).
    #[must_use]
    pub fn preconditioner_size(&self) -> (usize, usize) {
        self.inverse.fft_size()
    }

    /// Work space for [`NormalOperator::apply`], [`NormalOperator::apply_rows`] and
    /// [`NormalOperator::precondition_rows`]: the row spectra of the two transforms, about
    /// $n_y M_x/2$ complex numbers in double and $n_y M'_x/2$ in single precision.
    #[must_use]
    pub fn make_scratch(&self) -> NormalScratch {
        NormalScratch { product: self.conv.make_scratch(), inverse: self.inverse.make_scratch() }
    }

    /// FFT size $(M_x, M_y)$.
    #[must_use]
    pub fn fft_size(&self) -> (usize, usize) {
        self.conv.fft_size()
    }

    /// Lattice $(n_x, n_y)$.
    #[must_use]
    pub fn lattice(&self) -> (usize, usize) {
        (self.nx, self.ny)
    }

    /// The self-influence $K_{kk}$ (m/Pa): the displacement of a cell under unit pressure on
    /// itself.
    #[must_use]
    pub fn self_term(&self) -> f64 {
        self.self_term
    }

    /// The boundary it was planned for.
    #[must_use]
    pub fn boundary(&self) -> Boundary {
        if self.periodic {
            Boundary::Periodic
        } else {
            Boundary::Free
        }
    }

    /// What it was planned for: the cell sides $(h_x, h_y)$ and $c_1 = \sum (1-\nu)/G$ of the
    /// two bodies; a solver checks these against its problem before using the operator.
    #[must_use]
    pub fn planned(&self) -> (f64, f64, f64) {
        self.planned
    }

    /// Wall time spent planning it (s).
    #[must_use]
    pub fn setup_seconds(&self) -> f64 {
        self.setup_seconds
    }
}

/// Caller-owned work space of the operator's products ([`NormalOperator::make_scratch`]).
#[derive(Debug, Clone)]
pub struct NormalScratch {
    product: ScalarScratch<f64>,
    inverse: ScalarScratch<f32>,
}
