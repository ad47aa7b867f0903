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
    pub boundary: Option<Spanned<String>>,
    pub size: Option<Spanned<Vec<SQty>>>,
    pub cells: Option<Spanned<Vec<f64>>>,
    pub profile: Option<Spanned<RawProfile>>,
    pub roughness: Option<Spanned<RawRoughness>>,
}

// The crowned cylinder's keys (length, crown, end_radius) are part of the format and are
// refused by the reader until that profile is solved.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[allow(dead_code)]
pub(crate) struct RawProfile {
    pub shape: Spanned<String>,
    pub radius: Option<SQty>,
    pub radii: Option<Spanned<Vec<SQty>>>,
    pub edge_radius: Option<SQty>,
    pub wavelength: Option<SQty>,
    pub amplitude: Option<SQty>,
    pub along: Option<Spanned<String>>,
    pub length: Option<SQty>,
    pub crown: Option<SQty>,
    pub end_radius: Option<SQty>,
}

// Generated roughness's keys (hurst, rms_height, ...) are part of the format and are refused
// by the reader until generation is implemented.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[allow(dead_code)]
pub(crate) struct RawRoughness {
    pub file: Option<Spanned<String>>,
    pub unit: Option<Spanned<String>>,
    pub hurst: Option<Spanned<f64>>,
    pub rms_height: Option<SQty>,
    pub rms_slope: Option<Spanned<f64>>,
    pub k_low: Option<Spanned<f64>>,
    pub k_rolloff: Option<Spanned<f64>>,
    pub k_high: Option<Spanned<f64>>,
    pub seed: Option<Spanned<i64>>,
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
    pub material: Option<Spanned<String>>,
    pub e: Option<SQty>,
    pub e0: Option<SQty>,
    pub k: Option<Spanned<f64>>,
    pub nu: Option<Spanned<f64>>,
    pub alpha: Option<SQty>,
    pub beta: Option<SQty>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawIndenter {
    pub model: Spanned<String>,
    pub material: Option<Spanned<String>>,
    pub e: Option<SQty>,
    pub nu: Option<Spanned<f64>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawLoad {
    pub normal: Option<SQty>,
    pub half_width: Option<SQty>,
    pub approach: Option<SQty>,
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
