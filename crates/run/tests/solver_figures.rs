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
