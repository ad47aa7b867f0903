//! The effect planner: which physical effects a scene calls for, why, and which technique
//! serves each (SCENES.md, "Effects").
//!
//! The planner reads a validated [`Scene`] and decides, without computing anything:
//!
//! - for each of the eight effects of SCENES.md, whether it is on, with the reason;
//! - for each effect that is on, the [`Technique`] that will compute it (a closed form where
//!   one exists and applies, a numerical method otherwise, or what `solver.method` asks for);
//! - for 3D partial slip without a closed form, the grid solver and why: under
//!   `method = "auto"` the modified LP up to [`MAX_LP_ELEMENTS`] contact elements, the fast
//!   FFT solver beyond that or when a force and a moment act together ([`Plan::grid_solver`]);
//! - an estimate of the cost (kernel evaluations, seconds, memory), refusing grids whose
//!   memory would exceed [`MEMORY_LIMIT_BYTES`].
//!
//! It also refuses, before any computation, the combinations no solver in the workspace
//! handles (a graded sphere, a twisting moment together with a tangential force by the LP,
//! ...), each with the key to change and a hint. [`crate::run`] dispatches on the plan and nothing else,
//! so an effect that is off is never evaluated.

use std::fmt;

use crate::error::{ErrorKind, SceneError};
use crate::scene::{Ellipse, Geometry, Indenter, Method, Motion, NormalLoad, Scene, Substrate};

/// One of the physical effects of SCENES.md.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[non_exhaustive]
pub enum Effect {
    /// Normal contact: always on.
    NormalContact,
    /// Coulomb friction carrying a tangential load, a moment, sliding or rolling.
    Friction,
    /// A power-law graded substrate with $k > 0$.
    Grading,
    /// A viscoelastic substrate with $\alpha \ne \beta$.
    Viscoelasticity,
    /// Steady rolling.
    Rolling,
    /// A twisting moment about the contact normal.
    Twist,
    /// A Mindlin–Deresiewicz loading cycle.
    Hysteresis,
    /// Subsurface stresses on a grid.
    SubsurfaceField,
}

impl Effect {
    /// Every effect, in the order of SCENES.md.
    pub const ALL: [Effect; 8] = [
        Effect::NormalContact,
        Effect::Friction,
        Effect::Grading,
        Effect::Viscoelasticity,
        Effect::Rolling,
        Effect::Twist,
        Effect::Hysteresis,
        Effect::SubsurfaceField,
    ];

    /// The name used in SCENES.md and in result.json.
    pub fn name(self) -> &'static str {
        match self {
            Effect::NormalContact => "normal contact",
            Effect::Friction => "friction",
            Effect::Grading => "grading",
            Effect::Viscoelasticity => "viscoelasticity",
            Effect::Rolling => "rolling",
            Effect::Twist => "twist",
            Effect::Hysteresis => "hysteresis",
            Effect::SubsurfaceField => "subsurface field",
        }
    }

    pub(crate) fn index(self) -> usize {
        Effect::ALL.iter().position(|e| *e == self).unwrap_or(0)
    }
}

impl fmt::Display for Effect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// How an effect is computed: the physics-crate routine [`crate::run`] calls for it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Technique {
    /// 2D Hertz (FORMULAS.md B): `stickslip_halfspace::hertz::HertzLine`.
    HertzLine,
    /// Rigid cylinder on the graded half-plane, corrected seed 000 eq 15 and eq 16
    /// (FORMULAS.md A4): `stickslip_graded::RigidCylinder`.
    GradedCylinder,
    /// Flat rigid punch, $p = P/(\pi\sqrt{a^2-x^2})$ (Sadowsky; Johnson §2.8).
    FlatPunch,
    /// Hertz sphere (FORMULAS.md E): `stickslip_halfspace::hertz::HertzSphere`.
    HertzSphere,
    /// Hertz ellipse from the relative radii: `stickslip_halfspace::hertz::HertzEllipse`.
    HertzEllipse,
    /// Hertz pressure on given semi-axes, $p_0 = 3P/(2\pi ab)$ (FORMULAS.md E).
    EllipseGiven,
    /// Uniform pressure on each patch as given.
    PatchPressure,
    /// Full sliding, $q = f p$.
    Sliding,
    /// 2D Cattaneo–Mindlin (FORMULAS.md C): `stickslip_halfspace::cattaneo2d::Cattaneo2d`.
    Cattaneo2d,
    /// Cattaneo-type partial slip on the graded half-plane:
    /// `stickslip_graded::SurfaceLoad::partial_slip`.
    GradedPartialSlip,
    /// Mindlin (FORMULAS.md E): `stickslip_traction::closed::Mindlin`.
    Mindlin,
    /// Cattaneo ellipse (FORMULAS.md E): `stickslip_traction::closed::Cattaneo`.
    Cattaneo,
    /// The modified LP of seed 002 for a tangential force: `stickslip_traction::TractionProblem`.
    LpForce,
    /// The modified LP with the twist preprocessor (seed 002 §3.4).
    LpMoment,
    /// The fast partial-slip solver (issue 6): semismooth Newton with projected conjugate
    /// gradients, every influence product one zero-padded FFT convolution of the exact
    /// rectangle coefficients (FORMULAS.md F); both traction components free on the Coulomb
    /// disc $|\mathbf q| \le f p$, a force in any direction and a moment, alone or together:
    /// `stickslip_traction::FastProblem`.
    Fast,
    /// Lubkin torsion (FORMULAS.md G): `stickslip_traction::closed::Lubkin`.
    Lubkin,
    /// Carter's rolling closed form (FORMULAS.md D, elastic limit): `stickslip_rolling::carter`.
    Carter,
    /// Goryacheva's viscoelastic rolling (FORMULAS.md D): `stickslip_rolling::solve`.
    Goryacheva,
    /// The G&P kernels by full integration (FORMULAS.md A2, A3): `stickslip_graded`.
    GradedKernels,
    /// Mindlin–Deresiewicz loop (FORMULAS.md E): `stickslip_traction::closed::Deresiewicz`.
    Deresiewicz,
    /// McEwen / Muskhelishvili closed form (FORMULAS.md C): `stickslip_halfspace::mcewen`.
    McEwen,
    /// Full integration of the line-load field (FORMULAS.md A2; Flamant at $k = 0$):
    /// `stickslip_graded::StressField`.
    StressQuadrature,
}

impl Technique {
    /// Every technique, in the order of declaration.
    pub const ALL: [Technique; 22] = [
        Technique::HertzLine,
        Technique::GradedCylinder,
        Technique::FlatPunch,
        Technique::HertzSphere,
        Technique::HertzEllipse,
        Technique::EllipseGiven,
        Technique::PatchPressure,
        Technique::Sliding,
        Technique::Cattaneo2d,
        Technique::GradedPartialSlip,
        Technique::Mindlin,
        Technique::Cattaneo,
        Technique::LpForce,
        Technique::LpMoment,
        Technique::Fast,
        Technique::Lubkin,
        Technique::Carter,
        Technique::Goryacheva,
        Technique::GradedKernels,
        Technique::Deresiewicz,
        Technique::McEwen,
        Technique::StressQuadrature,
    ];

    /// Position in [`Technique::ALL`] (an exhaustive match: a new technique must be added
    /// to the list).
    pub fn index(self) -> usize {
        match self {
            Technique::HertzLine => 0,
            Technique::GradedCylinder => 1,
            Technique::FlatPunch => 2,
            Technique::HertzSphere => 3,
            Technique::HertzEllipse => 4,
            Technique::EllipseGiven => 5,
            Technique::PatchPressure => 6,
            Technique::Sliding => 7,
            Technique::Cattaneo2d => 8,
            Technique::GradedPartialSlip => 9,
            Technique::Mindlin => 10,
            Technique::Cattaneo => 11,
            Technique::LpForce => 12,
            Technique::LpMoment => 13,
            Technique::Fast => 14,
            Technique::Lubkin => 15,
            Technique::Carter => 16,
            Technique::Goryacheva => 17,
            Technique::GradedKernels => 18,
            Technique::Deresiewicz => 19,
            Technique::McEwen => 20,
            Technique::StressQuadrature => 21,
        }
    }

    /// True for closed forms (including those with a one-dimensional quadrature of a bounded
    /// integrand, as Lubkin's $M(c)$).
    pub fn is_closed_form(self) -> bool {
        !matches!(
            self,
            Technique::LpForce
                | Technique::LpMoment
                | Technique::Fast
                | Technique::Goryacheva
                | Technique::GradedKernels
                | Technique::StressQuadrature
        )
    }

    /// One line for `explain` and result.json.
    pub fn describe(self) -> &'static str {
        match self {
            Technique::HertzLine => "2D Hertz, a^2 = 4PR/(pi E*) (FORMULAS.md B)",
            Technique::GradedCylinder => {
                "rigid cylinder on the graded half-plane, corrected eq 15, h = a^2/(2Rk) (FORMULAS.md A4)"
            }
            Technique::FlatPunch => "flat punch, p = P/(pi sqrt(a^2 - x^2)) (Sadowsky)",
            Technique::HertzSphere => "Hertz sphere, a^3 = 3PR/(4E*) (FORMULAS.md E)",
            Technique::HertzEllipse => "Hertz ellipse from the relative radii (Johnson 4.2)",
            Technique::EllipseGiven => "Hertz pressure on the given semi-axes, p0 = 3P/(2 pi a b)",
            Technique::PatchPressure => "uniform pressure on each patch, as given",
            Technique::Sliding => "full sliding, q = f p",
            Technique::Cattaneo2d => "2D Cattaneo-Mindlin, c/a = sqrt(1 - Q/fP) (FORMULAS.md C)",
            Technique::GradedPartialSlip => {
                "graded Cattaneo-type partial slip, c/a = (1 - T/fP)^(1/(2+k)) (FORMULAS.md A4)"
            }
            Technique::Mindlin => "Mindlin, a*/a = (1 - T/fP)^(1/3) (FORMULAS.md E)",
            Technique::Cattaneo => "Cattaneo ellipse, a*/a = (1 - T/fP)^(1/3) (FORMULAS.md E)",
            Technique::LpForce => "modified LP on a contact grid (seed 002 Fig 3.5), numerical",
            Technique::LpMoment => {
                "modified LP with the twist preprocessor (seed 002 3.4), numerical"
            }
            Technique::Fast => {
                "fast solver on a contact grid (semismooth Newton + projected CG, FFT convolution), both traction components free, numerical"
            }
            Technique::Lubkin => "Lubkin torsion, M(c) by 1D quadrature (FORMULAS.md G)",
            Technique::Carter => "Carter, c = -a + 2 delta R / rho (FORMULAS.md D, elastic limit)",
            Technique::Goryacheva => {
                "Goryacheva eqs 19/24 (scaled), stresses by quadrature (FORMULAS.md D), numerical"
            }
            Technique::GradedKernels => {
                "G&P kernels by full integration (FORMULAS.md A2, A3), numerical"
            }
            Technique::Deresiewicz => "Mindlin-Deresiewicz loop and energy per cycle (FORMULAS.md E)",
            Technique::McEwen => "McEwen / Muskhelishvili closed form (FORMULAS.md C)",
            Technique::StressQuadrature => {
                "full integration of the line-load field (FORMULAS.md A2), numerical"
            }
        }
    }
}

/// The decision for one effect.
#[derive(Debug, Clone, PartialEq)]
pub struct EffectPlan {
    /// Which effect.
    pub effect: Effect,
    /// Whether the scene calls for it.
    pub on: bool,
    /// Why it is on or off.
    pub reason: String,
    /// How it is computed (None when off).
    pub technique: Option<Technique>,
}

/// Estimated cost of a run, before computing anything.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cost {
    /// Kernel or traction evaluations, roughly.
    pub evaluations: u64,
    /// Wall time on one core, roughly (s).
    pub seconds: f64,
    /// Largest working memory (bytes), roughly (the dense LP dominates).
    pub memory_bytes: u64,
}

/// The plan of a scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    /// One entry per effect, in the order of [`Effect::ALL`].
    pub effects: Vec<EffectPlan>,
    /// Points along the surface for 2D outputs (0 when surface output is off or 3D).
    pub surface_points: usize,
    /// Elements of a 3D grid (LP, fast solver, or closed forms sampled on a lattice).
    pub grid_elements: usize,
    /// Which grid solver serves 3D partial slip (the modified LP or the fast solver) and
    /// why; None when no grid solver runs.
    pub grid_solver: Option<String>,
    /// Estimated cost.
    pub cost: Cost,
    /// Statements about modelling assumptions the user should know.
    pub notes: Vec<String>,
}

/// Points along the surface of 2D results.
pub const SURFACE_POINTS: usize = 201;

/// The dense LP keeps several n x n matrices; beyond this many elements it needs more than
/// about 0.5 GB and minutes of pivoting.
pub const MAX_LP_ELEMENTS: usize = 3000;

/// A refusal found by the planner: the key to change, what is wrong, and a hint.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Issue {
    pub kind: ErrorKind,
    pub key: &'static str,
    pub message: String,
    pub hint: String,
}

fn issue(
    kind: ErrorKind,
    key: &'static str,
    message: impl Into<String>,
    hint: impl Into<String>,
) -> Issue {
    Issue { kind, key, message: message.into(), hint: hint.into() }
}

fn unsupported(key: &'static str, message: impl Into<String>, hint: impl Into<String>) -> Issue {
    issue(ErrorKind::Unsupported, key, message, hint)
}

impl Plan {
    /// Plan `scene`.
    ///
    /// # Errors
    /// A [`SceneError`] naming the key for a combination no solver handles. A scene read by
    /// [`Scene::from_toml_str`] has already passed this check (with line and column).
    #[allow(clippy::result_large_err)]
    pub fn new(scene: &Scene) -> Result<Plan, SceneError> {
        build(scene).map_err(|i| {
            SceneError::new(i.kind, i.message).key(i.key).hint(i.hint).in_file(scene.file.clone())
        })
    }

    /// The entry of `effect`.
    pub fn effect(&self, effect: Effect) -> &EffectPlan {
        &self.effects[effect.index()]
    }

    /// Whether `effect` is on.
    pub fn is_on(&self, effect: Effect) -> bool {
        self.effect(effect).on
    }

    /// The technique of `effect`, if it is on.
    pub fn technique(&self, effect: Effect) -> Option<Technique> {
        self.effect(effect).technique
    }

    /// The plan as `explain` prints it.
    pub fn explain(&self, scene: &Scene) -> String {
        let mut s = String::new();
        s.push_str(&format!("scene: {}\n", scene.title));
        if let Some(f) = &scene.file {
            s.push_str(&format!("file:  {}\n", f.display()));
        }
        s.push_str("\neffects on:\n");
        for e in self.effects.iter().filter(|e| e.on) {
            let t = e.technique.map_or("", Technique::describe);
            let kind = match e.technique {
                Some(t) if t.is_closed_form() => "closed form",
                Some(_) => "numerical",
                None => "",
            };
            s.push_str(&format!(
                "  {:<17} {}\n  {:<17}   -> [{kind}] {t}\n",
                e.effect.name(),
                e.reason,
                ""
            ));
        }
        s.push_str("\neffects off:\n");
        for e in self.effects.iter().filter(|e| !e.on) {
            s.push_str(&format!("  {:<17} {}\n", e.effect.name(), e.reason));
        }
        if let Some(g) = &self.grid_solver {
            s.push_str(&format!("\ngrid solver: {g}\n"));
        }
        if !self.notes.is_empty() {
            s.push_str("\nnotes:\n");
            for n in &self.notes {
                s.push_str(&format!("  - {n}\n"));
            }
        }
        let c = self.cost;
        s.push_str(&format!(
            "\nestimated cost: {} evaluations, about {} on one core, {} of working memory\n",
            c.evaluations,
            human_seconds(c.seconds),
            human_bytes(c.memory_bytes)
        ));
        s
    }
}

fn human_seconds(s: f64) -> String {
    if s < 1e-3 {
        "under a millisecond".to_string()
    } else if s < 1.0 {
        format!("{:.0} ms", s * 1e3)
    } else {
        format!("{s:.1} s")
    }
}

fn human_bytes(b: u64) -> String {
    let b = b as f64;
    if b < 1e6 {
        format!("{:.0} kB", b / 1e3)
    } else if b < 1e9 {
        format!("{:.0} MB", b / 1e6)
    } else {
        format!("{:.1} GB", b / 1e9)
    }
}

/// Elements of the lattice a 3D scene is solved or sampled on.
pub(crate) fn lattice_elements(scene: &Scene) -> usize {
    let n = scene.solver.grid;
    match &scene.geometry {
        // elements whose centres lie inside the circle / ellipse of the bounding box
        Geometry::Sphere { .. } | Geometry::Ellipsoid(_) => {
            (std::f64::consts::FRAC_PI_4 * (n * n) as f64).round() as usize
        }
        Geometry::Patches(ps) => {
            let (lo, hi) = crate::run::patch_bounds(ps);
            let h = (hi[0] - lo[0]).max(hi[1] - lo[1]) / n as f64;
            let area: f64 = ps.iter().map(|p| p.shape.area()).sum();
            (area / (h * h)).round() as usize
        }
        _ => 0,
    }
}

pub(crate) fn identical_materials(scene: &Scene) -> bool {
    match (scene.indenter, scene.substrate) {
        (Indenter::Same, _) => true,
        (Indenter::Homogeneous(i), Substrate::Homogeneous(s)) => i == s,
        (Indenter::Homogeneous(i), Substrate::Viscoelastic { elastic, .. }) => i == elastic,
        _ => false,
    }
}

/// Whether an ellipse load direction lies along one of the axes (the Cattaneo closed form).
fn along_axis(deg: f64) -> bool {
    let r = deg.rem_euclid(90.0);
    r.min(90.0 - r) < 1e-9
}

#[allow(clippy::too_many_lines)]
pub(crate) fn build(scene: &Scene) -> Result<Plan, Issue> {
    use Effect as E;
    use Technique as T;
    let g = &scene.geometry;
    let l = &scene.load;
    let method = scene.solver.method;
    let two_d = g.is_2d();
    let rolling = matches!(scene.motion, Motion::Rolling { .. });
    let graded_k = match scene.substrate {
        Substrate::Graded { k, .. } => Some(k),
        _ => None,
    };
    let grading = graded_k.is_some_and(|k| k > 0.0);
    let visco = match scene.substrate {
        Substrate::Viscoelastic { alpha, beta, .. } => Some(alpha != beta),
        _ => None,
    };
    let mut notes = Vec::new();
    if visco == Some(false) && !rolling {
        notes.push("alpha = beta: the standard solid is elastic with modulus E; solved as a homogeneous elastic body".to_string());
    }

    // ---- combinations no solver handles -------------------------------------------------
    if method == Method::Fast && (two_d || rolling) {
        return Err(unsupported(
            "solver.method",
            "the fast solver works on 3D contact grids (sphere, ellipsoid, patches); 2D and rolling contacts use closed forms or quadrature",
            "use method = \"auto\", \"closed-form\" or \"quadrature\"",
        ));
    }
    if visco == Some(true) && !rolling {
        return Err(unsupported(
            "substrate.model",
            "a viscoelastic substrate is solved in steady rolling (Goryacheva 1973); static viscoelastic indentation is not",
            "add [motion] kind = \"rolling\" with a speed, or use model = \"homogeneous\" with the relaxed modulus",
        ));
    }
    if graded_k.is_some() && !matches!(g, Geometry::Cylinder { .. }) {
        return Err(unsupported(
            "geometry.kind",
            "the graded substrate is solved for a rigid cylinder (seed 000, G&P 2000)",
            "use geometry.kind = \"cylinder\", or a homogeneous substrate",
        ));
    }
    if graded_k.is_some() && scene.indenter != Indenter::Rigid {
        return Err(unsupported(
            "indenter.model",
            "the graded-substrate solution (FORMULAS.md A4) is for a rigid cylinder",
            "use [indenter] model = \"rigid\"",
        ));
    }
    if rolling {
        if graded_k.is_some() {
            return Err(unsupported(
                "motion.kind",
                "rolling is solved for homogeneous (Carter) and viscoelastic (Goryacheva) bodies, not graded ones",
                "use motion.kind = \"static\", or a homogeneous / viscoelastic substrate",
            ));
        }
        if !matches!(g, Geometry::Cylinder { .. }) {
            return Err(unsupported(
                "geometry.kind",
                "rolling needs a cylinder",
                "use geometry.kind = \"cylinder\"",
            ));
        }
        if !identical_materials(scene) {
            return Err(unsupported(
                "indenter.model",
                "Carter and Goryacheva solve a cylinder rolling on a base of the same material",
                "use [indenter] model = \"same\"",
            ));
        }
        if !matches!(l.normal, NormalLoad::Force(_)) {
            return Err(unsupported(
                "load.half_width",
                "rolling takes the normal load; the contact length follows from it",
                "give load.normal = P (N/m)",
            ));
        }
        if l.tangential != 0.0 || l.sliding {
            return Err(issue(
                ErrorKind::Impossible,
                "load.tangential",
                "in steady rolling the tangential force follows from the creep; it cannot also be prescribed",
                "remove load.tangential / load.sliding and set motion.creep",
            ));
        }
        if l.friction <= 0.0 {
            return Err(issue(
                ErrorKind::Impossible,
                "load.friction",
                "rolling with stick and slip needs a friction coefficient",
                "give load.friction > 0",
            ));
        }
        if scene.outputs.field.is_some() {
            return Err(unsupported(
                "outputs.field",
                "subsurface fields are not computed for rolling contacts in this version",
                "remove outputs.field",
            ));
        }
        if matches!(method, Method::Lp) {
            return Err(unsupported(
                "solver.method",
                "the LP is a 3D grid solver; rolling uses Carter or Goryacheva",
                "use method = \"auto\"",
            ));
        }
        if method == Method::ClosedForm && visco == Some(true) {
            return Err(unsupported(
                "solver.method",
                "viscoelastic rolling has no closed form (Goryacheva's eqs 19 and 24 are solved numerically)",
                "use method = \"auto\" or \"quadrature\"",
            ));
        }
    }
    if scene.outputs.cycle.is_some() {
        if !matches!(g, Geometry::Sphere { .. }) {
            return Err(unsupported(
                "outputs.cycle",
                "the Mindlin-Deresiewicz cycle is solved for a sphere (Hertz circle)",
                "use geometry.kind = \"sphere\", or remove outputs.cycle",
            ));
        }
        if l.friction <= 0.0 {
            return Err(issue(
                ErrorKind::Impossible,
                "load.friction",
                "a loading cycle needs friction",
                "give load.friction > 0",
            ));
        }
        if l.sliding {
            return Err(issue(
                ErrorKind::Impossible,
                "load.sliding",
                "a loading cycle below gross slip cannot be combined with full sliding",
                "set sliding = false",
            ));
        }
    }
    if two_d {
        if matches!(method, Method::Lp) {
            return Err(unsupported(
                "solver.method",
                "the LP is a 3D grid solver; 2D contacts use closed forms or quadrature",
                "use method = \"auto\", \"closed-form\" or \"quadrature\"",
            ));
        }
        if matches!(g, Geometry::Punch { .. }) && l.tangential != 0.0 {
            return Err(unsupported(
                "load.tangential",
                "partial slip under a flat punch is not solved in this version",
                "use sliding = true (q = f p), or a cylinder",
            ));
        }
    } else {
        if scene.outputs.field.is_some() {
            return Err(unsupported(
                "outputs.field",
                "subsurface fields are computed for 2D contacts (cylinder, punch) in this version",
                "remove outputs.field, or use a cylinder",
            ));
        }
        if l.tangential != 0.0
            && l.moment != 0.0
            && matches!(method, Method::Lp | Method::ClosedForm)
        {
            return Err(unsupported(
                "load.moment",
                "a tangential force and a twisting moment together have no closed form, and the LP takes one load mode",
                "use method = \"fast\" (or \"auto\"), or give either load.tangential or load.moment",
            ));
        }
        if l.sliding && l.moment != 0.0 {
            return Err(issue(ErrorKind::Impossible, "load.moment", "with sliding = true the traction is q = f p along the sliding direction; a moment cannot also be prescribed", "remove load.moment or sliding"));
        }
        if l.moment != 0.0 && l.friction <= 0.0 {
            return Err(issue(
                ErrorKind::Impossible,
                "load.moment",
                "a twisting moment on a frictionless contact cannot be carried",
                "give load.friction > 0",
            ));
        }
        if method == Method::Quadrature && (l.tangential != 0.0 || l.moment != 0.0) {
            return Err(unsupported(
                "solver.method",
                "3D partial slip is solved by closed forms or grid solvers (LP, fast), not by quadrature",
                "use method = \"auto\", \"closed-form\", \"lp\" or \"fast\"",
            ));
        }
    }
    if let (Geometry::Sphere { .. }, true) = (g, l.moment != 0.0) {
        // Lubkin's gross-slip moment 3 pi f P a / 16 is checked in run once a is known.
    }
    if method == Method::ClosedForm {
        if grading {
            return Err(unsupported(
                "solver.method",
                "a graded substrate's displacements and stresses have no closed form; they are integrated numerically",
                "use method = \"auto\" or \"quadrature\"",
            ));
        }
        if matches!(g, Geometry::Patches(_)) && (l.tangential != 0.0 || l.moment != 0.0) {
            return Err(unsupported(
                "solver.method",
                "patches under a tangential load have no closed form",
                "use method = \"auto\", \"lp\" or \"fast\"",
            ));
        }
        if matches!(g, Geometry::Ellipsoid(_)) && l.moment != 0.0 {
            return Err(unsupported(
                "solver.method",
                "twisting an ellipse has no closed form",
                "use method = \"auto\", \"lp\" or \"fast\"",
            ));
        }
        if matches!(g, Geometry::Ellipsoid(_))
            && l.tangential != 0.0
            && !along_axis(l.direction_deg)
        {
            return Err(unsupported(
                "solver.method",
                "Cattaneo's closed form needs the load along an axis of the ellipse",
                "use direction_deg = 0 or 90, or method = \"auto\"",
            ));
        }
        if matches!(g, Geometry::Punch { .. }) && scene.outputs.field.is_some() {
            return Err(unsupported(
                "solver.method",
                "the flat-punch field is integrated numerically here",
                "use method = \"auto\"",
            ));
        }
    }

    // ---- the effects -------------------------------------------------------------------
    let mut effects: Vec<EffectPlan> = Vec::with_capacity(8);
    let on = |effect, reason: String, t: Technique| EffectPlan {
        effect,
        on: true,
        reason,
        technique: Some(t),
    };
    let off = |effect, reason: String| EffectPlan { effect, on: false, reason, technique: None };

    // normal contact
    let normal_t = match g {
        Geometry::Cylinder { .. } if rolling => {
            if visco == Some(true) {
                T::Goryacheva
            } else {
                T::Carter
            }
        }
        Geometry::Cylinder { .. } if grading => T::GradedCylinder,
        Geometry::Cylinder { .. } => T::HertzLine,
        Geometry::Punch { .. } => T::FlatPunch,
        Geometry::Sphere { .. } => T::HertzSphere,
        Geometry::Ellipsoid(Ellipse::Radii { .. }) => T::HertzEllipse,
        Geometry::Ellipsoid(Ellipse::SemiAxes { .. }) => T::EllipseGiven,
        Geometry::Patches(_) => T::PatchPressure,
    };
    effects.push(on(E::NormalContact, "always".to_string(), normal_t));

    // The grid solver for 3D partial slip that has no closed form (or where one is asked for).
    let both = l.tangential != 0.0 && l.moment != 0.0;
    let elements = if two_d { 0 } else { lattice_elements(scene) };
    let (grid_t, grid_reason) = grid_solver(method, elements, both);
    let closed_ok = !matches!(method, Method::Lp | Method::Fast);

    // friction
    let f = l.friction;
    let friction_cause = if l.tangential != 0.0 {
        Some("a tangential load")
    } else if l.sliding {
        Some("sliding = true")
    } else if l.moment != 0.0 {
        Some("a twisting moment")
    } else if rolling {
        Some("rolling")
    } else {
        None
    };
    match (f > 0.0, friction_cause) {
        (true, Some(cause)) => {
            let t = if rolling {
                normal_t
            } else if l.sliding {
                T::Sliding
            } else if l.moment != 0.0 && l.tangential == 0.0 {
                twist_technique(g, closed_ok, grid_t)
            } else {
                match g {
                    Geometry::Cylinder { .. } if grading => T::GradedPartialSlip,
                    Geometry::Cylinder { .. } => T::Cattaneo2d,
                    Geometry::Sphere { .. } if closed_ok && !both => T::Mindlin,
                    Geometry::Ellipsoid(_)
                        if closed_ok && !both && along_axis(l.direction_deg) =>
                    {
                        T::Cattaneo
                    }
                    _ if grid_t == T::Fast => T::Fast,
                    _ => T::LpForce,
                }
            };
            if t == T::Cattaneo2d && !identical_materials(scene) {
                notes.push("2D Cattaneo-Mindlin neglects the coupling of normal and tangential tractions; exact for identical materials only (Dundurs beta = 0)".to_string());
            }
            if t == T::GradedPartialSlip {
                notes.push("graded partial slip: the stick zone is where the q-induced u_x is uniform; the pressure-induced odd part of u_x (FORMULAS.md A5) is neglected, as in Cattaneo-Mindlin".to_string());
            }
            if matches!(t, T::Mindlin | T::Cattaneo | T::Lubkin) && !identical_materials(scene) {
                notes.push("Mindlin/Cattaneo/Lubkin neglect normal-tangential coupling (exact for identical materials)".to_string());
            }
            effects.push(on(E::Friction, format!("f = {f} > 0 with {cause}"), t));
        }
        (true, None) => effects.push(off(
            E::Friction,
            format!("f = {f} but no tangential load, sliding, moment or rolling: nothing for friction to carry"),
        )),
        (false, _) => effects.push(off(E::Friction, "friction coefficient is 0".to_string())),
    }

    // grading
    match graded_k {
        Some(k) if k > 0.0 => {
            effects.push(on(E::Grading, format!("graded substrate with k = {k}"), T::GradedKernels))
        }
        Some(_) => effects.push(off(
            E::Grading,
            "graded substrate with k = 0 is homogeneous: solved as a homogeneous half-plane"
                .to_string(),
        )),
        None => effects.push(off(E::Grading, "substrate is not graded".to_string())),
    }

    // viscoelasticity
    match (visco, scene.substrate) {
        (Some(true), Substrate::Viscoelastic { alpha, beta, .. }) => effects.push(on(
            E::Viscoelasticity,
            format!("standard solid with alpha = {alpha} s > beta = {beta} s"),
            T::Goryacheva,
        )),
        (Some(false), _) => effects.push(off(
            E::Viscoelasticity,
            "alpha = beta: the standard solid is elastic; solved as elastic (Carter)".to_string(),
        )),
        _ => effects.push(off(E::Viscoelasticity, "no viscoelastic material".to_string())),
    }

    // rolling
    if let Motion::Rolling { speed, creep } = scene.motion {
        let t = if visco == Some(true) { T::Goryacheva } else { T::Carter };
        effects.push(on(E::Rolling, format!("rolling at w = {speed} m/s, creep {creep}"), t));
    } else {
        effects.push(off(E::Rolling, "motion is static".to_string()));
    }

    // twist
    if l.moment != 0.0 {
        effects.push(on(
            E::Twist,
            format!("moment M = {} N m", l.moment),
            if both { T::Fast } else { twist_technique(g, closed_ok, grid_t) },
        ));
    } else {
        effects.push(off(E::Twist, "no twisting moment".to_string()));
    }

    // hysteresis
    match scene.outputs.cycle {
        Some(c) => effects.push(on(
            E::Hysteresis,
            format!("outputs.cycle with T*/(fP) = {}", c.amplitude),
            T::Deresiewicz,
        )),
        None => effects.push(off(E::Hysteresis, "no outputs.cycle".to_string())),
    }

    // subsurface field
    match scene.outputs.field {
        Some(fg) => {
            let t =
                if grading || matches!(g, Geometry::Punch { .. }) || method == Method::Quadrature {
                    T::StressQuadrature
                } else {
                    T::McEwen
                };
            effects.push(on(
                E::SubsurfaceField,
                format!("outputs.field with {} x {} points", fg.x.2, fg.y.2),
                t,
            ));
        }
        None => effects.push(off(E::SubsurfaceField, "no outputs.field".to_string())),
    }

    // ---- cost ----------------------------------------------------------------------------
    let surface_points = if two_d && scene.outputs.surface { SURFACE_POINTS } else { 0 };
    let grid_elements = elements;
    let lp = effects.iter().any(|e| matches!(e.technique, Some(T::LpForce | T::LpMoment)));
    let fast = effects.iter().any(|e| e.technique == Some(T::Fast));
    if lp && grid_elements > MAX_LP_ELEMENTS {
        return Err(issue(
            ErrorKind::OutOfRange,
            "solver.grid",
            format!("the dense LP on about {grid_elements} elements needs about {} of memory and minutes of pivoting", human_bytes(lp_memory(grid_elements))),
            format!("use a grid with at most {MAX_LP_ELEMENTS} contact elements (solver.grid about {} for a circle), or method = \"fast\"", ((MAX_LP_ELEMENTS as f64) / std::f64::consts::FRAC_PI_4).sqrt() as usize),
        ));
    }
    let grid_solver = (lp || fast).then(|| grid_reason.clone());
    let cells = if two_d { 0 } else { lattice_cells(scene) };
    // Memory of the 3D lattice arrays (result, JSON and CSV text) and of the fast solver.
    let grid_memory = cells as u64 * OUTPUT_BYTES_PER_CELL
        + if fast { fast_memory(cells, grid_elements) } else { 0 };
    if grid_memory > MEMORY_LIMIT_BYTES {
        let side = scene.solver.grid;
        let max_side =
            (side as f64 * (MEMORY_LIMIT_BYTES as f64 / grid_memory as f64).sqrt()) as usize;
        return Err(issue(
            ErrorKind::OutOfRange,
            "solver.grid",
            format!(
                "grid = {side} gives a lattice of {cells} cells ({grid_elements} contact elements) needing about {} of memory, more than the {} a run may use",
                human_bytes(grid_memory),
                human_bytes(MEMORY_LIMIT_BYTES)
            ),
            format!("use solver.grid <= {max_side} for this scene"),
        ));
    }
    let mut evals: u64 = 1;
    let mut secs = 1e-5;
    let mut mem: u64 = 1 << 20;
    if surface_points > 0 {
        let per = if grading {
            800
        } else if visco == Some(true) {
            600
        } else {
            4
        };
        evals += (surface_points * per) as u64;
        secs += (surface_points * per) as f64 * 2e-8;
    }
    if let Some(fg) = scene.outputs.field {
        let n = (fg.x.2 * fg.y.2) as u64;
        let per = if effects[E::SubsurfaceField.index()].technique == Some(T::StressQuadrature) {
            1200
        } else {
            6
        };
        evals += n * per;
        secs += (n * per) as f64 * 2.5e-8;
        mem += n * 64;
    }
    if grid_elements > 0 {
        let n = grid_elements as u64;
        evals += n;
        if lp {
            evals += n * n * 4;
            secs += (n * n) as f64 * 2e-7 + (n * n * n) as f64 * 2e-9;
            mem += lp_memory(grid_elements);
        } else if fast {
            // Each Newton step takes tens of CG iterations, one FFT product each; the count
            // grows slowly with the grid (measured: see fast_seconds).
            evals += n * FAST_PRODUCTS;
            secs += fast_seconds(cells);
        } else if effects[E::Twist.index()].technique == Some(T::Lubkin) {
            evals += n * 200;
            secs += n as f64 * 4e-6;
        }
    }
    if let Some(c) = scene.outputs.cycle {
        evals += 2 * c.points as u64 + 1;
    }
    Ok(Plan {
        effects,
        surface_points,
        grid_elements,
        grid_solver,
        cost: Cost { evaluations: evals, seconds: secs, memory_bytes: mem + grid_memory },
        notes,
    })
}

/// The most memory a run may plan for: two thirds of a 24 GiB machine, leaving room for the
/// operating system and for the error of the estimate. With the fast solver this admits
/// grids up to about 5100 per side (about 12 GB at the measured rate) and refuses larger ones.
pub const MEMORY_LIMIT_BYTES: u64 = 16 << 30;

/// Result arrays per lattice cell of a 3D run: p, qx, qy and the stick flag in the result,
/// their JSON tree for the finiteness check and the pretty JSON and CSV text.
///
/// Calibration (peak resident memory of `stickslip run --out` on the Mindlin sphere with the
/// fast solver): 36 MB at grid 256, 129 MB at 512, 498 MB at 1024, i.e. 475 bytes per
/// lattice cell in all. This constant and those of [`fast_memory`] add up to about 1.4
/// times that, so the refusal errs on the safe side.
const OUTPUT_BYTES_PER_CELL: u64 = 250;

/// FFT products of a fast solve, roughly (for the evaluation count).
const FAST_PRODUCTS: u64 = 300;

/// Working memory of the fast solver for a lattice of `cells` cells with `elements` contact
/// elements: the padded FFT lattice has about 4 cells per lattice cell (each side at least
/// 2n - 1, rounded up to a 5-smooth size), holding three real kernel spectra and the
/// convolution scratch; the Newton and CG vectors are per element. Calibrated with
/// [`OUTPUT_BYTES_PER_CELL`] on measured peak memory.
fn fast_memory(cells: usize, elements: usize) -> u64 {
    cells as u64 * 200 + elements as u64 * 250
}

/// Seconds of a fast solve on a lattice of `cells` cells: measured on the Mindlin sphere
/// (T/(fP) = 2/3, 2 shared cores) 1.7 s at 256^2, 12 s at 512^2, 91 s at 1024^2, i.e. about
/// $1.7\,(N/256^2)^{1.45}$ s (FFT products cost N log N, their count grows with the grid).
fn fast_seconds(cells: usize) -> f64 {
    1.7 * (cells as f64 / 65536.0).powf(1.45)
}

/// Lattice cells of a 3D scene: `grid` x `grid` over the bounding box of a circle or
/// ellipse; for patches, cells of side (largest extent)/`grid` over their bounding box.
pub(crate) fn lattice_cells(scene: &Scene) -> usize {
    let n = scene.solver.grid;
    match &scene.geometry {
        Geometry::Patches(ps) => {
            let (lo, hi) = crate::run::patch_bounds(ps);
            let h = (hi[0] - lo[0]).max(hi[1] - lo[1]) / n as f64;
            let nx = ((hi[0] - lo[0]) / h).round().max(1.0) as usize;
            let ny = ((hi[1] - lo[1]) / h).round().max(1.0) as usize;
            nx * ny
        }
        _ => n * n,
    }
}

fn lp_memory(n: usize) -> u64 {
    // two projected n x n matrices plus the tableau (about 2n x 3n)
    (8 * n * n * 8) as u64
}

fn twist_technique(g: &Geometry, closed_ok: bool, grid: Technique) -> Technique {
    match g {
        Geometry::Sphere { .. } if closed_ok => Technique::Lubkin,
        _ if grid == Technique::Fast => Technique::Fast,
        _ => Technique::LpMoment,
    }
}

/// The grid solver for 3D partial slip without a closed form, and why: what
/// `solver.method` asks for, or under `"auto"` the modified LP up to [`MAX_LP_ELEMENTS`]
/// contact elements (exact for its discretisation, seed 002) and the fast solver beyond it
/// or when a force and a moment act together (the LP takes one load mode). Returns
/// [`Technique::Fast`] or [`Technique::LpForce`] (standing for the LP in either load mode).
fn grid_solver(method: Method, elements: usize, both: bool) -> (Technique, String) {
    match method {
        Method::Lp => (Technique::LpForce, "solver.method = \"lp\"".to_string()),
        Method::Fast => (Technique::Fast, "solver.method = \"fast\"".to_string()),
        _ if both => (
            Technique::Fast,
            "a tangential force and a twisting moment act together; the LP takes one load mode: the fast solver".to_string(),
        ),
        _ if elements > MAX_LP_ELEMENTS => (
            Technique::Fast,
            format!("about {elements} contact elements > {MAX_LP_ELEMENTS}, the dense LP's limit: the fast solver"),
        ),
        _ => (
            Technique::LpForce,
            format!("about {elements} contact elements <= {MAX_LP_ELEMENTS}: the modified LP (exact for its discretisation, seed 002)"),
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::Technique;

    #[test]
    fn every_technique_is_listed_once_in_order() {
        for (i, t) in Technique::ALL.iter().enumerate() {
            assert_eq!(t.index(), i, "{t:?}");
        }
    }
}
