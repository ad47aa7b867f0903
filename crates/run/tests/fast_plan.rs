//! The fast solver in scenes: which grid solver `auto` picks and why (the LP up to
//! `MAX_LP_ELEMENTS` contact elements and for one load mode, the fast solver beyond or for a
//! force and a moment together), the memory refusal, and fast runs checked against closed
//! forms (Lubkin's rotation, FORMULAS.md G; Mindlin's per-body shares, FORMULAS.md E), with
//! the evaluation counters proving that effects that are off cost nothing.

// Scene errors carry file, position, key and hint; the tests pass them around whole.
#![allow(clippy::result_large_err)]

mod common;
use common::{rel, scenes_dir, tol, INCH, LBF, PSI};
use std::f64::consts::PI;
use stickslip_run::plan::{MAX_LP_ELEMENTS, MEMORY_LIMIT_BYTES};
use stickslip_run::{read_scene, run, Effect, Plan, RunOptions, Technique};
use stickslip_scene::{ErrorKind, Scene};

fn scene_text(name: &str) -> String {
    std::fs::read_to_string(scenes_dir().join(name)).unwrap()
}

fn parse(text: &str) -> Scene {
    Scene::from_toml_str(text, Some("test.toml".into())).unwrap_or_else(|e| panic!("{e}"))
}

/// Effects that are on were evaluated, effects that are off never were.
fn assert_counts(name: &str, plan: &Plan, out: &stickslip_run::Outcome) {
    for e in Effect::ALL {
        let n = out.evaluations.get(e);
        if plan.is_on(e) {
            assert!(n > 0, "{name}: {e} is on but was never evaluated");
        } else {
            assert_eq!(n, 0, "{name}: {e} is off but was evaluated {n} times");
        }
    }
}

#[test]
fn auto_picks_the_lp_up_to_its_limit_and_the_fast_solver_beyond() {
    // Example 4's uniformly pressed square: grid^2 elements.
    let base = scene_text("seed002_ex4_square.toml");
    let below = (MAX_LP_ELEMENTS as f64).sqrt().floor() as usize; // 54^2 = 2916
    for (grid, want) in
        [(10, Technique::LpForce), (below, Technique::LpForce), (below + 1, Technique::Fast)]
    {
        let s = parse(&base.replace("grid = 10", &format!("grid = {grid}")));
        let plan = Plan::new(&s).unwrap();
        let why = plan.grid_solver.clone().unwrap();
        println!(
            "grid {grid}: {:?} ({why}); estimate {:.3} s",
            plan.technique(Effect::Friction),
            plan.cost.seconds
        );
        assert_eq!(plan.technique(Effect::Friction), Some(want), "grid {grid}");
        let text = plan.explain();
        assert!(text.contains("grid solver:"), "{text}");
        if want == Technique::Fast {
            assert!(why.contains(&format!("> {MAX_LP_ELEMENTS}")) && why.contains("fast"), "{why}");
            assert!(text.contains("fast solver on a contact grid"), "{text}");
        } else {
            assert!(why.contains("modified LP"), "{why}");
        }
    }
    // Asking for the LP beyond its limit is refused, with the fast solver as the hint.
    let e = read_scene(
        &base.replace("grid = 10", &format!("method = \"lp\"\ngrid = {}", below + 1)),
        Some("lp.toml".into()),
    )
    .unwrap_err();
    println!("{e}");
    assert_eq!(e.kind, ErrorKind::OutOfRange);
    assert_eq!(e.key.as_deref(), Some("solver.grid"));
    assert!(e.hint.unwrap().contains("fast"));
    // Closed forms stay first where they apply: a sphere under a force is Mindlin at any grid.
    let s = parse(&scene_text("seed002_ex1_mindlin.toml").replace("grid = 20", "grid = 512"));
    let plan = Plan::new(&s).unwrap();
    assert_eq!(plan.technique(Effect::Friction), Some(Technique::Mindlin));
    assert!(plan.grid_solver.is_none());
}

#[test]
fn force_and_moment_together_go_to_the_fast_solver() {
    let base = scene_text("seed002_ex1_mindlin.toml")
        .replace("friction = 0.1", "friction = 0.1\nmoment = 0.1");
    let s = parse(&base);
    let plan = Plan::new(&s).unwrap();
    println!("{}", plan.explain());
    assert_eq!(plan.technique(Effect::Friction), Some(Technique::Fast));
    assert_eq!(plan.technique(Effect::Twist), Some(Technique::Fast));
    assert!(plan.grid_solver.as_deref().unwrap().contains("together"));
    for method in ["lp", "closed-form"] {
        let e = read_scene(
            &base.replace("grid = 20", &format!("method = \"{method}\"\ngrid = 20")),
            Some("both.toml".into()),
        )
        .unwrap_err();
        println!("{e}");
        assert_eq!(e.kind, ErrorKind::Unsupported);
        assert_eq!(e.key.as_deref(), Some("load.moment"));
        assert!(e.hint.unwrap().contains("fast"));
    }
}

#[test]
fn the_memory_estimate_admits_large_fast_grids_and_refuses_what_cannot_fit() {
    let base = scene_text("fast_mindlin_sphere_256.toml");
    let plan_of = |grid: usize| {
        Scene::from_toml_str(
            &base.replace("grid = 256", &format!("grid = {grid}")),
            Some("big.toml".into()),
        )
        .and_then(|s| Plan::new(&s))
    };
    for grid in [1024, 2048, 4096] {
        let p = plan_of(grid).unwrap_or_else(|e| panic!("grid {grid}: {e}"));
        println!(
            "grid {grid}: {} elements, estimate {:.2} GB, {:.0} s",
            p.grid_elements,
            p.cost.memory_bytes as f64 / 1e9,
            p.cost.seconds
        );
        assert!(p.cost.memory_bytes <= MEMORY_LIMIT_BYTES);
    }
    // 8192^2 cells would need well over 24 GiB (measured rate 475 B per cell: 32 GB).
    for grid in [6000, 8192] {
        let e = plan_of(grid).unwrap_err();
        println!("grid {grid}: {e}");
        assert_eq!(e.kind, ErrorKind::OutOfRange);
        assert_eq!(e.key.as_deref(), Some("solver.grid"));
        assert!(e.position.is_some() && e.message.contains("memory"));
    }
}

#[test]
fn fast_twist_matches_lubkin_and_counts_only_what_is_on() {
    // Seed 002's twist (FORMULAS.md G) by the fast solver on 64 x 64 cells (3,228 elements).
    let text = scene_text("seed002_twist_lubkin.toml")
        .replace("grid = 16", "method = \"fast\"\ngrid = 64");
    let s = parse(&text);
    let plan = Plan::new(&s).unwrap();
    assert_eq!(plan.technique(Effect::Twist), Some(Technique::Fast));
    let out = run(&s, &RunOptions::default()).unwrap();
    assert_counts("fast twist", &plan, &out);
    let (p, f, m) = (2160.0 * LBF, 0.1, 0.39737);
    let a = out.contact.a;
    let lub = stickslip_traction::closed::Lubkin::from_moment(a, p, f, m).unwrap();
    let kme = {
        let mm = 1.0 - (lub.stick_radius() / a).powi(2);
        stickslip_special::ellipk(mm) - stickslip_special::ellipe(mm)
    };
    let g = 30e6 * PSI / 2.6;
    let omega = 2.0 * 3.0 * f * p / (4.0 * PI * g * a * a) * kme;
    let got = out.rigid_displacement.rotation.unwrap();
    let gz = out.zones.grid.unwrap();
    let frac = (lub.stick_radius() / a).powi(2);
    println!(
        "fast twist 64^2: rotation {got:.10e} vs Lubkin {omega:.10e}, rel {:.2e}; stick fraction {:.4} vs (c/a)^2 = {frac:.4}; {} Newton, {} CG, residual {:.2e}",
        rel(got, omega),
        gz.stick_area_fraction,
        out.solver.iterations,
        out.solver.inner_iterations,
        out.solver.residual
    );
    assert!(rel(got, omega) < tol::FAST_SHIFT, "{got} vs {omega}");
    assert!(out.solver.residual <= tol::FAST_RESIDUAL);
    assert_eq!(out.forces.moment, m);
}

#[test]
fn fast_per_body_shares_follow_the_compliances() {
    // Example 2, steel on rubber (equal nu): the shares are in the ratio E_steel / E_rubber
    // = 30 exactly, and each matches Mindlin's per-body displacement to the discretisation
    // error (FORMULAS.md E; seed 002's 0.403917e-3 in and 0.134639e-4 in).
    let text =
        scene_text("seed002_ex2_rubber.toml").replace("grid = 20", "method = \"fast\"\ngrid = 128");
    let s = parse(&text);
    let plan = Plan::new(&s).unwrap();
    let out = run(&s, &RunOptions::default()).unwrap();
    assert_counts("fast rubber", &plan, &out);
    let pb = out.rigid_displacement.per_body.unwrap();
    println!(
        "fast rubber/steel 128^2: per body {:.6e} / {:.6e} in, ratio {:.15}; {} elements, {:.2} s",
        pb[0] / INCH,
        pb[1] / INCH,
        pb[0] / pb[1],
        out.solver.elements,
        out.solver.solve_seconds
    );
    assert!(rel(pb[0] / pb[1], 30.0) < tol::FFT_ROUNDING, "{}", pb[0] / pb[1]);
    assert!(rel(pb[0] / INCH, 0.403917e-3) < tol::FAST_SHIFT);
    assert!(rel(pb[1] / INCH, 0.134639e-4) < tol::FAST_SHIFT);
    let sum = pb[0] + pb[1];
    assert!(rel(sum, out.rigid_displacement.tangential.unwrap()) < tol::FFT_ROUNDING);
}

#[test]
fn loads_beyond_the_capacity_name_the_load_key() {
    let base = scene_text("fast_gasket_ring_force_and_twist.toml");
    // A moment alone beyond the spin capacity f sum p_k r_k A_k (about 150 N m here): refused
    // by validation, before any solver runs, at the moment's line.
    let text = base.replace("tangential = \"700 lbf\"\n", "").replace("80.0", "200.0");
    let e = read_scene(&text, Some("test.toml".into())).unwrap_err();
    println!("{e}");
    assert_eq!(e.kind, ErrorKind::Impossible);
    assert_eq!(e.key.as_deref(), Some("load.moment"));
    assert!(e.position.is_some());
    // A force below f P (1312.5 lbf) with a moment on top that together exceed what the
    // contact can carry (outside its limit surface): refused before solving, with the factor
    // by which the pair could be scaled.
    let e = read_scene(&base.replace("\"700 lbf\"", "\"1300 lbf\""), Some("test.toml".into()))
        .unwrap_err();
    println!("{e}");
    assert_eq!(e.kind, ErrorKind::Impossible);
    assert_eq!(e.key.as_deref(), Some("load.moment"));
    assert!(e.position.is_some());
    assert!(e.hint.unwrap().contains("scale load.tangential and load.moment by less than"));
}
