//! Grid solutions go through the traction crate's grid-solver contract: failures are typed
//! (no message matching) and reach the user with the key and its position; a negative
//! moment turns the contact the other way.

use stickslip_scene::{run, ErrorKind, RunOptions, Scene};

#[allow(clippy::result_large_err)]
fn scene(src: &str) -> Result<stickslip_scene::Outcome, stickslip_scene::SceneError> {
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
