//! Seed 002's worked examples (inputs in VERIFICATION.md, FORMULAS.md E) solved by the
//! modified LP and compared with the closed forms.

mod common;
use common::{extended, hertz_radius, steel, tol};
use std::time::Instant;
use stickslip_traction::closed::Mindlin;
use stickslip_traction::{
    ContactGrid, ElementState, InfluenceModel, Load, Regime, TractionProblem,
};

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
        sol.info.assembly_time.as_secs_f64(),
        sol.info.lp_time.as_secs_f64()
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
