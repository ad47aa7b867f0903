//! The modified LP: optimality conditions, an independent MILP cross-check (microlp),
//! Example 5 of seed 002, the twist preprocessor against Lubkin, and timings.

mod common;
use common::{extended, hertz_radius, steel, tol};
use microlp::{ComparisonOp, OptimizationDirection, Problem, SolveOutcome};
use std::time::Instant;
use stickslip_lattice::influence::projected_matrix;
use stickslip_lattice::{ContactGrid, GridPatch, InfluenceModel, PatchPressure, Shape};
use stickslip_traction::closed::Lubkin;
use stickslip_traction::{lp::modified_lp, lp::modified_lp_reference, lp::LpConfig};
use stickslip_traction::{ElementState, Load, Regime, TractionProblem, TractionSolution};

/// Optimality: 0 <= F <= fP, equality on slip elements, u = beta g on stick elements,
/// u <= beta g on slip elements, g.F = load. Returns the worst relative residual.
fn check_optimality(grid: &ContactGrid, f: f64, load: f64, s: &TractionSolution) -> f64 {
    let cap: Vec<f64> = grid.normal_force().iter().map(|p| f * p).collect();
    let cmax = cap.iter().copied().fold(0.0, f64::max);
    let umax = s.displacement.iter().map(|u| u.abs()).fold(0.0, f64::max);
    let mut worst: f64 = 0.0;
    for (k, &ck) in cap.iter().enumerate() {
        let fk = s.force[k];
        worst = worst.max((-fk).max(0.0) / cmax).max((fk - ck).max(0.0) / cmax);
        let gap = s.rigid.abs() * s.mode[k] - s.displacement[k];
        worst = worst.max((-gap).max(0.0) / umax);
        match s.state[k] {
            ElementState::Stick => worst = worst.max(gap.abs() / umax),
            ElementState::Slip => worst = worst.max((ck - fk).abs() / cmax),
        }
    }
    let total: f64 = s.force.iter().zip(&s.mode).map(|(a, b)| a * b).sum();
    worst.max((total - load).abs() / load)
}

/// The same complementarity problem as a mixed-integer LP for microlp (an independent
/// simplex with branch and bound): z_k = 1 marks slip (F_k = c_k), z_k = 0 forces Y1_k = 0.
fn microlp_solve(a: &[f64], cap: &[f64], load: f64) -> (Vec<f64>, f64) {
    let n = cap.len();
    let fs = cap.iter().copied().fold(0.0, f64::max);
    let asc = (0..n).map(|k| a[k * n + k]).fold(0.0, f64::max);
    // Scaled: A~ = A/asc, F~ = F/fs; slip bound: beta~ <= max_k (A~ c~)_k.
    let big: f64 = (0..n)
        .map(|k| (0..n).map(|j| a[k * n + j] / asc * cap[j] / fs).sum::<f64>())
        .fold(0.0, f64::max)
        * 1.01;
    let mut p = Problem::new(OptimizationDirection::Minimize);
    let fv: Vec<_> = cap.iter().map(|c| p.add_var(0.0, (0.0, c / fs))).collect();
    let y1: Vec<_> = (0..n).map(|_| p.add_var(0.0, (0.0, big))).collect();
    let z: Vec<_> = (0..n).map(|_| p.add_binary_var(1.0)).collect();
    let beta = p.add_var(0.0, (0.0, big));
    for k in 0..n {
        let mut row: Vec<_> = (0..n).map(|j| (fv[j], a[k * n + j] / asc)).collect();
        row.push((y1[k], 1.0));
        row.push((beta, -1.0));
        p.add_constraint(row, ComparisonOp::Eq, 0.0);
        p.add_constraint([(y1[k], 1.0), (z[k], -big)], ComparisonOp::Le, 0.0);
        p.add_constraint([(fv[k], 1.0), (z[k], -cap[k] / fs)], ComparisonOp::Ge, 0.0);
    }
    p.add_constraint(fv.iter().map(|&v| (v, 1.0)).collect::<Vec<_>>(), ComparisonOp::Eq, load / fs);
    let sol = match p.solve().expect("microlp") {
        SolveOutcome::Solution(s) => s,
        SolveOutcome::Interrupted(_) => panic!("microlp interrupted"),
    };
    let f: Vec<f64> = fv.iter().map(|&v| sol.var_value(v) * fs).collect();
    (f, sol.var_value(beta) * asc * fs)
}

#[test]
fn cross_check_against_microlp() {
    let s = steel();
    let c = stickslip_halfspace::rectangle::Compliance::pair(&s, &s);
    let cases: Vec<(&str, ContactGrid, f64)> = vec![
        ("Hertz circle 6 across", ContactGrid::hertz_circle(0.05, 1000.0, 6).unwrap(), 0.6),
        ("square 6x6 uniform", ContactGrid::uniform_square(1.0, 1e4, 6).unwrap(), 0.8),
        ("ellipse 12x6", ContactGrid::hertz_ellipse(0.1, 0.05, 800.0, 12, 6).unwrap(), 0.4),
    ];
    for (name, grid, ratio) in cases {
        let n = grid.len();
        let f = 0.2;
        let cap: Vec<f64> = grid.normal_force().iter().map(|p| f * p).collect();
        let load = ratio * cap.iter().sum::<f64>();
        let a = projected_matrix(&grid, &c, InfluenceModel::ExactRectangle, &vec![(1.0, 0.0); n]);
        let ours = modified_lp(&a, &vec![1.0; n], &cap, load, &LpConfig::default()).unwrap();
        let t0 = Instant::now();
        let (fm, bm) = microlp_solve(&a, &cap, load);
        let fmax = cap.iter().copied().fold(0.0, f64::max);
        let df = ours.force.iter().zip(&fm).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max) / fmax;
        let db = (ours.rigid - bm).abs() / bm;
        println!(
            "{name}: N = {n}, max |F - F_microlp| / max fP = {df:.3e}, rigid rel diff {db:.3e}, \
             pivots {}, degenerate {}, microlp {:.2} s",
            ours.iterations,
            ours.degenerate_pivots,
            t0.elapsed().as_secs_f64()
        );
        assert!(df < tol::CROSS_CHECK && db < tol::CROSS_CHECK, "{name}: {df} {db}");
    }
}

#[test]
fn optimality_conditions_and_regimes() {
    let s = steel();
    let grid = ContactGrid::hertz_ellipse(0.08, 0.04, 500.0, 16, 8).unwrap();
    let f = 0.15;
    let cap_total = f * grid.total_normal_force();
    for (ratio, angle) in [(0.05, 0.0), (0.5, 0.7), (0.95, 2.0), (1.0 - 1e-9, -1.0)] {
        let load = ratio * cap_total;
        let sol = TractionProblem::new(&grid, [s, s], f, Load::Force { magnitude: load, angle })
            .unwrap()
            .solve()
            .unwrap();
        let r = check_optimality(&grid, f, load, &sol);
        let res = sol.resultant.0.hypot(sol.resultant.1);
        println!(
            "ellipse N = {}, T/fP = {ratio}, angle {angle}: worst residual {r:.2e}, \
             |R| - T = {:.2e}, pivots {}, degenerate pivots {}, regime {:?}",
            grid.len(),
            res - load,
            sol.info.iterations,
            sol.info.degenerate_pivots,
            sol.regime
        );
        assert!(r < tol::LP_RESIDUAL, "{r}");
        assert!((res - load).abs() < tol::LP_RESIDUAL * load);
        assert!((sol.resultant.1.atan2(sol.resultant.0) - angle).abs() < 1e-12);
        // A small load may leave every element sticking on a coarse grid.
        let want = if ratio < 0.1 { Regime::FullStick } else { Regime::PartialSlip };
        assert_eq!(sol.regime, want);
        assert!(sol.rigid.is_finite() && sol.rigid > 0.0);
    }
    // At and beyond gross slip: a result, not a failure.
    for ratio in [1.0, 1.5] {
        let sol = TractionProblem::new(
            &grid,
            [s, stickslip_halfspace::Material::rigid()],
            f,
            Load::Force { magnitude: ratio * cap_total, angle: 0.3 },
        )
        .unwrap()
        .solve()
        .unwrap();
        assert_eq!(sol.regime, Regime::GrossSlip);
        assert!(sol.state.iter().all(|s| *s == ElementState::Slip));
        assert!(sol.rigid.is_finite() && sol.rigid_per_body[1] == 0.0);
        assert!((sol.excess_load - (ratio - 1.0) * cap_total).abs() < 1e-9 * cap_total);
    }
    // Tiny load: full stick is allowed.
    let sol = TractionProblem::new(&grid, [s, s], f, Load::Force { magnitude: 0.0, angle: 0.0 })
        .unwrap()
        .solve()
        .unwrap();
    assert_eq!(sol.regime, Regime::FullStick);
}

fn example5(pressure1: f64, load: f64) -> (ContactGrid, TractionSolution) {
    let sq = |cx: f64, p: f64| GridPatch {
        shape: Shape::Rectangle { cx, cy: 0.0, wx: 0.6, wy: 0.6 },
        pressure: PatchPressure::Uniform(p),
    };
    let grid =
        ContactGrid::from_patches(0.05, 0.05, (-0.8, -0.3), &[sq(-0.5, pressure1), sq(0.5, 1e4)])
            .unwrap();
    let s = steel();
    let sol = TractionProblem::new(
        &grid,
        [s, s],
        0.12,
        Load::Force { magnitude: load, angle: std::f64::consts::FRAC_PI_4 },
    )
    .unwrap()
    .solve()
    .unwrap();
    (grid, sol)
}

#[test]
fn example5_two_squares() {
    // Case 1: equal pressures: resultant through the centroid (by symmetry).
    let (_, s1) = example5(1e4, 800.0);
    println!("Ex5 case 1: centre of traction {:?}", s1.centre_of_traction);
    assert!(s1.centre_of_traction.0.abs() < 1e-9 && s1.centre_of_traction.1.abs() < 1e-9);
    // Case 2/3 geometry: gross slip at f * total normal force = 1296 lbf.
    let (g, below) = example5(2e4, 1295.0);
    let (_, at) = example5(2e4, 1296.0);
    let total = 0.12 * g.total_normal_force();
    println!(
        "Ex5: f * total normal force = {total:.6} lbf; regime at 1295 {:?}, at 1296 {:?}",
        below.regime, at.regime
    );
    assert!((total - 1296.0).abs() < 1e-9);
    assert_eq!(below.regime, Regime::PartialSlip);
    assert_eq!(at.regime, Regime::GrossSlip);
    // Load at which region 2 (10,000 psi) is fully slipping, by bisection on T.
    let full2 = |t: f64| {
        let (_, s) = example5(2e4, t);
        s.patches[1].slipping == s.patches[1].elements
    };
    let (mut lo, mut hi) = (300.0, 1295.0);
    assert!(!full2(lo) && full2(hi));
    while hi - lo > 0.5 {
        let mid = 0.5 * (lo + hi);
        if full2(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let (_, s3) = example5(2e4, 800.0);
    println!(
        "Ex5: region 2 fully slips from T = {hi:.1} lbf (seed: 1000 lbf); at 800 lbf region 1 \
         slipping {} of {}, region loads {:.1} / {:.1} lbf, centre of traction {:?}",
        s3.patches[0].slipping,
        s3.patches[0].elements,
        s3.patches[0].force,
        s3.patches[1].force,
        s3.centre_of_traction
    );
    assert!(hi > 432.0 && hi < 1296.0);
}

#[test]
fn twist_against_lubkin() {
    let s = steel();
    let (p, mu) = (2160.0, 0.1);
    let a = hertz_radius(p, 1.0, &s, &s);
    let sizes: &[usize] = if extended() { &[24, 50] } else { &[24] };
    for &na in sizes {
        let grid = ContactGrid::hertz_circle(a, p, na).unwrap();
        let mmax = 3.0 * std::f64::consts::PI * mu * p * a / 16.0;
        let m = 0.6 * mmax;
        let t0 = Instant::now();
        let sol = TractionProblem::new(&grid, [s, s], mu, Load::Moment { moment: m, centre: None })
            .unwrap()
            .solve()
            .unwrap();
        let secs = t0.elapsed().as_secs_f64();
        // Lubkin's stick radius from the LP rotation, then M(c) against the applied M.
        let (mut lo, mut hi) = (1e-9 * a, a * (1.0 - 1e-12));
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            let w = Lubkin::from_stick_radius(a, p, mu, mid).unwrap().rotation_relative(&s, &s);
            if w > sol.rigid {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let l = Lubkin::from_stick_radius(a, p, mu, lo).unwrap();
        let rel_m = l.moment().unwrap() / m - 1.0;
        let exact = Lubkin::from_moment(a, p, mu, m).unwrap();
        let rel_w = sol.rigid / exact.rotation_relative(&s, &s) - 1.0;
        println!(
            "twist N = {}: omega_LP = {:.6e}, Lubkin {:.6e} (rel {rel_w:+.3e}); M(c(omega)) / M - 1 = \
             {rel_m:+.3e}; c/a Lubkin {:.4}; full-stick CG {:?}; {secs:.2} s",
            grid.len(),
            sol.rigid,
            exact.rotation_relative(&s, &s),
            exact.stick_radius() / a,
            sol.assumption
        );
        let moment: f64 = sol.force.iter().zip(&sol.mode).map(|(f, g)| f * g).sum();
        assert!((moment / m - 1.0).abs() < 1e-9);
        if grid.len() >= 1900 {
            assert!(rel_m.abs() < tol::TWIST, "{rel_m}");
        } else {
            assert!(rel_m.abs() < 3.0 * tol::TWIST, "{rel_m}");
        }
    }
}

#[test]
fn timings() {
    let s = steel();
    let sizes: &[usize] = if extended() { &[10, 20, 32] } else { &[10, 20] };
    for &n in sizes {
        let grid = ContactGrid::uniform_square(1.0, 1e4, n).unwrap();
        let load = 0.8 * 0.12 * grid.total_normal_force();
        let t0 = Instant::now();
        let sol =
            TractionProblem::new(&grid, [s, s], 0.12, Load::Force { magnitude: load, angle: 0.0 })
                .unwrap()
                .solve()
                .unwrap();
        let secs = t0.elapsed().as_secs_f64();
        let r = check_optimality(&grid, 0.12, load, &sol);
        println!(
            "timing: N = {}, total {secs:.3} s (assembly {:.3} s, LP {:.3} s), pivots {}, residual {r:.1e}",
            grid.len(),
            sol.info.assembly_seconds,
            sol.info.lp_seconds,
            sol.info.iterations
        );
        assert!(r < tol::LP_RESIDUAL);
    }
}

/// The condensed tableau must reproduce the plain full tableau pivot for pivot: same pivot
/// count, same refusals, and the same answer to the last bit (the arithmetic is the same).
#[test]
fn condensed_tableau_matches_full_tableau() {
    let s = steel();
    let c = stickslip_halfspace::rectangle::Compliance::pair(&s, &s);
    let cases: Vec<(&str, ContactGrid, f64)> = vec![
        (
            "Hertz circle 10 across",
            ContactGrid::hertz_circle(0.046148, 2160.0, 10).unwrap(),
            0.6667,
        ),
        ("square 10x10 uniform", ContactGrid::uniform_square(1.0, 1e4, 10).unwrap(), 0.8),
        ("ellipse 16x8", ContactGrid::hertz_ellipse(0.1, 0.05, 800.0, 16, 8).unwrap(), 0.95),
        ("Hertz circle 20 across", ContactGrid::hertz_circle(0.05, 1000.0, 20).unwrap(), 0.3),
    ];
    for (name, grid, ratio) in cases {
        let n = grid.len();
        let cap: Vec<f64> = grid.normal_force().iter().map(|p| 0.12 * p).collect();
        let load = ratio * cap.iter().sum::<f64>();
        let a = projected_matrix(&grid, &c, InfluenceModel::ExactRectangle, &vec![(1.0, 0.0); n]);
        let g = vec![1.0; n];
        let t0 = Instant::now();
        let fast = modified_lp(&a, &g, &cap, load, &LpConfig::default()).unwrap();
        let t_fast = t0.elapsed().as_secs_f64();
        let t0 = Instant::now();
        let plain = modified_lp_reference(&a, &g, &cap, load, &LpConfig::default()).unwrap();
        let t_plain = t0.elapsed().as_secs_f64();
        println!(
            "{name}: N = {n}, pivots {} / {}, refused {} / {}, condensed {t_fast:.4} s, full {t_plain:.4} s",
            fast.iterations, plain.iterations, fast.rejected_entries, plain.rejected_entries
        );
        assert_eq!(fast, plain, "{name}");
    }
}
