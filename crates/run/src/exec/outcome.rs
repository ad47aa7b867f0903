//! The result of a run: the types result.json serialises, with the keys of the scene
//! format reference (docs/SCENES.md), and the run's options and instrumentation.

use serde::Serialize;
use stickslip_traction::ElementState;

use crate::plan::Effect;

// One check of the audit: defined beside the error, whose audit failures carry the checks.
pub use stickslip_scene::Check;

mod wheel_rail;
pub use wheel_rail::{
    CreepageOut, PatchLatticeOut, PatchMaps, TangentialSolveOut, TrackForce, WheelRailOut,
    WheelRailPatchOut,
};

/// Progress of a run, reported to [`RunOptions::progress`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Progress {
    /// What is being computed.
    pub stage: &'static str,
    /// Units done.
    pub done: usize,
    /// Units in this stage.
    pub total: usize,
}

/// Options of [`crate::run`].
#[derive(Clone, Copy, Default)]
pub struct RunOptions<'a> {
    /// Called as the run progresses (stage, done, total); the CLI draws a progress bar.
    pub progress: Option<&'a (dyn Fn(Progress) + Sync)>,
}

impl std::fmt::Debug for RunOptions<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RunOptions").field("progress", &self.progress.is_some()).finish()
    }
}

/// Evaluations made per effect (instrumentation): each counter is incremented where the
/// effect's physics is actually evaluated (one per traction, displacement, stress point,
/// root solve or loop point).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize)]
pub struct Evaluations {
    /// Normal-contact solves and pressure evaluations.
    pub normal_contact: u64,
    /// Tangential traction evaluations and friction solves.
    pub friction: u64,
    /// Graded-kernel integrals (surface displacement or stress points on a graded body).
    pub grading: u64,
    /// Viscoelastic solves and stress quadratures.
    pub viscoelasticity: u64,
    /// Rolling solves and rolling traction evaluations.
    pub rolling: u64,
    /// Twist solves and twist traction evaluations.
    pub twist: u64,
    /// Hysteresis-loop points.
    pub hysteresis: u64,
    /// Subsurface stress points.
    pub subsurface_field: u64,
}

impl Evaluations {
    /// The counter of `effect`.
    pub fn get(&self, effect: Effect) -> u64 {
        match effect {
            Effect::NormalContact => self.normal_contact,
            Effect::Friction => self.friction,
            Effect::Grading => self.grading,
            Effect::Viscoelasticity => self.viscoelasticity,
            Effect::Rolling => self.rolling,
            Effect::Twist => self.twist,
            Effect::Hysteresis => self.hysteresis,
            Effect::SubsurfaceField => self.subsurface_field,
        }
    }
}

/// `effects` in result.json.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EffectsOut {
    /// Effects that are on.
    pub on: Vec<String>,
    /// Effects that are off, with the reason.
    pub off: std::collections::BTreeMap<String, String>,
    /// Technique per effect that is on.
    pub methods: std::collections::BTreeMap<String, String>,
}

/// `contact` in result.json.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ContactOut {
    /// 2D: trailing half-width (x from -a); 3D: semi-axis along x (m).
    pub a: f64,
    /// 2D: leading half-width (x to b); 3D: semi-axis along y (m).
    pub b: f64,
    /// Peak pressure (Pa).
    pub p0: f64,
    /// Indentation (m) where an absolute one exists (graded k > 0: eq 16; 3D Hertz: the
    /// approach of distant points), else null.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub indentation: Option<f64>,
    /// Normal load (N/m in 2D, N in 3D).
    pub normal_load: f64,
    /// Contact area of a surface (m^2); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub area: Option<f64>,
    /// Fraction of a surface's lattice in contact; absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fraction: Option<f64>,
    /// Under a hardness (`interface.hardness`): the share of the contact cells at the
    /// hardness; absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic_fraction: Option<f64>,
    /// Under adhesion (`interface.adhesion`): the most tensile force along the approach path
    /// (N, negative when the bodies pull; the force itself when the path never pulls).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pull_off: Option<f64>,
    /// Under adhesion: whether the path passes the pull-off (the force turns back after its
    /// most tensile value and the contact has let go); false when the retraction stops
    /// before, so that `pull_off` is only the most tensile force reached.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pull_off_reached: Option<bool>,
}

/// `zones` in result.json.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Zones {
    /// Stick intervals.
    pub stick: Vec<[f64; 2]>,
    /// Slip intervals.
    pub slip: Vec<[f64; 2]>,
    /// What the intervals are measured along: "x", "radius", "x along the load", or "grid"
    /// (3D grid solutions: the counts are in `grid`, the map in `surface.stick`).
    pub coordinate: &'static str,
    /// Element counts of a grid solution (the LP or the fast solver); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub grid: Option<GridZones>,
}

/// Stick and slip element counts of a grid solution.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GridZones {
    /// Elements that stick.
    pub stick: usize,
    /// Elements that slip.
    pub slip: usize,
    /// Stick area over contact area (equal elements: stick / (stick + slip)).
    pub stick_area_fraction: f64,
}

impl GridZones {
    pub(crate) fn from_states(states: &[ElementState]) -> Self {
        let stick = states.iter().filter(|s| **s == ElementState::Stick).count();
        let slip = states.len() - stick;
        let stick_area_fraction =
            if states.is_empty() { 0.0 } else { stick as f64 / states.len() as f64 };
        GridZones { stick, slip, stick_area_fraction }
    }
}

/// `forces` in result.json.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Forces {
    /// Normal force.
    pub normal: f64,
    /// Tangential force (signed, along `load.direction_deg`).
    pub tangential: f64,
    /// Twisting moment.
    pub moment: f64,
    /// Rolling-friction moment.
    pub rolling_moment: f64,
    /// 3D rolling: creep force along x on body 1 (the indenter; N); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fx: Option<f64>,
    /// 3D rolling: creep force along y on body 1 (N).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fy: Option<f64>,
    /// 3D rolling: spin moment about the contact normal through the contact centre (N m).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mz: Option<f64>,
}

/// `rigid_displacement` in result.json.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RigidOut {
    /// Tangential rigid-body displacement of the stick zone (m): relative (two bodies) in
    /// 3D; in 2D on a graded substrate the absolute u_x of the stick zone; null where none is
    /// defined.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tangential: Option<f64>,
    /// Rigid rotation of the stick zone (rad, relative), twist only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rotation: Option<f64>,
    /// Per-body shares [substrate, indenter] of the tangential displacement or rotation.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub per_body: Option<[f64; 2]>,
}

/// `surface` in result.json: along x (2D) or on a grid (3D).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum SurfaceOut {
    /// 2D arrays along x.
    Line {
        /// Positions (m).
        x: Vec<f64>,
        /// Pressure (Pa).
        p: Vec<f64>,
        /// Shear traction on the substrate, +x (Pa).
        q: Vec<f64>,
        /// Tangential surface displacement of the substrate (m); empty if not computed.
        ux: Vec<f64>,
        /// Normal surface displacement of the substrate, positive into it (m).
        uy: Vec<f64>,
        /// What the displacements are measured from.
        datum: String,
    },
    /// 3D lattice: `p[i][j]` at (`x[i]`, `y[j]`).
    Grid {
        /// Lattice x (m).
        x: Vec<f64>,
        /// Lattice y (m).
        y: Vec<f64>,
        /// Pressure (Pa), 0 outside the contact.
        p: Vec<Vec<f64>>,
        /// Traction along x (Pa).
        qx: Vec<Vec<f64>>,
        /// Traction along y (Pa).
        qy: Vec<Vec<f64>>,
        /// 1 stick, 0 slip, -1 outside the contact.
        stick: Vec<Vec<i8>>,
        /// A surface's gap after loading (m), every cell; absent otherwise.
        #[serde(skip_serializing_if = "Option::is_none")]
        gap: Option<Vec<Vec<f64>>>,
        /// 3D rolling: micro-slip velocity of body 1 over body 2 along x (m/s), 0 where the
        /// surface sticks or outside the contact; absent otherwise.
        #[serde(skip_serializing_if = "Option::is_none")]
        slip_x: Option<Vec<Vec<f64>>>,
        /// 3D rolling: micro-slip velocity along y (m/s).
        #[serde(skip_serializing_if = "Option::is_none")]
        slip_y: Option<Vec<Vec<f64>>>,
        /// A load path: the energy dissipated per unit area over the whole path (J/m^2);
        /// absent otherwise.
        #[serde(skip_serializing_if = "Option::is_none")]
        dissipation: Option<Vec<Vec<f64>>>,
        /// A load path: the largest slip range of each cell over the path (m, peak to
        /// peak; docs/load-histories.md); absent otherwise.
        #[serde(skip_serializing_if = "Option::is_none")]
        slip_amplitude: Option<Vec<Vec<f64>>>,
        /// A load path on a free surface: the Ruiz parameter of each cell, the largest
        /// tangential surface stress times shear over the path's corners times the slip
        /// range (Pa·J/m² = Pa²·m; docs/load-histories.md); absent otherwise.
        #[serde(skip_serializing_if = "Option::is_none")]
        ruiz: Option<Vec<Vec<f64>>>,
        /// A surface under a hardness: 1 where the pressure is at the hardness (plastic),
        /// else 0; absent otherwise.
        #[serde(skip_serializing_if = "Option::is_none")]
        plastic: Option<Vec<Vec<f64>>>,
        /// A surface under a hardness: the plastic displacement (m), the interpenetration
        /// that plastic flow removes at a plastic cell, 0 elsewhere; absent otherwise.
        #[serde(skip_serializing_if = "Option::is_none")]
        plastic_displacement: Option<Vec<Vec<f64>>>,
    },
}

/// A lattice map `[i][j]`.
type Map = Vec<Vec<f64>>;

impl SurfaceOut {
    /// The plastic maps (mask, displacement) of a capped surface, on a lattice's maps.
    #[must_use]
    pub(crate) fn with_plastic(mut self, maps: Option<(Map, Map)>) -> Self {
        if let (SurfaceOut::Grid { plastic, plastic_displacement, .. }, Some((m, w))) =
            (&mut self, maps)
        {
            *plastic = Some(m);
            *plastic_displacement = Some(w);
        }
        self
    }
}

/// `field` in result.json: the plane field of a line contact, or the volume field of a 3D
/// contact.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Field {
    /// 2D: stresses on an x-depth grid (empty arrays when not asked).
    Plane(FieldOut),
    /// 3D: stresses on a box of points.
    Volume(Box<VolumeField>),
}

static NO_PLANE: FieldOut =
    FieldOut { x: Vec::new(), y: Vec::new(), sxx: Vec::new(), syy: Vec::new(), sxy: Vec::new() };

impl Default for Field {
    fn default() -> Self {
        Field::Plane(FieldOut::default())
    }
}

impl Field {
    /// The plane field (empty for a volume field).
    pub fn plane(&self) -> &FieldOut {
        match self {
            Field::Plane(f) => f,
            Field::Volume(_) => &NO_PLANE,
        }
    }

    /// The volume field, if any.
    pub fn volume(&self) -> Option<&VolumeField> {
        match self {
            Field::Plane(_) => None,
            Field::Volume(v) => Some(v),
        }
    }
}

/// The stresses of a 3D field, each a flat array over the box, index
/// `k * ny * nx + j * nx + i` at (`x[i]`, `y[j]`, depth `z[k]`); SI, compressive negative.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct FieldArrays {
    /// sigma_xx.
    pub sxx: Vec<f64>,
    /// sigma_yy.
    pub syy: Vec<f64>,
    /// sigma_zz.
    pub szz: Vec<f64>,
    /// sigma_xy.
    pub sxy: Vec<f64>,
    /// sigma_yz.
    pub syz: Vec<f64>,
    /// sigma_xz.
    pub sxz: Vec<f64>,
    /// von Mises equivalent stress.
    pub von_mises: Vec<f64>,
    /// Tresca: the largest shear stress (sigma_1 - sigma_3)/2.
    pub tresca: Vec<f64>,
    /// The largest principal stress (tension positive).
    pub max_principal: Vec<f64>,
}

/// Where a field quantity is largest.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FieldPeak {
    /// The value (Pa).
    pub value: f64,
    /// x (m).
    pub x: f64,
    /// y (m).
    pub y: f64,
    /// Depth z (m).
    pub z: f64,
}

/// The maxima of a 3D field over the box.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FieldMax {
    /// Largest von Mises stress: where yield starts.
    pub von_mises: FieldPeak,
    /// Largest shear stress (Tresca).
    pub tresca: FieldPeak,
    /// Largest principal stress: the tensile peak where cracks start.
    pub max_principal: FieldPeak,
}

/// `field` of a 3D contact: the box, the maxima, and the arrays (in result.json only when
/// the box is small; always in field.csv and, for large boxes, in `field_*.npy`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct VolumeField {
    /// x of the box (m).
    pub x: Vec<f64>,
    /// y of the box (m).
    pub y: Vec<f64>,
    /// Depths (m).
    pub z: Vec<f64>,
    /// `[nz, ny, nx]`.
    pub shape: [usize; 3],
    /// How the stresses were computed.
    pub method: String,
    /// The maxima.
    pub max: FieldMax,
    /// The arrays, inline when the box has at most [`INLINE_FIELD_POINTS`] points.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub values: Option<FieldArrays>,
    /// The arrays (always; written to field.csv and the .npy files).
    #[serde(skip)]
    pub arrays: FieldArrays,
}

/// Boxes up to this many points carry their arrays in result.json too.
pub const INLINE_FIELD_POINTS: usize = 20_000;

/// `field` of a line contact: `sxx[j][i]` at (`x[i]`, depth `y[j]`), compressive negative.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct FieldOut {
    /// x (m).
    pub x: Vec<f64>,
    /// Depth y (m).
    pub y: Vec<f64>,
    /// sigma_xx (Pa).
    pub sxx: Vec<Vec<f64>>,
    /// sigma_yy (Pa).
    pub syy: Vec<Vec<f64>>,
    /// sigma_xy (Pa).
    pub sxy: Vec<Vec<f64>>,
}

/// `solver` in result.json.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SolverOut {
    /// The techniques used (per effect), joined.
    pub method: String,
    /// Iterations of the last iterative solver that ran, its own figure (LP pivots,
    /// fast-solver, coupled-solve, load-path and exact-rolling Newton steps (a load path's and
    /// a coupled solve's summed over steps or passes), 1 for FASTSIM, root-solver iterations;
    /// a surface without a grid solver: the normal solver's conjugate-gradient iterations on
    /// the finest lattice), 0 for closed forms.
    pub iterations: usize,
    /// Inner iterations: conjugate-gradient iterations summed over the fast solver's Newton
    /// steps (the normal solver alone, a load path and exact rolling: their FFT products);
    /// 0 for solvers without inner iterations (the LP, FASTSIM, root solvers).
    pub inner_iterations: usize,
    /// Residual of the last iterative solve, 0 for closed forms (the fast solver: relative
    /// complementarity residual $\lVert\mathbf r\rVert/\lVert\mathbf q\rVert$; the LP:
    /// the load in excess of the friction capacity; the normal solver: the largest of its
    /// certified residuals).
    pub residual: f64,
    /// Elements of the last lattice solver (the grid solver's elements; the normal solver
    /// alone: its lattice cells), 0 when none ran.
    pub elements: usize,
    /// Wall time of the lattice solvers including their set-up (s): the normal solver of a
    /// surface (all its load steps) plus the grid solver, the load path or the rolling solve
    /// after it (the coupled solve: its own time, normal passes included); 0 when none ran.
    pub solve_seconds: f64,
    /// Wall time of the run (s).
    pub seconds: f64,
    /// The normal-tangential coupling of dissimilar bodies, when it was solved.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub coupling: Option<CouplingOut>,
    /// The normal solver of a surface or of a wheel on its rail, when it ran (the top-level
    /// figures are then the tangential stage's, when there is one).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub normal: Option<NormalSolverOut>,
}

/// `solver.normal` in result.json: the normal-contact solver of a surface (its last load
/// step; the count and times cover all steps) or of a wheel on its rail (the patches' final
/// solves, counts summed and residuals the largest; the count and time cover every solve of
/// the vertical-load iteration).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct NormalSolverOut {
    /// Conjugate-gradient iterations on the finest lattice (the surface's, or the patches'),
    /// coarser levels not included.
    pub iterations: usize,
    /// Coarser lattices solved first (the nested start; 0 for a cold or warm start).
    pub levels: usize,
    /// Iterations on the coarser lattices, summed.
    pub coarse_iterations: usize,
    /// FFT products with the influence operator on the surface's lattice.
    pub products: usize,
    /// Applications of the spectral preconditioner on the surface's lattice.
    pub preconditioner_products: usize,
    /// The certified residuals: gap, complementarity, force, and the largest.
    pub gap_residual: f64,
    /// See `gap_residual`.
    pub complementarity_residual: f64,
    /// See `gap_residual`.
    pub force_residual: f64,
    /// See `gap_residual`.
    pub residual: f64,
    /// Normal solves: the load steps of a sweep (1 for one load), plus one per normal load
    /// of a load path; for a wheel on its rail, every patch at every trial height.
    pub steps: usize,
    /// Wall time of planning the operator (s).
    pub setup_seconds: f64,
    /// Wall time of the iterations of all load steps, coarser lattices included (s).
    pub solve_seconds: f64,
}

/// `solver.coupling` in result.json: the alternating normal-tangential solve of dissimilar
/// bodies (Dundurs coupling).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CouplingOut {
    /// Dundurs' beta of the pair.
    pub beta: f64,
    /// Alternation passes (a normal and a tangential solve each).
    pub passes: usize,
    /// Relative change of the pressure over the last pass.
    pub pressure_change: f64,
    /// Relative change of the traction over the last pass.
    pub traction_change: f64,
    /// The larger of the two changes (the coupling residual).
    pub residual: f64,
    /// Normal CCG iterations over all passes.
    pub normal_iterations: usize,
    /// Tangential Newton steps over all passes.
    pub tangential_iterations: usize,
    /// A load path: its steps (each coupled on its own; `passes` is then the sum over the
    /// steps, the changes and the residual the largest of the steps'). Absent for one state.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub steps: Option<usize>,
    /// A load path: the most passes one step took.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub most_passes: Option<usize>,
}

/// `rolling` in result.json (FORMULAS.md D notation).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[allow(non_snake_case)]
pub struct RollingOut {
    /// Contact length l = a + b (m).
    pub l: f64,
    /// Shift of the contact centre d = (b - a)/2 (m).
    pub d: f64,
    /// Stick length m = b - c (m).
    pub m: f64,
    /// Start of the stick zone c (m).
    pub c: f64,
    /// Eq 25's constant (null for a homogeneous body, where no alpha exists).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub C2: Option<f64>,
    /// Tangential force Q (N/m).
    pub Q: f64,
    /// Pressure moment M1 (N).
    pub M1: f64,
    /// Rolling-friction moment M* = M1 + QR (N).
    pub Mstar: f64,
    /// "stick-slip", "full slip" or "full stick".
    pub regime: &'static str,
    /// "viscoelastic" or "elastic (alpha = beta, Carter)" or "elastic (Carter)".
    pub response: &'static str,
}

/// `punch` in result.json: a surface pressed by the sharp-edged flat punch
/// (`[geometry.profile] shape = "punch"` without `edge_radius`), checked against
/// Boussinesq's closed form $F = 2aE^*\delta$, $p(r) = E^*\delta/(\pi\sqrt{a^2-r^2})$.
///
/// The face is the set of cells whose centres lie on it; `equivalent_radius` is the radius
/// of the circle of the same area, the radius the closed form is evaluated with. The edge
/// pressure is singular, so the lattice's peak pressure (`contact.p0`) belongs to the edge
/// cells and grows as they shrink: it is reported as grid-dependent, not as a property of
/// the contact.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PunchOut {
    /// Cells whose centres lie on the face.
    pub face_cells: usize,
    /// Radius of the face as written (m).
    pub radius: f64,
    /// Radius of the circle with the area of the face cells (m).
    pub equivalent_radius: f64,
    /// Cells across the face diameter along x.
    pub cells_across: f64,
    /// Boussinesq's force $2 a E^* \delta$ at the equivalent radius and the approach (N).
    pub boussinesq_force: f64,
    /// (lattice force − Boussinesq's) / Boussinesq's.
    pub force_error: f64,
    /// The largest |p − p_Boussinesq(r)| / p_Boussinesq(r) over the cells with
    /// $r \le a/2$, away from the edge singularity.
    pub interior_pressure_error: f64,
    /// Always true: the peak pressure is that of the edge cells, p ~ 1/sqrt(a² − r²).
    pub peak_pressure_grid_dependent: bool,
}

/// `load_curve` in result.json: one entry per step of a surface's load sweep or approach
/// path.
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct LoadCurve {
    /// Normal force of each step (N).
    pub normal: Vec<f64>,
    /// Approach of the bodies (m).
    pub approach: Vec<f64>,
    /// Contact area (m^2).
    pub area: Vec<f64>,
    /// Fraction of the lattice in contact.
    pub fraction: Vec<f64>,
    /// Peak pressure (Pa).
    pub p0: Vec<f64>,
    /// Iterations of the normal solver per step (warm-started from the step before).
    pub iterations: Vec<usize>,
    /// Under adhesion: the area of the cohesive zone (gap below the range, the contact
    /// included) of each step (m^2).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub zone_area: Option<Vec<f64>>,
}

/// `cycle` in result.json: the Mindlin–Deresiewicz loop.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CycleOut {
    /// Amplitude T* (N).
    pub amplitude: f64,
    /// Tangential load along the loop (N).
    pub t: Vec<f64>,
    /// Relative tangential displacement of the two bodies (m).
    pub delta: Vec<f64>,
    /// Energy dissipated per cycle, per body [substrate, indenter] (J).
    pub energy_per_cycle: [f64; 2],
}

/// `history` in result.json: a load path solved step by step (`[load.history]`;
/// docs/load-histories.md), or transient rolling (`[motion.transient]`, `control` =
/// "rolling"), one value per step in each column.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HistoryOut {
    /// "force" or "shift": what the path prescribes along `direction_deg`; "rolling" for
    /// transient rolling (the creep force is prescribed, the contact rolls).
    pub control: &'static str,
    /// Direction of the tangential load (degrees from +x).
    pub direction_deg: f64,
    /// The step of each corner (step 0 is the first corner).
    pub corners: Vec<usize>,
    /// Tangential force along the direction (N), the resultant of the solved traction.
    pub tangential: Vec<f64>,
    /// Normal force (N).
    pub normal: Vec<f64>,
    /// Twisting moment about the path's centre (N m).
    pub moment: Vec<f64>,
    /// Rigid tangential displacement of the bodies along the direction (m), relative.
    pub shift: Vec<f64>,
    /// Rigid rotation (rad), with a moment.
    pub rotation: Vec<f64>,
    /// Cells that do not slip in the step over the cells in contact.
    pub stick_fraction: Vec<f64>,
    /// Energy dissipated since the start (J).
    pub dissipated: Vec<f64>,
    /// Work of the tangential loads since the start (J); work = stored + dissipated.
    pub work: Vec<f64>,
    /// Elastic energy stored by the tangential traction (J).
    pub elastic_energy: Vec<f64>,
    /// Whether the contact slides (gross slip) in the step.
    pub gross_slip: Vec<bool>,
    /// The closed cycles, with their energy.
    pub loops: Vec<HistoryLoopOut>,
    /// A load path on a free surface: the largest Ruiz parameter (Pa·J/m²) and where (m).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ruiz_max: Option<RuizMaxOut>,
    /// Transient rolling only: the distance rolled at each step (m; 0 for the step at rest).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub distance: Vec<f64>,
    /// Transient rolling only: the creep force on the indenter along x (N).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub fx: Vec<f64>,
    /// Transient rolling only: the creep force on the indenter along y (N).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub fy: Vec<f64>,
    /// Transient rolling only: the spin moment about the contact centre (N m).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub mz: Vec<f64>,
    /// Transient rolling only: the longitudinal creepage that carries the force in the step
    /// (0 for the step at rest of a shift start, which does not roll: its distance is 0).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub creepage_longitudinal: Vec<f64>,
    /// Transient rolling only: the lateral creepage (0 for the step at rest).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub creepage_lateral: Vec<f64>,
    /// Passes of the Dundurs coupling per step (a load path between dissimilar bodies; absent
    /// otherwise).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub coupling_passes: Vec<usize>,
}

/// The largest Ruiz parameter of a load path and its cell.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RuizMaxOut {
    /// $\max F_2$ (Pa·J/m²).
    pub value: f64,
    /// Cell centre x (m).
    pub x: f64,
    /// Cell centre y (m).
    pub y: f64,
}

/// One closed cycle of a load path.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HistoryLoopOut {
    /// Step where the loop starts (a turning point).
    pub first_step: usize,
    /// Step where it closes.
    pub last_step: usize,
    /// Energy dissipated over the loop: the energy per cycle (J).
    pub energy: f64,
    /// Work of the loads over the loop (J): the loop's area by the trapezoidal rule.
    pub work: f64,
    /// Range of the tangential force over the loop (N).
    pub force_range: f64,
    /// Range of the shift over the loop (m).
    pub shift_range: f64,
    /// Shift at the end minus at the start (m): non-zero under force control means
    /// ratcheting.
    pub shift_drift: f64,
}

/// `audit` in result.json: every check run on the result before it is written.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Audit {
    /// True when every check passed (a result that fails is not written).
    pub passed: bool,
    /// The checks, in the order run.
    pub checks: Vec<Check>,
}

/// The result of a run; serialises to result.json with the keys of docs/SCENES.md.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Outcome {
    /// Scene title.
    pub title: String,
    /// Effects on and off.
    pub effects: EffectsOut,
    /// Contact size and load.
    pub contact: ContactOut,
    /// Stick and slip zones.
    pub zones: Zones,
    /// Resultant forces.
    pub forces: Forces,
    /// Rigid-body displacement.
    pub rigid_displacement: RigidOut,
    /// Surface arrays.
    pub surface: SurfaceOut,
    /// Subsurface stresses (empty arrays when off).
    pub field: Field,
    /// Solver information.
    pub solver: SolverOut,
    /// Rolling results, when rolling.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rolling: Option<RollingOut>,
    /// Loading cycle, when asked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cycle: Option<CycleOut>,
    /// A load path solved step by step, when `[load.history]` is given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub history: Option<HistoryOut>,
    /// A surface's load sweep: the area-load and approach-load curves.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_curve: Option<LoadCurve>,
    /// The sharp-edged flat punch on a surface, checked against Boussinesq.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub punch: Option<PunchOut>,
    /// A wheel on its rail: the wheelset, the total force and the patches.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wheel_rail: Option<WheelRailOut>,
    /// The checks the result passed before it was written.
    pub audit: Audit,
    /// Evaluations per effect.
    pub evaluations: Evaluations,
    /// Modelling notes.
    pub notes: Vec<String>,
    /// Always "SI".
    pub units: &'static str,
}

impl Outcome {
    /// result.json text.
    pub fn to_json(&self) -> String {
        // Serialising plain structs of numbers and strings cannot fail.
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// The path of the first non-finite number, if any. serde_json writes NaN and the
    /// infinities as `null`, and no number of a result is ever `null` otherwise (absent
    /// values are left out), so every `null` is a non-finite number.
    pub(crate) fn first_non_finite(&self) -> Option<String> {
        let v = serde_json::to_value(self).ok()?;
        fn walk(v: &serde_json::Value, path: &str) -> Option<String> {
            match v {
                serde_json::Value::Array(a) => {
                    a.iter().enumerate().find_map(|(i, x)| walk(x, &format!("{path}[{i}]")))
                }
                serde_json::Value::Object(o) => {
                    o.iter().find_map(|(k, x)| walk(x, &format!("{path}.{k}")))
                }
                serde_json::Value::Null => Some(path.trim_start_matches('.').to_string()),
                _ => None,
            }
        }
        walk(&v, "")
    }
}
