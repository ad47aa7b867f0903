//! Bad input beyond parsing: combinations the planner refuses, checks that need the contact
//! solved (T > fP when the load is given as a half-width, Lubkin's gross-slip moment), the
//! LP or fast-solver grid too large for memory. Each error names the file, line and column,
//! the key, and what is allowed. (Output directories that cannot be written:
//! `stickslip-report`'s `tests/unwritable.rs`.)

mod common;

use common::SEED002_SPHERE as SPHERE;
use stickslip_run::read_scene;
use stickslip_scene::{ErrorKind, SceneError};

const ROLLER: &str = r#"[geometry]
kind = "cylinder"
radius = 0.3
[substrate]
model = "graded"
e0 = "1767600 kgf/m^2.1"
k = 0.1
nu = 0.3
[load]
half_width = 0.0178
friction = 0.5
"#;

fn parse(s: &str) -> SceneError {
    read_scene(s, Some("bad.toml".into())).unwrap_err()
}

struct Case {
    name: &'static str,
    err: SceneError,
    kind: ErrorKind,
    key: &'static str,
    line: Option<usize>,
}

fn cases() -> Vec<Case> {
    let visco = "[geometry]\nkind = \"cylinder\"\nradius = 0.05\n[substrate]\nmodel = \"viscoelastic\"\ne = 5e6\nnu = 0.49\nalpha = 1e-4\nbeta = 1e-6\n[indenter]\nmodel = \"same\"\n[load]\nnormal = 1000.0\nfriction = 0.8\n";
    vec![
        // P implied by a = 0.0178 m is 9673 N/m; f P = 4837 N/m.
        Case { name: "T > fP with partial slip, load given as half_width", err: parse(&format!("{ROLLER}tangential = 5000.0\n")), kind: ErrorKind::Impossible, key: "load.tangential", line: Some(12) },
        Case { name: "graded sphere", err: parse(&ROLLER.replace("kind = \"cylinder\"\nradius = 0.3", "kind = \"sphere\"\nradius = 0.3")), kind: ErrorKind::Unsupported, key: "geometry.kind", line: Some(2) },
        Case { name: "graded substrate under an elastic indenter", err: parse(&format!("{ROLLER}[indenter]\nmodel = \"same\"\n")), kind: ErrorKind::Unsupported, key: "indenter.model", line: Some(13) },
        Case { name: "rolling on a graded substrate", err: parse(&format!("{ROLLER}[motion]\nkind = \"rolling\"\nspeed = 1.0\n")), kind: ErrorKind::Unsupported, key: "motion.kind", line: Some(13) },
        Case { name: "static viscoelastic substrate", err: parse(visco), kind: ErrorKind::Unsupported, key: "substrate.model", line: Some(5) },
        Case { name: "rolling with a prescribed tangential load", err: parse(&format!("{}tangential = 10.0\n[motion]\nkind = \"rolling\"\nspeed = 0.01\n", visco)), kind: ErrorKind::Impossible, key: "load.tangential", line: Some(15) },
        Case { name: "rolling with a rigid indenter", err: parse(&format!("{}[motion]\nkind = \"rolling\"\nspeed = 0.01\n", visco.replace("model = \"same\"", "model = \"rigid\""))), kind: ErrorKind::Unsupported, key: "indenter.model", line: Some(11) },
        Case { name: "moment and tangential load together by the LP", err: parse(&format!("{SPHERE}tangential = \"10 lbf\"\nmoment = 0.1\n[solver]\nmethod = \"lp\"\n")), kind: ErrorKind::Unsupported, key: "load.moment", line: Some(14) },
        // 0.7 f P and 0.7 of Lubkin's moment (3 pi f P a/16 = 5.87 lbf in) together lie outside
        // the limit surface (each alone is carried): refused before solving.
        Case { name: "force and moment together beyond gross slip", err: parse(&format!("{SPHERE}tangential = \"151 lbf\"\nmoment = \"4.1 lbf in\"\n")), kind: ErrorKind::Impossible, key: "load.moment", line: Some(14) },
        Case { name: "moment beyond Lubkin's gross slip", err: parse(&format!("{SPHERE}moment = 1.0\n")), kind: ErrorKind::Impossible, key: "load.moment", line: Some(13) },
        Case { name: "3D subsurface field without its depth axis z", err: parse(&format!("{SPHERE}[outputs]\nfield = {{ x = [-1.0, 1.0, 5], y = [0.1, 1.0, 5] }}\n")), kind: ErrorKind::Schema, key: "outputs.field", line: Some(14) },
        Case { name: "loading cycle on a cylinder", err: parse(&format!("{ROLLER}[outputs]\ncycle = {{ amplitude = 0.5 }}\n")), kind: ErrorKind::Unsupported, key: "outputs.cycle", line: Some(13) },
        Case { name: "the fast solver on a 2D contact", err: parse(&format!("{ROLLER}[solver]\nmethod = \"fast\"\n")), kind: ErrorKind::Unsupported, key: "solver.method", line: Some(13) },
        Case { name: "LP on a 2D contact", err: parse(&format!("{ROLLER}[solver]\nmethod = \"lp\"\n")), kind: ErrorKind::Unsupported, key: "solver.method", line: Some(13) },
        Case { name: "closed form asked on a graded substrate", err: parse(&format!("{ROLLER}[solver]\nmethod = \"closed-form\"\n")), kind: ErrorKind::Unsupported, key: "solver.method", line: Some(13) },
        // 8000^2 lattice cells with the fast solver: about 70 GB by the planner's estimate.
        Case { name: "fast-solver grid too large for memory", err: parse(&format!("{SPHERE}tangential = \"10 lbf\"\n[solver]\nmethod = \"fast\"\ngrid = 8000\n")), kind: ErrorKind::OutOfRange, key: "solver.grid", line: Some(16) },
        Case { name: "LP grid too large for memory", err: parse(&format!("{SPHERE}tangential = \"10 lbf\"\n[solver]\nmethod = \"lp\"\ngrid = 1000\n")), kind: ErrorKind::OutOfRange, key: "solver.grid", line: Some(16) },
        Case { name: "half_width on an ellipsoid", err: parse("[geometry]\nkind = \"ellipsoid\"\nsemi_axes = [0.01, 0.005]\n[substrate]\nmodel = \"homogeneous\"\ne = 1e9\nnu = 0.3\n[load]\nhalf_width = 0.01\n"), kind: ErrorKind::Schema, key: "load.half_width", line: Some(9) },
    ]
}

#[test]
fn impossible_or_unsupported_scenes_are_refused_before_computing() {
    let cases = cases();
    let mut failures = Vec::new();
    for c in &cases {
        let e = &c.err;
        let msg = e.to_string();
        println!("{:<52} {msg}", c.name);
        if e.kind != c.kind {
            failures.push(format!("{}: kind {:?}, expected {:?}", c.name, e.kind, c.kind));
        }
        if e.key.as_deref() != Some(c.key) {
            failures.push(format!("{}: key {:?}, expected {}", c.name, e.key, c.key));
        }
        match c.line {
            Some(l) if e.position.map(|p| p.0) != Some(l) => {
                failures.push(format!("{}: position {:?}, expected line {l}", c.name, e.position));
            }
            None if e.position.is_none() => {
                failures.push(format!("{}: no position at all", c.name));
            }
            _ => {}
        }
        if !msg.starts_with("bad.toml:") {
            failures.push(format!("{}: message does not name the file", c.name));
        }
        if e.hint.is_none() {
            failures.push(format!("{}: no hint", c.name));
        }
    }
    println!("{} cases here + 32 parse cases in tests/scenes.rs", cases.len());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
