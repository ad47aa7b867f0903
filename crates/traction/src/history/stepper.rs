//! The history problem, its stepper (the path state) and the per-step record.

use super::path::{find_loops, HistoryLoop, LoadPath, PathControl};
use crate::contract::{check_pair, Load};
use crate::error::{Error, Result};
use crate::fast::{FastConfig, FastProblem, FastSolution, TractionDirections, WarmStart};
use crate::solve::{ElementState, Regime};
use std::f64::consts::PI;
use std::time::Instant;
use stickslip_halfspace::Material;
use stickslip_lattice::influence::InfluenceModel;
use stickslip_lattice::{ContactGrid, ConvScratch, TensorConvolution};

/// Number of directions along which the slip range is tracked (see the module docs).
pub const SLIP_RANGE_DIRECTIONS: usize = 8;

/// Which traction directions the history admits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HistoryDirections {
    /// Both traction components free on the Coulomb disc (the physical problem).
    Free,
    /// Every cell's traction along the path direction (the LP's one-direction assumption,
    /// seed 002 §3.3.1): the tangential problem becomes scalar, in which Masing's rule holds
    /// exactly. Not with a moment.
    Line,
}

/// The loads of one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepTarget {
    /// Force or shift control.
    pub control: PathControl,
    /// The tangential force (N) or the total rigid shift (m) along the path direction.
    pub tangential: f64,
    /// The twisting moment about the history's centre (N m), if prescribed (force control
    /// only). Without it the rotation is held at zero.
    pub moment: Option<f64>,
}

/// A contact grid, the two bodies and the friction coefficient, with the direction of the
/// tangential load: what stays fixed along a load path.
#[derive(Debug, Clone)]
pub struct HistoryProblem<'a> {
    grid: &'a ContactGrid,
    bodies: [Material; 2],
    friction: f64,
    angle: f64,
    directions: HistoryDirections,
    centre: Option<(f64, f64)>,
    model: InfluenceModel,
    config: FastConfig,
}

/// One solved step: the loads, the rigid motion, the stick fraction and the energies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HistoryStep {
    /// Force or shift control.
    pub control: PathControl,
    /// The prescribed value: the force (N, force control) or the shift (m, shift control)
    /// along the path direction.
    pub target: f64,
    /// Tangential force along the path direction, $\mathbf T\cdot\mathbf e$ (N), the
    /// resultant of the solved traction.
    pub tangential: f64,
    /// The resultant force $(T_x, T_y)$ (N).
    pub force: (f64, f64),
    /// Normal force of the step's pressure, $h_xh_y\sum_k p_k$ (N).
    pub normal: f64,
    /// Resultant moment about the history's centre (N m).
    pub moment: f64,
    /// The prescribed moment (N m), if the step had one.
    pub target_moment: Option<f64>,
    /// Rigid shift along the path direction, $\boldsymbol\delta\cdot\mathbf e$ (m), summed
    /// over the steps.
    pub shift: f64,
    /// The rigid shift $(\delta_x, \delta_y)$ (m).
    pub shift_vector: (f64, f64),
    /// Rigid rotation about the centre (rad), summed over the steps (zero without a moment).
    pub rotation: f64,
    /// Cells that do not slip in this step over the cells in contact ($p_k > 0$).
    pub stick_fraction: f64,
    /// Cells in contact.
    pub contact_cells: usize,
    /// Energy dissipated since the start of the path, $D^n$ (J; module docs).
    pub dissipated: f64,
    /// Work of the tangential loads since the start (J, trapezoidal rule):
    /// $\sum_m \tfrac12(\mathbf T^{m-1}+\mathbf T^m)\cdot\Delta\boldsymbol\delta^m +
    /// \tfrac12(M^{m-1}+M^m)\Delta\omega^m$.
    pub work: f64,
    /// Stored elastic energy of the tangential traction,
    /// $U = \tfrac12h_xh_y\,\mathbf q\cdot K\mathbf q$ (J); `work` $=$ `elastic_energy`
    /// $+$ `dissipated`.
    pub elastic_energy: f64,
    /// Full stick, partial slip or gross slip in this step.
    pub regime: Regime,
    /// Fast solves of the step (1 under force control; the trials of the search under shift
    /// control).
    pub solves: usize,
    /// Newton steps summed over the step's solves.
    pub newton_iterations: usize,
    /// Operator products summed over the step's solves.
    pub products: usize,
    /// Final relative residual of the step's solve (the larger of complementarity and load).
    pub residual: f64,
    /// Wall time of the step, seconds.
    pub seconds: f64,
}

/// Everything a solved path leaves: the per-step records, the loops, and the final fields.
#[derive(Debug, Clone, PartialEq)]
pub struct HistoryOutcome {
    /// One record per step of the path.
    pub steps: Vec<HistoryStep>,
    /// The closed loops ([`find_loops`]).
    pub loops: Vec<HistoryLoop>,
    /// Final traction per cell (Pa).
    pub traction: Vec<(f64, f64)>,
    /// Final stick/slip state per cell (of the last step).
    pub state: Vec<ElementState>,
    /// Final pressure per cell (Pa).
    pub pressure: Vec<f64>,
    /// Accumulated slip per cell (m).
    pub slip: Vec<(f64, f64)>,
    /// Energy dissipated per unit area over the whole path, per cell (J/m²).
    pub dissipation: Vec<f64>,
    /// Slip range per cell (m; module docs).
    pub slip_range: Vec<f64>,
}

impl<'a> HistoryProblem<'a> {
    /// The grid holds every cell that may be in contact along the path (its pressure is
    /// used when a step gives none); the tangential load acts along $+x$, traction
    /// directions free, the fast solver's default configuration and influence model.
    ///
    /// # Errors
    /// As the fast solver's problem: [`Error::OutOfDomain`] for $f \le 0$ or two rigid
    /// bodies, [`Error::EmptyGrid`].
    pub fn new(grid: &'a ContactGrid, bodies: [Material; 2], friction: f64) -> Result<Self> {
        check_pair(grid, &bodies, friction)?;
        Ok(Self {
            grid,
            bodies,
            friction,
            angle: 0.0,
            directions: HistoryDirections::Free,
            centre: None,
            model: InfluenceModel::default(),
            config: FastConfig::default(),
        })
    }

    /// The direction $\mathbf e = (\cos\theta, \sin\theta)$ of the tangential load (and
    /// shift), $\theta$ in radians from $+x$.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a non-finite angle.
    pub fn with_angle(mut self, angle: f64) -> Result<Self> {
        if !angle.is_finite() {
            return Err(Error::OutOfDomain {
                name: "history load angle",
                value: angle,
                allowed: "finite",
            });
        }
        self.angle = angle;
        Ok(self)
    }

    /// The admitted traction directions.
    #[must_use]
    pub fn with_directions(mut self, directions: HistoryDirections) -> Self {
        self.directions = directions;
        self
    }

    /// The centre of the moment and of the rotation, fixed along the path (default: the
    /// centre of the normal force of the first step), so that rotation increments add.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a non-finite coordinate.
    pub fn with_centre(mut self, centre: (f64, f64)) -> Result<Self> {
        if !(centre.0.is_finite() && centre.1.is_finite()) {
            return Err(Error::OutOfDomain {
                name: "history rotation centre",
                value: if centre.0.is_finite() { centre.1 } else { centre.0 },
                allowed: "finite",
            });
        }
        self.centre = Some(centre);
        Ok(self)
    }

    /// The fast solver's configuration for every step (its tolerance is each step's).
    #[must_use]
    pub fn with_config(mut self, config: FastConfig) -> Self {
        self.config = config;
        self
    }

    /// The influence model.
    #[must_use]
    pub fn with_model(mut self, model: InfluenceModel) -> Self {
        self.model = model;
        self
    }

    /// The path direction $\theta$ (rad).
    #[must_use]
    pub fn angle(&self) -> f64 {
        self.angle
    }

    /// The friction capacity $f\,h_xh_y\sum_k p_k$ of a pressure field on this grid (N).
    #[must_use]
    pub fn capacity(&self, pressure: &[f64]) -> f64 {
        self.friction * self.grid.element_area() * pressure.iter().sum::<f64>()
    }

    /// Plan the operator (once for the path) and return the stepper at the unloaded,
    /// traction-free state.
    ///
    /// # Errors
    /// As [`TensorConvolution::new`].
    pub fn start(&self) -> Result<LoadHistory<'a>> {
        let op = TensorConvolution::new(
            self.grid,
            &stickslip_lattice::Compliance::pair(&self.bodies[0], &self.bodies[1]),
            self.model,
        )?;
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

    /// Solve a whole path (see the module docs): check its corners, then step through
    /// [`LoadPath::points`], and find the loops.
    ///
    /// `pressure(P)` gives the pressure of every grid cell (Pa, zero where apart) under the
    /// normal load $P$: e.g. Hertz's at $P$ on the grid's lattice, or a normal solve's. It is
    /// called at each corner before solving and again whenever the normal load changes from
    /// one step to the next (a constant normal load costs one call per corner). Its errors
    /// pass through unchanged; the history's are turned into `E`.
    ///
    /// # Errors
    /// Before any step: [`Error::PathCorner`] for a corner whose force exceeds the friction
    /// capacity of its pressure (force control: no equilibrium), or whose force and moment
    /// together lie outside the limit surface ([`ContactGrid::load_capacity_factor`] below 1);
    /// [`Error::OutOfDomain`] for a moment on a shift-controlled path or with
    /// [`HistoryDirections::Line`]. During the path: [`Error::HistoryStep`] with the step
    /// index and the step's error.
    pub fn run<E, F>(
        &self,
        path: &LoadPath,
        mut pressure: F,
    ) -> std::result::Result<HistoryOutcome, E>
    where
        E: From<Error>,
        F: FnMut(f64) -> std::result::Result<Vec<f64>, E>,
    {
        if path.has_moment() {
            self.check_moment_allowed(path.control(), path.corner(0).map_or(0.0, |c| c.2))?;
        }
        let mut cache: Option<(f64, Vec<f64>)> = None;
        let mut fetch =
            |p: f64, cache: &mut Option<(f64, Vec<f64>)>| -> std::result::Result<(), E> {
                if cache.as_ref().is_none_or(|(q, _)| *q != p) {
                    let v = pressure(p)?;
                    if v.len() != self.grid.len() {
                        return Err(Error::LengthMismatch {
                            name: "history pressure (one per grid cell)",
                            expected: self.grid.len(),
                            got: v.len(),
                        }
                        .into());
                    }
                    *cache = Some((p, v));
                }
                Ok(())
            };
        // The corners first: nothing is solved for a path that cannot be.
        if path.control() == PathControl::Force {
            let e = (self.angle.cos(), self.angle.sin());
            for i in 0..path.corners() {
                let (t, p, m) = path.corner(i).unwrap_or((0.0, 1.0, 0.0));
                fetch(p, &mut cache)?;
                let pr = &cache
                    .as_ref()
                    .map(|c| &c.1)
                    .ok_or(Error::EmptyGrid { reason: "no pressure" })?;
                let cap = self.capacity(pr);
                if !path.has_moment() {
                    if t.abs() > cap * (1.0 + 1e-12) {
                        return Err(Error::PathCorner {
                            corner: i,
                            name: "tangential force / friction capacity f P",
                            value: t.abs() / cap,
                            allowed:
                                "<= 1 under force control (beyond it there is no equilibrium: \
                                      the bodies slide and accelerate; a shift path slides)",
                        }
                        .into());
                    }
                } else {
                    let mut g = self.grid.clone();
                    g.pressure.clone_from(pr);
                    let lambda = g.load_capacity_factor(self.friction, (t * e.0, t * e.1), m);
                    if lambda < 1.0 {
                        return Err(Error::PathCorner {
                            corner: i,
                            name: "load capacity factor of force and moment",
                            value: lambda,
                            allowed: ">= 1 (below 1 the force and moment together exceed what \
                                      friction carries: the bodies slide)",
                        }
                        .into());
                    }
                }
            }
        }
        let mut h = self.start()?;
        for (i, pt) in path.points().into_iter().enumerate() {
            fetch(pt.normal, &mut cache)?;
            let pr = cache.as_ref().map(|c| c.1.as_slice());
            let target = StepTarget {
                control: path.control(),
                tangential: pt.tangential,
                moment: pt.moment,
            };
            h.step(pr, target).map_err(|e| Error::HistoryStep { step: i, source: Box::new(e) })?;
        }
        Ok(h.into_outcome())
    }

    fn check_moment_allowed(&self, control: PathControl, m: f64) -> Result<()> {
        if control == PathControl::Shift {
            return Err(Error::OutOfDomain {
                name: "moment on a shift-controlled path",
                value: m,
                allowed: "none: shift control takes the force along the path only",
            });
        }
        if self.directions == HistoryDirections::Line {
            return Err(Error::OutOfDomain {
                name: "moment with tractions along the path direction (Line)",
                value: m,
                allowed: "none: a moment needs free traction directions",
            });
        }
        Ok(())
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

/// What one fast solve needs, borrowed from the stepper.
struct Ctx<'x> {
    grid: &'x ContactGrid,
    p: &'x HistoryProblem<'x>,
    op: &'x TensorConvolution,
    fixed: &'x Option<Vec<(f64, f64)>>,
    centre: (f64, f64),
}

/// Tallies of the solves of one step.
#[derive(Default)]
struct Tally {
    solves: usize,
    newton: usize,
    products: usize,
}

impl Ctx<'_> {
    /// One fast solve at the force $T$ along the path (negative: the opposite way) and the
    /// moment, with the prescribed displacement `u0`, from the first of `starts` that
    /// converges (`None`: the solver's cold start). A load beyond the capacity or bad input
    /// fails at once; a start from which the iteration does not converge
    /// ([`Error::NotConverged`], [`Error::NoStickLeft`], [`Error::NotPositiveDefinite`])
    /// passes to the next, and the last one's error is returned.
    fn solve_force(
        &self,
        scratch: &mut ConvScratch,
        t: f64,
        moment: Option<f64>,
        u0: Option<&[(f64, f64)]>,
        starts: &[Option<&WarmStart>],
        tally: &mut Tally,
    ) -> Result<FastSolution> {
        let angle = self.p.angle;
        let (mag, ang) = if t >= 0.0 { (t, angle) } else { (-t, angle + PI) };
        let mut load = Load::polar(mag, ang)?;
        if let Some(m) = moment {
            load = load.with_moment(m, Some(self.centre))?;
        }
        let mut fp = FastProblem::new(self.grid, self.p.bodies, self.p.friction, load)?
            .with_model(self.p.model)
            .with_config(self.p.config);
        if let Some(d) = self.fixed {
            fp = fp.with_directions(TractionDirections::Fixed(d.clone()))?;
        }
        if let Some(u0) = u0 {
            fp = fp.with_prescribed_displacement(u0)?;
        }
        let mut last = Error::EmptyGrid { reason: "no start given" };
        for start in starts {
            let solved = match start {
                Some(w) => fp.solve_from(self.op, scratch, w),
                None => fp.solve_with(self.op, scratch),
            };
            tally.solves += 1;
            match solved {
                Ok(s) => {
                    tally.newton += s.info.iterations;
                    tally.products += s.info.products;
                    return Ok(s);
                }
                Err(
                    e @ (Error::NotConverged { .. }
                    | Error::NoStickLeft { .. }
                    | Error::NotPositiveDefinite { .. }),
                ) => last = e,
                Err(e) => return Err(e),
            }
        }
        Err(last)
    }

    /// Shift control: the force whose solution shifts by `inc` along the path (module docs).
    /// Returns the solution (shift and slip set to the prescribed increment when sliding).
    #[allow(clippy::too_many_arguments)]
    fn solve_shift(
        &self,
        scratch: &mut ConvScratch,
        inc: f64,
        u0: Option<&[(f64, f64)]>,
        starts: &[Option<&WarmStart>],
        t_prev: f64,
        stiffness: Option<f64>,
        tally: &mut Tally,
    ) -> Result<FastSolution> {
        let e = (self.p.angle.cos(), self.p.angle.sin());
        let along = |s: &FastSolution| s.shift.0 * e.0 + s.shift.1 * e.1;
        let cap = self.p.capacity(&self.grid.pressure);
        // Sliding forward or backward: the onset shifts bound what partial slip reaches.
        let slide = |mut s: FastSolution| {
            let extra = inc - along(&s);
            s.shift = (s.shift.0 + extra * e.0, s.shift.1 + extra * e.1);
            for v in &mut s.slip {
                v.0 += extra * e.0;
                v.1 += extra * e.1;
            }
            s
        };
        let hi = self.solve_force(scratch, cap, None, u0, starts, tally)?;
        let g_hi = along(&hi) - inc;
        if g_hi <= 0.0 {
            return Ok(slide(hi));
        }
        let lo = self.solve_force(scratch, -cap, None, u0, starts, tally)?;
        let g_lo = along(&lo) - inc;
        if g_lo >= 0.0 {
            return Ok(slide(lo));
        }
        let tol = 1e-9 * (along(&hi) - along(&lo));
        let (mut a, mut b) = (-cap, cap);
        // First trial from the last step's secant stiffness (or the mean one over the
        // partial-slip range).
        let k = stiffness
            .filter(|k| k.is_finite() && *k > 0.0)
            .unwrap_or(2.0 * cap / (along(&hi) - along(&lo)));
        let inside = |t: f64, a: f64, b: f64| {
            let m = 1e-6 * (b - a);
            t.clamp(a + m, b - m)
        };
        let mut t = inside(t_prev + k * inc, a, b);
        let mut prev: Option<(f64, f64)> = None;
        let mut warm: Option<WarmStart> = None;
        for _ in 0..60 {
            let mut tries: Vec<Option<&WarmStart>> = Vec::with_capacity(starts.len() + 1);
            if let Some(w) = &warm {
                tries.push(Some(w));
            }
            tries.extend_from_slice(starts);
            let s = self.solve_force(scratch, t, None, u0, &tries, tally)?;
            let g = along(&s) - inc;
            if g.abs() <= tol || b - a <= 1e-13 * cap {
                return Ok(s);
            }
            if g < 0.0 {
                a = t;
            } else {
                b = t;
            }
            // Secant through the last two trials when it stays inside the bracket, else
            // bisection.
            let next = match prev {
                Some((tp, gp)) if g != gp => t - g * (t - tp) / (g - gp),
                _ => t - g * k,
            };
            prev = Some((t, g));
            t = if next > a && next < b { next } else { 0.5 * (a + b) };
            warm = Some(WarmStart::from(&s));
        }
        Err(Error::NotConverged {
            solver: "load history shift search",
            iterations: 60,
            residual: prev.map_or(f64::INFINITY, |p| p.1.abs()),
            tolerance: tol,
        })
    }
}

impl LoadHistory<'_> {
    /// Solve one step (module docs): `pressure` per grid cell (Pa; `None` keeps the
    /// previous step's, or the grid's at the first step), `target` the loads to reach.
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] for a pressure of the wrong length; [`Error::OutOfDomain`]
    /// for a negative or non-finite pressure, a step without normal force, a non-finite
    /// target, or a moment where none is allowed ([`HistoryProblem::run`]); the fast
    /// solver's errors (a force beyond the capacity: [`Error::CapacityExceeded`]).
    /// After an error the state is that of the last solved step.
    pub fn step(&mut self, pressure: Option<&[f64]>, target: StepTarget) -> Result<&HistoryStep> {
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
        let centre = *self.centre.get_or_insert_with(|| self.grid.force_centroid());
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
        // Warm starts, tried in order until one converges: after a reversal of a prescribed
        // load all stick (a reversed step starts by sticking everywhere), otherwise the
        // previous state; then the other of the two; then the solver's own cold start.
        let turned = |inc: f64, last: f64| inc != 0.0 && last != 0.0 && inc.signum() != last;
        let reversal = turned(dir_t, self.last_dir.0) || turned(dir_m, self.last_dir.1);
        let continuing = self.predicted_start(dir_t, dir_m);
        let sticking = WarmStart {
            traction: self.traction.clone(),
            shift: (0.0, 0.0),
            rotation: 0.0,
            state: Vec::new(),
        };
        let u0: Vec<(f64, f64)> = self.kq.iter().map(|v| (-v.0, -v.1)).collect();
        let (u0, starts) = if self.virgin {
            (None, vec![None])
        } else if reversal {
            (Some(u0.as_slice()), vec![Some(&sticking), Some(&continuing), None])
        } else {
            (Some(u0.as_slice()), vec![Some(&continuing), Some(&sticking), None])
        };
        let ctx =
            Ctx { grid: &self.grid, p: &self.problem, op: &self.op, fixed: &self.fixed, centre };
        let mut tally = Tally::default();
        let solved = match target.control {
            PathControl::Force => ctx.solve_force(
                &mut self.scratch,
                target.tangential,
                target.moment,
                u0,
                &starts,
                &mut tally,
            ),
            PathControl::Shift => ctx.solve_shift(
                &mut self.scratch,
                inc,
                u0,
                &starts,
                dot(self.force),
                self.stiffness,
                &mut tally,
            ),
        };
        let sol = match solved {
            Ok(s) => s,
            Err(err) => {
                self.grid.pressure = previous;
                return Err(err);
            }
        };
        self.pressure_prev = previous;
        self.commit(&sol, target, (dir_t, dir_m), centre, tally, t0);
        Ok(self.steps.last().expect("a step was just recorded"))
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
        let mut traction = Vec::with_capacity(self.traction.len());
        let mut state = Vec::with_capacity(self.traction.len());
        for ((q, d), p) in self.traction.iter().zip(&self.dq).zip(&self.grid.pressure) {
            let t = (q.0 + r * d.0, q.1 + r * d.1);
            let slips = t.0.hypot(t.1) >= f * p && *p > 0.0;
            traction.push(t);
            state.push(if slips { ElementState::Slip } else { ElementState::Stick });
        }
        WarmStart {
            traction,
            shift: (r * self.last_increment.0 .0, r * self.last_increment.0 .1),
            rotation: r * self.last_increment.1,
            state,
        }
    }

    /// Take a solved step into the path state and record it.
    fn commit(
        &mut self,
        sol: &FastSolution,
        target: StepTarget,
        dir: (f64, f64),
        centre: (f64, f64),
        tally: Tally,
        t0: Instant,
    ) {
        let n = self.grid.len();
        let area = self.grid.element_area();
        let theta = self.problem.angle;
        let dirs: [(f64, f64); SLIP_RANGE_DIRECTIONS] = std::array::from_fn(|j| {
            let a = theta + PI * j as f64 / SLIP_RANGE_DIRECTIONS as f64;
            (a.cos(), a.sin())
        });
        let mut dd = 0.0;
        let (mut contact, mut stick) = (0usize, 0usize);
        for k in 0..n {
            let (q0, q1, ds) = (self.traction[k], sol.traction[k], sol.slip[k]);
            let now = self.grid.pressure[k] > 0.0;
            if now || self.pressure_prev[k] > 0.0 {
                let d = 0.5 * ((q0.0 + q1.0) * ds.0 + (q0.1 + q1.1) * ds.1);
                self.dissipation[k] += d;
                dd += d;
            }
            if now {
                contact += 1;
                if sol.state[k] == ElementState::Stick {
                    stick += 1;
                }
                let s = &mut self.slip[k];
                s.0 += ds.0;
                s.1 += ds.1;
                let ext = &mut self.extent[k];
                for (j, d) in dirs.iter().enumerate() {
                    let v = s.0 * d.0 + s.1 * d.1;
                    ext[2 * j] = ext[2 * j].min(v);
                    ext[2 * j + 1] = ext[2 * j + 1].max(v);
                }
            }
        }
        let rotating = target.moment.is_some();
        let (f0, m0) = (self.force, self.moment);
        let (f1, m1) = (sol.resultant, if rotating { sol.moment } else { 0.0 });
        let drot = if rotating { sol.rotation } else { 0.0 };
        let dw = 0.5 * ((f0.0 + f1.0) * sol.shift.0 + (f0.1 + f1.1) * sol.shift.1)
            + 0.5 * (m0 + m1) * drot;
        // K q^n for the next step's prescribed displacement and the stored energy.
        let (qx, qy): (Vec<f64>, Vec<f64>) = sol.traction.iter().copied().unzip();
        let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
        self.op.apply(&qx, &qy, &mut ux, &mut uy, &mut self.scratch);
        let mut u2 = 0.0;
        for k in 0..n {
            self.kq[k] = (ux[k], uy[k]);
            u2 += qx[k] * ux[k] + qy[k] * uy[k];
        }
        let e = (theta.cos(), theta.sin());
        let dot = |v: (f64, f64)| v.0 * e.0 + v.1 * e.1;
        let dtan = dot(f1) - dot(f0);
        let dshift = dot(sol.shift);
        if dtan != 0.0 && dshift != 0.0 && dtan / dshift > 0.0 && sol.regime != Regime::GrossSlip {
            self.stiffness = Some(dtan / dshift);
        }
        for ((d, a), b) in self.dq.iter_mut().zip(&self.traction).zip(&sol.traction) {
            *d = (b.0 - a.0, b.1 - a.1);
        }
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
            (0..n)
                .map(|k| {
                    area * ((self.grid.x[k] - centre.0) * qy[k]
                        - (self.grid.y[k] - centre.1) * qx[k])
                })
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
            products: tally.products + 1,
            residual: sol.info.residual.max(sol.info.load_residual),
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
