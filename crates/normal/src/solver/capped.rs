//! Force control under a hardness cap: the capped iteration with the force kept by
//! projection, and, should that not converge, a safeguarded secant on the approach over
//! approach-controlled capped solves, each warm-started from the one before (module docs of
//! [`crate::solver`], "Hardness").

use super::iteration::Start;
use super::passes::{in_order, BLOCK};
use super::{Boundary, NormalLoad, NormalProblem, NormalSolution, SOLVER_NAME};
use crate::error::{Error, Result};
use rayon::prelude::*;
use std::time::Instant;
use stickslip_lattice::NormalOperator;
use stickslip_quad::Tolerance;

/// The most approach-controlled solves of one force-controlled capped solve.
const MAX_APPROACH_STEPS: usize = 60;

/// Relative tolerance of the elastic solve that gives a cold start its first approach.
const START_TOLERANCE: f64 = 1e-3;

/// The most steps of the projected iteration under a force before the secant takes over.
const PROJECTED_ITERATIONS: usize = 400;

impl NormalProblem<'_> {
    /// Force control under the hardness: the capped iteration with the force kept by the
    /// projection (module docs, "Hardness"); if that does not converge within
    /// [`PROJECTED_ITERATIONS`] (or the problem's limit), the secant on the approach
    /// ([`NormalProblem::run_capped`]) from a cold start, its counts added.
    pub(super) fn run_capped_force(
        &self,
        op: &NormalOperator,
        pf: f64,
        tol: f64,
        start: Start<'_>,
    ) -> Result<(NormalSolution, bool)> {
        let limit = self.max_iterations.min(PROJECTED_ITERATIONS);
        match self.iterate(op, NormalLoad::Force(pf), tol, Some(pf), start, limit) {
            Err(Error::NotConverged { iterations, .. }) => {
                let (mut s, warm) = self.run_capped(op, pf, tol, Start::Cold)?;
                s.info.iterations += iterations;
                Ok((s, warm))
            }
            other => other,
        }
    }

    /// The force `pf` under the hardness: the approach $\delta$ at which the capped contact
    /// carries `pf`, found by a secant on $F(\delta)$ (continuous and non-decreasing),
    /// kept inside the bracket of the approaches tried (false position when the secant
    /// leaves it); every solve is the capped iteration under approach control from the
    /// previous pressure. The first approach: from the start's pressure (the mean of
    /// $g^0 + Kp$ over the cells strictly between 0 and the cap), or, cold, that of the
    /// elastic contact under the same force (a lower bound: the cap only softens).
    pub(super) fn run_capped(
        &self,
        op: &NormalOperator,
        pf: f64,
        tol: f64,
        start: Start<'_>,
    ) -> Result<(NormalSolution, bool)> {
        let warm = !matches!(start, Start::Cold);
        let t0 = Instant::now();
        let cap = self.hardness.unwrap_or(f64::INFINITY);
        let g0 = self.gap;
        let n = g0.len();
        let gmin = g0.par_iter().copied().reduce(|| f64::INFINITY, f64::min);
        // Periodic: approaches stay below the mean gap (module docs, "Outcomes").
        let ceiling = match self.boundary {
            Boundary::Periodic => {
                in_order(g0.par_chunks(BLOCK).map(|b| b.iter().sum::<f64>())).iter().sum::<f64>()
                    / n as f64
            }
            Boundary::Free => f64::INFINITY,
        };
        let mut inner = self.clone();
        inner.min_contact_cells = 1;
        let (mut iterations, mut products, mut pre, mut steps) = (0, 0, 0, 0);
        let (mut p, mut delta) = match start {
            Start::Cold => {
                let mut el = inner.clone();
                el.hardness = None;
                let loose = tol.max(START_TOLERANCE);
                el.tolerance = Tolerance::relative(loose).unwrap_or(self.tolerance);
                let (s, _) = el.run(op, NormalLoad::Force(pf), loose, Some(pf), Start::Cold)?;
                iterations += s.info.iterations;
                products += s.info.products;
                pre += s.info.preconditioner_products;
                let p: Vec<f64> = s.pressure.iter().map(|p| p.min(cap)).collect();
                (p, s.approach)
            }
            Start::Borrowed(w) => self.start_approach(op, w.to_vec(), cap, &mut products),
            Start::Owned(w) => self.start_approach(op, w, cap, &mut products),
        };
        delta = delta.min(next_below(ceiling));
        let mut lo: Option<(f64, f64)> = None;
        let mut hi: Option<(f64, f64)> = None;
        let mut prev: Option<(f64, f64)> = None;
        // The approach solves far from the force need not be tight: each is solved to a
        // thousandth of the last force error, between a tenth of the tolerance (the last one)
        // and START_TOLERANCE, and tighter when that leaves the start unchanged.
        let tight = (0.1 * tol).max(Self::TOLERANCE_RANGE.0);
        let loose = START_TOLERANCE.max(tight);
        let mut inner_tol = loose;
        loop {
            steps += 1;
            inner.tolerance = Tolerance::relative(inner_tol).unwrap_or(self.tolerance);
            let (mut s, _) =
                inner.run(op, NormalLoad::Approach(delta), inner_tol, None, Start::Borrowed(&p))?;
            iterations += s.info.iterations;
            products += s.info.products;
            pre += s.info.preconditioner_products;
            let f = s.force;
            let err = (f - pf).abs() / pf;
            if err <= tol && inner_tol > tight {
                // Close enough: solve this approach again to a tenth of the tolerance.
                inner_tol = tight;
                p = s.pressure;
                continue;
            }
            if err <= tol {
                s.info.tolerance = self.tolerance;
                s.info.iterations = iterations;
                s.info.products = products;
                s.info.preconditioner_products = pre;
                s.info.approach_steps = steps;
                s.info.force_residual = err;
                s.info.residual = s.info.residual.max(err);
                s.info.solve_seconds = t0.elapsed().as_secs_f64();
                if s.contact_cells < self.min_contact_cells {
                    return Err(Error::UnresolvedContact {
                        cells: s.contact_cells,
                        minimum: self.min_contact_cells,
                    });
                }
                return Ok((s, warm));
            }
            if steps >= MAX_APPROACH_STEPS {
                return Err(Error::NotConverged {
                    solver: SOLVER_NAME,
                    iterations,
                    residual: err,
                    tolerance: tol,
                });
            }
            if s.info.iterations == 0 && inner_tol > tight {
                // The start already met this loose tolerance: the force it gives is the old
                // one. Solve the same approach tighter.
                inner_tol = (0.01 * inner_tol).max(tight);
                p = s.pressure;
                continue;
            }
            if f < pf {
                lo = Some((delta, f));
            } else {
                hi = Some((delta, f));
            }
            // The secant through the last two solves, or (first step) through this one and
            // the first touch (F = 0 at the smallest gap).
            let (d1, f1) = prev.unwrap_or((gmin, 0.0));
            let mut next = if delta != d1 && f != f1 {
                delta + (pf - f) * (delta - d1) / (f - f1)
            } else {
                f64::NAN
            };
            next = match (lo, hi) {
                (Some((dl, fl)), Some((dh, fh))) => {
                    if next > dl && next < dh {
                        next
                    } else {
                        dl + (pf - fl) * (dh - dl) / (fh - fl)
                    }
                }
                (Some(_), None) => {
                    if next > delta {
                        next
                    } else {
                        delta + (delta - gmin)
                    }
                }
                (None, Some(_)) => {
                    if next > gmin && next < delta {
                        next
                    } else {
                        gmin + 0.5 * (delta - gmin)
                    }
                }
                (None, None) => unreachable!("one side is set above"),
            };
            prev = Some((delta, f));
            p = s.pressure;
            inner_tol = (1e-3 * err).clamp(tight, loose);
            delta = next.min(next_below(ceiling));
        }
    }

    /// A start's pressure clipped to `[0, cap]` and its approach: the mean of $g^0 + Kp$ over
    /// the cells strictly between 0 and the cap, or, without such a cell, the largest over
    /// the plastic cells (one product).
    fn start_approach(
        &self,
        op: &NormalOperator,
        mut p: Vec<f64>,
        cap: f64,
        products: &mut usize,
    ) -> (Vec<f64>, f64) {
        p.par_iter_mut().for_each(|p| *p = p.clamp(0.0, cap));
        let mut u = vec![0.0; p.len()];
        op.apply(&p, &mut u, &mut op.make_scratch());
        *products += 1;
        let (sum, cells, top) = in_order(
            u.par_chunks(BLOCK).zip(self.gap.par_chunks(BLOCK).zip(p.par_chunks(BLOCK))).map(
                |(u, (g0, p))| {
                    let mut acc = (0.0, 0usize, f64::NEG_INFINITY);
                    for (u, (g0, p)) in u.iter().zip(g0.iter().zip(p)) {
                        if *p >= cap {
                            acc.2 = acc.2.max(g0 + u);
                        } else if *p > 0.0 {
                            acc = (acc.0 + g0 + u, acc.1 + 1, acc.2);
                        }
                    }
                    acc
                },
            ),
        )
        .into_iter()
        .fold((0.0, 0, f64::NEG_INFINITY), |a, b| (a.0 + b.0, a.1 + b.1, a.2.max(b.2)));
        let gmin = self.gap.par_iter().copied().reduce(|| f64::INFINITY, f64::min);
        let delta = if cells > 0 {
            sum / cells as f64
        } else if top.is_finite() {
            top
        } else {
            gmin
        };
        (p, delta)
    }
}

/// The largest double below `x` (itself if infinite).
fn next_below(x: f64) -> f64 {
    if x.is_finite() {
        x - x.abs().max(f64::MIN_POSITIVE) * f64::EPSILON
    } else {
        x
    }
}
