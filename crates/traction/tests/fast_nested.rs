//! Warm starts of the fast solver (issue 20): `FastProblem::solve` starts large lattices
//! from the 2 x 2 coarsened lattice's solution, and `FastProblem::solve_from` takes a start
//! from the caller (a neighbouring load on a load path). The problem is strictly convex, so
//! its discrete solution is unique: a warm start must reach the same tractions as the cold
//! start (`solve_with`), to the solver tolerance, and the same agreement with Mindlin's
//! closed form (FORMULAS.md E).

use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
use stickslip_traction::closed::Mindlin;
use stickslip_traction::{
    fast::FastConfig, fast::FastProblem, fast::WarmStart, fast::NEST_MIN_CELLS,
};
use stickslip_traction::{Error, Load, Tolerance};

const P: f64 = 2160.0;
const F: f64 = 0.1;

fn setup(n: usize) -> (ContactGrid, Material, f64) {
    let steel = Material::new(30e6, 0.3).unwrap();
    let a = (3.0 * P * (2.0 * steel.normal_compliance()) / 4.0).cbrt();
    (ContactGrid::hertz_circle(a, P, n).unwrap(), steel, a)
}

fn config() -> FastConfig {
    FastConfig::new(Tolerance::relative(1e-10).unwrap(), 100).unwrap()
}

/// Largest traction difference relative to the largest traction.
fn max_rel_diff(a: &[(f64, f64)], b: &[(f64, f64)]) -> f64 {
    let scale = a.iter().map(|q| q.0.hypot(q.1)).fold(0.0, f64::max);
    a.iter().zip(b).map(|(p, q)| (p.0 - q.0).hypot(p.1 - q.1)).fold(0.0, f64::max) / scale
}

#[test]
fn nested_start_reaches_the_cold_solution_and_mindlin() {
    // 2.5 x NEST_MIN_CELLS across: one coarse level (and the 120-across lattice two).
    for n in [5 * NEST_MIN_CELLS / 2, 5 * NEST_MIN_CELLS / 2 * 2] {
        let (grid, m, a) = setup(n);
        for ratio in [0.3, 0.9] {
            let load = Load::polar(ratio * F * P, 0.4).unwrap();
            let pr = FastProblem::new(&grid, [m, m], F, load).unwrap().with_config(config());
            let nested = pr.solve().unwrap();
            assert!(nested.info.levels >= 1, "n {n}: {:?}", nested.info);
            let op = pr.operator().unwrap();
            let cold = pr.solve_with(&op, &mut op.make_scratch()).unwrap();
            assert_eq!(cold.info.levels, 0);
            let d = max_rel_diff(&nested.traction, &cold.traction);
            assert!(d < 1e-7, "n {n} ratio {ratio}: nested vs cold traction {d:.2e}");
            // Mindlin's compliance: the shift along the load within 1 % on these lattices.
            let mindlin = Mindlin::new(a, P, F, ratio * F * P).unwrap();
            let along = nested.shift.0 * 0.4f64.cos() + nested.shift.1 * 0.4f64.sin();
            let err = along / mindlin.compliance_relative(&m, &m) - 1.0;
            assert!(err.abs() < 0.01, "n {n} ratio {ratio}: shift {err:+.4}");
            assert!(
                nested.info.iterations <= cold.info.iterations,
                "n {n} ratio {ratio}: nested {} Newton steps, cold {}",
                nested.info.iterations,
                cold.info.iterations
            );
        }
    }
}

#[test]
fn nested_start_with_a_moment_reaches_the_cold_solution() {
    let (grid, m, _) = setup(5 * NEST_MIN_CELLS / 2);
    let cap = grid.spin_capacity(F);
    let load = Load::polar(0.4 * F * P, 0.0).unwrap().with_moment(0.4 * cap, None).unwrap();
    let pr = FastProblem::new(&grid, [m, m], F, load).unwrap().with_config(config());
    let nested = pr.solve().unwrap();
    assert!(nested.info.levels >= 1);
    let op = pr.operator().unwrap();
    let cold = pr.solve_with(&op, &mut op.make_scratch()).unwrap();
    let d = max_rel_diff(&nested.traction, &cold.traction);
    assert!(d < 1e-7, "nested vs cold traction {d:.2e}");
    assert!((nested.rotation / cold.rotation - 1.0).abs() < 1e-7);
}

#[test]
fn load_path_warm_start_takes_fewer_steps_and_reaches_the_same_solution() {
    let (grid, m, _) = setup(64);
    let pr0 = FastProblem::new(&grid, [m, m], F, Load::polar(0.45 * F * P, 0.0).unwrap())
        .unwrap()
        .with_config(config());
    let op = pr0.operator().unwrap();
    let mut scratch = op.make_scratch();
    let prev = pr0.solve_with(&op, &mut scratch).unwrap();
    let pr1 = FastProblem::new(&grid, [m, m], F, Load::polar(0.5 * F * P, 0.0).unwrap())
        .unwrap()
        .with_config(config());
    let warm = pr1.solve_from(&op, &mut scratch, &WarmStart::from(&prev)).unwrap();
    let cold = pr1.solve_with(&op, &mut scratch).unwrap();
    let d = max_rel_diff(&warm.traction, &cold.traction);
    assert!(d < 1e-7, "warm vs cold traction {d:.2e}");
    assert!(warm.info.residual <= 1e-10 && warm.info.load_residual <= 1e-10);
    assert!(
        warm.info.iterations < cold.info.iterations,
        "warm {} Newton steps, cold {}",
        warm.info.iterations,
        cold.info.iterations
    );
    println!(
        "load step 0.45 -> 0.5 fP at 64 across: warm {} Newton / {} CG, cold {} / {}",
        warm.info.iterations,
        warm.info.cg_iterations,
        cold.info.iterations,
        cold.info.cg_iterations
    );
}

#[test]
fn warm_start_of_the_wrong_length_is_refused() {
    let (grid, m, _) = setup(16);
    let pr = FastProblem::new(&grid, [m, m], F, Load::polar(0.5 * F * P, 0.0).unwrap()).unwrap();
    let op = pr.operator().unwrap();
    let start = WarmStart {
        traction: vec![(0.0, 0.0); 3],
        shift: (0.0, 0.0),
        rotation: 0.0,
        state: vec![],
    };
    let e = pr.solve_from(&op, &mut op.make_scratch(), &start).unwrap_err();
    assert!(matches!(e, Error::LengthMismatch { .. }), "{e}");
}

#[test]
fn nested_start_carries_a_prescribed_displacement() {
    // Dundurs coupling enters as a prescribed displacement u0 = K_tn p, which points
    // radially for an axisymmetric pressure. With zero load it alone drives a
    // self-equilibrated traction; the nested start must coarsen u0 with the lattice and
    // reach the cold solution.
    let (grid, m, a) = setup(5 * NEST_MIN_CELLS / 2);
    let u0: Vec<(f64, f64)> = grid
        .x
        .iter()
        .zip(&grid.y)
        .map(|(&x, &y)| {
            let r2 = (x * x + y * y) / (a * a);
            let s = 2e-4 * a * (1.0 - r2).max(0.0).powf(1.5);
            (s * x / a, s * y / a)
        })
        .collect();
    for load in [Load::polar(0.0, 0.0).unwrap(), Load::polar(0.5 * F * P, 0.0).unwrap()] {
        let pr = FastProblem::new(&grid, [m, m], F, load)
            .unwrap()
            .with_config(config())
            .with_prescribed_displacement(&u0)
            .unwrap();
        let nested = pr.solve().unwrap();
        assert!(nested.info.levels >= 1, "{:?}", nested.info);
        let op = pr.operator().unwrap();
        let cold = pr.solve_with(&op, &mut op.make_scratch()).unwrap();
        let d = max_rel_diff(&nested.traction, &cold.traction);
        assert!(d < 1e-7, "nested vs cold traction {d:.2e}");
        // The traction is not trivial: u0 drives slip near the edge.
        let qmax = cold.traction.iter().map(|q| q.0.hypot(q.1)).fold(0.0, f64::max);
        assert!(qmax > 1e-3 * F * P / (a * a), "traction {qmax:e}");
    }
}
