//! Exact 3D steady rolling against independent references: Kalker's published creepage
//! coefficients (linear theory), saturation at full slip, Coulomb's law element by element,
//! the strip (Carter) limit of a contact long across the rolling direction, and FASTSIM's
//! linear limit.

use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
use stickslip_rolling::{
    steady3d::fastsim, steady3d::kalker, steady3d::Creepage, steady3d::RollingSolution,
    steady3d::SteadyRolling,
};

const G: f64 = 8e10;

fn material(nu: f64) -> Material {
    Material::new(2.0 * G * (1.0 + nu), nu).unwrap()
}

/// An ellipse of semi-axes a (rolling direction) and b = 1 mm with about `n` cells across
/// its longer axis, square cells.
fn ellipse(a_over_b: f64, n: usize, load: f64) -> (ContactGrid, f64, f64) {
    let b = 1e-3;
    let a = a_over_b * b;
    let h = 2.0 * a.max(b) / n as f64;
    let nx = ((2.0 * a / h).round() as usize).max(4);
    let ny = ((2.0 * b / h).round() as usize).max(4);
    (ContactGrid::hertz_ellipse(a, b, load, nx, ny).unwrap(), a, b)
}

/// (C11, C22, C23) of the linear theory on a grid of about `n` cells across.
fn coefficients(a_over_b: f64, nu: f64, n: usize) -> [f64; 3] {
    let (grid, a, b) = ellipse(a_over_b, n, 1e3);
    let m = material(nu);
    let p = SteadyRolling::new(&grid, [m, m], 0.3).unwrap().with_tolerance(1e-9).unwrap();
    let unit = 1e-4;
    let c = (a * b).sqrt();
    let s1 = p.solve_no_slip(&Creepage { longitudinal: unit, ..Default::default() }).unwrap();
    let s2 = p.solve_no_slip(&Creepage { lateral: unit, ..Default::default() }).unwrap();
    let s3 = p.solve_no_slip(&Creepage { spin: unit / c, ..Default::default() }).unwrap();
    let scale = G * a * b * unit;
    [-s1.fx / scale, -s2.fy / scale, -s3.fy / scale]
}

/// Kalker's C11, C22, C23 within 1.5 % for a/b = 0.5, 1, 2 and nu = 0, 0.25, 0.5. The grid
/// error is first order in the cell size (uniform elements, square-root traction singularity
/// at the trailing edge), so the estimate is the Richardson extrapolation 2 C(2n) - C(n) of
/// 40 and 80 cells across.
#[test]
fn linear_theory_reproduces_kalkers_coefficients() {
    let mut worst: f64 = 0.0;
    for &ab in &[0.5, 1.0, 2.0] {
        for &nu in &kalker::POISSON {
            let coarse = coefficients(ab, nu, 40);
            let fine = coefficients(ab, nu, 80);
            let k = kalker::coefficients(ab, nu).unwrap();
            for (i, reference) in [k.c11, k.c22, k.c23].into_iter().enumerate() {
                let extrapolated = 2.0 * fine[i] - coarse[i];
                let err = extrapolated / reference - 1.0;
                println!(
                    "a/b {ab} nu {nu} C{}: {:.4} (n=40 {:.4}, n=80 {:.4}) Kalker {reference} err {:+.2} %",
                    ["11", "22", "23"][i], extrapolated, coarse[i], fine[i], 100.0 * err
                );
                worst = worst.max(err.abs());
            }
        }
    }
    assert!(worst < 0.015, "largest deviation from Kalker's table {:.2} %", 100.0 * worst);
}

/// Coulomb's law on every element of a converged solution: |q| <= fp; stick elements do not
/// slip; slipping elements carry fp opposite to their slip.
fn assert_coulomb(s: &RollingSolution, f: f64, tol: f64) {
    let scale = s.sx.iter().chain(&s.sy).fold(0.0f64, |m, v| m.max(v.abs()));
    for k in 0..s.x.len() {
        let g = f * s.pressure[k];
        let q = s.qx[k].hypot(s.qy[k]);
        assert!(q <= g * (1.0 + tol) + 1e-12 * g.max(1.0), "element {k}: |q| {q} > fp {g}");
        let slip = s.sx[k].hypot(s.sy[k]);
        if s.stick[k] {
            assert!(
                slip <= 1e-4 * scale.max(1e-30),
                "stick element {k} slips {slip} (scale {scale})"
            );
        } else if slip > 1e-2 * scale && g > 0.0 {
            assert!((q / g - 1.0).abs() < 1e-6, "slip element {k}: |q|/fp = {}", q / g);
            let cos = -(s.qx[k] * s.sx[k] + s.qy[k] * s.sy[k]) / (q * slip);
            assert!(cos > 1.0 - 1e-6, "slip element {k}: traction not opposite to slip ({cos})");
        }
    }
}

#[test]
fn partial_slip_obeys_coulomb_and_saturates() {
    let (grid, a, b) = ellipse(1.0, 40, 1e3);
    let m = material(0.28);
    let f = 0.3;
    let p = SteadyRolling::new(&grid, [m, m], f).unwrap().with_tolerance(1e-10).unwrap();
    let fp = f * 1e3;
    let c = (a * b).sqrt();
    let mut last = 0.0;
    for xi in [2e-4, 6e-4, 1e-3, 3e-3] {
        let creep = Creepage { longitudinal: xi, lateral: 0.3 * xi, spin: 0.5 * xi / c };
        let s = p.solve(&creep).unwrap();
        assert!(s.info.residual <= 1e-10, "{:?}", s.info);
        assert_coulomb(&s, f, 1e-9);
        let force = s.fx.hypot(s.fy);
        println!("xi {xi}: |F| {force:.4} N, stick {:.3}, {:?}", s.stick_fraction(), s.info);
        assert!(force < fp, "|F| {force} at xi {xi}");
        // Below saturation the force grows with the creepage; once all slides, spin turns
        // it towards the rigid-slip limit below (not monotone).
        if s.stick_fraction() > 0.0 {
            assert!(force > last, "|F| {force} at xi {xi} after {last}");
        }
        last = force;
    }
    // Creepage so large that the elastic part of the slip is negligible: the traction is
    // fp against the rigid slip w, F = -sum fp w/|w| A (1e-3: elastic slip over rigid slip).
    let creep = Creepage { longitudinal: 5.0, lateral: 1.5, spin: 2.5 / c };
    let s = p.solve(&creep).unwrap();
    let (mut fx, mut fy) = (0.0, 0.0);
    for k in 0..s.x.len() {
        let w = creep.rigid_slip(s.x[k], s.y[k]);
        let wn = w[0].hypot(w[1]);
        fx -= f * s.pressure[k] * w[0] / wn * s.element_area;
        fy -= f * s.pressure[k] * w[1] / wn * s.element_area;
    }
    assert!((s.fx - fx).hypot(s.fy - fy) < 1e-3 * fp, "({}, {}) vs rigid ({fx}, {fy})", s.fx, s.fy);
    // Pure longitudinal creepage far beyond saturation: every element slides backwards and
    // |Fx| = fP (the element loads sum to P), up to the lateral elastic slip of the Poisson
    // coupling, which tilts the slip by about (elastic slip / creepage) ~ 1e-4 rad and so
    // changes |Fx| by ~1e-8 relative.
    let s = p.solve(&Creepage { longitudinal: 0.5, ..Default::default() }).unwrap();
    assert_eq!(s.stick_fraction(), 0.0);
    assert!((s.fx / -fp - 1.0).abs() < 1e-6 && s.fy.abs() < 1e-6 * fp, "F = ({}, {})", s.fx, s.fy);
    // Small creepage: the force per creepage tends to the linear theory's.
    let tiny = 1e-7;
    let s = p.solve(&Creepage { longitudinal: tiny, ..Default::default() }).unwrap();
    let lin = p.solve_no_slip(&Creepage { longitudinal: tiny, ..Default::default() }).unwrap();
    assert!((s.fx / lin.fx - 1.0).abs() < 1e-3, "{} vs {}", s.fx, lin.fx);
}

/// A contact long across the rolling direction (a/b = 0.05) rolls strip by strip as Carter's
/// 2D cylinders: strip y has half-width a_y = a sqrt(1 - y^2/b^2), peak pressure
/// p0_y = p0 a_y/a and saturates at xi_s(y) = 2(1 - nu) f p0_y / G (Carter, identical bodies:
/// xi_s = f a/R with a/R = 2(1 - nu) p0/G), below which its force is
/// f P'_y (1 - (1 - xi/xi_s)^2). The strip integral (midpoint rule, 20000 strips) against the
/// exact 3D solver at xi = 0.3 and 0.7 xi_s(0): within 3 % (the 3D effect at a/b = 0.05 and
/// the grid).
#[test]
fn long_contact_rolls_as_carter_strips() {
    let nu = 0.3;
    let f = 0.25;
    let (grid, a, b) = ellipse(0.05, 400, 1e3);
    let m = material(nu);
    let p0 = 3.0 * 1e3 / (2.0 * std::f64::consts::PI * a * b);
    let p = SteadyRolling::new(&grid, [m, m], f).unwrap().with_tolerance(1e-8).unwrap();
    let xi_s0 = 2.0 * (1.0 - nu) * f * p0 / G;
    for frac in [0.3, 0.7] {
        let xi = frac * xi_s0;
        let strips = 20000;
        let mut carter = 0.0;
        for i in 0..strips {
            let y = -b + (i as f64 + 0.5) * 2.0 * b / strips as f64;
            let r = (1.0 - (y / b).powi(2)).sqrt();
            let (ay, p0y) = (a * r, p0 * r);
            let load = std::f64::consts::PI * ay * p0y / 2.0;
            let xs = 2.0 * (1.0 - nu) * f * p0y / G;
            let ratio = if xi >= xs { 1.0 } else { 1.0 - (1.0 - xi / xs).powi(2) };
            carter += f * load * ratio * 2.0 * b / strips as f64;
        }
        let s = p.solve(&Creepage { longitudinal: xi, ..Default::default() }).unwrap();
        let err = -s.fx / carter - 1.0;
        println!(
            "xi/xi_s {frac}: exact {:.4} N, Carter strips {carter:.4} N, {:+.2} %",
            -s.fx,
            100.0 * err
        );
        assert!(err.abs() < 0.03, "{:.2} %", 100.0 * err);
    }
}

/// FASTSIM's flexibility is chosen so that its small-creepage forces are Kalker's linear
/// theory: F = -G a b C (creepage), to the grid's quadrature error (1 %).
#[test]
fn fastsim_reproduces_the_linear_theory_at_small_creepage() {
    let (grid, a, b) = ellipse(0.7, 80, 1e3);
    let nu = 0.25;
    let k = kalker::coefficients(a / b, nu).unwrap();
    let tiny = 1e-8;
    let c = (a * b).sqrt();
    for (creep, expected) in [
        (Creepage { longitudinal: tiny, ..Default::default() }, [-k.c11, 0.0]),
        (Creepage { lateral: tiny, ..Default::default() }, [0.0, -k.c22]),
        (Creepage { spin: tiny / c, ..Default::default() }, [0.0, -k.c23]),
    ] {
        let s = fastsim::solve(&grid, a, b, G, nu, 0.3, &creep).unwrap();
        let scale = G * a * b * tiny;
        let got = [s.fx / scale, s.fy / scale];
        for i in 0..2 {
            if expected[i] != 0.0 {
                assert!(
                    (got[i] / expected[i] - 1.0).abs() < 0.01,
                    "{creep:?}: {got:?} vs {expected:?}"
                );
            }
        }
    }
    // Beyond saturation FASTSIM also gives fP.
    let s =
        fastsim::solve(&grid, a, b, G, nu, 0.3, &Creepage { lateral: 1.0, ..Default::default() })
            .unwrap();
    assert!((s.fy / (-0.3 * 1e3) - 1.0).abs() < 1e-9);
}

/// The approximate theories against the exact one over a sweep of shapes and creepages: the
/// largest force error relative to fN stays within the bounds the planner relies on
/// (`FASTSIM_FORCE_ERROR`, `POLACH_FORCE_ERROR`).
#[test]
fn approximate_theories_stay_within_their_stated_error() {
    use stickslip_rolling::{
        steady3d::polach, steady3d::FASTSIM_FORCE_ERROR, steady3d::POLACH_FORCE_ERROR,
    };
    let nu = 0.28;
    let f = 0.3;
    let load = 1e4;
    let m = material(nu);
    let (mut worst_fastsim, mut worst_polach) = (0.0f64, 0.0f64);
    for ab in [0.3, 1.0, 3.0] {
        let (grid, a, b) = ellipse(ab, 40, load);
        let p0 = 1.5 * load / (std::f64::consts::PI * a * b);
        let scale = f * p0 / G;
        let exact = SteadyRolling::new(&grid, [m, m], f).unwrap().with_tolerance(1e-8).unwrap();
        let c = (a * b).sqrt();
        for dir in
            [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.7, 0.7, 0.0], [0.6, 0.3, 0.5]]
        {
            for s in [0.1, 0.3, 0.6, 1.0, 2.0, 5.0] {
                let creep = Creepage {
                    longitudinal: dir[0] * s * scale,
                    lateral: dir[1] * s * scale,
                    spin: dir[2] * s * scale / c,
                };
                let e = exact.solve(&creep).unwrap();
                let fs = fastsim::solve(&grid, a, b, G, nu, f, &creep).unwrap();
                worst_fastsim = worst_fastsim.max((fs.fx - e.fx).hypot(fs.fy - e.fy) / (f * load));
                if dir[2] == 0.0 {
                    let (px, py) = polach::forces(a, b, G, nu, load, f, &creep).unwrap();
                    worst_polach = worst_polach.max((px - e.fx).hypot(py - e.fy) / (f * load));
                }
            }
        }
    }
    println!("largest force error / fN: FASTSIM {worst_fastsim:.3}, Polach {worst_polach:.3}");
    assert!(worst_fastsim <= FASTSIM_FORCE_ERROR, "{worst_fastsim}");
    assert!(worst_polach <= POLACH_FORCE_ERROR, "{worst_polach}");
}

/// The nested start (the solution on the lattice coarsened 2 x 2 carried up) changes the
/// path of the iteration, not the answer: against the same problem solved from the
/// no-slip state on the fine lattice alone, at creepages from nearly linear to full slip,
/// on ellipses of 2:1 both ways, and at the smallest nested lattice (32 cells across).
/// Both answers meet the residual 1e-10, so their tractions differ by a few times that.
#[test]
fn the_nested_start_gives_the_answer_of_the_cold_start() {
    let m = material(0.28);
    let f = 0.3;
    for (a_over_b, n) in [(1.0, 96), (2.0, 80), (0.5, 80), (1.0, 32)] {
        let (grid, a, b) = ellipse(a_over_b, n, 1e3);
        let nested = SteadyRolling::new(&grid, [m, m], f).unwrap().with_tolerance(1e-10).unwrap();
        let cold = SteadyRolling::new(&grid, [m, m], f)
            .unwrap()
            .with_tolerance(1e-10)
            .unwrap()
            .without_nesting();
        let c = (a * b).sqrt();
        let p0 = 1.5 * 1e3 / (std::f64::consts::PI * a * b);
        for xi in [1e-5, 3e-4, 1e-3, 3e-3, 0.1] {
            let creep = Creepage { longitudinal: xi, lateral: -0.4 * xi, spin: 0.6 * xi / c };
            let s = nested.solve(&creep).unwrap();
            let r = cold.solve(&creep).unwrap();
            assert_coulomb(&s, f, 1e-9);
            let df = (s.fx - r.fx).hypot(s.fy - r.fy) / (f * 1e3);
            let dq =
                s.qx.iter()
                    .zip(&s.qy)
                    .zip(r.qx.iter().zip(&r.qy))
                    .map(|((x, y), (u, v))| (x - u).hypot(y - v))
                    .fold(0.0, f64::max)
                    / (f * p0);
            println!(
                "a/b {a_over_b}, {} elements, xi {xi}: nested {} Newton / {} products, cold {} / {}; \
                 forces {df:.1e} fP, tractions {dq:.1e} f p0",
                grid.len(),
                s.info.iterations,
                s.info.products,
                r.info.iterations,
                r.info.products
            );
            assert!(df <= 1e-9 && dq <= 1e-8, "a/b {a_over_b}, xi {xi}: {df:e} {dq:e}");
            assert!(s.info.residual <= 1e-10);
        }
    }
}
