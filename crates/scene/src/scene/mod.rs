//! The validated scene: every quantity in SI, every value inside what the physics allows.
//!
//! The enums here are exhaustive on purpose: the planner (`stickslip-run`) matches every
//! variant, so a new kind of geometry, body, load or output does not compile until the
//! planner has decided how to serve it.

// Scene errors are built on the cold path of parsing and carry the file, position, key and
// hint for the user; boxing them would buy nothing measurable.
#![allow(clippy::result_large_err)]

use std::ops::Range;
use std::path::{Path, PathBuf};

mod builder;
mod heights;
mod interface;
mod path_file;
pub mod ranges;
pub(crate) mod read;
pub(crate) mod validate;

pub use builder::SceneBuilder;
pub use interface::{AdhesionKeys, ApproachPath, HeightStep, Interface};

use crate::error::{ErrorKind, Issue, SceneError};

/// Contact geometry: what touches what.
#[derive(Debug, Clone, PartialEq)]
pub enum Geometry {
    /// A cylinder of radius R on a half-plane (2D, plane strain; loads per unit length).
    Cylinder {
        /// Radius R (m).
        radius: f64,
    },
    /// A sphere of radius R on a half-space.
    Sphere {
        /// Radius R (m).
        radius: f64,
    },
    /// An elliptical Hertz contact.
    Ellipsoid(Ellipse),
    /// A flat rigid punch of half-width a (2D).
    Punch {
        /// Half-width (m).
        half_width: f64,
    },
    /// Flat patches with given uniform pressures (3D), e.g. a bolted joint's contact areas.
    Patches(Vec<Patch>),
    /// Any surface: the initial gap on a lattice from a profile and roughness (3D); the
    /// pressure follows from the normal-contact solver.
    Surface(Surface),
    /// One wheel of a wheelset on its rail, both given by measured or design profiles
    /// (3D; CONTACT's track coordinates). The rail is the substrate, the wheel the indenter.
    WheelRail(WheelRail),
}

/// A wheel on its rail from profile files (`[geometry] kind = "wheel-rail"` and
/// `[position]`). Lengths in m, angles in rad.
#[derive(Debug, Clone, PartialEq)]
pub struct WheelRail {
    /// Which rail: the left side is the mirror image of the right.
    pub side: RailSide,
    /// The rail profile file.
    pub rail_profile: ProfileFile,
    /// The wheel profile file.
    pub wheel_profile: ProfileFile,
    /// Length of one profile-file unit (m).
    pub profile_unit: f64,
    /// Track gauge (m).
    pub gauge: f64,
    /// Depth below the track plane at which the gauge is measured (m).
    pub gauge_height: f64,
    /// Rail cant (rad).
    pub rail_cant: f64,
    /// Flange back distance of the wheelset (m).
    pub flange_back_distance: f64,
    /// The flange back's position in the wheel profile's own y (m).
    pub flange_back_position: f64,
    /// Nominal wheel radius at the wheel profile's origin (m).
    pub wheel_radius: f64,
    /// The wheelset's position (`[position]`).
    pub position: WheelsetPosition,
    /// What carries the vertical wheel load `load.normal` (`load.vertical`).
    pub vertical: WheelLoadDefinition,
}

/// What carries the vertical wheel load of a wheel on its rail (`load.vertical`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum WheelLoadDefinition {
    /// `"normal"` (the default): the vertical components of the patches' normal forces,
    /// $\sum_p F_{n,p}\cos\delta_p$.
    #[default]
    Normal,
    /// `"total"`: the total vertical force of the wheel on the rail, creep forces included,
    /// $\sum_p (F_{n,p}\cos\delta_p + F_{s,p}\sin\delta_p)$ (CONTACT's force control).
    Total,
}

/// Left or right rail.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RailSide {
    /// The left rail (looking in the rolling direction).
    Left,
    /// The right rail.
    Right,
}

/// A profile file as named in the scene, with its text (read when the scene is read; the
/// planner parses and checks it).
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileFile {
    /// The name as written in the scene.
    pub name: String,
    /// The path it was read from (relative names resolved against the scene's folder).
    pub path: PathBuf,
    /// The file's text.
    pub text: std::sync::Arc<str>,
}

/// The wheelset's position on the track.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WheelsetPosition {
    /// Lateral displacement along y (m).
    pub lateral: f64,
    /// Yaw angle (rad).
    pub yaw: f64,
    /// Roll angle (rad).
    pub roll: f64,
}

/// A surface given on a lattice.
#[derive(Debug, Clone, PartialEq)]
pub struct Surface {
    /// Free (an isolated contact) or periodic (the lattice is one period).
    pub boundary: SurfaceBoundary,
    /// Lattice extent along x and y (m).
    pub size: [f64; 2],
    /// Cells along x and y.
    pub cells: [usize; 2],
    /// The profile of the gap.
    pub profile: Profile,
    /// Roughness heights (m, positive towards the other body), row by row in y
    /// (index `j * nx + i`), added to the profile; None for a smooth surface.
    pub roughness: Option<Vec<f64>>,
}

/// Lateral boundary of a surface lattice.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SurfaceBoundary {
    /// An isolated contact: no periodic images.
    Free,
    /// The lattice is one period of a periodic surface.
    Periodic,
}

/// The smooth part of a surface's initial gap, centred on the lattice.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Profile {
    /// A sphere (relative radius R): $g = r^2/(2R)$.
    Sphere {
        /// Radius (m).
        radius: f64,
    },
    /// An ellipsoid (relative radii in x and y): $g = x^2/(2R_x) + y^2/(2R_y)$.
    Ellipsoid {
        /// Radii (m).
        radii: [f64; 2],
    },
    /// A flat circular punch: $g = 0$ for $r \le$ `radius`, then the parabolic rounded
    /// edge $(r - \text{radius})^2/(2\rho)$, or, with $\rho = 0$, the sharp edge (the
    /// Boussinesq punch, out of reach beyond the face).
    Punch {
        /// Radius of the flat face (m).
        radius: f64,
        /// Edge radius $\rho$ (m); 0 for the sharp edge.
        edge_radius: f64,
    },
    /// A wave of amplitude $\Delta$: $g = \Delta(1-\cos 2\pi x/\lambda)$ along x, or the
    /// sum of that in x and in y.
    Wavy {
        /// Wavelength (m).
        wavelength: f64,
        /// Amplitude (m).
        amplitude: f64,
        /// True for waves in x and y.
        along_xy: bool,
    },
    /// A roller of radius $R$ (in the x-z plane) with its axis along y, of length $L$
    /// centred on the origin: a straight middle part and, when `crown` $c > 0$, ends rounded
    /// by the parabola of radius $\rho$ = `end_radius` over the end length
    /// $l_e = \sqrt{2\rho c}$, so that the surface has dropped by $c$ at the ends:
    /// $$g = \frac{x^2}{2R} + \frac{\max(|y| - (L/2 - l_e), 0)^2}{2\rho}\quad (|y| \le L/2).$$
    /// Beyond the ends ($|y| > L/2$) there is no roller: the gap is $R$ (never closed).
    /// `crown = 0` is the sharp-ended (uncrowned) roller.
    Cylinder {
        /// Radius R (m).
        radius: f64,
        /// Length L (m).
        length: f64,
        /// Crown drop c at the ends (m), 0 for none.
        crown: f64,
        /// End radius $\rho$ (m); unused when the crown is 0.
        end_radius: f64,
    },
    /// A flat surface (roughness only).
    Flat,
}

impl Profile {
    /// The gap of the profile at (x, y) (m).
    pub fn gap(&self, x: f64, y: f64) -> f64 {
        use std::f64::consts::PI;
        match *self {
            Profile::Sphere { radius } => (x * x + y * y) / (2.0 * radius),
            Profile::Ellipsoid { radii } => x * x / (2.0 * radii[0]) + y * y / (2.0 * radii[1]),
            Profile::Punch { radius, edge_radius } => {
                let d = (x.hypot(y) - radius).max(0.0);
                if edge_radius == 0.0 {
                    // The sharp edge: off the face the punch is out of reach. Any height
                    // larger than every approach will do; the face radius is (the planner
                    // keeps the approach below 0.16 of it: 2 d/(pi a) <= 0.1).
                    if d > 0.0 {
                        radius
                    } else {
                        0.0
                    }
                } else {
                    d * d / (2.0 * edge_radius)
                }
            }
            Profile::Wavy { wavelength, amplitude, along_xy } => {
                let k = 2.0 * PI / wavelength;
                let gx = amplitude * (1.0 - (k * x).cos());
                if along_xy {
                    gx + amplitude * (1.0 - (k * y).cos())
                } else {
                    gx
                }
            }
            Profile::Cylinder { radius, length, crown, end_radius } => {
                let half = 0.5 * length;
                if y.abs() > half {
                    return radius;
                }
                let crowned = if crown > 0.0 {
                    let flat = half - (2.0 * end_radius * crown).sqrt();
                    let d = (y.abs() - flat).max(0.0);
                    d * d / (2.0 * end_radius)
                } else {
                    0.0
                };
                x * x / (2.0 * radius) + crowned
            }
            Profile::Flat => 0.0,
        }
    }
}

impl Geometry {
    /// True for plane-strain (per unit length) problems.
    pub fn is_2d(&self) -> bool {
        matches!(self, Geometry::Cylinder { .. } | Geometry::Punch { .. })
    }
}

/// How an elliptical contact is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Ellipse {
    /// The contact semi-axes a (along x) and b (along y), m.
    SemiAxes {
        /// Semi-axis along x (m).
        a: f64,
        /// Semi-axis along y (m).
        b: f64,
    },
    /// The principal relative radii of curvature (m); the semi-axes follow from Hertz.
    Radii {
        /// Radius in the x-z plane (m).
        rx: f64,
        /// Radius in the y-z plane (m).
        ry: f64,
    },
}

/// A flat contact patch with uniform pressure.
#[derive(Debug, Clone, PartialEq)]
pub struct Patch {
    /// Its outline.
    pub shape: PatchShape,
    /// Centre (m).
    pub centre: [f64; 2],
    /// Uniform pressure (Pa), > 0.
    pub pressure: f64,
}

/// Outline of a patch, centred on its `centre`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PatchShape {
    /// Axis-aligned square of this side (m).
    Square {
        /// Side (m).
        side: f64,
    },
    /// Axis-aligned rectangle with sides along x and y (m).
    Rectangle {
        /// Sides along x and y (m).
        sides: [f64; 2],
    },
    /// Circle of this radius (m).
    Circle {
        /// Radius (m).
        radius: f64,
    },
}

impl PatchShape {
    /// Area (m^2).
    pub fn area(&self) -> f64 {
        match *self {
            PatchShape::Square { side } => side * side,
            PatchShape::Rectangle { sides } => sides[0] * sides[1],
            PatchShape::Circle { radius } => std::f64::consts::PI * radius * radius,
        }
    }
}

impl Patch {
    /// Normal force carried by the patch (N).
    pub fn force(&self) -> f64 {
        self.pressure * self.shape.area()
    }

    /// True when the two outlines share a region of positive area (touching edges do not
    /// count: a split contact can have patches that abut).
    pub fn overlaps(&self, other: &Patch) -> bool {
        use PatchShape::*;
        let half = |s: &PatchShape| match *s {
            Square { side } => [side / 2.0; 2],
            Rectangle { sides } => [sides[0] / 2.0, sides[1] / 2.0],
            Circle { radius } => [radius; 2],
        };
        let d = [other.centre[0] - self.centre[0], other.centre[1] - self.centre[1]];
        match (self.shape, other.shape) {
            (Circle { radius: r1 }, Circle { radius: r2 }) => d[0].hypot(d[1]) < r1 + r2,
            (Circle { radius }, rect) | (rect, Circle { radius }) => {
                let (c_circle, c_rect) = if matches!(self.shape, Circle { .. }) {
                    (self.centre, other.centre)
                } else {
                    (other.centre, self.centre)
                };
                let h = half(&rect);
                let dx = (c_circle[0] - c_rect[0]).abs() - h[0];
                let dy = (c_circle[1] - c_rect[1]).abs() - h[1];
                let gap = dx.max(0.0).hypot(dy.max(0.0));
                // inside the rectangle (both negative) or closer than the radius
                (dx < 0.0 && dy < 0.0) || gap < radius
            }
            (a, b) => {
                let (ha, hb) = (half(&a), half(&b));
                d[0].abs() < ha[0] + hb[0] && d[1].abs() < ha[1] + hb[1]
            }
        }
    }
}

/// Bounding box of the patches: (lower-left, upper-right).
pub fn patch_bounds(ps: &[Patch]) -> ([f64; 2], [f64; 2]) {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in ps {
        let h = match p.shape {
            PatchShape::Square { side } => [side / 2.0; 2],
            PatchShape::Rectangle { sides } => [sides[0] / 2.0, sides[1] / 2.0],
            PatchShape::Circle { radius } => [radius; 2],
        };
        for d in 0..2 {
            lo[d] = lo[d].min(p.centre[d] - h[d]);
            hi[d] = hi[d].max(p.centre[d] + h[d]);
        }
    }
    (lo, hi)
}

/// An elastic material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Elastic {
    /// Young's modulus (Pa).
    pub e: f64,
    /// Poisson's ratio, in (-1, 0.5].
    pub nu: f64,
}

/// The body below.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Substrate {
    /// Homogeneous, linear elastic.
    Homogeneous(Elastic),
    /// Power-law graded, E = e0 y^k (Giannakopoulos & Pallot 2000).
    Graded {
        /// E0 in Pa / m^k.
        e0: f64,
        /// Grading exponent, 0 <= k < 1.
        k: f64,
        /// Poisson's ratio, below 1/(1+k).
        nu: f64,
    },
    /// Standard linear solid: eps + alpha eps' = (sigma + beta sigma') / E (Goryacheva 1973).
    Viscoelastic {
        /// Long-time modulus E (Pa) and Poisson's ratio.
        elastic: Elastic,
        /// Retardation time alpha (s).
        alpha: f64,
        /// Relaxation time beta (s), beta <= alpha.
        beta: f64,
    },
}

/// The body above.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Indenter {
    /// Rigid.
    Rigid,
    /// Homogeneous elastic.
    Homogeneous(Elastic),
    /// The same material as the substrate.
    Same,
}

/// How the normal load is prescribed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NormalLoad {
    /// The force P (N/m in 2D, N in 3D).
    Force(f64),
    /// The contact half-width a (m); the force follows.
    HalfWidth(f64),
    /// Given by the patches' pressures.
    FromPatches(f64),
    /// The approach of the two bodies (m): displacement control of a surface.
    Approach(f64),
}

/// Loads and friction.
#[derive(Debug, Clone, PartialEq)]
pub struct Load {
    /// Normal load.
    pub normal: NormalLoad,
    /// Tangential load T (N/m in 2D, N in 3D), along `direction_deg`.
    pub tangential: f64,
    /// Direction of T in degrees from +x.
    pub direction_deg: f64,
    /// Coulomb friction coefficient f >= 0.
    pub friction: f64,
    /// Full sliding: q = f p.
    pub sliding: bool,
    /// Twisting moment about the contact normal (N m, 3D).
    pub moment: f64,
    /// A load sweep up to `normal` (a surface only): the area–load and approach–load curves.
    pub normal_sweep: Option<NormalSweep>,
    /// An approach path (`load.approach = [from, to, steps]`, a surface only); the load is
    /// then `NormalLoad::Approach` of its last corner.
    pub approach_path: Option<ApproachPath>,
    /// `[load.history]`: a load path solved step by step (a static 3D contact).
    pub history: Option<History>,
}

/// `[load.history]`: a load path of corner values applied in order, `steps` linear
/// sub-steps between two corners, each step solved from the one before (Coulomb friction
/// has memory). The tangential value acts along `load.direction_deg`.
#[derive(Debug, Clone, PartialEq)]
pub struct History {
    /// Force control (`tangential`, N) or shift control (`shift`, m).
    pub control: HistoryControl,
    /// Corner values of the tangential force (N) or of the rigid shift (m).
    pub tangential: Vec<f64>,
    /// Corner values of the normal load (N); None: `load.normal` throughout.
    pub normal: Option<Vec<f64>>,
    /// Corner values of the twisting moment (N m); None: no moment (no rotation).
    pub moment: Option<Vec<f64>>,
    /// Sub-steps between two corners (default 10).
    pub steps: usize,
    /// Where the corners were read from, when `file` gave them (for messages).
    pub source: Option<PathSource>,
}

/// The table a load path's corners were read from (`[load.history] file`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PathSource {
    /// The file as opened.
    pub file: std::path::PathBuf,
    /// The 1-based line of each corner's row.
    pub lines: Vec<usize>,
}

impl PathSource {
    /// `" (path.csv:7)"` for corner `i` of a path read from a file, empty otherwise.
    #[must_use]
    pub fn origin(source: Option<&Self>, i: usize) -> String {
        source
            .and_then(|s| s.lines.get(i).map(|l| format!(" ({}:{l})", s.file.display())))
            .unwrap_or_default()
    }
}

/// What a load path prescribes along `load.direction_deg`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HistoryControl {
    /// The tangential force (key `tangential`).
    Force,
    /// The rigid tangential shift of the bodies (key `shift`); beyond the onset of sliding
    /// the contact slides.
    Shift,
}

impl History {
    /// The default number of sub-steps between two corners.
    pub const DEFAULT_STEPS: usize = 10;
    /// The largest number of sub-steps between two corners.
    pub const MAX_STEPS: usize = 10_000;
    /// The largest number of corners.
    pub const MAX_CORNERS: usize = 10_000;

    /// Where corner `i` was written: `" (path.csv:7)"` when the corners came from a file,
    /// empty otherwise (for messages that already name the corner's key).
    #[must_use]
    pub fn corner_origin(&self, i: usize) -> String {
        PathSource::origin(self.source.as_ref(), i)
    }

    /// The normal load at corner `i`: the path's, or `constant` (`load.normal`).
    #[must_use]
    pub fn normal_at(&self, i: usize, constant: f64) -> f64 {
        self.normal.as_ref().map_or(constant, |n| n[i])
    }
}

/// A normal-load sweep from `from` to the scene's `load.normal` in `steps` geometric steps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NormalSweep {
    /// The first force (N).
    pub from: f64,
    /// Number of steps, the first and the last included.
    pub steps: usize,
}

impl NormalSweep {
    /// The forces of the sweep up to `to`: equal ratios from `from` to `to`.
    #[must_use]
    pub fn forces(&self, to: f64) -> Vec<f64> {
        let n = self.steps.max(2);
        (0..n).map(|i| self.from * (to / self.from).powf(i as f64 / (n - 1) as f64)).collect()
    }
}

/// Motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Motion {
    /// No motion beyond the applied loads.
    Static,
    /// Steady rolling.
    Rolling {
        /// Speed w (m/s), > 0.
        speed: f64,
        /// Creep delta = (omega R - w) / w.
        creep: f64,
    },
    /// Steady 3D rolling with longitudinal and lateral creepage and spin.
    RollingCreepage {
        /// Speed V (m/s), > 0.
        speed: f64,
        /// Longitudinal creepage xi (dimensionless).
        longitudinal: f64,
        /// Lateral creepage eta (dimensionless).
        lateral: f64,
        /// Spin creepage phi (1/m).
        spin: f64,
        /// Rolled in time steps from a start state (`[motion.transient]`); the longitudinal
        /// and lateral creepages are then 0 here and follow from the creep force.
        transient: Option<Transient>,
    },
    /// A wheelset rolling along the track (`geometry.kind = "wheel-rail"`): the creepages of
    /// each patch follow from the speed, the pitch rate, the position and the patch.
    Wheelset {
        /// Forward speed V (m/s), > 0.
        speed: f64,
        /// Angular velocity about the axle (rad/s); None: free rolling at the nominal
        /// radius, -V / r0.
        pitch_rate: Option<f64>,
        /// Creepages given directly (`motion.creepage`: longitudinal, lateral, spin in 1/m),
        /// for a position with a single patch, instead of those of the motion.
        creepage: Option<[f64; 3]>,
    },
}

/// Transient 3D rolling (`[motion.transient]`): the contact rolls in steps of one element
/// length under the creep force `load.tangential` (along `load.direction`, on the indenter)
/// or, when `motion.creepage` gives the longitudinal or lateral creepage, at those
/// creepages; the spin creepage with either; from `start`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Transient {
    /// The state the rolling starts from.
    pub start: TransientStart,
    /// Distance rolled (m); None: two contact lengths along x under a creep force, ten under
    /// prescribed creepages.
    pub distance: Option<f64>,
    /// The longitudinal or lateral creepage is given: the contact rolls at the creepages
    /// (the creep force, if any, acts only in the shift at rest).
    pub creepage_control: bool,
}

/// Where transient rolling starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TransientStart {
    /// The creep force is applied at rest first (a Cattaneo shift), then the contact rolls.
    Shift,
    /// The contact rolls from the unloaded state; the creep force acts from the first step.
    Rest,
}

/// A subsurface grid, in units of `scale`: in 2D x and depth y; in 3D a box of x, y and
/// depth z.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldGrid {
    /// x from, to, count.
    pub x: (f64, f64, usize),
    /// 2D: depth y from, to, count (y > 0); 3D: y from, to, count (count 1 with from = to
    /// for a single section).
    pub y: (f64, f64, usize),
    /// 3D only: depth z from, to, count (z > 0).
    pub z: Option<(f64, f64, usize)>,
    /// Unit of x and y.
    pub scale: FieldScale,
}

/// Unit of a field grid's coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FieldScale {
    /// The contact half-width a.
    HalfWidth,
    /// Metres.
    Metres,
}

/// A Mindlin–Deresiewicz loading cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cycle {
    /// Amplitude T*/(fP), in (0, 1].
    pub amplitude: f64,
    /// Points along the loop.
    pub points: usize,
}

/// What to compute beyond the contact solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outputs {
    /// Surface arrays (p, q, displacements, zones).
    pub surface: bool,
    /// Subsurface stresses on a grid.
    pub field: Option<FieldGrid>,
    /// A loading cycle.
    pub cycle: Option<Cycle>,
    /// SVG plots beside the JSON and in report.html (default true).
    pub plots: bool,
}

/// Which method the user asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Let the planner choose.
    Auto,
    /// Closed forms only.
    ClosedForm,
    /// Quadrature of the kernels.
    Quadrature,
    /// The modified LP (seed 002).
    Lp,
    /// The fast FFT solver (in 3D rolling: the exact theory with FFT products).
    Fast,
    /// 3D rolling: Kalker's simplified theory (FASTSIM).
    Fastsim,
    /// 3D rolling: Polach's closed creep-force law (forces only, no spin).
    Polach,
}

/// Solver options.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverOptions {
    /// Requested method.
    pub method: Method,
    /// Elements per side for grid solvers.
    pub grid: usize,
    /// Requested relative tolerance.
    pub tolerance: f64,
    /// The element size [along x, across] of wheel-rail patches (m), when given.
    pub cell: Option<[f64; 2]>,
}

/// A validated scene. Every quantity is SI.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// Title.
    pub title: String,
    /// Where it came from, for messages.
    pub file: Option<PathBuf>,
    /// Geometry.
    pub geometry: Geometry,
    /// The body below.
    pub substrate: Substrate,
    /// The body above.
    pub indenter: Indenter,
    /// Loads.
    pub load: Load,
    /// Motion.
    pub motion: Motion,
    /// Requested outputs.
    pub outputs: Outputs,
    /// Solver options.
    pub solver: SolverOptions,
    /// The interface (`[interface]`; default: elastic, no cap).
    pub interface: Interface,
    /// The text the scene was read from with the span of each value (None when built in
    /// code); used to locate refusals.
    pub source: Option<std::sync::Arc<Source>>,
}

/// The largest grid side the scene format accepts. Whether a grid fits is decided by the
/// planner's memory estimate (its limit is 16 GiB of working memory): a 3D lattice costs
/// about 650 bytes per cell with the fast solver (estimate), so grids of about 5100 per side
/// and more are refused there; this bound only keeps the arithmetic far from overflow.
pub const MAX_GRID: usize = 16384;

/// The built-in default scene: the rigid roller of seed 000, Table 1 (FORMULAS.md A4).
pub const DEFAULT_SCENE: &str = r#"title = "Rigid roller on a power-law graded substrate (seed 000, Table 1)"

[geometry]
kind = "cylinder"
radius = "0.3 m"

[substrate]
model = "graded"
e0 = "1767600 kgf/m^2.1"
k = 0.1
nu = 0.3

[indenter]
model = "rigid"

[load]
half_width = "0.0178 m"
friction = 1.0
sliding = true

[outputs]
surface = true
field = { x = [-1.5, 1.5, 61], y = [0.02, 2.0, 40], scale = "a" }
plots = true
"#;

/// Where a scene came from: its text and the span of every value under its dotted key, so
/// that a refusal found after reading (validation, planning) names the line and column.
#[derive(Debug, Clone, PartialEq)]
pub struct Source {
    text: std::sync::Arc<str>,
    spans: std::collections::BTreeMap<String, Range<usize>>,
    materials: Vec<(String, crate::materials::Material)>,
}

impl Source {
    /// The named materials the scene used, with the table that named each ("substrate",
    /// "indenter").
    pub fn materials(&self) -> &[(String, crate::materials::Material)] {
        &self.materials
    }

    /// The text the scene was read from.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// The span of `key`: the value itself, or (for a key not in the file, or an element of
    /// a list) the nearest enclosing value or table that is.
    pub fn span(&self, key: &str) -> Option<Range<usize>> {
        let mut k = key;
        loop {
            if let Some(s) = self.spans.get(k) {
                return Some(s.clone());
            }
            k = &k[..k.rfind(['.', '['])?];
        }
    }
}

impl Default for SolverOptions {
    /// `auto`, 32 elements per side, relative tolerance 1e-10.
    fn default() -> Self {
        SolverOptions { method: Method::Auto, grid: 32, tolerance: 1e-10, cell: None }
    }
}

impl Scene {
    /// The built-in default scene (seed 000's Table 1 roller).
    pub fn default_scene() -> Scene {
        // The constant is tested to parse; a failure here is a bug in this crate.
        Scene::from_toml_str(DEFAULT_SCENE, None).expect("the built-in default scene is valid")
    }

    /// Read and validate a scene file.
    ///
    /// # Errors
    /// A [`SceneError`] with the file, line, column, key and a hint.
    pub fn from_file(path: &Path) -> Result<Scene, SceneError> {
        let text = std::fs::read_to_string(path).map_err(|e| {
            SceneError::new(ErrorKind::Io, format!("cannot read the scene file: {e}"))
                .in_file(Some(path.to_path_buf()))
                .hint("check the path; `stickslip run` without a file runs the built-in default scene")
        })?;
        Scene::from_toml_str(&text, Some(path.to_path_buf()))
    }

    /// Read a scene from TOML text and validate it ([`Scene::validate`]). `file` is used in
    /// error messages only.
    ///
    /// # Errors
    /// A [`SceneError`] with the line, column, key and a hint.
    pub fn from_toml_str(src: &str, file: Option<PathBuf>) -> Result<Scene, SceneError> {
        let scene = read::read(src, file)?;
        scene.checked()
    }

    /// A builder for a scene in code (SI values), validated by [`SceneBuilder::build`].
    pub fn builder(geometry: Geometry, substrate: Substrate) -> SceneBuilder {
        SceneBuilder::new(geometry, substrate)
    }

    /// Check every range and combination the format itself forbids (the checks of
    /// `scene/validate.rs`). What no solver handles (a graded sphere, a grid too large for
    /// the machine, ...) is the planner's to refuse, located the same way, when the scene
    /// is planned.
    ///
    /// # Errors
    /// The first refusal, located in the source file when the scene came from one.
    pub fn validate(&self) -> Result<(), SceneError> {
        validate::validate(self).map_err(|i| self.locate(i))
    }

    fn checked(self) -> Result<Scene, SceneError> {
        self.validate()?;
        Ok(self)
    }

    /// A refusal as a [`SceneError`]: the key, and when the scene came from a file, the file,
    /// line and column of the key's value (or of its table when the key is absent).
    pub fn locate(&self, i: Issue) -> SceneError {
        let mut e = SceneError::new(i.kind, i.message).key(i.key.clone());
        if !i.hint.is_empty() {
            e = e.hint(i.hint);
        }
        if let Some(src) = &self.source {
            e = e.at(&src.text, src.span(&i.key));
        }
        e.in_file(self.file.clone())
    }
}
