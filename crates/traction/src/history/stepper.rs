//! The stepper: the path state between steps, one step's solve and the per-step record.

use super::path::{find_loops, HistoryLoop, PathControl};
use super::problem::{
    HistoryDirections, HistoryOutcome, HistoryProblem, HistoryStep, StepTarget,
    SLIP_RANGE_DIRECTIONS,
};
use super::solves::{Ctx, Tally};
use crate::error::{Error, Result};
use crate::fast::{FastSolution, WarmStart};
use crate::solve::{ElementState, Regime};
use rayon::prelude::*;
use std::f64::consts::PI;
use std::time::Instant;
use stickslip_lattice::{ContactGrid, ConvScratch, TensorConvolution};

/// Block length of the stepper's parallel sums over cells: fixed blocks, their sums added
/// in order, so a path gives the same bits whatever the number of threads.
const BLOCK: usize = 4096;

impl<'a> HistoryProblem<'a> {
    /// Plan the operator (once for the path) and return the stepper at the unloaded,
    /// traction-free state.
    ///
    /// # Errors
    /// As [`TensorConvolution::new`] (or [`TensorConvolution::periodic`]).
    pub fn start(&self) -> Result<LoadHistory<'a>> {
        let c = stickslip_lattice::Compliance::pair(&self.bodies[0], &self.bodies[1]);
        let op = match &self.periodic {
            Some(lattice) => TensorConvolution::periodic(self.grid, &c, lattice)?,
            None => TensorConvolution::new(self.grid, &c, self.model)?,
        };
        let scratch = op.make_scratch();
        let n = self.grid.len();
        let e = (self.angle.cos(), self.angle.sin());
        let fixed = match self.directions {
            HistoryDirections::Free => None,
            HistoryDirections::Line => Some(vec![e; n]),
        };
        Ok(LoadHistory {
            problem: self.clone(),
            grid: self.grid.clone(),
            op,
            scratch,
            fixed,
            centre: self.centre,
            pressure_prev: vec![0.0; n],
            traction: vec![(0.0, 0.0); n],
            kq: vec![(0.0, 0.0); n],
            coupled: vec![(0.0, 0.0); n],
            state: vec![ElementState::Stick; n],
            slip: vec![(0.0, 0.0); n],
            dissipation: vec![0.0; n],
            extent: vec![[0.0; 2 * SLIP_RANGE_DIRECTIONS]; n],
            shift: (0.0, 0.0),
            rotation: 0.0,
            force: (0.0, 0.0),
            moment: 0.0,
            last_increment: ((0.0, 0.0), 0.0),
            last_dir: (0.0, 0.0),
            last_increment_load: (0.0, 0.0),
            dq: vec![(0.0, 0.0); n],
            stiffness: None,
            dissipated: 0.0,
            work: 0.0,
            steps: Vec::new(),
            virgin: true,
        })
    }
}

/// The path state and the operator: solves one step after another
/// ([`LoadHistory::step`]). It holds the previous traction, $K\mathbf q$, the stick/slip
/// state, the pressure, the accumulated slip, its extents and the dissipation per cell (a
/// few vectors of the grid's length), and one small record per step: never a step's
/// fields.
#[derive(Debug)]
pub struct LoadHistory<'a> {
    problem: HistoryProblem<'a>,
    grid: ContactGrid,
    op: TensorConvolution,
    scratch: ConvScratch,
    fixed: Option<Vec<(f64, f64)>>,
    centre: Option<(f64, f64)>,
    pressure_prev: Vec<f64>,
    traction: Vec<(f64, f64)>,
    kq: Vec<(f64, f64)>,
    /// The pressure's tangential displacement $K^{tn}p$ of the last step (Dundurs coupling;
    /// zero without it).
    coupled: Vec<(f64, f64)>,
    state: Vec<ElementState>,
    slip: Vec<(f64, f64)>,
    dissipation: Vec<f64>,
    extent: Vec<[f64; 2 * SLIP_RANGE_DIRECTIONS]>,
    shift: (f64, f64),
    rotation: f64,
    force: (f64, f64),
    moment: f64,
    last_increment: ((f64, f64), f64),
    last_dir: (f64, f64),
    last_increment_load: (f64, f64),
    dq: Vec<(f64, f64)>,
    stiffness: Option<f64>,
    dissipated: f64,
    work: f64,
    steps: Vec<HistoryStep>,
    virgin: bool,
}

/// One solved pass of a step, not yet part of the path state ([`LoadHistory::trial`]).
#[derive(Debug, Clone)]
pub struct StepTrial {
    sol: FastSolution,
    target: StepTarget,
    dir: (f64, f64),
    centre: (f64, f64),
    pressure: Vec<f64>,
    coupled: Option<Vec<(f64, f64)>>,
    u0: Option<Vec<(f64, f64)>>,
    tally: Tally,
    t0: Instant,
}

impl StepTrial {
    /// The pass's fast solution (traction per grid cell, slip increment, rigid motion).
    #[must_use]
    pub fn solution(&self) -> &FastSolution {
        &self.sol
    }

    /// The pass's traction per grid cell (Pa).
    #[must_use]
    pub fn traction(&self) -> &[(f64, f64)] {
        &self.sol.traction
    }

    /// The pressure per grid cell the pass was solved with (Pa).
    #[must_use]
    pub fn pressure(&self) -> &[f64] {
        &self.pressure
    }

    /// Count an earlier pass's solves, Newton steps and products in this one's (the step's
    /// record sums them over its passes), and start its clock at the earlier one's.
    pub(super) fn absorb(&mut self, earlier: &StepTrial) {
        self.tally.solves += earlier.tally.solves;
        self.tally.newton += earlier.tally.newton;
        self.tally.products += earlier.tally.products;
        self.t0 = earlier.t0.min(self.t0);
    }
}

impl LoadHistory<'_> {
    /// Solve one step (module docs): `pressure` per grid cell (Pa; `None` keeps the
    /// previous step's, or the grid's at the first step), `target` the loads to reach.
    /// The same as [`LoadHistory::trial`] without coupling, then [`LoadHistory::accept`].
    ///
    /// # Errors
    /// As [`LoadHistory::trial`]. After an error the state is that of the last solved step.
    pub fn step(&mut self, pressure: Option<&[f64]>, target: StepTarget) -> Result<&HistoryStep> {
        let trial = self.trial(pressure, target, None, None)?;
        Ok(self.accept(trial, 1, (0.0, 0.0)))
    }

    /// Solve one step without taking it into the path state: the pass of a coupled step
    /// (module docs, "Dissimilar bodies"), repeated with updated pressures until the pressure
    /// and the traction agree, then [`LoadHistory::accept`]ed.
    ///
    /// `coupled` is the tangential displacement $K^{tn}p^n$ of this step's pressure per grid
    /// cell (m; Dundurs coupling of dissimilar bodies): the step's slip then counts its change
    /// since the last step, $\mathbf u^0 = K^{tn}p^n - (K\mathbf q^{n-1} + K^{tn}p^{n-1})$.
    /// `None`: no coupling term (identical bodies), exactly the uncoupled step. `warm`, if
    /// given, is tried first (the previous pass's solution), then the usual starts.
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] for a pressure or coupling of the wrong length;
    /// [`Error::OutOfDomain`] for a negative or non-finite pressure, a non-finite coupling
    /// displacement, a step without normal force, a non-finite target, or a moment where
    /// none is allowed ([`HistoryProblem::run`]); the fast solver's errors (a force beyond
    /// the capacity: [`Error::CapacityExceeded`]). The state is unchanged in any case.
    pub fn trial(
        &mut self,
        pressure: Option<&[f64]>,
        target: StepTarget,
        coupled: Option<&[(f64, f64)]>,
        warm: Option<&WarmStart>,
    ) -> Result<StepTrial> {
        let t0 = Instant::now();
        let n = self.grid.len();
        if !target.tangential.is_finite() || target.moment.is_some_and(|m| !m.is_finite()) {
            return Err(Error::OutOfDomain {
                name: "history step load",
                value: target.tangential,
                allowed: "finite",
            });
        }
        if let Some(m) = target.moment {
            self.problem.check_moment_allowed(target.control, m)?;
        }
        if let Some(c) = coupled {
            if c.len() != n {
                return Err(Error::LengthMismatch {
                    name: "history coupling displacement (one per grid cell)",
                    expected: n,
                    got: c.len(),
                });
            }
            if let Some(v) = c.iter().map(|v| v.0.hypot(v.1)).find(|v| !v.is_finite()) {
                return Err(Error::OutOfDomain {
                    name: "history coupling displacement",
                    value: v,
                    allowed: "finite",
                });
            }
        }
        if let Some(p) = pressure {
            if p.len() != n {
                return Err(Error::LengthMismatch {
                    name: "history pressure (one per grid cell)",
                    expected: n,
                    got: p.len(),
                });
            }
            if let Some(&v) = p.iter().find(|v| !(v.is_finite() && **v >= 0.0)) {
                return Err(Error::OutOfDomain {
                    name: "history cell pressure",
                    value: v,
                    allowed: "finite and >= 0",
                });
            }
        }
        let previous = std::mem::take(&mut self.grid.pressure);
        self.grid.pressure = pressure.map_or_else(|| previous.clone(), <[f64]>::to_vec);
        let normal = self.grid.total_normal_force();
        if normal.is_nan() || normal <= 0.0 {
            self.grid.pressure = previous;
            return Err(Error::OutOfDomain {
                name: "normal force of the step",
                value: normal,
                allowed: "> 0 (the bodies must touch)",
            });
        }
        let centre = self.centre.unwrap_or_else(|| self.grid.force_centroid());
        let e = (self.problem.angle.cos(), self.problem.angle.sin());
        let dot = |v: (f64, f64)| v.0 * e.0 + v.1 * e.1;

        // The increment to apply (shift control prescribes the shift still missing), and
        // the direction of the prescribed loads' change since the last step (from the
        // prescribed values: the solved ones differ by the tolerance, noise on a hold).
        let inc = match target.control {
            PathControl::Force => target.tangential - dot(self.force),
            PathControl::Shift => target.tangential - dot(self.shift),
        };
        let last = self.steps.last();
        let dir_t = match last {
            Some(l) if l.control == target.control => target.tangential - l.target,
            _ => inc,
        };
        let dir_m = match (target.moment, last.and_then(|l| l.target_moment)) {
            (Some(m), Some(lm)) => m - lm,
            (Some(m), None) => m - self.moment,
            _ => 0.0,
        };
        // Warm starts, tried in order until one converges: the caller's (a coupled step's
        // previous pass); after a reversal of a prescribed load all stick (a reversed step
        // starts by sticking everywhere), otherwise the previous state; then the other of the
        // two; then the solver's own cold start.
        let turned = |inc: f64, last: f64| inc != 0.0 && last != 0.0 && inc.signum() != last;
        let reversal = turned(dir_t, self.last_dir.0) || turned(dir_m, self.last_dir.1);
        let continuing = self.predicted_start(dir_t, dir_m);
        let sticking = WarmStart {
            traction: self.traction.clone(),
            shift: (0.0, 0.0),
            rotation: 0.0,
            state: Vec::new(),
        };
        // The prescribed displacement: minus the last step's total tangential displacement
        // (elastic and, coupled, the pressure's), plus this step's pressure's share.
        let u0: Option<Vec<(f64, f64)>> = match (self.virgin, coupled) {
            (true, None) => None,
            (true, Some(c)) => Some(c.to_vec()),
            (false, None) => Some(self.kq.iter().map(|v| (-v.0, -v.1)).collect()),
            (false, Some(c)) => Some(
                self.kq
                    .iter()
                    .zip(c)
                    .zip(&self.coupled)
                    .map(|((k, c), c0)| (-k.0 + (c.0 - c0.0), -k.1 + (c.1 - c0.1)))
                    .collect(),
            ),
        };
        let mut starts: Vec<Option<&WarmStart>> = Vec::with_capacity(4);
        if let Some(w) = warm {
            starts.push(Some(w));
        }
        if self.virgin {
            starts.push(None);
        } else if reversal {
            starts.extend([Some(&sticking), Some(&continuing), None]);
        } else {
            starts.extend([Some(&continuing), Some(&sticking), None]);
        }
        let ctx = Ctx {
            grid: &self.grid,
            p: &self.problem,
            op: &self.op,
            fixed: &self.fixed,
            centre,
            increment: !self.virgin,
        };
        let mut tally = Tally::default();
        let solved = match target.control {
            PathControl::Force => ctx.solve_force(
                &mut self.scratch,
                target.tangential,
                target.moment,
                u0.as_deref(),
                &starts,
                &mut tally,
            ),
            PathControl::Shift => ctx.solve_shift(
                &mut self.scratch,
                inc,
                u0.as_deref(),
                &starts,
                dot(self.force),
                self.stiffness,
                &mut tally,
            ),
        };
        let step_pressure = std::mem::replace(&mut self.grid.pressure, previous);
        Ok(StepTrial {
            sol: solved?,
            target,
            dir: (dir_t, dir_m),
            centre,
            pressure: step_pressure,
            coupled: coupled.map(<[(f64, f64)]>::to_vec),
            u0,
            tally,
            t0,
        })
    }

    /// Take a solved pass into the path state and record the step, with the number of
    /// coupling passes it took and the coupling residual and pressure change
    /// ([`HistoryStep::coupling_residual`], [`HistoryStep::coupling_pressure_change`]; 1,
    /// 0 and 0 for an uncoupled step).
    pub fn accept(
        &mut self,
        trial: StepTrial,
        passes: usize,
        (coupling_residual, pressure_change): (f64, f64),
    ) -> &HistoryStep {
        let previous = std::mem::replace(&mut self.grid.pressure, trial.pressure);
        self.pressure_prev = previous;
        if self.centre.is_none() {
            self.centre = Some(trial.centre);
        }
        if let Some(c) = trial.coupled {
            self.coupled = c;
        }
        self.commit(
            &trial.sol,
            trial.u0.as_deref(),
            trial.target,
            trial.dir,
            trial.centre,
            (trial.tally, passes, coupling_residual, pressure_change),
            trial.t0,
        );
        self.steps.last().expect("a step was just recorded")
    }

    /// The start of a step that continues in the direction of the last one: the tractions
    /// extrapolated linearly from the last increment, scaled by the ratio of the prescribed
    /// increments, $\mathbf q^{n-1} + r\,(\mathbf q^{n-1} - \mathbf q^{n-2})$; cells whose
    /// extrapolated traction reaches their disc start slipping, the others sticking. (From
    /// the previous state alone the first Newton step keeps last step's stick zone and
    /// leaves a residual of about the load increment, 4e-2 at 128 cells across.)
    fn predicted_start(&self, dir_t: f64, dir_m: f64) -> WarmStart {
        let (lt, lm) = self.last_increment_load;
        let r = if lt != 0.0 {
            dir_t / lt
        } else if lm != 0.0 {
            dir_m / lm
        } else {
            0.0
        };
        let r = if r.is_finite() { r.clamp(0.0, 4.0) } else { 0.0 };
        let f = self.problem.friction;
        let (traction, state) = self
            .traction
            .par_iter()
            .zip(&self.dq)
            .zip(&self.grid.pressure)
            .map(|((q, d), p)| {
                let t = (q.0 + r * d.0, q.1 + r * d.1);
                let slips = t.0.hypot(t.1) >= f * p && *p > 0.0;
                (t, if slips { ElementState::Slip } else { ElementState::Stick })
            })
            .unzip();
        WarmStart {
            traction,
            shift: (r * self.last_increment.0 .0, r * self.last_increment.0 .1),
            rotation: r * self.last_increment.1,
            state,
        }
    }

    /// Take a solved step into the path state and record it.
    #[allow(clippy::too_many_arguments)]
    fn commit(
        &mut self,
        sol: &FastSolution,
        u0: Option<&[(f64, f64)]>,
        target: StepTarget,
        dir: (f64, f64),
        centre: (f64, f64),
        (tally, passes, coupling_residual, pressure_change): (Tally, usize, f64, f64),
        t0: Instant,
    ) {
        let n = self.grid.len();
        let area = self.grid.element_area();
        let theta = self.problem.angle;
        let dirs: [(f64, f64); SLIP_RANGE_DIRECTIONS] = std::array::from_fn(|j| {
            let a = theta + PI * j as f64 / SLIP_RANGE_DIRECTIONS as f64;
            (a.cos(), a.sin())
        });
        // The per-cell updates in parallel over fixed blocks of cells, the block sums added
        // in order (the same bits whatever the number of threads).
        let (traction, pressure, prev) = (&self.traction, &self.grid.pressure, &self.pressure_prev);
        let parts: Vec<(f64, usize, usize)> = self
            .dissipation
            .par_chunks_mut(BLOCK)
            .zip(self.slip.par_chunks_mut(BLOCK).zip(self.extent.par_chunks_mut(BLOCK)))
            .enumerate()
            .map(|(b, (diss, (slip, extent)))| {
                let (mut dd, mut contact, mut stick) = (0.0, 0usize, 0usize);
                for (o, (dk, (s, ext))) in
                    diss.iter_mut().zip(slip.iter_mut().zip(extent.iter_mut())).enumerate()
                {
                    let k = b * BLOCK + o;
                    let (q0, q1, ds) = (traction[k], sol.traction[k], sol.slip[k]);
                    let now = pressure[k] > 0.0;
                    if now || prev[k] > 0.0 {
                        let d = 0.5 * ((q0.0 + q1.0) * ds.0 + (q0.1 + q1.1) * ds.1);
                        *dk += d;
                        dd += d;
                    }
                    if now {
                        contact += 1;
                        if sol.state[k] == ElementState::Stick {
                            stick += 1;
                        }
                        s.0 += ds.0;
                        s.1 += ds.1;
                        for (j, d) in dirs.iter().enumerate() {
                            let v = s.0 * d.0 + s.1 * d.1;
                            ext[2 * j] = ext[2 * j].min(v);
                            ext[2 * j + 1] = ext[2 * j + 1].max(v);
                        }
                    }
                }
                (dd, contact, stick)
            })
            .collect();
        let (dd, contact, stick) =
            parts.iter().fold((0.0, 0, 0), |a, b| (a.0 + b.0, a.1 + b.1, a.2 + b.2));
        let rotating = target.moment.is_some();
        let (f0, m0) = (self.force, self.moment);
        let (f1, m1) = (sol.resultant, if rotating { sol.moment } else { 0.0 });
        let drot = if rotating { sol.rotation } else { 0.0 };
        let dw = 0.5 * ((f0.0 + f1.0) * sol.shift.0 + (f0.1 + f1.1) * sol.shift.1)
            + 0.5 * (m0 + m1) * drot;
        // K q^n for the next step's prescribed displacement and the stored energy: the
        // solver's displacement is K q^n + u0 (u0 = -K q^(n-1) uncoupled; the first step
        // uncoupled has none), so K q^n comes without another product.
        let u2: f64 = self
            .kq
            .par_chunks_mut(BLOCK)
            .enumerate()
            .map(|(b, kq)| {
                let mut u2 = 0.0;
                for (o, kq) in kq.iter_mut().enumerate() {
                    let k = b * BLOCK + o;
                    let (u, q) = (sol.displacement[k], sol.traction[k]);
                    *kq = match u0 {
                        None => u,
                        Some(u0) => (u.0 - u0[k].0, u.1 - u0[k].1),
                    };
                    u2 += q.0 * kq.0 + q.1 * kq.1;
                }
                u2
            })
            .collect::<Vec<f64>>()
            .iter()
            .sum();
        let e = (theta.cos(), theta.sin());
        let dot = |v: (f64, f64)| v.0 * e.0 + v.1 * e.1;
        let dtan = dot(f1) - dot(f0);
        let dshift = dot(sol.shift);
        if dtan != 0.0 && dshift != 0.0 && dtan / dshift > 0.0 && sol.regime != Regime::GrossSlip {
            self.stiffness = Some(dtan / dshift);
        }
        self.dq.par_iter_mut().zip(&self.traction).zip(&sol.traction).for_each(|((d, a), b)| {
            *d = (b.0 - a.0, b.1 - a.1);
        });
        self.last_increment_load = dir;
        self.traction.clone_from(&sol.traction);
        self.state.clone_from(&sol.state);
        self.shift = (self.shift.0 + sol.shift.0, self.shift.1 + sol.shift.1);
        self.rotation += drot;
        self.force = f1;
        // The moment about the history's centre, also when none is prescribed.
        self.moment = if rotating {
            m1
        } else {
            let (x, y, q) = (&self.grid.x, &self.grid.y, &sol.traction);
            (0..n.div_ceil(BLOCK))
                .into_par_iter()
                .map(|b| {
                    (b * BLOCK..((b + 1) * BLOCK).min(n))
                        .map(|k| area * ((x[k] - centre.0) * q[k].1 - (y[k] - centre.1) * q[k].0))
                        .sum::<f64>()
                })
                .collect::<Vec<f64>>()
                .iter()
                .sum()
        };
        self.last_increment = (sol.shift, drot);
        if dir.0 != 0.0 {
            self.last_dir.0 = dir.0.signum();
        }
        if dir.1 != 0.0 {
            self.last_dir.1 = dir.1.signum();
        }
        self.dissipated += dd * area;
        self.work += dw;
        self.virgin = false;
        self.steps.push(HistoryStep {
            control: target.control,
            target: target.tangential,
            tangential: dot(f1),
            force: f1,
            normal: self.grid.total_normal_force(),
            moment: self.moment,
            target_moment: target.moment,
            shift: dot(self.shift),
            shift_vector: self.shift,
            rotation: self.rotation,
            stick_fraction: if contact > 0 { stick as f64 / contact as f64 } else { 0.0 },
            contact_cells: contact,
            dissipated: self.dissipated,
            work: self.work,
            elastic_energy: 0.5 * area * u2,
            regime: sol.regime,
            solves: tally.solves,
            newton_iterations: tally.newton,
            products: tally.products,
            residual: sol.info.residual.max(sol.info.load_residual),
            coupling_passes: passes,
            coupling_residual,
            coupling_pressure_change: pressure_change,
            seconds: t0.elapsed().as_secs_f64(),
        });
    }

    /// The records of the steps solved so far.
    #[must_use]
    pub fn steps(&self) -> &[HistoryStep] {
        &self.steps
    }

    /// The current traction per cell (Pa).
    #[must_use]
    pub fn traction(&self) -> &[(f64, f64)] {
        &self.traction
    }

    /// The stick/slip state of the last step per cell.
    #[must_use]
    pub fn state(&self) -> &[ElementState] {
        &self.state
    }

    /// The current pressure per cell (Pa).
    #[must_use]
    pub fn pressure(&self) -> &[f64] {
        &self.grid.pressure
    }

    /// The accumulated slip per cell (m).
    #[must_use]
    pub fn slip(&self) -> &[(f64, f64)] {
        &self.slip
    }

    /// The energy dissipated per unit area so far, per cell (J/m²).
    #[must_use]
    pub fn dissipation(&self) -> &[f64] {
        &self.dissipation
    }

    /// The slip range per cell so far (m): the largest extent of the accumulated slip over
    /// the [`SLIP_RANGE_DIRECTIONS`] tracked directions (module docs).
    #[must_use]
    pub fn slip_range(&self) -> Vec<f64> {
        self.extent.iter().map(|e| e.chunks(2).map(|c| c[1] - c[0]).fold(0.0, f64::max)).collect()
    }

    /// The fixed centre of rotation (set at the first step).
    #[must_use]
    pub fn centre(&self) -> Option<(f64, f64)> {
        self.centre
    }

    /// The loops found so far ([`find_loops`]).
    #[must_use]
    pub fn loops(&self) -> Vec<HistoryLoop> {
        find_loops(&self.steps)
    }

    /// The outcome: records, loops, final fields.
    #[must_use]
    pub fn into_outcome(self) -> HistoryOutcome {
        HistoryOutcome {
            loops: self.loops(),
            slip_range: self.slip_range(),
            steps: self.steps,
            traction: self.traction,
            state: self.state,
            pressure: self.grid.pressure,
            slip: self.slip,
            dissipation: self.dissipation,
        }
    }
}
