//! Scenes: the user's way into stickslip.
//!
//! A scene is a TOML file describing one contact problem (bodies, materials, loads, motion,
//! requested outputs); the contract is `../shared/spec/SCENES.md`. This crate is the only
//! place (with the CLI) that knows about units, TOML and files; the physics crates work on
//! plain SI numbers.
//!
//! Status: only the [`units`] layer is written so far. Parsing of whole scenes, validation
//! with file/line/column errors, the effect planner and `run(scene)` are issue 10.

pub mod units;

pub use units::{parse_quantity, Dim, UnitError};
