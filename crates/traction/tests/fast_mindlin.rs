//! The fast solver on the Cattaneo–Mindlin sphere (FORMULAS.md E) at issue 6's sizes.

mod fast_common;
use fast_common::{extended, hertz_radius, steel, tol};
use std::time::Instant;
use stickslip_lattice::ContactGrid;
use stickslip_traction::closed::Mindlin;
use stickslip_traction::{ElementState, FastProblem, FastSolution, Load};

struct Report {
    n: usize,
    residual: f64,
    stick_err_cells: f64,
    shift_rel: f64,
    seconds: f64,
}

/// A `side` x `side` lattice grid centred on the contact, every cell an element, with the
/// Hertz pressure of radius `a` = `cells` lattice cells inside and zero outside (scaled so the
/// element forces sum to `p`, as `ContactGrid::hertz_circle` does).
fn hertz_box(side: usize, cells: usize, a: f64, p: f64) -> ContactGrid {
    let h = a / cells as f64;
    let half = side as f64 / 2.0;
    let mut pr = vec![0.0; side * side];
    for j in 0..side {
        for i in 0..side {
            let x = (i as f64 + 0.5 - half) * h;
            let y = (j as f64 + 0.5 - half) * h;
            pr[j * side + i] = (1.0 - (x * x + y * y) / (a * a)).max(0.0).sqrt();
        }
    }
    let sum: f64 = pr.iter().sum();
    let scale = p / (sum * h * h);
    pr.iter_mut().for_each(|v| *v *= scale);
    ContactGrid::from_mask(h, h, (-half * h, -half * h), side, side, &vec![true; side * side], &pr)
        .unwrap()
}

/// Seed 002 Example 1 proportions (P = 2160, f = 0.1) at load ratio `t` on a `side` x `side`
/// grid with contact radius `cells` lattice cells, the force at `angle`.
fn mindlin_case(side: usize, cells: usize, t: f64, angle: f64) -> (FastSolution, Report) {
    let (p, f) = (2160.0, 0.1);
    let a = hertz_radius(p, 1.0);
    let grid = hertz_box(side, cells, a, p);
    let h = grid.hx;
    let s = steel();
    let load = Load::polar(t * f * p, angle).unwrap();
    let t0 = Instant::now();
    let sol = FastProblem::new(&grid, [s, s], f, load).unwrap().solve().unwrap();
    let seconds = t0.elapsed().as_secs_f64();
    let m = Mindlin::new(a, p, f, t * f * p).unwrap();
    let n_stick = sol.state.iter().filter(|s| **s == ElementState::Stick).count();
    let r_stick = (n_stick as f64 * h * h / std::f64::consts::PI).sqrt();
    let stick_err_cells = (r_stick - m.stick_radius()) / h;
    let delta = m.compliance_relative(&s, &s);
    let shift = sol.shift.0.hypot(sol.shift.1);
    let shift_rel = shift / delta - 1.0;
    // Direction of the shift against the load direction.
    let dir_err = (sol.shift.1.atan2(sol.shift.0) - angle).abs();
    let max_qy_rel = sol
        .traction
        .iter()
        .map(|q| (-q.0 * angle.sin() + q.1 * angle.cos()).abs())
        .fold(0.0, f64::max)
        / (f * 3.0 * p / (2.0 * std::f64::consts::PI * a * a));
    println!(
        "Mindlin {side}x{side} (a = {cells} cells, N = {}), T/fP = {t}, angle {angle:.3}: \
         {} Newton, {} CG, {} FFT products, residual {:.2e}, load residual {:.2e}; \
         stick radius (area-equivalent) {:.3} cells vs Mindlin {:.3} (diff {stick_err_cells:+.3} cells); \
         shift {:.6e} vs Mindlin {:.6e} ({:+.3} %), direction error {dir_err:.1e} rad; \
         max transverse traction / (f p0) = {max_qy_rel:.3e}; setup {:.2} s, solve {:.2} s, total {seconds:.2} s",
        grid.len(),
        sol.info.iterations,
        sol.info.cg_iterations,
        sol.info.products,
        sol.info.residual,
        sol.info.load_residual,
        r_stick / h,
        m.stick_radius() / h,
        shift,
        delta,
        100.0 * shift_rel,
        sol.info.setup_seconds,
        sol.info.solve_seconds,
    );
    let rep =
        Report { n: grid.len(), residual: sol.info.residual, stick_err_cells, shift_rel, seconds };
    (sol, rep)
}

#[test]
fn mindlin_256() {
    let (_, r) = mindlin_case(256, 100, 2.0 / 3.0, 0.0);
    assert!(r.residual <= tol::RESIDUAL, "{}", r.residual);
    assert!(r.stick_err_cells.abs() <= 1.0, "{}", r.stick_err_cells);
    assert!(r.shift_rel.abs() <= tol::SHIFT_MINDLIN, "{}", r.shift_rel);
    println!("{} s for N = {} (speed is measured by the benches, not asserted)", r.seconds, r.n);
}

/// Issue 6's large case: 512 x 512 lattice (N = 262,144), contact radius 200 cells. About
/// 10 s on 2 cores, so it runs with `STICKSLIP_EXTENDED=1` only.
#[test]
fn mindlin_512() {
    if !extended() {
        println!("mindlin_512: skipped (set STICKSLIP_EXTENDED=1)");
        return;
    }
    let (_, r) = mindlin_case(512, 200, 2.0 / 3.0, 0.0);
    assert!(r.residual <= tol::RESIDUAL, "{}", r.residual);
    assert!(r.stick_err_cells.abs() <= 1.0, "{}", r.stick_err_cells);
    assert!(r.shift_rel.abs() <= tol::SHIFT_MINDLIN, "{}", r.shift_rel);
    println!("{} s for N = {} (speed is measured by the benches, not asserted)", r.seconds, r.n);
}

/// The load in an arbitrary direction: the same answer rotated (the grid is symmetric under
/// the reflections, not under the rotation, so the discrete answers differ slightly).
#[test]
fn mindlin_oblique_128() {
    let (sol, r) = mindlin_case(128, 50, 0.5, 0.7);
    assert!(r.residual <= tol::RESIDUAL, "{}", r.residual);
    assert!(r.stick_err_cells.abs() <= 1.0, "{}", r.stick_err_cells);
    assert!(r.shift_rel.abs() <= tol::SHIFT_MINDLIN, "{}", r.shift_rel);
    let ang = sol.shift.1.atan2(sol.shift.0);
    assert!((ang - 0.7).abs() < 1e-3, "{ang}");
}
