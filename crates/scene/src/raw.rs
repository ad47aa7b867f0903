//! The scene file as written: TOML tables with spans, before units and validation.
//! Field names here ARE the format (docs/SCENES.md); `deny_unknown_fields` makes a misspelt key
//! an error instead of a silently ignored setting.

use serde::Deserialize;
use toml::Spanned;

/// A number (SI) or a string with a unit.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub(crate) enum Qty {
    Num(f64),
    Text(String),
}

pub(crate) type SQty = Spanned<Qty>;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawScene {
    pub title: Option<String>,
    pub geometry: Spanned<RawGeometry>,
    pub substrate: Spanned<RawSubstrate>,
    pub indenter: Option<Spanned<RawIndenter>>,
    pub load: Spanned<RawLoad>,
    pub motion: Option<Spanned<RawMotion>>,
    pub outputs: Option<RawOutputs>,
    pub solver: Option<RawSolver>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawGeometry {
    pub kind: Spanned<String>,
    pub radius: Option<SQty>,
    pub semi_axes: Option<Spanned<Vec<SQty>>>,
    pub radii: Option<Spanned<Vec<SQty>>>,
    pub half_width: Option<SQty>,
    pub patches: Option<Spanned<Vec<Spanned<RawPatch>>>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPatch {
    pub shape: Spanned<String>,
    pub centre: Spanned<Vec<SQty>>,
    pub side: Option<SQty>,
    pub sides: Option<Spanned<Vec<SQty>>>,
    pub radius: Option<SQty>,
    pub pressure: SQty,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawSubstrate {
    pub model: Spanned<String>,
    pub e: Option<SQty>,
    pub e0: Option<SQty>,
    pub k: Option<Spanned<f64>>,
    pub nu: Spanned<f64>,
    pub alpha: Option<SQty>,
    pub beta: Option<SQty>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawIndenter {
    pub model: Spanned<String>,
    pub e: Option<SQty>,
    pub nu: Option<Spanned<f64>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawLoad {
    pub normal: Option<SQty>,
    pub half_width: Option<SQty>,
    pub tangential: Option<SQty>,
    pub direction_deg: Option<Spanned<f64>>,
    pub friction: Option<Spanned<f64>>,
    pub sliding: Option<bool>,
    pub moment: Option<SQty>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawMotion {
    pub kind: Spanned<String>,
    pub speed: Option<SQty>,
    pub creep: Option<Spanned<f64>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawOutputs {
    pub surface: Option<bool>,
    pub field: Option<Spanned<RawField>>,
    pub cycle: Option<Spanned<RawCycle>>,
    pub plots: Option<bool>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawField {
    pub x: Spanned<Vec<f64>>,
    pub y: Spanned<Vec<f64>>,
    pub z: Option<Spanned<Vec<f64>>>,
    pub scale: Option<Spanned<String>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawCycle {
    pub amplitude: Spanned<f64>,
    pub points: Option<Spanned<i64>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawSolver {
    pub method: Option<Spanned<String>>,
    pub grid: Option<Spanned<i64>>,
    pub tolerance: Option<Spanned<f64>>,
}
