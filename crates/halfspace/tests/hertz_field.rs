//! The Hertz sphere's subsurface field (Huber; Hamilton 1983): against adaptive quadrature of
//! Boussinesq's point-force stresses over the Hertz pressure, the axis closed forms of Johnson
//! eq. 3.45, and the classical maximum shear 0.31 p0 at z = 0.48 a (nu = 0.3).
#![allow(clippy::needless_range_loop)] // stress components are indexed 0..6 in parallel arrays
mod common;
use common::quad::gk;
use common::{tol, ErrStats};
use std::f64::consts::PI;
use stickslip_halfspace::hertz::sphere_field::hertz_sphere_stress;
use stickslip_halfspace::hertz::HertzSphere;
use stickslip_halfspace::point_load::boussinesq_stress;
use stickslip_halfspace::Stress3;

const NU: f64 = 0.3;

fn comps(s: &Stress3) -> [f64; 6] {
    [s.xx, s.yy, s.zz, s.xy, s.xz, s.yz]
}

/// Boussinesq integrated over p0 sqrt(1 - rho^2/a^2): rho = a sin u (so p = p0 cos u and
/// d rho = a cos u du are smooth), theta in [0, 2 pi) split at the field point's azimuth.
fn quad_field(a: f64, p0: f64, x: f64, y: f64, z: f64, k: usize) -> f64 {
    let th0 = y.atan2(x).rem_euclid(2.0 * PI);
    let r = x.hypot(y);
    let u0 = if r < a { (r / a).asin() } else { 0.5 * PI };
    gk(
        |th| {
            let (s, c) = th.sin_cos();
            gk(
                |u| {
                    let rho = a * u.sin();
                    let w = p0 * u.cos() * a * u.cos() * rho;
                    w * comps(&boussinesq_stress(NU, 1.0, x - rho * c, y - rho * s, z))[k]
                },
                0.0,
                0.5 * PI,
                &[u0],
                1e-12,
                1e-14 * p0,
            )
        },
        0.0,
        2.0 * PI,
        &[th0],
        1e-12,
        1e-13 * p0,
    )
}

#[test]
fn field_vs_quadrature() {
    let (a, p0) = (1.0, 1.0);
    let pts = [
        (0.0, 0.0, 0.5),
        (0.3, 0.2, 0.5),
        (0.9, 0.0, 0.15),
        (1.2, 0.5, 0.3),
        (-0.5, 0.7, 1.5),
        (0.0, 0.6, 0.2),
        (0.7, -0.7, 0.1),
        (2.0, 1.0, 0.8),
        (1e-3, 0.0, 0.4),
    ];
    let mut st = ErrStats::new("Hertz sphere field vs quadrature of Boussinesq");
    for &(x, y, z) in &pts {
        let got = comps(&hertz_sphere_stress(a, p0, NU, x, y, z));
        for k in 0..6 {
            let want = quad_field(a, p0, x, y, z, k);
            st.add(got[k], want, p0, &format!("({x}, {y}, {z}) comp {k}"));
        }
    }
    st.check(tol::HERTZ_FIELD_QUAD);
}

/// On the axis: sigma_z = -p0/(1 + z^2/a^2), sigma_r = p0[-(1+nu)(1 - (z/a) atan(a/z)) +
/// 1/(2(1 + z^2/a^2))] (Johnson eq. 3.45), and the off-axis formula approaches them.
#[test]
fn axis_limits() {
    let s = HertzSphere::new(1000.0, 0.02, 1.1e11).unwrap();
    let (a, p0) = (s.contact_radius(), s.max_pressure());
    let mut st = ErrStats::new("Hertz axis");
    for zeta in [0.01, 0.1, 0.48, 1.0, 3.0, 10.0] {
        let z = zeta * a;
        let want_z = -p0 / (1.0 + zeta * zeta);
        let want_r =
            p0 * (-(1.0 + NU) * (1.0 - zeta * (1.0 / zeta).atan()) + 0.5 / (1.0 + zeta * zeta));
        let on = s.stress(NU, 0.0, 0.0, z).unwrap();
        st.add(on.zz, want_z, p0, "zz");
        st.add(on.xx, want_r, p0, "xx");
        st.add(on.yy, want_r, p0, "yy");
        // just off the axis: O(r^2/a^2) = 1e-6 difference, and the cancellation of the
        // off-axis form costs eps a^2/r^2 = 2e-10.
        let off = s.stress(NU, 1e-3 * a, 0.0, z).unwrap();
        st.add(off.zz, want_z, p0, "zz off");
        let e = (off.xx - want_r).abs() / p0;
        assert!(e < tol::HERTZ_NEAR_AXIS, "xx just off the axis: {e:e}");
    }
    st.check(tol::HERTZ_NEAR_AXIS);
    assert!(s.stress(NU, 0.0, 0.0, 0.0).is_err());
    assert!(s.stress(NU, f64::NAN, 0.0, 1.0).is_err());
    assert!(s.stress(0.6, 0.0, 0.0, 1.0).is_err());
}

/// The maximum shear (sigma_r - sigma_z)/2 on the axis: 0.31 p0 at z = 0.48 a for nu = 0.3
/// (Johnson §4.2, quoted to two digits).
#[test]
fn classical_max_shear() {
    let (mut best, mut zb) = (0.0, 0.0);
    for i in 1..2000 {
        let z = i as f64 * 1e-3;
        let s = hertz_sphere_stress(1.0, 1.0, NU, 0.0, 0.0, z);
        let t = 0.5 * (s.xx - s.zz);
        if t > best {
            best = t;
            zb = z;
        }
    }
    assert!((best - 0.31).abs() < 0.005, "max shear {best}");
    assert!((zb - 0.48).abs() < 0.005, "at z = {zb}");
}

/// The sliding sphere reference (closed-form pressure part + quadrature of Cerruti for the
/// shear): no shear gives the closed form; the surface traction is recovered as z -> 0; the
/// trailing-edge tension approaches its closed form; and a Cartesian nested quadrature of
/// Boussinesq + Cerruti (a different parametrisation) agrees.
#[test]
fn sliding_sphere_reference() {
    use stickslip_halfspace::hertz::sphere_field::{
        sliding_sphere_stress, sliding_trailing_edge_tension,
    };
    use stickslip_halfspace::point_load::cerruti_stress;
    let (a, p0) = (1.0, 1.0);
    let s0 = sliding_sphere_stress(a, p0, 0.0, NU, (0.3, 0.2, 0.5), 1e-10).unwrap();
    assert_eq!(s0.stress, hertz_sphere_stress(a, p0, NU, 0.3, 0.2, 0.5));
    let f = 0.25;
    // Surface limit inside the contact: sigma_xz -> -f p, sigma_zz -> -p (O(z) corrections).
    let (x, y) = (0.3, 0.2);
    let s = sliding_sphere_stress(a, p0, f, NU, (x, y, 1e-6), 1e-10).unwrap();
    let p = (1.0f64 - x * x - y * y).sqrt();
    assert!((s.stress.xz + f * p).abs() < tol::SLIDING_SURFACE, "{:?}", s.stress);
    assert!((s.stress.zz + p).abs() < tol::SLIDING_SURFACE, "{:?}", s.stress);
    // Trailing edge: sqrt(z/a) approach, 0.4 % at z = 1e-6 a.
    let t = sliding_sphere_stress(a, p0, f, NU, (-a, 0.0, 1e-6), 1e-10).unwrap();
    let want = sliding_trailing_edge_tension(p0, NU, f);
    assert!((t.stress.xx - want).abs() < 1e-2 * want, "{} vs {want}", t.stress.xx);
    // Cartesian nested quadrature of the shear part at two interior points.
    let mut st = ErrStats::new("sliding sphere reference vs Cartesian quadrature");
    for &(x, y, z) in &[(0.2, -0.3, 0.4), (-0.9, 0.1, 0.2), (1.3, 0.4, 0.6)] {
        let got = sliding_sphere_stress(a, p0, f, NU, (x, y, z), 1e-11).unwrap();
        assert!(got.error < 1e-9, "error estimate {}", got.error);
        let normal = comps(&hertz_sphere_stress(a, p0, NU, x, y, z));
        let g = comps(&got.stress);
        for k in 0..6 {
            let shear = gk(
                |xi| {
                    let w = (a * a - xi * xi).max(0.0).sqrt();
                    gk(
                        |eta| {
                            let q =
                                f * p0 * (1.0 - (xi * xi + eta * eta) / (a * a)).max(0.0).sqrt();
                            q * comps(&cerruti_stress(NU, 1.0, x - xi, y - eta, z))[k]
                        },
                        -w,
                        w,
                        &[y],
                        1e-11,
                        1e-13,
                    )
                },
                -a,
                a,
                &[x],
                1e-11,
                1e-12,
            );
            st.add(g[k], normal[k] + shear, p0, &format!("({x}, {y}, {z}) comp {k}"));
        }
    }
    st.check(tol::HERTZ_FIELD_QUAD);
    assert!(sliding_sphere_stress(a, p0, f, NU, (0.0, 0.0, 0.0), 1e-10).is_err());
    assert!(sliding_sphere_stress(a, p0, f, NU, (0.0, 0.0, 1.0), 1.0).is_err());
}
