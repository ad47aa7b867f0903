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
