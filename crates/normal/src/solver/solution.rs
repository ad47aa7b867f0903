//! What a solve returns: the solution, its termination information, and how the iteration
//! assembles them.

use super::passes::{in_order, BLOCK};
use super::{LevelInfo, NormalProblem, SOLVER_NAME};
use crate::error::Result;
use rayon::prelude::*;
use std::time::Instant;
use stickslip_lattice::{Boundary, ContactGrid, NormalOperator};
use stickslip_quad::Tolerance;

/// Termination information of a normal solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NormalInfo {
    /// Which solver ([`SOLVER_NAME`]).
    pub solver: &'static str,
    /// Conjugate-gradient iterations on this lattice (coarse levels: `coarse_iterations`).
    pub iterations: usize,
    /// FFT convolutions with $K$ on this lattice (one or two per iteration, module docs).
    pub products: usize,
    /// Applications of the preconditioner on this lattice (one per iteration; 0 without).
    pub preconditioner_products: usize,
    /// Coarser lattices solved first (a nested start; 0 for a cold or warm start).
    pub levels: usize,
    /// Iterations on the coarser lattices, summed.
    pub coarse_iterations: usize,
    /// Wall time of the coarser lattices, seconds (part of `solve_seconds`).
    pub coarse_seconds: f64,
    /// Under force control with a hardness: the approach-controlled solves of the outer
    /// secant on the approach (module docs, "Hardness"); 0 otherwise. `iterations` and
    /// `products` are summed over them.
    pub approach_steps: usize,
    /// Gap residual $r_g$ (module docs).
    pub gap_residual: f64,
    /// Complementarity residual $r_c$ (module docs).
    pub complementarity_residual: f64,
    /// Force residual $r_F$ (module docs; 0 under displacement control).
    pub force_residual: f64,
    /// The largest of the three.
    pub residual: f64,
    /// The gap scale $s = \delta - \min_k g^0_k$ (m) of the relative residuals.
    pub gap_scale: f64,
    /// The tolerance requested.
    pub tolerance: Tolerance,
    /// FFT size $(M_x, M_y)$ of the convolution.
    pub fft_size: (usize, usize),
    /// Wall time of the operator planning (kernel and its spectrum), seconds.
    pub setup_seconds: f64,
    /// Wall time of the iteration, seconds.
    pub solve_seconds: f64,
}

/// The solution of a normal-contact problem. Arrays are row-major, index `j * nx + i`.
#[derive(Debug, Clone, PartialEq)]
pub struct NormalSolution {
    /// Cells along $x$.
    pub nx: usize,
    /// Cells along $y$.
    pub ny: usize,
    /// Cell side along $x$ (m).
    pub hx: f64,
    /// Cell side along $y$ (m).
    pub hy: f64,
    /// Lattice corner $(x_0, y_0)$ (m).
    pub origin: (f64, f64),
    /// Pressure per cell (Pa, compressive positive; $\ge 0$ except in an adhesive solution,
    /// [`NormalProblem::solve_adhesive`], where it is the total with the cohesive tension).
    pub pressure: Vec<f64>,
    /// Contact flag per cell ($p_k > 0$).
    pub contact: Vec<bool>,
    /// Gap after loading $g_k = g^0_k + u_k - \delta$ (m; zero to the residual in contact).
    pub gap: Vec<f64>,
    /// Approach $\delta$ (m, positive = pressed together; periodic: relative to the mean
    /// surface displacement).
    pub approach: f64,
    /// Total normal force $P = h_xh_y\sum_k p_k$ (N).
    pub force: f64,
    /// Number of contact cells.
    pub contact_cells: usize,
    /// Contact area $h_xh_y\cdot$`contact_cells` (m²).
    pub area: f64,
    /// Contact fraction: contact cells over all cells.
    pub fraction: f64,
    /// Peak pressure $\max_k p_k$ (Pa).
    pub peak_pressure: f64,
    /// Displacement control where the gap never closes: zero load, no contact.
    pub no_contact: bool,
    /// Free boundary: the contact reaches a lattice edge.
    pub touches_boundary: bool,
    /// The hardness that capped the pressure (Pa), if any.
    pub hardness: Option<f64>,
    /// Plastic flag per cell ($p_k$ at the hardness); empty without a hardness.
    pub plastic: Vec<bool>,
    /// Plastic displacement per cell (m): the interpenetration $\delta - g^0_k - u_k \ge 0$
    /// that plastic flow removes at a plastic cell, 0 elsewhere; empty without a hardness.
    /// The gap after loading is 0 at a plastic cell.
    pub plastic_displacement: Vec<f64>,
    /// Number of plastic cells.
    pub plastic_cells: usize,
    /// The share of the contact that is plastic: plastic cells over contact cells (0 without
    /// contact or hardness).
    pub plastic_fraction: f64,
    /// Termination information.
    pub info: NormalInfo,
    /// The coarser levels of a nested start, coarsest first (empty for a cold or warm start).
    pub levels: Vec<LevelInfo>,
}

impl NormalSolution {
    /// The contact cells with their pressure as a [`ContactGrid`] (element centres on the
    /// lattice, one patch) for the tangential solvers ([`stickslip_traction::GridProblem`],
    /// [`stickslip_traction::FastProblem`]).
    ///
    /// The pressure is taken as compressive only: a tensile pressure (the adhesive traction
    /// of [`NormalProblem::solve_adhesive`]) enters as zero, so that adhesive tension
    /// carries no friction.
    ///
    /// # Errors
    /// [`Error::Lattice`](crate::Error::Lattice) (an empty grid) when there is no contact.
    pub fn contact_grid(&self) -> Result<ContactGrid> {
        let clipped: Vec<f64>;
        let pressure = if self.pressure.iter().any(|&p| p < 0.0) {
            clipped = self.pressure.iter().map(|&p| p.max(0.0)).collect();
            &clipped
        } else {
            &self.pressure
        };
        Ok(ContactGrid::from_mask(
            self.hx,
            self.hy,
            self.origin,
            self.nx,
            self.ny,
            &self.contact,
            pressure,
        )?)
    }

    /// Centre of cell `k` (m).
    #[must_use]
    pub fn centre(&self, k: usize) -> (f64, f64) {
        let (i, j) = (k % self.nx, k / self.nx);
        (self.origin.0 + (i as f64 + 0.5) * self.hx, self.origin.1 + (j as f64 + 0.5) * self.hy)
    }
}

impl NormalProblem<'_> {
    /// The termination information of a solve on this lattice; `residuals` = gap,
    /// complementarity, force and their largest.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn info(
        &self,
        op: &NormalOperator,
        iterations: usize,
        products: usize,
        preconditioner_products: usize,
        residuals: (f64, f64, f64, f64),
        gap_scale: f64,
        t0: Instant,
    ) -> NormalInfo {
        NormalInfo {
            solver: SOLVER_NAME,
            iterations,
            products,
            preconditioner_products,
            levels: 0,
            coarse_iterations: 0,
            coarse_seconds: 0.0,
            approach_steps: 0,
            gap_residual: residuals.0,
            complementarity_residual: residuals.1,
            force_residual: residuals.2,
            residual: residuals.3,
            gap_scale,
            tolerance: self.tolerance,
            fft_size: op.fft_size(),
            setup_seconds: op.setup_seconds(),
            solve_seconds: t0.elapsed().as_secs_f64(),
        }
    }

    pub(super) fn finish(
        &self,
        pressure: Vec<f64>,
        mut gap: Vec<f64>,
        approach: f64,
        info: NormalInfo,
    ) -> NormalSolution {
        let (nx, ny) = (self.nx, self.ny);
        let (plastic, plastic_displacement) = match self.hardness {
            None => (Vec::new(), Vec::new()),
            Some(h) => {
                let plastic: Vec<bool> = pressure.iter().map(|&p| p >= h).collect();
                let mut w = vec![0.0; nx * ny];
                for ((w, g), &pl) in w.iter_mut().zip(gap.iter_mut()).zip(&plastic) {
                    if pl {
                        *w = (-*g).max(0.0);
                        *g = 0.0;
                    }
                }
                (plastic, w)
            }
        };
        let plastic_cells = plastic.iter().filter(|&&c| c).count();
        let area = self.hx * self.hy;
        // The contact flags, and per block the pressed cells, the pressure sum and peak, in
        // one parallel pass (the sums in block order, the same for any number of threads).
        let mut contact = vec![false; nx * ny];
        let (contact_cells, sum, peak) = in_order(
            contact.par_chunks_mut(BLOCK).zip(pressure.par_chunks(BLOCK)).map(|(c, p)| {
                let mut acc = (0usize, 0.0, 0.0f64);
                for (c, &p) in c.iter_mut().zip(p) {
                    *c = p > 0.0;
                    acc = (acc.0 + usize::from(*c), acc.1 + p, acc.2.max(p));
                }
                acc
            }),
        )
        .into_iter()
        .fold((0, 0.0, 0.0f64), |a, b| (a.0 + b.0, a.1 + b.1, a.2.max(b.2)));
        let touches_boundary = self.boundary == Boundary::Free && {
            let row = |j: usize| contact[j * nx..(j + 1) * nx].iter().any(|&c| c);
            row(0) || row(ny - 1) || (0..ny).any(|j| contact[j * nx] || contact[j * nx + nx - 1])
        };
        NormalSolution {
            nx,
            ny,
            hx: self.hx,
            hy: self.hy,
            origin: self.origin,
            force: area * sum,
            peak_pressure: peak,
            contact_cells,
            area: area * contact_cells as f64,
            fraction: contact_cells as f64 / (nx * ny) as f64,
            no_contact: contact_cells == 0,
            touches_boundary,
            hardness: self.hardness,
            plastic_fraction: if contact_cells > 0 {
                plastic_cells as f64 / contact_cells as f64
            } else {
                0.0
            },
            plastic,
            plastic_displacement,
            plastic_cells,
            pressure,
            contact,
            gap,
            approach,
            info,
            levels: Vec::new(),
        }
    }
}
