//! The wheel-rail problem: placement, contact search, the normal contact of every patch
//! under the vertical load, creepages and the tangential solution per patch.
//!
//! **Vertical load.** With [`VerticalLoad::Force`] the wheelset height $z_{ws}$ is found so
//! that the vertical components of the patches' normal forces carry the wheel load,
//! $$\sum_p F_{n,p}\cos\delta_p = F_z,$$
//! to the relative tolerance [`WheelRail::with_load_tolerance`] (default $10^{-7}$). The
//! patches do not load each other (CONTACT's planar contact approach); each trial height
//! re-evaluates the gap of every patch ([`crate::patch`], moved rigidly with the wheel) and
//! solves its normal contact warm-started from the previous trial. One patch: the normal
//! solver's force control at $F_n = F_z/\cos\delta$, whose approach moves the wheelset
//! ([`HEIGHT_CONSISTENCY`]). Several patches: approach control at trial heights, secant on
//! $F(z)^{2/3}$ (linear in $z$ for a Hertzian contact, $F\propto\delta^{3/2}$), from the
//! first touch $z_0$ (where the smallest vertical gap closes) plus an estimate of the
//! approach. [`VerticalLoad::TotalForce`] counts the tangential forces' vertical
//! components $F_{s,p}\sin\delta_p$ too, as CONTACT does (one patch: secant on its normal
//! force; several: on the height; each trial with the tangential solves).
//! [`VerticalLoad::Approach`] gives the height directly, as the wheelset's vertical
//! displacement beyond first touch.
//!
//! **Lattices.** Each patch gets a lattice of the given cell size over the bounding box of
//! its interpenetration on the search lines (at the line $y_k$ of depth $d_k$ the wheel's
//! circle of radius $\rho_k$ dips below the rail for $|x - x_k| < \sqrt{2d_k\rho_k}$) plus
//! [`LATTICE_MARGIN`] cells, centred on it, at a height deeper than the expected one. Since
//! the elastic displacements are positive, the contact lies inside the interpenetration
//! region, so a lattice that holds the interpenetration at the final height holds the
//! contact; if it does not, the lattices are laid out again deeper. Lattice sizes are
//! multiples of [`LATTICE_ROUND`] so that positions of a sweep share planned operators.
//!
//! **Frames.** A patch's frame starts at its region's centre ([`crate::search`]); after the
//! normal solve it moves to the pressure centroid, with the pressure-weighted mean
//! inclination of the rail surface as contact angle, unless it is there already
//! ([`FRAME_ACCEPT`]); then the patch is solved again. Without a previous position to
//! start from, that first solve runs on a lattice of twice the cell ([`COARSE_MIN_CELLS`]),
//! and the frame is checked once more against the fine solution's centroid.
//!
//! **From one position to the next** ([`Cache`]): the planned normal operators; each
//! patch's frame offset from its region's centre, its approach, its ratio of total to
//! normal vertical force and its pressure. The next position's region within
//! [`MEMORY_MATCH`] starts from the same offsets, approach and pressure: in a sweep of
//! nearby positions the frame then stands at once and the patch is solved once.

mod layout;
mod load;
mod position;
mod tangent;
mod working;

pub use tangent::fastsim_axes;
use tangent::Tangent;
use working::{touches_border, Memory, Working};

use crate::error::{Error, Result};
use crate::kinematics::{creepages, Motion};
use crate::patch::{self, Frame, Lattice};
use crate::placement::{PlacedRail, PlacedWheel, Position, Side, Track, Wheelset};
use crate::search::{search, Search};
use nalgebra::Vector3;
use std::time::Instant;
use stickslip_halfspace::hertz::HertzEllipse;
use stickslip_halfspace::material::{composite_modulus, Compliance};
use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
use stickslip_normal::{
    Boundary, NormalLoad, NormalOperator, NormalProblem, NormalSolution, Tolerance,
};
use stickslip_rolling::steady3d::fastsim;
use stickslip_rolling::{Creepage, RollingSolution, SteadyRolling};

/// Cells added around a patch's interpenetration region.
pub const LATTICE_MARGIN: usize = 2;
/// Lattice sizes are rounded up to a multiple of this.
pub const LATTICE_ROUND: usize = 4;
/// The wheel at its nominal height ($z_{ws} = 0$) hovering more than this above the rail
/// everywhere means the geometry is wrong (m).
pub const MAX_NOMINAL_GAP: f64 = 10e-3;
/// A wheel contact point less than this below the flange tip (in the profile's $z$) rides on
/// the top of the flange: flange climb (m). (A yawed wheelset touches its flange ahead of the
/// axle, high on the flange and beyond the steepest point of the profile: 5.1 mm below the
/// tip in the Manchester benchmark's position 21, 10 mm and 24 mrad; an unyawed
/// wheelset pushed 20 mm across touches 2.8 mm below it, with a contact angle that has
/// fallen from the flange's 70 degrees to 35.)
pub const FLANGE_TIP_BAND: f64 = 3e-3;
/// A wheel profile has a flange if a face next to its lowest point is steeper than this
/// (rad, 30 degrees; flanges have 60 to 75).
pub const FLANGE_MIN_ANGLE: f64 = 0.5;

/// How the wheel is pressed onto the rail.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum VerticalLoad {
    /// The vertical wheel load $F_z$ (N, $> 0$) carried by the vertical components of the
    /// patches' normal forces, $\sum_p F_{n,p}\cos\delta_p = F_z$; the wheelset height
    /// follows.
    Force(f64),
    /// The vertical wheel load $F_z$ (N, $> 0$) equal to the total vertical force of the
    /// wheel on the rail, creep forces included,
    /// $\sum_p (F_{n,p}\cos\delta_p + F_{s,p}\sin\delta_p) = F_z$ (CONTACT's force control;
    /// the two differ where a steep flange contact carries a large lateral creep force).
    /// Each trial height solves the tangential problem too. Without a tangential solution it
    /// is [`VerticalLoad::Force`].
    TotalForce(f64),
    /// The wheelset's vertical displacement beyond first touch (m, $> 0$).
    Approach(f64),
}

/// Which tangential theory solves the patches.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Tangential {
    /// Kalker's exact steady-rolling theory on the patch's contact cells
    /// ([`SteadyRolling`]) at the given relative tolerance.
    Exact {
        /// Relative tolerance of the natural residual.
        tolerance: f64,
    },
    /// FASTSIM on the same cells, with the flexibilities of the ellipse of the contact's
    /// area and aspect ratio ([`fastsim`]).
    Fastsim,
    /// Normal contact only.
    None,
}

/// A wheel-rail contact problem: one side of a wheelset on its track, the materials, the
/// friction coefficient and the lattice cell.
#[derive(Debug, Clone)]
pub struct WheelRail {
    side: Side,
    track: Track,
    wheelset: Wheelset,
    rail_offset: [f64; 2],
    bodies: [Material; 2],
    friction: f64,
    cell: (f64, f64),
    normal_tolerance: f64,
    load_tolerance: f64,
}

/// What one solve hands to the next: planned normal operators by lattice size (reused
/// across positions and trial heights), each patch's frame offsets, approach and pressure
/// (the next position's first guess: its frame, height and warm start), and the thread pool
/// the solves run in. A guess only saves work: the pressure centroid is checked against the
/// frame, and the frame moved if it is off ([`FRAME_ACCEPT`]).
///
/// A wheel-rail patch has a few thousand cells: its FFTs and sums are too small to share
/// among threads (handing each of them to a pool costs more than it saves), so by default a
/// solve runs on one thread of its own ([`Cache::with_threads`]); run several positions at
/// once for more.
#[derive(Debug, Default)]
pub struct Cache {
    operators: Vec<((usize, usize), NormalOperator)>,
    memory: Vec<Memory>,
    threads: usize,
    pool: Option<std::sync::Arc<rayon::ThreadPool>>,
    /// Operators found planned.
    pub hits: usize,
    /// Operators planned.
    pub misses: usize,
}

impl Cache {
    /// An empty cache; solves run on one thread.
    #[must_use]
    pub fn new() -> Self {
        Self { threads: 1, ..Self::default() }
    }

    /// Forget the previous position (the next solve starts from its own estimates).
    pub fn forget(&mut self) {
        self.memory.clear();
    }

    /// Solves run on `threads` threads of a pool of their own (0: in the caller's rayon
    /// pool, as it is).
    #[must_use]
    pub fn with_threads(mut self, threads: usize) -> Self {
        self.threads = threads;
        self.pool = None;
        self
    }

    /// The pool to run in (`None`: the caller's). Built on first use; if the system refuses
    /// a thread, the solve runs in the caller's pool.
    fn pool(&mut self) -> Option<std::sync::Arc<rayon::ThreadPool>> {
        if self.threads == 0 {
            return None;
        }
        if self.pool.is_none() {
            self.pool = rayon::ThreadPoolBuilder::new()
                .num_threads(self.threads)
                .build()
                .ok()
                .map(std::sync::Arc::new);
        }
        self.pool.clone()
    }

    fn operator(&mut self, pb: &NormalProblem<'_>) -> &NormalOperator {
        let key = pb.lattice();
        if let Some(k) = self.operators.iter().position(|(k, _)| *k == key) {
            self.hits += 1;
            return &self.operators[k].1;
        }
        self.misses += 1;
        self.operators.push((key, pb.operator()));
        &self.operators[self.operators.len() - 1].1
    }
}

/// A patch's lattice as reported (patch coordinates, m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchLattice {
    /// Cells along $x$.
    pub nx: usize,
    /// Cells along $s$.
    pub ns: usize,
    /// Cell side along $x$.
    pub hx: f64,
    /// Cell side along $s$.
    pub hs: f64,
    /// Lower corner $(x_0, s_0)$.
    pub origin: (f64, f64),
}

/// One contact patch's solution (side as asked; lateral quantities of a left side are the
/// mirror images of the right side's, [`crate::placement`]).
#[derive(Debug, Clone, PartialEq)]
pub struct PatchSolution {
    /// The contact reference point (the patch frame's origin, on the rail surface), track
    /// coordinates $(x, y, z)$ (m).
    pub reference: [f64; 3],
    /// The reference point in the rail profile's coordinates $(y_r, z_r)$ (m; on a left
    /// rail $y_r$ grows towards the track centre, as in CONTACT).
    pub rail_point: [f64; 2],
    /// The wheel's undeformed surface point on the patch normal through the reference
    /// point, in the wheel profile's coordinates $(y_w, z_w)$ (m).
    pub wheel_point: [f64; 2],
    /// Contact angle $\delta$ (rad): rotation about $x$ from the track $z$ axis to the
    /// patch normal.
    pub contact_angle: f64,
    /// Rolling radius: the wheel radius $r_0 + z_w$ at the wheel point (m).
    pub rolling_radius: f64,
    /// Rolling speed $V_r$ of the creepages (m/s).
    pub rolling_speed: f64,
    /// Creepages at the reference point ([`crate::kinematics`]).
    pub creepage: Creepage,
    /// Normal force $F_n$ (N, pressing the rail).
    pub normal_force: f64,
    /// Longitudinal creep force $F_x$ on the rail (N, patch frame).
    pub fx: f64,
    /// Lateral creep force $F_s$ on the rail (N, in the patch plane).
    pub fs: f64,
    /// Spin moment $M_n$ on the rail about the reference point (N m).
    pub mn: f64,
    /// Peak pressure (Pa).
    pub pmax: f64,
    /// Contact area (m²).
    pub area: f64,
    /// Contact cells.
    pub contact_cells: usize,
    /// Fraction of the contact cells that stick (none without a tangential solution).
    pub stick_fraction: Option<f64>,
    /// FASTSIM only: the semi-axes $(a, b)$ of its flexibilities ([`fastsim_axes`]).
    pub fastsim_axes: Option<(f64, f64)>,
    /// The force of the wheel on the rail in track coordinates $(F_x, F_y, F_z)$ (N).
    pub force_on_rail: [f64; 3],
    /// The patch lattice.
    pub lattice: PatchLattice,
    /// The undeformed gap on the lattice at the final height (m, row-major `j * nx + i`).
    pub gap: Vec<f64>,
    /// The normal solution on the lattice.
    pub normal: NormalSolution,
    /// The tangential solution on the contact cells (patch coordinates; traction on the
    /// rail).
    pub rolling: Option<RollingSolution>,
}

/// How a solve went.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SolveInfo {
    /// Trial heights of the vertical-load iteration.
    pub load_iterations: usize,
    /// Relative residual of the vertical load (0 under approach control).
    pub load_residual: f64,
    /// Normal solves (all patches, all trials).
    pub normal_solves: usize,
    /// Conjugate-gradient iterations of the normal solves, in all.
    pub normal_iterations: usize,
    /// FFT products of the normal solves, in all.
    pub normal_products: usize,
    /// Times the lattices were laid out.
    pub layouts: usize,
    /// Patches whose frame was moved to their pressure centroid (0 when the previous
    /// position's offsets placed every frame well).
    pub frames_moved: usize,
    /// Wall time of the geometry (search, frames, gaps), seconds.
    pub geometry_seconds: f64,
    /// Wall time of the normal solves, seconds.
    pub normal_seconds: f64,
    /// Wall time of the tangential solves, seconds.
    pub tangential_seconds: f64,
    /// Wall time of the whole solve, seconds.
    pub total_seconds: f64,
}

/// The solution of one wheel-rail position.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// The side solved.
    pub side: Side,
    /// Wheelset height $z_{ws}$ (m, track $z$ down; 0 puts the un-rolled wheel's profile
    /// origin on the track plane).
    pub z_wheelset: f64,
    /// $z_{ws}$ minus its value at first touch (m).
    pub approach: f64,
    /// The total force of the wheel on the rail, track coordinates $(F_x, F_y, F_z)$ (N),
    /// normal and tangential forces of all patches.
    pub total_on_rail: [f64; 3],
    /// The patches, in the order of increasing track $y$ on the right side.
    pub patches: Vec<PatchSolution>,
    /// How the solve went.
    pub info: SolveInfo,
}

impl WheelRail {
    /// The problem of `side` of `wheelset` on `track`, with rail and wheel materials, the
    /// friction coefficient and the lattice cell `(hx, hs)` (m, along $x$ and across the
    /// patch). The rail is placed here (the gauge point, [`crate::placement`]).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a non-positive cell side, a negative friction coefficient
    /// or two rigid bodies; [`Error::Placement`] if the rail cannot be placed.
    pub fn new(
        side: Side,
        track: Track,
        wheelset: Wheelset,
        rail_material: Material,
        wheel_material: Material,
        friction: f64,
        cell: (f64, f64),
    ) -> Result<Self> {
        crate::error::positive("cell hx", cell.0)?;
        crate::error::positive("cell hs", cell.1)?;
        if !(friction.is_finite() && friction >= 0.0) {
            return Err(Error::OutOfDomain {
                name: "friction",
                value: friction,
                allowed: "finite and >= 0",
            });
        }
        if rail_material.is_rigid() && wheel_material.is_rigid() {
            return Err(Error::OutOfDomain {
                name: "materials",
                value: f64::INFINITY,
                allowed: "at most one rigid body",
            });
        }
        let rail_offset = PlacedRail::new(&track)?.offset;
        Ok(Self {
            side,
            track,
            wheelset,
            rail_offset,
            bodies: [rail_material, wheel_material],
            friction,
            cell,
            normal_tolerance: 1e-8,
            load_tolerance: 1e-7,
        })
    }

    /// The relative tolerance of each patch's normal solve (default $10^{-8}$, far below the
    /// discretisation error of a lattice solution; the force itself is met to the load
    /// tolerance regardless; see [`NormalProblem::TOLERANCE_RANGE`]).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] outside the normal solver's range or above a tenth of the load
    /// tolerance (set that first when both change).
    pub fn with_normal_tolerance(mut self, tol: f64) -> Result<Self> {
        let (lo, hi) = NormalProblem::TOLERANCE_RANGE;
        if !(lo..=hi).contains(&tol) || 10.0 * tol > self.load_tolerance {
            return Err(Error::OutOfDomain {
                name: "normal tolerance",
                value: tol,
                allowed: "1e-12 to 1e-1, and at most a tenth of the load tolerance",
            });
        }
        self.normal_tolerance = tol;
        Ok(self)
    }

    /// The relative tolerance of the vertical load (default $10^{-7}$). The forces it sums
    /// come from normal solves of [`WheelRail::with_normal_tolerance`], so it must be at
    /// least ten times that.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] outside $[10^{-11}, 10^{-2}]$ or below ten times the normal
    /// tolerance.
    pub fn with_load_tolerance(mut self, tol: f64) -> Result<Self> {
        if !(1e-11..=1e-2).contains(&tol) || tol < 10.0 * self.normal_tolerance {
            return Err(Error::OutOfDomain {
                name: "load tolerance",
                value: tol,
                allowed: "1e-11 to 1e-2, and at least ten times the normal tolerance",
            });
        }
        self.load_tolerance = tol;
        Ok(self)
    }

    /// The side.
    #[must_use]
    pub fn side(&self) -> Side {
        self.side
    }

    /// The track.
    #[must_use]
    pub fn track(&self) -> &Track {
        &self.track
    }

    /// The wheelset.
    #[must_use]
    pub fn wheelset(&self) -> &Wheelset {
        &self.wheelset
    }

    /// Rail and wheel materials.
    #[must_use]
    pub fn bodies(&self) -> [Material; 2] {
        self.bodies
    }

    /// Offset $(y_0, z_0)$ of the placed right-side rail (m, [`crate::placement`]).
    #[must_use]
    pub fn rail_offset(&self) -> [f64; 2] {
        self.rail_offset
    }

    fn rail(&self) -> PlacedRail<'_> {
        PlacedRail::with_offset(&self.track, self.rail_offset)
    }

    /// The placed rail and wheel profiles as polylines in track coordinates $(y, z)$ at the
    /// given position and height (for drawing; side as asked).
    #[must_use]
    pub fn profiles_at(
        &self,
        position: &Position,
        z_wheelset: f64,
    ) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
        let sg = self.side.sign();
        let pos = self.right_position(position);
        let rail = self.rail();
        let wheel = PlacedWheel::new(&self.wheelset, &pos, z_wheelset);
        let (theta, _) = wheel.lowest(0.0);
        let r = rail.samples().iter().step_by(10).map(|s| [sg * s[1], s[2]]).collect();
        let w = wheel
            .profile
            .samples()
            .iter()
            .step_by(10)
            .map(|s| {
                let p = wheel.point(s[0], theta).w;
                [sg * p.y, p.z]
            })
            .collect();
        (r, w)
    }

    fn right_position(&self, p: &Position) -> Position {
        let sg = self.side.sign();
        Position { lateral: sg * p.lateral, yaw: sg * p.yaw, roll: sg * p.roll }
    }

    /// Solve one position: the contact patches, their normal contact under `load` and, for
    /// `tangential` other than [`Tangential::None`], their creep forces under `motion`.
    /// `cache` keeps planned operators for the next call.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for bad position, motion or load values; [`Error::NoContact`]
    /// when the profiles never come close; [`Error::FlangeClimb`] for a contact on or beyond
    /// the flange tip or at an end of a profile; [`Error::NotConverged`] if the height
    /// iteration misses the load; errors of the normal and rolling solvers.
    pub fn solve(
        &self,
        position: &Position,
        motion: &Motion,
        load: VerticalLoad,
        tangential: Tangential,
        cache: &mut Cache,
    ) -> Result<Solution> {
        match cache.pool() {
            Some(pool) => {
                pool.install(|| self.solve_here(position, motion, load, tangential, cache))
            }
            None => self.solve_here(position, motion, load, tangential, cache),
        }
    }
}

/// Gap value given to cells outside a patch's lateral band (m): never in contact.
const MASKED_GAP: f64 = 1e-2;
/// A patch's frame stands when its pressure centroid lies within these fractions of a cell
/// of its origin (along $x$ and $s$) and the pressure-weighted mean inclination within this
/// angle (rad) of its contact angle; else the frame moves there and the patch is solved
/// again. (0.1 cell moves the creepages' reference by 20 µm at 0.2 mm cells, which changes
/// the creep forces by less than $10^{-4}fF_n$; $10^{-4}$ rad changes the spin creepage by
/// $\omega_p\Delta\delta/V \approx 2\cdot10^{-4}$ 1/m, about 0.3 % of a tread contact's.)
pub const FRAME_ACCEPT: (f64, f64, f64) = (0.1, 0.1, 1e-4);
/// A one-patch force-controlled solve is accepted when the wheelset move it asks for would
/// change the gap by less than this fraction of the interpenetration beyond the uniform
/// approach (the normal force is the load regardless; the pressure and the creep forces
/// would change by about as much, two orders below the lattice's discretisation error).
pub const HEIGHT_CONSISTENCY: f64 = 1e-4;
/// A region takes the previous position's frame offsets from its patch whose region centre
/// lies within this lateral distance (m).
pub const MEMORY_MATCH: f64 = 2e-3;
/// Relative tolerances of the normal solves and the load in the first pass, before the
/// frames move to the pressure centroids.
pub const FIRST_PASS_TOLERANCE: f64 = 1e-5;
/// The coarse first pass: without a previous position's patch to start from, the first
/// pass (the height under the load and the pressure centroid that places the frame) runs on
/// a lattice of cells twice as large each way, a quarter of the cells; the patch then moves
/// to its lattice of the given cell size at that centroid, warm-started from the coarse
/// pressure, and the frame is checked against the fine pressure centroid once more
/// ([`FRAME_ACCEPT`]; moved and solved again if it is off). Only the frame and the starting
/// height come from the coarse lattice: every reported number is the fine lattice's. A
/// patch whose lattice has fewer cells than this along a side skips the coarse pass.
pub const COARSE_MIN_CELLS: usize = 16;
/// Trial heights of the vertical-load iteration, at most.
const MAX_LOAD_ITERATIONS: usize = 40;
