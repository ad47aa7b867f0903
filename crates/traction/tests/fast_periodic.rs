//! The fast solver on a periodic surface (issue 16: "free or periodic"): the operator of
//! `TensorConvolution::periodic` against the closed-form Fourier transfer of Cerruti's
//! solution, and the partial-slip solution in a large period against the isolated contact.
//!
//! The reference transfer is derived here from Cerruti's surface displacement for a
//! tangential point force Q along x (Johnson, Contact Mechanics, §3.2):
//! u_x = Q/(2πG r)·(1 − ν + ν x²/r²), u_y = Q/(2πG r)·ν x y/r². With the two-dimensional
//! transforms FT(1/r) = 2π/k, FT(x²/r³) = (2π/k)(1 − k̂x²) and FT(xy/r³) = −(2π/k) k̂x k̂y,
//! a traction cos(k·x) along x displaces the surface by
//! u_x = (1 − ν k̂x²)/(G k) cos(k·x) and u_y = −ν k̂x k̂y/(G k) cos(k·x); the relative
//! displacement of two bodies adds the two bodies' terms.

use stickslip_halfspace::Material;
use stickslip_lattice::influence::Compliance;
use stickslip_lattice::ContactGrid;
use stickslip_lattice::{PeriodicLattice, TensorConvolution};
use stickslip_traction::closed::Mindlin;
use stickslip_traction::{fast::FastConfig, fast::FastProblem};
use stickslip_traction::{ElementState, Error, Load, Tolerance};

#[test]
fn periodic_operator_is_cerruti_transfer_on_sinusoids() {
    let (nx, ny, h) = (24usize, 18usize, 2e-5);
    let steel = Material::new(210e9, 0.3).unwrap();
    let soft = Material::new(5e9, 0.45).unwrap();
    // The full period, listed from an origin off the lattice's own first cell and partly
    // beyond one period (the operator must wrap the indices).
    let origin = (3.0 * h, -5.0 * h);
    let mut mask_x = Vec::new();
    let mut mask_y = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            mask_x.push(origin.0 + (i as f64 + 7.0) * h);
            mask_y.push(origin.1 + (j as f64 - 4.0) * h);
        }
    }
    let grid = ContactGrid {
        hx: h,
        hy: h,
        x: mask_x,
        y: mask_y,
        pressure: vec![1.0; nx * ny],
        patch: vec![0; nx * ny],
    };
    let lattice = PeriodicLattice { cells: (nx, ny), origin };
    let c = Compliance::pair(&steel, &soft);
    let op = TensorConvolution::periodic(&grid, &c, &lattice).unwrap();
    let mut s = op.make_scratch();
    let n = grid.len();
    let (g1, g2) = (steel.shear_modulus(), soft.shear_modulus());
    let a = 1.0 / g1 + 1.0 / g2;
    let b = steel.poisson_ratio() / g1 + soft.poisson_ratio() / g2;
    let (lx, ly) = (nx as f64 * h, ny as f64 * h);
    for (mx, my) in [(1i32, 0i32), (0, 1), (3, 2), (-2, 5), (5, -4)] {
        let kx = 2.0 * std::f64::consts::PI * mx as f64 / lx;
        let ky = 2.0 * std::f64::consts::PI * my as f64 / ly;
        let k = kx.hypot(ky);
        let (ex, ey) = (kx / k, ky / k);
        let phase: Vec<f64> = (0..n)
            .map(|e| (kx * (grid.x[e] - origin.0) + ky * (grid.y[e] - origin.1)).cos())
            .collect();
        for along_x in [true, false] {
            let zero = vec![0.0; n];
            let (qx, qy) = if along_x { (&phase, &zero) } else { (&zero, &phase) };
            let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
            op.apply(qx, qy, &mut ux, &mut uy, &mut s);
            let (txx, txy, tyy) = ((a - b * ex * ex) / k, -b * ex * ey / k, (a - b * ey * ey) / k);
            let (cx, cy) = if along_x { (txx, txy) } else { (txy, tyy) };
            let scale = a / k;
            let err = (0..n)
                .map(|e| (ux[e] - cx * phase[e]).abs().max((uy[e] - cy * phase[e]).abs()))
                .fold(0.0, f64::max)
                / scale;
            assert!(err < 1e-12, "wave ({mx}, {my}) along x {along_x}: error {err:.2e}");
        }
    }
    // A uniform traction moves the periodic surface only rigidly (mean mode zero).
    let one = vec![1.0; n];
    let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
    op.apply(&one, &vec![0.0; n], &mut ux, &mut uy, &mut s);
    assert!(ux.iter().chain(&uy).all(|v| v.abs() < 1e-12 * a * h));
}

const P: f64 = 2160.0;
const F: f64 = 0.1;

#[test]
fn cattaneo_sphere_in_a_large_period_approaches_the_isolated_contact() {
    let steel = Material::new(30e6, 0.3).unwrap();
    let a = (3.0 * P * (2.0 * steel.normal_compliance()) / 4.0).cbrt();
    let across = 48;
    let grid = ContactGrid::hertz_circle(a, P, across).unwrap();
    let config = FastConfig::new(Tolerance::relative(1e-10).unwrap(), 100).unwrap();
    let ratio = 0.5;
    let load = Load::polar(ratio * F * P, 0.0).unwrap();
    let free = FastProblem::new(&grid, [steel, steel], F, load)
        .unwrap()
        .with_config(config)
        .solve()
        .unwrap();
    let q0 = 3.0 * F * P / (2.0 * std::f64::consts::PI * a * a);
    let mindlin = Mindlin::new(a, P, F, ratio * F * P).unwrap();
    let mut last = f64::INFINITY;
    for periods in [2usize, 4, 8] {
        let cells = periods * across;
        let lattice = PeriodicLattice { cells: (cells, cells), origin: (grid.x[0], grid.y[0]) };
        let sol = FastProblem::new(&grid, [steel, steel], F, load)
            .unwrap()
            .with_config(config)
            .with_periodic(lattice)
            .unwrap()
            .solve()
            .unwrap();
        assert!(sol.info.residual <= 1e-10 && sol.info.load_residual <= 1e-10, "{:?}", sol.info);
        assert_eq!(sol.info.levels, 0);
        // Equilibrium and Coulomb on every element.
        let h2 = grid.hx * grid.hy;
        let tx: f64 = sol.traction.iter().map(|t| t.0).sum::<f64>() * h2;
        assert!((tx / (ratio * F * P) - 1.0).abs() < 1e-9);
        for (t, p) in sol.traction.iter().zip(&grid.pressure) {
            assert!(t.0.hypot(t.1) <= F * p * (1.0 + 1e-9) + 1e-12 * q0);
        }
        let diff = sol
            .traction
            .iter()
            .zip(&free.traction)
            .map(|(p, f)| (p.0 - f.0).hypot(p.1 - f.1))
            .fold(0.0, f64::max)
            / q0;
        // The images' influence falls as the period grows.
        assert!(diff < last, "period {periods} diameters: {diff:.3e} after {last:.3e}");
        last = diff;
        let n_stick = sol.state.iter().filter(|s| **s == ElementState::Stick).count();
        let r_stick = (n_stick as f64 * h2 / std::f64::consts::PI).sqrt();
        let cells_off = (r_stick - mindlin.stick_radius()) / grid.hx;
        println!(
            "period {periods} diameters ({cells} cells): max |q_periodic - q_free| = \
             {diff:.3e} q0, stick radius {cells_off:+.2} cells from Mindlin, {} Newton, {} CG",
            sol.info.iterations, sol.info.cg_iterations
        );
        assert!(cells_off.abs() < 1.0, "stick radius {cells_off:+.2} cells from Mindlin");
    }
    assert!(last < 0.01, "8 diameters: {last:.3e} q0 from the isolated contact");
}

#[test]
fn periodic_surface_refuses_a_moment() {
    let steel = Material::new(210e9, 0.3).unwrap();
    let grid = ContactGrid::hertz_circle(1e-4, 10.0, 16).unwrap();
    let lattice = PeriodicLattice { cells: (32, 32), origin: (grid.x[0], grid.y[0]) };
    let load = Load::moment(1e-6, None).unwrap();
    let e = FastProblem::new(&grid, [steel, steel], 0.3, load)
        .unwrap()
        .with_periodic(lattice)
        .unwrap_err();
    assert!(matches!(e, Error::OutOfDomain { .. }), "{e}");
    // A period smaller than the grid holds two elements in one cell: refused when planned.
    let small = PeriodicLattice { cells: (8, 8), origin: (grid.x[0], grid.y[0]) };
    let pr = FastProblem::new(&grid, [steel, steel], 0.3, Load::polar(0.5, 0.0).unwrap())
        .unwrap()
        .with_periodic(small)
        .unwrap();
    // (The operator of the lattice refuses it: the error of `stickslip-lattice`, carried whole.)
    assert!(matches!(
        pr.solve().unwrap_err(),
        Error::Lattice(stickslip_lattice::Error::OutOfDomain { .. })
    ));
}

#[test]
fn the_contract_solves_a_periodic_surface_and_splits_the_shift_per_body() {
    use stickslip_traction::{FastSolver, GridProblem, GridSolver, ModifiedLp};
    // Two bodies of one Poisson ratio: each body's periodic transfer is (1/G_i)(I - nu k k),
    // so the substrate carries exactly (1/G_1) / (1/G_1 + 1/G_2) of the relative shift.
    let steel = Material::new(210e9, 0.3).unwrap();
    let alu = Material::new(70e9, 0.3).unwrap();
    let grid = ContactGrid::hertz_circle(1e-4, 10.0, 24).unwrap();
    let lattice = PeriodicLattice { cells: (64, 64), origin: (grid.x[0], grid.y[0]) };
    let problem = GridProblem::new(&grid, [steel, alu], 0.3).unwrap().with_periodic(lattice);
    let load = Load::polar(1.5, 0.3).unwrap();
    let sol = FastSolver::default().solve(&problem, &load).unwrap();
    assert_eq!(sol.periodic, Some(lattice));
    let share = sol.substrate_share(&grid, &[steel, alu], false, true).unwrap();
    let (g1, g2) = (steel.shear_modulus(), alu.shear_modulus());
    let want = (1.0 / g1) / (1.0 / g1 + 1.0 / g2);
    assert!((share / want - 1.0).abs() < 1e-9, "share {share} vs {want}");
    // The modified LP has no periodic images: refused, not solved as isolated.
    assert!(matches!(
        ModifiedLp::default().solve(&problem, &load).unwrap_err(),
        Error::OutOfDomain { .. }
    ));
}
