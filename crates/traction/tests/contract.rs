//! The grid-solver contract (`stickslip_traction::contract`) tested by its optimality
//! conditions, not by stored answers: both solvers on the same Hertz grid (about 300
//! elements, seed 002's Example 1 proportions) must give Coulomb-admissible tractions in
//! equilibrium with the load, zero slip on the stick elements, and the same traction; and
//! each typed error must come back as its variant.

use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
use stickslip_traction::{
    ElementState, Error, FastSolver, GridProblem, GridSolution, GridSolver, Load, LoadKind,
    ModifiedLp, Tolerance, TractionDirections,
};

/// The stated tolerances of the checks below.
mod tol {
    /// Coulomb admissibility: $|\mathbf q_k| \le fp_k(1 + \text{COULOMB}) +
    /// \varepsilon\lVert\mathbf q\rVert_2$ with $\varepsilon$ the requested relative
    /// tolerance (rounding of the projection on the disc, and the fast solver's natural
    /// residual $\mathbf q_k - \Pi(\mathbf q_k + \rho\mathbf s_k)$, which lets a stick
    /// element's traction lie outside the disc by at most the residual).
    pub const COULOMB: f64 = 1e-12;
    /// Equilibrium: $|h_xh_y\sum_k\mathbf q_k - \mathbf T| \le$ EQUILIBRIUM $|\mathbf T|$ (the
    /// solvers' requested tolerance is $10^{-10}$).
    pub const EQUILIBRIUM: f64 = 1e-9;
    /// Stick elements: $|\mathbf s_k| \le$ STICK_SLIP $|\boldsymbol\delta|$, the slip
    /// relative to the rigid shift (the fast solver's natural residual $10^{-10}$ bounds
    /// $\rho|\mathbf s_k|$ relative to $\lVert\mathbf q\rVert$).
    pub const STICK_SLIP: f64 = 1e-7;
    /// LP against the fast solver under the LP's one-direction assumption: the same discrete
    /// equations, max traction difference relative to $fp_0$.
    pub const LP_VS_FAST_PARALLEL: f64 = 1e-6;
    /// LP against the fast solver with both components free: the effect of the
    /// one-direction assumption (a few per cent of $fp_0$ at $\nu = 0.3$).
    pub const LP_VS_FAST_FREE: f64 = 0.05;
}

const P: f64 = 2160.0;
const F: f64 = 0.1;
const A: f64 = 0.046148;

fn steel() -> Material {
    Material::new(30e6, 0.3).unwrap()
}

fn grid() -> ContactGrid {
    let g = ContactGrid::hertz_circle(A, P, 20).unwrap();
    assert!((250..=350).contains(&g.len()), "{}", g.len());
    g
}

fn solvers() -> Vec<(&'static str, Box<dyn GridSolver>)> {
    vec![("LP", Box::new(ModifiedLp::default())), ("fast", Box::new(FastSolver::default()))]
}

/// Coulomb admissibility to the stated tolerance ([`tol::COULOMB`]).
fn check_coulomb(grid: &ContactGrid, s: &GridSolution, name: &str) {
    let qnorm = s.traction.iter().map(|q| q.0 * q.0 + q.1 * q.1).sum::<f64>().sqrt();
    let eps = s.info.tolerance.rel() * qnorm;
    let mut worst: f64 = 0.0;
    for k in 0..grid.len() {
        let q = s.traction[k].0.hypot(s.traction[k].1);
        let c = F * grid.pressure[k];
        worst = worst.max((q - c) / qnorm);
        assert!(q <= c * (1.0 + tol::COULOMB) + eps, "{name}: element {k} |q| {q:e} > f p {c:e}");
    }
    println!("{name}: max (|q_k| - f p_k) / |q| = {worst:.1e}");
}

/// Check Coulomb admissibility, equilibrium, zero slip on stick and the reported residual.
fn check_optimality(grid: &ContactGrid, s: &GridSolution, force: (f64, f64), name: &str) {
    let area = grid.element_area();
    let n = grid.len();
    check_coulomb(grid, s, name);
    // Equilibrium: sum of q * area equals the force.
    let (mut rx, mut ry) = (0.0, 0.0);
    for q in &s.traction {
        rx += q.0 * area;
        ry += q.1 * area;
    }
    let t = force.0.hypot(force.1);
    let err = (rx - force.0).hypot(ry - force.1) / t;
    assert!(err <= tol::EQUILIBRIUM, "{name}: equilibrium {err:e}");
    let err_r = (s.resultant.0 - force.0).hypot(s.resultant.1 - force.1) / t;
    assert!(err_r <= tol::EQUILIBRIUM, "{name}: reported resultant {err_r:e}");
    // Stick elements move with the rigid body: zero slip.
    let shift = s.shift.0.hypot(s.shift.1);
    let mut nstick = 0;
    for k in 0..n {
        if s.state[k] == ElementState::Stick {
            nstick += 1;
            let sk = s.slip[k].0.hypot(s.slip[k].1);
            assert!(sk <= tol::STICK_SLIP * shift, "{name}: stick element {k} slips {sk:e}");
        } else {
            // Slip elements sit on the Coulomb circle.
            let q = s.traction[k].0.hypot(s.traction[k].1);
            let c = F * grid.pressure[k];
            assert!((q - c).abs() <= 1e-9 * c, "{name}: slip element {k} |q| {q:e} vs {c:e}");
        }
    }
    assert!(nstick > 0 && nstick < n, "{name}: partial slip expected, {nstick} of {n} stick");
    assert!(s.info.residual <= s.info.tolerance.rel(), "{name}: {:?}", s.info);
    println!(
        "{name}: {} stick of {n}, {} iterations ({} inner), residual {:.1e}, {:.4} s",
        nstick,
        s.info.iterations,
        s.info.inner_iterations,
        s.info.residual,
        s.info.setup_seconds + s.info.solve_seconds
    );
}

#[test]
fn both_solvers_meet_the_optimality_conditions() {
    let g = grid();
    let pb = GridProblem::new(&g, [steel(), steel()], F).unwrap();
    let (t, angle) = (0.5 * F * P, 0.3);
    let load = Load::polar(t, angle).unwrap();
    let mut sols = Vec::new();
    for (name, solver) in solvers() {
        let s = solver.solve(&pb, &load).unwrap();
        assert_eq!(s.info.solver, solver.name());
        check_optimality(&g, &s, (t * angle.cos(), t * angle.sin()), name);
        sols.push(s);
    }
    // The LP and the fast solver agree: exactly (to the stated tolerance) under the LP's
    // one-direction assumption, to the size of that assumption's effect with both
    // components free.
    let par = FastSolver { directions: TractionDirections::ParallelToForce, ..Default::default() }
        .solve(&pb, &load)
        .unwrap();
    check_optimality(&g, &par, (t * angle.cos(), t * angle.sin()), "fast (parallel)");
    let p0 = 3.0 * P / (2.0 * std::f64::consts::PI * A * A);
    let diff = |a: &GridSolution, b: &GridSolution| {
        a.traction
            .iter()
            .zip(&b.traction)
            .map(|(x, y)| (x.0 - y.0).hypot(x.1 - y.1))
            .fold(0.0, f64::max)
            / (F * p0)
    };
    let d_par = diff(&sols[0], &par);
    let d_free = diff(&sols[0], &sols[1]);
    println!("max |q_LP - q_fast| / (f p0): parallel {d_par:.2e}, free {d_free:.2e}");
    assert!(d_par <= tol::LP_VS_FAST_PARALLEL, "{d_par:e}");
    assert!(d_free <= tol::LP_VS_FAST_FREE, "{d_free:e}");
    let states = sols[0].state.iter().zip(&par.state).filter(|(a, b)| a != b).count();
    assert_eq!(states, 0, "stick/slip differs on {states} elements");
}

#[test]
fn a_moment_meets_the_moment_balance() {
    let g = grid();
    let pb = GridProblem::new(&g, [steel(), steel()], F).unwrap();
    // About half the spin capacity f P (3 pi / 16) a.
    let m = 0.5 * F * P * 3.0 * std::f64::consts::PI / 16.0 * A;
    for (name, solver) in solvers() {
        let s = solver.solve(&pb, &Load::moment(m, None).unwrap()).unwrap();
        let err = (s.moment - m).abs() / m;
        assert!(err <= tol::EQUILIBRIUM, "{name}: moment balance {err:e}");
        let force = s.resultant.0.hypot(s.resultant.1);
        assert!(force <= tol::EQUILIBRIUM * m / A, "{name}: net force {force:e}");
        check_coulomb(&g, &s, name);
        assert!(s.rotation > 0.0 && s.info.residual <= s.info.tolerance.rel(), "{name}");
    }
}

#[test]
fn capacity_exceeded_for_a_force_beyond_f_p() {
    let g = grid();
    let pb = GridProblem::new(&g, [steel(), steel()], F).unwrap();
    for (name, solver) in solvers() {
        let e = solver.solve(&pb, &Load::polar(1.01 * F * P, 0.2).unwrap()).unwrap_err();
        println!("{name}: {e}");
        match e {
            Error::CapacityExceeded { load: LoadKind::Force, requested, capacity } => {
                // The fast solver checks each force component against f P first.
                assert!(requested > capacity, "{name}");
                assert!((capacity / (F * P) - 1.0).abs() < 1e-12, "{name}: {capacity}");
            }
            e => panic!("{name}: {e:?}"),
        }
        // Exactly at the capacity: a gross-slip solution, not an error.
        let s = solver.solve(&pb, &Load::polar(F * P, 0.2).unwrap()).unwrap();
        assert!(s.state.iter().all(|s| *s == ElementState::Slip), "{name}");
    }
}

#[test]
fn capacity_exceeded_for_a_moment_beyond_the_spin_capacity() {
    let g = grid();
    let pb = GridProblem::new(&g, [steel(), steel()], F).unwrap();
    let m = F * P * A; // beyond f P (3 pi / 16) a
    for (name, solver) in solvers() {
        let e = solver.solve(&pb, &Load::moment(-m, None).unwrap()).unwrap_err();
        println!("{name}: {e}");
        assert!(
            matches!(e, Error::CapacityExceeded { load: LoadKind::Moment, requested, capacity }
                if requested == m && capacity < m && capacity > 0.5 * m),
            "{name}: {e:?}"
        );
    }
}

#[test]
fn not_converged_with_a_tiny_iteration_budget() {
    let g = grid();
    let pb = GridProblem::new(&g, [steel(), steel()], F).unwrap().with_max_iterations(1);
    for (name, solver) in solvers() {
        let e = solver.solve(&pb, &Load::polar(0.5 * F * P, 0.0).unwrap()).unwrap_err();
        println!("{name}: {e}");
        assert!(
            matches!(e, Error::NotConverged { iterations: 1, residual, tolerance, solver: s }
                if residual > tolerance && s == solver.name()),
            "{name}: {e:?}"
        );
    }
}

#[test]
fn empty_grid() {
    let g = ContactGrid { hx: 1.0, hy: 1.0, x: vec![], y: vec![], pressure: vec![], patch: vec![] };
    let e = GridProblem::new(&g, [steel(), steel()], F).unwrap_err();
    assert!(matches!(e, Error::EmptyGrid { .. }), "{e:?}");
    let load = Load::polar(1.0, 0.0).unwrap();
    let e = stickslip_traction::TractionProblem::new(&g, [steel(), steel()], F, load).unwrap_err();
    assert!(matches!(e, Error::EmptyGrid { .. }), "{e:?}");
    let e = stickslip_traction::FastProblem::new(&g, [steel(), steel()], F, load).unwrap_err();
    assert!(matches!(e, Error::EmptyGrid { .. }), "{e:?}");
}

#[test]
fn tolerance_out_of_range() {
    let g = grid();
    let load = Load::polar(0.5 * F * P, 0.0).unwrap();
    for (name, solver) in solvers() {
        let (lo, hi) = solver.tolerance_range();
        for tolerance in [
            Tolerance::relative(0.5 * lo).unwrap(),
            Tolerance::relative(2.0 * hi).unwrap(),
            Tolerance::new(1e-3, lo).unwrap(),
        ] {
            let pb = GridProblem::new(&g, [steel(), steel()], F).unwrap().with_tolerance(tolerance);
            let e = solver.solve(&pb, &load).unwrap_err();
            assert!(
                matches!(e, Error::ToleranceOutOfRange { range, .. } if range == (lo, hi)),
                "{name}: {e:?}"
            );
        }
        // The ends of the range are accepted.
        let pb = GridProblem::new(&g, [steel(), steel()], F)
            .unwrap()
            .with_tolerance(Tolerance::relative(hi).unwrap());
        assert!(solver.solve(&pb, &load).is_ok(), "{name}");
    }
    assert_eq!(ModifiedLp::TOLERANCE_RANGE, (1e-10, 1e-1));
    assert_eq!(stickslip_traction::FastConfig::TOLERANCE_RANGE, (1e-14, 1e-1));
}

#[test]
fn force_and_moment_unsupported_by_the_lp_and_no_stick_left_near_gross_slip() {
    let g = grid();
    let pb = GridProblem::new(&g, [steel(), steel()], F).unwrap();
    let spin = F * P * 3.0 * std::f64::consts::PI / 16.0 * A;
    let load = Load::polar(0.9 * F * P, 0.0).unwrap().with_moment(0.8 * spin, None).unwrap();
    assert_eq!(load.kind(), LoadKind::Combined);
    let e = ModifiedLp::default().solve(&pb, &load).unwrap_err();
    assert!(matches!(e, Error::UnsupportedLoad { load: LoadKind::Combined, .. }), "{e:?}");
    // Each load alone is below its capacity; together they are beyond what the contact
    // carries, and the fast solver says so with a typed error.
    let e = FastSolver::default().solve(&pb, &load).unwrap_err();
    println!("fast, 0.9 f P with 0.8 of the spin capacity: {e}");
    assert!(
        matches!(e, Error::NoStickLeft { load: LoadKind::Combined, iteration, .. } if iteration >= 1),
        "{e:?}"
    );
}
