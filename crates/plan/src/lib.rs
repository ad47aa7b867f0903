//! The effect planner: which physical effects a scene calls for, why, and which technique
//! serves each (docs/SCENES.md, "Effects").
//!
//! The planner reads a validated [`Scene`] and decides, without computing anything, a
//! [`Plan`]: a typed [`Recipe`] that `stickslip-run` executes stage by stage and nothing
//! else, and the explanation `explain` prints:
//!
//! - for each of the eight effects of docs/SCENES.md, whether it is on, with the reason;
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
//! ...), each with the key to change and a hint. Execution (`stickslip-run`'s `exec`) follows the
//! recipe and decides nothing again, so an effect that is off is never evaluated.
//!
//! Files: `checks.rs` (refusals, tolerances, capacity checks), `build.rs` (the recipe and
//! the effects with their reasons), `cost.rs` (the estimate and the memory refusals),
//! `recipe.rs` (the types), `patches.rs` (pressure patches on a lattice), `overview.rs` (the
//! scenes overview page, from the planner alone).
//!
//! [`read_scene`], [`read_scene_file`] and [`check`] read a scene and refuse it as a run
//! refuses it: the format's checks, then the planner's.

// SceneError carries file, position, key and hint for the user; one per call.
#![allow(clippy::result_large_err)]

use std::fmt;
use std::path::{Path, PathBuf};

mod bodies;
mod build;
mod checks;
pub(crate) mod cost;
mod effects;
mod machine;
mod overview;
pub mod patches;
pub mod recipe;
mod refusal;

pub use cost::{human_bytes, human_seconds, MEMORY_LIMIT_BYTES};
pub use machine::{MachineLimits, DEFAULT_TIME_LIMIT_SECONDS};
pub use overview::scenes_page;
pub use recipe::Recipe;

pub(crate) use stickslip_scene::Issue;
use stickslip_scene::{Scene, SceneError};

/// One of the physical effects of docs/SCENES.md.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
// Exhaustive on purpose: the executor (`stickslip-run`) maps every effect to its counters,
// so a new effect must not compile until it does.
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
    /// Hysteresis: a Mindlin–Deresiewicz loading cycle (closed form), or a load path solved
    /// step by step.
    Hysteresis,
    /// Subsurface stresses on a grid.
    SubsurfaceField,
}

impl Effect {
    /// Every effect, in the order of docs/SCENES.md.
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

    /// The name used in docs/SCENES.md and in result.json.
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

/// How an effect is computed: the physics-crate routine the executor calls for it.
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
    /// Normal contact of any surface on a lattice by constrained conjugate gradients
    /// (Polonsky & Keer 1999): `stickslip_normal::NormalProblem`.
    SurfaceContact,
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
    /// The Hertz sphere's subsurface field in closed form (Huber; Hamilton 1983):
    /// `stickslip_halfspace::hertz::sphere_field`.
    HertzSphereField,
    /// The sliding Hertz sphere's or ellipse's subsurface field (Hamilton 1983; Sackfield &
    /// Hills 1983), one integral in the ellipsoidal coordinate per point and shear direction:
    /// `stickslip_halfspace::hertz::ellipse_field`.
    HamiltonSlidingField,
    /// The frictionless Hertz ellipse's subsurface field (Love 1929; Sackfield & Hills 1983),
    /// one integral in the ellipsoidal coordinate per point:
    /// `stickslip_halfspace::hertz::ellipse_field`.
    HertzEllipseField,
    /// Subsurface stresses of a lattice traction by FFT per depth layer with the exact
    /// uniform-rectangle stresses (FORMULAS.md F): `stickslip_lattice::field`.
    LatticeField,
    /// Exact 3D steady rolling with creepage and spin (Kalker's boundary-element theory, FFT
    /// products, semismooth Newton): `stickslip_rolling::steady3d::SteadyRolling`.
    SteadyRolling,
    /// Kalker's simplified theory: `stickslip_rolling::steady3d::fastsim`.
    Fastsim,
    /// Polach's creep-force law: `stickslip_rolling::steady3d::polach`.
    Polach,
    /// A load path solved step by step from the previous state (incremental Coulomb
    /// friction, each step the fast solver's problem with the memory $-K\mathbf q^{n-1}$;
    /// docs/load-histories.md): `stickslip_traction::history::HistoryProblem`.
    LoadHistory,
    /// 3D rolling in time steps of one element length from a start state (Kalker's
    /// transient discretisation, each step a warm fast solve):
    /// `stickslip_rolling::steady3d::TransientRolling`.
    TransientRolling,
    /// Maugis–Dugdale adhesion on a surface's lattice along an approach path: the contact
    /// solver over a cohesive zone updated until it reproduces itself, each point from the
    /// one before: `stickslip_normal::NormalProblem::solve_adhesive`.
    AdhesiveSurface,
}

impl Technique {
    /// Every technique, in the order of declaration.
    pub const ALL: [Technique; 33] = [
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
        Technique::HertzSphereField,
        Technique::LatticeField,
        Technique::SurfaceContact,
        Technique::SteadyRolling,
        Technique::Fastsim,
        Technique::Polach,
        Technique::HamiltonSlidingField,
        Technique::HertzEllipseField,
        Technique::LoadHistory,
        Technique::TransientRolling,
        Technique::AdhesiveSurface,
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
            Technique::HertzSphereField => 22,
            Technique::LatticeField => 23,
            Technique::SurfaceContact => 24,
            Technique::SteadyRolling => 25,
            Technique::Fastsim => 26,
            Technique::Polach => 27,
            Technique::HamiltonSlidingField => 28,
            Technique::HertzEllipseField => 29,
            Technique::LoadHistory => 30,
            Technique::TransientRolling => 31,
            Technique::AdhesiveSurface => 32,
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
                | Technique::LatticeField
                | Technique::SurfaceContact
                | Technique::SteadyRolling
                | Technique::Fastsim
                | Technique::LoadHistory
                | Technique::TransientRolling
                | Technique::AdhesiveSurface
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
            Technique::SurfaceContact => {
                "normal contact of the surface on its lattice, constrained conjugate gradients with FFT products (Polonsky-Keer), spectral preconditioner, nested start from coarser lattices, numerical"
            }
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
            Technique::HertzSphereField => {
                "Hertz sphere subsurface field in closed form (Huber; Hamilton 1983)"
            }
            Technique::HamiltonSlidingField => {
                "sliding Hertz sphere or ellipse field, q = f p (Hamilton 1983; Sackfield & Hills 1983), one integral in the ellipsoidal coordinate per point to 1e-11 p0"
            }
            Technique::HertzEllipseField => {
                "Hertz ellipse subsurface field (Love 1929; Sackfield & Hills 1983), one integral in the ellipsoidal coordinate per point to 1e-11 p0"
            }
            Technique::LatticeField => {
                "lattice traction by FFT per depth layer with exact rectangle stresses (FORMULAS.md F), interpolated to the box, numerical"
            }
            Technique::SteadyRolling => {
                "exact steady rolling on the grid: Kalker's discretisation, FFT products, semismooth Newton with GMRES (FORMULAS.md R3), numerical"
            }
            Technique::Fastsim => {
                "FASTSIM, Kalker's simplified theory with one flexibility per creepage term from Kalker's C11, C22, C23 (FORMULAS.md R3); force error up to 0.1 fN against the exact theory"
            }
            Technique::Polach => {
                "Polach's closed creep-force law (no spin; FORMULAS.md R3); force error up to 0.15 fN against the exact theory"
            }
            Technique::AdhesiveSurface => {
                "Maugis-Dugdale adhesion on the surface's lattice: the contact solver (constrained conjugate gradients, FFT products) over a cohesive zone updated until it reproduces itself, each point of the approach path from the one before, numerical"
            }
            Technique::TransientRolling => {
                "transient rolling in steps of one element length from the start state (Kalker's transient discretisation, each step a warm fast solve; docs/load-histories.md), numerical"
            }
            Technique::LoadHistory => {
                "load path step by step from the previous state (incremental Coulomb friction, each step a warm fast solve; docs/load-histories.md), numerical"
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
    /// The scene's title.
    pub title: String,
    /// The scene file, when the scene came from one (for messages).
    pub file: Option<std::path::PathBuf>,
    /// The scene's source text and spans, to locate refusals found while executing.
    pub source: Option<std::sync::Arc<stickslip_scene::Source>>,
    /// What execution does: the method and resolved inputs of every stage.
    pub recipe: Recipe,
}

/// Points along the surface of 2D results.
pub const SURFACE_POINTS: usize = 201;

/// The dense LP keeps several n x n matrices; beyond this many elements it needs more than
/// about 0.5 GB and minutes of pivoting.
pub const MAX_LP_ELEMENTS: usize = 3000;

impl Plan {
    /// Plan `scene`.
    ///
    /// # Errors
    /// A [`SceneError`] naming the key (and, for a scene read from a file, the line and
    /// column) of a combination no solver handles.
    #[allow(clippy::result_large_err)]
    pub fn new(scene: &Scene) -> Result<Plan, SceneError> {
        build::build(scene).map_err(|i| scene.locate(i))
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
    pub fn explain(&self) -> String {
        let mut s = String::new();
        s.push_str(&format!("scene: {}\n", self.title));
        if let Some(f) = &self.file {
            s.push_str(&format!("file:  {}\n", f.display()));
        }
        let named = self.source.as_ref().map_or(&[][..], |src| src.materials());
        if !named.is_empty() {
            s.push_str("\nmaterials (typical values of one grade; docs/materials.md):\n");
            for (table, m) in named {
                s.push_str(&format!(
                    "  {table:<10} {}: E = {}, nu = {} ({})\n",
                    m.name,
                    stickslip_scene::materials::modulus(m.e),
                    m.nu,
                    m.grade.split_whitespace().collect::<Vec<_>>().join(" ")
                ));
            }
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

/// Every refusal a run gives before solving: the scene's own validation
/// ([`Scene::validate`]), then the planner's ([`Plan::new`]), located in the file when the
/// scene came from one.
///
/// # Errors
/// The first refusal.
pub fn check(scene: &Scene) -> Result<(), SceneError> {
    scene.validate()?;
    Plan::new(scene).map(|_| ())
}

/// Read a scene from TOML text as a run does: [`Scene::from_toml_str`], then the planner's
/// refusals ([`check`]). `file` is used in error messages only.
///
/// # Errors
/// A [`SceneError`] with the file, line, column, key and a hint.
pub fn read_scene(text: &str, file: Option<PathBuf>) -> Result<Scene, SceneError> {
    let scene = Scene::from_toml_str(text, file)?;
    Plan::new(&scene)?;
    Ok(scene)
}

/// Read a scene file as a run does: [`Scene::from_file`], then the planner's refusals
/// ([`check`]).
///
/// # Errors
/// A [`SceneError`] with the file, line, column, key and a hint.
pub fn read_scene_file(path: &Path) -> Result<Scene, SceneError> {
    let scene = Scene::from_file(path)?;
    Plan::new(&scene)?;
    Ok(scene)
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
