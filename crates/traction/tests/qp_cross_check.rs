//! Cross-check of the modified LP against an independent interior-point QP solver
//! (clarabel) on grids of about 50, 120 and 200 elements.
//!
//! Seed 002's complementarity system (eq. 3.13) is the KKT system of the strictly convex QP
//!
//! $$ \min_F \tfrac12 F^{\mathsf T} A F \quad\text{s.t.}\quad 0 \le F \le fP,\quad
//!    g^{\mathsf T} F = T, $$
//!
//! with the rigid-body movement $\beta$ the multiplier of the equality, $Y_1 = \beta g - AF$
//! the multiplier of the upper bound, and $Y_2 = fP - F$ its slack. With clarabel's
//! convention ($Px + q + \mathsf{A}^{\mathsf T}z = 0$) the equality row $g^{\mathsf T}$ gives
//! $AF = -z_0\,g + \dots$, so $\beta = -z_0$. $A$ is symmetric positive definite, so $F$ is
//! unique and both solvers must find it.

mod common;
use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettingsBuilder, DefaultSolver, IPSolver, NonnegativeConeT, SolverStatus, ZeroConeT,
};
use common::{steel, tol};
use std::f64::consts::FRAC_PI_4;
use std::time::Instant;
use stickslip_halfspace::rectangle::Compliance;
use stickslip_lattice::influence::projected_matrix;
use stickslip_lattice::{ContactGrid, GridPatch, InfluenceModel, PatchPressure, Shape};
use stickslip_traction::{lp::modified_lp, lp::LpConfig};

/// Solve the QP with clarabel on the scaled problem (forces by max capacity, influence by
/// its largest diagonal entry) and return the forces and $\beta$ in the caller's units,
/// with clarabel's status and iterations.
fn clarabel_qp(a: &[f64], cap: &[f64], load: f64) -> (Vec<f64>, f64, SolverStatus, u32) {
    let n = cap.len();
    let fs = cap.iter().copied().fold(0.0, f64::max);
    let asc = (0..n).map(|k| a[k * n + k]).fold(0.0, f64::max);
    // P: upper triangle of A / asc, column by column.
    let (mut colptr, mut rowval, mut nzval) = (vec![0usize], Vec::new(), Vec::new());
    for j in 0..n {
        for i in 0..=j {
            rowval.push(i);
            nzval.push(a[i * n + j] / asc);
        }
        colptr.push(rowval.len());
    }
    let p = CscMatrix::new(n, n, colptr, rowval, nzval);
    // Constraint rows: [g^T; -I; I], cones Zero(1), Nonnegative(2N).
    let (mut colptr, mut rowval, mut nzval) = (vec![0usize], Vec::new(), Vec::new());
    for j in 0..n {
        rowval.extend([0, 1 + j, 1 + n + j]);
        nzval.extend([1.0, -1.0, 1.0]);
        colptr.push(rowval.len());
    }
    let amat = CscMatrix::new(2 * n + 1, n, colptr, rowval, nzval);
    let mut b = vec![0.0; 2 * n + 1];
    b[0] = load / fs;
    for (bk, c) in b[1 + n..].iter_mut().zip(cap) {
        *bk = c / fs;
    }
    let q = vec![0.0; n];
    let cones = [ZeroConeT(1), NonnegativeConeT(2 * n)];
    // Tight tolerances: the defaults (1e-8) would make the cross-check test clarabel's
    // stopping rule instead of the LP.
    let settings = DefaultSettingsBuilder::default()
        .verbose(false)
        .max_iter(200)
        .tol_gap_abs(1e-14)
        .tol_gap_rel(1e-14)
        .tol_feas(1e-14)
        .tol_ktratio(1e-12)
        .iterative_refinement_reltol(1e-15)
        .iterative_refinement_abstol(1e-15)
        .build()
        .expect("clarabel settings");
    let mut solver = DefaultSolver::new(&p, &q, &amat, &b, &cones, settings).expect("clarabel");
    solver.solve();
    let f = solver.solution.x.iter().map(|v| v * fs).collect();
    let beta = -solver.solution.z[0] * asc * fs;
    (f, beta, solver.solution.status, solver.solution.iterations)
}

fn two_patches(h: f64) -> ContactGrid {
    let sq = |cx: f64, p: f64| GridPatch {
        shape: Shape::Rectangle { cx, cy: 0.0, wx: 0.6, wy: 0.6 },
        pressure: PatchPressure::Uniform(p),
    };
    ContactGrid::from_patches(h, h, (-0.8, -0.3), &[sq(-0.5, 2e4), sq(0.5, 1e4)]).unwrap()
}

#[test]
fn lp_agrees_with_clarabel_qp_to_200_elements() {
    let s = steel();
    let c = Compliance::pair(&s, &s);
    // (name, grid, T / (f sum P), load angle)
    let cases: Vec<(&str, ContactGrid, f64, f64)> = vec![
        ("Hertz circle 8 across", ContactGrid::hertz_circle(0.05, 1000.0, 8).unwrap(), 0.5, 0.0),
        ("square 7x7", ContactGrid::uniform_square(1.0, 1e4, 7).unwrap(), 0.8, 0.7),
        ("two patches h 0.1", two_patches(0.1), 0.7, FRAC_PI_4),
        ("Hertz circle 12 across", ContactGrid::hertz_circle(0.05, 1000.0, 12).unwrap(), 0.9, 2.0),
        (
            "ellipse 16x8",
            ContactGrid::hertz_ellipse(0.1, 0.05, 800.0, 16, 8).unwrap(),
            0.3,
            FRAC_PI_4,
        ),
        ("square 11x11", ContactGrid::uniform_square(1.0, 1e4, 11).unwrap(), 0.5, 0.0),
        ("Hertz circle 16 across", ContactGrid::hertz_circle(0.05, 1000.0, 16).unwrap(), 0.6, 0.3),
        ("ellipse 20x10", ContactGrid::hertz_ellipse(0.1, 0.05, 800.0, 20, 10).unwrap(), 0.95, 1.2),
        ("square 14x14", ContactGrid::uniform_square(1.0, 1e4, 14).unwrap(), 0.9, 0.0),
        ("two patches h 0.06", two_patches(0.06), 0.8, FRAC_PI_4),
    ];
    let f = 0.12;
    let (mut worst_f, mut worst_b, mut worst_name) = (0.0_f64, 0.0_f64, "");
    for (name, grid, ratio, angle) in cases {
        let n = grid.len();
        let cap: Vec<f64> = grid.normal_force().iter().map(|p| f * p).collect();
        let load = ratio * cap.iter().sum::<f64>();
        let dirs = vec![(angle.cos(), angle.sin()); n];
        let a = projected_matrix(&grid, &c, InfluenceModel::ExactRectangle, &dirs);
        let lp = modified_lp(&a, &vec![1.0; n], &cap, load, &LpConfig::default()).unwrap();
        let t0 = Instant::now();
        let (fq, bq, status, iters) = clarabel_qp(&a, &cap, load);
        let secs = t0.elapsed().as_secs_f64();
        let fmax = cap.iter().copied().fold(0.0, f64::max);
        let df = lp.force.iter().zip(&fq).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max) / fmax;
        let db = (lp.rigid - bq).abs() / lp.rigid.abs();
        let slipping = lp.slip.iter().filter(|&&y| y > 1e-9 * lp.rigid).count();
        println!(
            "{name}: N = {n}, T/fP = {ratio}, angle {angle:.3}: max |F_LP - F_QP| / max fP = \
             {df:.2e}, |beta_LP - beta_QP| / beta = {db:.2e} (slipping {slipping}; LP {} pivots; \
             clarabel {status:?} in {iters} iterations, {secs:.3} s)",
            lp.iterations
        );
        assert!(
            matches!(status, SolverStatus::Solved | SolverStatus::AlmostSolved),
            "{name}: {status:?}"
        );
        assert!(df < tol::CROSS_CHECK && db < tol::CROSS_CHECK, "{name}: {df:e} {db:e}");
        if df.max(db) > worst_f.max(worst_b) {
            worst_name = name;
        }
        worst_f = worst_f.max(df);
        worst_b = worst_b.max(db);
    }
    println!(
        "worst agreement: force {worst_f:.2e} of max fP, rigid movement {worst_b:.2e} \
         (worst case {worst_name})"
    );
}
