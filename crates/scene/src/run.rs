//! `run(scene)`: the one code path from a scene to its results.
//!
//! [`run`] plans the scene ([`Plan`]), then dispatches each effect that is on to the physics
//! crate that computes it, and nothing else: an effect that is off is never evaluated. Each
//! effect has an evaluation counter ([`Evaluations`]) incremented where its code runs, which
//! result.json reports and the tests use to prove that effects that are off cost nothing.

// Scene errors carry file, position, key and hint; they are built on cold paths.
#![allow(clippy::result_large_err)]

use std::f64::consts::PI;
use std::time::Instant;

use serde::Serialize;

use stickslip_graded::{
    Accuracy, GradedMaterial, Patch as GradedPatch, Profile, RigidCylinder, StressField,
    SurfaceDisplacement, SurfaceLoad,
};
use stickslip_halfspace::cattaneo2d::Cattaneo2d;
use stickslip_halfspace::hertz::{HertzEllipse, HertzLine, HertzSphere};
use stickslip_halfspace::material::composite_modulus;
use stickslip_halfspace::mcewen::HertzTraction;
use stickslip_halfspace::{Material, Stress2};
use stickslip_rolling::{CarterParams, GoryachevaParams, Regime as RollRegime, StressConfig};
use stickslip_traction::closed::{Cattaneo, Deresiewicz, Lubkin, Mindlin};
use stickslip_traction::fast::TensorConvolution;
use stickslip_traction::{
    ContactGrid, ElementState, FastConfig, FastProblem, FastSolution, InfluenceModel,
    Load as TractionLoad, Patch as GridPatch, PatchPressure, Shape, TractionProblem,
};

use crate::error::{ErrorKind, SceneError};
use crate::plan::{Effect, Issue, Plan, Technique};
use crate::scene::{
    Elastic, Ellipse, FieldScale, Geometry, Indenter, Motion, NormalLoad, Patch, PatchShape, Scene,
    Substrate,
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

/// Options of [`run`].
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
    pub indentation: Option<f64>,
    /// Normal load (N/m in 2D, N in 3D).
    pub normal_load: f64,
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
    fn from_states(states: &[ElementState]) -> Self {
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
}

/// `rigid_displacement` in result.json.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RigidOut {
    /// Tangential rigid-body displacement of the stick zone (m): relative (two bodies) in
    /// 3D; in 2D on a graded substrate the absolute u_x of the stick zone; null where none is
    /// defined.
    pub tangential: Option<f64>,
    /// Rigid rotation of the stick zone (rad, relative), twist only.
    pub rotation: Option<f64>,
    /// Per-body shares [substrate, indenter] of the tangential displacement or rotation.
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
    },
}

/// `field` in result.json: `sxx[j][i]` at (`x[i]`, depth `y[j]`), compressive negative.
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
    /// Iterations (LP pivots, fast-solver Newton steps, root-solver iterations), 0 for
    /// closed forms.
    pub iterations: usize,
    /// Inner iterations: conjugate-gradient iterations summed over the fast solver's Newton
    /// steps; 0 otherwise.
    pub inner_iterations: usize,
    /// Residual of the last iterative solve, 0 for closed forms (the fast solver: relative
    /// complementarity residual $\lVert\mathbf r\rVert/\lVert\mathbf q\rVert$; the LP:
    /// the load in excess of the friction capacity).
    pub residual: f64,
    /// Elements of the grid solver (LP or fast), 0 when none ran.
    pub elements: usize,
    /// Wall time of the grid solver including its set-up (s), 0 when none ran.
    pub solve_seconds: f64,
    /// Wall time of the run (s).
    pub seconds: f64,
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

/// The result of a run; serialises to result.json with the keys of SCENES.md.
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
    pub field: FieldOut,
    /// Solver information.
    pub solver: SolverOut,
    /// Rolling results, when rolling.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rolling: Option<RollingOut>,
    /// Loading cycle, when asked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cycle: Option<CycleOut>,
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

    /// The first non-finite number, if any (a run never returns one: see [`run`]).
    fn first_non_finite(&self) -> Option<String> {
        let v = serde_json::to_value(self).ok()?;
        fn walk(v: &serde_json::Value, path: &str) -> Option<String> {
            match v {
                // serde_json writes NaN and infinities as null; real nulls are the
                // Option fields, which are listed here so they are not flagged.
                serde_json::Value::Array(a) => {
                    a.iter().enumerate().find_map(|(i, x)| walk(x, &format!("{path}[{i}]")))
                }
                serde_json::Value::Object(o) => {
                    o.iter().find_map(|(k, x)| walk(x, &format!("{path}.{k}")))
                }
                serde_json::Value::Null if path.contains("surface") || path.contains("field") => {
                    Some(path.to_string())
                }
                _ => None,
            }
        }
        walk(&v, "")
    }
}

fn solver_err(what: &str, e: impl std::fmt::Display) -> SceneError {
    SceneError::new(ErrorKind::Solver, format!("{what} failed: {e}")).hint(
        "the inputs passed validation, so this is an extreme case the solver cannot handle; \
         please report it with the scene",
    )
}

struct Ctx<'a> {
    ev: Evaluations,
    notes: Vec<String>,
    opts: RunOptions<'a>,
    iterations: usize,
    inner_iterations: usize,
    residual: f64,
    elements: usize,
    solve_seconds: f64,
}

impl Ctx<'_> {
    fn progress(&self, stage: &'static str, done: usize, total: usize) {
        if let Some(p) = self.opts.progress {
            p(Progress { stage, done, total });
        }
    }
}

/// Plan `scene` and compute what the plan asks for, nothing else.
///
/// # Errors
/// A [`SceneError`] for a scene the planner refuses, or (kind
/// [`ErrorKind::Solver`]) when a physics routine fails, or returns a non-finite number.
pub fn run(scene: &Scene, opts: &RunOptions<'_>) -> Result<Outcome, SceneError> {
    let t0 = Instant::now();
    let plan = Plan::new(scene)?;
    if let Some(i) = pre_check(scene) {
        return Err(SceneError::new(i.kind, i.message)
            .key(i.key)
            .hint(i.hint)
            .in_file(scene.file.clone()));
    }
    let mut cx = Ctx {
        ev: Evaluations::default(),
        notes: plan
            .notes
            .iter()
            .cloned()
            .chain(plan.grid_solver.as_ref().map(|g| format!("grid solver: {g}")))
            .collect(),
        opts: *opts,
        iterations: 0,
        inner_iterations: 0,
        residual: 0.0,
        elements: 0,
        solve_seconds: 0.0,
    };
    let parts = if matches!(scene.motion, Motion::Rolling { .. }) {
        run_rolling(scene, &plan, &mut cx)
    } else if scene.geometry.is_2d() {
        run_line(scene, &plan, &mut cx)
    } else {
        run_3d(scene, &plan, &mut cx)
    }
    .map_err(|e| e.in_file(scene.file.clone()))?;
    let mut effects =
        EffectsOut { on: Vec::new(), off: Default::default(), methods: Default::default() };
    let mut methods = Vec::new();
    for e in &plan.effects {
        if e.on {
            effects.on.push(e.effect.name().to_string());
            if let Some(t) = e.technique {
                effects.methods.insert(e.effect.name().to_string(), t.describe().to_string());
                let tag = format!("{t:?}");
                if !methods.contains(&tag) {
                    methods.push(tag);
                }
            }
        } else {
            effects.off.insert(e.effect.name().to_string(), e.reason.clone());
        }
    }
    let out = Outcome {
        title: scene.title.clone(),
        effects,
        contact: parts.contact,
        zones: parts.zones,
        forces: parts.forces,
        rigid_displacement: parts.rigid,
        surface: parts.surface,
        field: parts.field,
        solver: SolverOut {
            method: methods.join(" + "),
            iterations: cx.iterations,
            inner_iterations: cx.inner_iterations,
            residual: cx.residual,
            elements: cx.elements,
            solve_seconds: cx.solve_seconds,
            seconds: t0.elapsed().as_secs_f64(),
        },
        rolling: parts.rolling,
        cycle: parts.cycle,
        evaluations: cx.ev,
        notes: cx.notes,
        units: "SI",
    };
    if let Some(path) = out.first_non_finite() {
        return Err(SceneError::new(
            ErrorKind::Solver,
            format!("the solution has a non-finite value at {path}"),
        )
        .hint("the scene is beyond what the solvers handle in f64; please report it")
        .in_file(scene.file.clone()));
    }
    let bad = [out.contact.a, out.contact.b, out.contact.p0, out.contact.normal_load]
        .iter()
        .chain([out.forces.tangential, out.forces.moment, out.forces.rolling_moment].iter())
        .any(|v| !v.is_finite());
    if bad {
        return Err(SceneError::new(ErrorKind::Solver, "the contact solution is not finite")
            .hint("the scene is beyond what the solvers handle in f64; please report it")
            .in_file(scene.file.clone()));
    }
    Ok(out)
}

struct Parts {
    contact: ContactOut,
    zones: Zones,
    forces: Forces,
    rigid: RigidOut,
    surface: SurfaceOut,
    field: FieldOut,
    rolling: Option<RollingOut>,
    cycle: Option<CycleOut>,
}

// ---------------------------------------------------------------------------------------
// materials

fn elastic_material(e: Elastic) -> Result<Material, SceneError> {
    Material::new(e.e, e.nu).map_err(|er| solver_err("material", er))
}

/// The substrate as a homogeneous material (graded k = 0: E = e0; viscoelastic: E).
fn substrate_material(s: &Substrate) -> Result<Material, SceneError> {
    match *s {
        Substrate::Homogeneous(e) => elastic_material(e),
        Substrate::Graded { e0, nu, .. } => elastic_material(Elastic { e: e0, nu }),
        Substrate::Viscoelastic { elastic, .. } => elastic_material(elastic),
    }
}

fn indenter_material(scene: &Scene, sub: &Material) -> Result<Material, SceneError> {
    match scene.indenter {
        Indenter::Rigid => Ok(Material::rigid()),
        Indenter::Same => Ok(*sub),
        Indenter::Homogeneous(e) => elastic_material(e),
    }
}

/// Normal load implied by a prescribed contact size, where the geometry fixes it.
pub(crate) fn implied_load(scene: &Scene) -> Option<f64> {
    let a = match scene.load.normal {
        NormalLoad::HalfWidth(a) => a,
        NormalLoad::Force(p) | NormalLoad::FromPatches(p) => return Some(p),
    };
    let sub = substrate_material(&scene.substrate).ok()?;
    let ind = indenter_material(scene, &sub).ok()?;
    match (&scene.geometry, scene.substrate) {
        (Geometry::Cylinder { radius }, Substrate::Graded { e0, k, nu }) if k > 0.0 => {
            let m = GradedMaterial::new(e0, k, nu).ok()?;
            stickslip_graded::load_from_half_width(&m, *radius, a).ok()
        }
        (Geometry::Cylinder { radius }, _) => {
            HertzLine::from_half_width(a, *radius, composite_modulus(&sub, &ind))
                .ok()
                .map(|h| h.load())
        }
        (Geometry::Sphere { radius }, _) => {
            Some(4.0 * composite_modulus(&sub, &ind) * a.powi(3) / (3.0 * radius))
        }
        _ => None,
    }
}

/// Checks that need the contact solved in closed form: T > fP when the load is given as a
/// half-width, Lubkin's gross-slip moment, a half-width where none applies.
pub(crate) fn pre_check(scene: &Scene) -> Option<Issue> {
    let l = &scene.load;
    if let NormalLoad::HalfWidth(_) = l.normal {
        if matches!(scene.geometry, Geometry::Ellipsoid(_) | Geometry::Punch { .. }) {
            return Some(Issue {
                kind: ErrorKind::Schema,
                key: "load.half_width",
                message: "this geometry takes the normal load, not a half-width".to_string(),
                hint: "give load.normal = P".to_string(),
            });
        }
    }
    let p = implied_load(scene)?;
    if let NormalLoad::HalfWidth(_) = l.normal {
        if !l.sliding && l.tangential.abs() > l.friction * p {
            return Some(Issue {
                kind: ErrorKind::Impossible,
                key: "load.tangential",
                message: format!(
                    "|T| = {} exceeds f P = {} (P = {p} implied by the half-width): the contact slides, partial slip is impossible",
                    l.tangential.abs(),
                    l.friction * p
                ),
                hint: "reduce T below f P, or set sliding = true".to_string(),
            });
        }
    }
    if let (Geometry::Sphere { radius }, true) = (&scene.geometry, l.moment != 0.0) {
        let sub = substrate_material(&scene.substrate).ok()?;
        let ind = indenter_material(scene, &sub).ok()?;
        let a = HertzSphere::new(p, *radius, composite_modulus(&sub, &ind)).ok()?.contact_radius();
        let mmax = 3.0 * PI * l.friction * p * a / 16.0;
        if l.moment.abs() > mmax {
            return Some(Issue {
                kind: ErrorKind::Impossible,
                key: "load.moment",
                message: format!(
                    "|M| = {} exceeds the gross-slip moment 3 pi f P a / 16 = {mmax}: the contact spins",
                    l.moment.abs()
                ),
                hint: "reduce the moment below 3 pi f P a / 16 (Lubkin)".to_string(),
            });
        }
    }
    None
}

fn linspace(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    if n == 1 {
        return vec![0.5 * (lo + hi)];
    }
    (0..n).map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64).collect()
}

// ---------------------------------------------------------------------------------------
// 2D static: cylinder and punch

/// Cumulative integral of a Hertz-shaped traction $amp\sqrt{1-s^2/b^2}$ from $-b$ to $x$:
/// $\tfrac{amp\,b}{2}[t\sqrt{1-t^2} + \arcsin t + \pi/2]$, $t = x/b$ clipped to $[-1, 1]$.
fn hertz_cumulative(x: f64, b: f64, amp: f64) -> f64 {
    let t = (x / b).clamp(-1.0, 1.0);
    0.5 * amp * b * (t * ((1.0 - t) * (1.0 + t)).sqrt() + t.asin() + 0.5 * PI)
}

/// $\frac{2(1-\nu^2)}{\pi E}\int amp\sqrt{1-s^2/b^2}\,\ln\frac{|x-s|}{|s|}ds$, the log-kernel
/// displacement of a Hertz-shaped traction at $x$ relative to $x = 0$, for one body
/// (the per-body form of `HertzLine::approach_relative`, Johnson §4.3; FORMULAS.md B):
/// $b\,amp\,\frac{1-\nu^2}{E}G(|x|/b)$ with $G(\xi) = \xi^2$ ($\xi \le 1$) and
/// $G(\xi) = \xi/(\xi+\sqrt{\xi^2-1}) + \operatorname{acosh}\xi$ beyond.
fn hertz_log_relative(x: f64, b: f64, amp: f64, m: &Material) -> f64 {
    let xi = (x / b).abs();
    let g = if xi <= 1.0 {
        xi * xi
    } else {
        let s = ((xi - 1.0) * (xi + 1.0)).sqrt();
        xi / (xi + s) + xi.acosh()
    };
    b * amp * m.normal_compliance() * g
}

/// A Hertz-shaped shear patch: half-width, peak (signed).
#[derive(Clone, Copy)]
struct ShearShape {
    b: f64,
    amp: f64,
}

#[allow(clippy::too_many_lines)]
fn run_line(scene: &Scene, plan: &Plan, cx: &mut Ctx<'_>) -> Result<Parts, SceneError> {
    let l = &scene.load;
    let f = l.friction;
    let fr = plan.technique(Effect::Friction);
    let grading = plan.is_on(Effect::Grading);
    let (k, nu_sub) = match scene.substrate {
        Substrate::Graded { k, nu, .. } => (k, nu),
        Substrate::Homogeneous(e) => (0.0, e.nu),
        Substrate::Viscoelastic { elastic, .. } => (0.0, elastic.nu),
    };
    let sub = substrate_material(&scene.substrate)?;
    let ind = indenter_material(scene, &sub)?;

    // ---- normal contact
    let (a, p0, load, indentation, graded_mat, punch) = match (
        &scene.geometry,
        plan.technique(Effect::NormalContact),
    ) {
        (Geometry::Cylinder { radius }, Some(Technique::GradedCylinder)) => {
            let Substrate::Graded { e0, k, nu } = scene.substrate else {
                return unreachable_plan();
            };
            let m = GradedMaterial::new(e0, k, nu).map_err(|e| solver_err("graded material", e))?;
            let cyl = match l.normal {
                NormalLoad::HalfWidth(a) => RigidCylinder::from_half_width(&m, *radius, a),
                NormalLoad::Force(p) | NormalLoad::FromPatches(p) => {
                    RigidCylinder::from_load(&m, *radius, p)
                }
            }
            .map_err(|e| solver_err("rigid cylinder (corrected eq 15)", e))?;
            let h = cyl.indentation().map_err(|e| solver_err("indentation (eq 16)", e))?;
            (cyl.half_width(), cyl.p0(), cyl.load(), Some(h), Some(m), false)
        }
        (Geometry::Cylinder { radius }, _) => {
            let es = composite_modulus(&sub, &ind);
            let h = match l.normal {
                NormalLoad::HalfWidth(a) => HertzLine::from_half_width(a, *radius, es),
                NormalLoad::Force(p) | NormalLoad::FromPatches(p) => HertzLine::new(p, *radius, es),
            }
            .map_err(|e| solver_err("2D Hertz", e))?;
            cx.notes.push(format!(
                "2D contact: no absolute indentation exists; the approach relative to the surface point at 10 a is {:.6e} m",
                h.approach_relative(10.0 * h.half_width())
            ));
            (h.half_width(), h.max_pressure(), h.load(), None, None, false)
        }
        (Geometry::Punch { half_width }, _) => {
            let NormalLoad::Force(p) = l.normal else {
                return unreachable_plan();
            };
            (*half_width, p / (PI * half_width), p, None, None, true)
        }
        _ => unreachable_plan()?,
    };
    cx.ev.normal_contact += 1;
    let pressure = |x: f64| -> f64 {
        let t = x / a;
        if t.abs() >= 1.0 {
            0.0
        } else if punch {
            p0 / ((1.0 - t) * (1.0 + t)).sqrt()
        } else {
            p0 * ((1.0 - t) * (1.0 + t)).powf(0.5 * (1.0 + k))
        }
    };

    // ---- friction: traction shapes
    let mut c_stick = a;
    let mut tangential = 0.0;
    let mut shear: Vec<ShearShape> = Vec::new(); // homogeneous Hertz shapes
    let mut graded_mu = 0.0; // graded/punch: q = mu p (+ correction)
    let mut graded_c: Option<f64> = None;
    let mut cattaneo: Option<Cattaneo2d> = None;
    let mut sliding_all = false;
    match fr {
        None => {}
        Some(Technique::Sliding) => {
            sliding_all = true;
            c_stick = 0.0;
            tangential = f * load;
            graded_mu = f;
            shear.push(ShearShape { b: a, amp: f * p0 });
        }
        Some(Technique::Cattaneo2d) => {
            let cm = Cattaneo2d::new(a, p0, f, l.tangential)
                .map_err(|e| solver_err("2D Cattaneo-Mindlin", e))?;
            c_stick = cm.stick_half_width();
            tangential = l.tangential;
            let s = l.tangential.signum();
            shear.push(ShearShape { b: a, amp: s * f * p0 });
            if c_stick > 0.0 {
                shear.push(ShearShape { b: c_stick, amp: -s * f * p0 * c_stick / a });
            }
            cattaneo = Some(cm);
        }
        Some(Technique::GradedPartialSlip) => {
            // T = f P (1 - (c/a)^(2+k)) for the traction of SurfaceLoad::partial_slip.
            let ratio = (l.tangential.abs() / (f * load)).min(1.0);
            c_stick = a * (1.0 - ratio).powf(1.0 / (2.0 + k));
            tangential = l.tangential;
            graded_mu = f * l.tangential.signum();
            graded_c = (c_stick > 0.0).then_some(c_stick);
        }
        Some(_) => unreachable_plan()?,
    }
    let q_at = |x: f64| -> f64 {
        match fr {
            None => 0.0,
            Some(Technique::Cattaneo2d) => cattaneo.map_or(0.0, |c| c.traction(x)),
            Some(Technique::GradedPartialSlip) => {
                let t = x / a;
                if t.abs() >= 1.0 {
                    return 0.0;
                }
                let g = 0.5 * (1.0 + k);
                let mut q = graded_mu * p0 * ((1.0 - t) * (1.0 + t)).powf(g);
                if let Some(c) = graded_c {
                    let u = x / c;
                    if u.abs() < 1.0 {
                        q -= graded_mu
                            * p0
                            * (c / a).powf(1.0 + k)
                            * ((1.0 - u) * (1.0 + u)).powf(g);
                    }
                }
                q
            }
            _ => graded_mu * pressure(x),
        }
    };
    // The load the graded integrators see (pressure and shear patches).
    let graded_load = || -> Result<SurfaceLoad, SceneError> {
        if punch {
            let patch =
                GradedPatch::new(0.0, a, -0.5, Profile::Uniform { p: p0, q: graded_mu * p0 })
                    .map_err(|e| solver_err("punch load", e))?;
            return Ok(SurfaceLoad::new().with_patch(patch));
        }
        let mu = match fr {
            Some(Technique::Cattaneo2d) => f * l.tangential.signum(),
            _ => graded_mu,
        };
        let c = match fr {
            Some(Technique::Cattaneo2d) => (c_stick > 0.0).then_some(c_stick),
            _ => graded_c,
        };
        match c {
            Some(c) if c < a => SurfaceLoad::partial_slip(a, c, p0, k, mu),
            _ if fr.is_some() && !sliding_all && c_stick >= a => {
                SurfaceLoad::cylinder(a, p0, k, 0.0)
            }
            _ => SurfaceLoad::cylinder(a, p0, k, mu),
        }
        .map_err(|e| solver_err("surface load", e))
    };

    // ---- surface arrays
    let mut xs = Vec::new();
    let (mut ps, mut qs, mut uxs, mut uys) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let mut datum = String::new();
    let mut rigid_tangential = None;
    if plan.surface_points > 0 {
        xs = linspace(-1.5 * a, 1.5 * a, plan.surface_points);
        for &x in &xs {
            ps.push(pressure(x));
            cx.ev.normal_contact += 1;
            if fr.is_some() {
                qs.push(q_at(x));
                cx.ev.friction += 1;
            } else {
                qs.push(0.0);
            }
        }
        if grading {
            let m = graded_mat.ok_or_else(|| solver_err("plan", "graded material missing"))?;
            let acc = Accuracy::new(
                stickslip_graded::Tolerance::relative(scene.solver.tolerance.clamp(1e-15, 1e-2))
                    .map_err(|e| solver_err("accuracy", e))?,
            )
            .map_err(|e| solver_err("accuracy", e))?;
            let sd = SurfaceDisplacement::new(&m, graded_load()?, acc)
                .map_err(|e| solver_err("graded surface displacement", e))?;
            for (i, &x) in xs.iter().enumerate() {
                let d =
                    sd.displacement(x).map_err(|e| solver_err("graded surface displacement", e))?;
                uxs.push(d.x);
                uys.push(d.y);
                cx.ev.grading += 1;
                if i % 20 == 0 {
                    cx.progress("surface displacements", i, xs.len());
                }
            }
            if fr.is_some() {
                let d = sd
                    .displacement(0.0)
                    .map_err(|e| solver_err("graded surface displacement", e))?;
                cx.ev.grading += 1;
                rigid_tangential = Some(d.x);
            }
            datum = "absolute: measured from the undisturbed surface at infinity (graded, k > 0; FORMULAS.md A3)".to_string();
        } else if !punch {
            // Homogeneous: closed forms per body of the substrate (Flamant kernels, FORMULAS.md B).
            let e = sub.youngs_modulus();
            let nu = sub.poisson_ratio();
            let step = (1.0 - 2.0 * nu) * (1.0 + nu) / (2.0 * e);
            let load_p = PI * a * p0 / 2.0;
            for &x in &xs {
                let mut ux = -step * (2.0 * hertz_cumulative(x, a, p0) - load_p);
                let mut uy = -hertz_log_relative(x, a, p0, &sub);
                for s in &shear {
                    ux -= hertz_log_relative(x, s.b, s.amp, &sub);
                    uy += step * (2.0 * hertz_cumulative(x, s.b, s.amp) - PI * s.b * s.amp / 2.0);
                }
                uxs.push(ux);
                uys.push(uy);
            }
            datum = "substrate only; logarithmic parts relative to the surface point x = 0, odd (step) parts absolute (2D half-plane displacements are defined up to a constant; FORMULAS.md B)".to_string();
        } else {
            datum = "not computed for the flat punch".to_string();
        }
    }
    let _ = nu_sub;

    // ---- field
    let mut field = FieldOut::default();
    if let Some(fg) = scene.outputs.field {
        let scale = match fg.scale {
            FieldScale::HalfWidth => a,
            FieldScale::Metres => 1.0,
        };
        field.x = linspace(fg.x.0 * scale, fg.x.1 * scale, fg.x.2);
        field.y = linspace(fg.y.0 * scale, fg.y.1 * scale, fg.y.2);
        let ny = field.y.len();
        let tech = plan.technique(Effect::SubsurfaceField);
        let quad_field = if tech == Some(Technique::StressQuadrature) {
            let m = match graded_mat {
                Some(m) => m,
                None => GradedMaterial::new(sub.youngs_modulus(), 0.0, sub.poisson_ratio())
                    .map_err(|e| solver_err("Flamant material", e))?,
            };
            let acc = Accuracy::new(
                stickslip_graded::Tolerance::relative(scene.solver.tolerance.clamp(1e-15, 1e-2))
                    .map_err(|e| solver_err("accuracy", e))?,
            )
            .map_err(|e| solver_err("accuracy", e))?;
            Some(
                StressField::new(&m, graded_load()?, acc)
                    .map_err(|e| solver_err("stress field", e))?,
            )
        } else {
            None
        };
        let mcewen = HertzTraction::new(a, p0, if sliding_all { f * p0 } else { 0.0 })
            .map_err(|e| solver_err("McEwen field", e))?;
        for (j, &y) in field.y.iter().enumerate() {
            let row: Vec<Stress2> = match &quad_field {
                Some(sf) => sf.grid(&field.x, &[y]).map_err(|e| solver_err("stress field", e))?,
                None => field
                    .x
                    .iter()
                    .map(|&x| match &cattaneo {
                        Some(c) => c.stress(x, y),
                        None => mcewen.stress(x, y),
                    })
                    .collect::<Result<_, _>>()
                    .map_err(|e| solver_err("McEwen field", e))?,
            };
            cx.ev.subsurface_field += row.len() as u64;
            if grading {
                cx.ev.grading += row.len() as u64;
            }
            field.sxx.push(row.iter().map(|s| s.xx).collect());
            field.syy.push(row.iter().map(|s| s.yy).collect());
            field.sxy.push(row.iter().map(|s| s.xy).collect());
            cx.progress("subsurface field", j + 1, ny);
        }
    }

    // ---- zones
    let zones = if fr.is_none() {
        if f > 0.0 {
            Zones { stick: vec![[-a, a]], slip: vec![], coordinate: "x", grid: None }
        } else {
            Zones { stick: vec![], slip: vec![[-a, a]], coordinate: "x", grid: None }
        }
    } else if c_stick <= 0.0 {
        Zones { stick: vec![], slip: vec![[-a, a]], coordinate: "x", grid: None }
    } else if c_stick >= a {
        Zones { stick: vec![[-a, a]], slip: vec![], coordinate: "x", grid: None }
    } else {
        Zones {
            stick: vec![[-c_stick, c_stick]],
            slip: vec![[-a, -c_stick], [c_stick, a]],
            coordinate: "x",
            grid: None,
        }
    };

    Ok(Parts {
        contact: ContactOut { a, b: a, p0, indentation, normal_load: load },
        zones,
        forces: Forces { normal: load, tangential, moment: 0.0, rolling_moment: 0.0 },
        rigid: RigidOut { tangential: rigid_tangential, rotation: None, per_body: None },
        surface: SurfaceOut::Line { x: xs, p: ps, q: qs, ux: uxs, uy: uys, datum },
        field,
        rolling: None,
        cycle: None,
    })
}

/// A fast-solver error as a scene error: a load beyond the friction capacity is an impossible
/// scene (key `load.tangential` or `load.moment`), an unconverged iteration names
/// `solver.tolerance`; anything else is a solver failure.
fn fast_err(e: stickslip_traction::Error) -> SceneError {
    use stickslip_traction::{Error as E, LoadKind};
    match &e {
        E::CapacityExceeded { load, .. } => {
            let key = if *load == LoadKind::Moment { "load.moment" } else { "load.tangential" };
            SceneError::new(
                ErrorKind::Impossible,
                format!("the load exceeds what friction can carry: {e}"),
            )
            .key(key)
            .hint("reduce the load: a force alone is carried up to f P, a moment alone up to the spin capacity, and less of each when both act")
        }
        E::NoStickLeft { .. } => {
            SceneError::new(
                ErrorKind::Solver,
                format!("the load is at or near what friction can carry: {e}"),
            )
            .key("load.tangential")
            .hint("reduce load.tangential or load.moment: together they are carried only below gross slip, which comes before f P and the spin capacity are each reached")
        }
        E::NotConverged { .. } | E::ToleranceOutOfRange { .. } => {
            SceneError::new(ErrorKind::Solver, format!("fast solver: {e}"))
                .key("solver.tolerance")
                .hint("raise solver.tolerance (e.g. 1e-8), or change solver.grid")
        }
        _ => solver_err("fast solver", e),
    }
}

/// The substrate's share of the rigid shift (force) or rotation (moment) of a fast solution:
/// $\sum_{stick} \mathbf m\cdot\mathbf u^{(1)}_k / \sum_{stick} \mathbf m\cdot\mathbf u_k$,
/// with $\mathbf m$ the unit load direction (force) or $\hat z\times(\mathbf x_k-\mathbf c)/
/// |\mathbf x_k-\mathbf c|^2$ (moment), $\mathbf u^{(1)}$ the substrate's own displacement
/// and $\mathbf u$ the relative one: on the stick zone $\mathbf u$ is the rigid motion, so
/// this is the per-body mean the LP reports (FORMULAS.md F: $A = A^{(1)} + A^{(2)}$). Exactly
/// 1/2 for identical bodies, 1 under a rigid indenter; otherwise one extra FFT product.
fn substrate_share(
    grid: &ContactGrid,
    sol: &FastSolution,
    bodies: [&Material; 2],
    scene: &Scene,
    force: bool,
) -> Result<f64, SceneError> {
    if bodies[1].is_rigid() {
        return Ok(1.0);
    }
    if bodies[0].is_rigid() {
        return Ok(0.0);
    }
    if crate::plan::identical_materials(scene) {
        return Ok(0.5);
    }
    let op = TensorConvolution::new(grid, &bodies[0].compliance(), InfluenceModel::default())
        .map_err(|e| solver_err("substrate operator", e))?;
    let mut scratch = op.make_scratch();
    let n = grid.len();
    let qx: Vec<f64> = sol.traction.iter().map(|q| q.0).collect();
    let qy: Vec<f64> = sol.traction.iter().map(|q| q.1).collect();
    let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
    op.apply(&qx, &qy, &mut ux, &mut uy, &mut scratch);
    let (c, s) = {
        let t = sol.shift.0.hypot(sol.shift.1);
        if t > 0.0 {
            (sol.shift.0 / t, sol.shift.1 / t)
        } else {
            (1.0, 0.0)
        }
    };
    let any_stick = sol.state.contains(&ElementState::Stick);
    let (mut own, mut all) = (0.0, 0.0);
    for k in 0..n {
        if any_stick && sol.state[k] != ElementState::Stick {
            continue;
        }
        let m = if force {
            (c, s)
        } else {
            let (dx, dy) = (grid.x[k] - sol.centre.0, grid.y[k] - sol.centre.1);
            let r2 = dx * dx + dy * dy;
            if r2 == 0.0 {
                continue;
            }
            (-dy / r2, dx / r2)
        };
        own += m.0 * ux[k] + m.1 * uy[k];
        all += m.0 * sol.displacement[k].0 + m.1 * sol.displacement[k].1;
    }
    Ok(if all != 0.0 { own / all } else { 0.5 })
}

fn unreachable_plan<T>() -> Result<T, SceneError> {
    Err(solver_err("dispatch", "the plan and the scene disagree (a bug in stickslip-scene)"))
}

// ---------------------------------------------------------------------------------------
// rolling

fn run_rolling(scene: &Scene, plan: &Plan, cx: &mut Ctx<'_>) -> Result<Parts, SceneError> {
    let Motion::Rolling { speed, creep } = scene.motion else { return unreachable_plan() };
    let Geometry::Cylinder { radius } = scene.geometry else { return unreachable_plan() };
    let NormalLoad::Force(load) = scene.load.normal else { return unreachable_plan() };
    let rho = scene.load.friction;
    let cfg = StressConfig {
        tol: stickslip_rolling::Tolerance::relative(scene.solver.tolerance.clamp(1e-14, 1e-3))
            .map_err(|e| solver_err("tolerance", e))?,
        max_subdivisions: 200,
    };
    let (el, alpha_beta) = match scene.substrate {
        Substrate::Homogeneous(e) => (e, None),
        Substrate::Viscoelastic { elastic, alpha, beta } => (elastic, Some((alpha, beta))),
        Substrate::Graded { .. } => return unreachable_plan(),
    };
    let visco_on = plan.is_on(Effect::Viscoelasticity);
    let mut xs = Vec::new();
    let (mut ps, mut qs) = (Vec::new(), Vec::new());
    let npts = if scene.outputs.surface { plan.surface_points.max(2) } else { 0 };
    let (rear, front, stick_start, stick_len, q, m1, mstar, c2, regime, response, p0);
    match alpha_beta {
        Some((alpha, beta)) => {
            let gp =
                GoryachevaParams::new(el.e, el.nu, radius, load, rho, creep, alpha, beta, speed)
                    .map_err(|e| solver_err("Goryacheva parameters", e))?;
            let s = stickslip_rolling::solve(&gp).map_err(|e| solver_err("Goryacheva solve", e))?;
            cx.ev.rolling += 1;
            if visco_on {
                cx.ev.viscoelasticity += 1;
            }
            cx.iterations = s.info.length_iterations + s.info.stick_iterations;
            cx.residual = s.info.length_residual.abs().max(s.info.stick_residual.abs());
            rear = s.rear;
            front = s.front;
            stick_start = s.stick_start;
            stick_len = s.stick_length;
            q = s.tangential_force;
            m1 = s.moment_m1;
            mstar = s.rolling_moment;
            c2 = Some(s.c2);
            regime = s.regime;
            response =
                if visco_on { "viscoelastic" } else { "elastic (alpha = beta: solved as Carter)" };
            if !visco_on {
                cx.notes.push("alpha = beta: the standard solid is elastic; Goryacheva's solution reduces to Carter's and is solved as such".to_string());
            }
            let mut pmax: f64 = 0.0;
            if npts > 0 {
                xs = linspace(-rear, front, npts);
                for (i, &x) in xs.iter().enumerate() {
                    let pe =
                        s.pressure(x, &cfg).map_err(|e| solver_err("Goryacheva pressure", e))?;
                    let te = s.shear(x, &cfg).map_err(|e| solver_err("Goryacheva shear", e))?;
                    cx.ev.normal_contact += 1;
                    cx.ev.rolling += 1;
                    cx.ev.friction += 1;
                    if visco_on {
                        cx.ev.viscoelasticity += (pe.evals + te.evals) as u64;
                    }
                    pmax = pmax.max(pe.value);
                    ps.push(pe.value);
                    qs.push(te.value);
                    if i % 20 == 0 {
                        cx.progress("rolling stresses", i, npts);
                    }
                }
            }
            p0 = if pmax > 0.0 { pmax } else { 2.0 * load / (PI * 0.5 * (rear + front)) };
        }
        None => {
            let cp = CarterParams::new(el.e, el.nu, radius, load, rho, creep)
                .map_err(|e| solver_err("Carter parameters", e))?;
            let s = stickslip_rolling::carter(&cp);
            cx.ev.rolling += 1;
            rear = s.half_width;
            front = s.half_width;
            stick_start = s.stick_start;
            stick_len = s.stick_length;
            q = s.tangential_force;
            m1 = 0.0;
            mstar = s.rolling_moment;
            c2 = None;
            regime = s.regime;
            response = "elastic (Carter)";
            p0 = s.peak_pressure;
            if npts > 0 {
                xs = linspace(-rear, front, npts);
                for &x in &xs {
                    ps.push(s.pressure(x));
                    qs.push(s.shear(x));
                    cx.ev.normal_contact += 1;
                    cx.ev.rolling += 1;
                    cx.ev.friction += 1;
                }
            }
        }
    }
    let regime_s = match regime {
        RollRegime::StickSlip => "stick-slip",
        RollRegime::FullSlip => "full slip",
        RollRegime::FullStick => "full stick",
    };
    let zones = match regime {
        RollRegime::StickSlip => Zones {
            stick: vec![[stick_start, front]],
            slip: vec![[-rear, stick_start]],
            coordinate: "x",
            grid: None,
        },
        RollRegime::FullSlip => {
            Zones { stick: vec![], slip: vec![[-rear, front]], coordinate: "x", grid: None }
        }
        RollRegime::FullStick => {
            Zones { stick: vec![[-rear, front]], slip: vec![], coordinate: "x", grid: None }
        }
    };
    cx.notes.push("rolling: the cylinder moves in +x, the contact is (-a, b) with the trailing edge at -a; q is Goryacheva's tau_xy on the base (FORMULAS.md D); surface displacements are not computed for rolling".to_string());
    let l = rear + front;
    Ok(Parts {
        contact: ContactOut { a: rear, b: front, p0, indentation: None, normal_load: load },
        zones,
        forces: Forces { normal: load, tangential: q, moment: 0.0, rolling_moment: mstar },
        rigid: RigidOut { tangential: None, rotation: None, per_body: None },
        surface: SurfaceOut::Line {
            x: xs,
            p: ps,
            q: qs,
            ux: vec![],
            uy: vec![],
            datum: "not computed for rolling".to_string(),
        },
        field: FieldOut::default(),
        rolling: Some(RollingOut {
            l,
            d: 0.5 * (front - rear),
            m: stick_len,
            c: stick_start,
            C2: c2,
            Q: q,
            M1: m1,
            Mstar: mstar,
            regime: regime_s,
            response,
        }),
        cycle: None,
    })
}

// ---------------------------------------------------------------------------------------
// 3D

/// Bounding box of the patches: (lower-left, upper-right).
pub(crate) fn patch_bounds(ps: &[Patch]) -> ([f64; 2], [f64; 2]) {
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

/// Assemble lattice arrays from element centres and values.
struct Lattice {
    x: Vec<f64>,
    y: Vec<f64>,
    p: Vec<Vec<f64>>,
    qx: Vec<Vec<f64>>,
    qy: Vec<Vec<f64>>,
    stick: Vec<Vec<i8>>,
}

impl Lattice {
    fn new(x0: f64, y0: f64, hx: f64, hy: f64, nx: usize, ny: usize) -> Self {
        Lattice {
            x: (0..nx).map(|i| x0 + (i as f64 + 0.5) * hx).collect(),
            y: (0..ny).map(|j| y0 + (j as f64 + 0.5) * hy).collect(),
            p: vec![vec![0.0; ny]; nx],
            qx: vec![vec![0.0; ny]; nx],
            qy: vec![vec![0.0; ny]; nx],
            stick: vec![vec![-1; ny]; nx],
        }
    }

    fn index(&self, x: f64, y: f64) -> Option<(usize, usize)> {
        let hx = if self.x.len() > 1 { self.x[1] - self.x[0] } else { 1.0 };
        let hy = if self.y.len() > 1 { self.y[1] - self.y[0] } else { 1.0 };
        let i = ((x - self.x[0]) / hx).round();
        let j = ((y - self.y[0]) / hy).round();
        (i >= 0.0 && j >= 0.0 && (i as usize) < self.x.len() && (j as usize) < self.y.len())
            .then_some((i as usize, j as usize))
    }

    fn into_surface(self) -> SurfaceOut {
        SurfaceOut::Grid {
            x: self.x,
            y: self.y,
            p: self.p,
            qx: self.qx,
            qy: self.qy,
            stick: self.stick,
        }
    }
}

#[allow(clippy::too_many_lines)]
fn run_3d(scene: &Scene, plan: &Plan, cx: &mut Ctx<'_>) -> Result<Parts, SceneError> {
    let l = &scene.load;
    let f = l.friction;
    let sub = substrate_material(&scene.substrate)?;
    let ind = indenter_material(scene, &sub)?;
    let es = || composite_modulus(&sub, &ind);
    let n = scene.solver.grid;
    let angle = l.direction_deg.to_radians();
    let (dir, tmag) =
        if l.tangential < 0.0 { (angle + PI, -l.tangential) } else { (angle, l.tangential) };

    // ---- normal contact
    let (ax, ay, p0, load, indentation) =
        match (&scene.geometry, plan.technique(Effect::NormalContact)) {
            (Geometry::Sphere { radius }, _) => {
                let p = implied_load(scene).ok_or_else(|| solver_err("normal load", "no load"))?;
                let h = HertzSphere::new(p, *radius, es())
                    .map_err(|e| solver_err("Hertz sphere", e))?;
                (h.contact_radius(), h.contact_radius(), h.max_pressure(), p, Some(h.approach()))
            }
            (Geometry::Ellipsoid(Ellipse::Radii { rx, ry }), _) => {
                let NormalLoad::Force(p) = l.normal else { return unreachable_plan() };
                let h = HertzEllipse::new(*rx, *ry, p, es())
                    .map_err(|e| solver_err("Hertz ellipse", e))?;
                (h.semi_axis_x(), h.semi_axis_y(), h.max_pressure(), p, Some(h.approach()))
            }
            (Geometry::Ellipsoid(Ellipse::SemiAxes { a, b }), _) => {
                let NormalLoad::Force(p) = l.normal else { return unreachable_plan() };
                (*a, *b, 3.0 * p / (2.0 * PI * a * b), p, None)
            }
            (Geometry::Patches(ps), _) => {
                let (lo, hi) = patch_bounds(ps);
                let pmax = ps.iter().map(|p| p.pressure).fold(0.0, f64::max);
                let p: f64 = ps.iter().map(Patch::force).sum();
                (0.5 * (hi[0] - lo[0]), 0.5 * (hi[1] - lo[1]), pmax, p, None)
            }
            _ => return unreachable_plan(),
        };
    cx.ev.normal_contact += 1;

    // ---- the lattice (solver grid or closed-form sampling)
    let fr = plan.technique(Effect::Friction);
    let tw = plan.technique(Effect::Twist);
    let lp = matches!(fr, Some(Technique::LpForce | Technique::LpMoment));
    let grid = match &scene.geometry {
        Geometry::Sphere { .. } => ContactGrid::hertz_circle(ax, load, n),
        Geometry::Ellipsoid(_) => ContactGrid::hertz_ellipse(ax, ay, load, n, n),
        Geometry::Patches(ps) => {
            let (lo, hi) = patch_bounds(ps);
            let h = (hi[0] - lo[0]).max(hi[1] - lo[1]) / n as f64;
            let patches: Vec<GridPatch> = ps
                .iter()
                .map(|p| GridPatch {
                    shape: match p.shape {
                        PatchShape::Square { side } => Shape::Rectangle {
                            cx: p.centre[0],
                            cy: p.centre[1],
                            wx: side,
                            wy: side,
                        },
                        PatchShape::Rectangle { sides } => Shape::Rectangle {
                            cx: p.centre[0],
                            cy: p.centre[1],
                            wx: sides[0],
                            wy: sides[1],
                        },
                        PatchShape::Circle { radius } => {
                            Shape::Circle { cx: p.centre[0], cy: p.centre[1], r: radius }
                        }
                    },
                    pressure: PatchPressure::Uniform(p.pressure),
                })
                .collect();
            ContactGrid::from_patches(h, h, (lo[0], lo[1]), &patches)
        }
        _ => return unreachable_plan(),
    }
    .map_err(|e| solver_err("contact grid", e))?;
    let (x0, y0, nx, ny) = match &scene.geometry {
        Geometry::Patches(ps) => {
            let (lo, hi) = patch_bounds(ps);
            let h = grid.hx;
            (
                lo[0],
                lo[1],
                ((hi[0] - lo[0]) / h).round() as usize,
                ((hi[1] - lo[1]) / h).round() as usize,
            )
        }
        _ => (-ax, -ay, n, n),
    };
    let mut lat = Lattice::new(x0, y0, grid.hx, grid.hy, nx.max(1), ny.max(1));
    for kk in 0..grid.len() {
        if let Some((i, j)) = lat.index(grid.x[kk], grid.y[kk]) {
            lat.p[i][j] = grid.pressure[kk];
            lat.stick[i][j] = 1;
        }
    }
    cx.ev.normal_contact += grid.len() as u64;

    let mut tangential = 0.0;
    let mut moment = 0.0;
    let mut rigid = RigidOut { tangential: None, rotation: None, per_body: None };
    let mut zones = Zones { stick: vec![], slip: vec![], coordinate: "grid", grid: None };
    if f == 0.0 {
        for row in &mut lat.stick {
            for s in row.iter_mut().filter(|s| **s == 1) {
                *s = 0;
            }
        }
    }
    match fr {
        None => {}
        Some(Technique::Sliding) => {
            tangential = f * load;
            let (c, s) = (angle.cos(), angle.sin());
            for i in 0..lat.x.len() {
                for j in 0..lat.y.len() {
                    if lat.stick[i][j] >= 0 {
                        let q = f * lat.p[i][j];
                        lat.qx[i][j] = q * c;
                        lat.qy[i][j] = q * s;
                        lat.stick[i][j] = 0;
                        cx.ev.friction += 1;
                    }
                }
            }
            zones = Zones {
                stick: vec![],
                slip: vec![[0.0, 1.0]],
                coordinate: "fraction of the contact (all slips)",
                grid: None,
            };
        }
        Some(Technique::Mindlin) => {
            let m = Mindlin::new(ax, load, f, tmag).map_err(|e| solver_err("Mindlin", e))?;
            cx.ev.friction += 1;
            tangential = l.tangential;
            let astar = m.stick_radius();
            let (c, s) = (dir.cos(), dir.sin());
            for i in 0..lat.x.len() {
                for j in 0..lat.y.len() {
                    if lat.stick[i][j] >= 0 {
                        let r = lat.x[i].hypot(lat.y[j]);
                        let q = m.traction(r);
                        cx.ev.friction += 1;
                        lat.qx[i][j] = q * c;
                        lat.qy[i][j] = q * s;
                        lat.stick[i][j] = i8::from(r < astar);
                    }
                }
            }
            let d = [m.compliance_per_body(&sub), m.compliance_per_body(&ind)];
            rigid = RigidOut { tangential: Some(d[0] + d[1]), rotation: None, per_body: Some(d) };
            zones = Zones {
                stick: vec![[0.0, astar]],
                slip: vec![[astar, ax]],
                coordinate: "radius",
                grid: None,
            };
        }
        Some(Technique::Cattaneo) => {
            // Along x: a = ax is the semi-axis along the load; along y: swap.
            let along_x = (l.direction_deg.rem_euclid(180.0))
                .min(180.0 - l.direction_deg.rem_euclid(180.0))
                < 45.0;
            let (al, ac) = if along_x { (ax, ay) } else { (ay, ax) };
            let m = Cattaneo::new(al, ac, load, f, tmag).map_err(|e| solver_err("Cattaneo", e))?;
            cx.ev.friction += 1;
            tangential = l.tangential;
            let sc = m.stick_scale();
            let (c, s) = (dir.cos(), dir.sin());
            for i in 0..lat.x.len() {
                for j in 0..lat.y.len() {
                    if lat.stick[i][j] >= 0 {
                        let (u, v) =
                            if along_x { (lat.x[i], lat.y[j]) } else { (lat.y[j], lat.x[i]) };
                        let q = m.traction(u, v);
                        cx.ev.friction += 1;
                        lat.qx[i][j] = q * c;
                        lat.qy[i][j] = q * s;
                        lat.stick[i][j] =
                            i8::from((u / (sc * al)).powi(2) + (v / (sc * ac)).powi(2) < 1.0);
                    }
                }
            }
            let d = [m.compliance_per_body(&sub), m.compliance_per_body(&ind)];
            rigid = RigidOut { tangential: Some(d[0] + d[1]), rotation: None, per_body: Some(d) };
            zones = Zones {
                stick: vec![[-sc * al, sc * al]],
                slip: vec![[-al, -sc * al], [sc * al, al]],
                coordinate: "x along the load",
                grid: None,
            };
        }
        Some(Technique::Lubkin) => {
            let m = Lubkin::from_moment(ax, load, f, l.moment.abs())
                .map_err(|e| solver_err("Lubkin", e))?;
            cx.ev.twist += 1;
            cx.ev.friction += 1;
            moment = l.moment;
            let c = m.stick_radius();
            let sign = l.moment.signum();
            let total = lat.x.len();
            for i in 0..lat.x.len() {
                for j in 0..lat.y.len() {
                    if lat.stick[i][j] >= 0 {
                        let (x, y) = (lat.x[i], lat.y[j]);
                        let r = x.hypot(y);
                        let tau = m.traction(r).map_err(|e| solver_err("Lubkin traction", e))?;
                        cx.ev.twist += 1;
                        cx.ev.friction += 1;
                        if r > 0.0 {
                            lat.qx[i][j] = -sign * tau * y / r;
                            lat.qy[i][j] = sign * tau * x / r;
                        }
                        lat.stick[i][j] = i8::from(r < c);
                    }
                }
                cx.progress("Lubkin traction", i + 1, total);
            }
            let w = [m.rotation_per_body(&sub), m.rotation_per_body(&ind)];
            rigid = RigidOut {
                tangential: None,
                rotation: Some(sign * (w[0] + w[1])),
                per_body: Some([sign * w[0], sign * w[1]]),
            };
            zones = Zones {
                stick: vec![[0.0, c]],
                slip: vec![[c, ax]],
                coordinate: "radius",
                grid: None,
            };
        }
        Some(Technique::LpForce | Technique::LpMoment) => {
            let load_mode = if fr == Some(Technique::LpMoment) {
                TractionLoad::Moment { moment: l.moment, centre: None }
            } else {
                TractionLoad::Force { magnitude: tmag, angle: dir }
            };
            cx.progress("modified LP", 0, 1);
            let ts = Instant::now();
            let sol = TractionProblem::new(&grid, [sub, ind], f, load_mode)
                .map_err(|e| solver_err("traction problem", e))?
                .solve()
                .map_err(|e| solver_err("modified LP", e))?;
            cx.solve_seconds = ts.elapsed().as_secs_f64();
            cx.elements = grid.len();
            cx.progress("modified LP", 1, 1);
            cx.ev.friction += grid.len() as u64;
            if tw.is_some() {
                cx.ev.twist += grid.len() as u64;
            }
            cx.iterations = sol.info.iterations;
            cx.residual = sol.excess_load;
            for kk in 0..grid.len() {
                if let Some((i, j)) = lat.index(grid.x[kk], grid.y[kk]) {
                    let (dx, dy) = sol.direction[kk];
                    lat.qx[i][j] = sol.traction[kk] * dx;
                    lat.qy[i][j] = sol.traction[kk] * dy;
                    lat.stick[i][j] = i8::from(sol.state[kk] == ElementState::Stick);
                }
            }
            if fr == Some(Technique::LpMoment) {
                moment = l.moment;
                rigid = RigidOut {
                    tangential: None,
                    rotation: Some(l.moment.signum() * sol.rigid),
                    per_body: Some(sol.rigid_per_body),
                };
            } else {
                tangential = l.tangential;
                rigid = RigidOut {
                    tangential: Some(sol.rigid),
                    rotation: None,
                    per_body: Some(sol.rigid_per_body),
                };
            }
            let nstick = sol.state.iter().filter(|s| **s == ElementState::Stick).count();
            cx.notes.push(format!(
                "modified LP on {} elements ({} stick, {} slip), {} pivots; per-patch forces: {}",
                grid.len(),
                nstick,
                grid.len() - nstick,
                sol.info.iterations,
                sol.patches
                    .iter()
                    .map(|p| format!(
                        "{:.6e} of capacity {:.6e} ({} of {} slipping)",
                        p.force, p.capacity, p.slipping, p.elements
                    ))
                    .collect::<Vec<_>>()
                    .join("; ")
            ));
            zones = Zones {
                stick: vec![],
                slip: vec![],
                coordinate: "grid",
                grid: Some(GridZones::from_states(&sol.state)),
            };
        }
        Some(Technique::Fast) => {
            let force = l.tangential != 0.0;
            let twist = l.moment != 0.0;
            let mut load = TractionLoad::polar(if force { tmag } else { 0.0 }, dir)
                .map_err(|e| solver_err("fast solver load", e))?;
            if twist {
                load = load
                    .with_moment(l.moment, None)
                    .map_err(|e| solver_err("fast solver load", e))?;
            }
            let (lo, hi) = FastConfig::TOLERANCE_RANGE;
            let config =
                stickslip_traction::Tolerance::relative(scene.solver.tolerance.clamp(lo, hi))
                    .map_err(|e| solver_err("fast solver configuration", e))
                    .and_then(|t| {
                        FastConfig::new(t, 100)
                            .map_err(|e| solver_err("fast solver configuration", e))
                    })?;
            cx.progress("fast solver", 0, 1);
            let ts = Instant::now();
            let sol = FastProblem::new(&grid, [sub, ind], f, load)
                .map_err(fast_err)?
                .with_config(config)
                .solve()
                .map_err(fast_err)?;
            cx.progress("fast solver", 1, 1);
            cx.ev.friction += grid.len() as u64;
            if tw.is_some() {
                cx.ev.twist += grid.len() as u64;
            }
            // The rigid motion: the shift along the force, or the rotation.
            let e = (dir.cos(), dir.sin());
            let total = if force { sol.shift.0 * e.0 + sol.shift.1 * e.1 } else { sol.rotation };
            let share = substrate_share(&grid, &sol, [&sub, &ind], scene, force)?;
            cx.solve_seconds = ts.elapsed().as_secs_f64();
            cx.elements = grid.len();
            cx.iterations = sol.info.iterations;
            cx.inner_iterations = sol.info.cg_iterations;
            cx.residual = sol.info.residual;
            for kk in 0..grid.len() {
                if let Some((i, j)) = lat.index(grid.x[kk], grid.y[kk]) {
                    (lat.qx[i][j], lat.qy[i][j]) = sol.traction[kk];
                    lat.stick[i][j] = i8::from(sol.state[kk] == ElementState::Stick);
                }
            }
            let per_body = Some([share * total, (1.0 - share) * total]);
            tangential = if force { l.tangential } else { 0.0 };
            moment = if twist { l.moment } else { 0.0 };
            rigid = RigidOut {
                tangential: force.then_some(total),
                rotation: twist.then_some(sol.rotation),
                per_body,
            };
            let gz = GridZones::from_states(&sol.state);
            let across = -sol.shift.0 * e.1 + sol.shift.1 * e.0;
            cx.notes.push(format!(
                "fast solver on {} elements ({} stick, {} slip; {:?}): {} Newton steps, {} CG iterations, {} FFT products on a {} x {} padded lattice; residual {:.3e}, load residual {:.3e}; set-up {:.3} s, iteration {:.3} s; resultant ({:.6e}, {:.6e}) N, moment {:.6e} N m about ({:.6e}, {:.6e}) m; shift across the load {:.3e} m{}",
                grid.len(),
                gz.stick,
                gz.slip,
                sol.regime,
                sol.info.iterations,
                sol.info.cg_iterations,
                sol.info.products,
                sol.info.fft_size.0,
                sol.info.fft_size.1,
                sol.info.residual,
                sol.info.load_residual,
                sol.info.setup_seconds,
                sol.info.solve_seconds,
                sol.resultant.0,
                sol.resultant.1,
                sol.moment,
                sol.centre.0,
                sol.centre.1,
                across,
                if force && twist {
                    "; per-body shares are of the shift (both the shift and the rotation are reported)"
                } else {
                    ""
                }
            ));
            zones = Zones { stick: vec![], slip: vec![], coordinate: "grid", grid: Some(gz) };
        }
        Some(_) => return unreachable_plan(),
    }

    // ---- hysteresis
    let mut cycle = None;
    if let Some(cy) = scene.outputs.cycle {
        let amp = cy.amplitude * f * load;
        let d =
            Deresiewicz::new(ax, load, f, amp).map_err(|e| solver_err("Mindlin-Deresiewicz", e))?;
        let half = (cy.points / 2).max(1);
        let lsub = d.hysteresis_loop(&sub, half).map_err(|e| solver_err("hysteresis loop", e))?;
        let lind = d.hysteresis_loop(&ind, half).map_err(|e| solver_err("hysteresis loop", e))?;
        cx.ev.hysteresis += (lsub.len() + lind.len()) as u64;
        cycle = Some(CycleOut {
            amplitude: amp,
            t: lsub.iter().map(|p| p.0).collect(),
            delta: lsub.iter().zip(&lind).map(|(a, b)| a.1 + b.1).collect(),
            energy_per_cycle: [d.energy_per_cycle(&sub), d.energy_per_cycle(&ind)],
        });
    }

    Ok(Parts {
        contact: ContactOut { a: ax, b: ay, p0, indentation, normal_load: load },
        zones,
        forces: Forces { normal: load, tangential, moment, rolling_moment: 0.0 },
        rigid,
        surface: if scene.outputs.surface || lp || fr == Some(Technique::Fast) {
            lat.into_surface()
        } else {
            Lattice::new(0.0, 0.0, 1.0, 1.0, 0, 0).into_surface()
        },
        field: FieldOut::default(),
        rolling: None,
        cycle,
    })
}
