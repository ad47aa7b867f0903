//! Scenes: the user's way into stickslip.
//!
//! A scene is a TOML file describing one contact problem (bodies, materials, loads, motion,
//! requested outputs); its reference is the repository's `docs/SCENES.md`. This crate is the
//! only place (with the CLI) that knows about units, TOML and files; the physics crates work
//! on plain SI numbers.
//!
//! The path of a scene is **scene → validate → plan → execute**:
//!
//! - [`units`]: quantities with units to SI; [`materials`]: named materials (`material =
//!   "steel"`);
//! - [`Scene`]: parsing and validation, with errors naming file, line, column, key and what is
//!   allowed, including the combinations the planner refuses;
//! - [`plan`]: the planner ([`Plan::new`]): a typed [`Recipe`] (the method and resolved
//!   inputs of every stage), the effects on/off with reasons, the estimated cost; `explain`
//!   prints it;
//! - [`exec`]: [`Plan::execute`] runs the recipe stage by stage (normal contact → friction
//!   → twist → rolling → load cycle → subsurface field) into an [`Outcome`] (result.json),
//!   deciding nothing again ([`Evaluations`] counts what ran); [`run()`] is plan + execute;
//! - [`write_outputs`]: result.json, CSV, SVG plots and report.html, written all-or-nothing
//!   ([`write_outputs_report`] puts the scene and its plan into the report);
//! - [`json_schema`]: the JSON Schema of the format, for editors; [`templates`]: the
//!   commented starting scenes of `stickslip new`;
//! - [`sweep`]: parameter sweeps (the cartesian product of varied keys, shards, the CSV
//!   and Parquet table, merging shards);
//! - [`scenes_page`]: the overview of a directory of scenes (`docs/scenes.md`): effects and
//!   techniques per scene, from the planner alone.
//!
//! ```
//! use stickslip_scene::{run, RunOptions, Scene};
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

mod error;
pub mod exec;
pub mod json_schema;
pub mod materials;
mod output;
mod overview;
pub mod plan;
mod plots;
mod raw;
mod report;
mod scene;
pub mod sweep;
pub mod templates;
pub mod units;

pub use error::{Check, ErrorKind, Issue, SceneError};
pub use exec::outcome::{
    Audit, ContactOut, CycleOut, EffectsOut, Evaluations, Field, FieldArrays, FieldMax, FieldOut,
    FieldPeak, Forces, GridZones, Outcome, Progress, RigidOut, RollingOut, RunOptions, SolverOut,
    SurfaceOut, VolumeField, Zones, INLINE_FIELD_POINTS,
};
pub use output::{write_outputs, write_outputs_report, write_outputs_with, WriteOptions, Written};
pub use overview::scenes_page;
pub use plan::recipe::Recipe;
pub use plan::{
    Cost, Effect, EffectPlan, MachineLimits, Plan, Technique, DEFAULT_TIME_LIMIT_SECONDS,
};
pub use report::ReportContext;

/// Plan `scene` and execute the plan: [`Plan::new`] then [`Plan::execute`].
///
/// # Errors
/// A [`SceneError`] for a scene the planner refuses, or (kind [`ErrorKind::Solver`]) when a
/// physics routine fails or returns a non-finite number.
#[allow(clippy::result_large_err)]
pub fn run(scene: &Scene, opts: &RunOptions<'_>) -> Result<Outcome, SceneError> {
    Plan::new(scene)?.execute(opts)
}

/// Every refusal a run gives before solving: the scene's own validation
/// ([`Scene::validate`]), then the planner's ([`Plan::new`]), located in the file when the
/// scene came from one.
///
/// # Errors
/// The first refusal.
#[allow(clippy::result_large_err)]
pub fn check(scene: &Scene) -> Result<(), SceneError> {
    scene.validate()?;
    Plan::new(scene).map(|_| ())
}

/// Read a scene from TOML text as a run does: [`Scene::from_toml_str`], then the planner's
/// refusals ([`check`]). `file` is used in error messages only.
///
/// # Errors
/// A [`SceneError`] with the file, line, column, key and a hint.
#[allow(clippy::result_large_err)]
pub fn read_scene(text: &str, file: Option<std::path::PathBuf>) -> Result<Scene, SceneError> {
    let scene = Scene::from_toml_str(text, file)?;
    Plan::new(&scene)?;
    Ok(scene)
}

/// Read a scene file as a run does: [`Scene::from_file`], then the planner's refusals
/// ([`check`]).
///
/// # Errors
/// A [`SceneError`] with the file, line, column, key and a hint.
#[allow(clippy::result_large_err)]
pub fn read_scene_file(path: &std::path::Path) -> Result<Scene, SceneError> {
    let scene = Scene::from_file(path)?;
    Plan::new(&scene)?;
    Ok(scene)
}
pub use scene::{
    patch_bounds, Cycle, Elastic, Ellipse, FieldGrid, FieldScale, Geometry, Indenter, Load, Method,
    Motion, NormalLoad, NormalSweep, Outputs, Patch, PatchShape, Scene, SceneBuilder,
    SolverOptions, Source, Substrate, DEFAULT_SCENE, MAX_GRID,
};
pub use units::{parse_quantity, Dim, UnitError};
