//! The history problem: the grid, bodies, friction and options of a path, its corner checks,
//! and the whole-path driver [`HistoryProblem::run`].

use super::path::{HistoryLoop, LoadPath, PathControl};
use super::stepper::LoadHistory;
use crate::contract::check_pair;
use crate::error::{Error, Result};
use crate::fast::FastConfig;
use crate::solve::{ElementState, Regime};
use stickslip_halfspace::Material;
use stickslip_lattice::influence::InfluenceModel;
use stickslip_lattice::{ContactGrid, PeriodicLattice};

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
    pub(super) grid: &'a ContactGrid,
    pub(super) bodies: [Material; 2],
    pub(super) friction: f64,
    pub(super) angle: f64,
    pub(super) directions: HistoryDirections,
    pub(super) centre: Option<(f64, f64)>,
    pub(super) model: InfluenceModel,
    pub(super) config: FastConfig,
    pub(super) periodic: Option<PeriodicLattice>,
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
    /// Passes of the Dundurs coupling (a normal and a tangential solve each; module docs,
    /// "Dissimilar bodies"): 1 for an uncoupled step or a pressure that does not depend on
    /// the traction.
    pub coupling_passes: usize,
    /// The coupling residual of the accepted pass: the relative change of the traction
    /// between it and the traction that made its pressure (0 for an uncoupled step).
    pub coupling_residual: f64,
    /// The relative change ($L^2$) of the pressure between the last two coupling passes (0
    /// for a one-pass step: its pressure does not depend on the traction).
    pub coupling_pressure_change: f64,
    /// Wall time of the step, seconds.
    pub seconds: f64,
}

/// Everything a solved path leaves: the per-step records, the loops, and the final fields.
#[derive(Debug, Clone, PartialEq)]
pub struct HistoryOutcome {
    /// One record per step of the path.
    pub steps: Vec<HistoryStep>,
    /// The closed loops ([`find_loops`](super::find_loops)).
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
            periodic: None,
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

    /// Solve on a periodic surface: the grid's cells are cells of `lattice` (one period),
    /// the operator is the periodic one ([`stickslip_lattice::TensorConvolution::periodic`]: Cerruti's Fourier
    /// transfer, mean displacement zero), as for one state on a periodic surface
    /// ([`crate::fast::FastProblem::with_periodic`]). The shift is then relative to the mean
    /// surface displacement; a moment is refused (a rotation is not periodic).
    #[must_use]
    pub fn with_periodic(mut self, lattice: PeriodicLattice) -> Self {
        self.periodic = Some(lattice);
        self
    }

    /// The influence model (an isolated contact; a periodic one has its own transfer).
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
}

impl HistoryProblem<'_> {
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
    pub fn run<E, F>(&self, path: &LoadPath, pressure: F) -> std::result::Result<HistoryOutcome, E>
    where
        E: From<Error>,
        F: FnMut(f64) -> std::result::Result<Vec<f64>, E>,
    {
        self.run_observed(path, pressure, |_, _, _| Ok(()))
    }

    /// [`HistoryProblem::run`], calling `observe(step, corner, state)` after every step with
    /// the step's index, the corner's index when the step is a corner of the path, and the
    /// state (its traction, pressure, slip) as the step left it: for what a caller computes
    /// from intermediate states (e.g. surface stresses at the turning points) without storing
    /// every step's arrays.
    ///
    /// # Errors
    /// As [`HistoryProblem::run`], and `observe`'s errors unchanged.
    pub fn run_observed<E, F, O>(
        &self,
        path: &LoadPath,
        mut pressure: F,
        mut observe: O,
    ) -> std::result::Result<HistoryOutcome, E>
    where
        E: From<Error>,
        F: FnMut(f64) -> std::result::Result<Vec<f64>, E>,
        O: FnMut(usize, Option<usize>, &LoadHistory<'_>) -> std::result::Result<(), E>,
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
                self.check_corner(i, t, m, pr, e, path.has_moment())?;
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
            observe(i, pt.corner, &h)?;
        }
        Ok(h.into_outcome())
    }

    /// Corner `i` of a force-controlled path: the force `t` along the path (and the moment
    /// `m`) within what friction carries under the corner's pressure `pr`.
    pub(super) fn check_corner(
        &self,
        i: usize,
        t: f64,
        m: f64,
        pr: &[f64],
        e: (f64, f64),
        has_moment: bool,
    ) -> Result<()> {
        let cap = self.capacity(pr);
        if !has_moment {
            if t.abs() > cap * (1.0 + 1e-12) {
                return Err(Error::PathCorner {
                    corner: i,
                    name: "tangential force / friction capacity f P",
                    value: t.abs() / cap,
                    allowed: "<= 1 under force control (beyond it there is no equilibrium: \
                              the bodies slide and accelerate; a shift path slides)",
                });
            }
        } else {
            let mut g = self.grid.clone();
            g.pressure = pr.to_vec();
            let lambda = g.load_capacity_factor(self.friction, (t * e.0, t * e.1), m);
            if lambda < 1.0 {
                return Err(Error::PathCorner {
                    corner: i,
                    name: "load capacity factor of force and moment",
                    value: lambda,
                    allowed: ">= 1 (below 1 the force and moment together exceed what \
                              friction carries: the bodies slide)",
                });
            }
        }
        Ok(())
    }

    pub(super) fn check_moment_allowed(&self, control: PathControl, m: f64) -> Result<()> {
        if self.periodic.is_some() {
            return Err(Error::OutOfDomain {
                name: "moment on a periodic surface",
                value: m,
                allowed: "none: a rotation is not periodic",
            });
        }
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
