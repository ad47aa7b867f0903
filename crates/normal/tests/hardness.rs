//! The hardness cap of the normal solver (issue 32, item 1): an elastic–perfectly plastic
//! interface, `0 <= p <= H`, the gap closed by plastic flow where `p = H`. Checked against
//! the exact dense active-set solution of the box-constrained problem, the flat punch pressed
//! fully plastic (closed-form displacement at its centre), the Hertz sphere below and above
//! the onset `p0 = H` (its load derived from Hertz here), and a periodic rough surface
//! (audited: cap, force, gap conditions from a fresh product; the contact fraction bound; a
//! cap far above the peak gives the elastic answer). Every measured difference is printed.

use std::f64::consts::PI;
use stickslip_halfspace::material::composite_modulus;
use stickslip_halfspace::Material;
use stickslip_normal::{
    Boundary, Error, Nesting, NormalLoad, NormalProblem, NormalSolution, Tolerance,
};

mod common;
use common::{dense_box_approach, dense_box_force, dense_matrix, rough_periodic_gap};

/// Tolerances, each with its reason.
mod tol {
    /// Against the dense active-set solve (LU to ~1e-13): the solver's residual 1e-12 times
    /// the conditioning of K on the free set (~1e2 at these sizes), relative to the cap.
    pub const DENSE: f64 = 1e-9;
    /// Capped solves against uncapped ones, or two controls of one problem, both to a gap
    /// residual of 1e-10: the residual times the conditioning of K on the contact set (as
    /// `nested.rs`'s STARTS).
    pub const SAME: f64 = 1e-7;
}

fn steel() -> Material {
    Material::new(210e9, 0.3).unwrap()
}

fn tolerance(rel: f64) -> Tolerance {
    Tolerance::relative(rel).unwrap()
}

/// Centre of cell k on an nx x ny lattice of side h centred on the origin.
/// Steel under a rigid periodic rough surface `g0` on `n` x `n` cells, tolerance 1e-10.
fn rough_problem(n: usize, cell: f64, g0: &[f64]) -> NormalProblem<'_> {
    NormalProblem::new(n, n, (cell, cell), g0, [steel(), Material::rigid()], Boundary::Periodic)
        .unwrap()
        .with_tolerance(tolerance(1e-10))
}

fn centre(k: usize, n: usize, h: f64) -> (f64, f64) {
    let (i, j) = (k % n, k / n);
    ((i as f64 + 0.5 - 0.5 * n as f64) * h, (j as f64 + 0.5 - 0.5 * n as f64) * h)
}

fn sphere_gap(n: usize, h: f64, r: f64) -> Vec<f64> {
    (0..n * n)
        .map(|k| {
            let (x, y) = centre(k, n, h);
            (x * x + y * y) / (2.0 * r)
        })
        .collect()
}

/// Independent audit of a capped solution: u = K p by a fresh product, and the conditions
/// p in [0, H], gap zero below the cap, open off the contact, closed (interpenetrating) at the
/// cap, each to `tol` of the gap scale; the force; the plastic displacement; returns the
/// largest gap violation relative to the scale.
fn audit(pb: &NormalProblem, s: &NormalSolution, h: f64, g0: &[f64], force: Option<f64>) -> f64 {
    let op = pb.operator();
    let mut u = vec![0.0; g0.len()];
    op.apply(&s.pressure, &mut u, &mut op.make_scratch());
    let gmin = g0.iter().copied().fold(f64::INFINITY, f64::min);
    let scale = s.approach - gmin;
    let mut worst: f64 = 0.0;
    for k in 0..g0.len() {
        let p = s.pressure[k];
        assert!((0.0..=h).contains(&p), "cell {k}: p = {p} outside [0, {h}]");
        let g = g0[k] + u[k] - s.approach;
        let v = if p == 0.0 {
            (-g).max(0.0)
        } else if p < h {
            g.abs()
        } else {
            // At the cap: interpenetration, which the plastic displacement removes.
            let w = s.plastic_displacement[k];
            assert!((w - (-g).max(0.0)).abs() <= 1e-9 * scale, "plastic displacement at {k}");
            g.max(0.0)
        };
        assert_eq!(s.plastic[k], p >= h);
        worst = worst.max(v / scale);
    }
    if let Some(f) = force {
        let sum: f64 = s.pressure.iter().sum::<f64>() * s.hx * s.hy;
        assert!((sum - f).abs() <= 1e-9 * f, "force {sum} against {f}");
    }
    let cells = s.contact.iter().filter(|&&c| c).count();
    let plastic = s.plastic.iter().filter(|&&c| c).count();
    assert_eq!(s.plastic_cells, plastic);
    assert!((s.plastic_fraction - plastic as f64 / cells as f64).abs() < 1e-15);
    worst
}

/// The exact dense solution of the box-constrained problem on small lattices (free and
/// periodic, force and approach control) against the solver, nested and cold.
#[test]
fn against_dense_box_active_set() {
    let (m, rigid) = (steel(), Material::rigid());
    let (n, h, r) = (16usize, 2e-6, 2e-3);
    // A sphere with a ripple, so that the plastic set and the contact edge are irregular.
    let g0: Vec<f64> = (0..n * n)
        .map(|k| {
            let (x, y) = centre(k, n, h);
            (x * x + y * y) / (2.0 * r) + 3e-9 * (x / 7e-6).sin() * (y / 5e-6).cos()
        })
        .collect();
    for boundary in [Boundary::Free, Boundary::Periodic] {
        let pb0 = NormalProblem::new(n, n, (h, h), &g0, [m, rigid], boundary)
            .unwrap()
            .with_tolerance(tolerance(1e-12))
            .with_min_contact_cells(1);
        let op = pb0.operator();
        let k = dense_matrix(&op);
        let elastic = pb0.solve(NormalLoad::Force(0.05)).unwrap();
        let cap = 0.6 * elastic.peak_pressure;
        let pb = pb0.clone().with_hardness(cap);
        for (load, dense_load) in
            [(NormalLoad::Force(0.05), Some(0.05)), (NormalLoad::Approach(elastic.approach), None)]
        {
            let (pd, dd) = match dense_load {
                Some(f) => dense_box_force(&k, &g0, h * h, f, cap),
                None => (dense_box_approach(&k, &g0, elastic.approach, cap), elastic.approach),
            };
            let plastic_dense = pd.iter().filter(|&&p| p >= cap).count();
            for nesting in [Nesting::Nested { min_cells: 4 }, Nesting::Cold] {
                let s = pb.clone().with_nesting(nesting).solve(load).unwrap();
                let e = pd.iter().zip(&s.pressure).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max)
                    / cap;
                let ed = (s.approach - dd).abs() / dd.abs();
                let worst = audit(&pb, &s, cap, &g0, dense_load);
                println!(
                    "dense {boundary:?} {load:?} {nesting:?}: {} plastic of {} contact cells \
                     (dense {plastic_dense}), pressure {e:.1e}, approach {ed:.1e}, audit gap \
                     {worst:.1e}, {} it, residual {:.1e}",
                    s.plastic_cells, s.contact_cells, s.info.iterations, s.info.residual
                );
                assert!(plastic_dense > 4, "the cap binds on several cells");
                assert_eq!(s.plastic_cells, plastic_dense);
                assert!(e <= tol::DENSE && ed <= tol::DENSE, "pressure {e}, approach {ed}");
                assert!(worst <= 1e-11, "audit {worst}");
            }
        }
    }
}

/// A flat square punch (the whole free lattice, zero gap) pressed to an approach beyond the
/// displacement that a uniform pressure H gives at its centre: every cell plastic, p = H, the
/// force H times the area, and the plastic displacement at the centre delta - u_c with the
/// closed form u_c = 8 a H ln(1 + sqrt 2) / (pi E*) of a uniformly loaded square of side 2a
/// at its centre (the integral of 1/r over the square). The elastic punch at that approach
/// has a mean pressure above H. Under force control just below H times the area the edges are
/// plastic first; at or above it the force is refused.
#[test]
fn flat_punch_fully_plastic() {
    let (m, rigid) = (steel(), Material::rigid());
    let es = composite_modulus(&m, &rigid);
    let (n, h) = (41usize, 1e-5);
    let a = 0.5 * n as f64 * h;
    let hard = 2e9;
    let g0 = vec![0.0; n * n];
    let uc = 8.0 * a * hard * (1.0 + 2f64.sqrt()).ln() / (PI * es);
    let delta = 1.5 * uc;
    let pb0 = NormalProblem::new(n, n, (h, h), &g0, [m, rigid], Boundary::Free)
        .unwrap()
        .with_tolerance(tolerance(1e-10));
    let elastic = pb0.solve(NormalLoad::Approach(delta)).unwrap();
    let mean_el = elastic.force / (4.0 * a * a);
    let pb = pb0.clone().with_hardness(hard);
    let s = pb.solve(NormalLoad::Approach(delta)).unwrap();
    let centre_k = (n / 2) * n + n / 2;
    let w_err = (s.plastic_displacement[centre_k] - (delta - uc)).abs() / (delta - uc);
    let f_err = (s.force - hard * 4.0 * a * a).abs() / (hard * 4.0 * a * a);
    println!(
        "punch: elastic mean pressure {:.3} H; capped: {} of {} cells plastic, force {f_err:.1e} \
         off H A, centre plastic displacement {w_err:.1e} off delta - u_c ({} it)",
        mean_el / hard,
        s.plastic_cells,
        n * n,
        s.info.iterations
    );
    assert!(mean_el > hard, "the elastic punch's mean pressure {mean_el} exceeds H");
    assert_eq!(s.plastic_cells, n * n);
    assert!(s.pressure.iter().all(|&p| p == hard));
    assert_eq!(s.plastic_fraction, 1.0);
    assert!(f_err < 1e-14, "force {f_err}");
    // Love's rectangles summed over the lattice are the uniform square exactly; the rest is
    // the FFT product's rounding.
    assert!(w_err < 1e-9, "centre plastic displacement {w_err}");
    audit(&pb, &s, hard, &g0, None);

    // Force control just below H A: the edge cells (the elastic punch's singular edge)
    // are plastic, the centre is not.
    let f = 0.98 * hard * 4.0 * a * a;
    let s = pb.solve(NormalLoad::Force(f)).unwrap();
    let worst = audit(&pb, &s, hard, &g0, Some(f));
    println!(
        "punch at 0.98 H A: {} plastic cells, audit {worst:.1e}, {} it",
        s.plastic_cells, s.info.iterations
    );
    assert!(s.plastic[0] && s.plastic[n - 1] && s.plastic[n * n - 1], "corners plastic");
    assert!(!s.plastic[centre_k], "centre elastic");
    assert!(worst <= 1e-9);
    match pb.solve(NormalLoad::Force(hard * 4.0 * a * a)) {
        Err(Error::AboveCapacity { .. }) => {}
        other => panic!("expected AboveCapacity, got {other:?}"),
    }
}

/// The Hertz sphere: p0 = (6 F E*^2 / (pi^3 R^2))^(1/3), so p0 reaches H at
/// F_Y = pi^3 R^2 H^3 / (6 E*^2). Below (p0 = 0.97 H) nothing is plastic and the capped
/// solution is the elastic one; above (p0 = 1.03 H) the centre is plastic; at 1.5, 2 and 3
/// F_Y the plastic zone is a disc about the centre that grows with the load, each one
/// containing the one before.
#[test]
fn hertz_sphere_onset_and_growth() {
    let (m, rigid) = (steel(), Material::rigid());
    let es = composite_modulus(&m, &rigid);
    let (r, hard) = (0.01, 2e9f64);
    let f_y = PI.powi(3) * r * r * hard.powi(3) / (6.0 * es * es);
    let a_y = PI * r * hard / (2.0 * es);
    let (n, h) = (160usize, 5e-6);
    println!("F_Y = {f_y:.3} N, a_Y = {:.1} cells", a_y / h);
    let g0 = sphere_gap(n, h, r);
    let pb0 = NormalProblem::new(n, n, (h, h), &g0, [m, rigid], Boundary::Free)
        .unwrap()
        .with_tolerance(tolerance(1e-10));
    let pb = pb0.clone().with_hardness(hard);

    // Below the onset.
    let f = f_y * 0.97f64.powi(3);
    let el = pb0.solve(NormalLoad::Force(f)).unwrap();
    let s = pb.solve(NormalLoad::Force(f)).unwrap();
    let e = el.pressure.iter().zip(&s.pressure).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max)
        / el.peak_pressure;
    println!(
        "0.97^3 F_Y: elastic peak {:.4} H, {} plastic, capped against elastic {e:.1e}",
        el.peak_pressure / hard,
        s.plastic_cells
    );
    assert_eq!(s.plastic_cells, 0);
    assert!(e <= tol::SAME, "{e}");

    // Above the onset: plastic from the centre (the four cells about it).
    let f = f_y * 1.03f64.powi(3);
    let s = pb.solve(NormalLoad::Force(f)).unwrap();
    let worst = audit(&pb, &s, hard, &g0, Some(f));
    println!("1.03^3 F_Y: {} plastic cells, audit {worst:.1e}", s.plastic_cells);
    let c = n / 2;
    for k in [(c - 1) * n + c - 1, (c - 1) * n + c, c * n + c - 1, c * n + c] {
        assert!(s.plastic[k], "centre cell {k} plastic");
    }
    assert!(worst <= 1e-9);

    // Growth.
    let mut before: Option<Vec<bool>> = None;
    let mut radius_before = 0.0;
    for ratio in [1.5, 2.0, 3.0] {
        let s = pb.solve(NormalLoad::Force(ratio * f_y)).unwrap();
        let worst = audit(&pb, &s, hard, &g0, Some(ratio * f_y));
        let pl: Vec<usize> = (0..n * n).filter(|&k| s.plastic[k]).collect();
        let (mut cx, mut cy, mut rmax) = (0.0, 0.0, 0.0f64);
        for &k in &pl {
            let (x, y) = centre(k, n, h);
            cx += x;
            cy += y;
            rmax = rmax.max(x.hypot(y));
        }
        cx /= pl.len() as f64;
        cy /= pl.len() as f64;
        // A disc: every cell whose centre lies within the equivalent radius less one cell
        // diagonal is plastic.
        let r_eq = (pl.len() as f64 * h * h / PI).sqrt();
        let inside_elastic =
            (0..n * n).filter(|&k| centre(k, n, h).0.hypot(centre(k, n, h).1) < r_eq - 1.5 * h);
        let holes = inside_elastic.filter(|&k| !s.plastic[k]).count();
        println!(
            "{ratio} F_Y: {} plastic cells, equivalent radius {:.2} cells ({:.3} a_Y), largest \
             {:.2} cells, centroid ({:.1e}, {:.1e}) cells, {holes} elastic cells inside, \
             contact radius {:.3} a_Y, audit {worst:.1e}, {} it",
            pl.len(),
            r_eq / h,
            r_eq / a_y,
            rmax / h,
            cx / h,
            cy / h,
            (s.area / PI).sqrt() / a_y,
            s.info.iterations
        );
        assert!(cx.abs() < 0.01 * h && cy.abs() < 0.01 * h, "centred");
        assert_eq!(holes, 0);
        assert!(rmax < r_eq + 1.5 * h, "a disc");
        assert!(r_eq > radius_before);
        if let Some(b) = &before {
            assert!((0..n * n).all(|k| !b[k] || s.plastic[k]), "grows from the centre");
        }
        assert!(worst <= 1e-9);
        before = Some(s.plastic.clone());
        radius_before = r_eq;
    }
}

/// The Hertz sphere under approach control with the cap near its elastic peak (0.9 to 2.3
/// times it): every solve converges (a cold capped iteration stalled there at residual 1 to
/// 3 before the capped approach solves started from the elastic solution), passes the
/// independent audit, and gives the elastic answer wherever the cap lies above the peak; at
/// 0.9 times the peak the centre is plastic and the force falls below the elastic one.
#[test]
fn hertz_sphere_under_approach_with_the_cap_near_the_peak() {
    let (m, rigid) = (steel(), Material::rigid());
    let (n, h, r) = (128usize, 5e-6, 0.01);
    let g0 = sphere_gap(n, h, r);
    let pb0 = NormalProblem::new(n, n, (h, h), &g0, [m, rigid], Boundary::Free)
        .unwrap()
        .with_tolerance(tolerance(1e-10));
    let d = 9e-6;
    let el = pb0.solve(NormalLoad::Approach(d)).unwrap();
    for ratio in [0.9, 1.05, 1.5, 2.3] {
        let cap = ratio * el.peak_pressure;
        let pb = pb0.clone().with_hardness(cap);
        let s = pb.solve(NormalLoad::Approach(d)).unwrap();
        let worst = audit(&pb, &s, cap, &g0, None);
        let e = el.pressure.iter().zip(&s.pressure).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max)
            / el.peak_pressure;
        println!(
            "cap {ratio} x peak: {} plastic cells, force {:.6e} N (elastic {:.6e}), against elastic {e:.1e}, audit {worst:.1e}, {} iterations",
            s.plastic_cells, s.force, el.force, s.info.iterations
        );
        assert!(worst <= 1e-9, "{worst}");
        if ratio > 1.0 {
            assert_eq!(s.plastic_cells, 0);
            assert!(e <= tol::SAME, "{e}");
        } else {
            assert!(s.plastic[(n / 2) * n + n / 2] && s.force < el.force);
        }
    }
}

/// A periodic rough surface at 300 MPa mean pressure with the cap at 0.3 of the elastic
/// peak: the cap holds everywhere, the force balances, the gap conditions hold from a fresh
/// product, the contact fraction is at least the mean pressure over H; force and approach
/// control agree; a cap ten times the elastic peak gives the elastic answer.
#[test]
fn periodic_rough_surface() {
    let (n, size) = (128, 1e-3);
    let (g0, cell) = rough_periodic_gap(n, size, 11);
    let pb0 = rough_problem(n, cell, &g0);
    let mean = 300e6;
    let f = mean * size * size;
    let el = pb0.solve(NormalLoad::Force(f)).unwrap();
    let hard = 0.3 * el.peak_pressure;
    let pb = pb0.clone().with_hardness(hard);
    let s = pb.solve(NormalLoad::Force(f)).unwrap();
    let worst = audit(&pb, &s, hard, &g0, Some(f));
    println!(
        "rough 128^2: elastic peak {:.2} GPa, {} it ({} coarse); cap {:.2} GPa: fraction {:.4} \
         (elastic {:.4}, bound p/H {:.4}), plastic fraction {:.3}, {} it ({} coarse), audit \
         {worst:.1e}",
        el.peak_pressure / 1e9,
        el.info.iterations,
        el.info.coarse_iterations,
        hard / 1e9,
        s.fraction,
        el.fraction,
        mean / hard,
        s.plastic_fraction,
        s.info.iterations,
        s.info.coarse_iterations
    );
    assert!(s.peak_pressure <= hard);
    assert!(s.fraction >= mean / hard);
    assert!(s.plastic_cells > 0 && s.fraction > el.fraction);
    assert!(worst <= 1e-9, "{worst}");

    let d = pb.solve(NormalLoad::Approach(s.approach)).unwrap();
    let e =
        d.pressure.iter().zip(&s.pressure).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max) / hard;
    println!(
        "approach control at the same approach: force {:.1e}, pressure {e:.1e}",
        d.force / f - 1.0
    );
    assert!((d.force / f - 1.0).abs() <= tol::SAME && e <= tol::SAME);
    audit(&pb, &d, hard, &g0, None);

    let high =
        pb0.clone().with_hardness(10.0 * el.peak_pressure).solve(NormalLoad::Force(f)).unwrap();
    let e = high.pressure.iter().zip(&el.pressure).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max)
        / el.peak_pressure;
    println!(
        "cap 10 x the elastic peak: {} plastic, pressure {e:.1e} from elastic",
        high.plastic_cells
    );
    assert_eq!(high.plastic_cells, 0);
    assert!(e <= tol::SAME && (high.approach / el.approach - 1.0).abs() <= tol::SAME);
}

/// Force control under the cap is one iteration with the force kept by projection (no
/// secant on the approach: `approach_steps` 0), down to the hard plastic shares of the
/// 1024² case (98 % of the contact at H there): on a 128² periodic rough surface, caps that
/// leave from a third to nearly all of the contact plastic. Each solve is audited from a
/// fresh product, and the approach-controlled capped solve at the approach found (the box
/// problem, another path) gives the same force and pressure.
#[test]
fn force_control_by_projection_at_hard_plastic_shares() {
    let (n, size) = (128, 1e-3);
    let (g0, cell) = rough_periodic_gap(n, size, 5);
    let pb0 = rough_problem(n, cell, &g0);
    let mean = 300e6;
    let f = mean * size * size;
    let el = pb0.solve(NormalLoad::Force(f)).unwrap();
    let mut shares = vec![];
    for ratio in [0.5, 0.2, 0.08] {
        let hard = ratio * el.peak_pressure;
        let pb = pb0.clone().with_hardness(hard);
        let s = pb.solve(NormalLoad::Force(f)).unwrap();
        let worst = audit(&pb, &s, hard, &g0, Some(f));
        let d = pb.solve(NormalLoad::Approach(s.approach)).unwrap();
        let e = d.pressure.iter().zip(&s.pressure).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max)
            / hard;
        println!(
            "cap {ratio} x the elastic peak: plastic share {:.3}, fraction {:.4}, {} it ({} \
             coarse), {} approach steps, audit {worst:.1e}; approach control: force {:.1e}, \
             pressure {e:.1e}",
            s.plastic_fraction,
            s.fraction,
            s.info.iterations,
            s.info.coarse_iterations,
            s.info.approach_steps,
            d.force / f - 1.0
        );
        assert_eq!(s.info.approach_steps, 0, "the projected iteration, not the secant");
        assert!(worst <= 1e-9, "{worst}");
        assert!(s.fraction >= mean / hard);
        assert!((d.force / f - 1.0).abs() <= tol::SAME && e <= tol::SAME);
        shares.push(s.plastic_fraction);
    }
    assert!(shares.windows(2).all(|w| w[1] > w[0]), "the plastic share grows: {shares:?}");
    assert!(shares[shares.len() - 1] > 0.95, "a hard plastic share reached: {shares:?}");
}

/// A hardness that is not a positive finite number is refused.
#[test]
fn hardness_refused() {
    let g0 = vec![0.0; 64];
    for h in [0.0, -1e9, f64::NAN, f64::INFINITY] {
        let pb = NormalProblem::new(8, 8, (1e-5, 1e-5), &g0, [steel(), steel()], Boundary::Free)
            .unwrap()
            .with_hardness(h);
        match pb.solve(NormalLoad::Force(1.0)) {
            Err(Error::OutOfDomain { name: "hardness", .. }) => {}
            other => panic!("hardness {h}: {other:?}"),
        }
    }
}
