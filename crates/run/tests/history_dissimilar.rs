//! Load paths between dissimilar bodies in scenes (issue 31, Dundurs coupling): a sphere, an
//! ellipsoid of given semi-axes and a surface with an elastic substrate under a rigid
//! indenter run coupled, with the `history` columns in their usual form, the passes per
//! step in `history.coupling_passes` and the path's record in `solver.coupling`; identical
//! bodies keep the uncoupled path without either.

#![allow(clippy::result_large_err)]

use stickslip_run::{run, Outcome, Plan, RunOptions};
use stickslip_scene::Scene;

fn solve(text: &str) -> (Plan, Outcome) {
    let s = Scene::from_toml_str(text, Some("test.toml".into())).unwrap_or_else(|e| panic!("{e}"));
    let plan = Plan::new(&s).unwrap_or_else(|e| panic!("{e}"));
    let out = run(&s, &RunOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    (plan, out)
}

/// A sphere (R = 10 mm) of `geometry` under 100 N, f = 0.3, cycled between +-15 N, with the
/// substrate `substrate` under the indenter `indenter`.
fn scene(geometry: &str, indenter: &str, grid: usize) -> String {
    format!(
        r#"title = "dissimilar path"
[geometry]
{geometry}
[substrate]
model = "homogeneous"
e = "70 GPa"
nu = 0.3
[indenter]
{indenter}
[load]
normal = "100 N"
friction = 0.3
[load.history]
tangential = ["0 N", "15 N", "-15 N", "15 N"]
steps = 6
[solver]
grid = {grid}
tolerance = 1e-9
"#
    )
}

fn reason(plan: &Plan) -> String {
    format!("{:?}", plan.effects)
}

/// The common checks of a coupled path's outcome: audit, columns, admissible loads.
fn check_columns(out: &Outcome) {
    assert!(out.audit.passed, "{:?}", out.audit);
    let h = out.history.as_ref().expect("history");
    let n = h.tangential.len();
    assert_eq!(n, 19);
    for col in [&h.normal, &h.shift, &h.stick_fraction, &h.dissipated, &h.work, &h.elastic_energy] {
        assert_eq!(col.len(), n);
    }
    for (t, target) in h.tangential.iter().zip(
        std::iter::once(0.0)
            .chain((1..=6).map(|i| 15.0 * i as f64 / 6.0))
            .chain((1..=6).map(|i| 15.0 - 30.0 * i as f64 / 6.0))
            .chain((1..=6).map(|i| -15.0 + 30.0 * i as f64 / 6.0)),
    ) {
        assert!((t - target).abs() <= 1e-7 * 30.0, "{t} against {target}");
    }
    // Energy is dissipated, not returned, except for the midpoint rule's error where the
    // pressure changes (module docs of stickslip_traction::history): under the coupling the
    // pressure moves with the traction, on a surface also the contact's edge cells. Measured
    // on the 40 x 40 surface: a step returns 1.3e-5 of the path's dissipation.
    for (i, w) in h.dissipated.windows(2).enumerate() {
        assert!(w[1] >= w[0] - 3e-5 * h.dissipated[n - 1], "step {}: {w:?}", i + 1);
    }
    assert_eq!(h.loops.len(), 1);
    assert!(h.loops[0].energy > 0.0);
}

#[test]
fn sphere_on_a_softer_substrate_runs_coupled() {
    let (plan, out) =
        solve(&scene("kind = \"sphere\"\nradius = \"10 mm\"", "model = \"rigid\"", 32));
    assert!(reason(&plan).contains("coupled with the normal contact through Dundurs beta = 0.2857"));
    check_columns(&out);
    let h = out.history.as_ref().unwrap();
    assert_eq!(h.coupling_passes.len(), h.tangential.len());
    assert!(h.coupling_passes.iter().all(|&p| p >= 2), "{:?}", h.coupling_passes);
    let c = out.solver.coupling.expect("solver.coupling");
    assert!((c.beta - 2.0 / 7.0).abs() < 1e-12);
    assert_eq!(c.steps, Some(h.tangential.len()));
    assert_eq!(c.passes, h.coupling_passes.iter().sum::<usize>());
    assert_eq!(c.most_passes, h.coupling_passes.iter().copied().max());
    assert!(c.traction_change <= 1e-9 && c.pressure_change <= 1e-6, "{c:?}");
    assert!(c.normal_iterations > 0);
    let json = serde_json::to_value(&out).unwrap();
    assert!(json["history"]["coupling_passes"].is_array());
    assert_eq!(json["solver"]["coupling"]["steps"], 19);
}

#[test]
fn given_semi_axes_couple_one_way() {
    let (plan, out) = solve(&scene(
        "kind = \"ellipsoid\"\nsemi_axes = [\"0.2 mm\", \"0.1 mm\"]",
        "model = \"rigid\"",
        24,
    ));
    assert!(reason(&plan).contains("prescribed pressure does not respond"), "{}", reason(&plan));
    check_columns(&out);
    let h = out.history.as_ref().unwrap();
    assert!(h.coupling_passes.iter().all(|&p| p == 1));
    let c = out.solver.coupling.expect("solver.coupling");
    assert_eq!(c.passes, h.tangential.len());
    assert_eq!((c.traction_change, c.pressure_change), (0.0, 0.0));
}

#[test]
fn identical_bodies_stay_uncoupled() {
    let (plan, out) =
        solve(&scene("kind = \"sphere\"\nradius = \"10 mm\"", "model = \"same\"", 24));
    assert!(!reason(&plan).contains("Dundurs"));
    check_columns(&out);
    assert!(out.history.as_ref().unwrap().coupling_passes.is_empty());
    assert!(out.solver.coupling.is_none());
    let json = serde_json::to_value(&out).unwrap();
    assert!(json["history"].get("coupling_passes").is_none());
}

/// A rigid sphere (R = 10 mm) given as a surface of `cells` across `size` (free or periodic)
/// runs its path coupled: every step takes at least two passes and the traction settles.
fn surface_path_runs_coupled_on(geometry: &str) -> Outcome {
    let (plan, out) = solve(&scene(geometry, "model = \"rigid\"", 32));
    assert!(reason(&plan).contains("coupled with the normal contact through Dundurs beta = 0.2857"));
    check_columns(&out);
    let h = out.history.as_ref().unwrap();
    assert!(h.coupling_passes.iter().all(|&p| p >= 2), "{:?}", h.coupling_passes);
    assert!(out.solver.coupling.expect("solver.coupling").traction_change <= 1e-9);
    out
}

#[test]
fn surface_path_runs_coupled() {
    // The same sphere as a surface (contact radius about 0.21 mm under 100 N).
    let out = surface_path_runs_coupled_on(
        "kind = \"surface\"\nsize = [\"0.6 mm\", \"0.6 mm\"]\ncells = [40, 40]\n[geometry.profile]\nshape = \"sphere\"\nradius = \"10 mm\"",
    );
    // The surface's normal solves: one per pass and one per corner check.
    let c = out.solver.coupling.expect("solver.coupling");
    let normal = out.solver.normal.expect("solver.normal");
    assert!(normal.steps >= c.passes, "{} solves for {} passes", normal.steps, c.passes);
}

#[test]
fn periodic_surface_path_runs_coupled() {
    // The sphere on one period of 0.8 mm (about two contact diameters), the periodic cross
    // operators.
    surface_path_runs_coupled_on(
        "kind = \"surface\"\nboundary = \"periodic\"\nsize = [\"0.8 mm\", \"0.8 mm\"]\ncells = [48, 48]\n[geometry.profile]\nshape = \"sphere\"\nradius = \"10 mm\"",
    );
}
