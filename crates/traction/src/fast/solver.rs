//! The problem, configuration and result types of the fast solver (see the module
//! documentation of [`crate::fast`]); the iteration itself is in `newton.rs`.

use super::newton::Solver;
use crate::contract::{check_pair, Load};
use crate::error::{tolerance_in, Error, Result};
use crate::solve::{ElementState, Regime};
use std::time::Instant;
use stickslip_halfspace::Material;
use stickslip_lattice::influence::{Compliance, InfluenceModel};
use stickslip_lattice::ContactGrid;
use stickslip_lattice::{ConvScratch, PeriodicLattice, TensorConvolution, TensorKernel};
use stickslip_quad::Tolerance;

/// The fast solver's name, as in its errors.
pub(crate) const SOLVER_NAME: &str = "fast solver (semismooth Newton)";

/// The smallest lattice, in cells across in each direction, that [`FastProblem::solve`]
/// starts from a coarser lattice's solution: a lattice of at least twice this is coarsened
/// 2 x 2, down to between this and twice this. Below it a cold start is cheap.
pub const NEST_MIN_CELLS: usize = 48;

/// Relative residual at which the coarse levels of [`FastProblem::solve`] stop (or the
/// problem's own tolerance if looser). The start only needs the coarse active set: the fine
/// lattice's first residual is set by the discretisation difference between the lattices
/// (4.8e-3 at 512 across whether the coarse levels stop at 1e-4 or 1e-2), while the coarse
/// levels' work fell from about 10 to 3.5 fine-lattice products at 512 across (Cattaneo
/// sphere of `fast_probe`) and their time from 0.5 s to 0.3 s.
const COARSE_TOLERANCE: f64 = 1e-2;

/// Which traction directions are admitted.
#[derive(Debug, Clone, PartialEq)]
pub enum TractionDirections {
    /// Both components free on the Coulomb disc (the physical problem).
    Free,
    /// Every element's traction parallel to the force (the LP's assumption, seed 002
    /// §3.3.1); force loads only.
    ParallelToForce,
    /// Element $k$'s traction along the given direction (normalised here), e.g. the LP's
    /// twist directions [`crate::TractionSolution::direction`]. Either a force or a moment,
    /// not both.
    Fixed(Vec<(f64, f64)>),
}

/// Accuracy knob and limits of the fast solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FastConfig {
    tolerance: Tolerance,
    max_iterations: usize,
    max_cg: usize,
}

impl Default for FastConfig {
    /// Relative residual $10^{-10}$ ([`Tolerance::default`]), 100 Newton steps, 5,000 CG
    /// iterations per step.
    fn default() -> Self {
        Self { tolerance: Tolerance::default(), max_iterations: 100, max_cg: 5000 }
    }
}

impl FastConfig {
    /// The relative residual targets the solver supports, inclusive: below $10^{-14}$ the
    /// FFT products' rounding (about $10^{-15}$ relative) stops the residual from falling
    /// further; above $10^{-1}$ the active set is not settled.
    pub const TOLERANCE_RANGE: (f64, f64) = (1e-14, 1e-1);

    /// Relative residual target $\varepsilon$ = `tolerance.rel()` in
    /// [`FastConfig::TOLERANCE_RANGE`] (purely relative: `tolerance.abs() == 0`) and Newton
    /// step limit $\ge 1$.
    ///
    /// # Errors
    /// [`Error::ToleranceOutOfRange`] outside the range (never clamped);
    /// [`Error::OutOfDomain`] for `max_iterations == 0`.
    pub fn new(tolerance: Tolerance, max_iterations: usize) -> Result<Self> {
        tolerance_in(SOLVER_NAME, tolerance, Self::TOLERANCE_RANGE)?;
        if max_iterations == 0 {
            return Err(Error::OutOfDomain {
                name: "fast solver max_iterations",
                value: 0.0,
                allowed: ">= 1",
            });
        }
        Ok(Self { tolerance, max_iterations, ..Self::default() })
    }

    /// Conjugate-gradient iteration limit per Newton step ($\ge 10$).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if below 10.
    pub fn with_max_cg(mut self, max_cg: usize) -> Result<Self> {
        if max_cg < 10 {
            return Err(Error::OutOfDomain {
                name: "fast solver max_cg",
                value: max_cg as f64,
                allowed: ">= 10",
            });
        }
        self.max_cg = max_cg;
        Ok(self)
    }

    /// The relative residual target.
    #[must_use]
    pub fn tolerance(&self) -> Tolerance {
        self.tolerance
    }

    /// The Newton step limit.
    #[must_use]
    pub fn max_iterations(&self) -> usize {
        self.max_iterations
    }

    /// The conjugate-gradient limit per Newton step.
    #[must_use]
    pub fn max_cg(&self) -> usize {
        self.max_cg
    }
}

/// Diagnostics of a fast solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FastInfo {
    /// Newton (active-set) steps.
    pub iterations: usize,
    /// Conjugate-gradient iterations summed over the steps.
    pub cg_iterations: usize,
    /// FFT convolutions (operator products) performed.
    pub products: usize,
    /// Final relative complementarity residual $\lVert\mathbf r\rVert/\lVert\mathbf q\rVert$.
    pub residual: f64,
    /// Final relative residual of the load constraints.
    pub load_residual: f64,
    /// Wall time of the iteration, seconds.
    pub solve_seconds: f64,
    /// Wall time of planning the operator (kernel and FFT plans), seconds; 0 for
    /// [`FastProblem::solve_with`].
    pub setup_seconds: f64,
    /// Padded FFT size $(M_x, M_y)$.
    pub fft_size: (usize, usize),
    /// Coarser lattices solved first to start this one ([`FastProblem::solve`]'s nested
    /// start; 0 for a cold or caller-given start). Their work is included in
    /// `solve_seconds` but not in the iteration and product counts.
    pub levels: usize,
    /// Wall time of the coarser levels, seconds (part of `solve_seconds`).
    pub coarse_seconds: f64,
}

/// A starting point for [`FastProblem::solve_from`]: element tractions and the rigid motion,
/// e.g. the solution of a neighbouring load on the same grid (load paths, sweeps) or a
/// coarser lattice's solution carried to this one. It only changes where the iteration
/// starts: the converged result meets the same conditions and tolerance as a cold start.
#[derive(Debug, Clone, PartialEq)]
pub struct WarmStart {
    /// Traction of each element (clamped to the element's disc and projected on its admitted
    /// direction before use).
    pub traction: Vec<(f64, f64)>,
    /// Rigid shift of the two bodies.
    pub shift: (f64, f64),
    /// Rigid rotation about the load's centre (ignored without a moment).
    pub rotation: f64,
    /// Stick or slip of each element: the first active set (empty: every loaded element
    /// starts in stick). A slip element starts at its capacity along its start traction.
    pub state: Vec<ElementState>,
}

impl From<&FastSolution> for WarmStart {
    fn from(s: &FastSolution) -> Self {
        Self {
            traction: s.traction.clone(),
            shift: s.shift,
            rotation: s.rotation,
            state: s.state.clone(),
        }
    }
}

/// The solution of a fast solve.
#[derive(Debug, Clone, PartialEq)]
pub struct FastSolution {
    /// Contact regime.
    pub regime: Regime,
    /// Traction $\mathbf q_k$ of each element (stress units).
    pub traction: Vec<(f64, f64)>,
    /// Stick or slip per element.
    pub state: Vec<ElementState>,
    /// Slip $\mathbf s_k = \mathbf w_k - \mathbf u_k$ (projected on the element direction
    /// for fixed directions).
    pub slip: Vec<(f64, f64)>,
    /// Relative displacement $\mathbf u_k = (K*\mathbf q)_k$ (plus the prescribed
    /// $\mathbf u^0_k$ when one was given).
    pub displacement: Vec<(f64, f64)>,
    /// Rigid shift $\boldsymbol\delta$ of the two bodies (for gross slip: the value at the
    /// onset of sliding).
    pub shift: (f64, f64),
    /// Rigid rotation $\omega$ about [`FastSolution::centre`] (0 without a moment).
    pub rotation: f64,
    /// Centre of rotation used for the moment.
    pub centre: (f64, f64),
    /// Resultant force $h_xh_y\sum_k\mathbf q_k$.
    pub resultant: (f64, f64),
    /// Moment of the traction about the centre.
    pub moment: f64,
    /// Diagnostics.
    pub info: FastInfo,
}

impl FastSolution {
    /// Number of stick elements.
    #[must_use]
    pub fn stick_count(&self) -> usize {
        self.state.iter().filter(|s| **s == ElementState::Stick).count()
    }
}

/// A validated fast problem: grid, bodies, friction, load, admitted directions, influence
/// model and solver configuration.
#[derive(Debug, Clone)]
pub struct FastProblem<'a> {
    pub(super) grid: &'a ContactGrid,
    pub(super) bodies: [Material; 2],
    pub(super) friction: f64,
    pub(super) load: Load,
    pub(super) directions: TractionDirections,
    pub(super) model: InfluenceModel,
    pub(super) config: FastConfig,
    /// A prescribed relative tangential displacement $\mathbf u^0_k$ added to $K*\mathbf q$
    /// (the pressure's share under Dundurs coupling; [`FastProblem::with_prescribed_displacement`]).
    pub(super) prescribed: Option<&'a [(f64, f64)]>,
    /// The period of a periodic surface ([`FastProblem::with_periodic`]); `None`: an isolated
    /// contact (zero-padded FFT).
    pub(super) periodic: Option<PeriodicLattice>,
    /// The problem is an increment from a converged state (a load-history step,
    /// [`FastProblem::with_increment_start`]): once the load is met, its Newton steps keep it
    /// without the product of a load-correcting start.
    pub(super) increment: bool,
}

impl<'a> FastProblem<'a> {
    /// Validate $f > 0$, a non-empty grid, at least one deformable body and the load (any
    /// [`Load`]: a pure [`Load::Moment`] holds the net force at zero).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] or [`Error::EmptyGrid`] naming the offending input.
    pub fn new(
        grid: &'a ContactGrid,
        bodies: [Material; 2],
        friction: f64,
        load: Load,
    ) -> Result<Self> {
        check_pair(grid, &bodies, friction)?;
        load.validate()?;
        // Element indices are stored in 32 bits inside the solver (a grid this large would
        // not fit in memory anyway).
        if grid.len() > u32::MAX as usize {
            return Err(Error::OutOfDomain {
                name: "number of grid elements",
                value: grid.len() as f64,
                allowed: "at most 2^32 - 1",
            });
        }
        Ok(Self {
            grid,
            bodies,
            friction,
            load,
            directions: TractionDirections::Free,
            model: InfluenceModel::default(),
            config: FastConfig::default(),
            prescribed: None,
            periodic: None,
            increment: false,
        })
    }

    /// Add a prescribed relative tangential displacement $\mathbf u^0_k$ (m, one per grid
    /// element) to the elastic one: the slip becomes
    /// $\mathbf s_k = \mathbf w_k - (K*\mathbf q)_k - \mathbf u^0_k$. This is how the normal
    /// pressure enters the tangential problem of dissimilar bodies (Dundurs coupling,
    /// `stickslip-normal`'s Dundurs coupling): $\mathbf u^0 = K_{tn}\,p$. With it a zero load is no longer
    /// trivial (the pressure alone drives a self-equilibrated traction).
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] for a list of another length than the grid,
    /// [`Error::OutOfDomain`] for a non-finite value.
    pub fn with_prescribed_displacement(mut self, u0: &'a [(f64, f64)]) -> Result<Self> {
        if u0.len() != self.grid.len() {
            return Err(Error::LengthMismatch {
                name: "prescribed displacement",
                expected: self.grid.len(),
                got: u0.len(),
            });
        }
        if let Some(v) = u0.iter().map(|v| v.0.hypot(v.1)).find(|v| !v.is_finite()) {
            return Err(Error::OutOfDomain {
                name: "prescribed displacement",
                value: v,
                allowed: "finite",
            });
        }
        self.prescribed = Some(u0);
        Ok(self)
    }

    /// Mark the problem as a small increment from a converged state (a load-history step:
    /// the prescribed displacement carries the previous traction, the warm start is close).
    /// After its first Newton step the load is met far inside the tolerance, and the later
    /// steps keep it (no load correction, so no product for the PCG's start); the stopping
    /// test is unchanged.
    #[must_use]
    pub(crate) fn with_increment_start(mut self) -> Self {
        self.increment = true;
        self
    }

    /// Solve on a periodic surface: the grid's elements are cells of the lattice `lattice`
    /// (one period), and the operator is the periodic one of
    /// [`TensorConvolution::periodic`] (Fourier transfer of Cerruti's solution, mean mode
    /// zero). The rigid shift is then relative to the mean tangential displacement. A
    /// twisting moment has no meaning on a periodic surface (a rotation is not periodic) and
    /// is refused; the nested start is not used (the period need not halve).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a load with a moment.
    pub fn with_periodic(mut self, lattice: PeriodicLattice) -> Result<Self> {
        if let Some(m) = self.load.moment_value() {
            return Err(Error::OutOfDomain {
                name: "twisting moment on a periodic surface",
                value: m,
                allowed: "none: a rotation is not periodic",
            });
        }
        self.periodic = Some(lattice);
        Ok(self)
    }

    /// Restrict the traction directions (the LP's one-direction assumption).
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] for a direction list of the wrong length,
    /// [`Error::OutOfDomain`] for a zero or non-finite direction, for
    /// [`TractionDirections::ParallelToForce`] without a force or with a moment, and for
    /// fixed directions with both a force and a moment.
    pub fn with_directions(mut self, directions: TractionDirections) -> Result<Self> {
        let (tx, ty) = self.load.force_components();
        let has_force = tx != 0.0 || ty != 0.0;
        let directions = match directions {
            TractionDirections::Free => TractionDirections::Free,
            TractionDirections::ParallelToForce => {
                if !has_force || self.load.moment_value().is_some() {
                    return Err(Error::OutOfDomain {
                        name: "|T| for traction parallel to the force",
                        value: tx.hypot(ty),
                        allowed: "> 0 and no moment",
                    });
                }
                TractionDirections::ParallelToForce
            }
            TractionDirections::Fixed(d) => {
                if d.len() != self.grid.len() {
                    return Err(Error::LengthMismatch {
                        name: "fixed traction directions",
                        expected: self.grid.len(),
                        got: d.len(),
                    });
                }
                if has_force && self.load.moment_value().is_some() {
                    return Err(Error::OutOfDomain {
                        name: "moment with fixed directions and a force",
                        value: self.load.moment_value().unwrap_or(0.0),
                        allowed: "fixed directions take either a force or a moment",
                    });
                }
                let mut out = Vec::with_capacity(d.len());
                for (x, y) in d {
                    let r = x.hypot(y);
                    if !(r.is_finite() && r > 0.0) {
                        return Err(Error::OutOfDomain {
                            name: "fixed traction direction length",
                            value: r,
                            allowed: "finite and > 0",
                        });
                    }
                    out.push((x / r, y / r));
                }
                TractionDirections::Fixed(out)
            }
        };
        self.directions = directions;
        Ok(self)
    }

    /// Use another influence model.
    #[must_use]
    pub fn with_model(mut self, model: InfluenceModel) -> Self {
        self.model = model;
        self
    }

    /// Use another solver configuration.
    #[must_use]
    pub fn with_config(mut self, config: FastConfig) -> Self {
        self.config = config;
        self
    }

    /// The relative compliance constants of the pair, $c_1 = \sum_i(1-\nu_i)/G_i$,
    /// $c_2 = \sum_i\nu_i/G_i$ ([`Compliance::pair`]; FORMULAS.md F, $A = A^{(1)} + A^{(2)}$).
    #[must_use]
    pub fn compliance(&self) -> Compliance {
        Compliance::pair(&self.bodies[0], &self.bodies[1])
    }

    /// Plan the convolution operator $\mathbf u = K * \mathbf q$ of this problem (FORMULAS.md F;
    /// reusable across loads with [`FastProblem::solve_with`]).
    ///
    /// # Errors
    /// As [`TensorConvolution::new`].
    pub fn operator(&self) -> Result<TensorConvolution> {
        Ok(match &self.periodic {
            Some(lattice) => TensorConvolution::periodic(self.grid, &self.compliance(), lattice)?,
            None => TensorConvolution::new(self.grid, &self.compliance(), self.model)?,
        })
    }

    /// Plan the operator and solve the discrete problem of the [`crate::fast`] module docs
    /// (see [`FastProblem::solve_with`]).
    ///
    /// # Errors
    /// As [`FastProblem::solve_with`] and [`TensorConvolution::new`].
    ///
    /// On lattices of at least [`NEST_MIN_CELLS`] cells across in both directions (free or
    /// force-parallel directions) the iteration starts from the solution of the same problem
    /// on the lattice coarsened 2 x 2 (itself solved the same way): the active set is then
    /// nearly right, and the fine lattice needs a few Newton steps instead of creeping from
    /// full stick. If the coarse solve or the warm solve fails, the fine lattice is solved
    /// again from a cold start, so the nesting never turns a solvable problem into a failure.
    pub fn solve(&self) -> Result<FastSolution> {
        // On rayon's pool: the solve's loops are then split without a hand-over each.
        stickslip_lattice::on_pool(|| self.solve_here())
    }

    fn solve_here(&self) -> Result<FastSolution> {
        self.solve_nested(None)
    }

    /// [`FastProblem::solve`] on a lattice of the nested start: `finer` is the kernel of the
    /// finer lattice this one was coarsened from (None at the top).
    fn solve_nested(&self, finer: Option<&TensorKernel>) -> Result<FastSolution> {
        // The coarse levels first, so that their memory is released before this lattice's
        // operator is planned; the kernel's quadrant (3 doubles a cell of the lattice box)
        // is computed before them, once, and every level plans its operator from it.
        let t1 = Instant::now();
        let Coarse { start: nested, kernel: own, kernel_seconds } = self.coarse_start(finer);
        let coarse = t1.elapsed().as_secs_f64() - kernel_seconds;
        let t0 = Instant::now();
        let op = match finer.or(own.as_ref()) {
            // The same operator as `operator()` to the bit (`from_kernel`), without the
            // influence coefficients.
            Some(k) => TensorConvolution::from_kernel(self.grid, k).or_else(|_| self.operator())?,
            None => self.operator()?,
        };
        drop(own);
        let mut scratch = op.make_scratch();
        let setup = kernel_seconds + t0.elapsed().as_secs_f64();
        let t1 = Instant::now();
        let mut s = match &nested {
            Some((start, levels)) => match self.solve_from(&op, &mut scratch, start) {
                Ok(mut s) => {
                    s.info.levels = *levels;
                    s
                }
                Err(_) => self.solve_with(&op, &mut scratch)?,
            },
            None => self.solve_with(&op, &mut scratch)?,
        };
        s.info.setup_seconds = setup;
        s.info.coarse_seconds = coarse;
        s.info.solve_seconds = coarse + t1.elapsed().as_secs_f64();
        Ok(s)
    }

    /// The nested start of [`FastProblem::solve`]: the solution on the 2 x 2 coarsened
    /// lattice carried to this one (each element takes its coarse element's traction), and
    /// the number of levels below; no start when the lattice is too small, the directions are
    /// fixed per element, or the coarse problem fails. At the top level (`finer` None) the
    /// kernel of this lattice is computed for the coarse levels and handed back for this one.
    fn coarse_start(&self, finer: Option<&TensorKernel>) -> Coarse {
        let mut out = Coarse { start: None, kernel: None, kernel_seconds: 0.0 };
        if matches!(self.directions, TractionDirections::Fixed(_)) || self.periodic.is_some() {
            return out;
        }
        let Some((coarse, parent)) = self.grid.coarsened(NEST_MIN_CELLS) else {
            return out;
        };
        if finer.is_none() {
            let t = Instant::now();
            out.kernel = TensorConvolution::kernel(self.grid, &self.compliance(), self.model).ok();
            out.kernel_seconds = t.elapsed().as_secs_f64();
        }
        out.start = self.coarse_solve(&coarse, &parent, finer.or(out.kernel.as_ref()));
        out
    }

    /// The coarse level's solution carried to this lattice, and the levels below.
    fn coarse_solve(
        &self,
        coarse: &ContactGrid,
        parent: &[usize],
        kernel: Option<&TensorKernel>,
    ) -> Option<(WarmStart, usize)> {
        let load = match self.load {
            Load::Moment { moment, centre } => Load::Moment {
                moment,
                centre: Some(centre.unwrap_or_else(|| self.grid.force_centroid())),
            },
            Load::ForceAndMoment { magnitude, angle, moment, centre } => Load::ForceAndMoment {
                magnitude,
                angle,
                moment,
                centre: Some(centre.unwrap_or_else(|| self.grid.force_centroid())),
            },
            other => other,
        };
        // The coarse solution is only a start: its active set is settled well before the fine
        // tolerance, so coarse levels stop at a looser residual.
        let tol = self.config.tolerance().rel().max(COARSE_TOLERANCE);
        let config = FastConfig { tolerance: Tolerance::relative(tol).ok()?, ..self.config };
        // A prescribed displacement (Dundurs coupling) goes down as its mean over each coarse
        // element's children.
        let prescribed: Option<Vec<(f64, f64)>> = self.prescribed.map(|u0| {
            let mut sum = vec![(0.0, 0.0, 0usize); coarse.len()];
            for (&c, u) in parent.iter().zip(u0) {
                sum[c].0 += u.0;
                sum[c].1 += u.1;
                sum[c].2 += 1;
            }
            sum.iter().map(|&(x, y, m)| (x / m.max(1) as f64, y / m.max(1) as f64)).collect()
        });
        let problem = FastProblem {
            grid: coarse,
            load,
            config,
            prescribed: prescribed.as_deref(),
            ..self.clone()
        };
        let s = problem.solve_nested(kernel).ok()?;
        let traction = parent.iter().map(|&c| s.traction[c]).collect();
        let state = parent.iter().map(|&c| s.state[c]).collect();
        Some((
            WarmStart { traction, shift: s.shift, rotation: s.rotation, state },
            s.info.levels + 1,
        ))
    }

    /// Solve from a warm start (see [`WarmStart`]) with an operator planned by
    /// [`FastProblem::operator`] for this grid: same conditions, tolerance and errors as
    /// [`FastProblem::solve_with`].
    ///
    /// # Errors
    /// As [`FastProblem::solve_with`]; also [`Error::LengthMismatch`] if the start's traction
    /// has not one entry per element.
    pub fn solve_from(
        &self,
        op: &TensorConvolution,
        scratch: &mut ConvScratch,
        start: &WarmStart,
    ) -> Result<FastSolution> {
        // On rayon's pool, as `solve`: load paths call this once a step.
        stickslip_lattice::on_pool(|| self.solve_from_here(op, scratch, start))
    }

    fn solve_from_here(
        &self,
        op: &TensorConvolution,
        scratch: &mut ConvScratch,
        start: &WarmStart,
    ) -> Result<FastSolution> {
        if start.traction.len() != self.grid.len() {
            return Err(Error::LengthMismatch {
                name: "warm-start tractions",
                expected: self.grid.len(),
                got: start.traction.len(),
            });
        }
        if op.len() != self.grid.len() {
            return Err(Error::LengthMismatch {
                name: "operator elements",
                expected: self.grid.len(),
                got: op.len(),
            });
        }
        Solver::new(self, op, scratch).run(Some(start))
    }

    /// Solve with an operator planned by [`FastProblem::operator`] for the same grid, bodies
    /// and model (the caller's responsibility; only the element count is checked).
    ///
    /// Solves the conditions of the [`crate::fast`] module docs,
    /// $|\mathbf q_k| \le fp_k$, $\mathbf s_k = \lambda_k\mathbf q_k$ with $\lambda_k \ge 0$ and
    /// $\lambda_k(fp_k - |\mathbf q_k|) = 0$, $h_xh_y\sum_k\mathbf q_k = \mathbf T$ (and the moment
    /// if one is prescribed), by semismooth Newton on the natural residual
    /// $\mathbf r_k = \mathbf q_k - \Pi_{D_k}(\mathbf q_k + \rho\,\mathbf s_k)$ (Hüeber, Stadler &
    /// Wohlmuth 2008) with projected conjugate gradients (Gould, Hribar & Nocedal 2001); the
    /// influence operator is that of FORMULAS.md F.
    ///
    /// # Errors
    /// * [`Error::LengthMismatch`] if the operator belongs to a grid of another size;
    /// * [`Error::CapacityExceeded`] when the load exceeds the friction capacity (no
    ///   equilibrium: the bodies slide), with the load kind (force or moment), the load and
    ///   the capacity;
    /// * [`Error::NoStickLeft`] when the active set leaves no free component to carry the
    ///   load (at or near gross slip, e.g. a force and a moment that together exceed what the
    ///   contact carries);
    /// * [`Error::NotConverged`] (iterations, residual reached, tolerance) when the Newton
    ///   step limit is reached;
    /// * [`Error::NotPositiveDefinite`] if a conjugate-gradient curvature is not positive
    ///   (index: the CG iteration).
    pub fn solve_with(
        &self,
        op: &TensorConvolution,
        scratch: &mut ConvScratch,
    ) -> Result<FastSolution> {
        if op.len() != self.grid.len() {
            return Err(Error::LengthMismatch {
                name: "operator elements",
                expected: self.grid.len(),
                got: op.len(),
            });
        }
        Solver::new(self, op, scratch).run(None)
    }
}

/// What [`FastProblem::solve`]'s coarse levels hand to the fine lattice.
struct Coarse {
    /// The start and the number of levels below, if the lattice nests.
    start: Option<(WarmStart, usize)>,
    /// This lattice's kernel, computed for the levels (top level only).
    kernel: Option<TensorKernel>,
    /// Wall time of computing it, seconds (part of the set-up, not of the coarse levels).
    kernel_seconds: f64,
}

/// Resultant force and moment about `centre` of element tractions.
pub(crate) fn resultant_moment(
    g: &ContactGrid,
    qx: &[f64],
    qy: &[f64],
    centre: (f64, f64),
) -> ((f64, f64), f64) {
    let area = g.element_area();
    let (mut rx, mut ry, mut mz) = (0.0, 0.0, 0.0);
    for k in 0..g.len() {
        rx += area * qx[k];
        ry += area * qy[k];
        mz += area * ((g.x[k] - centre.0) * qy[k] - (g.y[k] - centre.1) * qx[k]);
    }
    ((rx, ry), mz)
}
