//! The fast solver against the dense modified LP (issue 5) on the same grid: with the LP's
//! one-direction assumption imposed they solve the same discrete equations; with both
//! components free the difference is the effect of that assumption.

mod fast_common;
use fast_common::{extended, steel, tol};
use std::time::Instant;
use stickslip_lattice::ContactGrid;
use stickslip_traction::closed::Lubkin;
use stickslip_traction::{ElementState, FastProblem, Load, TractionDirections, TractionProblem};

/// Sphere (Example 1 proportions) on a grid `n_across` elements across the diameter.
fn compare_force(n_across: usize, t: f64, angle: f64) {
    let (p, f) = (2160.0, 0.1);
    let a = 0.046148;
    let grid = ContactGrid::hertz_circle(a, p, n_across).unwrap();
    let s = steel();
    let n = grid.len();
    let t0 = Instant::now();
    let lp = TractionProblem::new(&grid, [s, s], f, Load::Force { magnitude: t * f * p, angle })
        .unwrap()
        .solve()
        .unwrap();
    let t_lp = t0.elapsed().as_secs_f64();
    let load = Load::polar(t * f * p, angle).unwrap();
    let t1 = Instant::now();
    let fast = FastProblem::new(&grid, [s, s], f, load)
        .unwrap()
        .with_directions(TractionDirections::ParallelToForce)
        .unwrap()
        .solve()
        .unwrap();
    let t_fast = t1.elapsed().as_secs_f64();
    let area = grid.element_area();
    let (c, sn) = (angle.cos(), angle.sin());
    let fmax = lp.force.iter().copied().fold(0.0, f64::max);
    let mut worst: f64 = 0.0;
    let mut worst_k = 0;
    let mut state_diff = 0;
    for k in 0..n {
        let ff = area * (fast.traction[k].0 * c + fast.traction[k].1 * sn);
        let e = (ff - lp.force[k]).abs() / fmax;
        if e > worst {
            worst = e;
            worst_k = k;
        }
        if fast.state[k] != lp.state[k] {
            state_diff += 1;
        }
    }
    let shift = fast.shift.0 * c + fast.shift.1 * sn;
    let shift_err = (shift / lp.rigid - 1.0).abs();
    println!(
        "vs LP, N = {n}, T/fP = {t}, angle {angle}: max |F_fast - F_lp| / max F = {worst:.2e} \
         (element {worst_k}), rigid shift rel. diff {shift_err:.2e}, stick/slip differences {state_diff}; \
         LP {t_lp:.3} s ({} pivots), fast {t_fast:.4} s ({} Newton, {} CG, residual {:.1e}): speed ratio {:.0}",
        lp.info.iterations,
        fast.info.iterations,
        fast.info.cg_iterations,
        fast.info.residual,
        t_lp / t_fast
    );
    assert!(worst <= tol::VS_LP, "{worst:e}");
    assert!(shift_err <= tol::VS_LP, "{shift_err:e}");
}

#[test]
fn one_direction_matches_lp_small() {
    compare_force(12, 2.0 / 3.0, 0.0);
    compare_force(14, 0.3, 0.6);
}

#[test]
fn one_direction_matches_lp_1000() {
    compare_force(36, 2.0 / 3.0, 0.0);
}

/// The effect of the one-direction assumption: the same grid and load solved with both
/// components free. Printed: the largest transverse traction, the largest change of the
/// traction, of the stick count and of the rigid shift.
#[test]
fn one_direction_assumption_effect() {
    let (p, f, a) = (2160.0, 0.1, 0.046148);
    let s = steel();
    let cases: &[(usize, f64)] = if extended() {
        &[(36, 2.0 / 3.0), (200, 2.0 / 3.0), (200, 0.999)]
    } else {
        &[(36, 2.0 / 3.0), (100, 2.0 / 3.0)]
    };
    for &(n_across, t) in cases {
        let grid = ContactGrid::hertz_circle(a, p, n_across).unwrap();
        let load = Load::polar(t * f * p, 0.0).unwrap();
        let base = FastProblem::new(&grid, [s, s], f, load).unwrap();
        let par = base
            .clone()
            .with_directions(TractionDirections::ParallelToForce)
            .unwrap()
            .solve()
            .unwrap();
        let free = base.solve().unwrap();
        let p0 = 3.0 * p / (2.0 * std::f64::consts::PI * a * a);
        let mut dq: f64 = 0.0;
        let mut qy: f64 = 0.0;
        for k in 0..grid.len() {
            let (a1, b1) = free.traction[k];
            let (a2, b2) = par.traction[k];
            dq = dq.max((a1 - a2).hypot(b1 - b2) / (f * p0));
            qy = qy.max(b1.abs() / (f * p0));
        }
        let stick_f = free.state.iter().filter(|s| **s == ElementState::Stick).count();
        let stick_p = par.state.iter().filter(|s| **s == ElementState::Stick).count();
        println!(
            "one-direction effect, N = {}, T/fP = {t:.3}: max |q_free - q_parallel| / (f p0) = {dq:.3e}, \
             max |q_y| / (f p0) = {qy:.3e}, stick elements {stick_f} (free) vs {stick_p} (parallel), \
             shift {:.6e} vs {:.6e} ({:+.3} %)",
            grid.len(),
            free.shift.0,
            par.shift.0,
            100.0 * (free.shift.0 / par.shift.0 - 1.0)
        );
        assert!(free.info.residual <= tol::RESIDUAL && par.info.residual <= tol::RESIDUAL);
        // Both minimise the same complementary energy (1/2) sum_k q_k.u_k h^2 (the discrete
        // convex program of the fast module's documentation); the free problem is the less
        // constrained one, so its energy cannot be larger.
        let energy = |sol: &stickslip_traction::FastSolution| -> f64 {
            let area = grid.element_area();
            0.5 * area
                * sol
                    .traction
                    .iter()
                    .zip(&sol.displacement)
                    .map(|(q, u)| q.0 * u.0 + q.1 * u.1)
                    .sum::<f64>()
        };
        let (ef, ep) = (energy(&free), energy(&par));
        println!(
            "    complementary energy: free {ef:.9e}, parallel {ep:.9e} (ratio - 1 = {:.2e})",
            ef / ep - 1.0
        );
        assert!(ef <= ep * (1.0 + 1e-12), "{ef} {ep}");
    }
}

/// Twist with the LP's directions (its full-stick preprocessor, seed 002 §3.4.1) imposed:
/// the same answer as the LP; and the Lubkin moment at c/a = 0.5 for reference.
#[test]
fn twist_fixed_directions_match_lp() {
    let (p, f, a) = (2160.0, 0.1, 0.046148);
    let s = steel();
    let grid = ContactGrid::hertz_circle(a, p, 20).unwrap();
    let m = Lubkin::from_stick_radius(a, p, f, 0.5 * a).unwrap().moment().unwrap();
    let t0 = Instant::now();
    let lp = TractionProblem::new(&grid, [s, s], f, Load::Moment { moment: m, centre: None })
        .unwrap()
        .solve()
        .unwrap();
    let t_lp = t0.elapsed().as_secs_f64();
    let fast = FastProblem::new(&grid, [s, s], f, Load::moment(m, None).unwrap())
        .unwrap()
        .with_directions(TractionDirections::Fixed(lp.direction.clone()))
        .unwrap()
        .solve()
        .unwrap();
    let area = grid.element_area();
    let fmax = lp.force.iter().copied().fold(0.0, f64::max);
    let mut worst: f64 = 0.0;
    for k in 0..grid.len() {
        let (tx, ty) = lp.direction[k];
        let ff = area * (fast.traction[k].0 * tx + fast.traction[k].1 * ty);
        worst = worst.max((ff - lp.force[k]).abs() / fmax);
    }
    let rot_err = (fast.rotation / lp.rigid - 1.0).abs();
    println!(
        "twist vs LP (fixed directions), N = {}: max |F_fast - F_lp| / max F = {worst:.2e}, \
         rotation rel. diff {rot_err:.2e}; LP {t_lp:.3} s, fast {:.4} s ({} Newton, {} CG)",
        grid.len(),
        fast.info.solve_seconds + fast.info.setup_seconds,
        fast.info.iterations,
        fast.info.cg_iterations
    );
    assert!(worst <= tol::VS_LP, "{worst:e}");
    assert!(rot_err <= tol::VS_LP, "{rot_err:e}");
}
