//! Subsurface field on a lattice (`lattice::field`): FFT against the dense sum of exact
//! rectangle stresses, the Hertz sphere (Huber/Hamilton closed form, Johnson eq. 3.45 on the
//! axis), the sliding sphere against quadrature of Boussinesq + Cerruti over the Hertz
//! traction, a long strip against the 2D McEwen field, the periodic option against a direct
//! image sum, and bad input.
#![allow(clippy::needless_range_loop)] // stress components are indexed 0..6 in parallel arrays
use std::f64::consts::PI;
use stickslip_halfspace::hertz::sphere_field::hertz_sphere_stress;
use stickslip_halfspace::mcewen::stress_potential;
use stickslip_halfspace::point_load::{boussinesq_stress, cerruti_stress};
use stickslip_halfspace::Stress3;
use stickslip_lattice::Error;
use stickslip_lattice::{
    field::direct_stress, field::invariants, field::subsurface_field, field::Boundary,
    field::FieldConfig, field::Lattice, field::StressField, field::SurfaceTraction,
};
use stickslip_quad::{gauss_kronrod, AdaptiveConfig, Tolerance};

/// Tolerances of this file, each with its reason.
mod tol {
    /// FFT against the dense sum: both evaluate the same exact kernels; the FFT adds
    /// ~eps log N and the dense sum's far-field Gauss rule differs from the node corner sums
    /// by ~eps (d/h)^2 <= 1e-13 on these small lattices.
    pub const FFT_VS_DIRECT: f64 = 1e-12;
    /// Hertz sphere sampled at cell centres with 128 cells across the contact: the
    /// piecewise-constant sampling errs by O((h/a)^{3/2}) near the edge and O((h/z)^2) locally;
    /// the target on the axis is 0.5 %.
    pub const HERTZ_AXIS: f64 = 5e-3;
    /// Sliding sphere (f = 0.25, 0.5) against quadrature of the exact Hertz traction: the
    /// issue's 1 %, relative to p0.
    pub const SLIDING: f64 = 1e-2;
    /// Long strip (length 200 a) against plane-strain McEwen: sampling error as for the
    /// sphere plus the finite length, O((a/L)^2) = 2.5e-5; 1 % of p0.
    pub const STRIP: f64 = 1e-2;
    /// Periodic spectral kernel against the direct image sum over 41 x 41 periods: the
    /// truncated image tail of the absolutely convergent components (decaying like R^-4).
    pub const PERIODIC: f64 = 1e-5;
    /// A uniform traction on a periodic lattice: sigma_zz, sigma_xz, sigma_yz are the mean
    /// traction exactly (zero frequency only), up to the inverse FFT's rounding.
    pub const PERIODIC_UNIFORM: f64 = 1e-13;
    /// The classical maximum shear 0.31 p0 at z = 0.48 a is quoted to two digits.
    pub const TWO_DIGITS: f64 = 5e-3;
    /// Layers 0.01 a apart: the depth of the maximum is found to one layer spacing.
    pub const LAYER_SPACING: f64 = 0.011;
    /// The surface tensile peak p0 [(1 - 2 nu)/3 + pi (4 + nu) f / 8] against quadrature at
    /// z = 1e-6 a, which approaches it like sqrt(z/a) (0.4 % there).
    pub const SURFACE_PEAK: f64 = 1e-2;
}

fn comps(s: &Stress3) -> [f64; 6] {
    [s.xx, s.yy, s.zz, s.xy, s.xz, s.yz]
}

/// Deterministic pseudo-random values in [-1, 1].
fn noise(n: usize, seed: u64) -> Vec<f64> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((s >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        })
        .collect()
}

fn max_err(field: &StressField, want: impl Fn(usize, usize, usize) -> Stress3) -> f64 {
    let l = field.lattice;
    let mut worst = 0.0f64;
    for (li, layer) in field.layers.iter().enumerate() {
        let mut scale = 0.0f64;
        let mut errs = Vec::new();
        for j in 0..l.ny {
            for i in 0..l.nx {
                let k = j * l.nx + i;
                let got = comps(&layer.stress(k));
                let w = comps(&want(li, i, j));
                for c in 0..6 {
                    scale = scale.max(w[c].abs());
                    errs.push((got[c] - w[c]).abs());
                }
            }
        }
        let e = errs.iter().fold(0.0f64, |m, v| m.max(*v)) / scale;
        worst = worst.max(e);
    }
    worst
}

#[test]
fn fft_equals_direct_sum() {
    let l = Lattice::new(9, 7, 0.3, 0.2, -1.0, 0.5).unwrap();
    let n = l.len();
    let p: Vec<f64> = noise(n, 1).iter().map(|v| 1.0 + v).collect();
    let qx = noise(n, 2);
    let qy = noise(n, 3);
    let t = SurfaceTraction { p: &p, qx: &qx, qy: &qy };
    let depths = [0.01, 0.1, 0.3, 1.0, 3.0, 10.0];
    for parallel in [false, true] {
        let f = subsurface_field(
            l,
            0.3,
            &t,
            &depths,
            FieldConfig { boundary: Boundary::Free, parallel },
        )
        .unwrap();
        let e = max_err(&f, |li, i, j| {
            let (x, y) = l.centre(i, j);
            direct_stress(&l, 0.3, &t, x, y, depths[li]).unwrap()
        });
        println!("[FFT vs direct, parallel = {parallel}] max rel err {e:.3e}");
        assert!(e < tol::FFT_VS_DIRECT, "{e:e}");
    }
    // Only pressure (two loads absent): the same.
    let t1 = SurfaceTraction { p: &p, ..Default::default() };
    let f = subsurface_field(l, 0.25, &t1, &depths, FieldConfig::default()).unwrap();
    let e = max_err(&f, |li, i, j| {
        let (x, y) = l.centre(i, j);
        direct_stress(&l, 0.25, &t1, x, y, depths[li]).unwrap()
    });
    println!("[FFT vs direct, pressure only] max rel err {e:.3e}");
    assert!(e < tol::FFT_VS_DIRECT, "{e:e}");
    // Invariants are those of the tensor at each point.
    let layer = &f.layers[2];
    for k in 0..n {
        let inv = invariants(&layer.stress(k));
        assert_eq!(inv.von_mises, layer.von_mises[k]);
        assert_eq!(inv.tresca, layer.tresca[k]);
        assert_eq!(inv.principal[0], layer.max_principal[k]);
    }
}

/// Hertz pressure p0 sqrt(1 - r^2/a^2) on a (2m+1)^2 lattice, cell centre (m, m) at the origin,
/// `cells` cells per radius.
fn hertz_lattice(cells: usize, margin: usize) -> (Lattice, Vec<f64>, f64) {
    let a = 1.0;
    let h = a / cells as f64;
    let m = cells + margin;
    let n = 2 * m + 1;
    let l = Lattice::new(n, n, h, h, -(m as f64) * h, -(m as f64) * h).unwrap();
    let mut p = vec![0.0; n * n];
    for j in 0..n {
        for i in 0..n {
            let (x, y) = l.centre(i, j);
            p[j * n + i] = (1.0 - (x * x + y * y) / (a * a)).max(0.0).sqrt();
        }
    }
    (l, p, a)
}

#[test]
fn hertz_sphere_on_axis_and_max_shear() {
    let nu = 0.3;
    let (l, p, a) = hertz_lattice(64, 2);
    let c = l.nx / 2;
    let kc = c * l.nx + c;
    let zs: Vec<f64> = [0.1, 0.25, 0.5, 1.0, 2.0].iter().map(|v| v * a).collect();
    let f = subsurface_field(
        l,
        nu,
        &SurfaceTraction { p: &p, ..Default::default() },
        &zs,
        FieldConfig::default(),
    )
    .unwrap();
    let mut worst = 0.0f64;
    for layer in &f.layers {
        let z = layer.z;
        let zeta = z / a;
        let sz = -1.0 / (1.0 + zeta * zeta);
        let sr = -(1.0 + nu) * (1.0 - zeta * (1.0 / zeta).atan()) + 0.5 / (1.0 + zeta * zeta);
        let s = layer.stress(kc);
        let ez = (s.zz - sz).abs() / sz.abs();
        let er = (s.xx - sr).abs() / sr.abs();
        let ey = (s.yy - sr).abs() / sr.abs();
        println!("[Hertz axis] z/a = {zeta}: sigma_z {:.6} vs {sz:.6} ({ez:.2e}), sigma_r {:.6} vs {sr:.6} ({er:.2e})", s.zz, s.xx);
        worst = worst.max(ez).max(er).max(ey);
        // Off-axis points against the full closed form (Hamilton 1983), relative to p0.
        for &(di, dj) in &[(20usize, 0usize), (40, 30), (60, 0), (62, 10), (45, 45)] {
            let k = (c + dj) * l.nx + c + di;
            let (x, y) = l.centre(c + di, c + dj);
            let want = comps(&hertz_sphere_stress(a, 1.0, nu, x, y, z));
            let got = comps(&layer.stress(k));
            for q in 0..6 {
                let e = (got[q] - want[q]).abs();
                assert!(
                    e < tol::HERTZ_AXIS,
                    "off axis ({x}, {y}, {z}) comp {q}: {} vs {} ({e:e})",
                    got[q],
                    want[q]
                );
            }
        }
    }
    println!("[Hertz axis] max rel err {worst:.3e}");
    assert!(worst < tol::HERTZ_AXIS);

    // Maximum shear: 0.31 p0 at 0.48 a for nu = 0.3 (reference from the closed form on the
    // axis, searched finely; the classical two-digit values are checked in halfspace).
    let zs: Vec<f64> = (0..=16).map(|k| (0.40 + 0.01 * k as f64) * a).collect();
    let f = subsurface_field(
        l,
        nu,
        &SurfaceTraction { p: &p, ..Default::default() },
        &zs,
        FieldConfig::default(),
    )
    .unwrap();
    let m = f.maxima();
    let (mut best, mut zb) = (0.0, 0.0);
    for k in 0..=16000 {
        let z = (0.40 + 1e-5 * k as f64) * a;
        let s = hertz_sphere_stress(a, 1.0, nu, 0.0, 0.0, z);
        if 0.5 * (s.xx - s.zz) > best {
            best = 0.5 * (s.xx - s.zz);
            zb = z;
        }
    }
    println!("[Hertz max shear] lattice {:.5} p0 at z = {:.3} a, (x, y) = ({}, {}); closed form {best:.5} p0 at {zb:.4} a",
        m.tresca.value, m.tresca.z, m.tresca.x, m.tresca.y);
    assert!((m.tresca.value - best).abs() / best < tol::HERTZ_AXIS);
    assert!((m.tresca.z - zb).abs() <= tol::LAYER_SPACING * a);
    assert!(m.tresca.x.abs() < 1e-12 && m.tresca.y.abs() < 1e-12);
    assert!((m.tresca.value - 0.31).abs() < tol::TWO_DIGITS);
    assert!((m.tresca.z - 0.48).abs() < tol::LAYER_SPACING);
}

/// Adaptive Gauss–Kronrod with a relative tolerance.
fn gk(f: impl FnMut(f64) -> f64, a: f64, b: f64, bps: &[f64], rel: f64, abs: f64) -> f64 {
    let inside: Vec<f64> = bps.iter().copied().filter(|&p| p > a && p < b).collect();
    let cfg = AdaptiveConfig::new(Tolerance::new(abs, rel).unwrap())
        .with_breakpoints(inside)
        .unwrap()
        .with_max_subdivisions(5000)
        .unwrap();
    gauss_kronrod(f, a, b, &cfg).map(|e| e.value).unwrap_or_else(|e| panic!("quadrature: {e:?}"))
}

/// Stress under the Hertz traction p = p0 sqrt(1 - r^2/a^2), qx = f p, by quadrature of
/// Boussinesq + Cerruti (rho = a sin u, so the square-root edge is smooth).
fn sliding_quad(nu: f64, f: f64, x: f64, y: f64, z: f64) -> [f64; 6] {
    let a = 1.0;
    let th0 = y.atan2(x).rem_euclid(2.0 * PI);
    let r = x.hypot(y);
    let u0 = if r < a { (r / a).asin() } else { 0.5 * PI };
    let mut out = [0.0; 6];
    for (k, o) in out.iter_mut().enumerate() {
        *o = gk(
            |th| {
                let (s, c) = th.sin_cos();
                gk(
                    |u| {
                        let rho = a * u.sin();
                        let w = u.cos() * a * u.cos() * rho;
                        let (dx, dy) = (x - rho * c, y - rho * s);
                        let b = comps(&boussinesq_stress(nu, 1.0, dx, dy, z));
                        let q = comps(&cerruti_stress(nu, f, dx, dy, z));
                        w * (b[k] + q[k])
                    },
                    0.0,
                    0.5 * PI,
                    &[u0],
                    1e-10,
                    1e-12,
                )
            },
            0.0,
            2.0 * PI,
            &[th0],
            1e-10,
            1e-11,
        );
    }
    out
}

#[test]
fn sliding_sphere() {
    let nu = 0.3;
    let (l, _, a) = hertz_lattice(64, 8);
    // Cell averages of the Hertz pressure (40 x 40 midpoint sums per cell): the lattice then
    // carries the exact cell means, so near the contact edge the field converges like the
    // moments of the in-cell variation rather than like the centre sampling's edge shift.
    let mut p = vec![0.0; l.len()];
    for j in 0..l.ny {
        for i in 0..l.nx {
            let (x, y) = l.centre(i, j);
            let mut s = 0.0;
            for u in 0..40 {
                for v in 0..40 {
                    let xx = x + ((u as f64 + 0.5) / 40.0 - 0.5) * l.hx;
                    let yy = y + ((v as f64 + 0.5) / 40.0 - 0.5) * l.hy;
                    s += (1.0 - (xx * xx + yy * yy) / (a * a)).max(0.0).sqrt();
                }
            }
            p[j * l.nx + i] = s / 1600.0;
        }
    }
    let c = l.nx / 2;
    for f in [0.25, 0.5] {
        let qx: Vec<f64> = p.iter().map(|v| f * v).collect();
        let t = SurfaceTraction { p: &p, qx: &qx, ..Default::default() };
        let zs = [0.03 * a, 0.25 * a, 0.5 * a, 1.0 * a];
        let field = subsurface_field(l, nu, &t, &zs, FieldConfig::default()).unwrap();
        let mut worst = 0.0f64;
        for layer in &field.layers {
            for &(di, dj) in
                &[(0i64, 0i64), (-64, 0), (-40, 20), (32, 0), (64, 0), (-70, 0), (10, -50)]
            {
                let (i, j) = ((c as i64 + di) as usize, (c as i64 + dj) as usize);
                let (x, y) = l.centre(i, j);
                let want = sliding_quad(nu, f, x, y, layer.z);
                let got = comps(&layer.stress(j * l.nx + i));
                for q in 0..6 {
                    let e = (got[q] - want[q]).abs();
                    if e > worst {
                        worst = e;
                    }
                    assert!(
                        e < tol::SLIDING,
                        "f = {f}, ({x}, {y}, {}) comp {q}: {} vs {}",
                        layer.z,
                        got[q],
                        want[q]
                    );
                }
            }
        }
        println!("[sliding sphere f = {f}] max err / p0 = {worst:.3e}");
        // Trailing-edge tensile peak: largest principal stress on the shallowest layer near
        // x = -a, against the quadrature at the same point, and the surface closed form
        // p0 [(1 - 2 nu)/3 + pi (4 + nu) f / 8] (Johnson §7.2; Hamilton 1983) as z -> 0.
        let shallow = &field.layers[0];
        let mut best = (f64::NEG_INFINITY, 0usize);
        for (k, &v) in shallow.max_principal.iter().enumerate() {
            if v > best.0 {
                best = (v, k);
            }
        }
        let (i, j) = (best.1 % l.nx, best.1 / l.nx);
        let (x, y) = l.centre(i, j);
        let want = invariants(&{
            let w = sliding_quad(nu, f, x, y, shallow.z);
            Stress3 { xx: w[0], yy: w[1], zz: w[2], xy: w[3], xz: w[4], yz: w[5] }
        });
        let surface = (1.0 - 2.0 * nu) / 3.0 + PI * (4.0 + nu) * f / 8.0;
        // The surface value is approached like sqrt(z/a) (0.534, 0.549, 0.553 p0 at
        // z/a = 1e-4, 1e-5, 1e-6 for f = 0.25): at z = 1e-6 a it is within 0.5 %.
        let near_surface = sliding_quad(nu, f, -a, 0.0, 1e-6 * a)[0];
        println!("[sliding sphere f = {f}] tensile peak {:.5} p0 at ({x:.4}, {y:.4}, {:.3}); quadrature there {:.5}; surface closed form {surface:.5}, quadrature at (-a, 0, 1e-6 a) {near_surface:.5}",
            best.0, shallow.z, want.principal[0]);
        assert!((best.0 - want.principal[0]).abs() < tol::SLIDING * want.principal[0]);
        assert!((x + a).abs() < 0.1 * a && y.abs() < 1e-12, "peak at the trailing edge");
        assert!((near_surface - surface).abs() < tol::SURFACE_PEAK * surface);
    }
}

#[test]
fn long_strip_is_mcewen() {
    let nu = 0.3;
    let (a, f) = (1.0, 0.3);
    let cells = 64;
    let hx = a / cells as f64;
    let nx = 2 * (cells + 4) + 1;
    let (ny, hy) = (401, 0.5 * a);
    let l = Lattice::new(nx, ny, hx, hy, -((cells + 4) as f64) * hx, -200.0 * hy).unwrap();
    let mut p = vec![0.0; l.len()];
    for j in 0..ny {
        for i in 0..nx {
            let (x, _) = l.centre(i, j);
            p[j * nx + i] = (1.0 - x * x / (a * a)).max(0.0).sqrt();
        }
    }
    let qx: Vec<f64> = p.iter().map(|v| f * v).collect();
    let zs = [0.1 * a, 0.3 * a, 0.78 * a, 1.5 * a];
    let field = subsurface_field(
        l,
        nu,
        &SurfaceTraction { p: &p, qx: &qx, ..Default::default() },
        &zs,
        FieldConfig::default(),
    )
    .unwrap();
    let jc = ny / 2;
    let mut worst = 0.0f64;
    for layer in &field.layers {
        for i in (0..nx).step_by(8) {
            let (x, y) = l.centre(i, jc);
            assert!(y.abs() < 1e-12);
            let m = stress_potential(a, 1.0, f, x, layer.z);
            // 2D (x, depth) -> 3D (x, z); plane strain sigma_yy = nu (sigma_xx + sigma_zz).
            let want = [m.xx, nu * (m.xx + m.yy), m.yy, 0.0, m.xy, 0.0];
            let got = comps(&layer.stress(jc * nx + i));
            for q in 0..6 {
                let e = (got[q] - want[q]).abs();
                worst = worst.max(e);
                assert!(
                    e < tol::STRIP,
                    "x = {x}, z = {} comp {q}: {} vs {}",
                    layer.z,
                    got[q],
                    want[q]
                );
            }
        }
    }
    println!("[long strip vs McEwen] max err / p0 = {worst:.3e}");
}

#[test]
fn periodic_matches_image_sum() {
    let l = Lattice::new(8, 6, 0.25, 0.4, 0.0, 0.0).unwrap();
    let n = l.len();
    let p: Vec<f64> = noise(n, 7).iter().map(|v| 1.0 + v).collect();
    // Zero-mean shears: a mean shear's image sum converges only like 1/D (its exact periodic
    // value, sigma_xz = -mean qx, is checked separately below).
    let zero_mean = |v: Vec<f64>| {
        let m = v.iter().sum::<f64>() / v.len() as f64;
        v.into_iter().map(|x| x - m).collect::<Vec<f64>>()
    };
    let qx = zero_mean(noise(n, 8));
    let qy = zero_mean(noise(n, 9));
    let t = SurfaceTraction { p: &p, qx: &qx, qy: &qy };
    let zs = [0.2, 0.7];
    let f = subsurface_field(
        l,
        0.3,
        &t,
        &zs,
        FieldConfig { boundary: Boundary::Periodic, parallel: true },
    )
    .unwrap();
    let (lx, ly) = (l.nx as f64 * l.hx, l.ny as f64 * l.hy);
    let images = 20i32;
    let mut worst = 0.0f64;
    for (li, layer) in f.layers.iter().enumerate() {
        for &(i, j) in &[(0usize, 0usize), (3, 2), (7, 5)] {
            let (x, y) = l.centre(i, j);
            let mut want = [0.0; 6];
            for mi in -images..=images {
                for mj in -images..=images {
                    let s =
                        direct_stress(&l, 0.3, &t, x + mi as f64 * lx, y + mj as f64 * ly, zs[li])
                            .unwrap();
                    for (w, v) in want.iter_mut().zip(comps(&s)) {
                        *w += v;
                    }
                }
            }
            let got = comps(&layer.stress(j * l.nx + i));
            // sigma_zz, sigma_xz, sigma_yz decay like R^-4 or faster: absolutely convergent.
            for q in [2, 4, 5] {
                let e = (got[q] - want[q]).abs();
                worst = worst.max(e);
                assert!(
                    e < tol::PERIODIC,
                    "({x}, {y}, {}) comp {q}: {} vs {}",
                    zs[li],
                    got[q],
                    want[q]
                );
            }
        }
    }
    println!("[periodic vs image sum] max abs err {worst:.3e} (tractions O(1))");
    // Uniform shear and pressure on a periodic lattice: sigma_zz = -p, sigma_xz = -qx,
    // sigma_yz = -qy at every depth (equilibrium of a layer).
    let (pu, qxu, qyu) = (vec![1.5; n], vec![0.4; n], vec![-0.3; n]);
    let t = SurfaceTraction { p: &pu, qx: &qxu, qy: &qyu };
    let f = subsurface_field(
        l,
        0.3,
        &t,
        &[0.05, 0.5, 5.0],
        FieldConfig { boundary: Boundary::Periodic, parallel: false },
    )
    .unwrap();
    for layer in &f.layers {
        for k in 0..n {
            assert!((layer.zz[k] + 1.5).abs() < tol::PERIODIC_UNIFORM, "{}", layer.zz[k]);
            assert!((layer.xz[k] + 0.4).abs() < tol::PERIODIC_UNIFORM, "{}", layer.xz[k]);
            assert!((layer.yz[k] - 0.3).abs() < tol::PERIODIC_UNIFORM, "{}", layer.yz[k]);
        }
    }
}

#[test]
fn bad_input_is_an_error() {
    let l = Lattice::new(4, 3, 1.0, 1.0, 0.0, 0.0).unwrap();
    let p = vec![1.0; 12];
    let t = SurfaceTraction { p: &p, ..Default::default() };
    let cfg = FieldConfig::default();
    for z in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            subsurface_field(l, 0.3, &t, &[1.0, z], cfg),
            Err(Error::OutOfDomain { .. })
        ));
        assert!(direct_stress(&l, 0.3, &t, 0.0, 0.0, z).is_err());
    }
    let short = vec![1.0; 11];
    assert!(matches!(
        subsurface_field(l, 0.3, &SurfaceTraction { p: &p, qx: &short, qy: &[] }, &[1.0], cfg),
        Err(Error::LengthMismatch { name: "qx", expected: 12, got: 11 })
    ));
    let nan = vec![f64::NAN; 12];
    assert!(subsurface_field(
        l,
        0.3,
        &SurfaceTraction { p: &nan, ..Default::default() },
        &[1.0],
        cfg
    )
    .is_err());
    assert!(subsurface_field(l, 0.7, &t, &[1.0], cfg).is_err());
    assert!(subsurface_field(l, 0.3, &t, &[], cfg).is_err());
    assert!(Lattice::new(0, 3, 1.0, 1.0, 0.0, 0.0).is_err());
    assert!(Lattice::new(3, 3, -1.0, 1.0, 0.0, 0.0).is_err());
    assert!(Lattice::new(3, 3, 1.0, 1.0, f64::NAN, 0.0).is_err());
    let bad = Lattice { nx: 3, ny: 3, hx: 0.0, hy: 1.0, x0: 0.0, y0: 0.0 };
    assert!(subsurface_field(bad, 0.3, &t, &[1.0], cfg).is_err());
    // Empty traction: zero field, not an error.
    let f = subsurface_field(l, 0.3, &SurfaceTraction::default(), &[1.0], cfg).unwrap();
    assert!(f.layers[0].zz.iter().all(|v| *v == 0.0));
}

/// A contact grid maps onto the lattice: every element centre is its cell's centre and the
/// scattered arrays carry its values.
#[test]
fn lattice_from_contact_grid() {
    let g = stickslip_lattice::ContactGrid::hertz_circle(1.0, 10.0, 21).unwrap();
    let (l, cell) = Lattice::from_grid(&g).unwrap();
    let p = l.scatter(&cell, &g.pressure).unwrap();
    for (k, &c) in cell.iter().enumerate() {
        let (x, y) = l.centre(c % l.nx, c / l.nx);
        assert!((x - g.x[k]).abs() < 1e-12 && (y - g.y[k]).abs() < 1e-12);
        assert_eq!(p[c], g.pressure[k]);
    }
    let total: f64 = p.iter().sum::<f64>() * l.hx * l.hy;
    assert!((total - 10.0).abs() < 1e-9);
    assert!(matches!(l.scatter(&cell, &g.pressure[1..]), Err(Error::LengthMismatch { .. })));
    let f = subsurface_field(
        l,
        0.3,
        &SurfaceTraction { p: &p, ..Default::default() },
        &[0.5],
        FieldConfig::default(),
    )
    .unwrap();
    let (x, y) = l.centre(3, 7);
    let want = direct_stress(&l, 0.3, &SurfaceTraction { p: &p, ..Default::default() }, x, y, 0.5)
        .unwrap();
    let got = f.layers[0].stress(7 * l.nx + 3);
    assert!((got.zz - want.zz).abs() < 1e-12 * want.zz.abs().max(1.0));
}
