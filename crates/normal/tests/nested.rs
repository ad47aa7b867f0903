//! The nested start and the spectral preconditioner of the normal solver (issue 30): the
//! nested solve against the exact dense active-set solution, against cold solves with and
//! without the preconditioner, against Hertz and Westergaard, and the hard cases (lattices
//! that cannot be coarsened, a contact that vanishes on the coarse level, periodic full
//! contact, a contact too small to resolve, thread counts). Every measured difference is
//! printed.

use std::f64::consts::PI;
use stickslip_halfspace::material::composite_modulus;
use stickslip_halfspace::rectangle::{pressure_uz, Compliance, Rect};
use stickslip_halfspace::Material;
use stickslip_normal::{
    Boundary, Error, Nesting, NormalLoad, NormalProblem, NormalSolution, Preconditioner, Tolerance,
};

mod common;
use common::{dense_active_set, dense_matrix, rough_periodic_gap};

/// Tolerances, each with its reason.
mod tol {
    /// Against the dense active-set solve (LU good to ~1e-13): the solver's gap residual
    /// 1e-12 times the conditioning of K on the contact (~1e2 at these sizes), relative to the
    /// peak pressure.
    pub const DENSE: f64 = 1e-10;
    /// Nested against cold solves of the same problem, both to a gap residual of 1e-10: two
    /// points within the tolerance of one solution differ by the residual times the
    /// conditioning of K on the contact set (measured up to 5e-10 of the peak pressure on
    /// the 128^2 rough surface; 4.4e-9 on the nested Hertz sphere).
    pub const STARTS: f64 = 1e-7;
    /// Westergaard full contact: one Fourier mode, exact under the periodic transfer; the
    /// rest is the tolerance (1e-12) times the conditioning.
    pub const WESTERGAARD_FULL: f64 = 1e-8;
    /// Hertz peak pressure and approach at 128 cells across: as issue 16's tests (measured
    /// 5e-5 and 3e-5).
    pub const HERTZ: f64 = 0.005;
}

fn steel() -> Material {
    Material::new(210e9, 0.3).unwrap()
}

fn tolerance(rel: f64) -> Tolerance {
    Tolerance::relative(rel).unwrap()
}

fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max)
}

/// Certified residuals within the tolerance (the solver's own claim, checked).
fn certified(s: &NormalSolution, tol: f64) {
    assert!(s.info.gap_residual <= tol, "gap residual {:e}", s.info.gap_residual);
    assert!(s.info.complementarity_residual <= tol, "compl {:e}", s.info.complementarity_residual);
    assert!(s.info.force_residual <= tol, "force residual {:e}", s.info.force_residual);
}

/// A sphere of radius `r` with a deterministic ripple and an off-centre apex on an
/// `nx` x `ny` lattice of cells `h`, centred.
fn rippled_sphere(nx: usize, ny: usize, h: f64, r: f64, ripple: f64) -> Vec<f64> {
    let mut seed = 12345u64;
    (0..nx * ny)
        .map(|k| {
            let x = ((k % nx) as f64 + 0.5 - 0.5 * nx as f64) * h;
            let y = ((k / nx) as f64 + 0.5 - 0.5 * ny as f64) * h;
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            let noise = (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            ((x - 0.7 * h).powi(2) + (y + 0.3 * h).powi(2)) / (2.0 * r) + ripple * noise
        })
        .collect()
}

/// The dense influence matrix of a free lattice (Love's rectangle between cell centres).
fn dense_free(nx: usize, ny: usize, h: f64, c: &Compliance) -> Vec<f64> {
    let n = nx * ny;
    let cell = Rect { x1: -0.5 * h, x2: 0.5 * h, y1: -0.5 * h, y2: 0.5 * h };
    let mut k = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            let dx = (i % nx) as f64 - (j % nx) as f64;
            let dy = (i / nx) as f64 - (j / nx) as f64;
            k[i * n + j] = pressure_uz(c, &cell, dx * h, dy * h);
        }
    }
    k
}

/// The nested solve (coarsened down to 6 cells a side, so that a lattice the dense solve can
/// handle has two coarser levels; odd sides coarsen with a short last cell) equals the exact
/// active-set solution, under force and under displacement control.
#[test]
fn nested_against_dense_active_set() {
    let (m, rigid) = (steel(), Material::rigid());
    let (nx, ny, h, r) = (27usize, 25usize, 1e-5, 1e-2);
    let g0 = rippled_sphere(nx, ny, h, r, 2e-9);
    let k = dense_free(nx, ny, h, &Compliance::pair(&m, &rigid));
    let load = 20.0;
    let (pd, dd) = dense_active_set(&k, &g0, h * h, load);
    let pmax = pd.iter().copied().fold(0.0, f64::max);
    let cells = pd.iter().filter(|&&v| v > 0.0).count();
    let pb = NormalProblem::new(nx, ny, (h, h), &g0, [m, rigid], Boundary::Free)
        .unwrap()
        .with_tolerance(tolerance(1e-12))
        .with_nesting(Nesting::Nested { min_cells: 6 });
    for load_kind in [NormalLoad::Force(load), NormalLoad::Approach(dd)] {
        let s = pb.solve(load_kind).unwrap();
        let e = max_diff(&s.pressure, &pd) / pmax;
        let ed = (s.approach - dd).abs() / dd;
        let ef = (s.force - load).abs() / load;
        let levels: Vec<_> = s.levels.iter().map(|l| (l.lattice, l.iterations)).collect();
        println!(
            "dense free {nx}x{ny} {load_kind:?}: {cells} contact cells, levels {levels:?}, fine {} it; \
             max |p - p_dense| / p_max {e:.1e}, approach {ed:.1e}, force {ef:.1e}",
            s.info.iterations
        );
        assert_eq!(s.info.levels, 2, "27 x 25 -> 14 x 13 -> 7 x 7");
        assert_eq!(s.levels[0].lattice, (7, 7));
        assert!(e <= tol::DENSE && ed <= tol::DENSE && ef <= tol::DENSE, "{e} {ed} {ef}");
        assert_eq!(s.contact_cells, cells);
        certified(&s, 1e-12);
    }

    // Periodic, even sides: the dense matrix from the operator's own columns.
    let (nx, ny) = (24usize, 20usize);
    let g0 = rippled_sphere(nx, ny, h, r, 2e-9);
    let pb = NormalProblem::new(nx, ny, (h, h), &g0, [m, rigid], Boundary::Periodic)
        .unwrap()
        .with_tolerance(tolerance(1e-12))
        .with_nesting(Nesting::Nested { min_cells: 5 });
    let op = pb.operator();
    let kp = dense_matrix(&op);
    let load = 30.0;
    let (pd, dd) = dense_active_set(&kp, &g0, h * h, load);
    let s = pb.solve_with(&op, NormalLoad::Force(load), None).unwrap();
    let pmax = pd.iter().copied().fold(0.0, f64::max);
    let e = max_diff(&s.pressure, &pd) / pmax;
    let ed = (s.approach - dd).abs() / dd.abs();
    println!(
        "dense periodic {nx}x{ny}: {} contact cells, {} levels, pressure {e:.1e}, approach {ed:.1e} ({} it)",
        pd.iter().filter(|&&v| v > 0.0).count(),
        s.info.levels,
        s.info.iterations
    );
    assert_eq!(s.info.levels, 2, "24 x 20 -> 12 x 10 -> 6 x 5");
    assert!(e <= tol::DENSE && ed <= tol::DENSE, "pressure {e}, approach {ed}");
    certified(&s, 1e-12);
}

/// A rough periodic surface (128^2, H = 0.8): the nested preconditioned solve, the cold
/// preconditioned solve and the cold solve without preconditioner (Polonsky & Keer's) find
/// the same contact and pressure; the nested one takes the fewest fine iterations.
#[test]
fn nested_matches_cold_solves_on_a_rough_surface() {
    let n = 128;
    let size = 1e-3;
    let (g0, cell) = rough_periodic_gap(n, size, 11);
    let pb = NormalProblem::new(
        n,
        n,
        (cell, cell),
        &g0,
        [steel(), Material::rigid()],
        Boundary::Periodic,
    )
    .unwrap()
    .with_tolerance(tolerance(1e-10));
    let load = NormalLoad::Force(300e6 * size * size);
    let nested = pb.solve(load).unwrap();
    let cold = pb.clone().with_nesting(Nesting::Cold).solve(load).unwrap();
    let plain = pb
        .clone()
        .with_nesting(Nesting::Cold)
        .with_preconditioner(Preconditioner::Identity)
        .solve(load)
        .unwrap();
    let pmax = plain.peak_pressure;
    let (e1, e2) = (
        max_diff(&nested.pressure, &plain.pressure) / pmax,
        max_diff(&cold.pressure, &plain.pressure) / pmax,
    );
    println!(
        "rough 128^2, contact {:.4}: nested {} levels ({} coarse it) + {} fine it; cold {} it; \
         unpreconditioned {} it; max |dp| / p_max nested {e1:.1e}, cold {e2:.1e}",
        nested.fraction,
        nested.info.levels,
        nested.info.coarse_iterations,
        nested.info.iterations,
        cold.info.iterations,
        plain.info.iterations
    );
    for s in [&nested, &cold, &plain] {
        certified(s, 1e-10);
    }
    assert_eq!(nested.info.levels, 2, "128 -> 64 -> 32");
    assert!(e1 <= tol::STARTS && e2 <= tol::STARTS, "{e1} {e2}");
    // The contact sets agree but for cells whose pressure is within the tolerance of zero.
    let differ: Vec<f64> = (0..n * n)
        .filter(|&k| nested.contact[k] != plain.contact[k])
        .map(|k| nested.pressure[k].max(plain.pressure[k]) / pmax)
        .collect();
    assert!(differ.iter().all(|&p| p <= tol::STARTS), "differing cells {differ:?}");
    assert!(nested.info.iterations < cold.info.iterations);
    assert!(cold.info.iterations < plain.info.iterations);
}

/// Hertz at 128 cells across the contact, nested (164 -> 82 -> 41): the closed form as in
/// issue 16's tests, and the cold solve.
#[test]
fn nested_hertz_sphere() {
    let (m, r) = (steel(), 0.01);
    let es = composite_modulus(&m, &m);
    let a = 1e-4;
    let p = 4.0 * es * a * a * a / (3.0 * r);
    let across = 128;
    let h = 2.0 * a / across as f64;
    let side = across * 5 / 4 + 4;
    let g0: Vec<f64> = (0..side * side)
        .map(|k| {
            let x = ((k % side) as f64 + 0.5 - 0.5 * side as f64) * h;
            let y = ((k / side) as f64 + 0.5 - 0.5 * side as f64) * h;
            (x * x + y * y) / (2.0 * r)
        })
        .collect();
    let pb = NormalProblem::new(side, side, (h, h), &g0, [m, m], Boundary::Free)
        .unwrap()
        .with_tolerance(tolerance(1e-10));
    let s = pb.solve(NormalLoad::Force(p)).unwrap();
    let cold = pb.clone().with_nesting(Nesting::Cold).solve(NormalLoad::Force(p)).unwrap();
    let p0 = 3.0 * p / (2.0 * PI * a * a);
    let (ep, ed) = (s.peak_pressure / p0 - 1.0, s.approach / (a * a / r) - 1.0);
    let e = max_diff(&s.pressure, &cold.pressure) / s.peak_pressure;
    println!(
        "nested Hertz {side}^2: {} levels, {} coarse + {} fine it (cold {} it); p0 {ep:+.1e}, \
         approach {ed:+.1e}; nested - cold {e:.1e} p_max",
        s.info.levels, s.info.coarse_iterations, s.info.iterations, cold.info.iterations
    );
    assert_eq!(s.info.levels, 2);
    assert!(ep.abs() <= tol::HERTZ && ed.abs() <= tol::HERTZ);
    assert!(e <= tol::STARTS);
    certified(&s, 1e-10);
}

/// Lattices that cannot be coarsened (all the way): a periodic lattice with an odd side is
/// solved cold; one whose half is odd stops after one level; a free lattice with odd sides
/// nests with a short last coarse cell (129 x 127 -> 65 x 64 -> 33 x 32). Each equals the
/// cold solve.
#[test]
fn lattices_that_cannot_be_coarsened() {
    let (m, rigid) = (steel(), Material::rigid());
    let h = 2e-6;
    for (nx, ny, boundary, levels) in [
        (129usize, 128usize, Boundary::Periodic, 0usize),
        (130, 132, Boundary::Periodic, 1),
        (129, 127, Boundary::Free, 2),
    ] {
        let g0 = rippled_sphere(nx, ny, h, 1e-3, 1e-9);
        let pb = NormalProblem::new(nx, ny, (h, h), &g0, [m, rigid], boundary)
            .unwrap()
            .with_tolerance(tolerance(1e-10));
        let load = NormalLoad::Force(2.0);
        let s = pb.solve(load).unwrap();
        let cold = pb.clone().with_nesting(Nesting::Cold).solve(load).unwrap();
        let e = max_diff(&s.pressure, &cold.pressure) / cold.peak_pressure;
        println!(
            "{nx}x{ny} {boundary:?}: {} levels {:?}, {} fine it (cold {}), contact {} cells, nested - cold {e:.1e}",
            s.info.levels,
            s.levels.iter().map(|l| l.lattice).collect::<Vec<_>>(),
            s.info.iterations,
            cold.info.iterations,
            s.contact_cells
        );
        assert_eq!(s.info.levels, levels);
        assert!(e <= tol::STARTS);
        certified(&s, 1e-10);
    }
}

/// A contact that vanishes on the coarse level: single low cells on a flat (displacement
/// control) average away on the 2 x 2 coarsened lattice, which then has no contact; the fine
/// lattice is solved cold and finds its contact.
#[test]
fn contact_vanishing_on_the_coarse_level() {
    let (m, rigid) = (steel(), Material::rigid());
    let (n, h) = (128usize, 1e-6);
    let mut g0 = vec![1e-7; n * n];
    for &(i, j) in &[(31usize, 40usize), (90, 77), (64, 64)] {
        g0[j * n + i] = 0.0;
    }
    let pb = NormalProblem::new(n, n, (h, h), &g0, [m, rigid], Boundary::Free)
        .unwrap()
        .with_tolerance(tolerance(1e-10))
        .with_min_contact_cells(1);
    // Each low cell overlaps by 5e-8; a coarse cell holding one has a mean gap of 7.5e-8.
    let load = NormalLoad::Approach(5e-8);
    let s = pb.solve(load).unwrap();
    let cold = pb.clone().with_nesting(Nesting::Cold).solve(load).unwrap();
    println!(
        "vanishing coarse contact: {} levels, {} contact cells, force {:.4e} N (cold {:.4e} N)",
        s.info.levels, s.contact_cells, s.force, cold.force
    );
    assert_eq!(s.info.levels, 0, "the coarse level had no contact: a cold start");
    assert_eq!(s.contact_cells, 3);
    assert_eq!(s.pressure, cold.pressure);
    certified(&s, 1e-10);
}

/// Periodic full contact under force control, nested: Westergaard's wave pressed flat
/// (128^2, the wave along x); the pressure is exactly mean + p* cos.
#[test]
fn nested_periodic_full_contact() {
    let (m, rigid) = (steel(), Material::rigid());
    let es = composite_modulus(&m, &rigid);
    let (lambda, amp, n) = (1e-3, 1e-6, 128usize);
    let h = lambda / n as f64;
    let pstar = PI * es * amp / lambda;
    let xs = |k: usize| (k % n) as f64 * h + 0.5 * h - 0.5 * lambda;
    let g0: Vec<f64> =
        (0..n * n).map(|k| amp * (1.0 - (2.0 * PI * xs(k) / lambda).cos())).collect();
    let mean = 1.05 * pstar;
    let s = NormalProblem::new(n, n, (h, h), &g0, [m, rigid], Boundary::Periodic)
        .unwrap()
        .with_tolerance(tolerance(1e-12))
        .solve(NormalLoad::Force(mean * lambda * lambda))
        .unwrap();
    let e = (0..n * n)
        .map(|k| (s.pressure[k] - mean - pstar * (2.0 * PI * xs(k) / lambda).cos()).abs())
        .fold(0.0, f64::max)
        / pstar;
    println!(
        "nested Westergaard full contact: {} levels, fraction {}, max |p - exact| / p* = {e:.1e} ({} it)",
        s.info.levels, s.fraction, s.info.iterations
    );
    assert!(s.info.levels >= 1);
    assert_eq!(s.contact_cells, n * n);
    assert!(e <= tol::WESTERGAARD_FULL);
}

/// A contact too small to resolve is refused after the nesting as before it: the coarse
/// levels accept any contact, the fine one applies the minimum.
#[test]
fn tiny_contact_refused_after_nesting() {
    let (m, r, n, h) = (steel(), 1e-2, 128usize, 1e-6);
    let g0: Vec<f64> = (0..n * n)
        .map(|k| {
            let x = ((k % n) as f64 + 0.5 - 0.5 * n as f64) * h;
            let y = ((k / n) as f64 + 0.5 - 0.5 * n as f64) * h;
            (x * x + y * y) / (2.0 * r)
        })
        .collect();
    let pb = NormalProblem::new(n, n, (h, h), &g0, [m, m], Boundary::Free).unwrap();
    match pb.solve(NormalLoad::Force(1e-5)) {
        Err(Error::UnresolvedContact { cells, minimum }) => {
            println!("tiny contact: {cells} cells < {minimum}, refused");
            assert!(cells < minimum);
        }
        Ok(s) => panic!("expected UnresolvedContact, got a contact of {} cells", s.contact_cells),
        Err(e) => panic!("expected UnresolvedContact, got {e}"),
    }
}

/// The nested solve gives the same bits for any number of threads (every sum in fixed
/// blocks or rows, added in order), and a warm start skips the coarse levels.
#[test]
fn thread_count_and_warm_start() {
    let n = 128;
    let size = 1e-3;
    let (g0, cell) = rough_periodic_gap(n, size, 5);
    let pb = NormalProblem::new(
        n,
        n,
        (cell, cell),
        &g0,
        [steel(), Material::rigid()],
        Boundary::Periodic,
    )
    .unwrap()
    .with_tolerance(tolerance(1e-10));
    let load = NormalLoad::Force(300e6 * size * size);
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| pb.solve(load).unwrap())
    };
    let (one, three) = (run(1), run(3));
    assert_eq!(one.pressure, three.pressure);
    assert_eq!(one.approach.to_bits(), three.approach.to_bits());
    let op = pb.operator();
    let warm = pb.solve_with(&op, load, Some(&one.pressure)).unwrap();
    println!(
        "threads 1 and 3: identical ({} levels, {} it); warm start {} levels, {} it",
        one.info.levels, one.info.iterations, warm.info.levels, warm.info.iterations
    );
    assert_eq!(warm.info.levels, 0);
    assert!(warm.info.iterations <= 2);
}

/// A lattice whose solve would need more memory than allowed is refused before anything is
/// planned, with the bytes it needs and the cells that would fit.
#[test]
fn memory_limit_refuses_before_solving() {
    let n = 256;
    let g0 = rippled_sphere(n, n, 1e-6, 1e-3, 0.0);
    let needed = NormalProblem::memory_bytes(n, n, Boundary::Free);
    let per_cell = needed as f64 / (8.0 * (n * n) as f64);
    println!("free {n}^2: {needed} bytes, {per_cell:.2} doubles per cell");
    assert!(per_cell < 12.0, "the solve's own memory must leave room for the gap within 13");
    let pb =
        NormalProblem::new(n, n, (1e-6, 1e-6), &g0, [steel(), Material::rigid()], Boundary::Free)
            .unwrap()
            .with_memory_limit(needed / 2);
    match pb.solve(NormalLoad::Force(1.0)) {
        Err(Error::MemoryExceeded { cells, needed: got, limit, fits }) => {
            assert_eq!((cells, got, limit), (n * n, needed, needed / 2));
            assert!(fits < cells / 2 + 1 && fits > cells / 3, "fits {fits}");
        }
        Ok(_) => panic!("a solve beyond the memory limit ran"),
        Err(e) => panic!("expected MemoryExceeded, got {e}"),
    }
    // At the limit it runs.
    let s = pb.with_memory_limit(needed).solve(NormalLoad::Force(1.0)).unwrap();
    assert!(s.contact_cells > 0);
    let periodic =
        NormalProblem::memory_bytes(n, n, Boundary::Periodic) as f64 / (8.0 * (n * n) as f64);
    println!("periodic {n}^2: {periodic:.2} doubles per cell");
    assert!(periodic < per_cell);
}
