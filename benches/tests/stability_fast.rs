//! Robustness sweep of the fast partial-slip solver (issue 20, item 2), beside the
//! hard-case suite `stability.rs`.
//!
//! On Hertz circles of 16, 32, 64, 128 and 256 cells across: a tangential force alone at
//! T/fP in {0.05, 0.5, 0.9, 0.99, 0.999} (traction free, and parallel to the force), a
//! twisting moment alone at the same fractions of the contact's full-slip moment, and a
//! force and a moment together at 0.5 and 0.999 of the limit surface
//! (`ContactGrid::load_capacity_factor`). Every case must converge to the requested residual
//! and pass checks that do not come from the solver:
//!
//! * Coulomb admissibility cell by cell, |q_k| <= f p_k up to the bound the converged
//!   residual implies, and equilibrium: the resultant force and moment summed here from the
//!   element tractions equal the load;
//! * force alone: Mindlin's closed form (FORMULAS.md E) for the stick radius
//!   a (1 - T/fP)^(1/3), the tangential compliance and the traction field, where Mindlin's
//!   solution is the exact solution of the problem posed: traction parallel to the force
//!   (any nu), or both components free with nu = 0 (no coupling of the two directions; with
//!   nu > 0 the free solution departs from Mindlin's by an amount that does not vanish with
//!   the grid, so those cases are held to admissibility and equilibrium, and their deviation
//!   is printed);
//! * moment alone: Lubkin's closed form (FORMULAS.md G, `closed::Lubkin`) for the stick
//!   radius, the rotation and the circumferential traction;
//! * force and moment together: no closed form; admissibility and equilibrium.
//!
//! Loads beyond the capacity (1.001 fP, 1.001 times the full-slip moment, 1.01 times the
//! limit surface) are refused by the checks the planner makes before solving
//! (`load_capacity_factor` < 1, `spin_capacity`), and the solver itself returns an error for
//! them, never a solution. `STICKSLIP_EXTENDED=1` adds the nu = 0 free cases at 256 across
//! and more points on the limit surface. The 512 and 1024 grids are run outside CI by the
//! example `fast_large` (results in docs/hard-cases.md). The cases and checks are
//! `stickslip_benches::fast_sweep`.

use stickslip_benches::fast_sweep::{
    body, circle, combined_case, force_case, moment_case, Outcome, F, RATIOS,
};
use stickslip_traction::Load;
use stickslip_traction::{fast::FastProblem, fast::TractionDirections};

const GRIDS: [usize; 5] = [16, 32, 64, 128, 256];

fn extended() -> bool {
    std::env::var("STICKSLIP_EXTENDED").is_ok_and(|v| v == "1")
}

/// A named case.
type Case = (String, Box<dyn Fn() -> Outcome>);

/// Run cases, print one line each, fail listing every failure.
fn run(cases: Vec<Case>) {
    let mut failed = Vec::new();
    for (id, case) in cases {
        match case() {
            Ok(s) => println!("ok   {id:<40} {s}"),
            Err(e) => {
                println!("FAIL {id:<40} {e}");
                failed.push(format!("{id}: {e}"));
            }
        }
    }
    assert!(failed.is_empty(), "{failed:#?}");
}

#[test]
fn force_alone_parallel_to_the_force_matches_mindlin() {
    let mut cases: Vec<Case> = Vec::new();
    for n in GRIDS {
        for r in RATIOS {
            cases.push((
                format!("force n={n} T/fP={r} parallel"),
                Box::new(move || force_case(n, 0.3, r, TractionDirections::ParallelToForce, true)),
            ));
        }
    }
    run(cases);
}

#[test]
fn force_alone_free_directions() {
    let mut cases: Vec<Case> = Vec::new();
    for n in GRIDS {
        for r in RATIOS {
            cases.push((
                format!("force n={n} T/fP={r} free nu=0.3"),
                Box::new(move || force_case(n, 0.3, r, TractionDirections::Free, false)),
            ));
            if n < 256 || extended() {
                cases.push((
                    format!("force n={n} T/fP={r} free nu=0"),
                    Box::new(move || force_case(n, 0.0, r, TractionDirections::Free, true)),
                ));
            }
        }
    }
    run(cases);
}

#[test]
fn moment_alone_matches_lubkin() {
    let mut cases: Vec<Case> = Vec::new();
    for n in GRIDS {
        for r in RATIOS {
            cases.push((format!("moment n={n} M/Mf={r}"), Box::new(move || moment_case(n, r))));
        }
    }
    run(cases);
}

#[test]
fn force_and_moment_inside_the_limit_surface() {
    let scales: &[f64] = if extended() { &[0.5, 0.9, 0.99, 0.999] } else { &[0.5, 0.999] };
    let mut cases: Vec<Case> = Vec::new();
    for n in GRIDS {
        for mix in [0.2, 0.5, 0.8] {
            for &s in scales {
                cases.push((
                    format!("combined n={n} mix={mix} at {s}"),
                    Box::new(move || combined_case(n, mix, s)),
                ));
            }
        }
    }
    run(cases);
}

/// Beyond the capacity the planner's checks refuse the load before any solve, and the
/// solver, if called anyway, returns an error rather than a solution.
#[test]
fn loads_beyond_capacity_are_refused_before_solving() {
    let m = body(0.3);
    for n in GRIDS {
        let (g, _) = circle(n, &m);
        let fp = F * g.total_normal_force();
        let cap = g.spin_capacity(F);
        let beyond: Vec<(String, Load, bool)> = {
            let mut v = vec![
                (format!("force 1.001 fP, n={n}"), Load::polar(1.001 * fp, 0.3).unwrap(), false),
                (format!("moment 1.001 Mf, n={n}"), Load::moment(1.001 * cap, None).unwrap(), true),
            ];
            for mix in [0.2, 0.5, 0.8] {
                let (t, mo) = ((1.0 - mix) * fp, mix * cap);
                let lam = g.load_capacity_factor(F, (t, 0.0), mo);
                let load = Load::polar(1.01 * lam * t, 0.0)
                    .unwrap()
                    .with_moment(1.01 * lam * mo, None)
                    .unwrap();
                v.push((format!("mix {mix} at 1.01 of the limit, n={n}"), load, false));
            }
            v
        };
        for (what, load, spin) in beyond {
            let (tx, ty) = load.force_components();
            let mo = load.moment_value().unwrap_or(0.0);
            // The planner's checks (crates/plan/src/checks.rs): the full-slip moment
            // for a moment, the limit surface for a force with or without a moment.
            let refused =
                if spin { mo.abs() > cap } else { g.load_capacity_factor(F, (tx, ty), mo) < 1.0 };
            assert!(refused, "{what}: not refused by the planner's check");
            let got = FastProblem::new(&g, [m, m], F, load).unwrap().solve();
            assert!(got.is_err(), "{what}: the solver returned a solution beyond the capacity");
            println!("refused {what}: the solver says {}", got.unwrap_err());
        }
    }
}
