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
//! example `fast_sweep_large` (results in docs/hard-cases.md).

use std::f64::consts::PI;
use std::time::Instant;
use stickslip_halfspace::Material;
use stickslip_traction::closed::{Lubkin, Mindlin};
use stickslip_traction::fast::{FastConfig, FastProblem, FastSolution, TractionDirections};
use stickslip_traction::{ContactGrid, Load};

/// Tolerances of the sweep, each with its reason. `h` is the cell width, `a` the contact
/// radius.
mod tol {
    /// The requested relative residual (the solver's default, `Tolerance::default`).
    pub const RESIDUAL: f64 = 1e-10;
    /// Stick radius (area-equivalent radius of the stick cells) against the closed form, in
    /// cell widths: the stick/slip boundary is resolved to a cell. Measured <= 0.36.
    pub const STICK_CELLS: f64 = 1.0;
    /// Rigid shift (Mindlin) or rotation (Lubkin), relative, as `C (h/a)^(3/2)`: the closed
    /// forms' tractions have square-root edges at the contact and stick radii, which limit
    /// the cell-centred discretisation to order 3/2. Measured C <= 0.3 (shift) and <= 0.9
    /// (rotation) over the sweep.
    pub const RIGID: f64 = 1.0;
    /// RMS traction error over the cells relative to f p0 (p0 = 3P/(2 pi a^2)), as
    /// `C h/a`: an O(sqrt(h/a)) error on the band of O(h/a) of the cells at the edges.
    /// Measured C <= 0.23.
    pub const TRACTION_RMS: f64 = 0.5;
    /// Largest traction error of one cell relative to f p0, as `C sqrt(h/a)` (the square
    /// root edge inside one cell). Measured C <= 0.53.
    pub const TRACTION_MAX: f64 = 1.0;
    /// Summation rounding of the resultants: a few eps per term of the sums, relative to the
    /// sum of the magnitudes.
    pub const SUM_EPS: f64 = 8.0 * f64::EPSILON;
}

/// Seed 002 Example 1 proportions (FORMULAS.md E): P = 2160, f = 0.1, E = 30e6.
const P: f64 = 2160.0;
const F: f64 = 0.1;
const GRIDS: [usize; 5] = [16, 32, 64, 128, 256];
const RATIOS: [f64; 5] = [0.05, 0.5, 0.9, 0.99, 0.999];

fn extended() -> bool {
    std::env::var("STICKSLIP_EXTENDED").is_ok_and(|v| v == "1")
}

fn body(nu: f64) -> Material {
    Material::new(30e6, nu).unwrap()
}

/// Hertz radius of a unit sphere on a flat of the same material, a = (3 P R / (4 E*))^(1/3).
fn hertz_radius(m: &Material) -> f64 {
    (3.0 * P * (2.0 * m.normal_compliance()) / 4.0).cbrt()
}

/// A Hertz circle of `n` cells across and its contact radius.
fn circle(n: usize, m: &Material) -> (ContactGrid, f64) {
    let a = hertz_radius(m);
    (ContactGrid::hertz_circle(a, P, n).unwrap(), a)
}

/// Area-equivalent radius of the stick cells.
fn stick_radius(g: &ContactGrid, s: &FastSolution) -> f64 {
    (s.stick_count() as f64 * g.element_area() / PI).sqrt()
}

/// A failed check, or the case's summary line.
type Outcome = Result<String, String>;

/// Solve, then check the residual, admissibility and equilibrium against the load.
fn solve_checked(
    g: &ContactGrid,
    m: Material,
    load: Load,
    dirs: TractionDirections,
) -> Result<(FastSolution, String), String> {
    let config = FastConfig::new(
        stickslip_quad::Tolerance::relative(tol::RESIDUAL).map_err(|e| e.to_string())?,
        100,
    )
    .map_err(|e| e.to_string())?;
    let t0 = Instant::now();
    let s = FastProblem::new(g, [m, m], F, load)
        .and_then(|p| p.with_directions(dirs))
        .map(|p| p.with_config(config))
        .and_then(|p| p.solve())
        .map_err(|e| format!("failed mid-solve: {e}"))?;
    let secs = t0.elapsed().as_secs_f64();
    if !(s.info.residual <= tol::RESIDUAL && s.info.load_residual <= tol::RESIDUAL) {
        return Err(format!(
            "residual {:.2e} / load residual {:.2e} above {:.0e}",
            s.info.residual,
            s.info.load_residual,
            tol::RESIDUAL
        ));
    }
    // Admissibility: the natural residual bounds every element's distance from its disc,
    // dist(q_k, D_k) <= |r_k| <= ||r|| <= eps ||q||.
    let qnorm = s.traction.iter().map(|q| q.0 * q.0 + q.1 * q.1).sum::<f64>().sqrt();
    let bound = tol::RESIDUAL * qnorm;
    let (mut worst, mut at) = (f64::NEG_INFINITY, 0);
    for (k, q) in s.traction.iter().enumerate() {
        let excess = q.0.hypot(q.1) - F * g.pressure[k];
        if excess > worst {
            (worst, at) = (excess, k);
        }
    }
    if worst > bound {
        return Err(format!(
            "cell {at} at ({:.3e}, {:.3e}) exceeds its Coulomb disc by {worst:.3e} (bound {bound:.3e})",
            g.x[at], g.y[at]
        ));
    }
    // Equilibrium, summed here; the moment about the force centroid (the load's centre).
    let area = g.element_area();
    let c = g.force_centroid();
    let (mut rx, mut ry, mut mz, mut sf, mut sm) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for (k, q) in s.traction.iter().enumerate() {
        let (dx, dy) = (g.x[k] - c.0, g.y[k] - c.1);
        rx += area * q.0;
        ry += area * q.1;
        mz += area * (dx * q.1 - dy * q.0);
        sf += area * q.0.hypot(q.1);
        sm += area * dx.hypot(dy) * q.0.hypot(q.1);
    }
    let (tx, ty) = load.force_components();
    let mw = load.moment_value();
    let n = g.len() as f64;
    let ferr = (rx - tx).hypot(ry - ty);
    let fbound = tol::RESIDUAL * tx.hypot(ty).max(mw.map_or(0.0, |m| m.abs()) / g.hx)
        + n * tol::SUM_EPS * sf;
    if ferr > fbound {
        return Err(format!("resultant force off by {ferr:.3e} (bound {fbound:.3e})"));
    }
    if let Some(mw) = mw {
        let merr = (mz - mw).abs();
        let mbound = tol::RESIDUAL * (mw.abs() + tx.hypot(ty) * g.hx) + n * tol::SUM_EPS * sm;
        if merr > mbound {
            return Err(format!("resultant moment off by {merr:.3e} (bound {mbound:.3e})"));
        }
    }
    let line = format!(
        "{} Newton, {} CG, residual {:.1e}, admissibility {:+.1e} f p, {:.2} s",
        s.info.iterations,
        s.info.cg_iterations,
        s.info.residual,
        worst / (F * g.pressure.iter().copied().fold(0.0, f64::max)),
        secs
    );
    Ok((s, line))
}

/// Check an error against its bound, naming it.
fn within(what: &str, err: f64, bound: f64) -> Result<(), String> {
    if err <= bound {
        Ok(())
    } else {
        Err(format!("{what} error {err:.3e} above {bound:.3e}"))
    }
}

/// A force alone at `ratio` of f P: admissibility and equilibrium, and Mindlin's solution
/// when it is exact for the problem posed (`exact`).
fn force_case(n: usize, nu: f64, ratio: f64, dirs: TractionDirections, exact: bool) -> Outcome {
    let m = body(nu);
    let (g, a) = circle(n, &m);
    let t = ratio * F * g.total_normal_force();
    let (s, line) = solve_checked(&g, m, Load::polar(t, 0.0).unwrap(), dirs)?;
    let mi = Mindlin::new(a, P, F, t).map_err(|e| e.to_string())?;
    let (h, q0) = (g.hx, 3.0 * F * P / (2.0 * PI * a * a));
    let stick = (stick_radius(&g, &s) - mi.stick_radius()) / h;
    let shift = s.shift.0 / mi.compliance_relative(&m, &m) - 1.0;
    let (mut emax, mut e2) = (0.0f64, 0.0);
    for (k, q) in s.traction.iter().enumerate() {
        let e = (q.0 - mi.traction(g.x[k].hypot(g.y[k]))).hypot(q.1) / q0;
        emax = emax.max(e);
        e2 += e * e;
    }
    let erms = (e2 / g.len() as f64).sqrt();
    let summary = format!(
        "{line}; vs Mindlin: stick radius {stick:+.2} cells, shift {shift:+.1e}, traction rms {erms:.1e} max {emax:.1e}"
    );
    if exact {
        let ha = h / a;
        within("stick radius (cells)", stick.abs(), tol::STICK_CELLS)?;
        within("Mindlin shift", shift.abs(), tol::RIGID * ha.powf(1.5))?;
        within("traction rms", erms, tol::TRACTION_RMS * ha)?;
        within("traction max", emax, tol::TRACTION_MAX * ha.sqrt())?;
        Ok(summary)
    } else {
        Ok(format!("{summary} (not exact at nu = {nu}: printed only)"))
    }
}

/// A moment alone at `ratio` of the grid's full-slip moment against Lubkin at the same
/// fraction of his.
fn moment_case(n: usize, ratio: f64) -> Outcome {
    let m = body(0.3);
    let (g, a) = circle(n, &m);
    let cap = g.spin_capacity(F);
    let load = Load::moment(ratio * cap, None).unwrap();
    let (s, line) = solve_checked(&g, m, load, TractionDirections::Free)?;
    let l = Lubkin::from_moment(a, P, F, ratio * Lubkin::gross_slip_moment_of(a, P, F))
        .map_err(|e| e.to_string())?;
    let (h, q0) = (g.hx, 3.0 * F * P / (2.0 * PI * a * a));
    let stick = (stick_radius(&g, &s) - l.stick_radius()) / h;
    let rot = s.rotation / l.rotation_relative(&m, &m) - 1.0;
    let (mut emax, mut e2) = (0.0f64, 0.0);
    for (k, q) in s.traction.iter().enumerate() {
        let (x, y) = (g.x[k] - s.centre.0, g.y[k] - s.centre.1);
        let r = x.hypot(y);
        let (tau, rad) = ((x * q.1 - y * q.0) / r, (x * q.0 + y * q.1) / r);
        let want = l.traction(r).map_err(|e| e.to_string())?;
        let e = (tau - want).hypot(rad) / q0;
        emax = emax.max(e);
        e2 += e * e;
    }
    let erms = (e2 / g.len() as f64).sqrt();
    let ha = h / a;
    within("stick radius (cells)", stick.abs(), tol::STICK_CELLS)?;
    within("Lubkin rotation", rot.abs(), tol::RIGID * ha.powf(1.5))?;
    within("traction rms", erms, tol::TRACTION_RMS * ha)?;
    within("traction max", emax, tol::TRACTION_MAX * ha.sqrt())?;
    Ok(format!(
        "{line}; vs Lubkin: stick radius {stick:+.2} cells, rotation {rot:+.1e}, traction rms {erms:.1e} max {emax:.1e}"
    ))
}

/// A force along x and a moment, their mix `mix` of the two pure capacities, scaled to
/// `s` of the limit surface.
fn combined_case(n: usize, mix: f64, s: f64) -> Outcome {
    let m = body(0.3);
    let (g, _) = circle(n, &m);
    let (t, mo) = ((1.0 - mix) * F * g.total_normal_force(), mix * g.spin_capacity(F));
    let lam = g.load_capacity_factor(F, (t, 0.0), mo);
    let load = Load::polar(s * lam * t, 0.0).unwrap().with_moment(s * lam * mo, None).unwrap();
    let (sol, line) = solve_checked(&g, m, load, TractionDirections::Free)?;
    Ok(format!("{line}; limit factor {lam:.4}, {} stick cells", sol.stick_count()))
}

/// Run cases, print one line each, fail listing every failure.
fn run(cases: Vec<(String, Box<dyn Fn() -> Outcome>)>) {
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
    let mut cases: Vec<(String, Box<dyn Fn() -> Outcome>)> = Vec::new();
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
    let mut cases: Vec<(String, Box<dyn Fn() -> Outcome>)> = Vec::new();
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
    let mut cases: Vec<(String, Box<dyn Fn() -> Outcome>)> = Vec::new();
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
    let mut cases: Vec<(String, Box<dyn Fn() -> Outcome>)> = Vec::new();
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
            // The planner's checks (crates/scene/src/plan/checks.rs): the full-slip moment
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
