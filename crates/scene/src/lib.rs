//! Scenes: the user's way into stickslip.
//!
//! A scene is a TOML file describing one contact problem (bodies, materials, loads, motion,
//! requested outputs); the contract is `../shared/spec/SCENES.md`. This crate is the only
//! place (with the CLI) that knows about units, TOML and files; the physics crates work on
//! plain SI numbers.
//!
//! - [`units`]: quantities with units to SI;
//! - [`Scene`]: parsing and validation, with errors naming file, line, column, key and what is
//!   allowed, including the combinations the planner refuses;
//! - [`plan`]: the effect planner ([`Plan`]): effects on/off with reasons, the technique per
//!   effect (closed form where one applies), the estimated cost; `explain` prints it;
//! - [`run()`]: the one code path from a scene to an [`Outcome`] (result.json), dispatching to
//!   the physics crates for the effects that are on and nothing else ([`Evaluations`] counts
//!   what ran);
//! - [`write_outputs`]: result.json, CSV and SVG plots, written all-or-nothing;
//! - [`scenes_page`]: the overview of a directory of scenes (`docs/scenes.md`): effects and
//!   techniques per scene, from the planner alone.
//!
//! ```no_run
//! use stickslip_scene::{run, RunOptions, Scene};
//! let scene = Scene::default_scene();
//! let out = run(&scene, &RunOptions::default()).unwrap();
//! println!("a = {} m, P = {} N/m", out.contact.a, out.contact.normal_load);
//! ```

mod error;
mod output;
mod overview;
pub mod plan;
mod plots;
mod raw;
mod run;
mod scene;
pub mod units;

pub use error::{ErrorKind, SceneError};
pub use output::{write_outputs, Written};
pub use overview::scenes_page;
pub use plan::{Cost, Effect, EffectPlan, Plan, Technique};
pub use run::{
    run, ContactOut, CycleOut, EffectsOut, Evaluations, FieldOut, Forces, GridZones, Outcome,
    Progress, RigidOut, RollingOut, RunOptions, SolverOut, SurfaceOut, Zones,
};
pub use scene::{
    Cycle, Elastic, Ellipse, FieldGrid, FieldScale, Geometry, Indenter, Load, Method, Motion,
    NormalLoad, Outputs, Patch, PatchShape, Scene, SolverOptions, Substrate, DEFAULT_SCENE,
    MAX_GRID,
};
pub use units::{parse_quantity, Dim, UnitError};
