//! The normal influence operator of a lattice: surface deflection $u_z = Kp$ under
//! piecewise-constant pressure, free (Love's rectangle, zero-padded FFT) or periodic
//! (Fourier transfer $2/(E^*|\mathbf q|)$ on the period).

use super::{ConvScratch, TensorConvolution};
use crate::Boundary;
use rayon::prelude::*;
use std::time::Instant;
use stickslip_halfspace::rectangle::{pressure_uz, Compliance, Rect};

/// The planned influence operator of a lattice (reusable across loads).
#[derive(Debug)]
pub struct NormalOperator {
    conv: TensorConvolution,
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
    setup_seconds: f64,
}

impl NormalOperator {
    /// Plan the operator of an `nx` × `ny` lattice of cells `cell = (hx, hy)` for the pair
    /// compliance `c` (`Compliance::pair(substrate, indenter)`) on `boundary`.
    #[must_use]
    pub fn new(nx: usize, ny: usize, cell: (f64, f64), c: &Compliance, boundary: Boundary) -> Self {
        let t0 = Instant::now();
        let (hx, hy) = cell;
        let (conv, self_term) = match boundary {
            Boundary::Free => {
                let cell = Rect { x1: -0.5 * hx, x2: 0.5 * hx, y1: -0.5 * hy, y2: 0.5 * hy };
                let conv = TensorConvolution::scalar_free(nx, ny, |di, dj| {
                    pressure_uz(c, &cell, di as f64 * hx, dj as f64 * hy)
                });
                let s = conv.self_term()[0];
                (conv, s)
            }
            Boundary::Periodic => {
                // u(q) = c1/|q| p(q), c1 = sum (1-nu)/G = 2/E*.
                let c1 = c.one_minus_nu;
                let conv = TensorConvolution::scalar_periodic(
                    nx,
                    ny,
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
                (conv, 0.0)
            }
        };
        let mut column = vec![0.0; nx * ny];
        let mut unit = vec![0.0; nx * ny];
        unit[0] = 1.0;
        conv.apply_scalar(&unit, &mut column, &mut conv.make_scalar_scratch());
        // Periodic: the self-term is the kernel's own (free: the exact rectangle value).
        let self_term = if boundary == Boundary::Periodic { column[0] } else { self_term };
        Self {
            conv,
            nx,
            ny,
            self_term,
            column,
            periodic: boundary == Boundary::Periodic,
            planned: (hx, hy, c.one_minus_nu),
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
        self.conv.apply_scalar(p, u, &mut scratch.0);
    }

    /// Work space for [`NormalOperator::apply`].
    #[must_use]
    pub fn make_scratch(&self) -> NormalScratch {
        NormalScratch(self.conv.make_scalar_scratch())
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

/// Caller-owned work space of [`NormalOperator::apply`].
#[derive(Debug, Clone)]
pub struct NormalScratch(ConvScratch);
