//! The nested (coarse-to-fine) start of the module docs and the fallback to a cold start.

use super::iteration::Start;
use super::{
    Boundary, LevelInfo, Nesting, NormalLoad, NormalProblem, NormalSolution, COARSE_TOLERANCE,
};
use crate::error::{Error, Result};
use rayon::prelude::*;
use std::time::Instant;
use stickslip_lattice::NormalOperator;
use stickslip_quad::Tolerance;

impl NormalProblem<'_> {
    /// Iterate from the nested start `coarse` (if any) and record its levels; if the warm
    /// iteration fails to converge, solve again from a cold start, so that the nesting never
    /// turns a solvable problem into a failure.
    pub(super) fn run_from(
        &self,
        op: &NormalOperator,
        load: NormalLoad,
        tol: f64,
        force: Option<f64>,
        coarse: Option<Coarse>,
        coarse_seconds: f64,
    ) -> Result<NormalSolution> {
        let t0 = Instant::now();
        let (mut s, levels) = match coarse {
            Some(c) => match self.run(op, load, tol, force, Start::Owned(c.pressure)) {
                Ok((s, _)) => (s, c.levels),
                Err(Error::NotConverged { .. }) => {
                    (self.run(op, load, tol, force, Start::Cold)?.0, vec![])
                }
                Err(e) => return Err(e),
            },
            None => (self.run(op, load, tol, force, Start::Cold)?.0, vec![]),
        };
        s.info.levels = levels.len();
        s.info.coarse_iterations = levels.iter().map(|l| l.iterations).sum();
        s.info.coarse_seconds = coarse_seconds;
        s.info.solve_seconds = coarse_seconds + t0.elapsed().as_secs_f64();
        s.levels = levels;
        Ok(s)
    }

    /// The nested start: this problem on the lattice coarsened 2 x 2 (see [`Nesting`]),
    /// solved, its pressure carried to this lattice; `None` when nesting is off, the lattice
    /// is too small (or, periodic, odd), or the coarse problem has no contact or fails.
    pub(super) fn coarse_start(&self, load: NormalLoad) -> Option<Coarse> {
        let (nx, ny) = (self.nx, self.ny);
        let Nesting::Nested { min_cells } = self.nesting else { return None };
        if nx < 2 * min_cells
            || ny < 2 * min_cells
            || (self.boundary == Boundary::Periodic && (nx % 2 == 1 || ny % 2 == 1))
        {
            return None;
        }
        // A free lattice of odd size gets a last coarse column (row) over one fine column
        // (row): its gap is the mean of the children it has.
        let (cx, cy) = (nx.div_ceil(2), ny.div_ceil(2));
        let g0 = self.gap;
        let mut gap = vec![0.0; cx * cy];
        gap.par_chunks_mut(cx).enumerate().for_each(|(jc, row)| {
            for (ic, v) in row.iter_mut().enumerate() {
                let (mut sum, mut m) = (0.0, 0.0);
                for j in 2 * jc..(2 * jc + 2).min(ny) {
                    for i in 2 * ic..(2 * ic + 2).min(nx) {
                        sum += g0[j * nx + i];
                        m += 1.0;
                    }
                }
                *v = sum / m;
            }
        });
        let tolerance = Tolerance::relative(self.tolerance.rel().max(COARSE_TOLERANCE)).ok()?;
        let coarse = NormalProblem {
            nx: cx,
            ny: cy,
            hx: 2.0 * self.hx,
            hy: 2.0 * self.hy,
            origin: self.origin,
            gap: &gap,
            bodies: self.bodies,
            boundary: self.boundary,
            tolerance,
            max_iterations: self.max_iterations,
            min_contact_cells: 1,
            nesting: self.nesting,
            preconditioner: self.preconditioner,
            memory_limit: None,
            hardness: self.hardness,
        };
        let s = coarse.solve(load).ok()?;
        drop(gap);
        if s.contact_cells == 0 {
            return None;
        }
        let mut pressure = vec![0.0; nx * ny];
        pressure.par_chunks_mut(nx).enumerate().for_each(|(j, row)| {
            let src = &s.pressure[(j / 2) * cx..(j / 2 + 1) * cx];
            for (i, p) in row.iter_mut().enumerate() {
                *p = src[i / 2];
            }
        });
        let mut levels = s.levels;
        levels.push(LevelInfo {
            lattice: (cx, cy),
            iterations: s.info.iterations,
            products: s.info.products,
            preconditioner_products: s.info.preconditioner_products,
            residual: s.info.residual,
            seconds: s.info.setup_seconds + s.info.solve_seconds - s.info.coarse_seconds,
        });
        Some(Coarse { pressure, levels })
    }
}

/// A nested start: the coarse levels' pressure on this lattice, and the levels.
pub(super) struct Coarse {
    pressure: Vec<f64>,
    levels: Vec<LevelInfo>,
}
