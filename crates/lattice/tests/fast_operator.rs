//! The FFT convolution operator against the dense influence matrix (the naive reference):
//! the same kernel entries applied by a plain O(N^2) product.

mod fast_common;
use fast_common::{steel, tol};
use stickslip_halfspace::Material;
use stickslip_lattice::TensorConvolution;
use stickslip_lattice::{influence::tensor_matrix, influence::Compliance};
use stickslip_lattice::{ContactGrid, GridPatch, InfluenceModel, PatchPressure, Shape};

/// Deterministic pseudo-random numbers in [-1, 1) (64-bit LCG; no dependency).
fn lcg(seed: &mut u64) -> f64 {
    *seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
    ((*seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
}

fn check(name: &str, grid: &ContactGrid, c: &Compliance, model: InfluenceModel) -> f64 {
    let n = grid.len();
    let op = TensorConvolution::new(grid, c, model).unwrap();
    let mut scratch = op.make_scratch();
    let mut seed = 12345u64;
    let qx: Vec<f64> = (0..n).map(|_| lcg(&mut seed)).collect();
    let qy: Vec<f64> = (0..n).map(|_| lcg(&mut seed)).collect();
    let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
    op.apply(&qx, &qy, &mut ux, &mut uy, &mut scratch);
    // Dense: per unit force, so multiply the traction by the area.
    let a = tensor_matrix(grid, c, model);
    let area = grid.element_area();
    let m = 2 * n;
    let mut worst: f64 = 0.0;
    let mut worst_row = 0;
    let mut rms = 0.0;
    let mut umax: f64 = 0.0;
    let mut dense = vec![0.0; m];
    for (r, d) in dense.iter_mut().enumerate() {
        let row = &a[r * m..(r + 1) * m];
        *d = (0..n).map(|j| (row[2 * j] * qx[j] + row[2 * j + 1] * qy[j]) * area).sum();
        umax = umax.max(d.abs());
    }
    for k in 0..n {
        for (r, got) in [(2 * k, ux[k]), (2 * k + 1, uy[k])] {
            let e = (got - dense[r]).abs() / umax;
            rms += e * e;
            if e > worst {
                worst = e;
                worst_row = r;
            }
        }
    }
    rms = (rms / m as f64).sqrt();
    println!(
        "{name}: N = {n}, lattice {:?}, FFT {:?}: max |FFT - dense| / max|u| = {worst:.2e} \
         (row {worst_row}), RMS {rms:.2e}",
        op.lattice(),
        op.fft_size()
    );
    worst
}

#[test]
fn fft_product_matches_dense_matrix() {
    let s = steel();
    let c = Compliance::pair(&s, &s);
    let rubber = Material::new(1e6, 0.45).unwrap();
    let c2 = Compliance::pair(&s, &rubber);
    let cases: Vec<(&str, ContactGrid, Compliance, InfluenceModel)> = vec![
        (
            "Hertz circle 36 across",
            ContactGrid::hertz_circle(0.05, 1e3, 36).unwrap(),
            c,
            InfluenceModel::ExactRectangle,
        ),
        (
            "ellipse 30x12, steel/rubber",
            ContactGrid::hertz_ellipse(0.1, 0.04, 800.0, 30, 12).unwrap(),
            c2,
            InfluenceModel::ExactRectangle,
        ),
        (
            "rectangular cells, point-load model",
            ContactGrid::hertz_ellipse(0.1, 0.1, 800.0, 14, 26).unwrap(),
            c,
            InfluenceModel::PointLoad,
        ),
        (
            "two patches",
            ContactGrid::from_patches(
                0.01,
                0.01,
                (-0.3, -0.1),
                &[
                    GridPatch {
                        shape: Shape::Circle { cx: -0.15, cy: 0.0, r: 0.08 },
                        pressure: PatchPressure::Hertz { load: 100.0 },
                    },
                    GridPatch {
                        shape: Shape::Rectangle { cx: 0.12, cy: 0.03, wx: 0.1, wy: 0.06 },
                        pressure: PatchPressure::Uniform(1e4),
                    },
                ],
            )
            .unwrap(),
            c,
            InfluenceModel::ExactRectangle,
        ),
        (
            "single element",
            ContactGrid::from_mask(1.0, 2.0, (0.0, 0.0), 1, 1, &[true], &[1.0]).unwrap(),
            c,
            InfluenceModel::ExactRectangle,
        ),
    ];
    for (name, grid, cc, model) in &cases {
        let w = check(name, grid, cc, *model);
        assert!(w <= tol::FFT_VS_DENSE, "{name}: {w:e}");
    }
}

#[test]
fn off_lattice_grid_is_refused() {
    let s = steel();
    let c = Compliance::pair(&s, &s);
    let mut g = ContactGrid::uniform_square(1.0, 1.0, 4).unwrap();
    g.x[3] += 0.01;
    let e = TensorConvolution::new(&g, &c, InfluenceModel::ExactRectangle).unwrap_err();
    println!("{e}");
    assert!(matches!(e, stickslip_lattice::Error::OutOfDomain { .. }));
}

/// The preconditioner's transforms in single precision: the same operator as in double to
/// the rounding of single precision (relative 1e-6 of the largest output), symmetric to that
/// rounding ($x\cdot My = y\cdot Mx$), and sharing one scratch with the double-precision
/// operator changes neither's results.
#[test]
fn single_precision_preconditioner() {
    let s = steel();
    let c = Compliance::pair(&s, &s);
    let grid = ContactGrid::hertz_circle(0.05, 1e3, 40).unwrap();
    let n = grid.len();
    let op = TensorConvolution::new(&grid, &c, InfluenceModel::ExactRectangle).unwrap();
    let k0 = op.self_term()[0];
    let p64 = TensorConvolution::<f64>::inverse_symbol(&grid, &c, k0).unwrap();
    let p32 = TensorConvolution::<f32>::inverse_symbol(&grid, &c, k0).unwrap();
    let mut seed = 777u64;
    let v: Vec<Vec<f64>> = (0..4).map(|_| (0..n).map(|_| lcg(&mut seed)).collect()).collect();
    let zeros = || (vec![0.0; n], vec![0.0; n]);
    let (mut x64, mut y64) = zeros();
    p64.apply(&v[0], &v[1], &mut x64, &mut y64, &mut p64.make_scratch());
    let (mut x32, mut y32) = zeros();
    p32.apply(&v[0], &v[1], &mut x32, &mut y32, &mut p32.make_scratch());
    let big = x64.iter().chain(&y64).fold(0.0f64, |m, v| m.max(v.abs()));
    let diff = x64
        .iter()
        .zip(&x32)
        .chain(y64.iter().zip(&y32))
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    println!(
        "single vs double precision preconditioner: max difference / max value {:.2e}",
        diff / big
    );
    assert!(diff / big < 1e-6, "{:e}", diff / big);
    // Symmetry: v0 . M v2  against  v2 . M v0, in single precision.
    let (mut a, mut b) = zeros();
    p32.apply(&v[2], &v[3], &mut a, &mut b, &mut p32.make_scratch());
    let lhs: f64 = (0..n).map(|k| v[0][k] * a[k] + v[1][k] * b[k]).sum();
    let rhs: f64 = (0..n).map(|k| v[2][k] * x32[k] + v[3][k] * y32[k]).sum();
    let scale: f64 = (0..n).map(|k| (v[0][k] * a[k]).abs() + (v[1][k] * b[k]).abs()).sum();
    println!(
        "single precision: |x.My - y.Mx| / sum|x_k (My)_k| = {:.2e}",
        (lhs - rhs).abs() / scale
    );
    assert!((lhs - rhs).abs() / scale < 1e-6);
    // One scratch for the operator and both preconditioners: the same results to the bit.
    let (mut px, mut py) = zeros();
    op.apply(&v[0], &v[1], &mut px, &mut py, &mut op.make_scratch());
    let mut shared = op.make_scratch();
    let (mut ox, mut oy) = zeros();
    op.apply(&v[0], &v[1], &mut ox, &mut oy, &mut shared);
    let (mut sx, mut sy) = zeros();
    p32.apply(&v[0], &v[1], &mut sx, &mut sy, &mut shared);
    assert_eq!((&sx, &sy), (&x32, &y32));
    p64.apply(&v[0], &v[1], &mut sx, &mut sy, &mut shared);
    assert_eq!((&sx, &sy), (&x64, &y64));
    op.apply(&v[0], &v[1], &mut ox, &mut oy, &mut shared);
    assert_eq!((&ox, &oy), (&px, &py));
}

/// The operators of a lattice's coarsened lattices planned from its kernel are the ones
/// planned from scratch, to the bit (the coefficients are homogeneous of degree 1 in the cell
/// size and a power-of-two scaling is exact), for both influence models and oblong cells;
/// a cell size that is not the kernel's times a power of two is refused.
#[test]
fn coarse_operators_from_the_fine_kernel() {
    let s = steel();
    let c = Compliance::pair(&s, &s);
    for model in [InfluenceModel::ExactRectangle, InfluenceModel::PointLoad] {
        let fine = ContactGrid::hertz_ellipse(0.1, 0.07, 800.0, 200, 140).unwrap();
        let kernel = TensorConvolution::kernel(&fine, &c, model).unwrap();
        let (mid, _) = fine.coarsened(24).unwrap();
        let (coarse, _) = mid.coarsened(24).unwrap();
        for grid in [&fine, &mid, &coarse] {
            let direct = TensorConvolution::new(grid, &c, model).unwrap();
            let shared = TensorConvolution::from_kernel(grid, &kernel).unwrap();
            assert_eq!(direct.self_term(), shared.self_term());
            let n = grid.len();
            let mut seed = 99u64;
            let qx: Vec<f64> = (0..n).map(|_| lcg(&mut seed)).collect();
            let qy: Vec<f64> = (0..n).map(|_| lcg(&mut seed)).collect();
            let mut u = [vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]];
            let [ux, uy, vx, vy] = &mut u;
            direct.apply(&qx, &qy, ux, uy, &mut direct.make_scratch());
            shared.apply(&qx, &qy, vx, vy, &mut shared.make_scratch());
            assert!(ux == vx && uy == vy, "{model:?}, {} elements", n);
        }
        let mut off = coarse.clone();
        off.hx *= 1.5;
        off.x.iter_mut().for_each(|x| *x *= 1.5);
        let e = TensorConvolution::from_kernel(&off, &kernel).unwrap_err();
        println!("{e}");
        assert!(matches!(e, stickslip_lattice::Error::OutOfDomain { .. }));
    }
}
