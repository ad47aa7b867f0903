//! Adhesion of the Maugis–Dugdale kind (issue 32, item 2): a constant tensile traction
//! $\sigma_0 = w/h_0$ wherever the gap is below the range $h_0$ (module docs of
//! [`crate::solver`], "Adhesion").

use super::passes::{in_order, BLOCK};
use super::{NormalLoad, NormalProblem, NormalSolution};
use crate::error::{positive, Error, Result};
use rayon::prelude::*;
use std::time::Instant;
use stickslip_lattice::NormalOperator;

/// The solver's name (as in [`Error::NotConverged`]).
pub const ADHESIVE_SOLVER_NAME: &str = "normal adhesive (Maugis-Dugdale zone fixed point over CCG)";

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
    /// The solution with the **total** pressure $p_k = p^c_k - \sigma_0\mathbf 1_Z(k)$ (Pa,
    /// compressive positive, negative where the adhesion pulls), its force
    /// $h_xh_y\sum_k p_k$ (negative when pulling), the contact $p^c_k > 0$ (the gap closed),
    /// the gap after loading, and the termination information of the last contact solve
    /// with `iterations` and `products` summed over all of them.
    pub normal: NormalSolution,
    /// The contact pressure $p^c_k \ge 0$ (Pa): what the closed gap carries besides the
    /// cohesive traction.
    pub contact_pressure: Vec<f64>,
    /// The cohesive zone: cells with $g_k < h_0$ (the contact included), where the traction
    /// $\sigma_0$ pulls.
    pub zone: Vec<bool>,
    /// Cells in the zone.
    pub zone_cells: usize,
    /// The adhesion solved with.
    pub adhesion: Adhesion,
    /// Contact solves (zone updates) until the zone reproduced itself.
    pub zone_updates: usize,
    /// The largest violation of the zone condition by the returned gap, relative to $h_0$:
    /// $\max(\max_{k\in Z}(g_k - h_0)^+, \max_{k\notin Z}(h_0 - g_k)^+)/h_0$ (0 at the fixed
    /// point; the gap and complementarity residuals are in `normal.info`).
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
        let mut zone: Vec<bool> = match warm {
            Some(w) => w.zone.clone(),
            None => vec![false; n],
        };
        let mut pc: Option<Vec<f64>> = warm.map(|w| w.contact_pressure.clone());
        let mut scratch = op.make_scratch();
        let mut tension = vec![0.0; n];
        let mut ut = vec![0.0; n];
        let mut g0 = vec![0.0; n];
        let (mut iterations, mut products, mut pre, mut updates) = (0, 0, 0, 0);
        loop {
            updates += 1;
            // The cohesive traction on the zone and the displacement it causes: the contact
            // problem sees the initial gap g0 + K(-s0 1_Z).
            let any = zone.iter().any(|&z| z);
            if any {
                tension
                    .par_iter_mut()
                    .zip(zone.par_iter())
                    .for_each(|(t, &z)| *t = if z { -s0 } else { 0.0 });
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
            // A start without a pressed cell gives the iteration no direction: start such a
            // solve cold (from the rigid interference) instead; a warm solve that fails is
            // tried once more cold.
            let start = pc.as_deref().filter(|p| p.iter().any(|&p| p > 0.0));
            let load = NormalLoad::Approach(approach);
            let s = match inner.solve_with(op, load, start) {
                Ok(s) => s,
                Err(_) if start.is_some() => inner.solve_with(op, load, None)?,
                Err(e) => return Err(e),
            };
            iterations += s.info.iterations;
            products += s.info.products;
            pre += s.info.preconditioner_products;
            // The gap of the contact solve is the true gap g0 + K p - delta.
            let next: Vec<bool> = s.gap.par_iter().map(|&g| g < h0).collect();
            let same = next == zone;
            if same {
                return self.finish_adhesive(
                    s,
                    zone,
                    adhesion,
                    (iterations, products, pre, updates),
                    t0,
                );
            }
            if updates >= max_zone_updates {
                let changed = next.iter().zip(&zone).filter(|(a, b)| a != b).count();
                return Err(Error::NotConverged {
                    solver: ADHESIVE_SOLVER_NAME,
                    iterations: updates,
                    residual: changed as f64 / n as f64,
                    tolerance: 0.0,
                });
            }
            zone = next;
            pc = Some(s.pressure);
        }
    }

    /// The adhesive solution from the last contact solve `s` at the fixed-point zone.
    fn finish_adhesive(
        &self,
        s: NormalSolution,
        zone: Vec<bool>,
        adhesion: Adhesion,
        counts: (usize, usize, usize, usize),
        t0: Instant,
    ) -> Result<AdhesiveSolution> {
        let (h0, s0) = (adhesion.range(), adhesion.stress());
        // No minimum of cells: along a path the zone starts and ends with one cell; whether
        // the range is resolved by the lattice is the caller's check.
        let zone_cells = zone.iter().filter(|&&z| z).count();
        let contact_pressure = s.pressure.clone();
        let mut normal = s;
        let total: Vec<f64> = contact_pressure
            .par_iter()
            .zip(zone.par_iter())
            .map(|(&p, &z)| if z { p - s0 } else { p })
            .collect();
        let zone_residual =
            in_order(normal.gap.par_chunks(BLOCK).zip(zone.par_chunks(BLOCK)).map(|(g, z)| {
                g.iter().zip(z).fold(0.0f64, |m, (&g, &z)| {
                    m.max(if z { (g - h0).max(0.0) } else { (h0 - g).max(0.0) })
                })
            }))
            .into_iter()
            .fold(0.0, f64::max)
                / h0;
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
            adhesion,
            zone_updates: counts.3,
            zone_residual,
        })
    }
}
