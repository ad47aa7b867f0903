//! Refusals of the TOML front end in plain words: a table of damaged scenes (wrong types for
//! every kind of value, missing tables and keys, unknown keys and tables, arrays of the
//! wrong shape, broken syntax), each refused with the dotted key, line:column, a hint, and
//! no serde or Rust type name; and the exit-code mapping of every error kind.

// SceneError carries file, position, key and hint; tests return it as is.
#![allow(clippy::result_large_err)]

use stickslip_scene::{ErrorKind, Scene, SceneError};

/// A valid scene with one of every kind of value (strings, numbers, whole numbers,
/// booleans, quantities, arrays of quantities and of numbers, tables, inline tables).
const GOOD: &str = r#"title = "all kinds of values"
[geometry]
kind = "cylinder"
radius = "10 mm"
[substrate]
model = "homogeneous"
e = "210 GPa"
nu = 0.3
[indenter]
model = "same"
[load]
normal = "100 N/mm"
tangential = "10 N/mm"
friction = 0.3
sliding = false
[outputs]
surface = true
field = { x = [-2.0, 2.0, 41], y = [0.05, 2.0, 20], scale = "a" }
plots = false
[solver]
grid = 16
tolerance = 1e-8
"#;

const PATCHES: &str = r#"[geometry]
kind = "patches"
patches = [ { shape = "square", centre = [0.0, 0.0], side = "1 in", pressure = "10000 psi" } ]
[substrate]
model = "homogeneous"
e = "30e6 psi"
nu = 0.3
[load]
tangential = "800 lbf"
friction = 0.12
"#;

/// Words that name Rust or serde internals.
pub const INTERNAL: &[&str] =
    &["Qty", "Raw", "untagged", "struct", "f64", "i64", "enum", "variant", "Spanned", "serde"];

fn parse(src: &str) -> Result<Scene, SceneError> {
    Scene::from_toml_str(src, Some("bad.toml".into()))
}

fn sub(from: &str, to: &str) -> String {
    assert!(GOOD.contains(from), "test bug: {from:?} not in GOOD");
    GOOD.replacen(from, to, 1)
}

#[test]
fn the_base_scenes_are_valid() {
    parse(GOOD).unwrap();
    parse(PATCHES).unwrap();
}

/// (name, scene text, expected key, expected line, words the message must contain)
fn cases() -> Vec<(&'static str, String, &'static str, usize, &'static str)> {
    vec![
        ("number as string", sub("nu = 0.3", "nu = \"0.3\""), "substrate.nu", 8, "expected a number, found the string \"0.3\""),
        ("number as boolean", sub("friction = 0.3", "friction = true"), "load.friction", 14, "expected a number, found the boolean true"),
        ("number as array", sub("nu = 0.3", "nu = [0.3]"), "substrate.nu", 8, "found an array"),
        ("number as table", sub("friction = 0.3", "friction = { value = 0.3 }"), "load.friction", 14, "found a table"),
        ("number as date", sub("nu = 0.3", "nu = 1979-05-27"), "substrate.nu", 8, "date-time"),
        ("quantity as boolean", sub("radius = \"10 mm\"", "radius = true"), "geometry.radius", 4, "a number or a quantity with a unit"),
        ("quantity as array", sub("radius = \"10 mm\"", "radius = [\"10 mm\", 2]"), "geometry.radius", 4, "found an array of 2 values"),
        ("load sweep of two values", sub("normal = \"100 N/mm\"", "normal = [100, 2]"), "load.normal", 12, "a load sweep is `[from, to, steps]`"),
        ("quantity as table", sub("e = \"210 GPa\"", "e = { value = 210, unit = \"GPa\" }"), "substrate.e", 7, "found a table"),
        ("string as number", sub("kind = \"cylinder\"", "kind = 3"), "geometry.kind", 3, "expected a string, found the number 3"),
        ("string as boolean", sub("model = \"same\"", "model = false"), "indenter.model", 10, "expected a string"),
        ("title as number", sub("title = \"all kinds of values\"", "title = 7"), "title", 1, "expected a string"),
        ("whole number as float", sub("grid = 16", "grid = 16.5"), "solver.grid", 21, "expected a whole number, found the number 16.5"),
        ("whole number as string", sub("grid = 16", "grid = \"16\""), "solver.grid", 21, "expected a whole number"),
        ("whole number too large", sub("grid = 16", "grid = 123456789012345678901234567890"), "solver.grid", 21, "too large"),
        ("boolean as string", sub("sliding = false", "sliding = \"false\""), "load.sliding", 15, "expected true or false"),
        ("boolean as number", sub("plots = false", "plots = 0"), "outputs.plots", 19, "expected true or false"),
        ("table as value", format!("motion = \"rolling\"\n{GOOD}"), "motion", 1, "expected a table"),
        ("top-level table as key", sub("[indenter]\nmodel = \"same\"", "indenter = \"same\""), "substrate.indenter", 9, "unknown key `indenter` in [substrate]"),
        ("missing table", GOOD.replacen("[substrate]\nmodel = \"homogeneous\"\ne = \"210 GPa\"\nnu = 0.3\n", "", 1), "substrate", 1, "[substrate] is missing"),
        ("missing key", sub("nu = 0.3\n", ""), "substrate.nu", 5, "missing key `nu`"),
        ("missing kind", sub("kind = \"cylinder\"\n", ""), "geometry.kind", 2, "missing key `kind`"),
        ("unknown key, far", sub("nu = 0.3", "nu = 0.3\nporosity = 0.3"), "substrate.porosity", 9, "unknown key `porosity` in [substrate]"),
        ("unknown key, near miss", sub("friction = 0.3", "frictoin = 0.3"), "load.frictoin", 14, "unknown key `frictoin` in [load]"),
        ("unknown key, other name", sub("nu = 0.3", "poisson = 0.3"), "substrate.poisson", 8, "unknown key `poisson`"),
        ("unknown table", sub("[indenter]", "[indentor]"), "indentor", 9, "unknown table [indentor]"),
        ("unknown nested table", sub("[solver]", "[solver.extra]\nx = 1\n[solver]"), "solver.extra", 20, "unknown key `extra` in [solver]"),
        ("field axis of strings", sub("x = [-2.0, 2.0, 41]", "x = [\"-2\", 2.0, 41]"), "outputs.field.x", 18, "expected a number, found the string"),
        ("field axis not an array", sub("x = [-2.0, 2.0, 41]", "x = 41"), "outputs.field.x", 18, "an array [from, to, count]"),
        ("field as string", sub("field = { x = [-2.0, 2.0, 41], y = [0.05, 2.0, 20], scale = \"a\" }", "field = \"yes\""), "outputs.field", 18, "expected a table"),
        ("field missing y", sub(", y = [0.05, 2.0, 20]", ""), "outputs.field.y", 18, "missing key `y`"),
        ("patches not an array", PATCHES.replacen("patches = [ { shape = \"square\", centre = [0.0, 0.0], side = \"1 in\", pressure = \"10000 psi\" } ]", "patches = 3", 1), "geometry.patches", 3, "expected an array of tables"),
        ("patch not a table", PATCHES.replacen("[ { shape", "[ 1, { shape", 1), "geometry.patches[0]", 3, "expected a table, found the number 1"),
        ("patch centre of booleans", PATCHES.replacen("centre = [0.0, 0.0]", "centre = [true, 0.0]", 1), "geometry.patches[0].centre", 3, "value 1 of the array"),
        ("patch unknown key", PATCHES.replacen("side = \"1 in\"", "size = \"1 in\"", 1), "geometry.patches[0].size", 3, "unknown key `size`"),
        ("patch missing pressure", PATCHES.replacen(", pressure = \"10000 psi\"", "", 1), "geometry.patches[0].pressure", 3, "missing key `pressure`"),
        ("graded key without model", sub("model = \"homogeneous\"\n", "").replacen("nu = 0.3", "nu = 0.3\nk = 0.5", 1), "substrate.model", 8, "`k` belongs to a graded substrate"),
        ("viscoelastic key without model", sub("model = \"homogeneous\"\n", "").replacen("nu = 0.3", "nu = 0.3\nalpha = \"2 s\"", 1), "substrate.model", 8, "`alpha` belongs to a viscoelastic substrate"),
        ("graded key, homogeneous", sub("nu = 0.3", "nu = 0.3\ne0 = 1e9"), "substrate.e0", 9, "`e0` is not a key of a homogeneous substrate"),
        ("viscoelastic key, graded", sub("model = \"homogeneous\"\ne = \"210 GPa\"", "model = \"graded\"\ne0 = 1e9\nk = 0.5\nbeta = 1"), "substrate.beta", 9, "`beta` is not a key of a graded substrate"),
        ("modulus of a same indenter", sub("model = \"same\"", "model = \"same\"\ne = \"1 GPa\""), "indenter.e", 11, "a same indenter takes no `e`"),
        ("speed of a static contact", format!("{GOOD}[motion]\nkind = \"static\"\nspeed = \"1 m/s\"\n"), "motion.speed", 25, "a static contact takes no `speed`"),
        ("syntax: unquoted string", sub("model = \"homogeneous\"", "model = homogeneous"), "substrate.model", 6, ""),
        ("syntax: missing value", sub("nu = 0.3", "nu = "), "substrate.nu", 8, ""),
        ("syntax: duplicate key", sub("nu = 0.3", "nu = 0.3\nnu = 0.2"), "substrate.nu", 9, ""),
        ("syntax: unclosed header", sub("[load]", "[load"), "load", 11, ""),
    ]
}

/// Keys with one sensible value may be left out: `substrate.model` is homogeneous when the
/// body is given by a material or e and nu, `indenter.model` homogeneous when it has elastic
/// constants and rigid otherwise, `motion.kind` rolling when a speed is given.
#[test]
fn obvious_defaults_read_as_written_out() {
    let explicit = parse(GOOD).unwrap();
    let short = parse(&sub("model = \"homogeneous\"\n", "")).unwrap();
    assert_eq!(short.substrate, explicit.substrate);
    let named = |sub_keys: &str, ind_keys: &str| {
        format!(
            "[geometry]\nkind = \"sphere\"\nradius = \"5 mm\"\n[substrate]\n{sub_keys}\n[indenter]\n{ind_keys}\n[load]\nnormal = \"10 N\"\n"
        )
    };
    let a = parse(&named("material = \"steel\"", "material = \"steel\"")).unwrap();
    let b = parse(&named(
        "model = \"homogeneous\"\nmaterial = \"steel\"",
        "model = \"homogeneous\"\nmaterial = \"steel\"",
    ))
    .unwrap();
    assert_eq!(a.substrate, b.substrate);
    assert_eq!(a.indenter, b.indenter);
    assert!(matches!(a.indenter, stickslip_scene::Indenter::Homogeneous(_)));
    let c = parse(&named("e = \"70 GPa\"\nnu = 0.33", "e = \"210 GPa\"\nnu = 0.3")).unwrap();
    assert!(matches!(c.substrate, stickslip_scene::Substrate::Homogeneous(_)));
    assert!(matches!(c.indenter, stickslip_scene::Indenter::Homogeneous(_)));
    let empty = parse(&named("material = \"steel\"", "")).unwrap();
    assert_eq!(empty.indenter, stickslip_scene::Indenter::Rigid);
    let rolling = "[geometry]\nkind = \"cylinder\"\nradius = \"0.46 m\"\n[substrate]\nmaterial = \"steel\"\n[indenter]\nmodel = \"same\"\n[load]\nnormal = \"500 kN/m\"\nfriction = 0.3\n[motion]\nspeed = \"20 m/s\"\ncreep = 0.0005\n";
    let r = parse(rolling).unwrap();
    let r2 = parse(&rolling.replace("[motion]\n", "[motion]\nkind = \"rolling\"\n")).unwrap();
    assert_eq!(r.motion, r2.motion);
    assert!(matches!(r.motion, stickslip_scene::Motion::Rolling { .. }), "{:?}", r.motion);
}

#[test]
fn damaged_scenes_name_the_key_the_position_and_a_hint_in_plain_words() {
    let cases = cases();
    assert!(cases.len() >= 20);
    let mut failures = Vec::new();
    for (name, src, key, line, words) in &cases {
        let e = match parse(src) {
            Ok(_) => {
                failures.push(format!("{name}: accepted"));
                continue;
            }
            Err(e) => e,
        };
        let msg = e.to_string();
        println!("{name:<28} {msg}");
        if e.key.as_deref() != Some(*key) {
            failures.push(format!("{name}: key {:?}, expected {key}", e.key));
        }
        if e.position.map(|p| p.0) != Some(*line) {
            failures.push(format!("{name}: position {:?}, expected line {line}", e.position));
        }
        if !msg.contains(words) {
            failures.push(format!("{name}: message lacks {words:?}: {msg}"));
        }
        if e.hint.as_deref().is_none_or(str::is_empty) {
            failures.push(format!("{name}: no hint"));
        }
        if !msg.starts_with(&format!("bad.toml:{line}:")) {
            failures.push(format!("{name}: no file:line:column: {msg}"));
        }
        for w in INTERNAL {
            if msg.contains(w) {
                failures.push(format!("{name}: internal word {w:?}: {msg}"));
            }
        }
        if e.exit_code() != 2 {
            failures.push(format!("{name}: exit code {}", e.exit_code()));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn near_misses_get_a_did_you_mean() {
    for (from, to, want) in [
        ("friction = 0.3", "frictoin = 0.3", "did you mean `friction`?"),
        ("nu = 0.3", "poisson = 0.3", "did you mean `nu`?"),
        ("[indenter]", "[indentor]", "did you mean `indenter`?"),
        ("[load]", "[load]\nnu = 0.1", "`nu` belongs in [substrate] or [indenter]"),
    ] {
        let e = parse(&sub(from, to)).unwrap_err();
        assert!(e.to_string().contains(want), "{to}: {e}");
    }
}

#[test]
fn exit_codes_of_every_kind() {
    use ErrorKind::*;
    for (kind, code) in [
        (Io, 1),
        (Syntax, 2),
        (Schema, 2),
        (Unit, 2),
        (OutOfRange, 2),
        (Impossible, 2),
        (Unsupported, 2),
        (Solver, 3),
        (Audit, 3),
    ] {
        assert_eq!(kind.exit_code(), code, "{kind:?}");
    }
    // Through SceneError, from real refusals.
    assert_eq!(parse("nu = ").unwrap_err().exit_code(), 2);
    assert_eq!(
        parse(&sub("radius = \"10 mm\"", "radius = \"10 psi\"")).unwrap_err().exit_code(),
        2
    );
    let io = Scene::from_file(std::path::Path::new("/nonexistent/scene.toml")).unwrap_err();
    assert_eq!(io.exit_code(), 1);
}
