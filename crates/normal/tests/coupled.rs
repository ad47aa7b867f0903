//! Dundurs coupling: the alternating (Panagiotopoulos) process of `coupled` against an
//! independent dense direct solve of the coupled full-stick problem (active-set enumeration
//! with Gaussian elimination on the uniform-rectangle coefficients evaluated directly, no
//! FFT), and the optimality conditions of a partial-slip solution checked with the dense
//! influence matrices.

use stickslip_halfspace::material::{dundurs_beta, Compliance};
use stickslip_halfspace::rectangle::{
    pressure_displacement, pressure_uz, shear_x_displacement, shear_y_displacement, Rect,
};
use stickslip_halfspace::Material;
use stickslip_normal::CoupledProblem;
use stickslip_normal::NormalLoad;
use stickslip_traction::contract::Load;
use stickslip_traction::Tolerance;

const N: usize = 12;
const H: f64 = 1e-5;
const R: f64 = 0.01;

fn sphere_gap() -> Vec<f64> {
    let mut g = vec![0.0; N * N];
    for j in 0..N {
        for i in 0..N {
            let x = -0.5 * N as f64 * H + (i as f64 + 0.5) * H;
            let y = -0.5 * N as f64 * H + (j as f64 + 0.5) * H;
            g[j * N + i] = (x * x + y * y) / (2.0 * R);
        }
    }
    g
}

fn centre(k: usize) -> (f64, f64) {
    let (i, j) = (k % N, k / N);
    (-0.5 * N as f64 * H + (i as f64 + 0.5) * H, -0.5 * N as f64 * H + (j as f64 + 0.5) * H)
}

/// Dense coefficient blocks at cell k due to unit traction on cell j: rows (n, x, y),
/// columns (p, qx, qy).
fn block(c: &Compliance, k: usize, j: usize) -> [[f64; 3]; 3] {
    let (xk, yk) = centre(k);
    let (xj, yj) = centre(j);
    let r = Rect::new(xj - 0.5 * H, xj + 0.5 * H, yj - 0.5 * H, yj + 0.5 * H).unwrap();
    let p = pressure_displacement(c, &r, xk, yk);
    let sx = shear_x_displacement(c, &r, xk, yk);
    let sy = shear_y_displacement(c, &r, xk, yk);
    [[pressure_uz(c, &r, xk, yk), sx.z, sy.z], [p.x, sx.x, sy.x], [p.y, sx.y, sy.y]]
}

/// Gaussian elimination with partial pivoting.
fn dense_solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Vec<f64> {
    let n = b.len();
    for c in 0..n {
        let piv = (c..n).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs())).unwrap();
        a.swap(c, piv);
        b.swap(c, piv);
        assert!(a[c][c].abs() > 0.0, "singular dense system");
        for r in c + 1..n {
            let f = a[r][c] / a[c][c];
            if f != 0.0 {
                let (top, bottom) = a.split_at_mut(r);
                for (x, y) in bottom[0][c..].iter_mut().zip(&top[c][c..]) {
                    *x -= f * y;
                }
                b[r] -= f * b[c];
            }
        }
    }
    let mut x = vec![0.0; n];
    for r in (0..n).rev() {
        let s: f64 = (r + 1..n).map(|k| a[r][k] * x[k]).sum();
        x[r] = (b[r] - s) / a[r][r];
    }
    x
}

/// Full-stick coupled problem by active-set enumeration: on the contact set C,
/// $K^{nn}p + K^{nt}q - \delta = -g^0$, $K^{tn}p + K^{tt}q - \mathbf w = 0$, and the three
/// resultants; cells with $p < 0$ leave C, cells with $g < 0$ enter, until C is stable.
/// Returns (p, qx, qy) on the lattice.
fn dense_full_stick(
    c: &Compliance,
    g0: &[f64],
    load: f64,
    t: (f64, f64),
) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let nn = N * N;
    let area = H * H;
    let blocks: Vec<Vec<[[f64; 3]; 3]>> =
        (0..nn).map(|k| (0..nn).map(|j| block(c, k, j)).collect()).collect();
    let gmin = g0.iter().copied().fold(f64::INFINITY, f64::min);
    let mut set: Vec<bool> = g0.iter().map(|g| *g <= gmin + 0.25 * H * H / R * 9.0).collect();
    for _round in 0..100 {
        let cells: Vec<usize> = (0..nn).filter(|&k| set[k]).collect();
        let m = cells.len();
        let dim = 3 * m + 3;
        let mut a = vec![vec![0.0; dim]; dim];
        let mut b = vec![0.0; dim];
        for (r, &k) in cells.iter().enumerate() {
            for (s, &j) in cells.iter().enumerate() {
                let bl = blocks[k][j];
                for comp in 0..3 {
                    for src in 0..3 {
                        a[comp * m + r][src * m + s] = bl[comp][src];
                    }
                }
            }
            // -delta, -wx, -wy
            for comp in 0..3 {
                a[comp * m + r][3 * m + comp] = -1.0;
            }
            b[r] = -g0[k];
            for comp in 0..3 {
                a[3 * m + comp][comp * m + r] = area;
            }
        }
        b[3 * m] = load;
        b[3 * m + 1] = t.0;
        b[3 * m + 2] = t.1;
        let x = dense_solve(a, b);
        let mut p = vec![0.0; nn];
        let mut qx = vec![0.0; nn];
        let mut qy = vec![0.0; nn];
        for (r, &k) in cells.iter().enumerate() {
            p[k] = x[r];
            qx[k] = x[m + r];
            qy[k] = x[2 * m + r];
        }
        let delta = x[3 * m];
        let mut changed = false;
        for k in 0..nn {
            if set[k] && p[k] < 0.0 {
                set[k] = false;
                changed = true;
            }
        }
        if !changed {
            for k in 0..nn {
                if !set[k] {
                    let u: f64 = cells
                        .iter()
                        .map(|&j| {
                            (0..3)
                                .map(|s| blocks[k][j][0][s] * [p[j], qx[j], qy[j]][s])
                                .sum::<f64>()
                        })
                        .sum();
                    if g0[k] + u - delta < 0.0 {
                        set[k] = true;
                        changed = true;
                    }
                }
            }
        }
        if !changed {
            return (p, qx, qy);
        }
    }
    panic!("dense active set did not settle");
}

fn steel() -> Material {
    Material::new(210e9, 0.3).unwrap()
}

fn check_against_dense(bodies: [Material; 2], t: (f64, f64)) {
    let c = Compliance::pair(&bodies[0], &bodies[1]);
    let beta = dundurs_beta(&bodies[0], &bodies[1]);
    let g0 = sphere_gap();
    let load = 1.5;
    let (p, qx, qy) = dense_full_stick(&c, &g0, load, t);
    let tmag = t.0.hypot(t.1);
    let tangential = Load::Force { magnitude: tmag, angle: t.1.atan2(t.0) };
    let sol = CoupledProblem::new(N, N, (H, H), &g0, bodies, 1e3, tangential)
        .unwrap()
        .with_tolerance(Tolerance::relative(1e-12).unwrap())
        .solve(NormalLoad::Force(load))
        .unwrap();
    let pmax = p.iter().copied().fold(0.0, f64::max);
    let mut worst_p = 0.0f64;
    let mut worst_q = 0.0f64;
    for k in 0..N * N {
        assert_eq!(sol.normal.contact[k], p[k] > 0.0, "contact set differs at cell {k}");
        worst_p = worst_p.max((sol.normal.pressure[k] - p[k]).abs() / pmax);
        let d = (sol.traction[k].0 - qx[k]).hypot(sol.traction[k].1 - qy[k]);
        worst_q = worst_q.max(d / pmax);
        // full stick really holds in the dense answer (f = 1e3)
        assert!(qx[k].hypot(qy[k]) <= 1e3 * p[k] + 1e-300);
    }
    let qmax = qx.iter().zip(&qy).map(|(a, b)| a.hypot(*b)).fold(0.0, f64::max);
    eprintln!(
        "beta = {beta:.4}, T = {t:?}: passes {}, coupling residual {:.2e}; max |dp|/p_max = \
         {worst_p:.2e}, max |dq|/p_max = {worst_q:.2e} (q_max/p_max = {:.3e})",
        sol.info.passes,
        sol.info.residual,
        qmax / pmax
    );
    assert!(worst_p <= 1e-8 && worst_q <= 1e-8, "fast coupled vs dense: {worst_p:e} {worst_q:e}");
    assert!(sol.info.passes > 1);
}

#[test]
fn rigid_sphere_on_steel_pure_normal_load_matches_dense_solve() {
    // Pure normal load: the traction is the coupling's alone (Spence's problem), and it is
    // not small: beta = 0.286.
    check_against_dense([steel(), Material::rigid()], (0.0, 0.0));
}

#[test]
fn aluminium_sphere_on_steel_with_tangential_force_matches_dense_solve() {
    let alu = Material::new(70e9, 0.33).unwrap();
    check_against_dense([steel(), alu], (0.3, -0.2));
}

#[test]
fn identical_materials_are_refused_as_uncoupled() {
    let g0 = sphere_gap();
    let e = CoupledProblem::new(
        N,
        N,
        (H, H),
        &g0,
        [steel(), steel()],
        0.3,
        Load::Force { magnitude: 0.1, angle: 0.0 },
    )
    .unwrap_err();
    assert!(e.to_string().contains("beta"), "{e}");
}

#[test]
fn partial_slip_meets_the_coupled_contact_conditions_with_dense_influence() {
    // f = 0.3, T = 0.2 P: a stick core and a slip annulus. The conditions are evaluated with
    // the directly summed coefficients of `block` (no FFT), on the final p and q together.
    let bodies = [steel(), Material::rigid()];
    let c = Compliance::pair(&bodies[0], &bodies[1]);
    let g0 = sphere_gap();
    let (load, f) = (1.5, 0.3);
    let sol = CoupledProblem::new(
        N,
        N,
        (H, H),
        &g0,
        bodies,
        f,
        Load::Force { magnitude: 0.2 * load, angle: 0.0 },
    )
    .unwrap()
    .with_tolerance(Tolerance::relative(1e-11).unwrap())
    .solve(NormalLoad::Force(load))
    .unwrap();
    let nn = N * N;
    let p = &sol.normal.pressure;
    let q = &sol.traction;
    let mut u = vec![[0.0; 3]; nn];
    for (k, uk) in u.iter_mut().enumerate() {
        for j in 0..nn {
            let b = block(&c, k, j);
            let src = [p[j], q[j].0, q[j].1];
            for comp in 0..3 {
                uk[comp] += (0..3).map(|s| b[comp][s] * src[s]).sum::<f64>();
            }
        }
    }
    let delta = sol.normal.approach;
    let gmin = g0.iter().copied().fold(f64::INFINITY, f64::min);
    let scale = delta - gmin;
    let w = sol.tangential.shift;
    let pmax = p.iter().copied().fold(0.0, f64::max);
    let (mut gap_err, mut stick_slip, mut cone, mut align) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let (mut n_stick, mut n_slip) = (0, 0);
    for k in 0..nn {
        let g = g0[k] + u[k][0] - delta;
        if p[k] > 0.0 {
            gap_err = gap_err.max(g.abs() / scale);
            let s = (w.0 - u[k][1], w.1 - u[k][2]);
            let qm = q[k].0.hypot(q[k].1);
            cone = cone.max((qm - f * p[k]).max(0.0) / pmax);
            if qm < f * p[k] * (1.0 - 1e-6) {
                n_stick += 1;
                stick_slip = stick_slip.max(s.0.hypot(s.1) / scale);
            } else {
                n_slip += 1;
                // slip parallel to the traction, same sense: s = lambda q, lambda >= 0
                let cross = (s.0 * q[k].1 - s.1 * q[k].0) / qm;
                let dot = (s.0 * q[k].0 + s.1 * q[k].1) / qm;
                align = align.max(cross.abs() / scale).max((-dot).max(0.0) / scale);
            }
        } else {
            gap_err = gap_err.max((-g).max(0.0) / scale);
        }
    }
    eprintln!(
        "passes {}, stick {n_stick}, slip {n_slip}: gap {gap_err:.2e}, stick slip {stick_slip:.2e}, \
         cone {cone:.2e}, slip alignment {align:.2e} (relative to the interference {scale:.3e} m)",
        sol.info.passes
    );
    assert!(n_stick > 0 && n_slip > 0, "expected partial slip");
    assert!(gap_err <= 1e-9 && stick_slip <= 1e-9 && cone <= 1e-12 && align <= 1e-9);
}

/// A rigid flat circular punch of radius `a` (a cells across the radius) on a lattice of
/// `n` x `n` cells of side `h`: gap 0 on the face, far away outside it.
fn punch_gap(n: usize, h: f64, a: f64) -> Vec<f64> {
    let mut g = vec![0.0; n * n];
    for j in 0..n {
        for i in 0..n {
            let x = -0.5 * n as f64 * h + (i as f64 + 0.5) * h;
            let y = -0.5 * n as f64 * h + (j as f64 + 0.5) * h;
            if x.hypot(y) > a {
                g[j * n + i] = 1.0;
            }
        }
    }
    g
}

#[test]
fn bonded_flat_punch_is_stiffer_by_mossakovskiis_factor() {
    // A rigid flat punch pressed into steel (nu = 0.3) with complete adhesion (no slip) is
    // stiffer than the frictionless one by artanh(beta)/beta = (1 - nu) ln(3 - 4 nu)/(1 - 2 nu)
    // (Mossakovskii 1954; Spence 1968; Borodich & Keer 2004, Proc. R. Soc. A 460): 1.0286 at
    // nu = 0.3. Both solves on the same lattice, so the discretisation error largely cancels
    // in the ratio.
    let (n, h) = (64usize, 1e-5);
    let a = 24.5 * h;
    let g0 = punch_gap(n, h, a);
    let bodies = [steel(), Material::rigid()];
    let beta = dundurs_beta(&bodies[0], &bodies[1]);
    let delta = 1e-7;
    let tol = Tolerance::relative(1e-10).unwrap();
    let plain = stickslip_normal::NormalProblem::new(
        n,
        n,
        (h, h),
        &g0,
        bodies,
        stickslip_normal::Boundary::Free,
    )
    .unwrap()
    .with_tolerance(tol)
    .solve(NormalLoad::Approach(delta))
    .unwrap();
    let bonded = CoupledProblem::new(
        n,
        n,
        (h, h),
        &g0,
        bodies,
        1e4,
        Load::Force { magnitude: 0.0, angle: 0.0 },
    )
    .unwrap()
    .with_tolerance(tol)
    .solve(NormalLoad::Approach(delta))
    .unwrap();
    let got = bonded.normal.force / plain.force;
    let want = beta.atanh() / beta;
    let nu = 0.3f64;
    assert!((want - (1.0 - nu) * (3.0 - 4.0 * nu).ln() / (1.0 - 2.0 * nu)).abs() < 1e-12);
    let area = plain.area;
    let a_eff = (area / std::f64::consts::PI).sqrt();
    let e_star = 210e9 / (1.0 - nu * nu);
    eprintln!(
        "flat punch, {} cells in contact: frictionless P/(2 a E* delta) = {:.5} (a from the area), \
         bonded/frictionless = {got:.5} vs {want:.5} ({:+.2e}); {} passes",
        plain.contact_cells,
        plain.force / (2.0 * a_eff * e_star * delta),
        (got - want) / want,
        bonded.info.passes
    );
    assert!(bonded.tangential.regime == stickslip_traction::Regime::FullStick);
    assert!((got - want).abs() <= 2e-3 * want, "bonded/frictionless {got} vs {want}");
}
