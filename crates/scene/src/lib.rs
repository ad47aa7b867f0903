//! Scenes: the user's way into stickslip.
//!
//! A scene is a TOML file describing one contact problem (bodies, materials, loads, motion,
//! requested outputs); the contract is `../shared/spec/SCENES.md`. This crate is the only
//! place (with the CLI) that knows about units, TOML and files; the physics crates work on
//! plain SI numbers.
//!
//! Written so far: [`units`] (quantities with units to SI) and [`Scene`] (parsing and
//! validation, with errors naming file, line, column, key and what is allowed). The effect
//! planner and `run(scene)` are still to come (issue 10).

mod error;
mod raw;
mod scene;
pub mod units;

pub use error::{ErrorKind, SceneError};
pub use scene::{
    Cycle, Elastic, Ellipse, FieldGrid, FieldScale, Geometry, Indenter, Load, Method, Motion,
    NormalLoad, Outputs, Patch, PatchShape, Scene, SolverOptions, Substrate, DEFAULT_SCENE,
    MAX_GRID,
};
pub use units::{parse_quantity, Dim, UnitError};
