//! Subsurface stress below a uniformly loaded rectangle (`rect_stress`): against nested
//! adaptive quadrature of the Boussinesq and Cerruti point-force stresses over the rectangle,
//! the surface limits, the far field (point force), and equilibrium of a layer.
#![allow(clippy::needless_range_loop)] // stress components are indexed 0..6 in parallel arrays
mod common;
use common::quad::gk;
use common::{tol, ErrStats};
use stickslip_halfspace::point_load::{boussinesq_stress, cerruti_stress};
use stickslip_halfspace::rect_stress::{
    checked_rect_stress, potential_derivatives, rect_stress, stress_from_potential, Traction,
};
use stickslip_halfspace::rectangle::Rect;
use stickslip_halfspace::{Error, Stress3};

const NU: f64 = 0.3;

fn comps(s: &Stress3) -> [f64; 6] {
    [s.xx, s.yy, s.zz, s.xy, s.xz, s.yz]
}

/// Point-force stress per unit force for one of the three unit tractions.
fn point(t: &Traction, x: f64, y: f64, z: f64) -> [f64; 6] {
    let mut out = [0.0; 6];
    if t.p != 0.0 {
        let s = comps(&boussinesq_stress(NU, t.p, x, y, z));
        out.iter_mut().zip(s).for_each(|(o, v)| *o += v);
    }
    if t.qx != 0.0 {
        let s = comps(&cerruti_stress(NU, t.qx, x, y, z));
        out.iter_mut().zip(s).for_each(|(o, v)| *o += v);
    }
    if t.qy != 0.0 {
        // Cerruti along y: swap the roles of x and y.
        let c = cerruti_stress(NU, t.qy, y, x, z);
        let s = [c.yy, c.xx, c.zz, c.xy, c.yz, c.xz];
        out.iter_mut().zip(s).for_each(|(o, v)| *o += v);
    }
    out
}

/// Field points around the rectangle [-0.5, 0.5] x [-0.25, 0.75] (x, y, z, tag).
const POINTS: [(f64, f64, f64, &str); 22] = [
    (0.1, 0.2, 0.3, "interior"),
    (0.0, 0.25, 0.5, "below centre"),
    (0.0, 0.25, 1e-3, "below centre, shallow"),
    (-0.375, 0.625, 0.05, "near corner, shallow"),
    (0.5, 0.1, 0.2, "below edge x2"),
    (0.5, 0.1, 1e-3, "below edge x2, shallow"),
    (-0.2, -0.25, 0.01, "below edge y1"),
    (0.5, 0.75, 0.1, "below corner"),
    (-0.5, -0.25, 1e-3, "below corner, shallow"),
    (0.7, 0.3, 0.2, "outside near"),
    (-0.5, 1.0, 0.4, "outside on edge line"),
    (0.5625, -0.3125, 0.02, "outside near corner"),
    (0.0, 0.25, 2.0, "deep"),
    (0.3, -0.1, 5.0, "deep, just below switch"),
    (0.3, -0.1, 7.0, "deep, far rule"),
    (0.0, 0.25, 50.0, "very deep"),
    (2.0, -1.0, 0.5, "lateral"),
    (5.0, -3.0, 1.0, "far lateral"),
    (6.2, 0.1, 0.3, "just beyond switch"),
    (5.9, 0.1, 0.3, "just inside switch"),
    (-20.0, 40.0, 3.0, "far 40"),
    (0.05, 0.3, 1e-2, "interior shallow"),
];

/// Nested adaptive Gauss–Kronrod over the rectangle (relative 1e-11) with breakpoints at the
/// field point's projection and at offsets z, 10 z, 100 z from it, where the point-force
/// kernel (width ~z) changes scale.
fn nested(f: impl Fn(f64, f64) -> f64, r: &Rect, (x, y, z): (f64, f64, f64), abs: f64) -> f64 {
    let bps = |c: f64| -> Vec<f64> {
        let mut v = vec![c];
        for k in [1.0, 10.0, 100.0] {
            v.push(c - k * z);
            v.push(c + k * z);
        }
        v
    };
    let (bx, by) = (bps(x), bps(y));
    gk(
        |xi| gk(|eta| f(xi, eta), r.y1, r.y2, &by, 1e-11, (abs * 0.1).max(1e-14 / z)),
        r.x1,
        r.x2,
        &bx,
        1e-11,
        abs,
    )
}

fn check_vs_quad(t: Traction, name: &str) {
    let r = Rect::new(-0.5, 0.5, -0.25, 0.75).unwrap();
    let mut st = ErrStats::new(name);
    for &(x, y, z, tag) in &POINTS {
        let got = comps(&rect_stress(NU, &r, &t, x, y, z));
        // Absolute floor of the quadrature: 1e-14 of the stress scale of the resultant force
        // (or of the traction itself near the surface).
        let d2 = x * x + (y - 0.25) * (y - 0.25) + z * z;
        let floor = 1e-12 * (r.area() / (2.0 * std::f64::consts::PI * d2)).min(1.0);
        let want: Vec<f64> = (0..6)
            .map(|k| nested(|xi, eta| point(&t, x - xi, y - eta, z)[k], &r, (x, y, z), floor))
            .collect();
        let scale = want.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for k in 0..6 {
            st.add(got[k], want[k], scale, &format!("{tag} ({x}, {y}, {z}) comp {k}"));
        }
    }
    st.check(tol::RECT_VS_QUAD);
}

#[test]
fn pressure_vs_quadrature() {
    check_vs_quad(Traction::PRESSURE, "rect stress, pressure vs quadrature");
}

#[test]
fn shear_x_vs_quadrature() {
    check_vs_quad(Traction::SHEAR_X, "rect stress, shear x vs quadrature");
}

#[test]
fn shear_y_vs_quadrature() {
    check_vs_quad(Traction::SHEAR_Y, "rect stress, shear y vs quadrature");
}

#[test]
fn combined_is_superposition() {
    let r = Rect::new(-0.5, 0.5, -0.25, 0.75).unwrap();
    let t = Traction { p: 2.0, qx: -0.5, qy: 0.25 };
    let mut st = ErrStats::new("superposition");
    for &(x, y, z, tag) in &POINTS {
        let got = comps(&rect_stress(NU, &r, &t, x, y, z));
        let a = comps(&rect_stress(NU, &r, &Traction::PRESSURE, x, y, z));
        let b = comps(&rect_stress(NU, &r, &Traction::SHEAR_X, x, y, z));
        let c = comps(&rect_stress(NU, &r, &Traction::SHEAR_Y, x, y, z));
        let want: Vec<f64> = (0..6).map(|k| 2.0 * a[k] - 0.5 * b[k] + 0.25 * c[k]).collect();
        let scale = want.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for k in 0..6 {
            st.add(got[k], want[k], scale, tag);
        }
    }
    st.check(tol::IDENTITY);
}

/// z -> 0+ under the interior: the traction is recovered, sigma_zz = -p, sigma_xz = -qx,
/// sigma_yz = -qy (outward normal -z), with an O(z/h) correction.
#[test]
fn surface_limit() {
    let r = Rect::new(-0.5, 0.5, -0.25, 0.75).unwrap();
    let t = Traction { p: 1.5, qx: 0.4, qy: -0.3 };
    let mut st = ErrStats::new("surface limit z = 1e-9");
    for &(x, y) in &[(0.0, 0.25), (0.3, 0.5), (-0.45, -0.2)] {
        let s = rect_stress(NU, &r, &t, x, y, 1e-9);
        st.add(s.zz, -t.p, 1.0, "zz");
        st.add(s.xz, -t.qx, 1.0, "xz");
        st.add(s.yz, -t.qy, 1.0, "yz");
        // Outside: the surface is traction free.
        let o = rect_stress(NU, &r, &t, x + 2.0, y, 1e-9);
        st.add(o.zz, 0.0, 1.0, "zz outside");
        st.add(o.xz, 0.0, 1.0, "xz outside");
        st.add(o.yz, 0.0, 1.0, "yz outside");
    }
    st.check(tol::RECT_SURFACE_LIMIT);
}

/// Far from the rectangle the field is that of a point force of the same resultant, with a
/// relative correction O((h/d)^2); the corner-sum path (forced by using the potential
/// directly) agrees with the far-field rule at the switch.
#[test]
fn far_field_is_point_force() {
    let r = Rect::new(-0.05, 0.05, -0.05, 0.05).unwrap();
    let area = r.area();
    for t in [Traction::PRESSURE, Traction::SHEAR_X, Traction::SHEAR_Y] {
        for &(x, y, z) in &[(1.0, 0.5, 2.0), (0.0, 0.0, 3.0), (-2.0, 1.0, 0.7)] {
            let got = comps(&rect_stress(NU, &r, &t, x, y, z));
            let want = point(&t, x, y, z);
            let scale = want.iter().fold(0.0f64, |m, v| m.max(v.abs())).max(1.0 / (z * z)) * area;
            for k in 0..6 {
                let e = (got[k] - area * want[k]).abs() / scale;
                assert!(e < tol::RECT_POINT_FORCE, "{t:?} ({x},{y},{z}) comp {k}: rel {e:e}");
            }
            let cs = comps(&stress_from_potential(NU, z, &t, &potential_derivatives(&r, x, y, z)));
            for k in 0..6 {
                let e = (got[k] - cs[k]).abs() / scale;
                assert!(
                    e < tol::RECT_CORNER_VS_FAR,
                    "corner sum vs far rule {t:?} ({x},{y},{z}) comp {k}: {e:e}"
                );
            }
        }
    }
}

#[test]
fn bad_input_is_an_error() {
    let r = Rect::new(-0.5, 0.5, -0.25, 0.75).unwrap();
    let t = Traction::PRESSURE;
    assert!(matches!(
        checked_rect_stress(NU, &r, &t, 0.0, 0.0, 0.0),
        Err(Error::OutOfDomain { name: "z", .. })
    ));
    assert!(checked_rect_stress(NU, &r, &t, 0.0, 0.0, -1.0).is_err());
    assert!(checked_rect_stress(NU, &r, &t, f64::NAN, 0.0, 1.0).is_err());
    assert!(checked_rect_stress(0.7, &r, &t, 0.0, 0.0, 1.0).is_err());
    let bad = Traction { p: f64::INFINITY, ..t };
    assert!(checked_rect_stress(NU, &r, &bad, 0.0, 0.0, 1.0).is_err());
    let flipped = Rect { x1: 1.0, x2: 0.0, y1: 0.0, y2: 1.0 };
    assert!(checked_rect_stress(NU, &flipped, &t, 0.0, 0.0, 1.0).is_err());
    assert!(checked_rect_stress(NU, &r, &t, 0.1, 0.2, 0.3).is_ok());
}

/// Equilibrium of the layer above a plane z = c: the tractions on the plane balance the
/// applied forces, iint sigma_zz = -p A, iint sigma_xz = -qx A, iint sigma_yz = -qy A
/// (integrals over the whole plane by nested adaptive quadrature on infinite ranges).
#[test]
fn layer_equilibrium() {
    let r = Rect::new(-0.5, 0.5, -0.25, 0.75).unwrap();
    let t = Traction { p: 1.5, qx: 0.4, qy: -0.3 };
    let mut st = ErrStats::new("layer equilibrium");
    for c in [0.3, 2.0] {
        let plane = |k: usize| {
            gk(
                |x| {
                    gk(
                        |y| comps(&rect_stress(NU, &r, &t, x, y, c))[k],
                        f64::NEG_INFINITY,
                        f64::INFINITY,
                        &[-0.25, 0.75],
                        1e-11,
                        1e-14,
                    )
                },
                f64::NEG_INFINITY,
                f64::INFINITY,
                &[-0.5, 0.5],
                1e-11,
                1e-13,
            )
        };
        st.add(plane(2), -t.p * r.area(), 1.0, &format!("zz at z = {c}"));
        st.add(plane(4), -t.qx * r.area(), 1.0, &format!("xz at z = {c}"));
        st.add(plane(5), -t.qy * r.area(), 1.0, &format!("yz at z = {c}"));
    }
    st.check(tol::QUAD);
}
