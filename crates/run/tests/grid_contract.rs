//! Grid solutions go through the traction crate's grid-solver contract: failures are typed
//! (no message matching) and reach the user with the key and its position; a negative
//! moment turns the contact the other way.

use stickslip_run::{run, RunOptions};
use stickslip_scene::{ErrorKind, Scene};

#[allow(clippy::result_large_err)]
fn scene(src: &str) -> Result<stickslip_run::Outcome, stickslip_scene::SceneError> {
    let s = Scene::from_toml_str(src, Some("g.toml".into()))?;
    run(&s, &RunOptions::default())
}

const JOINT: &str = "[geometry]\nkind = \"patches\"\npatches = [\n  { shape = \"square\", centre = [\"-0.5 in\", 0.0], side = \"0.6 in\", pressure = \"10000 psi\" },\n  { shape = \"square\", centre = [\"0.5 in\", 0.0], side = \"0.6 in\", pressure = \"10000 psi\" },\n]\n[substrate]\nmodel = \"homogeneous\"\ne = \"30e6 psi\"\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nMOMENT\nfriction = 0.12\n[solver]\nmethod = \"lp\"\ngrid = 16\n";

#[test]
fn a_negative_moment_turns_the_other_way_with_the_lp_and_the_fast_solver() {
    for method in ["lp", "fast"] {
        let src = JOINT.replace("method = \"lp\"", &format!("method = \"{method}\""));
        let pos = scene(&src.replace("MOMENT", "moment = 40.0")).unwrap();
        let neg = scene(&src.replace("MOMENT", "moment = -40.0")).unwrap();
        let (wp, wn) =
            (pos.rigid_displacement.rotation.unwrap(), neg.rigid_displacement.rotation.unwrap());
        assert!(wp > 0.0 && wn < 0.0, "{method}: rotations {wp}, {wn}");
        assert!((wp + wn).abs() <= 1e-9 * wp, "{method}: |{wp}| != |{wn}|");
        let (bp, bn) =
            (pos.rigid_displacement.per_body.unwrap(), neg.rigid_displacement.per_body.unwrap());
        assert!((bp[0] + bn[0]).abs() <= 1e-9 * bp[0].abs(), "{method}: per body {bp:?} {bn:?}");
        assert_eq!(neg.forces.moment, -40.0);
    }
}

#[test]
fn a_lattice_that_does_not_resolve_the_patches_is_refused_before_solving() {
    // At 4 elements across, the squares hold 1 x 1 cells of a lattice too coarse for their
    // area: the lattice force would miss P (and the capacity f P) by far.
    let src = JOINT
        .replace("MOMENT", "tangential = \"820 lbf\"")
        .replace("grid = 16", "grid = 4")
        .replace("method = \"lp\"", "method = \"fast\"");
    let e = scene(&src).unwrap_err();
    assert_eq!(e.kind, ErrorKind::OutOfRange, "{e}");
    assert_eq!(e.key.as_deref(), Some("solver.grid"), "{e}");
    assert_eq!(e.position.map(|p| p.0), Some(18), "{e}");
    let hint = e.hint.clone().unwrap_or_default();
    let min: usize = hint.trim_start_matches("use solver.grid >= ").parse().expect(&hint);
    // The grid the hint names is accepted and solves.
    let ok = scene(&src.replace("grid = 4", &format!("grid = {min}"))).unwrap();
    assert!(ok.audit.passed);
}

const ELLIPSE: &str = "[geometry]\nkind = \"ellipsoid\"\nsemi_axes = [\"2 mm\", \"1 mm\"]\n[substrate]\nmodel = \"homogeneous\"\ne = 2e11\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = 1000.0\nMOMENT\nfriction = 0.3\n[solver]\ngrid = 24\n";

/// The full-slip moment of the Hertz ellipse pressure about its centre,
/// f p0 * integral of sqrt(1 - x^2/a^2 - y^2/b^2) r dA, by a fine midpoint sum here,
/// independent of the lattice the planner uses.
fn ellipse_spin_capacity() -> f64 {
    let (a, b, p, f) = (2e-3, 1e-3, 1000.0, 0.3);
    let p0 = 3.0 * p / (2.0 * std::f64::consts::PI * a * b);
    let n = 2000;
    let (hx, hy) = (2.0 * a / n as f64, 2.0 * b / n as f64);
    let mut m = 0.0;
    for i in 0..n {
        for j in 0..n {
            let (x, y) = (-a + (i as f64 + 0.5) * hx, -b + (j as f64 + 0.5) * hy);
            let s = 1.0 - (x / a).powi(2) - (y / b).powi(2);
            if s > 0.0 {
                m += s.sqrt() * x.hypot(y) * hx * hy;
            }
        }
    }
    f * p0 * m
}

#[test]
fn a_moment_beyond_the_full_slip_moment_is_refused_before_solving() {
    let cap = ellipse_spin_capacity();
    let e = scene(&ELLIPSE.replace("MOMENT", &format!("moment = {}", 1.05 * cap))).unwrap_err();
    assert_eq!((e.kind, e.key.as_deref()), (ErrorKind::Impossible, Some("load.moment")), "{e}");
    assert_eq!(e.position.map(|p| p.0), Some(12), "{e}");
    // Below it the fast solver carries it, and the audit checks the moment on the lattice.
    let ok = scene(&ELLIPSE.replace("MOMENT", &format!("moment = {}", 0.5 * cap))).unwrap();
    assert!(ok.audit.checks.iter().any(|c| c.name == "moment resultant" && c.pass));
}

#[test]
fn an_lp_without_a_solution_on_a_coarse_lattice_names_the_grid() {
    // Seed 002's twist by the LP on 5 elements across: the restricted-entry simplex finds no
    // complementary solution there.
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../scenes/seed002_twist_lp.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let src: String = text
        .lines()
        .map(|l| if l.starts_with("grid =") { "grid = 5" } else { l })
        .collect::<Vec<_>>()
        .join("\n");
    let e = scene(&src).unwrap_err();
    assert_eq!(e.key.as_deref(), Some("solver.grid"), "{e}");
    assert!(e.position.is_some(), "{e}");
    assert!(!e.hint.unwrap_or_default().contains("please report"));
}
