//! The run of a stickslip scene: the planner (`stickslip-plan`, re-exported here as
//! [`plan`]) decides how each effect is computed, the stages compute it with the physics
//! crates, and the audit checks the result before anyone sees it.
//!
//! The path of a run is **scene → plan → execute → audit**; the scene itself (its format,
//! reading and validation) is `stickslip-scene`, the files written from a result are
//! `stickslip-report`.
//!
//! - [`plan`] (the crate `stickslip-plan`, re-exported): the planner ([`Plan::new`]): the
//!   refusals of what no solver handles, a typed [`Recipe`] (the method and resolved inputs
//!   of every stage), the effects on/off with reasons, the estimated [`Cost`] and the
//!   machine check; `explain` prints it ([`Plan::explain`]); [`read_scene`],
//!   [`read_scene_file`] and [`check`] read a scene and refuse it as a run refuses it (the
//!   format's checks, then the planner's); [`scenes_page`] is the overview of a directory
//!   of scenes (`docs/scenes.md`), from the planner alone;
//! - [`exec`]: [`Execute::execute`] (`plan.execute(&opts)`) runs the recipe stage by stage
//!   (normal contact → friction → twist → rolling → load cycle → subsurface field), deciding
//!   nothing again ([`Evaluations`] counts what ran), audits the result and returns an
//!   [`Outcome`] (the content of result.json); [`run()`] is plan + execute;
//! - [`reference`](mod@reference): the closed forms a plot draws beside a result.
//!
//! ```
//! use stickslip_run::{run, RunOptions};
//! use stickslip_scene::Scene;
//! let scene = Scene::from_toml_str(
//!     r#"
//! [geometry]
//! kind = "cylinder"
//! radius = "20 mm"
//! [substrate]
//! model = "homogeneous"
//! e = "210 GPa"
//! nu = 0.3
//! [indenter]
//! model = "same"
//! [load]
//! normal = "100 kN/m"
//! tangential = "15 kN/m"
//! friction = 0.3
//! "#,
//!     None,
//! )
//! .unwrap();
//! let out = run(&scene, &RunOptions::default()).unwrap();
//! assert!(out.audit.passed);
//! // 2D Hertz: a^2 = 4 P R / (pi E*), E* = E / (2 (1 - nu^2)) for two steel bodies.
//! let e_star = 210e9 / (2.0 * (1.0 - 0.3 * 0.3));
//! let a = (4.0 * 100e3 * 0.02 / (std::f64::consts::PI * e_star)).sqrt();
//! assert!((out.contact.a - a).abs() < 1e-12 * a);
//! assert_eq!(out.forces.tangential, 15e3);
//! ```

// SceneError carries file, position, key and hint for the user; one per call.
#![allow(clippy::result_large_err)]

pub mod exec;
pub mod reference;

/// The planner, `stickslip-plan`, under the name the stages use.
pub use stickslip_plan as plan;

pub use exec::outcome::{
    Audit, Check, ContactOut, CycleOut, EffectsOut, Evaluations, Field, FieldArrays, FieldMax,
    FieldOut, FieldPeak, Forces, GridZones, HistoryLoopOut, HistoryOut, LoadCurve, NormalSolverOut,
    Outcome, PatchMaps, Progress, RigidOut, RollingOut, RuizMaxOut, RunOptions, SolverOut,
    SurfaceOut, TrackForce, VolumeField, WheelRailOut, WheelRailPatchOut, Zones,
    INLINE_FIELD_POINTS,
};
pub use exec::{execute, Execute};
pub use stickslip_plan::recipe::Recipe;
pub use stickslip_plan::{
    check, read_scene, read_scene_file, scenes_page, Cost, Effect, EffectPlan, MachineLimits, Plan,
    Technique, DEFAULT_TIME_LIMIT_SECONDS,
};
use stickslip_scene::{Scene, SceneError};

/// Plan `scene` and execute the plan: [`Plan::new`] then [`Execute::execute`].
///
/// # Errors
/// A [`SceneError`] for a scene the planner refuses, or (kind
/// [`Solver`](stickslip_scene::ErrorKind::Solver)) when a physics routine fails or returns a
/// non-finite number, or (kind [`Audit`](stickslip_scene::ErrorKind::Audit)) when the result
/// fails its audit.
pub fn run(scene: &Scene, opts: &RunOptions<'_>) -> Result<Outcome, SceneError> {
    Plan::new(scene)?.execute(opts)
}
