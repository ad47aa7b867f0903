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
//! ([`FRAME_ACCEPT`]); then the patch is solved again.
//!
//! **From one position to the next** ([`Cache`]): the planned normal operators; each
//! patch's frame offset from its region's centre, its approach, its ratio of total to
//! normal vertical force and its pressure. The next position's region within
//! [`MEMORY_MATCH`] starts from the same offsets, approach and pressure: in a sweep of
//! nearby positions the frame then stands at once and the patch is solved once.

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

/// A patch while solving: frame, lattice, the allowed lateral band, the geometry at a base
/// height, and its last state.
struct Working {
    frame: Frame,
    lattice: Lattice,
    /// Track-$y$ band of this region (the gap is ignored outside it).
    band: (f64, f64),
    /// Height at which the wheel layer was evaluated.
    z_base: f64,
    /// Rail normal coordinate and parameter per column; columns outside the band.
    nr: Vec<f64>,
    rail_t: Vec<f64>,
    masked: Vec<bool>,
    /// Wheel normal coordinate and slope per cell at `z_base`.
    nw: Vec<f64>,
    dnw: Vec<f64>,
    /// The gap at the last height asked.
    gap: Vec<f64>,
    sol: Option<NormalSolution>,
    /// The region's centre at the frame height, $(y, x, \delta)$ (right-side track
    /// coordinates), which the frame's offsets in [`Memory`] are taken from.
    region: (f64, f64, f64),
    /// The frame came from the previous position's offsets.
    predicted: bool,
    /// A pressure to start the first solve from (the previous position's).
    warm: Option<Vec<f64>>,
}

/// What a patch of one position hands to the next ([`Cache`]): where its frame lay relative
/// to its interpenetration region's centre, how far the wheelset was pressed down, and its
/// pressure.
#[derive(Debug, Clone)]
struct Memory {
    region: (f64, f64, f64),
    offset: (f64, f64, f64),
    approach: f64,
    /// Total vertical force over the normal forces' vertical part.
    total_ratio: f64,
    lattice: Lattice,
    pressure: Vec<f64>,
}

impl Memory {
    /// The remembered pressure at the cells of `lat` (same patch coordinates; zero outside).
    fn pressure_on(&self, lat: &Lattice) -> Option<Vec<f64>> {
        let m = &self.lattice;
        if (m.hx - lat.hx).abs() > 1e-12 * m.hx || (m.hs - lat.hs).abs() > 1e-12 * m.hs {
            return None;
        }
        let mut out = vec![0.0; lat.len()];
        for j in 0..lat.ns {
            let jm = ((lat.s(j) - m.s0) / m.hs).floor();
            if jm < 0.0 || jm as usize >= m.ns {
                continue;
            }
            for i in 0..lat.nx {
                let im = ((lat.x(i) - m.x0) / m.hx).floor();
                if im >= 0.0 && (im as usize) < m.nx {
                    out[j * lat.nx + i] = self.pressure[jm as usize * m.nx + im as usize];
                }
            }
        }
        out.iter().any(|&p| p > 0.0).then_some(out)
    }
}

impl Working {
    /// The geometry of a patch with the wheel at height `wheel.z`.
    fn new(
        rail: &PlacedRail<'_>,
        wheel: &PlacedWheel<'_>,
        z: f64,
        frame: Frame,
        lattice: Lattice,
        band: (f64, f64),
    ) -> Result<Self> {
        let (nr, rail_t) = patch::rail_column(rail, &frame, &lattice)?;
        let masked = (0..lattice.ns)
            .map(|j| {
                let y = frame.global([0.0, lattice.s(j), nr[j]]).y;
                y < band.0 || y > band.1
            })
            .collect();
        let (nw, dnw) = patch::wheel_layer(wheel, &frame, &lattice)?;
        let n = lattice.len();
        Ok(Self {
            frame,
            lattice,
            band,
            z_base: z,
            nr,
            rail_t,
            masked,
            nw,
            dnw,
            gap: vec![0.0; n],
            sol: None,
            region: (frame.origin.y, frame.origin.x, frame.delta),
            predicted: false,
            warm: None,
        })
    }

    /// The gap at height `z`: the wheel moved rigidly by $\Delta z$ along track $z$, i.e. by
    /// $\Delta z\sin\delta$ along $s$ and $\Delta z\cos\delta$ along $n$, so
    /// $n_{wheel}(x, s; z) = n_{wheel}(x, s - \Delta z\sin\delta; z_b) + \Delta z\cos\delta$,
    /// the shifted value from the cubic Hermite interpolant of the cell values and slopes
    /// along $s$ (error of order $h_s^4\,\partial^4 n/\partial s^4$, below $10^{-11}$ m for
    /// profile radii above 10 mm at 0.2 mm cells).
    fn gap_at(&mut self, z: f64) {
        let lat = self.lattice;
        let dz = z - self.z_base;
        let (sd, cd) = self.frame.delta.sin_cos();
        let shift = dz * sd / lat.hs;
        let (nx, ns, hs) = (lat.nx, lat.ns, lat.hs);
        for j in 0..ns {
            let u = j as f64 - shift;
            let k = u.floor();
            let tau = u - k;
            for i in 0..nx {
                let w = if k >= 0.0 && (k as usize) + 1 < ns {
                    let k = k as usize;
                    let (f0, f1) = (self.nw[k * nx + i], self.nw[(k + 1) * nx + i]);
                    let (m0, m1) = (self.dnw[k * nx + i] * hs, self.dnw[(k + 1) * nx + i] * hs);
                    let (t2, t3) = (tau * tau, tau * tau * tau);
                    (2.0 * t3 - 3.0 * t2 + 1.0) * f0
                        + (t3 - 2.0 * t2 + tau) * m0
                        + (-2.0 * t3 + 3.0 * t2) * f1
                        + (t3 - t2) * m1
                } else {
                    // Beyond the lattice: the tangent of the end row.
                    let e = if k < 0.0 { 0 } else { ns - 1 };
                    self.nw[e * nx + i] + (u - e as f64) * hs * self.dnw[e * nx + i]
                };
                let g = self.nr[j] - (w + dz * cd);
                self.gap[j * nx + i] = if self.masked[j] { g.max(MASKED_GAP) } else { g };
            }
        }
    }
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

    fn solve_here(
        &self,
        position: &Position,
        motion: &Motion,
        load: VerticalLoad,
        tangential: Tangential,
        cache: &mut Cache,
    ) -> Result<Solution> {
        let t_start = Instant::now();
        position.validate()?;
        if !matches!(tangential, Tangential::None) {
            motion.validate()?;
        }
        match load {
            VerticalLoad::Force(f) | VerticalLoad::TotalForce(f) => {
                crate::error::positive("load.normal", f)?
            }
            VerticalLoad::Approach(d) => crate::error::positive("load.approach", d)?,
        };
        let total = match (load, tangential) {
            (VerticalLoad::TotalForce(f), t) if !matches!(t, Tangential::None) => Some(f),
            _ => None,
        };
        let load = match load {
            VerticalLoad::TotalForce(f) => VerticalLoad::Force(f),
            l => l,
        };
        let mut info = SolveInfo::default();
        let pos = self.right_position(position);
        let motion_r = if self.side == Side::Left { motion.mirrored() } else { *motion };
        let rail = self.rail();
        let wheel0 = PlacedWheel::new(&self.wheelset, &pos, 0.0);
        let t0 = Instant::now();
        let s0 = search(&rail, &wheel0)?;
        if !s0.min_gap.is_finite() || s0.min_gap > MAX_NOMINAL_GAP {
            return Err(Error::NoContact {
                min_gap: s0.min_gap,
                y: self.side.sign() * s0.y[s0.k_min],
                overlap: true,
            });
        }
        let z_touch = s0.min_gap;
        // The previous position's patches: the first guesses of this one.
        let memory = std::mem::take(&mut cache.memory);
        let ratio = match (total, memory.first()) {
            (Some(_), Some(m)) => m.total_ratio,
            _ => 1.0,
        };
        let load = match load {
            VerticalLoad::Force(f) => VerticalLoad::Force(f / ratio),
            l => l,
        };
        let estimate = match (load, memory.first()) {
            (VerticalLoad::Approach(d), _) => d,
            (_, Some(m)) => m.approach,
            (VerticalLoad::Force(f) | VerticalLoad::TotalForce(f), None) => {
                self.estimate_approach(&rail, &wheel0, &s0, f)?
            }
        };
        info.geometry_seconds += t0.elapsed().as_secs_f64();
        let mut z_layout = z_touch + 1.3 * estimate;
        let mut z_start = z_touch + estimate;
        let (z, mut patches) = loop {
            info.layouts += 1;
            let mut patches =
                self.layout(&rail, &wheel0, &s0, z_start, z_layout, &memory, &mut info)?;
            let predicted = !patches.is_empty() && patches.iter().all(|p| p.predicted);
            let mut z =
                self.height(&mut patches, load, z_touch, z_start, predicted, cache, &mut info)?;
            patches.retain(|p| p.sol.as_ref().is_some_and(|s| !s.no_contact));
            let tg = Instant::now();
            let moved: Vec<Option<(f64, f64, f64)>> =
                patches.iter().map(|p| self.off_centre(&rail, p)).collect::<Result<_>>()?;
            info.geometry_seconds += tg.elapsed().as_secs_f64();
            info.frames_moved += moved.iter().filter(|m| m.is_some()).count();
            if moved.iter().any(Option::is_some) {
                // Once more, in the frame of each patch's pressure centroid.
                let tg = Instant::now();
                let wheel = wheel0.at_height(z);
                patches = patches
                    .into_iter()
                    .zip(moved)
                    .map(|(p, m)| match m {
                        Some(c) => self.refine(&rail, &wheel, z, p, c),
                        None => Ok(p),
                    })
                    .collect::<Result<_>>()?;
                info.geometry_seconds += tg.elapsed().as_secs_f64();
                z = self.height(&mut patches, load, z_touch, z, true, cache, &mut info)?;
            } else if !predicted {
                // The frames stand; the first pass's looser tolerances are tightened.
                z = self.height(&mut patches, load, z_touch, z, true, cache, &mut info)?;
            }
            // The interpenetration at the final height must stay inside every lattice.
            let inside = patches.iter().all(|p| !touches_border(&p.gap, &p.lattice));
            if inside || info.layouts >= 6 {
                break (z, patches);
            }
            z_layout = z + 0.6 * (z - z_touch);
            z_start = z;
        };
        // Keep the patches that carry load.
        patches.retain(|p| p.sol.as_ref().is_some_and(|s| !s.no_contact));
        let mut z = z;
        let mut tang =
            self.tangential_all(&wheel0.at_height(z), &patches, &motion_r, tangential, &mut info)?;
        if let (Some(target), [_]) = (total, patches.as_slice()) {
            // One patch: the total vertical force G(Fn) = Fn cos d + Fs(Fn) sin d, secant on
            // the normal force, each trial a force-controlled normal solve and a tangential
            // solve (Fs grows about in proportion to Fn: the first slope).
            let (sd, cd) = patches[0].frame.delta.sin_cos();
            let mut fnt = patches[0].sol.as_ref().map_or(0.0, |s| s.force);
            let mut g = fnt * cd + tang[0].fs() * sd - target;
            let mut slope = cd + tang[0].fs() / fnt.max(f64::MIN_POSITIVE) * sd;
            let mut converged = false;
            for _ in 0..MAX_LOAD_ITERATIONS {
                info.load_residual = g.abs() / target;
                if info.load_residual <= self.load_tolerance {
                    converged = true;
                    break;
                }
                let step = if slope > 0.0 { -g / slope } else { -g / cd };
                let fnew = (fnt + step).max(0.05 * fnt);
                z = self.force_patch(
                    &mut patches[0],
                    fnew,
                    z,
                    self.normal_tolerance,
                    cache,
                    &mut info,
                )?;
                tang = self.tangential_all(
                    &wheel0.at_height(z),
                    &patches,
                    &motion_r,
                    tangential,
                    &mut info,
                )?;
                let gnew = fnew * cd + tang[0].fs() * sd - target;
                if fnew != fnt {
                    slope = (gnew - g) / (fnew - fnt);
                }
                (fnt, g) = (fnew, gnew);
            }
            if !converged {
                return Err(Error::NotConverged {
                    iterations: MAX_LOAD_ITERATIONS,
                    residual: info.load_residual,
                });
            }
        } else if let Some(target) = total {
            // The total vertical force: secant on F^(2/3) in the height, each trial with the
            // normal solves (approach control, warm) and the tangential solves.
            let vertical = |patches: &[Working], tang: &[Tangent]| {
                patches
                    .iter()
                    .zip(tang)
                    .map(|(p, t)| {
                        let (sd, cd) = p.frame.delta.sin_cos();
                        p.sol.as_ref().map_or(0.0, |s| s.force) * cd + t.fs() * sd
                    })
                    .sum::<f64>()
            };
            let g_target = target.powf(2.0 / 3.0);
            let mut prev = (z_touch, 0.0);
            let mut converged = false;
            for _ in 0..MAX_LOAD_ITERATIONS {
                let f = vertical(&patches, &tang);
                info.load_residual = (f - target).abs() / target;
                if info.load_residual <= self.load_tolerance {
                    converged = true;
                    break;
                }
                let g = f.max(0.0).powf(2.0 / 3.0);
                let slope = if g != prev.1 { (z - prev.0) / (g - prev.1) } else { 0.0 };
                prev = (z, g);
                let mut zn = z + (g_target - g) * slope;
                if !zn.is_finite() || zn <= z_touch || slope <= 0.0 {
                    zn = z_touch
                        + (z - z_touch)
                            * (target / f.max(f64::MIN_POSITIVE)).powf(2.0 / 3.0).min(4.0);
                }
                z = zn;
                for p in patches.iter_mut() {
                    self.normal_patch(
                        p,
                        z,
                        NormalLoad::Approach(0.0),
                        self.normal_tolerance,
                        cache,
                        &mut info,
                    )?;
                }
                info.load_iterations += 1;
                tang = self.tangential_all(
                    &wheel0.at_height(z),
                    &patches,
                    &motion_r,
                    tangential,
                    &mut info,
                )?;
            }
            if !converged {
                return Err(Error::NotConverged {
                    iterations: MAX_LOAD_ITERATIONS,
                    residual: info.load_residual,
                });
            }
        }
        let normal_vertical: f64 = patches
            .iter()
            .map(|p| p.sol.as_ref().map_or(0.0, |s| s.force) * p.frame.delta.cos())
            .sum();
        let all_vertical: f64 = normal_vertical
            + patches.iter().zip(&tang).map(|(p, t)| t.fs() * p.frame.delta.sin()).sum::<f64>();
        cache.memory = patches
            .iter()
            .filter_map(|p| {
                let sol = p.sol.as_ref()?;
                Some(Memory {
                    region: p.region,
                    offset: (
                        p.frame.origin.y - p.region.0,
                        p.frame.origin.x - p.region.1,
                        p.frame.delta - p.region.2,
                    ),
                    approach: z - z_touch,
                    total_ratio: if normal_vertical > 0.0 {
                        all_vertical / normal_vertical
                    } else {
                        1.0
                    },
                    lattice: p.lattice,
                    pressure: sol.pressure.clone(),
                })
            })
            .collect();
        let mut out = Vec::with_capacity(patches.len());
        for (p, t) in patches.into_iter().zip(tang) {
            out.push(self.finish_patch(&rail, p, t));
        }
        let mut sum = [0.0; 3];
        for p in &out {
            for (t, f) in sum.iter_mut().zip(p.force_on_rail) {
                *t += f;
            }
        }
        info.total_seconds = t_start.elapsed().as_secs_f64();
        Ok(Solution {
            side: self.side,
            z_wheelset: z,
            approach: z - z_touch,
            total_on_rail: sum,
            patches: out,
            info,
        })
    }

    /// Flange climb: a wheel contact point on the flange side of its steepest point and
    /// within `band` of the flange tip's height ([`FLANGE_TIP_BAND`]). A wheel without a
    /// flange (no face steeper than [`FLANGE_MIN_ANGLE`]) cannot climb.
    fn check_climb(&self, w: [f64; 2], band: f64) -> Result<()> {
        let (ys, angle) = self.wheelset.flange();
        if angle < FLANGE_MIN_ANGLE {
            return Ok(());
        }
        let (wy, wz) = self.wheelset.wheel().points();
        let (ktip, ztip) = wz.iter().copied().enumerate().fold((0, f64::NEG_INFINITY), |a, b| {
            if b.1 > a.1 {
                b
            } else {
                a
            }
        });
        if w[0] < ys && ztip - w[1] < band {
            return Err(Error::FlangeClimb {
                what: format!(
                    "the wheel touches the rail at (y_w, z_w) = ({:.4e}, {:.4e}) m of its profile, {:.3e} m below its flange tip (y_w = {:.4e} m), beyond the flange's steepest point (flange angle {:.4} rad)",
                    self.side.sign() * w[0],
                    w[1],
                    ztip - w[1],
                    self.side.sign() * wy[ktip],
                    angle
                ),
            });
        }
        Ok(())
    }

    /// The kinematics and tangential solution of every patch with the wheel at its height.
    fn tangential_all(
        &self,
        wheel: &PlacedWheel<'_>,
        patches: &[Working],
        motion: &Motion,
        tangential: Tangential,
        info: &mut SolveInfo,
    ) -> Result<Vec<Tangent>> {
        patches.iter().map(|p| self.tangential_patch(wheel, p, motion, tangential, info)).collect()
    }

    /// A Hertz estimate of the vertical approach under the load `f`, from the curvatures of
    /// the two profiles at the first touch.
    fn estimate_approach(
        &self,
        rail: &PlacedRail<'_>,
        wheel: &PlacedWheel<'_>,
        s: &Search,
        f: f64,
    ) -> Result<f64> {
        let k = s.k_min;
        let (_, d1, d2) = rail.at(s.rail_t[k]);
        let slope = d1[1] / d1[0];
        let zr2 = (d2[1] * d1[0] - d1[1] * d2[0]) / d1[0].powi(3);
        let (theta, _) = wheel.lowest(0.0);
        let tw = s.wheel_t[k];
        let h = 1e-4;
        let locus = |t: f64| {
            let w = wheel.point(t, theta).w;
            (w.y, w.z)
        };
        let (a, b, c) = (locus(tw - h), locus(tw), locus(tw + h));
        let (dy1, dz1) = ((c.0 - a.0) / (2.0 * h), (c.1 - a.1) / (2.0 * h));
        let (dy2, dz2) = ((c.0 - 2.0 * b.0 + a.0) / (h * h), (c.1 - 2.0 * b.1 + a.1) / (h * h));
        let zw2 = (dz2 * dy1 - dz1 * dy2) / dy1.powi(3);
        let cosd = 1.0 / (1.0 + slope * slope).sqrt();
        let rho = wheel.point(tw, theta).rho;
        let kx = cosd / rho;
        let ks = ((zr2 - zw2) * cosd.powi(3)).max(2.0);
        let e_star = composite_modulus(&self.bodies[0], &self.bodies[1]);
        let hz = HertzEllipse::from_curvatures(kx, ks, f / cosd, e_star)?;
        Ok(hz.approach() / cosd)
    }

    /// Lay out the patches: frames from the interpenetration regions with the wheel at
    /// height `z_frame`, lattices holding the interpenetration at the deeper `z_lattice`.
    fn layout(
        &self,
        rail: &PlacedRail<'_>,
        wheel0: &PlacedWheel<'_>,
        s0: &Search,
        z_frame: f64,
        z_lattice: f64,
        memory: &[Memory],
        info: &mut SolveInfo,
    ) -> Result<Vec<Working>> {
        let tg = Instant::now();
        // Gaps on the search lines move with the wheel: g(z) = g(0) - z.
        let at = |z: f64| {
            let mut s = s0.clone();
            s.gap.iter_mut().for_each(|g| *g -= z);
            s
        };
        let (sf, sl) = (at(z_frame), at(z_lattice));
        let regions = sl.regions();
        let wheel = wheel0.at_height(z_lattice);
        let n = sl.y.len();
        let mut out = Vec::with_capacity(regions.len());
        for (r, reg) in regions.iter().enumerate() {
            if reg.k0 == 0 || reg.k1 + 1 == n {
                return Err(Error::FlangeClimb {
                    what: format!(
                        "the interpenetration reaches the end of the profiles' common lateral range at y = {:.4e} m",
                        self.side.sign() * sl.y[if reg.k0 == 0 { 0 } else { n - 1 }]
                    ),
                });
            }
            let lo = if r == 0 {
                f64::NEG_INFINITY
            } else {
                0.5 * (sl.y[regions[r - 1].k1] + sl.y[reg.k0])
            };
            let hi = if r + 1 == regions.len() {
                f64::INFINITY
            } else {
                0.5 * (sl.y[reg.k1] + sl.y[regions[r + 1].k0])
            };
            // The frame: the region's interpenetration at the expected height if it has one
            // there, else at the lattice height.
            let inner = sf.regions().into_iter().find(|q| q.k0 <= reg.k1 && q.k1 >= reg.k0);
            let (_yc, tr, tw, xw) = match inner {
                Some(q) => sf.centre(q),
                None => sl.centre(*reg),
            };
            // On the flange tip already at the layout height: refused before any solve.
            self.check_climb(self.wheelset.wheel().eval(tw).p, 0.3 * FLANGE_TIP_BAND)?;
            let (p, d1, _) = rail.at(tr);
            let (theta, _) = wheel.lowest(0.0);
            let wp = wheel.point(tw, theta);
            let delta = 0.5 * (d1[1].atan2(d1[0]) + wp.dt.z.atan2(wp.dt.y));
            let region = (p[0], xw, delta);
            // The previous position's patch nearest this region, if near enough.
            let remembered =
                memory.iter().filter(|m| (m.region.0 - region.0).abs() < MEMORY_MATCH).min_by(
                    |a, b| (a.region.0 - region.0).abs().total_cmp(&(b.region.0 - region.0).abs()),
                );
            let frame = match remembered {
                Some(m) => {
                    // Its frame's offsets from its region's centre, on this region.
                    let y = region.0 + m.offset.0;
                    let mut t = tr;
                    for _ in 0..30 {
                        let (q, d, _) = rail.at(t);
                        let step = (q[0] - y) / d[0];
                        t -= step;
                        if step.abs() < 1e-15 {
                            break;
                        }
                    }
                    let q = rail.at(t).0;
                    Frame::new(
                        Vector3::new(xw + m.offset.1, q[0], q[1]),
                        delta + m.offset.2,
                        t,
                        tw,
                        theta,
                    )
                }
                None => Frame::new(Vector3::new(xw, p[0], p[1]), delta, tr, tw, theta),
            };
            // The lattice: the bounding box, in the patch frame, of the interpenetration on
            // the search lines (at line k it spans x = x_k -+ sqrt(2 d_k rho_k) along the wheel's
            // circle of radius rho_k), plus the margin; grown if the gap says it is short.
            let (hx, hs) = self.cell;
            let (mut x0, mut x1, mut s0, mut s1) =
                (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
            let r0 = self.wheelset.wheel_radius();
            for k in reg.k0..=reg.k1 {
                let d = -sl.gap[k];
                if d <= 0.0 {
                    continue;
                }
                let rho = r0 + self.wheelset.wheel().eval(sl.wheel_t[k]).p[1];
                let h = (2.0 * d * rho).sqrt();
                let xc = sl.wheel_x[k] - frame.origin.x;
                let q = rail.at(sl.rail_t[k]).0;
                let sk = frame.local(&Vector3::new(0.0, q[0], q[1]))[1];
                (x0, x1, s0, s1) = (x0.min(xc - h), x1.max(xc + h), s0.min(sk), s1.max(sk));
            }
            if !x0.is_finite() {
                (x0, x1, s0, s1) = (-hx, hx, -hs, hs);
            }
            let mut extra = 0.0;
            let mut w = loop {
                let (mx, ms) = (
                    (LATTICE_MARGIN as f64 + 0.5) * hx + extra * (x1 - x0),
                    (LATTICE_MARGIN as f64 + 0.5) * hs + extra * (s1 - s0),
                );
                let round =
                    |n: f64| ((n / LATTICE_ROUND as f64).ceil() as usize).max(1) * LATTICE_ROUND;
                let (nx, ns) = (round((x1 - x0 + 2.0 * mx) / hx), round((s1 - s0 + 2.0 * ms) / hs));
                let lat = Lattice {
                    nx,
                    ns,
                    hx,
                    hs,
                    x0: 0.5 * (x0 + x1) - 0.5 * nx as f64 * hx,
                    s0: 0.5 * (s0 + s1) - 0.5 * ns as f64 * hs,
                };
                let mut w = Working::new(rail, &wheel, z_lattice, frame, lat, (lo, hi))?;
                w.gap_at(z_lattice);
                if !touches_border(&w.gap, &lat) || extra > 2.0 {
                    break w;
                }
                extra = 2.0 * extra + 0.25;
            };
            w.gap_at(z_lattice);
            w.region = region;
            if let Some(m) = remembered {
                w.predicted = true;
                w.warm = m.pressure_on(&w.lattice);
            }
            out.push(w);
        }
        info.geometry_seconds += tg.elapsed().as_secs_f64();
        Ok(out)
    }

    /// The pressure centroid $(\bar x, \bar s)$ of a solved patch in its frame and the
    /// pressure-weighted mean inclination of the rail surface, if they are further from the
    /// frame than [`FRAME_ACCEPT`] allows.
    fn off_centre(&self, rail: &PlacedRail<'_>, p: &Working) -> Result<Option<(f64, f64, f64)>> {
        let Some(sol) = &p.sol else { return Ok(None) };
        let lat = p.lattice;
        let (mut ps, mut px, mut pss, mut pa) = (0.0, 0.0, 0.0, 0.0);
        for j in 0..lat.ns {
            let (_, d1, _) = rail.at(p.rail_t[j]);
            let angle = d1[1].atan2(d1[0]);
            for i in 0..lat.nx {
                let pr = sol.pressure[j * lat.nx + i];
                ps += pr;
                px += pr * lat.x(i);
                pss += pr * lat.s(j);
                pa += pr * angle;
            }
        }
        if ps <= 0.0 {
            return Ok(None);
        }
        let (xb, sb, delta) = (px / ps, pss / ps, pa / ps);
        let (fx, fs, fd) = FRAME_ACCEPT;
        let off =
            xb.abs() > fx * lat.hx || sb.abs() > fs * lat.hs || (delta - p.frame.delta).abs() > fd;
        Ok(off.then_some((xb, sb, delta)))
    }

    /// The patch once more with its frame at the pressure centroid $(\bar x, \bar s)$ and the
    /// pressure-weighted mean inclination of the rail surface as its contact angle
    /// ([`WheelRail::off_centre`]); the lattice keeps its size and moves with the frame, so
    /// the pressure carries over cell by cell as the next warm start.
    fn refine(
        &self,
        rail: &PlacedRail<'_>,
        wheel: &PlacedWheel<'_>,
        z: f64,
        p: Working,
        centroid: (f64, f64, f64),
    ) -> Result<Working> {
        let lat = p.lattice;
        let (xb, sb, delta) = centroid;
        // The rail point at s = sb in the old frame.
        let probe =
            Lattice { nx: 1, ns: 1, hx: lat.hx, hs: lat.hs, x0: 0.0, s0: sb - 0.5 * lat.hs };
        let (nr, tr) = patch::rail_column(rail, &p.frame, &probe)?;
        let origin = p.frame.global([xb, sb, nr[0]]);
        let w = patch::wheel_point(wheel, &p.frame, xb, sb, (p.frame.wheel_t, p.frame.wheel_theta))
            .ok_or_else(|| Error::FlangeClimb {
                what: "the wheel surface cannot be followed at the pressure centroid".to_string(),
            })?;
        let frame = Frame::new(origin, delta, tr[0], w.t, w.theta);
        let moved = Lattice { x0: lat.x0 - xb, s0: lat.s0 - sb, ..lat };
        let mut out = Working::new(rail, wheel, z, frame, moved, p.band)?;
        out.gap_at(z);
        out.sol = p.sol;
        out.region = p.region;
        Ok(out)
    }

    /// One patch pressed with the normal force `fn_target`: the normal solver's force
    /// control gives the approach $\delta_n$ still missing, which moves the wheelset by
    /// $\delta_n/\cos\delta$; the move is accepted without another solve when its tangential
    /// part $\delta_n\tan\delta$ changes the gap over the contact by less than
    /// [`HEIGHT_CONSISTENCY`] of the interpenetration. Returns the height.
    fn force_patch(
        &self,
        p: &mut Working,
        fn_target: f64,
        z_start: f64,
        ntol: f64,
        cache: &mut Cache,
        info: &mut SolveInfo,
    ) -> Result<f64> {
        let (sd, cd) = p.frame.delta.sin_cos();
        let mut z = z_start;
        for _ in 0..MAX_LOAD_ITERATIONS {
            self.normal_patch(p, z, NormalLoad::Force(fn_target), ntol, cache, info)?;
            info.load_iterations += 1;
            let sol = p.sol.as_ref().expect("solved");
            let scale = -p.gap.iter().copied().fold(0.0, f64::min) + sol.approach.abs();
            let slope = sol
                .contact
                .iter()
                .zip(&p.dnw)
                .filter(|(c, _)| **c)
                .fold(0.0f64, |m, (_, d)| m.max(d.abs()));
            z += sol.approach / cd;
            info.load_residual = 0.0;
            if (sol.approach / cd * sd).abs() * slope <= HEIGHT_CONSISTENCY * scale {
                return Ok(z);
            }
        }
        Err(Error::NotConverged { iterations: MAX_LOAD_ITERATIONS, residual: f64::NAN })
    }

    /// Solve the normal contact of one patch at height `z`.
    fn normal_patch(
        &self,
        p: &mut Working,
        z: f64,
        load: NormalLoad,
        tolerance: f64,
        cache: &mut Cache,
        info: &mut SolveInfo,
    ) -> Result<()> {
        let tg = Instant::now();
        p.gap_at(z);
        info.geometry_seconds += tg.elapsed().as_secs_f64();
        let tn = Instant::now();
        let lat = p.lattice;
        let tol = Tolerance::relative(tolerance).map_err(|_| Error::OutOfDomain {
            name: "normal tolerance",
            value: tolerance,
            allowed: "a valid relative tolerance",
        })?;
        let pb = NormalProblem::new(
            lat.nx,
            lat.ns,
            (lat.hx, lat.hs),
            &p.gap,
            self.bodies,
            Boundary::Free,
        )?
        .with_origin((lat.x0, lat.s0))
        .with_tolerance(tol)
        .with_min_contact_cells(1);
        let warm = match p.sol.as_ref().filter(|s| !s.no_contact) {
            Some(s) => Some(s.pressure.clone()),
            None => p.warm.take(),
        };
        let op = cache.operator(&pb);
        let sol = pb.solve_with(op, load, warm.as_deref())?;
        info.normal_solves += 1;
        info.normal_iterations += sol.info.iterations;
        info.normal_products += sol.info.products;
        info.normal_seconds += tn.elapsed().as_secs_f64();
        p.sol = Some(sol);
        Ok(())
    }

    /// The wheelset height under `load` (module docs). One patch under a force: the normal
    /// solver's force control gives the approach $\delta_n$ still missing, which moves the
    /// wheelset by $\delta_n/\cos\delta$; the move is accepted without another solve when
    /// its tangential part $\delta_n\tan\delta$ changes the gap over the contact by less
    /// than the tolerance (relative to the interpenetration). Several patches: approach
    /// control at trial heights, secant on $F^{2/3}$. The first pass (`final_pass` false,
    /// before the frames move to the pressure centroids) uses looser tolerances
    /// ([`FIRST_PASS_TOLERANCE`]).
    #[allow(clippy::too_many_arguments)]
    fn height(
        &self,
        patches: &mut [Working],
        load: VerticalLoad,
        z_touch: f64,
        z_start: f64,
        final_pass: bool,
        cache: &mut Cache,
        info: &mut SolveInfo,
    ) -> Result<f64> {
        let (ntol, ltol) = if final_pass {
            (self.normal_tolerance, self.load_tolerance)
        } else {
            (
                self.normal_tolerance.max(FIRST_PASS_TOLERANCE),
                self.load_tolerance.max(FIRST_PASS_TOLERANCE),
            )
        };
        let target = match load {
            VerticalLoad::Approach(d) => {
                for p in patches.iter_mut() {
                    self.normal_patch(
                        p,
                        z_touch + d,
                        NormalLoad::Approach(0.0),
                        ntol,
                        cache,
                        info,
                    )?;
                }
                info.load_iterations += 1;
                return Ok(z_touch + d);
            }
            VerticalLoad::Force(f) | VerticalLoad::TotalForce(f) => f,
        };
        if let [p] = patches {
            let cd = p.frame.delta.cos();
            return self.force_patch(p, target / cd, z_start, ntol, cache, info);
        }
        let g_target = target.powf(2.0 / 3.0);
        let mut z = z_start;
        let mut prev = (z_touch, 0.0);
        let mut residual = f64::INFINITY;
        for _ in 0..MAX_LOAD_ITERATIONS {
            let mut f = 0.0;
            for p in patches.iter_mut() {
                self.normal_patch(p, z, NormalLoad::Approach(0.0), ntol, cache, info)?;
                f += p.sol.as_ref().map_or(0.0, |s| s.force) * p.frame.delta.cos();
            }
            info.load_iterations += 1;
            residual = (f - target).abs() / target;
            info.load_residual = residual;
            if residual <= ltol {
                return Ok(z);
            }
            let g = f.powf(2.0 / 3.0);
            let (zp, gp) = prev;
            let slope = if g != gp { (z - zp) / (g - gp) } else { 0.0 };
            prev = (z, g);
            let mut zn = z + (g_target - g) * slope;
            // Safeguards: stay above first touch, and move if the secant stalls.
            if !zn.is_finite() || zn <= z_touch || slope <= 0.0 {
                zn = z_touch
                    + (z - z_touch) * (target / f.max(f64::MIN_POSITIVE)).powf(2.0 / 3.0).min(4.0);
            }
            z = zn;
        }
        Err(Error::NotConverged { iterations: MAX_LOAD_ITERATIONS, residual })
    }

    /// The wheel point at the reference, the flange-climb check, the creepages and the
    /// tangential solution of one patch.
    fn tangential_patch(
        &self,
        wheel: &PlacedWheel<'_>,
        p: &Working,
        motion: &Motion,
        tangential: Tangential,
        info: &mut SolveInfo,
    ) -> Result<Tangent> {
        let f = p.frame;
        let sol = p.sol.as_ref().expect("solved patches only");
        let q = patch::wheel_point(wheel, &f, 0.0, 0.0, (f.wheel_t, f.wheel_theta)).ok_or_else(
            || Error::FlangeClimb {
                what: "the wheel surface cannot be followed at the reference point".to_string(),
            },
        )?;
        let qw = self.wheelset.wheel().eval(q.t).p;
        let qpt = f.global([0.0, 0.0, q.n]);
        self.check_climb(qw, FLANGE_TIP_BAND)?;
        let tt = Instant::now();
        let (creep, vr, rolling, axes) = match tangential {
            Tangential::None => (Creepage::default(), 0.0, None, None),
            t => {
                let (creep, vr) = creepages(wheel, motion, &f, &qpt)?;
                let grid = sol.contact_grid()?;
                let (r, axes) = match t {
                    Tangential::Exact { tolerance } => (
                        SteadyRolling::new(&grid, self.bodies, self.friction)?
                            .with_tolerance(tolerance)?
                            .solve(&creep)?,
                        None,
                    ),
                    _ => {
                        let (a, b) = fastsim_axes(&grid);
                        let c = Compliance::pair(&self.bodies[0], &self.bodies[1]);
                        let sum = c.one_minus_nu + c.nu;
                        let r = fastsim::solve(
                            &grid,
                            a,
                            b,
                            2.0 / sum,
                            c.nu / sum,
                            self.friction,
                            &creep,
                        )?;
                        (r, Some((a, b)))
                    }
                };
                (creep, vr, Some(r), axes)
            }
        };
        info.tangential_seconds += tt.elapsed().as_secs_f64();
        Ok(Tangent { wheel_point: qw, creep, vr, rolling, fastsim_axes: axes })
    }

    /// The patch's solution as reported, mirrored for a left side.
    fn finish_patch(&self, rail: &PlacedRail<'_>, p: Working, t: Tangent) -> PatchSolution {
        let f = p.frame;
        let sol = p.sol.expect("solved patches only");
        let rail_pt = rail.to_profile([f.origin.y, f.origin.z]);
        let (fx, fs, mn) = t.rolling.as_ref().map_or((0.0, 0.0, 0.0), |r| (r.fx, r.fy, r.mz));
        let force = f.ex * fx + f.es * fs + f.en * sol.force;
        let lattice =
            PatchLattice { nx: sol.nx, ns: sol.ny, hx: sol.hx, hs: sol.hy, origin: sol.origin };
        let mut out = PatchSolution {
            reference: [f.origin.x, f.origin.y, f.origin.z],
            rail_point: rail_pt,
            wheel_point: t.wheel_point,
            contact_angle: f.delta,
            rolling_radius: self.wheelset.wheel_radius() + t.wheel_point[1],
            rolling_speed: t.vr,
            creepage: t.creep,
            normal_force: sol.force,
            fx,
            fs,
            mn,
            pmax: sol.peak_pressure,
            area: sol.area,
            contact_cells: sol.contact_cells,
            stick_fraction: t.rolling.as_ref().map(RollingSolution::stick_fraction),
            fastsim_axes: t.fastsim_axes,
            force_on_rail: [force.x, force.y, force.z],
            lattice,
            gap: p.gap,
            normal: sol,
            rolling: t.rolling,
        };
        if self.side == Side::Left {
            mirror(&mut out);
        }
        out
    }
}

/// A patch's kinematics and tangential solution (right side).
struct Tangent {
    wheel_point: [f64; 2],
    creep: Creepage,
    vr: f64,
    rolling: Option<RollingSolution>,
    fastsim_axes: Option<(f64, f64)>,
}

impl Tangent {
    fn fs(&self) -> f64 {
        self.rolling.as_ref().map_or(0.0, |r| r.fy)
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
/// Trial heights of the vertical-load iteration, at most.
const MAX_LOAD_ITERATIONS: usize = 40;

/// Mirror a right-side patch solution into the left side (module [`crate::placement`]).
fn mirror(p: &mut PatchSolution) {
    p.reference[1] = -p.reference[1];
    p.rail_point[0] = -p.rail_point[0];
    p.wheel_point[0] = -p.wheel_point[0];
    p.contact_angle = -p.contact_angle;
    p.creepage.lateral = -p.creepage.lateral;
    p.creepage.spin = -p.creepage.spin;
    p.fs = -p.fs;
    p.mn = -p.mn;
    p.force_on_rail[1] = -p.force_on_rail[1];
    // Lattices: s -> -s reverses the rows.
    let (nx, ns) = (p.lattice.nx, p.lattice.ns);
    let flip = |v: &mut Vec<f64>| {
        let old = v.clone();
        for j in 0..ns {
            v[j * nx..(j + 1) * nx].copy_from_slice(&old[(ns - 1 - j) * nx..(ns - j) * nx]);
        }
    };
    let s0 = -(p.lattice.origin.1 + ns as f64 * p.lattice.hs);
    p.lattice.origin.1 = s0;
    flip(&mut p.gap);
    let n = &mut p.normal;
    n.origin.1 = s0;
    flip(&mut n.pressure);
    flip(&mut n.gap);
    let old = n.contact.clone();
    for j in 0..ns {
        n.contact[j * nx..(j + 1) * nx].copy_from_slice(&old[(ns - 1 - j) * nx..(ns - j) * nx]);
    }
    if let Some(r) = &mut p.rolling {
        r.y.iter_mut().for_each(|v| *v = -*v);
        r.qy.iter_mut().for_each(|v| *v = -*v);
        r.sy.iter_mut().for_each(|v| *v = -*v);
        r.fy = -r.fy;
        r.mz = -r.mz;
    }
}

/// Whether any cell with negative gap lies on the lattice border.
fn touches_border(g: &[f64], lat: &Lattice) -> bool {
    (0..lat.ns).any(|j| {
        (0..lat.nx).any(|i| {
            (i == 0 || j == 0 || i + 1 == lat.nx || j + 1 == lat.ns) && g[j * lat.nx + i] < 0.0
        })
    })
}

/// The semi-axes $(a, b)$ FASTSIM takes its flexibilities from: the ellipse with the
/// contact's area and the aspect ratio of its extents along $x$ and $s$, $\pi ab = A$,
/// $a/b = L_x/L_s$, the ratio kept within Kalker's table, $0.1 \le a/b \le 10$ (a narrow
/// flange contact can be longer; it is then given the coefficients of $a/b = 10$).
#[must_use]
pub fn fastsim_axes(grid: &ContactGrid) -> (f64, f64) {
    let ext = |v: &[f64]| {
        v.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, &x| (a.0.min(x), a.1.max(x)))
    };
    let (x0, x1) = ext(&grid.x);
    let (y0, y1) = ext(&grid.y);
    let lx = x1 - x0 + grid.hx;
    let ly = y1 - y0 + grid.hy;
    let area = grid.len() as f64 * grid.element_area();
    // Inside the table with a margin for the rounding of a/b.
    let ratio = (lx / ly).clamp(0.1 * (1.0 + 1e-9), 10.0 * (1.0 - 1e-9));
    ((area * ratio / std::f64::consts::PI).sqrt(), (area / (ratio * std::f64::consts::PI)).sqrt())
}
