//! Adhesion of the Maugis–Dugdale kind (issue 32, item 2): a constant tensile traction
//! $\sigma_0 = w/h_0$ wherever the gap is below the range $h_0$, on the share of each cell
//! where it is (module docs of [`crate::solver`], "Adhesion").

use super::cohesive::shares;
use super::passes::{in_order, BLOCK};
use super::{NormalLoad, NormalProblem, NormalSolution};
use crate::error::{positive, tolerance_in, Error, Result};
use rayon::prelude::*;
use std::time::Instant;
use stickslip_lattice::NormalOperator;

/// The solver's name (as in [`Error::NotConverged`]).
pub const ADHESIVE_SOLVER_NAME: &str = "normal adhesive (Maugis-Dugdale zone fixed point over CCG)";

/// An update of the shares is extrapolated only when its change and the last one's have a
/// cosine above this (the same direction).
const EXTRAPOLATE_ALIGNMENT: f64 = 0.95;

/// The largest extrapolation factor of an update of the shares.
const EXTRAPOLATE_MAX: f64 = 20.0;

/// Default budget of zone updates (contact solves) of one adhesive solve.
pub const DEFAULT_MAX_ZONE_UPDATES: usize = 2000;

/// A Maugis–Dugdale interface: the work of adhesion $w$ and the range $h_0$; the cohesive
/// traction is $\sigma_0 = w/h_0$ (Maugis 1992, *J. Colloid Interface Sci.* 150).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Adhesion {
    work: f64,
    range: f64,
}

impl Adhesion {
    /// The work of adhesion `work` (J/m²) and the range `range` (m), both finite and $> 0$.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] (named "adhesion work" or "adhesion range") otherwise.
    pub fn new(work: f64, range: f64) -> Result<Self> {
        positive("adhesion work", work)?;
        positive("adhesion range", range)?;
        let s = work / range;
        if !s.is_finite() {
            return Err(Error::OutOfDomain {
                name: "adhesion work / range",
                value: s,
                allowed: "a finite cohesive stress",
            });
        }
        Ok(Self { work, range })
    }

    /// The work of adhesion $w$ (J/m²).
    #[must_use]
    pub fn work(&self) -> f64 {
        self.work
    }

    /// The range $h_0$ (m).
    #[must_use]
    pub fn range(&self) -> f64 {
        self.range
    }

    /// The cohesive (Dugdale) stress $\sigma_0 = w/h_0$ (Pa).
    #[must_use]
    pub fn stress(&self) -> f64 {
        self.work / self.range
    }
}

/// The solution of an adhesive solve: the normal solution with the total pressure, and the
/// cohesive zone.
#[derive(Debug, Clone, PartialEq)]
pub struct AdhesiveSolution {
    /// The solution with the **total** pressure $p_k = p^c_k - \sigma_0f_k$ (Pa,
    /// compressive positive, negative where the adhesion pulls), its force
    /// $h_xh_y\sum_k p_k$ (negative when pulling), the contact $p^c_k > 0$ (the gap closed),
    /// the gap after loading, and the termination information of the last contact solve
    /// with `iterations` and `products` summed over all of them.
    pub normal: NormalSolution,
    /// The contact pressure $p^c_k \ge 0$ (Pa): what the closed gap carries besides the
    /// cohesive traction.
    pub contact_pressure: Vec<f64>,
    /// The cohesive zone: cells with a part where the gap is below $h_0$ (the contact
    /// included), where the traction pulls: `zone_share > 0`.
    pub zone: Vec<bool>,
    /// Cells in the zone.
    pub zone_cells: usize,
    /// The share $f_k \in [0, 1]$ of each cell under the cohesive traction: the traction on
    /// the cell is $\sigma_0f_k$ (module docs, "Adhesion: the zone inside a cell"); 1 inside
    /// the zone, 0 outside, between on its edge.
    pub zone_share: Vec<f64>,
    /// The adhesion solved with.
    pub adhesion: Adhesion,
    /// Contact solves (zone updates) until the shares reproduced themselves.
    pub zone_updates: usize,
    /// Of the zone updates, those that went further than the new shares along the last
    /// two changes (module docs, "Adhesion: the updates").
    pub zone_extrapolations: usize,
    /// The largest difference between a cell's share and the share that the returned gap
    /// gives it, $\max_k|F_k(g) - f_k|$ (at most [`zone_tolerance`] of the contact solves'
    /// tolerance; the gap and complementarity residuals are in `normal.info`).
    pub zone_residual: f64,
}

impl AdhesiveSolution {
    /// The cells in the zone but not in contact: where only the cohesive traction acts
    /// (the Dugdale zone proper, $0 < g_k < h_0$).
    #[must_use]
    pub fn cohesive_only_cells(&self) -> usize {
        self.zone.iter().zip(&self.normal.contact).filter(|(z, c)| **z && !**c).count()
    }
}

impl NormalProblem<'_> {
    /// The adhesive contact at the approach `approach` (m; any sign: negative = the
    /// surfaces held apart) under the Maugis–Dugdale `adhesion` (module docs, "Adhesion"),
    /// from `warm` (the solution at the previous step of a path: its zone and contact
    /// pressure) or, without it, from no zone (the approach from far). `op` is this
    /// problem's [`NormalProblem::operator`].
    ///
    /// # Errors
    /// As [`NormalProblem::solve_with`] under approach control (the tolerance, the memory, a
    /// periodic approach at or above the mean gap); [`Error::OutOfDomain`] (named
    /// "adhesion with hardness") when the problem has a hardness;
    /// [`Error::NotConverged`] (named [`ADHESIVE_SOLVER_NAME`]) when the zone does not
    /// reproduce itself within `max_zone_updates` contact solves;
    /// [`Error::LengthMismatch`] for a warm start of another lattice.
    pub fn solve_adhesive(
        &self,
        op: &NormalOperator,
        adhesion: Adhesion,
        approach: f64,
        warm: Option<&AdhesiveSolution>,
        max_zone_updates: usize,
    ) -> Result<AdhesiveSolution> {
        let t0 = Instant::now();
        if let Some(h) = self.hardness {
            return Err(Error::OutOfDomain {
                name: "adhesion with hardness",
                value: h,
                allowed: "adhesion or a hardness, not both (not implemented together)",
            });
        }
        let n = self.nx * self.ny;
        if let Some(w) = warm {
            if w.zone.len() != n {
                return Err(Error::LengthMismatch {
                    name: "adhesive warm start",
                    expected: n,
                    got: w.zone.len(),
                });
            }
        }
        let (h0, s0) = (adhesion.range(), adhesion.stress());
        let tol = tolerance_in(ADHESIVE_SOLVER_NAME, self.tolerance, Self::TOLERANCE_RANGE)?;
        let share_tol = zone_tolerance(tol);
        // The share of each cell under the cohesive traction (1 inside the zone, 0 outside,
        // between on its edge).
        let mut share: Vec<f64> = match warm {
            Some(w) => w.zone_share.clone(),
            None => vec![0.0; n],
        };
        let mut next = share.clone();
        // The last step's change of the shares, and the plain steps since an extrapolated one.
        let mut last_step = vec![0.0; n];
        let (mut plain_steps, mut extrapolations) = (0usize, 0usize);
        let mut pc: Option<Vec<f64>> = warm.map(|w| w.contact_pressure.clone());
        let mut scratch = op.make_scratch();
        let mut tension = vec![0.0; n];
        let mut ut = vec![0.0; n];
        let mut g0 = vec![0.0; n];
        let (mut iterations, mut products, mut pre, mut updates) = (0, 0, 0, 0);
        loop {
            updates += 1;
            // The cohesive traction on the zone and the displacement it causes: the contact
            // problem sees the initial gap g0 + K(-s0 f).
            let any = share.iter().any(|&f| f > 0.0);
            if any {
                tension.par_iter_mut().zip(share.par_iter()).for_each(|(t, &f)| *t = -s0 * f);
                op.apply(&tension, &mut ut, &mut scratch);
                products += 1;
            } else {
                ut.iter_mut().for_each(|u| *u = 0.0);
            }
            g0.par_iter_mut()
                .zip(self.gap.par_iter().zip(ut.par_iter()))
                .for_each(|(g, (a, b))| *g = a + b);
            let mut inner = NormalProblem { gap: &g0, ..self.clone() };
            inner.min_contact_cells = 1;
            // A warm solve that fails is tried once more cold (a zero warm start is taken as
            // the cold one by the iteration itself).
            let start = pc.as_deref();
            let load = NormalLoad::Approach(approach);
            let s = match inner.solve_with(op, load, start) {
                Ok(s) => s,
                Err(_) if start.is_some() => inner.solve_with(op, load, None)?,
                Err(e) => return Err(e),
            };
            iterations += s.info.iterations;
            products += s.info.products;
            pre += s.info.preconditioner_products;
            // The gap of the contact solve is the true gap g0 + K p - delta; the shares it
            // gives.
            let change = shares(&s.gap, self.nx, self.boundary, h0, &share, &mut next);
            if change <= share_tol {
                let mut out = self.finish_adhesive(
                    s,
                    share,
                    change,
                    adhesion,
                    (iterations, products, pre, updates),
                    t0,
                )?;
                out.zone_extrapolations = extrapolations;
                return Ok(out);
            }
            if updates >= max_zone_updates {
                return Err(Error::NotConverged {
                    solver: ADHESIVE_SOLVER_NAME,
                    iterations: updates,
                    residual: change,
                    tolerance: share_tol,
                });
            }
            // The step: the new shares, or further along the same direction when the last
            // two steps went the same way and shrank by a steady ratio (module docs).
            let (dd, dp, pp) = in_order(
                next.par_chunks(BLOCK)
                    .zip(share.par_chunks(BLOCK).zip(last_step.par_chunks(BLOCK)))
                    .map(|(x, (f, d0))| {
                        x.iter().zip(f.iter().zip(d0)).fold((0.0, 0.0, 0.0), |a, (x, (f, d0))| {
                            let d = x - f;
                            (a.0 + d * d, a.1 + d * d0, a.2 + d0 * d0)
                        })
                    }),
            )
            .into_iter()
            .fold((0.0, 0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1, a.2 + b.2));
            let ratio = if plain_steps >= 2 && pp > 0.0 { dp / pp } else { 0.0 };
            let aligned = dp > EXTRAPOLATE_ALIGNMENT * (dd * pp).sqrt();
            let factor = if aligned && ratio > 0.0 && ratio < 1.0 {
                (1.0 / (1.0 - ratio)).min(EXTRAPOLATE_MAX)
            } else {
                1.0
            };
            last_step.par_iter_mut().zip(share.par_iter_mut().zip(next.par_iter())).for_each(
                |(d0, (f, x))| {
                    *d0 = x - *f;
                    *f = (*f + factor * *d0).clamp(0.0, 1.0);
                },
            );
            if factor > 1.0 {
                extrapolations += 1;
                plain_steps = 0;
            } else {
                plain_steps += 1;
            }
            pc = Some(s.pressure);
        }
    }

    /// The adhesive solution from the last contact solve `s` at the fixed-point shares
    /// `share` (`change` the largest change the last solve would have made to them).
    fn finish_adhesive(
        &self,
        s: NormalSolution,
        share: Vec<f64>,
        change: f64,
        adhesion: Adhesion,
        counts: (usize, usize, usize, usize),
        t0: Instant,
    ) -> Result<AdhesiveSolution> {
        let s0 = adhesion.stress();
        // No minimum of cells: along a path the zone starts and ends with one cell; whether
        // the range is resolved by the lattice is the caller's check.
        let zone: Vec<bool> = share.par_iter().map(|&f| f > 0.0).collect();
        let zone_cells = zone.iter().filter(|&&z| z).count();
        let contact_pressure = s.pressure.clone();
        let mut normal = s;
        let total: Vec<f64> = contact_pressure
            .par_iter()
            .zip(share.par_iter())
            .map(|(&p, &f)| if f > 0.0 { p - s0 * f } else { p })
            .collect();
        let area = self.hx * self.hy;
        normal.force = area
            * in_order(total.par_chunks(BLOCK).map(|b| b.iter().sum::<f64>())).iter().sum::<f64>();
        normal.peak_pressure = total.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        normal.pressure = total;
        normal.info.solver = ADHESIVE_SOLVER_NAME;
        normal.info.iterations = counts.0;
        normal.info.products = counts.1;
        normal.info.preconditioner_products = counts.2;
        normal.info.approach_steps = counts.3;
        normal.info.solve_seconds = t0.elapsed().as_secs_f64();
        Ok(AdhesiveSolution {
            normal,
            contact_pressure,
            zone,
            zone_cells,
            zone_share: share,
            adhesion,
            zone_updates: counts.3,
            zone_extrapolations: 0,
            zone_residual: change,
        })
    }
}

/// The largest change of a cell's share of the zone at which the zone updates stop, for the
/// contact solves' relative tolerance `tol`: $\sqrt{\mathrm{tol}}$ within
/// $[10^{-6}, 10^{-3}]$. A share moves by the gap's error over the gap's change across the
/// cell, and the gap's error is `tol` times the rigid interference, which is hundreds of
/// ranges in the JKR regime: a share tolerance at `tol` itself is below that noise
/// (measured: the updates stall at a change of 8e-8 with `tol` = 1e-9 on a sphere at
/// Maugis parameter 6).
#[must_use]
pub fn zone_tolerance(tol: f64) -> f64 {
    tol.sqrt().clamp(1e-6, 1e-3)
}
