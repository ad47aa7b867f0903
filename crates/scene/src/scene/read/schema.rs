//! Plain words for a scene file that does not fit the format.
//!
//! The reader deserialises the file into the `raw` structs with serde; serde's messages
//! ("invalid type: string \"0.3\", expected f64", "data did not match any variant of
//! untagged enum Qty", "missing field `nu`") name Rust types and never the dotted key. When
//! serde refuses a file, [`explain`] walks the TOML document itself (with the spans of
//! `toml::de::DeTable`) against a description of the format ([`TOP`], the same keys as
//! `crate::raw`) and says what is wrong in the words of docs/SCENES.md: the full dotted
//! key, what was found, what is expected, and a hint; line and column come from the span.
//! Whatever it cannot explain gets the key located from serde's span and a message with
//! every internal name removed.

use std::ops::Range;

use toml::de::{DeTable, DeValue};
use toml::Spanned;

use crate::error::{ErrorKind, SceneError};

/// What a key takes.
#[derive(Clone, Copy)]
enum Kind {
    /// A string; the allowed values when the format fixes them (for the hint).
    Str(&'static [&'static str]),
    /// A number (integer or float).
    Num,
    /// A whole number.
    Int,
    /// true or false.
    Bool,
    /// A number in SI or a string with a unit; an example for the hint.
    Qty(&'static str),
    /// An array of quantities; an example for the hint.
    QtyArray(&'static str),
    /// A quantity, or an array of quantities (`load.normal`'s sweep); examples of both.
    QtyOrArray(&'static str, &'static str),
    /// An array of numbers; an example for the hint.
    NumArray(&'static str),
    /// An array of strings; an example for the hint.
    StrArray(&'static str),
    /// A table.
    Table(&'static Table),
    /// An array of tables.
    TableArray(&'static Table),
}

struct Field {
    name: &'static str,
    kind: Kind,
    required: bool,
}

const fn f(name: &'static str, kind: Kind) -> Field {
    Field { name, kind, required: false }
}

const fn req(name: &'static str, kind: Kind) -> Field {
    Field { name, kind, required: true }
}

/// A table of the format: how to name it in a message, and its keys.
struct Table {
    fields: &'static [Field],
}

const PAIR: &str = "[\"2 mm\", \"1 mm\"]";

static PATCH: Table = Table {
    fields: &[
        req("shape", Kind::Str(&["square", "rectangle", "circle"])),
        req("centre", Kind::QtyArray("[\"0 mm\", \"5 mm\"]")),
        f("side", Kind::Qty("\"4 mm\"")),
        f("sides", Kind::QtyArray(PAIR)),
        f("radius", Kind::Qty("\"2 mm\"")),
        req("pressure", Kind::Qty("\"10 MPa\"")),
    ],
};

static PROFILE: Table = Table {
    fields: &[
        req("shape", Kind::Str(&["sphere", "ellipsoid", "cylinder", "punch", "wavy", "flat"])),
        f("radius", Kind::Qty("\"10 mm\"")),
        f("radii", Kind::QtyArray("[\"20 mm\", \"10 mm\"]")),
        f("edge_radius", Kind::Qty("\"1 mm\"")),
        f("wavelength", Kind::Qty("\"1 mm\"")),
        f("amplitude", Kind::Qty("\"1 um\"")),
        f("along", Kind::Str(&["x", "xy"])),
        f("length", Kind::Qty("\"10 mm\"")),
        f("crown", Kind::Qty("\"5 um\"")),
        f("end_radius", Kind::Qty("\"1 mm\"")),
    ],
};

static ROUGHNESS: Table = Table {
    fields: &[
        f("file", Kind::Str(&[])),
        f("unit", Kind::Str(&[])),
        f("hurst", Kind::Num),
        f("rms_height", Kind::Qty("\"1 um\"")),
        f("rms_slope", Kind::Num),
        f("k_low", Kind::Num),
        f("k_rolloff", Kind::Num),
        f("k_high", Kind::Num),
        f("seed", Kind::Int),
    ],
};

static GEOMETRY: Table = Table {
    fields: &[
        req(
            "kind",
            Kind::Str(&[
                "cylinder",
                "sphere",
                "ellipsoid",
                "punch",
                "patches",
                "surface",
                "wheel-rail",
            ]),
        ),
        f("boundary", Kind::Str(&["free", "periodic"])),
        f("size", Kind::QtyArray("[\"4 mm\", \"4 mm\"]")),
        f("cells", Kind::NumArray("[256, 256]")),
        f("profile", Kind::Table(&PROFILE)),
        f("roughness", Kind::Table(&ROUGHNESS)),
        f("radius", Kind::Qty("\"10 mm\"")),
        f("semi_axes", Kind::QtyArray(PAIR)),
        f("radii", Kind::QtyArray("[\"20 mm\", \"10 mm\"]")),
        f("half_width", Kind::Qty("\"5 mm\"")),
        f("patches", Kind::TableArray(&PATCH)),
        f("side", Kind::Str(&["left", "right"])),
        f("rail_profile", Kind::Str(&[])),
        f("wheel_profile", Kind::Str(&[])),
        f("profile_unit", Kind::Str(&[])),
        f("gauge", Kind::Qty("\"1435 mm\"")),
        f("gauge_height", Kind::Qty("\"14 mm\"")),
        f("rail_cant", Kind::Qty("\"25 mrad\"")),
        f("flange_back_distance", Kind::Qty("\"1360 mm\"")),
        f("flange_back_position", Kind::Qty("\"-70 mm\"")),
        f("wheel_radius", Kind::Qty("\"460 mm\"")),
    ],
};

static POSITION: Table = Table {
    fields: &[
        f("lateral", Kind::Qty("\"2 mm\"")),
        f("yaw", Kind::Qty("\"4.8 mrad\"")),
        f("roll", Kind::Qty("\"-0.1128 mrad\"")),
    ],
};

static SUBSTRATE: Table = Table {
    fields: &[
        req("model", Kind::Str(&["homogeneous", "graded", "viscoelastic"])),
        f("material", Kind::Str(&[])),
        f("e", Kind::Qty("\"210 GPa\"")),
        f("e0", Kind::Qty("\"1767600 kgf/m^2.1\"")),
        f("k", Kind::Num),
        f("nu", Kind::Num),
        f("alpha", Kind::Qty("\"2 s\"")),
        f("beta", Kind::Qty("\"1 s\"")),
    ],
};

static INDENTER: Table = Table {
    fields: &[
        req("model", Kind::Str(&["rigid", "homogeneous", "same"])),
        f("material", Kind::Str(&[])),
        f("e", Kind::Qty("\"210 GPa\"")),
        f("nu", Kind::Num),
    ],
};

static LOAD: Table = Table {
    fields: &[
        f("normal", Kind::QtyOrArray("\"100 N\" (N/m in 2D)", "[\"1 N\", \"100 N\", 20]")),
        f("half_width", Kind::Qty("\"5 mm\"")),
        f("approach", Kind::QtyOrArray("\"2 um\"", "[\"-20 nm\", \"100 nm\", 41]")),
        f("tangential", Kind::Qty("\"30 N\" (N/m in 2D)")),
        f("direction_deg", Kind::Num),
        f("friction", Kind::Num),
        f("sliding", Kind::Bool),
        f("moment", Kind::Qty("\"0.5 N m\"")),
        f("vertical", Kind::Str(&["normal", "total"])),
        f("history", Kind::Table(&HISTORY)),
    ],
};

static HISTORY: Table = Table {
    fields: &[
        f("tangential", Kind::QtyArray("[\"0 N\", \"20 N\", \"-20 N\", \"20 N\"]")),
        f("shift", Kind::QtyArray("[\"0 um\", \"2 um\", \"-2 um\"]")),
        f("normal", Kind::QtyArray("[\"100 N\", \"100 N\", \"80 N\", \"100 N\"]")),
        f("moment", Kind::QtyArray("[\"0 N m\", \"0.1 N m\", \"-0.1 N m\"]")),
        f("steps", Kind::Int),
        f("file", Kind::Str(&[])),
        f("columns", Kind::StrArray("[\"tangential\", \"normal\"]")),
        f("units", Kind::Table(&HISTORY_UNITS)),
    ],
};

static HISTORY_UNITS: Table = Table {
    fields: &[
        f("tangential", Kind::Str(&[])),
        f("shift", Kind::Str(&[])),
        f("normal", Kind::Str(&[])),
        f("moment", Kind::Str(&[])),
    ],
};

static MOTION: Table = Table {
    fields: &[
        req("kind", Kind::Str(&["static", "rolling"])),
        f("speed", Kind::Qty("\"10 cm/s\"")),
        f("creep", Kind::Num),
        f("creepage", Kind::Table(&CREEPAGE)),
        f("pitch_rate", Kind::Qty("\"-4.35 rad/s\"")),
        f("transient", Kind::Table(&TRANSIENT)),
    ],
};

static TRANSIENT: Table = Table {
    fields: &[f("start", Kind::Str(&["shift", "rest"])), f("distance", Kind::Qty("\"1.6 mm\""))],
};

static CREEPAGE: Table = Table {
    fields: &[
        f("longitudinal", Kind::Num),
        f("lateral", Kind::Num),
        f("spin", Kind::Qty("\"0.1 1/m\"")),
    ],
};

static FIELD: Table = Table {
    fields: &[
        req("x", Kind::NumArray("[-2.0, 2.0, 41]")),
        req("y", Kind::NumArray("[0.01, 3.0, 31]")),
        f("z", Kind::NumArray("[0.02, 2.0, 40]")),
        f("scale", Kind::Str(&["a", "m"])),
    ],
};

static CYCLE: Table = Table { fields: &[req("amplitude", Kind::Num), f("points", Kind::Int)] };

static OUTPUTS: Table = Table {
    fields: &[
        f("surface", Kind::Bool),
        f("field", Kind::Table(&FIELD)),
        f("cycle", Kind::Table(&CYCLE)),
        f("plots", Kind::Bool),
    ],
};

static SOLVER: Table = Table {
    fields: &[
        f(
            "method",
            Kind::Str(&["auto", "closed-form", "quadrature", "lp", "fast", "fastsim", "polach"]),
        ),
        f("grid", Kind::Int),
        f("tolerance", Kind::Num),
        f("cell", Kind::QtyArray("[\"0.2 mm\", \"0.2 mm\"]")),
    ],
};

/// `[interface]`.
static INTERFACE: Table = Table {
    fields: &[f("hardness", Kind::Qty("\"2 GPa\"")), f("adhesion", Kind::Table(&ADHESION))],
};

/// `interface.adhesion`.
static ADHESION: Table =
    Table { fields: &[f("work", Kind::Qty("\"50 mJ/m^2\"")), f("range", Kind::Qty("\"10 nm\""))] };

/// The whole file.
static TOP: Table = Table {
    fields: &[
        f("title", Kind::Str(&[])),
        req("geometry", Kind::Table(&GEOMETRY)),
        req("substrate", Kind::Table(&SUBSTRATE)),
        f("indenter", Kind::Table(&INDENTER)),
        f("position", Kind::Table(&POSITION)),
        req("load", Kind::Table(&LOAD)),
        f("motion", Kind::Table(&MOTION)),
        f("outputs", Kind::Table(&OUTPUTS)),
        f("solver", Kind::Table(&SOLVER)),
        f("interface", Kind::Table(&INTERFACE)),
    ],
};

/// Every table of the format with its dotted name, to say where a misplaced key belongs.
fn tables() -> [(&'static str, &'static Table); 15] {
    [
        ("geometry", &GEOMETRY),
        ("position", &POSITION),
        ("geometry.profile", &PROFILE),
        ("geometry.roughness", &ROUGHNESS),
        ("geometry.patches", &PATCH),
        ("substrate", &SUBSTRATE),
        ("indenter", &INDENTER),
        ("load", &LOAD),
        ("load.history", &HISTORY),
        ("motion", &MOTION),
        ("outputs", &OUTPUTS),
        ("outputs.field", &FIELD),
        ("outputs.cycle", &CYCLE),
        ("solver", &SOLVER),
        ("interface", &INTERFACE),
    ]
}

/// One thing wrong with the document.
struct Problem {
    kind: ErrorKind,
    key: String,
    span: Option<Range<usize>>,
    message: String,
    hint: String,
}

fn problem(key: &str, span: Range<usize>, message: String, hint: String) -> Problem {
    Problem { kind: ErrorKind::Schema, key: key.to_string(), span: Some(span), message, hint }
}

/// What a value is, in words ("the string \"0.3\"", "a table").
fn found(v: &DeValue<'_>) -> String {
    match v {
        DeValue::String(s) => {
            let mut t: String = s.chars().take(40).collect();
            if t.len() < s.len() {
                t.push_str("...");
            }
            format!("the string {t:?}")
        }
        DeValue::Integer(i) => format!("the number {i}"),
        DeValue::Float(x) => format!("the number {}", x.as_str()),
        DeValue::Boolean(b) => format!("the boolean {b}"),
        DeValue::Datetime(d) => format!("the date-time {d}"),
        DeValue::Array(a) => match a.len() {
            0 => "an empty array".to_string(),
            1 => "an array of 1 value".to_string(),
            n => format!("an array of {n} values"),
        },
        DeValue::Table(_) => "a table".to_string(),
    }
}

/// The key written in TOML, for hints (`nu = 0.3`).
fn leaf(key: &str) -> &str {
    key.rsplit('.').next().unwrap_or(key)
}

fn is_number(v: &DeValue<'_>) -> bool {
    matches!(v, DeValue::Integer(_) | DeValue::Float(_))
}

/// A number too large to be read (an integer beyond 64 bits, a float beyond f64), in words.
fn too_large(v: &DeValue<'_>) -> Option<String> {
    match v {
        DeValue::Integer(i) if i64::from_str_radix(i.as_str(), i.radix()).is_err() => {
            Some(format!("the number {i} is too large to be read"))
        }
        DeValue::Float(x) => {
            let s = x.as_str();
            let parsed: Option<f64> = s.parse().ok();
            match parsed {
                Some(p) if p.is_finite() || s.contains("inf") => None,
                _ => Some(format!("the number {s} is too large to be read")),
            }
        }
        _ => None,
    }
}

/// Check one value against its kind; push what is wrong.
fn check(v: &Spanned<DeValue<'_>>, kind: Kind, key: &str, out: &mut Vec<Problem>) {
    let span = v.span();
    let val = v.get_ref();
    let name = leaf(key);
    let wrong = |expected: &str, hint: String| {
        problem(key, span.clone(), format!("expected {expected}, found {}", found(val)), hint)
    };
    if let Some(m) = too_large(val) {
        let hint = if matches!(kind, Kind::Int) {
            format!("a whole number that fits in 64 bits, e.g. {name} = 64")
        } else {
            "write a number within about ±1.8e308, e.g. 1e20".to_string()
        };
        out.push(problem(key, span, m, hint));
        return;
    }
    let kind = match kind {
        Kind::QtyOrArray(_, sweep) if matches!(val, DeValue::Array(_)) => Kind::QtyArray(sweep),
        Kind::QtyOrArray(one, _) => Kind::Qty(one),
        k => k,
    };
    match kind {
        Kind::Str(choices) => {
            if !matches!(val, DeValue::String(_)) {
                let hint = if name == "material" {
                    "a name in quotes, e.g. material = \"steel\" (docs/materials.md)".to_string()
                } else if choices.is_empty() {
                    format!("write it in quotes, e.g. {name} = \"my scene\"")
                } else {
                    format!(
                        "one of: {} (in quotes, e.g. {name} = \"{}\")",
                        choices.join(", "),
                        choices[0]
                    )
                };
                out.push(wrong("a string", hint));
            }
        }
        Kind::Num => {
            if !is_number(val) {
                let hint = match val {
                    DeValue::String(s) if s.trim().parse::<f64>().is_ok() => {
                        format!("write the number without quotes: {name} = {}", s.trim())
                    }
                    DeValue::String(_) => {
                        format!("`{key}` is a plain number without a unit, e.g. {name} = 0.3")
                    }
                    _ => format!("a plain number, e.g. {name} = 0.3"),
                };
                out.push(wrong("a number", hint));
            }
        }
        Kind::Int => {
            if !matches!(val, DeValue::Integer(_)) {
                let hint = match val {
                    DeValue::Float(x) => format!(
                        "write it without a decimal point or exponent, e.g. {name} = {}",
                        x.as_str().parse::<f64>().map_or(64.0, |v| v.round().abs())
                    ),
                    DeValue::String(s) if s.trim().parse::<i64>().is_ok() => {
                        format!("write the number without quotes: {name} = {}", s.trim())
                    }
                    _ => format!("a whole number, e.g. {name} = 64"),
                };
                out.push(wrong("a whole number", hint));
            }
        }
        Kind::Bool => {
            if !matches!(val, DeValue::Boolean(_)) {
                let hint = match val {
                    DeValue::String(s) if matches!(s.trim(), "true" | "false") => {
                        format!("write it without quotes: {name} = {}", s.trim())
                    }
                    _ => format!("{name} = true or {name} = false"),
                };
                out.push(wrong("true or false", hint));
            }
        }
        Kind::Qty(example) => {
            if !(is_number(val) || matches!(val, DeValue::String(_))) {
                out.push(wrong(
                    &format!("a number or a quantity with a unit such as {example}"),
                    format!("a number in SI units, or a string with a unit: {name} = {example}"),
                ));
            }
        }
        Kind::QtyArray(example) => match val {
            DeValue::Array(a) => {
                for (i, e) in a.iter().enumerate() {
                    let ev = e.get_ref();
                    if let Some(m) = too_large(ev) {
                        out.push(problem(
                            key,
                            e.span(),
                            format!("value {}: {m}", i + 1),
                            "write a number within about ±1.8e308".into(),
                        ));
                    } else if !(is_number(ev) || matches!(ev, DeValue::String(_))) {
                        out.push(problem(
                            key,
                            e.span(),
                            format!(
                                "value {} of the array: expected a number or a quantity with a unit, found {}",
                                i + 1,
                                found(ev)
                            ),
                            format!("{name} = {example}"),
                        ));
                    }
                }
            }
            _ => out.push(wrong(
                &format!("an array of quantities such as {example}"),
                format!("{name} = {example}"),
            )),
        },
        Kind::NumArray(example) => match val {
            DeValue::Array(a) => {
                for (i, e) in a.iter().enumerate() {
                    let ev = e.get_ref();
                    if let Some(m) = too_large(ev) {
                        out.push(problem(
                            key,
                            e.span(),
                            format!("value {}: {m}", i + 1),
                            "write a number within about ±1.8e308".into(),
                        ));
                    } else if !is_number(ev) {
                        out.push(problem(
                            key,
                            e.span(),
                            format!(
                                "value {} of the array: expected a number, found {}",
                                i + 1,
                                found(ev)
                            ),
                            format!("[from, to, count] as plain numbers, e.g. {name} = {example}"),
                        ));
                    }
                }
            }
            _ => out.push(wrong(
                "an array [from, to, count] of numbers",
                format!("{name} = {example}"),
            )),
        },
        Kind::StrArray(example) => match val {
            DeValue::Array(a) => {
                for (i, e) in a.iter().enumerate() {
                    if !matches!(e.get_ref(), DeValue::String(_)) {
                        out.push(problem(
                            key,
                            e.span(),
                            format!(
                                "value {} of the array: expected a string, found {}",
                                i + 1,
                                found(e.get_ref())
                            ),
                            format!("{name} = {example}"),
                        ));
                    }
                }
            }
            _ => out.push(wrong(
                &format!("an array of strings such as {example}"),
                format!("{name} = {example}"),
            )),
        },
        // Resolved to Qty or QtyArray above.
        Kind::QtyOrArray(..) => {}
        Kind::Table(t) => match val {
            DeValue::Table(tab) => walk(tab, t, key, span, out),
            _ => out.push(wrong(
                "a table",
                format!("write it as a table: a line [{key}] followed by its keys, one per line"),
            )),
        },
        Kind::TableArray(t) => match val {
            DeValue::Array(a) => {
                for (i, e) in a.iter().enumerate() {
                    let k = format!("{key}[{i}]");
                    match e.get_ref() {
                        DeValue::Table(tab) => walk(tab, t, &k, e.span(), out),
                        other => out.push(problem(
                            &k,
                            e.span(),
                            format!("expected a table, found {}", found(other)),
                            format!("each entry is a table, e.g. {{ shape = \"square\", side = \"4 mm\", centre = [0.0, 0.0], pressure = \"10 MPa\" }}, or a [[{key}]] section"),
                        )),
                    }
                }
            }
            _ => out.push(wrong(
                "an array of tables",
                format!("one [[{key}]] section per entry, or {name} = [{{ ... }}, {{ ... }}]"),
            )),
        },
    }
}

/// Edit distance, for "did you mean".
fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}

/// Other names people give the format's keys.
const ALIASES: &[(&str, &str)] = &[
    ("poisson", "nu"),
    ("poisson_ratio", "nu"),
    ("poissons_ratio", "nu"),
    ("young", "e"),
    ("youngs_modulus", "e"),
    ("modulus", "e"),
    ("mu", "friction"),
    ("cof", "friction"),
    ("force", "normal"),
    ("type", "kind"),
    ("material", "model"),
    ("center", "centre"),
];

/// The allowed key closest to `k`, if it is close.
fn did_you_mean(k: &str, allowed: &[&'static str]) -> Option<&'static str> {
    let low = k.to_lowercase();
    if let Some(a) = ALIASES.iter().find(|(from, to)| *from == low && allowed.contains(to)) {
        return allowed.iter().copied().find(|x| *x == a.1);
    }
    allowed
        .iter()
        .map(|a| (distance(&low, a), *a))
        .filter(|(d, a)| *d <= (a.chars().count() / 3).max(1))
        .min()
        .map(|(_, a)| a)
}

/// Check a table of the document against the format.
fn walk(
    table: &DeTable<'_>,
    schema: &Table,
    prefix: &str,
    table_span: Range<usize>,
    out: &mut Vec<Problem>,
) {
    let names: Vec<&'static str> = schema.fields.iter().map(|f| f.name).collect();
    let place =
        if prefix.is_empty() { "at the top level".to_string() } else { format!("in [{prefix}]") };
    let dotted = |k: &str| if prefix.is_empty() { k.to_string() } else { format!("{prefix}.{k}") };
    for (k, v) in table {
        let kname: &str = k.get_ref();
        let key = dotted(kname);
        match schema.fields.iter().find(|f| f.name == kname) {
            Some(field) => check(v, field.kind, &key, out),
            None => {
                let what = if matches!(v.get_ref(), DeValue::Table(_)) && prefix.is_empty() {
                    format!("unknown table [{kname}]")
                } else {
                    format!("unknown key `{kname}` {place}")
                };
                let mut hint = String::new();
                if let Some(m) = did_you_mean(kname, &names) {
                    hint.push_str(&format!("did you mean `{m}`? "));
                } else if !prefix.is_empty() && TOP.fields.iter().any(|f| f.name == kname) {
                    hint.push_str(&format!(
                        "[{kname}] is a table of its own: write its keys under a line [{kname}], not inside [{prefix}]; "
                    ));
                } else {
                    let homes: Vec<String> = tables()
                        .iter()
                        .filter(|(_, t)| t.fields.iter().any(|f| f.name == kname))
                        .map(|(n, _)| format!("[{n}]"))
                        .collect();
                    if !homes.is_empty() {
                        hint.push_str(&format!("`{kname}` belongs in {}; ", homes.join(" or ")));
                    }
                }
                hint.push_str(&format!("allowed {place}: {}", names.join(", ")));
                out.push(problem(&key, k.span(), what, hint));
            }
        }
    }
    for field in schema.fields.iter().filter(|f| f.required) {
        if !table.keys().any(|k| k.get_ref() == field.name) {
            let key = dotted(field.name);
            let p = if prefix.is_empty() {
                Problem {
                    kind: ErrorKind::Schema,
                    key: key.clone(),
                    span: None,
                    message: format!("the table [{key}] is missing"),
                    hint: "every scene has [geometry], [substrate] and [load] tables; see docs/SCENES.md"
                        .to_string(),
                }
            } else {
                let hint = match field.kind {
                    Kind::Str(c) if !c.is_empty() => {
                        format!("add {} = \"{}\" (one of: {})", field.name, c[0], c.join(", "))
                    }
                    Kind::Num => format!("add {} = a number", field.name),
                    Kind::Qty(e) | Kind::QtyOrArray(e, _) => format!("add {} = {e}", field.name),
                    Kind::QtyArray(e) | Kind::NumArray(e) | Kind::StrArray(e) => {
                        format!("add {} = {e}", field.name)
                    }
                    _ => format!("add `{}`; see docs/SCENES.md", field.name),
                };
                problem(
                    &key,
                    table_span.clone(),
                    format!("missing key `{}` in [{prefix}]", field.name),
                    hint,
                )
            };
            out.push(p);
        }
    }
}

/// The dotted key whose value (or key) holds byte `at`, the deepest one.
fn key_at(table: &DeTable<'_>, prefix: &str, at: usize) -> Option<String> {
    for (k, v) in table {
        let key = if prefix.is_empty() {
            k.get_ref().to_string()
        } else {
            format!("{prefix}.{}", k.get_ref())
        };
        if k.span().contains(&at) {
            return Some(key);
        }
        if v.span().contains(&at) || v.span().end == at {
            return Some(value_key(v, &key, at).unwrap_or(key));
        }
    }
    None
}

fn value_key(v: &Spanned<DeValue<'_>>, key: &str, at: usize) -> Option<String> {
    match v.get_ref() {
        DeValue::Table(t) => key_at(t, key, at),
        DeValue::Array(a) => {
            a.iter().enumerate().find(|(_, e)| e.span().contains(&at)).map(|(i, e)| {
                let k = format!("{key}[{i}]");
                value_key(e, &k, at).unwrap_or(k)
            })
        }
        _ => None,
    }
}

/// Words that name Rust or serde internals; a message holding one is not shown as is.
const INTERNAL: &[&str] = &[
    "Qty", "Raw", "untagged", "struct", "f64", "i64", "u64", "enum", "variant", "Spanned", "serde",
];

/// A message for a file serde refused (`e`, with its span) or that is not TOML.
pub(super) fn explain(src: &str, e: &toml::de::Error) -> SceneError {
    let doc = match DeTable::parse(src) {
        Ok(d) => d,
        Err(syntax) => return syntax_error(src, &syntax),
    };
    let mut problems = Vec::new();
    walk(doc.get_ref(), &TOP, "", doc.span(), &mut problems);
    let at = e.span().map(|s| s.start);
    // Prefer the problem serde met; otherwise the first in the file.
    problems.sort_by_key(|p| p.span.as_ref().map_or(0, |s| s.start));
    let pick = at
        .and_then(|a| problems.iter().position(|p| p.span.as_ref().is_some_and(|s| s.contains(&a))))
        .unwrap_or(0);
    if problems.len() > pick {
        let p = problems.swap_remove(pick);
        let span = p.span.unwrap_or(0..0);
        return SceneError::new(p.kind, p.message).key(p.key).at(src, Some(span)).hint(p.hint);
    }
    // Not explained by the walk: locate the key, keep serde's words only if they are plain.
    let msg = e.message().trim();
    let key = at.and_then(|a| key_at(doc.get_ref(), "", a));
    let message = if INTERNAL.iter().any(|w| msg.contains(w)) {
        "this value does not have the form this key takes".to_string()
    } else {
        msg.to_string()
    };
    let mut err = SceneError::new(ErrorKind::Schema, message)
        .at(src, Some(e.span().unwrap_or(0..0)))
        .hint("see docs/SCENES.md for the keys each table takes and their types; units go in strings, e.g. \"10 mm\"");
    if let Some(k) = key {
        err = err.key(k);
    }
    err
}

/// A TOML syntax error: toml's message, the position, and the key of the line when the
/// line is `key = ...` (under the last `[table]` header before it).
fn syntax_error(src: &str, e: &toml::de::Error) -> SceneError {
    let span = e.span().unwrap_or(0..0);
    let mut err = SceneError::new(ErrorKind::Syntax, e.message().trim().to_string())
        .at(src, Some(span.clone()))
        .hint("the file must be valid TOML (https://toml.io): key = value lines under [table] headers, strings in quotes");
    let at = span.start.min(src.len());
    let line_start = src[..at].rfind('\n').map_or(0, |i| i + 1);
    let line = src[line_start..].lines().next().unwrap_or("").trim();
    let header = |l: &str| -> Option<String> {
        let l = l.trim();
        let inner = l
            .strip_prefix("[[")
            .and_then(|r| r.split("]]").next())
            .or_else(|| l.strip_prefix('[').and_then(|r| r.split(']').next()))?;
        let inner = inner.trim();
        (!inner.is_empty()).then(|| inner.to_string())
    };
    let bare = |s: &str| {
        !s.is_empty()
            && s.chars().all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.'))
    };
    if let Some(h) = header(line).filter(|h| bare(h)) {
        return err.key(h);
    }
    if let Some((k, v)) = line.split_once('=') {
        let k = k.trim();
        if v.trim().is_empty() || v.trim().starts_with('#') {
            err.message = format!("the value of `{k}` is missing after `=`");
        }
        if bare(k) {
            let table = src[..line_start].lines().rev().find_map(|l| {
                let t = l.trim();
                if t.starts_with('[') {
                    header(t)
                } else {
                    None
                }
            });
            err = err.key(match table.filter(|t| bare(t)) {
                Some(t) => format!("{t}.{k}"),
                None => k.to_string(),
            });
        }
    }
    err
}

/// Every key of the format, dotted (keys of an array of tables as `geometry.patches.shape`),
/// with the values a string key allows (empty when any string goes) or None for keys that
/// are not strings: for the JSON Schema (`crate::json_schema`), which takes its enums from
/// here so the two descriptions of the format cannot drift apart.
pub(crate) fn keys() -> Vec<(String, Option<&'static [&'static str]>)> {
    fn walk(t: &Table, prefix: &str, out: &mut Vec<(String, Option<&'static [&'static str]>)>) {
        for f in t.fields {
            let key =
                if prefix.is_empty() { f.name.to_string() } else { format!("{prefix}.{}", f.name) };
            match f.kind {
                Kind::Str(c) => out.push((key, Some(c))),
                Kind::Table(sub) | Kind::TableArray(sub) => {
                    out.push((key.clone(), None));
                    walk(sub, &key, out);
                }
                _ => out.push((key, None)),
            }
        }
    }
    let mut out = Vec::new();
    walk(&TOP, "", &mut out);
    out
}
