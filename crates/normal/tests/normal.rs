//! The normal-contact solver (issue 16, solver half): Hertz, flat punch, Westergaard, a dense
//! direct solve, force against displacement control, typed errors, and the hand-over of the
//! computed contact to the tangential solver. Every measured error is printed.

use std::f64::consts::PI;
use stickslip_halfspace::hertz::HertzEllipse;
use stickslip_halfspace::material::composite_modulus;
use stickslip_halfspace::rectangle::{pressure_uz, Compliance, Rect};
use stickslip_halfspace::Material;
use stickslip_normal::{Boundary, Error, NormalLoad, NormalProblem, NormalSolution};
use stickslip_traction::closed::Mindlin;
use stickslip_traction::{ElementState, FastProblem, Load, Tolerance};

mod common;
use common::{dense_active_set, dense_matrix};

/// Tolerances, each with its reason.
mod tol {
    /// Issue 16: Hertz peak pressure within 1 % at 128 cells across (also asserted at 64;
    /// measured 2e-4 at 64 and 5e-5 at 128: the discrete contact edge and the cell centre
    /// nearest the axis).
    pub const HERTZ_P0: f64 = 0.01;
    /// Issue 16: Hertz approach within 0.5 %.
    pub const HERTZ_APPROACH: f64 = 0.005;
    /// Issue 16: flat punch force F = 2 a E* delta within 0.5 % (a from the punch's cell
    /// area, the same discrete punch).
    pub const PUNCH: f64 = 0.005;
    /// Issue 16: Westergaard contact width and peak pressure within 1 %.
    pub const WESTERGAARD: f64 = 0.01;
    /// Westergaard full contact: one Fourier mode, which the periodic transfer solves exactly;
    /// the rest is the solver tolerance (1e-12) times the conditioning.
    pub const WESTERGAARD_FULL: f64 = 1e-8;
    /// Issue 16: the iterative solver against a dense direct solve, 1e-10 of the peak
    /// pressure (solver tolerance 1e-12 on the gap; the dense LU is good to ~1e-13).
    pub const DENSE: f64 = 1e-10;
    /// Force against displacement control: both solved to 1e-12 on the gap; the pressure
    /// differs by the gap residual times the conditioning of K on the contact (~1e3).
    pub const CONTROL: f64 = 1e-8;
}

fn steel() -> Material {
    Material::new(210e9, 0.3).unwrap()
}

/// Centre of cell k on an nx x ny lattice of side h centred on the origin.
fn centre(k: usize, nx: usize, ny: usize, h: f64) -> (f64, f64) {
    let (i, j) = (k % nx, k / nx);
    ((i as f64 + 0.5 - 0.5 * nx as f64) * h, (j as f64 + 0.5 - 0.5 * ny as f64) * h)
}

fn sphere_gap(nx: usize, ny: usize, h: f64, r: f64) -> Vec<f64> {
    (0..nx * ny)
        .map(|k| {
            let (x, y) = centre(k, nx, ny, h);
            (x * x + y * y) / (2.0 * r)
        })
        .collect()
}

fn tight() -> Tolerance {
    Tolerance::relative(1e-12).unwrap()
}

/// Hertz sphere with `across` cells across the contact diameter; returns the errors
/// (contact radius in cells, p0 relative, approach relative).
fn hertz(across: usize) -> (f64, f64, f64, NormalSolution) {
    let (m, r) = (steel(), 0.01);
    let es = composite_modulus(&m, &m);
    let a = 1e-4;
    let p = 4.0 * es * a * a * a / (3.0 * r);
    let h = 2.0 * a / across as f64;
    let side = across * 5 / 4 + 4;
    let g0 = sphere_gap(side, side, h, r);
    let s = NormalProblem::new(side, side, (h, h), &g0, [m, m], Boundary::Free)
        .unwrap()
        .with_tolerance(Tolerance::relative(1e-10).unwrap())
        .solve(NormalLoad::Force(p))
        .unwrap();
    let a_num = (s.area / PI).sqrt();
    let p0 = 3.0 * p / (2.0 * PI * a * a);
    let delta = a * a / r;
    let e = ((a_num - a) / h, s.peak_pressure / p0 - 1.0, s.approach / delta - 1.0);
    println!(
        "hertz {across} across ({side}^2, {} it, residual {:.1e}, {:.2} s): a {:+.3} cells, \
         p0 {:+.3e}, approach {:+.3e}, force {:+.1e}",
        s.info.iterations,
        s.info.residual,
        s.info.solve_seconds + s.info.setup_seconds,
        e.0,
        e.1,
        e.2,
        s.force / p - 1.0
    );
    (e.0, e.1, e.2, s)
}

#[test]
fn hertz_sphere_64_across() {
    let (ea, ep, ed, s) = hertz(64);
    assert!(ea.abs() <= 1.0, "contact radius {ea} cells");
    assert!(ep.abs() <= tol::HERTZ_P0, "p0 {ep}");
    assert!(ed.abs() <= tol::HERTZ_APPROACH, "approach {ed}");
    assert!(!s.touches_boundary && !s.no_contact);
    assert!(s.info.gap_residual <= 1e-10 && s.info.force_residual <= 1e-10);
    assert!(s.info.complementarity_residual <= s.info.gap_residual);
}

/// 128 cells across the contact (issue 16's resolution; 0.2 s, so not behind
/// `STICKSLIP_EXTENDED`).
#[test]
fn hertz_sphere_128_across() {
    let (ea, ep, ed, _) = hertz(128);
    assert!(ea.abs() <= 1.0, "contact radius {ea} cells");
    assert!(ep.abs() <= tol::HERTZ_P0, "p0 {ep}");
    assert!(ed.abs() <= tol::HERTZ_APPROACH, "approach {ed}");
}

/// Non-square cells (hx = 2 hy): the rectangle kernel takes them as they are. Hertz sphere
/// with 64 cells across along x and 128 along y.
#[test]
fn hertz_sphere_rectangular_cells() {
    let (m, r, a) = (steel(), 0.01, 1e-4);
    let es = composite_modulus(&m, &m);
    let p = 4.0 * es * a * a * a / (3.0 * r);
    let (hx, hy) = (2.0 * a / 64.0, 2.0 * a / 128.0);
    let (nx, ny) = (84usize, 164usize);
    let g0: Vec<f64> = (0..nx * ny)
        .map(|k| {
            let x = ((k % nx) as f64 + 0.5 - 0.5 * nx as f64) * hx;
            let y = ((k / nx) as f64 + 0.5 - 0.5 * ny as f64) * hy;
            (x * x + y * y) / (2.0 * r)
        })
        .collect();
    let s = NormalProblem::new(nx, ny, (hx, hy), &g0, [m, m], Boundary::Free)
        .unwrap()
        .solve(NormalLoad::Force(p))
        .unwrap();
    let ea = ((s.area / PI).sqrt() - a) / hx;
    let ep = s.peak_pressure / (3.0 * p / (2.0 * PI * a * a)) - 1.0;
    let ed = s.approach / (a * a / r) - 1.0;
    println!(
        "hertz on hx = 2 hy cells: a {ea:+.3} cells (hx), p0 {ep:+.2e}, approach {ed:+.2e} ({} it)",
        s.info.iterations
    );
    assert!(ea.abs() <= 1.0 && ep.abs() <= tol::HERTZ_P0 && ed.abs() <= tol::HERTZ_APPROACH);
}

/// Hertz ellipse (R'x = 10 mm, R'y = 30 mm) with 128 cells across the major axis: the
/// semi-axes from the outermost contact cells, the peak pressure and the approach against
/// `HertzEllipse` (Johnson §3.4, elliptic integrals).
#[test]
fn hertz_ellipse_128_across() {
    let m = steel();
    let es = composite_modulus(&m, &m);
    let (rx, ry) = (0.01, 0.03);
    let load = 20.0;
    let e = HertzEllipse::new(rx, ry, load, es).unwrap();
    let (a, b) = (e.semi_axis_x(), e.semi_axis_y());
    let h = 2.0 * a.max(b) / 128.0;
    let nx = (2.0 * a / h * 1.2) as usize / 2 * 2 + 4;
    let ny = (2.0 * b / h * 1.2) as usize / 2 * 2 + 4;
    let g0: Vec<f64> = (0..nx * ny)
        .map(|k| {
            let (x, y) = centre(k, nx, ny, h);
            x * x / (2.0 * rx) + y * y / (2.0 * ry)
        })
        .collect();
    let s = NormalProblem::new(nx, ny, (h, h), &g0, [m, m], Boundary::Free)
        .unwrap()
        .solve(NormalLoad::Force(load))
        .unwrap();
    let (mut xm, mut ym) = (0.0f64, 0.0f64);
    for k in (0..nx * ny).filter(|&k| s.contact[k]) {
        let (x, y) = centre(k, nx, ny, h);
        xm = xm.max(x.abs());
        ym = ym.max(y.abs());
    }
    // The contact edge lies within the half cell beyond the outermost contact centre.
    let (ea, eb) = ((xm + 0.5 * h - a) / h, (ym + 0.5 * h - b) / h);
    let ep = s.peak_pressure / e.max_pressure() - 1.0;
    let ed = s.approach / e.approach() - 1.0;
    println!(
        "hertz ellipse b/a = {:.3}, {nx}x{ny} ({} it, {:.2} s): a {ea:+.2} cells, b {eb:+.2} cells, \
         p0 {ep:+.2e}, approach {ed:+.2e}",
        b / a,
        s.info.iterations,
        s.info.setup_seconds + s.info.solve_seconds
    );
    assert!(ea.abs() <= 1.0 && eb.abs() <= 1.0, "semi-axes {ea}, {eb} cells");
    assert!(ep.abs() <= tol::HERTZ_P0, "p0 {ep}");
    assert!(ed.abs() <= tol::HERTZ_APPROACH, "approach {ed}");
}

#[test]
fn flat_punch_displacement_control() {
    let (m, rigid) = (steel(), Material::rigid());
    let es = composite_modulus(&m, &rigid);
    let cells = 40.0; // punch radius in cells
    let side = 96;
    let a = 1e-3;
    let h = a / cells;
    let g0: Vec<f64> = (0..side * side)
        .map(|k| {
            let (x, y) = centre(k, side, side, h);
            if x.hypot(y) < a {
                0.0
            } else {
                1.0
            }
        })
        .collect();
    let n_punch = g0.iter().filter(|&&g| g == 0.0).count();
    let a_eff = (n_punch as f64 * h * h / PI).sqrt();
    let delta = 1e-6;
    let s = NormalProblem::new(side, side, (h, h), &g0, [m, rigid], Boundary::Free)
        .unwrap()
        .with_tolerance(Tolerance::relative(1e-10).unwrap())
        .solve(NormalLoad::Approach(delta))
        .unwrap();
    let f = 2.0 * a_eff * es * delta;
    let e = s.force / f - 1.0;
    println!(
        "punch {cells} cells radius ({side}^2, {} it, residual {:.1e}): F {:+.3e} vs 2 a_eff E* d \
         (a_eff/a - 1 = {:+.1e}); {} of {n_punch} punch cells in contact",
        s.info.iterations,
        s.info.residual,
        e,
        a_eff / a - 1.0,
        s.contact_cells
    );
    assert!(e.abs() <= tol::PUNCH, "punch force {e}");
    assert_eq!(s.contact_cells, n_punch);
}

/// Westergaard's wave g0 = D (1 - cos 2 pi x / L) along x, periodic, n cells per wavelength.
fn westergaard(n: usize, mean: f64) -> (NormalSolution, f64) {
    let (m, rigid) = (steel(), Material::rigid());
    let es = composite_modulus(&m, &rigid);
    let (lambda, amp) = (1e-3, 1e-6);
    let pstar = PI * es * amp / lambda;
    let h = lambda / n as f64;
    let ny = 4;
    let g0: Vec<f64> = (0..n * ny)
        .map(|k| {
            let x = (k % n) as f64 * h + 0.5 * h - 0.5 * lambda;
            amp * (1.0 - (2.0 * PI * x / lambda).cos())
        })
        .collect();
    let p = mean * pstar * lambda * ny as f64 * h;
    let s = NormalProblem::new(n, ny, (h, h), &g0, [m, rigid], Boundary::Periodic)
        .unwrap()
        .with_tolerance(tight())
        .solve(NormalLoad::Force(p))
        .unwrap();
    (s, pstar)
}

#[test]
fn westergaard_full_contact() {
    let mean = 1.05;
    let (s, pstar) = westergaard(256, mean);
    let pmax = s.peak_pressure;
    let pmin = s.pressure.iter().copied().fold(f64::INFINITY, f64::min);
    let amp = 0.5 * (pmax - pmin) / pstar;
    // The cell centres sample the cosine; its extremes at the centres nearest x = 0, L/2.
    let sample = (PI / 256.0).cos();
    let e = amp / sample - 1.0;
    println!(
        "westergaard full contact at mean p = {mean} p*: fraction {}, pressure amplitude {e:+.2e} \
         from p* (residual {:.1e}, {} it)",
        s.fraction, s.info.residual, s.info.iterations
    );
    assert_eq!(s.fraction, 1.0);
    assert!(e.abs() <= tol::WESTERGAARD_FULL, "amplitude {e}");
    // Just below p*: not full contact.
    let (s, _) = westergaard(256, 0.98);
    assert!(s.fraction < 1.0);
}

#[test]
fn westergaard_partial_contact() {
    let n = 1024;
    for mean in [0.1, 0.3, 0.6] {
        let (s, pstar) = westergaard(n, mean);
        // Contact half-width a: p_mean = p* sin^2(pi a / L) (Johnson §13.2).
        let a = mean.sqrt().asin() / PI; // in wavelengths
        let a_num = 0.5 * s.fraction;
        let ea = a_num / a - 1.0;
        // Peak pressure 2 sqrt(p_mean p*) at x = 0 (the cell centres are h/2 from it).
        let x = 0.5 / n as f64;
        let (sa, sx) = ((PI * a).sin(), (PI * x).sin());
        let p0 = 2.0 * mean * pstar * (PI * x).cos() / (sa * sa) * (sa * sa - sx * sx).sqrt();
        let ep = s.peak_pressure / p0 - 1.0;
        println!(
            "westergaard {n} cells/wavelength, mean p = {mean} p*: half-width {ea:+.2e} \
             ({:+.2} cells), peak {ep:+.2e} ({} it, residual {:.1e})",
            (a_num - a) * n as f64,
            s.info.iterations,
            s.info.residual
        );
        assert!(ea.abs() <= tol::WESTERGAARD, "width {ea}");
        assert!(ep.abs() <= tol::WESTERGAARD, "peak {ep}");
    }
}

#[test]
fn against_dense_direct_solve() {
    let (m, rigid) = (steel(), Material::rigid());
    let (nx, ny, h, r) = (14usize, 11usize, 1e-5, 5e-3);
    // A sphere with a deterministic ripple and an offset centre: not symmetric.
    let mut seed = 12345u64;
    let g0: Vec<f64> = (0..nx * ny)
        .map(|k| {
            let (x, y) = centre(k, nx, ny, h);
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            let noise = (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            ((x - 0.7 * h).powi(2) + (y + 0.3 * h).powi(2)) / (2.0 * r) + 2e-9 * noise
        })
        .collect();
    let n = nx * ny;
    let c = Compliance::pair(&m, &rigid);
    let cell = Rect { x1: -0.5 * h, x2: 0.5 * h, y1: -0.5 * h, y2: 0.5 * h };
    let mut k = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            let (xi, yi) = centre(i, nx, ny, h);
            let (xj, yj) = centre(j, nx, ny, h);
            k[i * n + j] = pressure_uz(&c, &cell, xi - xj, yi - yj);
        }
    }
    let load = 4.0;
    let (pd, dd) = dense_active_set(&k, &g0, h * h, load);
    let s = NormalProblem::new(nx, ny, (h, h), &g0, [m, rigid], Boundary::Free)
        .unwrap()
        .with_tolerance(tight())
        .solve(NormalLoad::Force(load))
        .unwrap();
    let pmax = pd.iter().copied().fold(0.0, f64::max);
    let e = s.pressure.iter().zip(&pd).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max) / pmax;
    let ed = (s.approach - dd).abs() / dd;
    let cells = pd.iter().filter(|&&v| v > 0.0).count();
    println!(
        "dense free {nx}x{ny}: {cells} contact cells, max |p - p_dense| / p_max = {e:.1e}, \
         approach {ed:.1e} ({} it, residual {:.1e})",
        s.info.iterations, s.info.residual
    );
    assert!(e <= tol::DENSE && ed <= tol::DENSE, "pressure {e}, approach {ed}");
    assert_eq!(s.contact_cells, cells);

    // Periodic: the dense matrix from the operator's own columns (checks the iteration).
    let pb = NormalProblem::new(nx, ny, (h, h), &g0, [m, rigid], Boundary::Periodic)
        .unwrap()
        .with_tolerance(tight());
    let op = pb.operator();
    let kp = dense_matrix(&op);
    let load = 6.0;
    let (pd, dd) = dense_active_set(&kp, &g0, h * h, load);
    let s = pb.solve_with(&op, NormalLoad::Force(load), None).unwrap();
    let pmax = pd.iter().copied().fold(0.0, f64::max);
    let e = s.pressure.iter().zip(&pd).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max) / pmax;
    let ed = (s.approach - dd).abs() / dd.abs();
    println!(
        "dense periodic {nx}x{ny}: {} contact cells, pressure {e:.1e}, approach {ed:.1e} ({} it)",
        pd.iter().filter(|&&v| v > 0.0).count(),
        s.info.iterations
    );
    assert!(e <= tol::DENSE && ed <= tol::DENSE, "pressure {e}, approach {ed}");
}

#[test]
fn force_and_displacement_control_agree() {
    let m = steel();
    let (side, h, r) = (48usize, 2e-6, 0.01);
    let g0 = sphere_gap(side, side, h, r);
    let pb = NormalProblem::new(side, side, (h, h), &g0, [m, m], Boundary::Free)
        .unwrap()
        .with_tolerance(tight());
    let op = pb.operator();
    let f = pb.solve_with(&op, NormalLoad::Force(0.5), None).unwrap();
    let d = pb.solve_with(&op, NormalLoad::Approach(f.approach), None).unwrap();
    let e = f.pressure.iter().zip(&d.pressure).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max)
        / f.peak_pressure;
    let ef = d.force / f.force - 1.0;
    println!(
        "force vs displacement control: pressure {e:.1e}, force {ef:+.1e}, contact cells {} / {} \
         ({} / {} it)",
        f.contact_cells, d.contact_cells, f.info.iterations, d.info.iterations
    );
    assert!(e <= tol::CONTROL && ef.abs() <= tol::CONTROL);
    assert_eq!(f.contact, d.contact);
    // A warm start from the solution converges at once.
    let w = pb.solve_with(&op, NormalLoad::Force(0.5), Some(&f.pressure)).unwrap();
    assert!(w.info.iterations <= 2, "warm start {} it", w.info.iterations);

    // Periodic: Westergaard's wave in partial contact.
    let (f, _) = westergaard(256, 0.3);
    let g0: Vec<f64> = (0..256 * 4)
        .map(|k| {
            let x = (k % 256) as f64 * f.hx + 0.5 * f.hx - 0.5e-3;
            1e-6 * (1.0 - (2.0 * PI * x / 1e-3).cos())
        })
        .collect();
    let d = NormalProblem::new(
        256,
        4,
        (f.hx, f.hy),
        &g0,
        [steel(), Material::rigid()],
        Boundary::Periodic,
    )
    .unwrap()
    .with_tolerance(tight())
    .solve(NormalLoad::Approach(f.approach))
    .unwrap();
    let e = f.pressure.iter().zip(&d.pressure).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max)
        / f.peak_pressure;
    let ef = d.force / f.force - 1.0;
    println!("periodic force vs displacement control: pressure {e:.1e}, force {ef:+.1e}");
    assert!(e <= tol::CONTROL && ef.abs() <= tol::CONTROL);
    // Periodic full contact under displacement control has no finite force: refused.
    let mean = g0.iter().sum::<f64>() / g0.len() as f64;
    assert!(matches!(
        NormalProblem::new(
            256,
            4,
            (f.hx, f.hy),
            &g0,
            [steel(), Material::rigid()],
            Boundary::Periodic
        )
        .unwrap()
        .solve(NormalLoad::Approach(mean)),
        Err(Error::OutOfDomain { name: "approach", .. })
    ));
}

#[test]
fn typed_errors_and_outcomes() {
    let m = steel();
    let (side, h, r) = (32usize, 2e-6, 0.01);
    let g0 = sphere_gap(side, side, h, r);
    let pb = NormalProblem::new(side, side, (h, h), &g0, [m, m], Boundary::Free).unwrap();
    for bad in [0.0, -1.0, f64::NAN] {
        assert!(matches!(
            pb.solve(NormalLoad::Force(bad)),
            Err(Error::OutOfDomain { name: "normal force", .. })
        ));
    }
    // Gap never closes: zero load, said so.
    let s = pb.solve(NormalLoad::Approach(-1e-9)).unwrap();
    assert!(s.no_contact && s.force == 0.0 && s.contact_cells == 0);
    assert!(s.contact_grid().is_err());
    // A contact wider than the lattice: a result, said so.
    let s = pb.solve(NormalLoad::Force(2e3)).unwrap();
    assert!(s.touches_boundary);
    // Unresolved: a tiny load touches a handful of cells.
    match pb.solve(NormalLoad::Force(1e-6)) {
        Err(Error::UnresolvedContact { cells, minimum }) => {
            println!("unresolved: {cells} cells < {minimum}");
            assert!(cells < minimum);
        }
        other => panic!("expected UnresolvedContact, got {other:?}"),
    }
    // Not converged, with the residual.
    match pb.clone().with_max_iterations(2).solve(NormalLoad::Force(0.5)) {
        Err(Error::NotConverged { iterations: 2, residual, .. }) => assert!(residual > 1e-10),
        other => panic!("expected NotConverged, got {other:?}"),
    }
    assert!(matches!(
        pb.clone()
            .with_tolerance(Tolerance::relative(1e-14).unwrap())
            .solve(NormalLoad::Force(0.5)),
        Err(Error::ToleranceOutOfRange { .. })
    ));
    let mut nan = g0.clone();
    nan[7] = f64::NAN;
    assert!(matches!(
        NormalProblem::new(side, side, (h, h), &nan, [m, m], Boundary::Free),
        Err(Error::OutOfDomain { name: "initial gap", .. })
    ));
    assert!(matches!(
        NormalProblem::new(side, side + 1, (h, h), &g0, [m, m], Boundary::Free),
        Err(Error::LengthMismatch { .. })
    ));
    assert!(matches!(
        NormalProblem::new(
            side,
            side,
            (h, h),
            &g0,
            [Material::rigid(), Material::rigid()],
            Boundary::Free
        ),
        Err(Error::OutOfDomain { name: "bodies", .. })
    ));
}

/// Partial slip on the computed contact: the fast tangential solver on `contact_grid()`,
/// stick radius against Mindlin.
#[test]
fn partial_slip_on_computed_contact() {
    let m = steel();
    let (r, a) = (0.01, 1e-4);
    let es = composite_modulus(&m, &m);
    let p = 4.0 * es * a * a * a / (3.0 * r);
    let across = 40;
    let h = 2.0 * a / across as f64;
    let side = 52;
    let g0 = sphere_gap(side, side, h, r);
    let s = NormalProblem::new(side, side, (h, h), &g0, [m, m], Boundary::Free)
        .unwrap()
        .solve(NormalLoad::Force(p))
        .unwrap();
    let grid = s.contact_grid().unwrap();
    assert_eq!(grid.len(), s.contact_cells);
    assert!((grid.total_normal_force() / p - 1.0).abs() < 1e-9);
    let (f, ratio) = (0.3, 0.5);
    let sol = FastProblem::new(&grid, [m, m], f, Load::polar(ratio * f * p, 0.0).unwrap())
        .unwrap()
        .solve()
        .unwrap();
    let stick = sol.state.iter().filter(|s| **s == ElementState::Stick).count();
    let c = (stick as f64 * h * h / PI).sqrt();
    let mindlin = Mindlin::new(a, p, f, ratio * f * p).unwrap();
    let e = (c - mindlin.stick_radius()) / h;
    println!("partial slip on the computed contact: stick radius {e:+.2} cells from Mindlin");
    assert!(e.abs() <= 1.5, "stick radius {e} cells");
}
