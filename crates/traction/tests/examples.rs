//! Seed 002's worked examples (inputs in VERIFICATION.md, FORMULAS.md E) solved by the
//! modified LP and compared with the closed forms.

mod common;
use common::{extended, hertz_radius, steel, tol};
use std::f64::consts::PI;
use std::time::Instant;
use stickslip_halfspace::Material;
use stickslip_lattice::influence::projected_matrix;
use stickslip_lattice::{ContactGrid, InfluenceModel};
use stickslip_traction::{closed::Cattaneo, closed::Mindlin};
use stickslip_traction::{lp::modified_lp, lp::LpConfig};
use stickslip_traction::{ElementState, Load, Regime, TractionProblem};

fn example1(n_across: usize, model: InfluenceModel) -> (usize, f64, f64, f64, f64, f64) {
    let (p, t, f) = (2160.0, 144.0, 0.1);
    let s = steel();
    let a = hertz_radius(p, 1.0, &s, &s);
    let grid = ContactGrid::hertz_circle(a, p, n_across).unwrap();
    let t0 = Instant::now();
    let sol = TractionProblem::new(&grid, [s, s], f, Load::Force { magnitude: t, angle: 0.0 })
        .unwrap()
        .with_model(model)
        .solve()
        .unwrap();
    let secs = t0.elapsed().as_secs_f64();
    let m = Mindlin::new(a, p, f, t).unwrap();
    let want = m.compliance_per_body(&s);
    // Stick radius: the largest centre radius of a stick element, versus Mindlin's a*.
    let r_stick = (0..grid.len())
        .filter(|&k| sol.state[k] == ElementState::Stick)
        .map(|k| grid.x[k].hypot(grid.y[k]))
        .fold(0.0, f64::max);
    assert_eq!(sol.regime, Regime::PartialSlip);
    println!(
        "  pivots {}, degenerate {}, rejected entries {}, assembly {:.2} s, LP {:.2} s",
        sol.info.iterations,
        sol.info.degenerate_pivots,
        sol.info.rejected_entries,
        sol.info.assembly_seconds,
        sol.info.lp_seconds
    );
    (grid.len(), sol.rigid_per_body[0], want, r_stick, m.stick_radius(), secs)
}

#[test]
fn example1_80_elements() {
    for model in [InfluenceModel::PointLoad, InfluenceModel::ExactRectangle] {
        let (n, got, want, rs, astar, secs) = example1(10, model);
        let rel = got / want - 1.0;
        let h = 2.0 * 0.046148 / 10.0;
        println!(
            "Example 1 {model:?}: N = {n}, delta_LP = {got:.6e} in, Mindlin {want:.6e} in, \
             rel {rel:+.4e} (seed: -1.41 %); stick radius {rs:.5} vs a* {astar:.5} (h = {h:.5}); {secs:.3} s"
        );
        assert_eq!(n, 80);
        // Issue 5's 1.5 % target is for the exact influence coefficients; the seed's
        // point-load model is printed for comparison with its -1.41 %.
        if model == InfluenceModel::ExactRectangle {
            assert!(rel.abs() < tol::EX1_COARSE, "{rel}");
        } else {
            assert!(rel.abs() < 2.0 * tol::EX1_COARSE, "{rel}");
        }
        assert!((rs - astar).abs() <= h, "{rs} {astar}");
    }
}

#[test]
fn example1_fine_grid() {
    // 50 across gives 1976 elements; 36 across (1008 elements) always runs.
    let sizes: &[usize] = if extended() { &[36, 50] } else { &[36] };
    for &na in sizes {
        let (n, got, want, rs, astar, secs) = example1(na, InfluenceModel::ExactRectangle);
        let rel = got / want - 1.0;
        let h = 2.0 * 0.046148 / na as f64;
        println!(
            "Example 1 exact, N = {n}: delta = {got:.6e}, Mindlin {want:.6e}, rel {rel:+.4e}; \
             stick radius {rs:.5} vs {astar:.5} (h {h:.5}); {secs:.2} s"
        );
        assert!(rs.sub_abs(astar) <= h);
        if n >= 1900 {
            assert!(rel.abs() < tol::EX1_FINE, "{rel}");
        } else {
            assert!(rel.abs() < tol::EX1_COARSE, "{rel}");
        }
    }
}

trait SubAbs {
    fn sub_abs(self, o: f64) -> f64;
}
impl SubAbs for f64 {
    fn sub_abs(self, o: f64) -> f64 {
        (self - o).abs()
    }
}

/// Seed 002 Example 2: steel sphere (R = 1 in) on the "rubber" half-space of FORMULAS.md E
/// (E = 1.0e6 psi, nu = 0.3), P = 270 lbf, T = 36 lbf, f = 0.2, 80 elements.
///
/// T/fP = 2/3 and both bodies have nu = 0.3, exactly as in Example 1: after scaling by the
/// contact radius and the compliances this is the SAME discrete problem, so the LP's
/// per-body movements must (i) stand in the ratio G_steel/G_rubber = 30 and (ii) deviate
/// from Mindlin by the same fraction as Example 1 on the same lattice. The seed's 2.29 %
/// (Example 2) and 1.41 % (Example 1) therefore cannot both come from one discretisation.
#[test]
fn example2_steel_on_rubber() {
    let (p, t, f) = (270.0, 36.0, 0.2);
    let steel = steel();
    let rubber = Material::new(1.0e6, 0.3).unwrap();
    let a = hertz_radius(p, 1.0, &steel, &rubber);
    let grid = ContactGrid::hertz_circle(a, p, 10).unwrap();
    assert_eq!(grid.len(), 80);
    let m = Mindlin::new(a, p, f, t).unwrap();
    let (want_r, want_s) = (m.compliance_per_body(&rubber), m.compliance_per_body(&steel));
    println!(
        "Example 2: a = {a:.6} in, Mindlin per body rubber {want_r:.6e}, steel {want_s:.6e} in \
         (FORMULAS.md E: 0.403917e-3, 0.134639e-4)"
    );
    assert!((want_r / 0.403917e-3 - 1.0).abs() < tol::SIX_DIGITS);
    assert!((want_s / 0.134639e-4 - 1.0).abs() < tol::SIX_DIGITS);
    let (pub_r, pub_s) = (0.39469e-3, 0.13156e-4);
    for model in [InfluenceModel::ExactRectangle, InfluenceModel::PointLoad] {
        let sol = TractionProblem::new(
            &grid,
            [rubber, steel],
            f,
            Load::Force { magnitude: t, angle: 0.0 },
        )
        .unwrap()
        .with_model(model)
        .solve()
        .unwrap();
        let [dr, ds] = sol.rigid_per_body;
        let (rel_r, rel_s) = (dr / want_r - 1.0, ds / want_s - 1.0);
        let (ex1, _, _, _, _, _) = example1_rel(model);
        println!(
            "Example 2 {model:?}: rubber {dr:.5e} in (published {pub_r:.5e}, LP/published - 1 = \
             {:+.3e}), steel {ds:.5e} in (published {pub_s:.5e}, {:+.3e}); ratio {:.12}; vs \
             Mindlin {rel_r:+.4e} / {rel_s:+.4e} (seed: -2.29 %); Example 1 on the same lattice \
             {ex1:+.4e}",
            dr / pub_r - 1.0,
            ds / pub_s - 1.0,
            dr / ds
        );
        let g_ratio = steel.shear_modulus() / rubber.shear_modulus();
        assert!((dr / ds / g_ratio - 1.0).abs() < tol::IDENTITY, "{}", dr / ds);
        assert!((g_ratio - 30.0).abs() < 1e-12);
        assert!((rel_r - ex1).abs() < tol::IDENTITY && (rel_s - ex1).abs() < tol::IDENTITY);
        // Below Mindlin, and within issue 5's 1.5 % for the exact influence coefficients.
        assert!(rel_r < 0.0 && rel_s < 0.0);
        if model == InfluenceModel::ExactRectangle {
            assert!(rel_r.abs() < tol::EX1_COARSE, "{rel_r}");
        }
    }
}

/// Example 1's deviation from Mindlin (per body) with the given model, 10 across.
fn example1_rel(model: InfluenceModel) -> (f64, usize, f64, f64, f64, f64) {
    let (n, got, want, rs, astar, secs) = example1(10, model);
    (got / want - 1.0, n, want, rs, astar, secs)
}

/// Issue 5 item 3: the seed's point-load model at Example 1's 80 elements.
///
/// Investigation (seed 002 §3.3.2 gives the point-load coefficient for k != j; its k = j
/// formula is lost in the text, FORMULAS.md F). On the 10-across lattice (corner at the
/// centre, elements selected by their centres, h = a/5):
///
/// | self-term                   | pressure per element                  | Ex1 deviation |
/// |-----------------------------|---------------------------------------|---------------|
/// | exact square                | centre value, rescaled to sum to P    | -2.210 %      |
/// | exact square                | centre value of Hertz, not rescaled   | -2.360 %      |
/// | equal-area circle           | centre value of Hertz, not rescaled   | -2.285 %      |
/// | exact square                | element average, rescaled             | -1.503 %      |
/// | equal-area circle           | element average, rescaled             | -1.425 %      |
///
/// (element averages by a 200 x 200 midpoint rule over element ∩ circle; the equal-area
/// circle self-term is $(2-\nu)/(2\sqrt\pi G h)$, FORMULAS.md F). Letting h vary over the
/// range that still gives 80 elements (0.97 a/5 to 1.01 a/5) moves every row by up to
/// 0.8 points, and several arbitrary combinations land within 0.03 points of -1.41 %.
/// No single documented choice reproduces -1.41 %; it stays a recorded divergence. The
/// most literal reading of the seed (point loads, Hertz pressure at the element centres,
/// equal-area circle self-term) gives -2.285 %: Example 2's published -2.29 %, which is the
/// same normalised problem (see `example2_steel_on_rubber`). That row is asserted here.
#[test]
fn example1_point_load_discretisation() {
    let (p, t, f) = (2160.0, 144.0, 0.1);
    let s = steel();
    let a = hertz_radius(p, 1.0, &s, &s);
    let mut grid = ContactGrid::hertz_circle(a, p, 10).unwrap();
    let n = grid.len();
    let h = grid.hx;
    let p0 = 3.0 * p / (2.0 * PI * a * a);
    for k in 0..n {
        let r2 = (grid.x[k].powi(2) + grid.y[k].powi(2)) / (a * a);
        grid.pressure[k] = p0 * (1.0 - r2).sqrt();
    }
    let c = s.compliance();
    let nu = s.poisson_ratio();
    let self_circle = (2.0 - nu) / (2.0 * PI.sqrt() * s.shear_modulus() * h);
    let mut am = projected_matrix(&grid, &c, InfluenceModel::PointLoad, &vec![(1.0, 0.0); n]);
    for k in 0..n {
        am[k * n + k] = self_circle;
    }
    let cap: Vec<f64> = grid.normal_force().iter().map(|q| f * q).collect();
    let sol = modified_lp(&am, &vec![1.0; n], &cap, t, &LpConfig::default()).unwrap();
    let want = Mindlin::new(a, p, f, t).unwrap().compliance_per_body(&s);
    let rel = sol.rigid / want - 1.0;
    println!(
        "Example 1, point loads, centre pressures (sum {:.2} lbf), equal-area-circle self-term: \
         delta = {:.5e} in, rel {rel:+.4e} (seed Ex1 -1.41 %, seed Ex2 -2.29 %)",
        grid.total_normal_force(),
        sol.rigid
    );
    assert!((rel + 0.0229).abs() < tol::PUBLISHED_5_DIGITS_PERCENT, "{rel}");
}

/// Seed 002 Example 3 (Table 3.1): Hertz ellipses a/b = 2, 0.5, 8, 0.125, load along the
/// a-axis (x), with 112, 112, 116, 116 elements. The seed does not give its lattices, only
/// that the elements were rectangular; we take elements twice as long along the major axis
/// as across it (12 x 12 cells over the bounding box for a/b = 2 and 0.5; 24 x 6 and
/// 6 x 24 for a/b = 8 and 0.125), which gives exactly those counts. Steel on steel,
/// P = 2160 lbf, f = 0.1, T/fP = 2/3 as in Example 1, major semi-axis 0.1 in.
#[test]
fn example3_ellipses() {
    let s = steel();
    let (p, f) = (2160.0, 0.1);
    let t = 2.0 / 3.0 * f * p;
    let cases = [
        (2.0, 112usize, 12usize, 12usize),
        (0.5, 112, 12, 12),
        (8.0, 116, 24, 6),
        (0.125, 116, 6, 24),
    ];
    for (ratio, count, nx, ny) in cases {
        let (a, b) = if ratio >= 1.0 { (0.1, 0.1 / ratio) } else { (0.1 * ratio, 0.1) };
        let grid = ContactGrid::hertz_ellipse(a, b, p, nx, ny).unwrap();
        assert_eq!(grid.len(), count, "a/b = {ratio}");
        let sol = TractionProblem::new(&grid, [s, s], f, Load::Force { magnitude: t, angle: 0.0 })
            .unwrap()
            .solve()
            .unwrap();
        let cat = Cattaneo::new(a, b, p, f, t).unwrap();
        let want = cat.compliance_per_body(&s);
        let rel = sol.rigid_per_body[0] / want - 1.0;
        // Traction along the loaded axis: the two element rows next to y = 0, against
        // Cattaneo at the element centres, relative to f p0.
        let fp0 = f * cat.peak_pressure();
        let axis: Vec<usize> = (0..grid.len())
            .filter(|&k| (grid.y[k].abs() - 0.5 * grid.hy).abs() < 1e-9 * b)
            .collect();
        let errs: Vec<f64> = axis
            .iter()
            .map(|&k| (sol.traction[k] - cat.traction(grid.x[k], grid.y[k])) / fp0)
            .collect();
        let max = errs.iter().map(|e| e.abs()).fold(0.0, f64::max);
        let rms = (errs.iter().map(|e| e * e).sum::<f64>() / errs.len() as f64).sqrt();
        let worst = axis[errs
            .iter()
            .map(|e| e.abs())
            .enumerate()
            .max_by(|p, q| p.1.total_cmp(&q.1))
            .unwrap()
            .0];
        println!(
            "Example 3 a/b = {ratio}: N = {} ({nx} x {ny} cells, hx/hy = {:.3}), delta_LP = \
             {:.5e}, Cattaneo {want:.5e} (Lambda {:?} axis), rel {rel:+.4e}; traction on the \
             loaded axis ({} elements): max |q_LP - q_C| / f p0 = {max:.3e}, RMS {rms:.3e}, \
             worst at x/a = {:.3}",
            grid.len(),
            grid.hx / grid.hy,
            sol.rigid_per_body[0],
            cat.load_axis(),
            axis.len(),
            grid.x[worst] / a
        );
        assert_eq!(sol.regime, Regime::PartialSlip);
        assert!(rel.abs() < tol::EX3_COMPLIANCE, "a/b = {ratio}: {rel}");
        assert!(max < tol::EX3_TRACTION, "a/b = {ratio}: {max}");
    }
}

/// Seed 002 Example 4: 1 in square, uniform 10,000 psi, steel on steel, f = 0.12,
/// 10 x 10 elements. Slip starts at the corners and spreads inward as T grows (the slip
/// region at 800 lbf lies inside the one at 1000 lbf, Figs 3.12-3.14); the rigid-body
/// movement grows with T, ever faster, up to gross slip at f p A = 1200 lbf (Fig. 3.15).
#[test]
fn example4_uniform_square() {
    let s = steel();
    let grid = ContactGrid::uniform_square(1.0, 1e4, 10).unwrap();
    assert_eq!(grid.len(), 100);
    let f = 0.12;
    let gross = f * grid.total_normal_force();
    assert!((gross - 1200.0).abs() < 1e-9);
    let solve = |t: f64| {
        TractionProblem::new(&grid, [s, s], f, Load::Force { magnitude: t, angle: 0.0 })
            .unwrap()
            .solve()
            .unwrap()
    };
    let loads: Vec<f64> = (1..=12).map(|i| 100.0 * i as f64).collect();
    let sols: Vec<_> = loads.iter().map(|&t| solve(t)).collect();
    let mut prev_slip: Vec<bool> = vec![false; grid.len()];
    let mut prev = (0.0, 0.0);
    let mut prev_slope = 0.0;
    for (&t, sol) in loads.iter().zip(&sols) {
        let slip: Vec<bool> = sol.state.iter().map(|s| *s == ElementState::Slip).collect();
        let n_slip = slip.iter().filter(|&&v| v).count();
        let slope = (sol.rigid - prev.1) / (t - prev.0);
        println!(
            "Example 4: T = {t:6.1} lbf: {:?}, slipping {n_slip:3} of 100, rigid movement {:.5e} \
             in (relative), secant stiffness {:.4e} lbf/in",
            sol.regime,
            sol.rigid,
            1.0 / slope
        );
        // Nested slip regions, movement increasing, compliance increasing.
        assert!(slip.iter().zip(&prev_slip).all(|(now, before)| *now || !*before), "T = {t}");
        assert!(sol.rigid > prev.1 && slope >= prev_slope * (1.0 - 1e-12), "T = {t}");
        if t >= 1200.0 {
            assert_eq!(sol.regime, Regime::GrossSlip);
        } else if t >= 800.0 {
            assert_eq!(sol.regime, Regime::PartialSlip, "T = {t}");
        } else {
            // Small loads may leave all 100 elements sticking on this coarse grid.
            assert_ne!(sol.regime, Regime::GrossSlip, "T = {t}");
        }
        prev_slip = slip;
        prev = (t, sol.rigid);
        prev_slope = slope;
    }
    // Slip starts at the four corners: the first load with any slip has exactly them.
    let first = sols.iter().find(|s| s.regime == Regime::PartialSlip).unwrap();
    for k in 0..100 {
        let corner = grid.x[k].abs() > 0.4 && grid.y[k].abs() > 0.4;
        assert_eq!(first.state[k] == ElementState::Slip, corner, "element {k}");
    }
    for (t, sol) in [(800.0, &sols[7]), (1000.0, &sols[9])] {
        println!("Example 4: stick map at T = {t} lbf (o stick, x slip), traction in psi:");
        for j in (0..10).rev() {
            let row: String = (0..10)
                .map(|i| if sol.state[j * 10 + i] == ElementState::Stick { 'o' } else { 'x' })
                .collect();
            let q: Vec<String> =
                (0..10).map(|i| format!("{:5.0}", sol.traction[j * 10 + i])).collect();
            println!("  {row}  {}", q.join(" "));
        }
        // Slipping elements carry f p = 1200 psi; the traction is symmetric about both axes.
        for k in 0..100 {
            if sol.state[k] == ElementState::Slip {
                assert!((sol.traction[k] - 1200.0).abs() < 1e-9 * 1200.0);
            }
        }
    }
}
