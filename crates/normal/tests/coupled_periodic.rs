//! Dundurs coupling on a periodic surface: the periodic cross operator against the
//! plane-strain closed forms for sinusoidal loads, and the coupled solution in a period much
//! larger than the contact against the isolated (free-boundary) coupled solution.
//!
//! Reference (Johnson, Contact Mechanics, §2.x, plane strain, one body): a pressure
//! p0 cos(kx) moves the surface sideways by u_x = −(1 − 2ν)/(2Gk) p0 sin(kx); by Betti's
//! reciprocity a shear q0 cos(kx) lifts it by u_z = +(1 − 2ν)/(2Gk) q0 sin(kx). For two bodies
//! the coefficient is c3 = (1 − 2ν1)/G1 − (1 − 2ν2)/G2 (the relative displacement), and for a
//! wave along a direction k̂ the tangential part points along k̂ (u = −c3/(2|k|) k̂ sin).

use stickslip_halfspace::material::Compliance;
use stickslip_halfspace::Material;
use stickslip_normal::Boundary;
use stickslip_normal::NormalLoad;
use stickslip_normal::{CoupledProblem, CrossOperator};
use stickslip_traction::contract::Load;
use stickslip_traction::Tolerance;

#[test]
fn periodic_cross_operator_is_the_plane_strain_closed_form_on_sinusoids() {
    let (nx, ny, h) = (20usize, 16usize, 3e-5);
    let steel = Material::new(210e9, 0.3).unwrap();
    let alu = Material::new(70e9, 0.33).unwrap();
    let c = Compliance::pair(&steel, &alu);
    let c3 = 0.4 / steel.shear_modulus() - (1.0 - 0.66) / alu.shear_modulus();
    assert!((c.one_minus_two_nu / c3 - 1.0).abs() < 1e-12);
    let op = CrossOperator::periodic(nx, ny, (h, h), &c);
    let (lx, ly) = (nx as f64 * h, ny as f64 * h);
    for (mx, my) in [(1i32, 0i32), (0, 2), (3, -1), (-4, 5)] {
        let kx = 2.0 * std::f64::consts::PI * mx as f64 / lx;
        let ky = 2.0 * std::f64::consts::PI * my as f64 / ly;
        let k = kx.hypot(ky);
        let (mut cosv, mut sinv) = (vec![0.0; nx * ny], vec![0.0; nx * ny]);
        for j in 0..ny {
            for i in 0..nx {
                let ph = kx * i as f64 * h + ky * j as f64 * h;
                cosv[j * nx + i] = ph.cos();
                sinv[j * nx + i] = ph.sin();
            }
        }
        let scale = c3.abs() / (2.0 * k);
        let (ux, uy) = op.traction_from_pressure(&cosv);
        let zero = vec![0.0; nx * ny];
        let uzx = op.normal_from_traction(&cosv, &zero);
        let uzy = op.normal_from_traction(&zero, &cosv);
        let mut worst = 0.0f64;
        for m in 0..nx * ny {
            let s = sinv[m];
            worst = worst
                .max((ux[m] + c3 / (2.0 * k) * (kx / k) * s).abs())
                .max((uy[m] + c3 / (2.0 * k) * (ky / k) * s).abs())
                .max((uzx[m] - c3 / (2.0 * k) * (kx / k) * s).abs())
                .max((uzy[m] - c3 / (2.0 * k) * (ky / k) * s).abs());
        }
        assert!(worst < 1e-12 * scale, "wave ({mx}, {my}): {:.2e}", worst / scale);
    }
    // A uniform load moves nothing across (mean mode zero).
    let (ux, _) = op.traction_from_pressure(&vec![1.0; nx * ny]);
    assert!(ux.iter().all(|v| v.abs() < 1e-25));
}

#[test]
fn coupled_sphere_in_a_growing_period_approaches_the_isolated_contact() {
    // An aluminium sphere on steel (beta != 0) under a normal and a tangential force, its
    // contact about 32 cells across, in periods of 96 and 192 cells (same cells). The
    // periodic solution differs from the isolated one by the images and the zero mean; the
    // difference must fall (like 1/L^2 for the far field) as the period grows.
    let (h, r) = (2.5e-6, 0.01);
    let bodies = [Material::new(210e9, 0.3).unwrap(), Material::new(70e9, 0.33).unwrap()];
    let load = NormalLoad::Force(0.5);
    let tangential = Load::Force { magnitude: 0.05, angle: 0.0 };
    let diff = |n: usize| {
        let mut gap = vec![0.0; n * n];
        for j in 0..n {
            for i in 0..n {
                let x = -0.5 * n as f64 * h + (i as f64 + 0.5) * h;
                let y = -0.5 * n as f64 * h + (j as f64 + 0.5) * h;
                gap[j * n + i] = (x * x + y * y) / (2.0 * r);
            }
        }
        let solve = |boundary| {
            CoupledProblem::new(n, n, (h, h), &gap, bodies, 0.3, tangential)
                .unwrap()
                .with_tolerance(Tolerance::relative(1e-10).unwrap())
                .with_boundary(boundary)
                .solve(load)
                .unwrap()
        };
        let free = solve(Boundary::Free);
        let per = solve(Boundary::Periodic);
        assert!(per.info.passes > 1 && per.info.residual <= 1e-10);
        let fx: f64 = per.traction.iter().map(|t| t.0).sum::<f64>() * h * h;
        assert!((fx / 0.05 - 1.0).abs() < 1e-8, "{fx}");
        let pmax = free.normal.pressure.iter().copied().fold(0.0, f64::max);
        let dp = per
            .normal
            .pressure
            .iter()
            .zip(&free.normal.pressure)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max)
            / pmax;
        let dq = per
            .traction
            .iter()
            .zip(&free.traction)
            .map(|(a, b)| (a.0 - b.0).hypot(a.1 - b.1))
            .fold(0.0, f64::max)
            / pmax;
        println!(
            "n = {n}: periodic vs free coupled sphere, max |dp| {dp:.2e} p_max, max |dq| \
             {dq:.2e} p_max, passes {} vs {}",
            per.info.passes, free.info.passes
        );
        (dp, dq)
    };
    let (p1, q1) = diff(96);
    let (p2, q2) = diff(192);
    assert!(p2 < 0.5 * p1 && q2 < 0.5 * q1, "{p1:e} -> {p2:e}, {q1:e} -> {q2:e}");
    assert!(p2 < 0.01 && q2 < 0.01, "{p2:e} {q2:e}");
}

#[test]
fn periodic_and_free_cross_operators_differ_by_the_images_which_fall_as_the_period_grows() {
    // A Gaussian load of 6 cells at the centre of an n x n period, the displacements compared
    // within 10 cells of it. The periodic response differs from the isolated one by the
    // images and by the zero mean (for a 1/r kernel a correction of relative size about
    // pi r^2 / L^2), so the difference falls like 1/L^2: by about 4 from n = 64 to 128.
    let c =
        Compliance::pair(&Material::new(210e9, 0.3).unwrap(), &Material::new(70e9, 0.33).unwrap());
    let h = 1e-5;
    let gap = |n: usize| {
        let free = CrossOperator::new(n, n, (h, h), &c);
        let per = CrossOperator::periodic(n, n, (h, h), &c);
        let m = (n as f64 - 1.0) / 2.0;
        let mut p = vec![0.0; n * n];
        for j in 0..n {
            for i in 0..n {
                let (x, y) = (i as f64 - m, j as f64 - m);
                p[j * n + i] = (-(x * x + y * y) / 72.0).exp();
            }
        }
        let (fx, _) = free.traction_from_pressure(&p);
        let (px, _) = per.traction_from_pressure(&p);
        let fz = free.normal_from_traction(&p, &vec![0.0; n * n]);
        let pz = per.normal_from_traction(&p, &vec![0.0; n * n]);
        let big = |v: &[f64]| v.iter().map(|a| a.abs()).fold(0.0, f64::max);
        let mut worst = [0.0f64; 2];
        for j in n / 2 - 10..n / 2 + 10 {
            for i in n / 2 - 10..n / 2 + 10 {
                let k = j * n + i;
                worst[0] = worst[0].max((fx[k] - px[k]).abs() / big(&fx));
                worst[1] = worst[1].max((fz[k] - pz[k]).abs() / big(&fz));
            }
        }
        worst
    };
    let (w64, w128) = (gap(64), gap(128));
    println!("free vs periodic cross near the load: n = 64 {w64:?}, n = 128 {w128:?}");
    for (a, b) in w64.iter().zip(&w128) {
        assert!(*b < 0.03 && (3.0..5.0).contains(&(a / b)), "{a:e} -> {b:e}");
    }
}
