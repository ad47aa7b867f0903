//! Scene parsing: the default scene, unit handling, and the bad-input suite (each malformed or
//! impossible scene must be refused with the right kind, a position where one exists, the key,
//! and a hint).

use stickslip_scene::{ErrorKind, Geometry, NormalLoad, Scene, Substrate, DEFAULT_SCENE};

const GOOD: &str = r#"
title = "ok"
[geometry]
kind = "sphere"
radius = "1 in"
[substrate]
model = "homogeneous"
e = "30e6 psi"
nu = 0.3
[indenter]
model = "same"
[load]
normal = "2160 lbf"
tangential = "144 lbf"
friction = 0.1
"#;

#[test]
fn default_scene_is_the_seed_000_roller() {
    let s = Scene::default_scene();
    assert!(matches!(s.geometry, Geometry::Cylinder { radius } if radius == 0.3));
    match s.substrate {
        Substrate::Graded { e0, k, nu } => {
            assert_eq!((k, nu), (0.1, 0.3));
            assert!((e0 / (1767600.0 * 9.80665) - 1.0).abs() < 1e-15);
        }
        other => panic!("default substrate is {other:?}"),
    }
    assert_eq!(s.load.normal, NormalLoad::HalfWidth(0.0178));
    assert!(DEFAULT_SCENE.contains("kgf/m^2.1"));
}

#[test]
fn good_scene_in_inch_pound_units() {
    let s = Scene::from_toml_str(GOOD, None).unwrap();
    assert!(matches!(s.geometry, Geometry::Sphere { radius } if radius == 0.0254));
    assert_eq!(s.load.normal, NormalLoad::Force(2160.0 * 4.4482216152605));
    assert!((s.load.tangential - 144.0 * 4.4482216152605).abs() < 1e-9);
}

/// Replace `from` by `to` in GOOD (which must contain it) and parse.
fn mutate(from: &str, to: &str) -> stickslip_scene::SceneError {
    assert!(GOOD.contains(from), "test bug: {from:?} not in GOOD");
    Scene::from_toml_str(&GOOD.replacen(from, to, 1), Some("bad.toml".into())).unwrap_err()
}

fn graded(nu: &str, k: &str) -> String {
    format!(
        "[geometry]\nkind = \"cylinder\"\nradius = 0.3\n[substrate]\nmodel = \"graded\"\ne0 = \"1767600 kgf/m^2.1\"\nk = {k}\nnu = {nu}\n[load]\nhalf_width = 0.0178\n"
    )
}

fn visco(alpha: &str, beta: &str) -> String {
    format!(
        "[geometry]\nkind = \"cylinder\"\nradius = 0.3\n[substrate]\nmodel = \"viscoelastic\"\ne = 1e7\nnu = 0.45\nalpha = {alpha}\nbeta = {beta}\n[load]\nnormal = 1000.0\n"
    )
}

fn patches(p: &str) -> String {
    format!(
        "[geometry]\nkind = \"patches\"\npatches = [\n{p}\n]\n[substrate]\nmodel = \"homogeneous\"\ne = \"30e6 psi\"\nnu = 0.3\n[load]\ntangential = \"800 lbf\"\nfriction = 0.12\n"
    )
}

struct Case {
    name: &'static str,
    err: stickslip_scene::SceneError,
    kind: ErrorKind,
    key: Option<&'static str>,
    line: Option<usize>,
}

fn cases() -> Vec<Case> {
    let p = |s: &str| Scene::from_toml_str(s, Some("bad.toml".into())).unwrap_err();
    vec![
        Case { name: "syntax: unclosed string", err: mutate("\"sphere\"", "\"sphere"), kind: ErrorKind::Syntax, key: None, line: Some(4) },
        Case { name: "syntax: missing value", err: mutate("nu = 0.3", "nu = "), kind: ErrorKind::Syntax, key: None, line: Some(9) },
        Case { name: "unknown key", err: mutate("nu = 0.3", "nu = 0.3\npoisson = 0.3"), kind: ErrorKind::Schema, key: None, line: Some(10) },
        Case { name: "unknown table", err: mutate("[indenter]", "[indentor]"), kind: ErrorKind::Schema, key: None, line: None },
        Case { name: "wrong type", err: mutate("nu = 0.3", "nu = \"0.3\""), kind: ErrorKind::Schema, key: None, line: Some(9) },
        Case { name: "unknown geometry kind", err: mutate("\"sphere\"", "\"torus\""), kind: ErrorKind::Schema, key: Some("geometry.kind"), line: Some(4) },
        Case { name: "unknown unit", err: mutate("\"1 in\"", "\"1 furlong\""), kind: ErrorKind::Unit, key: Some("geometry.radius"), line: Some(5) },
        Case { name: "wrong dimension", err: mutate("\"1 in\"", "\"1 psi\""), kind: ErrorKind::Unit, key: Some("geometry.radius"), line: Some(5) },
        Case { name: "2D load unit on 3D scene", err: mutate("\"2160 lbf\"", "\"2160 N/m\""), kind: ErrorKind::Unit, key: Some("load.normal"), line: Some(13) },
        Case { name: "negative radius", err: mutate("\"1 in\"", "-0.02"), kind: ErrorKind::OutOfRange, key: Some("geometry.radius"), line: Some(5) },
        Case { name: "zero modulus", err: mutate("\"30e6 psi\"", "0.0"), kind: ErrorKind::OutOfRange, key: Some("substrate.e"), line: Some(8) },
        Case { name: "nu > 0.5", err: mutate("nu = 0.3", "nu = 0.51"), kind: ErrorKind::OutOfRange, key: Some("substrate.nu"), line: Some(9) },
        Case { name: "nu <= -1", err: mutate("nu = 0.3", "nu = -1.0"), kind: ErrorKind::OutOfRange, key: Some("substrate.nu"), line: Some(9) },
        Case { name: "graded beta not real", err: p(&graded("0.95", "0.1")), kind: ErrorKind::OutOfRange, key: Some("substrate.nu"), line: Some(8) },
        Case { name: "k = 1", err: p(&graded("0.3", "1.0")), kind: ErrorKind::OutOfRange, key: Some("substrate.k"), line: Some(7) },
        Case { name: "k < 0", err: p(&graded("0.3", "-0.1")), kind: ErrorKind::OutOfRange, key: Some("substrate.k"), line: Some(7) },
        Case { name: "graded modulus unit does not match k", err: p(&graded("0.3", "0.2")), kind: ErrorKind::Unit, key: Some("substrate.e0"), line: Some(6) },
        Case { name: "alpha < beta", err: p(&visco("0.1", "1.0")), kind: ErrorKind::OutOfRange, key: Some("substrate.alpha"), line: Some(8) },
        Case { name: "T > fP with partial slip", err: mutate("\"144 lbf\"", "\"300 lbf\""), kind: ErrorKind::Impossible, key: Some("load.tangential"), line: Some(14) },
        Case { name: "T on a frictionless contact", err: mutate("friction = 0.1", "friction = 0.0"), kind: ErrorKind::Impossible, key: Some("load.tangential"), line: Some(14) },
        Case { name: "negative friction", err: mutate("friction = 0.1", "friction = -0.1"), kind: ErrorKind::OutOfRange, key: Some("load.friction"), line: Some(15) },
        Case { name: "both normal and half_width", err: mutate("normal = \"2160 lbf\"", "normal = \"2160 lbf\"\nhalf_width = 0.001"), kind: ErrorKind::Schema, key: Some("load"), line: None },
        Case { name: "empty patch list", err: p(&patches("")), kind: ErrorKind::OutOfRange, key: Some("geometry.patches"), line: Some(3) },
        Case { name: "patch without pressure", err: p(&patches("{ shape = \"square\", centre = [0.0, 0.0], side = \"0.6 in\", pressure = 0.0 }")), kind: ErrorKind::OutOfRange, key: Some("geometry.patches[0].pressure"), line: Some(4) },
        Case { name: "overlapping patches", err: p(&patches("{ shape = \"square\", centre = [0.0, 0.0], side = \"0.6 in\", pressure = \"1e4 psi\" },\n{ shape = \"square\", centre = [\"0.5 in\", 0.0], side = \"0.6 in\", pressure = \"1e4 psi\" }")), kind: ErrorKind::Impossible, key: Some("geometry.patches[1]"), line: Some(5) },
        Case { name: "grid too large for memory", err: mutate("friction = 0.1", "friction = 0.1\n[solver]\ngrid = 100000"), kind: ErrorKind::OutOfRange, key: Some("solver.grid"), line: Some(17) },
        Case { name: "moment on a 2D contact", err: p(&graded("0.3", "0.1").replace("half_width = 0.0178", "half_width = 0.0178\nmoment = 1.0")), kind: ErrorKind::Impossible, key: Some("load.moment"), line: Some(11) },
        Case { name: "field above the surface", err: mutate("friction = 0.1", "friction = 0.1\n[outputs]\nfield = { x = [-1.5, 1.5, 61], y = [0, 0, 1], z = [-0.1, 2.0, 40] }"), kind: ErrorKind::OutOfRange, key: Some("outputs.field.z"), line: Some(17) },
        Case { name: "3D field without the depth axis", err: mutate("friction = 0.1", "friction = 0.1\n[outputs]\nfield = { x = [-1.5, 1.5, 61], y = [0.1, 2.0, 40] }"), kind: ErrorKind::Schema, key: Some("outputs.field"), line: Some(17) },
        Case { name: "cycle amplitude above gross slip", err: mutate("friction = 0.1", "friction = 0.1\n[outputs]\ncycle = { amplitude = 1.5 }"), kind: ErrorKind::OutOfRange, key: Some("outputs.cycle.amplitude"), line: Some(17) },
        Case { name: "rolling without speed", err: p(&visco("2.0", "1.0").replace("normal = 1000.0", "normal = 1000.0\n[motion]\nkind = \"rolling\"")), kind: ErrorKind::Schema, key: Some("motion.speed"), line: None },
        Case { name: "missing substrate", err: p("[geometry]\nkind = \"sphere\"\nradius = 0.01\n[load]\nnormal = 1.0\n"), kind: ErrorKind::Schema, key: None, line: None },
        Case { name: "ellipsoid with both radii and semi-axes", err: mutate("kind = \"sphere\"\nradius = \"1 in\"", "kind = \"ellipsoid\"\nradii = [1.0, 2.0]\nsemi_axes = [0.1, 0.2]"), kind: ErrorKind::Schema, key: Some("geometry"), line: None },
    ]
}

#[test]
fn bad_scenes_are_refused_with_location_key_and_hint() {
    let cases = cases();
    assert!(cases.len() >= 25, "the suite must hold at least 25 bad scenes");
    let mut failures = Vec::new();
    for c in &cases {
        let e = &c.err;
        let msg = e.to_string();
        println!("{:<40} {msg}", c.name);
        if e.kind != c.kind {
            failures.push(format!("{}: kind {:?}, expected {:?}", c.name, e.kind, c.kind));
        }
        if let Some(k) = c.key {
            if e.key.as_deref() != Some(k) {
                failures.push(format!("{}: key {:?}, expected {k}", c.name, e.key));
            }
        }
        if let Some(l) = c.line {
            if e.position.map(|p| p.0) != Some(l) {
                failures.push(format!("{}: position {:?}, expected line {l}", c.name, e.position));
            }
        }
        if !msg.starts_with("bad.toml") {
            failures.push(format!("{}: message does not name the file: {msg}", c.name));
        }
        if e.hint.is_none() {
            failures.push(format!("{}: no hint", c.name));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn missing_file_is_an_io_error_naming_the_path() {
    let e = Scene::from_file(std::path::Path::new("/nonexistent/scene.toml")).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Io);
    assert!(e.to_string().contains("/nonexistent/scene.toml"), "{e}");
}

#[test]
fn alpha_equal_beta_is_accepted_as_elastic() {
    let s = Scene::from_toml_str(&visco("1.0", "1.0"), None).unwrap();
    assert!(matches!(s.substrate, Substrate::Viscoelastic { alpha, beta, .. } if alpha == beta));
}
