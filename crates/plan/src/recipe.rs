//! The recipe: what execution does, decided once by the planner.
//!
//! A [`Recipe`] is the typed half of a [`Plan`](crate::Plan): one variant per kind of
//! problem, each carrying the resolved inputs (SI values, validated materials, the method
//! chosen for each step) of the stages that run. The types admit only the combinations the
//! planner produces: a line contact cannot carry a 3D grid solver, rolling has no separate
//! normal step (Carter and Goryacheva solve both together), a flat punch has no
//! partial-slip step. The executor (`stickslip-run`'s `exec`) therefore matches on these types and
//! never on the scene, and has no arm for "the plan and the scene disagree".

use stickslip_graded::{Accuracy, GradedMaterial};
use stickslip_halfspace::Material;
pub use stickslip_rolling::{steady3d::Creepage, steady3d::RollingMethod};
use stickslip_rolling::{CarterParams, GoryachevaParams, StressConfig};

use stickslip_scene::{FieldGrid, Patch};

/// What execution does.
#[derive(Debug, Clone, PartialEq)]
// Exhaustive on purpose: the executor (`stickslip-run`) matches every variant, so a new
// kind of problem does not compile until it has its stages. One recipe is made per run, so
// the size of its largest variant costs nothing worth a box.
#[allow(clippy::large_enum_variant)]
pub enum Recipe {
    /// A static plane-strain contact (cylinder or punch), per unit length.
    Line(LineRecipe),
    /// Steady rolling of a cylinder on a base of the same material (2D).
    Rolling(RollingRecipe),
    /// A static 3D contact (sphere, ellipse, patches) sampled or solved on a lattice.
    Contact(ContactRecipe),
    /// One wheel on its rail from profiles: contact search, each patch's normal contact
    /// under the vertical wheel load, its creepages and creep forces (`stickslip-wheelrail`).
    WheelRail(Box<WheelRailRecipe>),
}

/// A wheel on its rail, resolved: the profiles read and checked, the track and the wheelset
/// placed, the materials, the position, the motion and the methods.
#[derive(Debug, Clone, PartialEq)]
pub struct WheelRailRecipe {
    /// The rail the wheel runs on.
    pub side: stickslip_wheelrail::Side,
    /// The rail on the track.
    pub track: stickslip_wheelrail::Track,
    /// The wheel on the wheelset.
    pub wheelset: stickslip_wheelrail::Wheelset,
    /// Rail (substrate) and wheel (indenter).
    pub bodies: Bodies,
    /// Friction coefficient.
    pub friction: f64,
    /// Element size (along x, across the patch), m.
    pub cell: (f64, f64),
    /// The wheelset's position.
    pub position: stickslip_wheelrail::Position,
    /// The wheelset's motion (None: normal contact only).
    pub motion: Option<stickslip_wheelrail::Motion>,
    /// The vertical wheel load or the approach.
    pub load: stickslip_wheelrail::VerticalLoad,
    /// The tangential theory of every patch.
    pub tangential: stickslip_wheelrail::Tangential,
}

/// The two bodies of a scene, resolved once when it is planned: every check, recipe and
/// stage reads the materials, the composite modulus and Dundurs' $\beta$ here, none derives
/// them again from the scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bodies {
    /// The substrate as a homogeneous material (graded: $E_0$ with its $\nu$, as the
    /// homogeneous limit $k = 0$; viscoelastic: the long-time modulus).
    pub substrate: Material,
    /// The indenter (rigid, the substrate's material, or its own).
    pub indenter: Material,
    /// The composite modulus $E^*$ of the pair (FORMULAS.md C;
    /// `stickslip_halfspace::material::composite_modulus`).
    pub e_star: f64,
    /// Dundurs' $\beta$ of the pair (0 for identical bodies;
    /// `stickslip_halfspace::material::dundurs_beta`).
    pub beta: f64,
    /// True when the two bodies are of one material (per-body shares are then 1/2).
    pub identical: bool,
    /// The power-law graded substrate $E = E_0 y^k$ when $k > 0$.
    pub graded: Option<GradedMaterial>,
}

impl Bodies {
    /// `[substrate, indenter]`, as the solvers take them.
    #[must_use]
    pub fn pair(&self) -> [Material; 2] {
        [self.substrate, self.indenter]
    }
}

// ---------------------------------------------------------------------------------------
// 2D static

/// The stages of a static line contact.
#[derive(Debug, Clone, PartialEq)]
pub struct LineRecipe {
    /// Normal contact.
    pub normal: LineNormal,
    /// The friction coefficient (zones are stick when it is positive and nothing loads
    /// the contact tangentially).
    pub friction_coefficient: f64,
    /// Shear traction, when friction carries something.
    pub friction: Option<LineFriction>,
    /// Surface arrays along x, when asked.
    pub surface: Option<LineSurface>,
    /// Subsurface stresses, when asked.
    pub field: Option<LineField>,
}

/// Surface arrays of a line contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineSurface {
    /// Points along x, over 1.5 contact half-widths either side.
    pub points: usize,
    /// How the surface displacements are computed.
    pub displacements: LineDisplacements,
}

/// How the surface displacements of a line contact are computed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LineDisplacements {
    /// Closed forms for the homogeneous substrate (Flamant kernels), relative to x = 0.
    Homogeneous {
        /// The substrate.
        substrate: Material,
    },
    /// The graded kernels by quadrature, absolute.
    Graded {
        /// The graded substrate.
        material: GradedMaterial,
        /// Accuracy of the kernel integrals.
        accuracy: Accuracy,
    },
    /// Not computed (flat punch).
    None,
}

/// How the normal load of a line contact is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LineLoad {
    /// The force per unit length P (N/m).
    Force(f64),
    /// The contact half-width a (m).
    HalfWidth(f64),
}

/// The normal-contact method of a line contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LineNormal {
    /// 2D Hertz between two homogeneous bodies.
    Hertz {
        /// Cylinder radius (m).
        radius: f64,
        /// Load or half-width.
        load: LineLoad,
        /// The two bodies.
        bodies: Bodies,
    },
    /// A rigid cylinder on the power-law graded half-plane ($k > 0$).
    Graded {
        /// Cylinder radius (m).
        radius: f64,
        /// Load or half-width.
        load: LineLoad,
        /// The graded substrate.
        material: GradedMaterial,
    },
    /// A flat rigid punch; no surface displacements.
    Punch {
        /// Half-width (m).
        half_width: f64,
        /// Force per unit length (N/m).
        force: f64,
    },
}

/// The shear traction of a line contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LineFriction {
    /// Full sliding, q = f p.
    Sliding {
        /// Friction coefficient.
        friction: f64,
    },
    /// 2D Cattaneo–Mindlin partial slip.
    Cattaneo {
        /// Friction coefficient.
        friction: f64,
        /// Tangential force per unit length (N/m, signed).
        tangential: f64,
    },
    /// Cattaneo-type partial slip on the graded half-plane.
    GradedPartialSlip {
        /// Friction coefficient.
        friction: f64,
        /// Tangential force per unit length (N/m, signed).
        tangential: f64,
    },
}

/// Subsurface stresses of a line contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineField {
    /// The points, in units of the grid's scale.
    pub grid: FieldGrid,
    /// How the stresses are computed.
    pub method: LineFieldMethod,
}

/// How the stresses of a line contact are computed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LineFieldMethod {
    /// McEwen / Muskhelishvili closed form (Hertz pressure, sliding or Cattaneo shear).
    McEwen,
    /// Full integration of the line-load kernels of `material` (graded, or Flamant at
    /// $k = 0$).
    Quadrature {
        /// The substrate as a graded material ($k = 0$ for a homogeneous one).
        material: GradedMaterial,
        /// Accuracy of the integrals.
        accuracy: Accuracy,
    },
}

// ---------------------------------------------------------------------------------------
// rolling

/// Steady rolling.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollingRecipe {
    /// The rolling model with its validated parameters.
    pub model: RollingModel,
    /// Surface arrays at this many points, when asked.
    pub surface_points: Option<usize>,
}

/// The rolling model.
#[derive(Debug, Clone, Copy, PartialEq)]
#[allow(clippy::large_enum_variant)]
pub enum RollingModel {
    /// Carter's elastic closed form.
    Carter(CarterParams),
    /// Goryacheva's standard-solid rolling, solved numerically.
    Goryacheva {
        /// Validated parameters.
        params: GoryachevaParams,
        /// Quadrature settings of the pressure and shear.
        stress: StressConfig,
        /// False when alpha = beta (the solid is elastic and the solution is Carter's).
        viscoelastic: bool,
    },
}

// ---------------------------------------------------------------------------------------
// 3D static

/// The stages of a static 3D contact.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactRecipe {
    /// Normal contact.
    pub normal: ContactNormal,
    /// Substrate and indenter (the indenter may be rigid), with their composite modulus and
    /// Dundurs' $\beta$.
    pub bodies: Bodies,
    /// Elements per side of the lattice.
    pub grid: usize,
    /// Friction coefficient.
    pub friction: f64,
    /// The tangential step (force, moment or both), when friction carries something.
    pub tangential: Option<Tangential>,
    /// A Mindlin–Deresiewicz cycle (a sphere only), when asked.
    pub cycle: Option<CycleRecipe>,
    /// A load path solved step by step (`[load.history]`); it replaces the tangential step
    /// and leaves the path's final state in the lattice.
    pub history: Option<HistoryRecipe>,
    /// Whether the lattice arrays go into the result.
    pub lattice_output: bool,
    /// Subsurface stresses on a box of points, when asked.
    pub field: Option<ContactField>,
    /// Dundurs' $\beta$ when the normal and tangential stages are solved together (a surface
    /// with a fast-solver tangential step between dissimilar bodies, $\beta \ne 0$); None
    /// when they separate.
    pub coupling: Option<f64>,
}

/// Subsurface stresses of a 3D contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactField {
    /// The box, in units of the grid's scale (the contact semi-axis a along x, or metres).
    pub grid: FieldGrid,
    /// How the stresses are computed.
    pub method: ContactFieldMethod,
    /// Poisson's ratio of the substrate.
    pub nu: f64,
}

/// How the stresses of a 3D contact are computed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ContactFieldMethod {
    /// The Hertz sphere's closed-form field (frictionless normal contact).
    HertzSphere,
    /// A Hertz sphere or ellipse in full sliding, shear $fp$ along `angle` (radians from x)
    /// on the substrate: Hamilton's (1983) field (Sackfield & Hills 1983 for the ellipse), as
    /// one integral in the ellipsoidal coordinate per shear direction
    /// (`stickslip_halfspace::hertz::ellipse_field`).
    HertzSliding {
        /// Friction coefficient.
        friction: f64,
        /// Direction of the shear on the substrate (radians from x).
        angle: f64,
    },
    /// The frictionless Hertz ellipse's field (Love 1929; Sackfield & Hills 1983), one
    /// integral in the ellipsoidal coordinate per point.
    HertzEllipse,
    /// The lattice's pressure and tractions by FFT convolution per depth layer with the exact
    /// stresses of uniformly loaded rectangles, interpolated bilinearly to the box.
    Lattice,
}

/// The normal contact of a 3D scene.
#[derive(Debug, Clone, PartialEq)]
pub enum ContactNormal {
    /// Hertz sphere.
    Sphere {
        /// Radius (m).
        radius: f64,
        /// Normal force (N), given or implied by the contact radius.
        force: f64,
        /// Composite modulus E* (Pa).
        e_star: f64,
    },
    /// Hertz ellipse from the relative radii.
    Ellipse {
        /// Radius in the x-z plane (m).
        rx: f64,
        /// Radius in the y-z plane (m).
        ry: f64,
        /// Normal force (N).
        force: f64,
        /// Composite modulus E* (Pa).
        e_star: f64,
    },
    /// Hertz pressure on given semi-axes.
    EllipseGiven {
        /// Semi-axis along x (m).
        a: f64,
        /// Semi-axis along y (m).
        b: f64,
        /// Normal force (N).
        force: f64,
    },
    /// Uniform pressure on each patch.
    Patches(Vec<Patch>),
    /// Any surface: the normal-contact solver on its lattice.
    Surface {
        /// The surface.
        surface: Box<stickslip_scene::Surface>,
        /// Force or approach.
        load: SurfaceLoad,
        /// Relative tolerance of the solver.
        tolerance: f64,
        /// A load sweep up to the force, warm-started step by step.
        sweep: Option<stickslip_scene::NormalSweep>,
        /// The hardness capping the pressure (`interface.hardness`, Pa), if any.
        hardness: Option<f64>,
        /// An approach path (`load.approach = [from, to, steps]`): the approach of every
        /// point (m), each solved from the one before; the last is the scene's load.
        approaches: Option<Vec<f64>>,
        /// Maugis–Dugdale adhesion (`interface.adhesion`), if any: solved under the approach.
        adhesion: Option<stickslip_scene::AdhesionKeys>,
    },
}

/// How a surface is loaded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SurfaceLoad {
    /// The normal force (N).
    Force(f64),
    /// The approach of the two bodies (m).
    Approach(f64),
}

/// The tangential step of a 3D contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tangential {
    /// Full sliding along `angle` (rad from +x): q = f p.
    Sliding {
        /// Direction (rad).
        angle: f64,
    },
    /// Mindlin's circle.
    Mindlin {
        /// The tangential force.
        force: Force,
    },
    /// Cattaneo's ellipse, the load along an axis.
    Cattaneo {
        /// The tangential force.
        force: Force,
        /// True when the load is along x, false along y.
        along_x: bool,
    },
    /// Lubkin's torsion of a circle.
    Lubkin {
        /// Moment (N m, signed).
        moment: f64,
    },
    /// A grid solver through the traction crate's contract.
    Grid(GridStep),
    /// 3D steady rolling with creepage and spin.
    Rolling(RollingStep),
}

/// A 3D steady-rolling step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollingStep {
    /// The theory: exact, FASTSIM or Polach.
    pub method: RollingMethod,
    /// The creepages.
    pub creepage: Creepage,
    /// Rolling speed V (m/s): the micro-slip velocity is V times the slip.
    pub speed: f64,
    /// Relative tolerance of the exact solver's residual (unused by FASTSIM and Polach).
    pub tolerance: f64,
    /// Rolled in steps from a start state instead of solved steady (method
    /// `RollingMethod::Transient`; under a creep force the creepages' longitudinal and lateral
    /// parts are unknowns, under prescribed creepages the force is).
    pub transient: Option<TransientRecipe>,
}

/// Transient rolling: the creep force held, where it starts, how far it rolls.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TransientRecipe {
    /// The creep force on body 1 (the indenter), $(F_x, F_y)$ (N).
    pub force: (f64, f64),
    /// Direction of the force (degrees from +x), for the history's columns.
    pub direction_deg: f64,
    /// First a step at rest under the force (a Cattaneo shift), then rolling.
    pub shift_first: bool,
    /// Distance rolled (m); None: two contact lengths along x under a force, ten under
    /// prescribed creepages (the start's memory decays more slowly there).
    pub distance: Option<f64>,
    /// Rolling at these creepages $(\xi, \eta)$ instead of under `force` (which then acts only
    /// in the shift at rest, when `shift_first`): the creep force is found at every step.
    pub creepage: Option<(f64, f64)>,
}

/// Which grid solver.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GridMethod {
    /// The modified LP of seed 002: a force or a moment, not both.
    Lp,
    /// The fast FFT solver: a force, a moment, or both.
    Fast,
}

/// A grid solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridStep {
    /// The solver.
    pub method: GridMethod,
    /// The force, if any.
    pub force: Option<Force>,
    /// The direction of the force (rad from +x); with a moment alone, the scene's
    /// `load.direction_deg` (it orients the reported shift across the load).
    pub direction: f64,
    /// The moment (N m, signed), if any.
    pub moment: Option<f64>,
    /// Relative tolerance, inside the solver's supported range.
    pub tolerance: f64,
}

/// A tangential force as the scene gives it and as the solvers take it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Force {
    /// The signed value of `load.tangential` (N).
    pub signed: f64,
    /// Its magnitude (N).
    pub magnitude: f64,
    /// The direction of the magnitude (rad from +x; `load.direction_deg`, turned by pi
    /// when the signed value is negative).
    pub direction: f64,
}

/// A Mindlin–Deresiewicz loading cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CycleRecipe {
    /// Amplitude T*/(fP).
    pub amplitude: f64,
    /// Points along the loop.
    pub points: usize,
}

/// A load path (`[load.history]`) on a 3D contact, solved by the fast solver step by step.
#[derive(Debug, Clone, PartialEq)]
pub struct HistoryRecipe {
    /// Force or shift control.
    pub control: stickslip_scene::HistoryControl,
    /// Direction of the tangential load (rad from +x).
    pub direction: f64,
    /// Corner values of the tangential force (N) or shift (m) along `direction`.
    pub tangential: Vec<f64>,
    /// Corner values of the normal load (N), the scene's `load.normal` where the path gives
    /// none.
    pub normal: Vec<f64>,
    /// Corner values of the moment (N m), if the path has one.
    pub moment: Option<Vec<f64>>,
    /// Sub-steps between corners.
    pub steps: usize,
    /// The table the corners were read from, if a file gave them (for messages).
    pub source: Option<stickslip_scene::PathSource>,
    /// Relative tolerance of every step's fast solve.
    pub tolerance: f64,
}
