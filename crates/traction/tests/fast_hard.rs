//! Hard cases of issue 6, each checked by its optimality conditions (friction disc,
//! zero slip on stick, slip parallel to traction on slip, load balance) and, where one exists,
//! against a closed form: T/(fP) = 0.999 and 1e-6 (Mindlin), a ring-shaped contact, two
//! patches with a 10:1 pressure ratio, the twist at c/a = 0.1 (Lubkin), gross slip and loads
//! beyond it.

mod fast_common;
use fast_common::{steel, tol};
use std::f64::consts::PI;
use stickslip_lattice::TensorConvolution;
use stickslip_lattice::{ContactGrid, GridPatch, PatchPressure, Shape};
use stickslip_traction::{closed::Lubkin, closed::Mindlin};
use stickslip_traction::{
    ElementState, Error, FastProblem, FastSolution, Load, LoadKind, Regime, Tolerance,
    TractionDirections,
};

/// Worst violation of the optimality conditions, each relative to its natural scale
/// (tractions to max f p, displacements to max |u|, forces to |T| or f P, moments to M).
/// The displacement is recomputed here with a freshly planned operator.
fn optimality(
    grid: &ContactGrid,
    f: f64,
    sol: &FastSolution,
    load: (f64, f64),
    moment: Option<f64>,
) -> f64 {
    let s = steel();
    let c = stickslip_lattice::influence::Compliance::pair(&s, &s);
    let op = TensorConvolution::new(grid, &c, Default::default()).unwrap();
    let n = grid.len();
    let qx: Vec<f64> = sol.traction.iter().map(|q| q.0).collect();
    let qy: Vec<f64> = sol.traction.iter().map(|q| q.1).collect();
    let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
    op.apply(&qx, &qy, &mut ux, &mut uy, &mut op.make_scratch());
    let cap: Vec<f64> = grid.pressure.iter().map(|p| f * p).collect();
    let cmax = cap.iter().copied().fold(0.0, f64::max);
    let umax = ux.iter().chain(&uy).map(|v| v.abs()).fold(0.0, f64::max);
    let (mut cone, mut stick, mut slip_mag, mut slip_dir) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for k in 0..n {
        let (dx, dy) = (grid.x[k] - sol.centre.0, grid.y[k] - sol.centre.1);
        let w = (sol.shift.0 - sol.rotation * dy, sol.shift.1 + sol.rotation * dx);
        let sv = (w.0 - ux[k], w.1 - uy[k]);
        let q = sol.traction[k];
        let qn = q.0.hypot(q.1);
        cone = cone.max((qn - cap[k]).max(0.0) / cmax);
        match sol.state[k] {
            ElementState::Stick => stick = stick.max(sv.0.hypot(sv.1) / umax),
            ElementState::Slip => {
                slip_mag = slip_mag.max((qn - cap[k]).abs() / cmax);
                if cap[k] > 0.0 {
                    // Slip parallel to and along the traction.
                    let cross = (q.0 * sv.1 - q.1 * sv.0).abs() / cap[k];
                    let along = (q.0 * sv.0 + q.1 * sv.1) / cap[k];
                    slip_dir = slip_dir.max(cross / umax).max((-along).max(0.0) / umax);
                }
            }
        }
    }
    let area = grid.element_area();
    let fcap: f64 = cap.iter().sum::<f64>() * area;
    let (rx, ry) = sol.resultant;
    let fscale = load.0.hypot(load.1).max(1e-300);
    let eq = (rx - load.0).hypot(ry - load.1) / fscale.max(1e-3 * fcap);
    let meq = moment.map_or(0.0, |m| (sol.moment - m).abs() / m.abs());
    println!(
        "    optimality: cone {cone:.1e}, stick slip {stick:.1e}, slip |q|-fp {slip_mag:.1e}, \
         slip direction {slip_dir:.1e}, force balance {eq:.1e}, moment balance {meq:.1e}"
    );
    [cone, stick, slip_mag, slip_dir, eq, meq].into_iter().fold(0.0, f64::max)
}

fn hertz(a_cells: usize) -> (ContactGrid, f64, f64, f64) {
    let (p, f, a) = (2160.0, 0.1, 0.046148);
    (ContactGrid::hertz_circle(a, p, 2 * a_cells).unwrap(), p, f, a)
}

fn summary(name: &str, sol: &FastSolution) {
    println!(
        "{name}: N = {}, {:?}, stick {}, {} Newton, {} CG, residual {:.2e}, {:.3} s",
        sol.traction.len(),
        sol.regime,
        sol.stick_count(),
        sol.info.iterations,
        sol.info.cg_iterations,
        sol.info.residual,
        sol.info.solve_seconds + sol.info.setup_seconds
    );
}

/// T/(fP) = 0.999 (stick radius a/10) and 1e-6 (slip annulus far thinner than a cell) on the
/// a = 100 cells grid. Mindlin's solution keeps the traction parallel to the load; it is the
/// exact answer of the one-direction problem (the LP's), which is held to one cell of the
/// stick radius and 0.5 % of the shift. With both components free the stick zone differs
/// from Mindlin's by the Poisson coupling; that difference is printed and only bounded
/// loosely (below 2 cells and 0.5 % in shift) as a regression guard.
#[test]
fn near_gross_slip_and_tiny_load() {
    let (grid, p, f, a) = hertz(100);
    let s = steel();
    let h = grid.hx;
    for t in [0.999, 1e-6] {
        let m = Mindlin::new(a, p, f, t * f * p).unwrap();
        for dirs in [TractionDirections::ParallelToForce, TractionDirections::Free] {
            let load = Load::polar(t * f * p, 0.0).unwrap();
            let sol = FastProblem::new(&grid, [s, s], f, load)
                .unwrap()
                .with_directions(dirs.clone())
                .unwrap()
                .solve()
                .unwrap();
            summary(&format!("T/fP = {t}, {dirs:?}"), &sol);
            let r_eq = (sol.stick_count() as f64 * h * h / PI).sqrt();
            let shift_rel = sol.shift.0 / m.compliance_relative(&s, &s) - 1.0;
            let dr = (r_eq - m.stick_radius()) / h;
            let (mut ex, mut ey) = (0.0f64, 0.0f64);
            for k in 0..grid.len() {
                if sol.state[k] == ElementState::Stick {
                    ex = ex.max(grid.x[k].abs() + 0.5 * h);
                    ey = ey.max(grid.y[k].abs() + 0.5 * h);
                }
            }
            println!(
                "    stick zone half-extents: {:.1} cells along T, {:.1} across",
                ex / h,
                ey / h
            );
            println!(
                "    stick radius {:.3} cells vs Mindlin {:.3} ({dr:+.3} cells); shift {:.6e} vs \
                 Mindlin {:.6e} ({:+.3} %)",
                r_eq / h,
                m.stick_radius() / h,
                sol.shift.0,
                m.compliance_relative(&s, &s),
                100.0 * shift_rel
            );
            assert!(sol.info.residual <= tol::RESIDUAL);
            assert!(shift_rel.abs() <= tol::SHIFT_MINDLIN, "{shift_rel}");
            if dirs == TractionDirections::Free {
                assert!(optimality(&grid, f, &sol, (t * f * p, 0.0), None) <= tol::OPTIMALITY);
                assert!(dr.abs() <= 2.0, "free-direction stick radius {dr} cells from Mindlin");
            } else {
                assert!(dr.abs() <= 1.0, "one-direction stick radius {dr} cells from Mindlin");
            }
        }
    }
}

#[test]
fn ring_contact() {
    // Annulus 60 < r/h < 100 with a parabolic pressure across the ring width.
    let (n, h) = (200usize, 1e-3);
    let (ri, ro) = (60.0 * h, 100.0 * h);
    let mut mask = vec![false; n * n];
    let mut pr = vec![0.0; n * n];
    for j in 0..n {
        for i in 0..n {
            let x = (i as f64 + 0.5 - 100.0) * h;
            let y = (j as f64 + 0.5 - 100.0) * h;
            let r = x.hypot(y);
            if r > ri && r < ro {
                mask[j * n + i] = true;
                pr[j * n + i] = 1e8 * ((r - ri) * (ro - r)).sqrt() / (0.5 * (ro - ri));
            }
        }
    }
    let grid = ContactGrid::from_mask(h, h, (-0.1, -0.1), n, n, &mask, &pr).unwrap();
    let s = steel();
    let f = 0.3;
    let fp = f * grid.total_normal_force();
    for (t, ang) in [(0.5 * fp, 0.3), (0.95 * fp, 0.0)] {
        let load = Load::polar(t, ang).unwrap();
        let sol = FastProblem::new(&grid, [s, s], f, load).unwrap().solve().unwrap();
        summary(&format!("ring, T/fP = {:.2}", t / fp), &sol);
        assert!(sol.info.residual <= tol::RESIDUAL);
        assert!(
            optimality(&grid, f, &sol, (t * ang.cos(), t * ang.sin()), None) <= tol::OPTIMALITY
        );
    }
}

#[test]
fn two_patches_ten_to_one() {
    let sq = |cx: f64, p: f64| GridPatch {
        shape: Shape::Rectangle { cx, cy: 0.0, wx: 0.06, wy: 0.06 },
        pressure: PatchPressure::Uniform(p),
    };
    let h = 1e-3;
    let grid =
        ContactGrid::from_patches(h, h, (-0.1, -0.05), &[sq(-0.05, 1e9), sq(0.05, 1e8)]).unwrap();
    let s = steel();
    let f = 0.2;
    let fp = f * grid.total_normal_force();
    for (frac, ang) in [(0.3, 0.0), (0.8, 1.2)] {
        let t = frac * fp;
        let load = Load::polar(t, ang).unwrap();
        let sol = FastProblem::new(&grid, [s, s], f, load).unwrap().solve().unwrap();
        summary(&format!("two patches 10:1, T/fP = {frac}"), &sol);
        let (mut f0, mut f1) = ((0.0, 0.0), (0.0, 0.0));
        let mut slip = [0usize; 2];
        for k in 0..grid.len() {
            let q = sol.traction[k];
            let acc = if grid.patch[k] == 0 { &mut f0 } else { &mut f1 };
            acc.0 += q.0 * h * h;
            acc.1 += q.1 * h * h;
            if sol.state[k] == ElementState::Slip {
                slip[grid.patch[k]] += 1;
            }
        }
        println!(
            "    patch forces |F0| = {:.4e}, |F1| = {:.4e} (capacities {:.4e}, {:.4e}); slipping {slip:?}",
            f0.0.hypot(f0.1),
            f1.0.hypot(f1.1),
            f * 1e9 * 0.06 * 0.06,
            f * 1e8 * 0.06 * 0.06
        );
        assert!(sol.info.residual <= tol::RESIDUAL);
        assert!(
            optimality(&grid, f, &sol, (t * ang.cos(), t * ang.sin()), None) <= tol::OPTIMALITY
        );
    }
}

/// Lubkin (FORMULAS.md G) at c/a = 0.1: the moment M(c), then the fast solver's stick zone
/// and rotation against c and the relative rotation.
#[test]
fn twist_lubkin_c_over_a_0_1() {
    let (grid, p, f, a) = hertz(100);
    let s = steel();
    let h = grid.hx;
    let lub = Lubkin::from_stick_radius(a, p, f, 0.1 * a).unwrap();
    let m = lub.moment().unwrap();
    let load = Load::moment(m, None).unwrap();
    let sol = FastProblem::new(&grid, [s, s], f, load).unwrap().solve().unwrap();
    summary("twist c/a = 0.1", &sol);
    let r_eq = (sol.stick_count() as f64 * h * h / PI).sqrt();
    let omega = lub.rotation_relative(&s, &s);
    let rot_rel = sol.rotation / omega - 1.0;
    println!(
        "    M = {m:.6e} ({:.4} of the spin capacity); stick radius {:.3} cells vs Lubkin c = {:.3}; \
         rotation {:.6e} vs Lubkin {:.6e} ({:+.3} %); shift ({:.1e}, {:.1e})",
        m / lub.gross_slip_moment(),
        r_eq / h,
        0.1 * a / h,
        sol.rotation,
        omega,
        100.0 * rot_rel,
        sol.shift.0,
        sol.shift.1
    );
    assert!(sol.info.residual <= tol::RESIDUAL);
    assert!(optimality(&grid, f, &sol, (0.0, 0.0), Some(m)) <= tol::OPTIMALITY);
    assert!((r_eq - 0.1 * a).abs() <= h, "stick radius {r_eq} vs {}", 0.1 * a);
    assert!(rot_rel.abs() <= tol::TWIST, "{rot_rel}");
}

#[test]
fn gross_slip_zero_load_and_errors() {
    let (grid, p, f, _) = hertz(10);
    let s = steel();
    // Exactly at the capacity: gross slip, every element at f p along the force.
    let sol = FastProblem::new(&grid, [s, s], f, Load::polar(f * p, 0.5).unwrap())
        .unwrap()
        .solve()
        .unwrap();
    summary("T = fP", &sol);
    assert_eq!(sol.regime, Regime::GrossSlip);
    assert!((sol.resultant.0.hypot(sol.resultant.1) / (f * p) - 1.0).abs() < 1e-13);
    // Zero load: zero traction, full stick.
    let sol = FastProblem::new(&grid, [s, s], f, Load::force(0.0, 0.0).unwrap())
        .unwrap()
        .solve()
        .unwrap();
    assert_eq!(sol.regime, Regime::FullStick);
    assert!(sol.traction.iter().all(|q| q.0 == 0.0 && q.1 == 0.0));
    // Beyond the capacity: a typed error carrying the load and the capacity.
    let e = FastProblem::new(&grid, [s, s], f, Load::polar(1.01 * f * p, 0.0).unwrap())
        .unwrap()
        .solve()
        .unwrap_err();
    println!("T = 1.01 fP: {e}");
    assert!(matches!(
        e,
        Error::CapacityExceeded { load: LoadKind::Force, requested, capacity }
            if (requested / capacity - 1.01).abs() < 1e-9
    ));
    // A moment beyond the spin capacity.
    let e = FastProblem::new(&grid, [s, s], f, Load::moment(1e6, None).unwrap())
        .unwrap()
        .solve()
        .unwrap_err();
    println!("M beyond the spin capacity: {e}");
    assert!(matches!(
        e,
        Error::CapacityExceeded { load: LoadKind::Moment, requested, capacity }
            if requested == 1e6 && capacity < requested
    ));
    // Bad inputs.
    assert!(Load::force(f64::NAN, 0.0).is_err());
    assert!(Load::polar(-1.0, 0.0).is_err());
    assert!(FastProblem::new(&grid, [s, s], 0.0, Load::force(1.0, 0.0).unwrap()).is_err());
    let rel = |r: f64| Tolerance::relative(r).unwrap();
    assert!(matches!(
        stickslip_traction::FastConfig::new(rel(1e-15), 10),
        Err(Error::ToleranceOutOfRange { range: (1e-14, 1e-1), .. })
    ));
    assert!(stickslip_traction::FastConfig::new(rel(1e-8), 0).is_err());
    // An iteration budget that is too small: the error carries the residual reached.
    let cfg = stickslip_traction::FastConfig::new(rel(1e-12), 1).unwrap();
    let e = FastProblem::new(&grid, [s, s], f, Load::polar(0.5 * f * p, 0.0).unwrap())
        .unwrap()
        .with_config(cfg)
        .solve()
        .unwrap_err();
    println!("one Newton step: {e}");
    assert!(matches!(
        e,
        Error::NotConverged { iterations: 1, residual, tolerance, .. }
            if residual > tolerance && tolerance == 1e-12
    ));
}
