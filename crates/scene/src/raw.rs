//! The scene file as written: TOML tables with spans, before units and validation.
//! Field names here ARE the format (docs/SCENES.md); `deny_unknown_fields` makes a misspelt key
//! an error instead of a silently ignored setting.

use schemars::JsonSchema;
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

/// `load.normal`: one force, or a sweep `[from, to, steps]`.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(untagged)]
pub(crate) enum RawNormal {
    /// One force.
    One(Qty),
    /// A load sweep: from, to (forces), and the number of steps (spans inside an untagged
    /// value are not available; refusals point at the array).
    Sweep(Vec<Qty>),
}

/// In the JSON Schema a quantity is a number (SI) or a string that starts with a number; the
/// unit and its dimension are the reader's to check (`crate::units`).
impl JsonSchema for Qty {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "Quantity".into()
    }

    fn json_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
        schemars::json_schema!({
            "description": "A number in SI units, or a string: a number and a unit, e.g. \"10 mm\", \"1 mN\", \"210 GPa\", \"30e6 psi\", \"10 cm/s\". Units: m, N, Pa, s with a prefix p n u m c k M G; in ft lbf kgf psi ksi min h.",
            "anyOf": [
                { "type": "number" },
                { "type": "string", "pattern": "^\\s*[-+]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?(\\s*[^\\s].*)?$" }
            ]
        })
    }
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawScene {
    /// A title for messages, plots and result.json.
    pub title: Option<String>,
    /// What touches what: the kind of contact and its dimensions.
    #[schemars(with = "RawGeometry")]
    pub geometry: Spanned<RawGeometry>,
    /// The body below.
    #[schemars(with = "RawSubstrate")]
    pub substrate: Spanned<RawSubstrate>,
    /// The body above; rigid when the table is absent.
    #[schemars(with = "Option<RawIndenter>")]
    pub indenter: Option<Spanned<RawIndenter>>,
    /// Wheel-rail: the wheelset's position on the track.
    #[schemars(with = "Option<RawPosition>")]
    pub position: Option<Spanned<RawPosition>>,
    /// Normal and tangential loads, friction, moment.
    #[schemars(with = "RawLoad")]
    pub load: Spanned<RawLoad>,
    /// Static (the default) or steady rolling.
    #[schemars(with = "Option<RawMotion>")]
    pub motion: Option<Spanned<RawMotion>>,
    /// What to compute beyond the contact solution.
    pub outputs: Option<RawOutputs>,
    /// How to solve; the planner chooses when absent.
    pub solver: Option<RawSolver>,
    /// The interface beyond elastic contact (a hardness cap, adhesion); elastic when absent.
    pub interface: Option<RawInterface>,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawInterface {
    /// Hardness H (stress, e.g. "2 GPa"): the contact pressure is capped at H (surface
    /// lattices only).
    #[schemars(with = "Option<Qty>")]
    pub hardness: Option<SQty>,
    /// Maugis–Dugdale adhesion: `{ work = "50 mJ/m^2", range = "10 nm" }` (surface lattices
    /// under an approach, `load.approach`).
    #[schemars(with = "Option<RawAdhesion>")]
    pub adhesion: Option<Spanned<RawAdhesion>>,
}

/// `interface.adhesion`: the work of adhesion and the range of the attraction.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawAdhesion {
    /// The work of adhesion w (energy per area, e.g. "50 mJ/m^2").
    #[schemars(with = "Option<Qty>")]
    pub work: Option<SQty>,
    /// The range h0 over which the constant attraction w/h0 acts (length, e.g. "10 nm").
    #[schemars(with = "Option<Qty>")]
    pub range: Option<SQty>,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawGeometry {
    /// The kind of contact.
    #[schemars(with = "String")]
    pub kind: Spanned<String>,
    /// Radius R of the cylinder or sphere (length, e.g. "10 mm").
    #[schemars(with = "Option<Qty>")]
    pub radius: Option<SQty>,
    /// Ellipsoid: the contact semi-axes [a, b] (lengths).
    #[schemars(with = "Option<Vec<Qty>>")]
    pub semi_axes: Option<Spanned<Vec<SQty>>>,
    /// Ellipsoid: the relative radii of curvature [Rx, Ry] (lengths).
    #[schemars(with = "Option<Vec<Qty>>")]
    pub radii: Option<Spanned<Vec<SQty>>>,
    /// Punch: the half-width (length).
    #[schemars(with = "Option<Qty>")]
    pub half_width: Option<SQty>,
    /// Patches: the flat contact patches with their pressures.
    #[schemars(with = "Option<Vec<RawPatch>>")]
    pub patches: Option<Spanned<Vec<Spanned<RawPatch>>>>,
    /// Surface: free (an isolated contact) or periodic (the lattice is one period).
    #[schemars(with = "Option<String>")]
    pub boundary: Option<Spanned<String>>,
    /// Surface: the lattice extent [x, y] (lengths).
    #[schemars(with = "Option<Vec<Qty>>")]
    pub size: Option<Spanned<Vec<SQty>>>,
    /// Surface: the cells along x and y, e.g. [256, 256].
    #[schemars(with = "Option<Vec<f64>>")]
    pub cells: Option<Spanned<Vec<f64>>>,
    /// Surface: the smooth part of the gap.
    #[schemars(with = "Option<RawProfile>")]
    pub profile: Option<Spanned<RawProfile>>,
    /// Surface: roughness from a file or generated.
    #[schemars(with = "Option<RawRoughness>")]
    pub roughness: Option<Spanned<RawRoughness>>,
    /// Wheel-rail: "left" or "right" (the left side mirrors the right).
    #[schemars(with = "Option<String>")]
    pub side: Option<Spanned<String>>,
    /// Wheel-rail: the rail profile file (.prr, .ban, or two columns y z), relative to the scene file.
    #[schemars(with = "Option<String>")]
    pub rail_profile: Option<Spanned<String>>,
    /// Wheel-rail: the wheel profile file (.prw, .whl, or two columns y z), relative to the scene file.
    #[schemars(with = "Option<String>")]
    pub wheel_profile: Option<Spanned<String>>,
    /// Wheel-rail: the length unit of the profile files, e.g. "mm" (default) or "m".
    #[schemars(with = "Option<String>")]
    pub profile_unit: Option<Spanned<String>>,
    /// Wheel-rail: the track gauge (length, e.g. "1435 mm").
    #[schemars(with = "Option<Qty>")]
    pub gauge: Option<SQty>,
    /// Wheel-rail: the depth below the track plane at which the gauge is measured (length).
    #[schemars(with = "Option<Qty>")]
    pub gauge_height: Option<SQty>,
    /// Wheel-rail: the rail cant (angle: rad, mrad or deg; default 0).
    #[schemars(with = "Option<Qty>")]
    pub rail_cant: Option<SQty>,
    /// Wheel-rail: the wheelset's flange back distance (length).
    #[schemars(with = "Option<Qty>")]
    pub flange_back_distance: Option<SQty>,
    /// Wheel-rail: the flange back's position in the wheel profile's own y (length).
    #[schemars(with = "Option<Qty>")]
    pub flange_back_position: Option<SQty>,
    /// Wheel-rail: the nominal wheel radius at the wheel profile's origin (length).
    #[schemars(with = "Option<Qty>")]
    pub wheel_radius: Option<SQty>,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPosition {
    /// Lateral displacement of the wheelset along y (length; default 0).
    #[schemars(with = "Option<Qty>")]
    pub lateral: Option<SQty>,
    /// Yaw angle (rad, mrad or deg; default 0).
    #[schemars(with = "Option<Qty>")]
    pub yaw: Option<SQty>,
    /// Roll angle (rad, mrad or deg; default 0).
    #[schemars(with = "Option<Qty>")]
    pub roll: Option<SQty>,
}

// The crowned cylinder's keys (length, crown, end_radius) are part of the format and are
// refused by the reader until that profile is solved.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[allow(dead_code)]
pub(crate) struct RawProfile {
    /// The profile shape.
    #[schemars(with = "String")]
    pub shape: Spanned<String>,
    /// Sphere: the radius; punch: the radius of the flat face; cylinder: the roller radius (length).
    #[schemars(with = "Option<Qty>")]
    pub radius: Option<SQty>,
    /// Ellipsoid: the radii [Rx, Ry] (lengths).
    #[schemars(with = "Option<Vec<Qty>>")]
    pub radii: Option<Spanned<Vec<SQty>>>,
    /// Punch: the edge radius (length); left out or 0, the edge is sharp (Boussinesq).
    #[schemars(with = "Option<Qty>")]
    pub edge_radius: Option<SQty>,
    /// Wavy: the wavelength (length).
    #[schemars(with = "Option<Qty>")]
    pub wavelength: Option<SQty>,
    /// Wavy: the amplitude (length).
    #[schemars(with = "Option<Qty>")]
    pub amplitude: Option<SQty>,
    /// Wavy: waves along x, or along x and y.
    #[schemars(with = "Option<String>")]
    pub along: Option<Spanned<String>>,
    /// Cylinder: the roller length along y (length).
    #[schemars(with = "Option<Qty>")]
    pub length: Option<SQty>,
    /// Cylinder: the crown drop at the roller ends (length; default 0, no crown).
    #[schemars(with = "Option<Qty>")]
    pub crown: Option<SQty>,
    /// Cylinder: the radius of the rounded ends (length; needed with a crown).
    #[schemars(with = "Option<Qty>")]
    pub end_radius: Option<SQty>,
}

// Generated roughness's keys (hurst, rms_height, ...) are part of the format and are refused
// by the reader until generation is implemented.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[allow(dead_code)]
pub(crate) struct RawRoughness {
    /// Heights from a file: .npy of float64 (ny, nx) or .csv with one row per y, relative to the scene file.
    #[schemars(with = "Option<String>")]
    pub file: Option<Spanned<String>>,
    /// The length unit of the heights in the file, e.g. "um" or "nm" (default m).
    #[schemars(with = "Option<String>")]
    pub unit: Option<Spanned<String>>,
    /// Generated: the Hurst exponent, 0 < H <= 1.
    #[schemars(with = "Option<f64>")]
    pub hurst: Option<Spanned<f64>>,
    /// Generated: the rms height (length); or give rms_slope.
    #[schemars(with = "Option<Qty>")]
    pub rms_height: Option<SQty>,
    /// Generated: the rms slope; or give rms_height.
    #[schemars(with = "Option<f64>")]
    pub rms_slope: Option<Spanned<f64>>,
    /// Generated: the lowest wavenumber (cycles per lattice length along x), >= 1.
    #[schemars(with = "Option<f64>")]
    pub k_low: Option<Spanned<f64>>,
    /// Generated: the roll-off wavenumber, k_low <= k_rolloff <= k_high.
    #[schemars(with = "Option<f64>")]
    pub k_rolloff: Option<Spanned<f64>>,
    /// Generated: the highest wavenumber (default: the Nyquist limit).
    #[schemars(with = "Option<f64>")]
    pub k_high: Option<Spanned<f64>>,
    /// Generated: the random seed, a whole number >= 0.
    #[schemars(with = "Option<i64>")]
    pub seed: Option<Spanned<i64>>,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPatch {
    /// The outline of the patch.
    #[schemars(with = "String")]
    pub shape: Spanned<String>,
    /// The centre [x, y] (lengths).
    #[schemars(with = "Vec<Qty>")]
    pub centre: Spanned<Vec<SQty>>,
    /// Square: the side (length).
    #[schemars(with = "Option<Qty>")]
    pub side: Option<SQty>,
    /// Rectangle: the sides [along x, along y] (lengths).
    #[schemars(with = "Option<Vec<Qty>>")]
    pub sides: Option<Spanned<Vec<SQty>>>,
    /// Circle: the radius (length).
    #[schemars(with = "Option<Qty>")]
    pub radius: Option<SQty>,
    /// The uniform pressure on the patch (stress, e.g. "10 MPa").
    #[schemars(with = "Qty")]
    pub pressure: SQty,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawSubstrate {
    /// The material model: "homogeneous" (the default), "graded" or "viscoelastic".
    #[schemars(with = "Option<String>")]
    pub model: Option<Spanned<String>>,
    /// A named material (docs/materials.md) instead of e and nu: homogeneous and viscoelastic only.
    #[schemars(with = "Option<String>")]
    pub material: Option<Spanned<String>>,
    /// Young's modulus (stress, e.g. "210 GPa"); the long-time modulus when viscoelastic.
    #[schemars(with = "Option<Qty>")]
    pub e: Option<SQty>,
    /// Graded: E0 of E = e0 y^k, in force/length^(2+k), e.g. "1767600 kgf/m^2.1".
    #[schemars(with = "Option<Qty>")]
    pub e0: Option<SQty>,
    /// Graded: the exponent k of E = e0 y^k, 0 <= k < 1.
    #[schemars(with = "Option<f64>")]
    pub k: Option<Spanned<f64>>,
    /// Poisson's ratio, -1 < nu <= 0.5 (required unless material is given).
    #[schemars(with = "Option<f64>")]
    pub nu: Option<Spanned<f64>>,
    /// Viscoelastic: the retardation time (time, e.g. "2 s").
    #[schemars(with = "Option<Qty>")]
    pub alpha: Option<SQty>,
    /// Viscoelastic: the relaxation time (time), beta <= alpha.
    #[schemars(with = "Option<Qty>")]
    pub beta: Option<SQty>,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawIndenter {
    /// Rigid, homogeneous elastic, or the same material as the substrate: "rigid",
    /// "homogeneous" or "same". Left out: "homogeneous" when material, e or nu is given,
    /// "rigid" otherwise.
    #[schemars(with = "Option<String>")]
    pub model: Option<Spanned<String>>,
    /// Homogeneous: a named material (docs/materials.md) instead of e and nu.
    #[schemars(with = "Option<String>")]
    pub material: Option<Spanned<String>>,
    /// Homogeneous: Young's modulus (stress).
    #[schemars(with = "Option<Qty>")]
    pub e: Option<SQty>,
    /// Homogeneous: Poisson's ratio, -1 < nu <= 0.5.
    #[schemars(with = "Option<f64>")]
    pub nu: Option<Spanned<f64>>,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawLoad {
    /// The normal force: N/m for a cylinder or punch (2D), N otherwise; for a surface also a
    /// load sweep `[from, to, steps]`, e.g. ["1 N", "100 N", 20].
    #[schemars(with = "Option<RawNormal>")]
    pub normal: Option<Spanned<RawNormal>>,
    /// Instead of normal: the contact half-width (length).
    #[schemars(with = "Option<Qty>")]
    pub half_width: Option<SQty>,
    /// Surface, instead of normal: the approach of the bodies (length), or an approach path
    /// `[from, to, steps]` in equal steps (any sign; more corners before `steps` make a path
    /// that turns, e.g. ["-20 nm", "100 nm", "-20 nm", 60]).
    #[schemars(with = "Option<RawNormal>")]
    pub approach: Option<Spanned<RawNormal>>,
    /// The tangential force (N/m in 2D, N in 3D).
    #[schemars(with = "Option<Qty>")]
    pub tangential: Option<SQty>,
    /// The direction of the tangential force, degrees from +x.
    #[schemars(with = "Option<f64>")]
    pub direction_deg: Option<Spanned<f64>>,
    /// The Coulomb friction coefficient, >= 0.
    #[schemars(with = "Option<f64>")]
    pub friction: Option<Spanned<f64>>,
    /// Full sliding: q = f p.
    pub sliding: Option<bool>,
    /// A twisting moment about the contact normal (force x length, e.g. "0.5 N m").
    #[schemars(with = "Option<Qty>")]
    pub moment: Option<SQty>,
    /// A load path solved step by step from the previous state (a static 3D contact).
    #[schemars(with = "Option<RawHistory>")]
    pub history: Option<Spanned<RawHistory>>,
    /// A wheel on its rail: what carries the vertical wheel load `normal`: "normal" (the
    /// default: the vertical components of the patches' normal forces) or "total" (the
    /// total vertical force of the wheel on the rail, creep forces included, as CONTACT's
    /// force control).
    #[schemars(with = "Option<RawVertical>")]
    pub vertical: Option<Spanned<String>>,
}

/// `load.vertical`'s values (for the schema).
#[derive(JsonSchema)]
#[serde(rename_all = "lowercase")]
#[allow(dead_code)]
pub(crate) enum RawVertical {
    /// The vertical components of the patches' normal forces carry the load.
    Normal,
    /// The total vertical force, creep forces included, carries the load (CONTACT's).
    Total,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawHistory {
    /// Corner values of the tangential force along direction_deg (forces, e.g. ["0 N", "20 N", "-20 N", "20 N"]), applied in order.
    #[schemars(with = "Option<Vec<Qty>>")]
    pub tangential: Option<Spanned<Vec<SQty>>>,
    /// Instead of tangential: corner values of the rigid tangential shift of the bodies (lengths, e.g. ["0 um", "2 um", "-2 um"]); beyond the onset of sliding the contact slides.
    #[schemars(with = "Option<Vec<Qty>>")]
    pub shift: Option<Spanned<Vec<SQty>>>,
    /// Corner values of the normal load (forces, as many as the tangential values); load.normal throughout when absent.
    #[schemars(with = "Option<Vec<Qty>>")]
    pub normal: Option<Spanned<Vec<SQty>>>,
    /// Corner values of the twisting moment (force x length, as many as the tangential values).
    #[schemars(with = "Option<Vec<Qty>>")]
    pub moment: Option<Spanned<Vec<SQty>>>,
    /// Linear sub-steps between two corners, 1 to 10000 (default 10).
    #[schemars(with = "Option<i64>")]
    pub steps: Option<Spanned<i64>>,
    /// Instead of the lists: a table of corners (text, comma-separated, relative to the scene file), one row per corner, a header naming the columns tangential or shift, normal, moment, each with its unit ("tangential [N]", or "tangential_N" as in a run's history.csv) unless `units` gives it.
    #[schemars(with = "Option<String>")]
    pub file: Option<Spanned<String>>,
    /// With `file`: the columns to read (others are ignored), e.g. ["tangential", "normal"] to read a run's history.csv; default every column, each of which must be one of tangential, shift, normal, moment.
    #[schemars(with = "Option<Vec<String>>")]
    pub columns: Option<Spanned<Vec<Spanned<String>>>>,
    /// With `file`: the unit of each column whose header gives none, e.g. { tangential = "kN", shift = "um" }.
    #[schemars(with = "Option<RawHistoryUnits>")]
    pub units: Option<Spanned<RawHistoryUnits>>,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawHistoryUnits {
    /// Unit of the tangential column (a force, e.g. "N", "kN", "lbf").
    #[schemars(with = "Option<String>")]
    pub tangential: Option<Spanned<String>>,
    /// Unit of the shift column (a length, e.g. "um").
    #[schemars(with = "Option<String>")]
    pub shift: Option<Spanned<String>>,
    /// Unit of the normal column (a force).
    #[schemars(with = "Option<String>")]
    pub normal: Option<Spanned<String>>,
    /// Unit of the moment column (force x length, e.g. "N m").
    #[schemars(with = "Option<String>")]
    pub moment: Option<Spanned<String>>,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawMotion {
    /// "static" or "rolling". Left out: "rolling" when speed, creep or creepage is given,
    /// "static" otherwise.
    #[schemars(with = "Option<String>")]
    pub kind: Option<Spanned<String>>,
    /// Rolling: the speed (length/time, e.g. "10 cm/s").
    #[schemars(with = "Option<Qty>")]
    pub speed: Option<SQty>,
    /// 2D rolling of a cylinder: the creep ratio (omega R - w) / w.
    #[schemars(with = "Option<f64>")]
    pub creep: Option<Spanned<f64>>,
    /// 3D rolling: the longitudinal, lateral and spin creepages.
    #[schemars(with = "Option<RawCreepage>")]
    pub creepage: Option<Spanned<RawCreepage>>,
    /// Wheel-rail: the wheelset's angular velocity about its axle (e.g. "-4.35 rad/s");
    /// default free rolling, -speed / wheel_radius.
    #[schemars(with = "Option<Qty>")]
    pub pitch_rate: Option<SQty>,
    /// 3D rolling solved in time steps from a start state (transient rolling): the creep
    /// force is load.tangential and the creepages follow from it, or, when
    /// creepage.longitudinal or lateral is given, the contact rolls at those creepages and
    /// the force follows.
    #[schemars(with = "Option<RawTransient>")]
    pub transient: Option<Spanned<RawTransient>>,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawTransient {
    /// "shift" (default): the creep force is first applied at rest, a Cattaneo shift, then
    /// the contact rolls under it; "rest": the contact rolls from the unloaded state with
    /// the creep force applied from the first step.
    #[schemars(with = "Option<String>")]
    pub start: Option<Spanned<String>>,
    /// The distance rolled (a length), in steps of one element length; default two contact
    /// lengths along the rolling direction.
    #[schemars(with = "Option<Qty>")]
    pub distance: Option<SQty>,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawCreepage {
    /// Longitudinal creepage xi (dimensionless), default 0.
    #[schemars(with = "Option<f64>")]
    pub longitudinal: Option<Spanned<f64>>,
    /// Lateral creepage eta (dimensionless), default 0.
    #[schemars(with = "Option<f64>")]
    pub lateral: Option<Spanned<f64>>,
    /// Spin creepage, a reciprocal length with its unit (e.g. "0.1 1/m"), default 0.
    #[schemars(with = "Option<Qty>")]
    pub spin: Option<SQty>,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawOutputs {
    /// Surface arrays (pressure, tractions, displacements, zones); default true.
    pub surface: Option<bool>,
    /// Subsurface stresses on a grid.
    #[schemars(with = "Option<RawField>")]
    pub field: Option<Spanned<RawField>>,
    /// A loading cycle (hysteresis) of the tangential load.
    #[schemars(with = "Option<RawCycle>")]
    pub cycle: Option<Spanned<RawCycle>>,
    /// SVG plots beside result.json and in report.html; default true (false turns them off).
    pub plots: Option<bool>,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawField {
    /// x: [from, to, count]; with scale = "m", from and to may be lengths with units
    /// ("-1.5 mm").
    #[schemars(with = "Vec<Qty>")]
    pub x: Spanned<Vec<SQty>>,
    /// 2D: depth [from, to, count] (from > 0); 3D: y [from, to, count].
    #[schemars(with = "Vec<Qty>")]
    pub y: Spanned<Vec<SQty>>,
    /// 3D only: depth [from, to, count] (from > 0).
    #[schemars(with = "Option<Vec<Qty>>")]
    pub z: Option<Spanned<Vec<SQty>>>,
    /// The unit of the coordinates: the contact half-width a, or metres.
    #[schemars(with = "Option<String>")]
    pub scale: Option<Spanned<String>>,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawCycle {
    /// The amplitude T*/(f P), in (0, 1].
    #[schemars(with = "f64")]
    pub amplitude: Spanned<f64>,
    /// Points along the loop, 4 to 100000 (default 60).
    #[schemars(with = "Option<i64>")]
    pub points: Option<Spanned<i64>>,
}

#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawSolver {
    /// The method; auto lets the planner choose.
    #[schemars(with = "Option<String>")]
    pub method: Option<Spanned<String>>,
    /// Elements per side of grid solvers.
    #[schemars(with = "Option<i64>")]
    pub grid: Option<Spanned<i64>>,
    /// The relative tolerance.
    #[schemars(with = "Option<f64>")]
    pub tolerance: Option<Spanned<f64>>,
    /// Wheel-rail: the element size [along x, across the patch] (lengths, e.g. ["0.2 mm", "0.2 mm"]).
    #[schemars(with = "Option<Vec<Qty>>")]
    pub cell: Option<Spanned<Vec<SQty>>>,
}
