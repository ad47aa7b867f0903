//! One contract for the grid solvers: a [`GridProblem`] (contact grid, the two bodies,
//! friction coefficient, influence model, tolerance) and a [`Load`] go in, a [`GridSolution`]
//! (traction, stick/slip state, slip, displacement, rigid motion) with its [`SolverInfo`]
//! (iterations, residual, tolerance, wall time) comes out, through the [`GridSolver`] trait.
//!
//! Implemented by [`ModifiedLp`] (the modified LP of seed 002 through
//! [`crate::TractionProblem`]: one traction direction per element) and [`FastSolver`] (the
//! semismooth Newton solver through [`crate::FastProblem`]: both components free on the
//! Coulomb disc). The specialised problems stay available (they expose solver-specific
//! diagnostics); the contract is a thin layer over them.
//!
//! Failures are typed [`Error`] variants a caller can match on: [`Error::CapacityExceeded`]
//! (the load is beyond what friction can carry), [`Error::NoStickLeft`] (at or near gross slip
//! the fast solver's active set left nothing to carry the load), [`Error::NotConverged`],
//! [`Error::EmptyGrid`], [`Error::ToleranceOutOfRange`], [`Error::UnsupportedLoad`].
//!
//! The contract's solvers return [`Error::CapacityExceeded`] for a load beyond the friction
//! capacity (by more than $10^{-12}$ relative) and a gross-slip solution at the capacity.
//! ([`crate::TractionProblem::solve`] itself returns a gross-slip solution with
//! [`crate::TractionSolution::excess_load`] for any load beyond it.)

use crate::error::{non_negative, positive, tolerance_in, Error, Result};
use crate::fast::{FastConfig, FastProblem, TractionDirections};
use crate::lp::LpConfig;
use crate::solve::{DirectionAssumption, ElementState, PatchSummary, Regime, TractionProblem};
use stickslip_halfspace::Material;
use stickslip_lattice::influence::InfluenceModel;
use stickslip_lattice::ContactGrid;
use stickslip_lattice::PeriodicLattice;
use stickslip_quad::Tolerance;

/// Which kind of load: used by [`Error::CapacityExceeded`] and friends to say which load to
/// reduce.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoadKind {
    /// A tangential force.
    Force,
    /// A twisting moment.
    Moment,
    /// A force and a moment together.
    Combined,
}

impl std::fmt::Display for LoadKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            LoadKind::Force => "tangential force",
            LoadKind::Moment => "twisting moment",
            LoadKind::Combined => "tangential force and twisting moment",
        })
    }
}

/// The applied tangential load. Non-exhaustive: displacement-controlled loads (a prescribed
/// rigid shift or rotation) will be added by coming solvers.
#[non_exhaustive]
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Load {
    /// A tangential force of `magnitude` $\ge 0$ along the direction at `angle` (radians from
    /// $+x$). Under the modified LP the traction is parallel to the load (seed 002 §3.3.1).
    Force {
        /// Magnitude $T \ge 0$.
        magnitude: f64,
        /// Direction angle in radians.
        angle: f64,
    },
    /// A twisting moment $M$ (counter-clockwise positive) about `centre` (`None`: the centre
    /// of the normal force), with zero net force. Under the modified LP the traction
    /// directions come from the seed's preprocessor (§3.4.1): the full-stick solution for a
    /// rigid rotation about the centre.
    Moment {
        /// Moment $M$.
        moment: f64,
        /// Centre of rotation.
        centre: Option<(f64, f64)>,
    },
    /// A force and a moment together (the fast solver only).
    ForceAndMoment {
        /// Force magnitude $T \ge 0$.
        magnitude: f64,
        /// Force direction angle in radians.
        angle: f64,
        /// Moment $M$.
        moment: f64,
        /// Centre of rotation.
        centre: Option<(f64, f64)>,
    },
}

impl Load {
    /// A force $(T_x, T_y)$ without moment.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a non-finite component.
    pub fn force(tx: f64, ty: f64) -> Result<Self> {
        finite("force T_x", tx)?;
        finite("force T_y", ty)?;
        Ok(Load::Force { magnitude: tx.hypot(ty), angle: ty.atan2(tx) })
    }

    /// A force of magnitude $T \ge 0$ at `angle` radians from $+x$.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for $T < 0$ or non-finite input.
    pub fn polar(magnitude: f64, angle: f64) -> Result<Self> {
        let load = Load::Force { magnitude, angle };
        load.validate()?;
        Ok(load)
    }

    /// A pure twisting moment $M$ about `centre` (`None`: the centre of the normal force).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for non-finite input.
    pub fn moment(moment: f64, centre: Option<(f64, f64)>) -> Result<Self> {
        let load = Load::Moment { moment, centre };
        load.validate()?;
        Ok(load)
    }

    /// Add (or replace) a twisting moment $M$ about `centre` (a zero force and a moment is a
    /// [`Load::Moment`]).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for non-finite input.
    pub fn with_moment(self, moment: f64, centre: Option<(f64, f64)>) -> Result<Self> {
        let load = match self {
            Load::Force { magnitude, angle } | Load::ForceAndMoment { magnitude, angle, .. }
                if magnitude != 0.0 =>
            {
                Load::ForceAndMoment { magnitude, angle, moment, centre }
            }
            _ => Load::Moment { moment, centre },
        };
        load.validate()?;
        Ok(load)
    }

    /// Check every number: a finite force magnitude $\ge 0$ and angle, a finite moment and
    /// centre.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] naming the offending input.
    pub fn validate(&self) -> Result<()> {
        if let Load::Force { magnitude, angle } | Load::ForceAndMoment { magnitude, angle, .. } =
            *self
        {
            non_negative("force magnitude", magnitude)?;
            finite("force angle", angle)?;
        }
        if let Load::Moment { moment, centre } | Load::ForceAndMoment { moment, centre, .. } = *self
        {
            finite("moment", moment)?;
            if let Some((x, y)) = centre {
                finite("rotation centre x", x)?;
                finite("rotation centre y", y)?;
            }
        }
        Ok(())
    }

    /// Force, moment, or both.
    #[must_use]
    pub fn kind(&self) -> LoadKind {
        match self {
            Load::Force { .. } => LoadKind::Force,
            Load::Moment { .. } => LoadKind::Moment,
            Load::ForceAndMoment { .. } => LoadKind::Combined,
        }
    }

    /// The force $(T_x, T_y) = T(\cos\theta, \sin\theta)$ ($(0, 0)$ for a pure moment).
    #[must_use]
    pub fn force_components(&self) -> (f64, f64) {
        match *self {
            Load::Force { magnitude, angle } | Load::ForceAndMoment { magnitude, angle, .. } => {
                (magnitude * angle.cos(), magnitude * angle.sin())
            }
            Load::Moment { .. } => (0.0, 0.0),
        }
    }

    /// The prescribed moment, if any.
    #[must_use]
    pub fn moment_value(&self) -> Option<f64> {
        match *self {
            Load::Force { .. } => None,
            Load::Moment { moment, .. } | Load::ForceAndMoment { moment, .. } => Some(moment),
        }
    }

    /// The prescribed centre of rotation, if any (`None`: the centre of the normal force).
    #[must_use]
    pub fn centre(&self) -> Option<(f64, f64)> {
        match *self {
            Load::Force { .. } => None,
            Load::Moment { centre, .. } | Load::ForceAndMoment { centre, .. } => centre,
        }
    }
}

fn finite(name: &'static str, v: f64) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Error::OutOfDomain { name, value: v, allowed: "finite" })
    }
}

/// The checks every grid problem makes: $f > 0$, a non-empty grid, at least one deformable
/// body.
pub(crate) fn check_pair(grid: &ContactGrid, bodies: &[Material; 2], friction: f64) -> Result<()> {
    positive("friction coefficient", friction)?;
    if grid.is_empty() {
        return Err(Error::EmptyGrid { reason: "the grid has no element" });
    }
    if bodies[0].is_rigid() && bodies[1].is_rigid() {
        return Err(Error::OutOfDomain {
            name: "bodies",
            value: f64::INFINITY,
            allowed: "at least one deformable body",
        });
    }
    Ok(())
}

/// A validated grid problem: the contact grid (lattice and pressure), the two bodies, the
/// friction coefficient, the influence model, the tolerance and an optional iteration budget.
#[derive(Debug, Clone)]
pub struct GridProblem<'a> {
    grid: &'a ContactGrid,
    bodies: [Material; 2],
    friction: f64,
    model: InfluenceModel,
    tolerance: Tolerance,
    max_iterations: Option<usize>,
    periodic: Option<PeriodicLattice>,
}

impl<'a> GridProblem<'a> {
    /// Validate $f > 0$, a non-empty grid and at least one deformable body. The influence
    /// model is [`InfluenceModel::default`], the tolerance [`Tolerance::default`] ($10^{-10}$
    /// relative), the iteration budget each solver's default.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] or [`Error::EmptyGrid`] naming the offending input.
    pub fn new(grid: &'a ContactGrid, bodies: [Material; 2], friction: f64) -> Result<Self> {
        check_pair(grid, &bodies, friction)?;
        Ok(Self {
            grid,
            bodies,
            friction,
            model: InfluenceModel::default(),
            tolerance: Tolerance::default(),
            max_iterations: None,
            periodic: None,
        })
    }

    /// The grid is one period of a periodic surface of lattice `lattice` (see
    /// [`FastProblem::with_periodic`]); only [`FastSolver`] solves it, without a moment.
    #[must_use]
    pub fn with_periodic(mut self, lattice: PeriodicLattice) -> Self {
        self.periodic = Some(lattice);
        self
    }

    /// The periodic lattice, if the surface is periodic.
    #[must_use]
    pub fn periodic(&self) -> Option<PeriodicLattice> {
        self.periodic
    }

    /// Use another influence model.
    #[must_use]
    pub fn with_model(mut self, model: InfluenceModel) -> Self {
        self.model = model;
        self
    }

    /// Request another tolerance (checked by each solver against its `TOLERANCE_RANGE`).
    #[must_use]
    pub fn with_tolerance(mut self, tolerance: Tolerance) -> Self {
        self.tolerance = tolerance;
        self
    }

    /// Limit the iterations (fast solver: Newton steps; modified LP: pivots).
    #[must_use]
    pub fn with_max_iterations(mut self, max_iterations: usize) -> Self {
        self.max_iterations = Some(max_iterations);
        self
    }

    /// The contact grid.
    #[must_use]
    pub fn grid(&self) -> &'a ContactGrid {
        self.grid
    }

    /// The two bodies.
    #[must_use]
    pub fn bodies(&self) -> &[Material; 2] {
        &self.bodies
    }

    /// The friction coefficient $f$.
    #[must_use]
    pub fn friction(&self) -> f64 {
        self.friction
    }

    /// The influence model.
    #[must_use]
    pub fn model(&self) -> InfluenceModel {
        self.model
    }

    /// The requested tolerance.
    #[must_use]
    pub fn tolerance(&self) -> Tolerance {
        self.tolerance
    }

    /// The iteration budget (`None`: the solver's default).
    #[must_use]
    pub fn max_iterations(&self) -> Option<usize> {
        self.max_iterations
    }
}

/// Termination information of a grid solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverInfo {
    /// Which solver.
    pub solver: &'static str,
    /// Outer iterations (fast solver: Newton steps; modified LP: pivots).
    pub iterations: usize,
    /// Inner iterations (fast solver: conjugate-gradient iterations; modified LP: 0).
    pub inner_iterations: usize,
    /// Relative residual reached (fast solver: the larger of the complementarity and load
    /// residuals; modified LP: the relative load residual $|g^{\mathsf T}F - L|/L$, the
    /// Coulomb and complementarity conditions holding by construction).
    pub residual: f64,
    /// The tolerance requested (the residual is at most its relative part).
    pub tolerance: Tolerance,
    /// Wall time of the set-up (influence assembly or operator planning), seconds.
    pub setup_seconds: f64,
    /// Wall time of the solve proper, seconds.
    pub solve_seconds: f64,
}

/// The solution of a grid problem.
#[derive(Debug, Clone, PartialEq)]
pub struct GridSolution {
    /// Contact regime.
    pub regime: Regime,
    /// Traction $\mathbf q_k$ of each element (stress units).
    pub traction: Vec<(f64, f64)>,
    /// Stick or slip per element.
    pub state: Vec<ElementState>,
    /// Slip $\mathbf s_k = \mathbf w_k - \mathbf u_k$ (rigid motion minus elastic
    /// displacement; for the modified LP along the element's traction direction).
    pub slip: Vec<(f64, f64)>,
    /// Relative elastic displacement $\mathbf u_k$ (for the modified LP its component along
    /// the element's traction direction, the only one that model computes).
    pub displacement: Vec<(f64, f64)>,
    /// Rigid shift $\boldsymbol\delta$ of the two bodies (for gross slip: at the onset).
    pub shift: (f64, f64),
    /// Rigid rotation $\omega$ about [`GridSolution::centre`] (0 without a moment).
    pub rotation: f64,
    /// Centre of rotation (the load's, or the centre of the normal force).
    pub centre: (f64, f64),
    /// Resultant force $h_xh_y\sum_k\mathbf q_k$.
    pub resultant: (f64, f64),
    /// Moment of the traction about [`GridSolution::centre`].
    pub moment: f64,
    /// The rigid motion split per body, [substrate, indenter], when the solver computes the
    /// split itself (the modified LP: shift along the force, or rotation); otherwise
    /// [`GridSolution::substrate_share`] gives it.
    pub rigid_per_body: Option<[f64; 2]>,
    /// The period of a periodic surface the solution was solved on (`None`: an isolated
    /// contact); [`GridSolution::substrate_share`] uses the same operator.
    pub periodic: Option<PeriodicLattice>,
    /// Termination information.
    pub info: SolverInfo,
}

impl GridSolution {
    /// The substrate's share of the rigid shift (`force`) or rotation (`!force`):
    /// $\sum_{stick} \mathbf m\cdot\mathbf u^{(1)}_k / \sum_{stick} \mathbf m\cdot\mathbf u_k$,
    /// with $\mathbf m$ the unit direction of the shift (force) or
    /// $\hat z\times(\mathbf x_k-\mathbf c)/|\mathbf x_k-\mathbf c|^2$ (moment),
    /// $\mathbf u^{(1)}$ the substrate's own displacement under the solution's traction
    /// and $\mathbf u$ the relative one: on the stick zone $\mathbf u$ is the rigid motion,
    /// so this is the per-body mean (FORMULAS.md F: $A = A^{(1)} + A^{(2)}$). Exactly 1 under
    /// a rigid indenter, 0 on a rigid substrate, 1/2 for `identical` bodies; otherwise one
    /// FFT product of the substrate's influence coefficients.
    ///
    /// # Errors
    /// The operator's errors (an empty grid).
    pub fn substrate_share(
        &self,
        grid: &ContactGrid,
        bodies: &[Material; 2],
        identical: bool,
        force: bool,
    ) -> Result<f64> {
        if bodies[1].is_rigid() {
            return Ok(1.0);
        }
        if bodies[0].is_rigid() {
            return Ok(0.0);
        }
        if identical {
            return Ok(0.5);
        }
        let op = match &self.periodic {
            Some(lattice) => stickslip_lattice::TensorConvolution::periodic(
                grid,
                &bodies[0].compliance(),
                lattice,
            )?,
            None => stickslip_lattice::TensorConvolution::new(
                grid,
                &bodies[0].compliance(),
                InfluenceModel::default(),
            )?,
        };
        let mut scratch = op.make_scratch();
        let n = grid.len();
        let qx: Vec<f64> = self.traction.iter().map(|q| q.0).collect();
        let qy: Vec<f64> = self.traction.iter().map(|q| q.1).collect();
        let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
        op.apply(&qx, &qy, &mut ux, &mut uy, &mut scratch);
        let (c, s) = {
            let t = self.shift.0.hypot(self.shift.1);
            if t > 0.0 {
                (self.shift.0 / t, self.shift.1 / t)
            } else {
                (1.0, 0.0)
            }
        };
        let any_stick = self.state.contains(&ElementState::Stick);
        let (mut own, mut all) = (0.0, 0.0);
        for k in 0..n {
            if any_stick && self.state[k] != ElementState::Stick {
                continue;
            }
            let m = if force {
                (c, s)
            } else {
                let (dx, dy) = (grid.x[k] - self.centre.0, grid.y[k] - self.centre.1);
                let r2 = dx * dx + dy * dy;
                if r2 == 0.0 {
                    continue;
                }
                (-dy / r2, dx / r2)
            };
            own += m.0 * ux[k] + m.1 * uy[k];
            all += m.0 * self.displacement[k].0 + m.1 * self.displacement[k].1;
        }
        Ok(if all != 0.0 { own / all } else { 0.5 })
    }

    /// Per patch of `grid` (in the order of [`ContactGrid::patch`]): the force carried,
    /// $\sum_k |\mathbf q_k| h_xh_y$, the capacity $\sum_k f p_k h_xh_y$, the
    /// force-weighted centre, the element count and the slipping elements.
    pub fn patch_summaries(&self, grid: &ContactGrid, friction: f64) -> Vec<PatchSummary> {
        let area = grid.element_area();
        let n = grid.len();
        let npatch = grid.patch.iter().copied().max().map_or(0, |m| m + 1);
        (0..npatch)
            .map(|p| {
                let (mut s, mut sx, mut sy, mut cap) = (0.0, 0.0, 0.0, 0.0);
                let (mut elements, mut slipping) = (0, 0);
                for k in (0..n).filter(|&k| grid.patch[k] == p) {
                    let f = self.traction[k].0.hypot(self.traction[k].1) * area;
                    s += f;
                    sx += f * grid.x[k];
                    sy += f * grid.y[k];
                    cap += friction * grid.pressure[k] * area;
                    elements += 1;
                    slipping += usize::from(self.state[k] == ElementState::Slip);
                }
                let centre = if s > 0.0 { (sx / s, sy / s) } else { (f64::NAN, f64::NAN) };
                PatchSummary { force: s, capacity: cap, centre, elements, slipping }
            })
            .collect()
    }
}

/// A grid solver: problem and load in, solution and termination information out.
pub trait GridSolver {
    /// The solver's name (as in its errors).
    fn name(&self) -> &'static str;

    /// The relative tolerances it supports, inclusive (the absolute part must be 0).
    fn tolerance_range(&self) -> (f64, f64);

    /// Solve `problem` under `load`.
    ///
    /// # Errors
    /// [`Error::ToleranceOutOfRange`], [`Error::CapacityExceeded`], [`Error::NotConverged`],
    /// [`Error::UnsupportedLoad`], [`Error::NoStickLeft`] (fast solver),
    /// [`Error::OutOfDomain`] for an invalid load, and the specialised solvers' errors.
    fn solve(&self, problem: &GridProblem<'_>, load: &Load) -> Result<GridSolution>;
}

/// The modified LP of seed 002 (Fig. 3.5) as a [`GridSolver`], through
/// [`TractionProblem`]: one traction direction per element (parallel to a force; from the
/// full-stick solution for a moment). Force or moment, not both.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ModifiedLp {
    /// The simplex tolerances (`max_pivots` is overridden by
    /// [`GridProblem::max_iterations`] when set).
    pub config: LpConfig,
}

impl ModifiedLp {
    /// The solver's name.
    pub const NAME: &'static str = "modified LP";

    /// Supported relative tolerances: the simplex is a finite method whose phase 1 stops at
    /// an artificial sum below `feasibility_tol` ($10^{-11}$) of the scaled right-hand side,
    /// so the load balance holds to about $10^{-11}$; a request below $10^{-10}$ cannot be
    /// promised, and above $10^{-1}$ is not meaningful.
    pub const TOLERANCE_RANGE: (f64, f64) = (1e-10, 1e-1);
}

impl GridSolver for ModifiedLp {
    fn name(&self) -> &'static str {
        Self::NAME
    }

    fn tolerance_range(&self) -> (f64, f64) {
        Self::TOLERANCE_RANGE
    }

    fn solve(&self, problem: &GridProblem<'_>, load: &Load) -> Result<GridSolution> {
        if problem.periodic.is_some() {
            return Err(Error::OutOfDomain {
                name: "periodic surface for the modified LP",
                value: 1.0,
                allowed: "an isolated contact (the LP's influence matrix has no periodic images); use the fast solver",
            });
        }
        let tol = tolerance_in(Self::NAME, problem.tolerance, Self::TOLERANCE_RANGE)?;
        let mut config = self.config;
        if let Some(m) = problem.max_iterations {
            config.max_pivots = Some(m);
        }
        let grid = problem.grid;
        let s = TractionProblem::new(grid, problem.bodies, problem.friction, *load)?
            .with_model(problem.model)
            .with_lp_config(config)
            .solve()?;
        let requested = match *load {
            Load::Force { magnitude, .. } => magnitude,
            Load::Moment { moment, .. } => moment.abs(),
            Load::ForceAndMoment { .. } => {
                return Err(Error::UnsupportedLoad { solver: Self::NAME, load: load.kind() })
            }
        };
        if s.excess_load > 1e-12 * s.capacity {
            return Err(Error::CapacityExceeded {
                load: load.kind(),
                requested,
                capacity: s.capacity,
            });
        }
        let carried: f64 = s.mode.iter().zip(&s.force).map(|(g, f)| g * f).sum();
        let residual = if requested > 0.0 { (carried - requested).abs() / requested } else { 0.0 };
        if residual > tol {
            return Err(Error::NotConverged {
                solver: Self::NAME,
                iterations: s.info.iterations,
                residual,
                tolerance: tol,
            });
        }
        let along = |v: &[f64]| -> Vec<(f64, f64)> {
            v.iter().zip(&s.direction).map(|(a, d)| (a * d.0, a * d.1)).collect()
        };
        let traction = along(&s.traction);
        let (shift, rotation, centre) = match s.assumption {
            DirectionAssumption::ParallelToLoad { angle } => {
                ((s.rigid * angle.cos(), s.rigid * angle.sin()), 0.0, grid.force_centroid())
            }
            DirectionAssumption::FromFullStick { centre, .. } => ((0.0, 0.0), s.rigid, centre),
        };
        let (qx, qy): (Vec<f64>, Vec<f64>) = traction.iter().copied().unzip();
        let (resultant, moment) = crate::fast::resultant_moment(grid, &qx, &qy, centre);
        Ok(GridSolution {
            regime: s.regime,
            state: s.state.clone(),
            slip: along(&s.slip),
            displacement: along(&s.displacement),
            traction,
            shift,
            rotation,
            centre,
            resultant,
            moment,
            rigid_per_body: Some(s.rigid_per_body),
            periodic: None,
            info: SolverInfo {
                solver: Self::NAME,
                iterations: s.info.iterations,
                inner_iterations: 0,
                residual,
                tolerance: problem.tolerance,
                setup_seconds: s.info.assembly_seconds,
                solve_seconds: s.info.lp_seconds,
            },
        })
    }
}

/// The fast solver (semismooth Newton with FFT products) as a [`GridSolver`], through
/// [`FastProblem`]: both traction components free on the Coulomb disc unless
/// [`FastSolver::directions`] restricts them.
#[derive(Debug, Clone, PartialEq)]
pub struct FastSolver {
    /// Admitted traction directions ([`TractionDirections::Free`] by default).
    pub directions: TractionDirections,
    /// Conjugate-gradient limit per Newton step (see [`FastConfig::with_max_cg`]).
    pub max_cg: usize,
}

impl Default for FastSolver {
    fn default() -> Self {
        Self { directions: TractionDirections::Free, max_cg: FastConfig::default().max_cg() }
    }
}

impl FastSolver {
    /// The solver's name (as in [`Error::NotConverged`]).
    pub const NAME: &'static str = crate::fast::SOLVER_NAME;
}

impl GridSolver for FastSolver {
    fn name(&self) -> &'static str {
        Self::NAME
    }

    fn tolerance_range(&self) -> (f64, f64) {
        FastConfig::TOLERANCE_RANGE
    }

    fn solve(&self, problem: &GridProblem<'_>, load: &Load) -> Result<GridSolution> {
        let max_iterations =
            problem.max_iterations.unwrap_or(FastConfig::default().max_iterations());
        let config =
            FastConfig::new(problem.tolerance, max_iterations)?.with_max_cg(self.max_cg)?;
        let mut fp = FastProblem::new(problem.grid, problem.bodies, problem.friction, *load)?
            .with_model(problem.model)
            .with_directions(self.directions.clone())?
            .with_config(config);
        if let Some(lattice) = problem.periodic {
            fp = fp.with_periodic(lattice)?;
        }
        let s = fp.solve()?;
        Ok(GridSolution {
            regime: s.regime,
            traction: s.traction,
            state: s.state,
            slip: s.slip,
            displacement: s.displacement,
            shift: s.shift,
            rotation: s.rotation,
            centre: s.centre,
            resultant: s.resultant,
            moment: s.moment,
            rigid_per_body: None,
            periodic: problem.periodic,
            info: SolverInfo {
                solver: Self::NAME,
                iterations: s.info.iterations,
                inner_iterations: s.info.cg_iterations,
                residual: s.info.residual.max(s.info.load_residual),
                tolerance: problem.tolerance,
                setup_seconds: s.info.setup_seconds,
                solve_seconds: s.info.solve_seconds,
            },
        })
    }
}
