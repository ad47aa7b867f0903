//! result.json's `solver` block carries each lattice solver's own figures (issue 33, item 8):
//! every kind of scene that runs a lattice solver reports its iterations, its elements and
//! a positive solve time, and the top-level figures agree with the solver's own record where
//! result.json keeps one (`solver.normal`, `solver.coupling`, `load_curve`).

mod common;
use common::scenes_dir;
use stickslip_run::{run, Outcome, RunOptions};
use stickslip_scene::Scene;

fn file(name: &str) -> Outcome {
    let scene = Scene::from_file(&scenes_dir().join(name)).unwrap_or_else(|e| panic!("{e}"));
    run(&scene, &RunOptions::default()).unwrap_or_else(|e| panic!("{name}: {e}"))
}

const SURFACE: &str = "[geometry]\nkind = \"surface\"\nsize = [\"0.8 mm\", \"0.8 mm\"]\ncells = [64, 64]\n[geometry.profile]\nshape = \"sphere\"\nradius = \"10 mm\"\n[substrate]\nmodel = \"homogeneous\"\ne = \"210 GPa\"\nnu = 0.3\n[indenter]\nINDENTER\n[load]\nLOAD\n";

fn surface(indenter: &str, load: &str) -> Outcome {
    let src = SURFACE.replace("INDENTER", indenter).replace("LOAD", load);
    let dir = std::env::temp_dir();
    let scene = Scene::from_toml_str(&src, Some(dir.join("s.toml"))).unwrap();
    run(&scene, &RunOptions::default()).unwrap_or_else(|e| panic!("{e}"))
}

/// The figures every lattice solver reports: iterations, elements, a finite residual and a
/// positive solve time no longer than the run; inner iterations when the solver has them.
fn reports(what: &str, out: &Outcome, inner: bool) {
    let s = &out.solver;
    println!(
        "{what}: {} iterations, {} inner, residual {:.2e}, {} elements, solve {:.4} s of {:.4} s",
        s.iterations, s.inner_iterations, s.residual, s.elements, s.solve_seconds, s.seconds
    );
    assert!(s.iterations > 0, "{what}: no iterations");
    assert_eq!(s.inner_iterations > 0, inner, "{what}: inner iterations {}", s.inner_iterations);
    assert!(s.elements > 0, "{what}: no elements");
    assert!(s.residual.is_finite() && s.residual >= 0.0, "{what}: residual {}", s.residual);
    assert!(s.solve_seconds > 0.0, "{what}: solve time {}", s.solve_seconds);
    assert!(s.solve_seconds <= s.seconds, "{what}: {} > run {}", s.solve_seconds, s.seconds);
}

#[test]
fn the_normal_solver_of_a_surface() {
    let out = surface("model = \"same\"", "normal = \"10 N\"");
    reports("surface, normal only", &out, true);
    let n = out.solver.normal.unwrap();
    assert_eq!((out.solver.iterations, out.solver.inner_iterations), (n.iterations, n.products));
    assert_eq!(out.solver.elements, 64 * 64);
    assert!(out.solver.solve_seconds >= n.setup_seconds + n.solve_seconds);
}

#[test]
fn a_load_sweep_counts_every_step() {
    let out = surface("model = \"same\"", "normal = [\"1 N\", \"10 N\", 4]");
    reports("surface, load sweep", &out, true);
    let n = out.solver.normal.unwrap();
    let curve = out.load_curve.as_ref().unwrap();
    assert_eq!(n.steps, 4);
    assert_eq!(curve.iterations.len(), 4);
    assert!(curve.iterations.iter().all(|&k| k > 0), "{:?}", curve.iterations);
    // The top level is the last step's; the time covers all steps.
    assert_eq!(out.solver.iterations, *curve.iterations.last().unwrap());
    assert!(out.solver.solve_seconds >= n.solve_seconds);
}

#[test]
fn the_fast_solver_after_a_surface() {
    let out =
        surface("model = \"same\"", "normal = \"10 N\"\ntangential = \"1 N\"\nfriction = 0.3");
    reports("surface + fast solver", &out, true);
    let n = out.solver.normal.unwrap();
    // The time covers both solvers; the counts are the fast solver's.
    assert!(out.solver.solve_seconds > n.setup_seconds + n.solve_seconds);
    assert!(out.solver.elements < 64 * 64);
}

#[test]
fn the_coupled_solve_of_dissimilar_bodies() {
    let out = surface(
        "model = \"homogeneous\"\ne = \"70 GPa\"\nnu = 0.33",
        "normal = \"10 N\"\ntangential = \"1 N\"\nfriction = 0.2",
    );
    reports("surface, coupled", &out, true);
    let c = out.solver.coupling.unwrap();
    assert_eq!(out.solver.iterations, c.tangential_iterations);
}

#[test]
fn a_load_path_on_a_surface_adds_to_the_normal_solve() {
    let out = file("rough_periodic_fretting.toml");
    reports("surface + load path", &out, true);
    let n = out.solver.normal.unwrap();
    // The path's steps come on top of the normal solve (they used to replace its time).
    assert!(out.solver.solve_seconds > n.setup_seconds + n.solve_seconds);
    // The top level is the path's own: every step makes at least one operator product, so
    // its products outnumber its steps (they used to be the last normal solve's figures,
    // 12 iterations and 14 products against 41 steps).
    let steps = out.history.as_ref().unwrap().tangential.len();
    assert!(steps > 1);
    assert!(out.solver.inner_iterations >= steps, "{} products", out.solver.inner_iterations);
    assert!(out.solver.elements == 64 * 64);
    // The path's note gives the same figures.
    let note = out.notes.iter().find(|t| t.starts_with("load path:")).unwrap();
    let said = format!(
        "{} Newton steps, {} operator products",
        out.solver.iterations, out.solver.inner_iterations
    );
    assert!(note.contains(&said), "{note} lacks {said}");
    // `solver.normal` counts the surface's first solve and the path's (at least one, at the
    // path's normal load), and their time.
    assert!(n.steps >= 2, "{} normal solves", n.steps);
    assert!(n.iterations > 0 && n.residual <= 1e-10);
}

#[test]
fn a_wheel_on_its_rail_reports_both_solvers() {
    let out = file("wheel_rail_manchester_a22.toml");
    reports("wheel on rail, exact rolling", &out, true);
    let w = out.wheel_rail.as_ref().unwrap();
    // The top level is the creep-force solvers' (summed over the patches).
    let newton: usize = w.patches.iter().map(|p| p.tangential.as_ref().unwrap().iterations).sum();
    assert_eq!(out.solver.iterations, newton);
    let residual =
        w.patches.iter().map(|p| p.tangential.as_ref().unwrap().residual).fold(0.0, f64::max);
    assert_eq!(out.solver.residual, residual);
    // `solver.normal`: the patches' final normal solves, and every solve of the load
    // iteration in its count and time.
    let n = out.solver.normal.expect("solver.normal for a wheel on its rail");
    assert!(n.iterations > 0 && n.products >= n.iterations);
    assert!(
        n.residual > 0.0 && n.residual <= 1e-6,
        "normal residual {} (solver.tolerance 1e-6)",
        n.residual
    );
    assert!(n.steps > w.patches.len(), "{} normal solves", n.steps);
    assert!(n.solve_seconds > 0.0 && n.solve_seconds <= out.solver.solve_seconds);
}

#[test]
fn the_grid_solvers_and_the_load_path() {
    // The modified LP has pivots and no inner iterations.
    reports("modified LP, force", &file("seed002_ex1_lp.toml"), false);
    reports("modified LP, moment", &file("seed002_twist_lp.toml"), false);
    reports("fast solver, force and moment", &file("fast_gasket_ring_force_and_twist.toml"), true);
    reports("load path on a Hertz contact", &file("sphere_fretting_history.toml"), true);
}

#[test]
fn the_rolling_solvers() {
    reports("exact steady rolling", &file("wheel_rail_creepage_spin.toml"), true);
    // FASTSIM: one pass over the strips, no inner iterations.
    reports("FASTSIM", &file("wheel_rail_fastsim.toml"), false);
}
