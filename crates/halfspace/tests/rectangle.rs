//! Rectangle influence coefficients: nested adaptive quadrature of the point-load solutions,
//! Betti reciprocity, the square self-term closed form, the far field, timing.
mod common;
use common::quad::{duffy_rect, gk, gk2};
use common::{tol, ErrStats};
use std::f64::consts::PI;
use std::hint::black_box;
use std::time::Instant;
use stickslip_halfspace::material::Compliance;
use stickslip_halfspace::point_load::{boussinesq_displacement, cerruti_displacement};
use stickslip_halfspace::rectangle::{
    kernel_integrals, pressure_displacement, pressure_uz, shear_in_plane, shear_self_term,
    shear_x_displacement, shear_x_ux, shear_y_displacement, Rect,
};
use stickslip_halfspace::{Displacement3, Material};

fn mat() -> Material {
    Material::new(2.0, 0.3125).unwrap()
}

/// Field points around the rectangle [-0.5, 0.5] x [-0.25, 0.75]: interior, edges, corners,
/// near and far outside.
const POINTS: [(f64, f64, &str); 14] = [
    (0.1, 0.2, "interior"),
    (0.0, 0.25, "centre"),
    (-0.375, 0.625, "interior near corner"),
    (0.5, 0.1, "edge x2"),
    (-0.2, -0.25, "edge y1"),
    (0.0, 0.75, "edge y2"),
    (0.5, 0.75, "corner (x2,y2)"),
    (-0.5, -0.25, "corner (x1,y1)"),
    (0.7, 0.3, "outside near"),
    (-0.5, 1.0, "outside on edge line"),
    (0.5625, -0.3125, "outside near corner"),
    (5.0, -3.0, "far"),
    (-20.0, 40.0, "far 40"),
    (0.0, -2.0, "below"),
];

fn vs_quad(
    name: &str,
    closed: impl Fn(&Rect, f64, f64) -> Displacement3,
    point: impl Fn(f64, f64) -> Displacement3,
) {
    let r = Rect::new(-0.5, 0.5, -0.25, 0.75).unwrap();
    let mut st = ErrStats::new(name);
    for &(x, y, tag) in &POINTS {
        let got = closed(&r, x, y);
        let bounds = (r.x1, r.x2, r.y1, r.y2);
        let comp = |k: usize| {
            duffy_rect(
                |xi, eta| {
                    let u = point(x - xi, y - eta);
                    [u.x, u.y, u.z][k]
                },
                bounds,
                (x, y),
                1e-12,
                1e-15,
            )
        };
        let want = [comp(0), comp(1), comp(2)];
        let scale = got.x.abs().max(got.y.abs()).max(got.z.abs());
        // relative per component, floored at 1e-6 of the largest component (zeros by symmetry)
        st.add(got.x, want[0], 1e-6 * scale, &format!("{tag} ux"));
        st.add(got.y, want[1], 1e-6 * scale, &format!("{tag} uy"));
        st.add(got.z, want[2], 1e-6 * scale, &format!("{tag} uz"));
    }
    st.check(tol::RECT_VS_QUAD);
}

#[test]
fn pressure_vs_nested_quadrature_of_boussinesq() {
    let m = mat();
    let c = m.compliance();
    vs_quad(
        "rect pressure vs quad(Boussinesq)",
        |r, x, y| pressure_displacement(&c, r, x, y),
        |dx, dy| boussinesq_displacement(&m, 1.0, dx, dy, 0.0),
    );
}

#[test]
fn shear_x_vs_nested_quadrature_of_cerruti() {
    let m = mat();
    let c = m.compliance();
    vs_quad(
        "rect shear x vs quad(Cerruti)",
        |r, x, y| shear_x_displacement(&c, r, x, y),
        |dx, dy| cerruti_displacement(&m, 1.0, dx, dy, 0.0),
    );
}

#[test]
fn shear_y_vs_nested_quadrature_of_cerruti() {
    let m = mat();
    let c = m.compliance();
    vs_quad(
        "rect shear y vs quad(Cerruti rotated)",
        |r, x, y| shear_y_displacement(&c, r, x, y),
        |dx, dy| {
            let u = cerruti_displacement(&m, 1.0, dy, dx, 0.0);
            Displacement3 { x: u.y, y: u.x, z: u.z }
        },
    );
}

#[test]
fn fast_paths_match_full() {
    let c = mat().compliance();
    let r = Rect::new(-0.5, 0.5, -0.25, 0.75).unwrap();
    let mut st = ErrStats::new("fast paths vs full vectors");
    for &(x, y, tag) in &POINTS {
        st.add(pressure_uz(&c, &r, x, y), pressure_displacement(&c, &r, x, y).z, 1e-300, tag);
        st.add(shear_x_ux(&c, &r, x, y), shear_x_displacement(&c, &r, x, y).x, 1e-300, tag);
    }
    // different summation order; the corner sum cancels to ~eps (d/h)^2 ~ 5e-13 at "far 40"
    st.check(1e-12);
}

/// The tangential coefficients of a lattice come from `shear_in_plane`, which evaluates the
/// kernel integrals once for both shear directions and leaves out the normal-coupling
/// kernels: the same arithmetic on each kept kernel, so the same values to the bit as the full
/// displacement vectors (which the quadrature tests above check), near (corner sums) and far
/// (each order of the Gauss rule).
#[test]
fn in_plane_pair_is_the_full_vectors_to_the_bit() {
    let c = mat().compliance();
    let r = Rect::new(-0.5, 0.5, -0.25, 0.75).unwrap();
    let far = [(3.0, 2.5), (7.0, -1.0), (-30.0, 55.0), (150.0, 0.0), (-900.0, 420.0), (3e4, 2e4)];
    let points = POINTS.iter().map(|&(x, y, _)| (x, y)).chain(far);
    for (x, y) in points {
        let [uxx, uyx, uyy] = shear_in_plane(&c, &r, x, y);
        let (sx, sy) = (shear_x_displacement(&c, &r, x, y), shear_y_displacement(&c, &r, x, y));
        assert_eq!(uxx.to_bits(), sx.x.to_bits(), "ux under x-shear at ({x}, {y})");
        assert_eq!(uyx.to_bits(), sx.y.to_bits(), "uy under x-shear at ({x}, {y})");
        assert_eq!(uyx.to_bits(), sy.x.to_bits(), "ux under y-shear at ({x}, {y})");
        assert_eq!(uyy.to_bits(), sy.y.to_bits(), "uy under y-shear at ({x}, {y})");
    }
}

#[test]
fn square_self_terms() {
    let m = mat();
    let c = m.compliance();
    let (g, nu) = (m.shear_modulus(), m.poisson_ratio());
    let mut st = ErrStats::new("self terms vs closed forms");
    for h in [1e-6, 0.5, 3.0, 1e5] {
        // centre scaled with h so that forming x - xi loses no digits to the offset
        let (cx, cy) = (0.25 * h, -h);
        let r = Rect::centered(cx, cy, h / 2.0, h / 2.0).unwrap();
        let ln = (1.0 + 2f64.sqrt()).ln();
        // FORMULAS.md F: (2 - nu) ln(1 + sqrt 2) / (pi G h) per unit force.
        let want = (2.0 - nu) * ln / (PI * g * h);
        st.add(shear_x_ux(&c, &r, cx, cy) / (h * h), want, 1e-300, &format!("shear h={h}"));
        st.add(shear_self_term(&c, h / 2.0, h / 2.0), want, 1e-300, &format!("A_kk h={h}"));
        // Love: centre of a square, u_z = (1-nu^2)/(pi E) * 4 h ln(1 + sqrt 2) = 2(1-nu)/(pi G) h ln
        let want_p = 2.0 * (1.0 - nu) * h * ln / (PI * g);
        st.add(pressure_uz(&c, &r, cx, cy), want_p, 1e-300, &format!("pressure h={h}"));
    }
    // rectangle self-term formula vs the element-to-point formula
    for (cx, cy) in [(0.5, 0.125), (0.125, 2.0)] {
        let r = Rect::centered(0.0, 0.0, cx, cy).unwrap();
        let got = shear_x_ux(&c, &r, 0.0, 0.0) / (4.0 * cx * cy);
        st.add(got, shear_self_term(&c, cx, cy), 1e-300, &format!("A_kk {cx}x{cy}"));
    }
    st.check(tol::IDENTITY);
    // Equal-area circle estimate is 0.55 % high (FORMULAS.md F): sanity.
    let h = 1.0;
    let circle = (2.0 - nu) / (2.0 * PI.sqrt() * g * h);
    let exact = shear_self_term(&c, 0.5, 0.5);
    println!("[self term] equal-area circle / exact - 1 = {:.4}", circle / exact - 1.0);
}

/// Integral over rectangle `b` of a displacement component produced by a unit traction on `a`.
fn work(a: &Rect, b: &Rect, f: impl Fn(&Rect, f64, f64) -> f64) -> f64 {
    gk2(|x, y| f(a, x, y), (b.x1, b.x2, b.y1, b.y2), (b.x1, b.y1), 1e-11, 1e-14)
}

#[test]
fn betti_reciprocity_between_elements() {
    let m = mat();
    let c = m.compliance();
    let a = Rect::new(-0.5, 0.25, 0.0, 0.5).unwrap();
    let mut st = ErrStats::new("Betti reciprocity");
    for (b, tag) in [
        (Rect::new(1.0, 1.5, -0.75, 0.125).unwrap(), "disjoint"),
        (Rect::new(0.25, 1.0, 0.0, 0.5).unwrap(), "edge-adjacent"),
        (Rect::new(0.25, 0.75, 0.5, 1.25).unwrap(), "corner-adjacent"),
    ] {
        // pressure-pressure, shear-shear (x on a, x on b), shear-shear cross (x on a, y on b),
        // pressure-shear (pressure on a, x-shear on b)
        let pp = (
            work(&a, &b, |r, x, y| pressure_uz(&c, r, x, y)),
            work(&b, &a, |r, x, y| pressure_uz(&c, r, x, y)),
        );
        let ss = (
            work(&a, &b, |r, x, y| shear_x_ux(&c, r, x, y)),
            work(&b, &a, |r, x, y| shear_x_ux(&c, r, x, y)),
        );
        let xy = (
            work(&a, &b, |r, x, y| shear_x_displacement(&c, r, x, y).y),
            work(&b, &a, |r, x, y| shear_y_displacement(&c, r, x, y).x),
        );
        let ps = (
            work(&a, &b, |r, x, y| pressure_displacement(&c, r, x, y).x),
            work(&b, &a, |r, x, y| shear_x_displacement(&c, r, x, y).z),
        );
        // floor: pairs that vanish by symmetry are compared absolutely, at the scale of the
        // p-p work
        let floor = 1e-3 * pp.0.abs();
        st.add(pp.0, pp.1, floor, &format!("{tag} p-p"));
        st.add(ss.0, ss.1, floor, &format!("{tag} qx-qx"));
        st.add(xy.0, xy.1, floor, &format!("{tag} qx-qy"));
        st.add(ps.0, ps.1, floor, &format!("{tag} p-qx"));
    }
    st.check(tol::QUAD);
}

#[test]
fn far_field_tends_to_point_load_and_stays_accurate() {
    let m = mat();
    let c = m.compliance();
    let h = 1.0;
    let r = Rect::centered(0.0, 0.0, h / 2.0, h / 2.0).unwrap();
    let gl = stickslip_quad::GaussLegendre::new(24).unwrap();
    use stickslip_quad::Rule;
    println!(
        "[far field] d/h, |rect/point - 1| (uz, ux shear), rel err vs 24x24 Gauss (uz, ux, uy)"
    );
    let mut worst = 0.0_f64;
    for d in [3.0, 5.9, 6.1, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6] {
        let (x, y) = (0.6 * d, 0.8 * d);
        let uz = pressure_uz(&c, &r, x, y);
        let sx = shear_x_displacement(&c, &r, x, y);
        let pz = boussinesq_displacement(&m, 1.0, x, y, 0.0).z;
        let px = cerruti_displacement(&m, 1.0, x, y, 0.0).x;
        // product Gauss rule: integrand analytic on the element when d >= 3h
        let q = |k: usize| {
            gl.integrate(
                |xi| {
                    gl.integrate(
                        |eta| match k {
                            0 => boussinesq_displacement(&m, 1.0, x - xi, y - eta, 0.0).z,
                            1 => cerruti_displacement(&m, 1.0, x - xi, y - eta, 0.0).x,
                            _ => cerruti_displacement(&m, 1.0, x - xi, y - eta, 0.0).y,
                        },
                        -0.5,
                        0.5,
                    )
                    .unwrap()
                    .value
                },
                -0.5,
                0.5,
            )
            .unwrap()
            .value
        };
        let e = [(uz / q(0) - 1.0).abs(), (sx.x / q(1) - 1.0).abs(), (sx.y / q(2) - 1.0).abs()];
        println!(
            "  {d:>7}: {:.2e} {:.2e} | {:.2e} {:.2e} {:.2e}",
            (uz / pz - 1.0).abs(),
            (sx.x / px - 1.0).abs(),
            e[0],
            e[1],
            e[2]
        );
        // point-load limit: difference O((h/d)^2)
        assert!((uz / pz - 1.0).abs() < 0.1 * (h / d).powi(2) + 1e-12 * d * d);
        // The corner sums cancel like eps (d/h)^2; beyond FAR_FIELD element sizes the Gauss
        // far-field rule takes over, so the error stays at rounding level at every distance.
        for ei in e {
            assert!(ei < tol::FAR_FIELD, "d = {d}: {ei:e}");
            worst = worst.max(ei);
        }
    }
    println!("[far field] worst relative error vs 24x24 Gauss, d/h in [3, 1e6] = {worst:.2e}");
    // Absurdly far points (coordinates beyond 1e154, where squares overflow) stay finite and on
    // the point-load limit.
    for d in [1e160, 1e300] {
        let (x, y) = (0.6 * d, 0.8 * d);
        let uz = pressure_uz(&c, &r, x, y);
        // Point-load limits written with r = hypot(x, y) (the point-load functions square
        // their coordinates and return 0 this far out): Boussinesq u_z = c1/(2 pi r) and
        // Cerruti u_x = (c1 + c2 x^2/r^2)/(2 pi r), for the unit force of the unit element.
        let rr = x.hypot(y);
        let pz = c.one_minus_nu / (2.0 * PI * rr);
        let sx = shear_x_displacement(&c, &r, x, y);
        let px = (c.one_minus_nu + c.nu * (x / rr).powi(2)) / (2.0 * PI * rr);
        assert!(uz.is_finite() && (uz / pz - 1.0).abs() < 1e-14, "d = {d:e}: {uz:e} vs {pz:e}");
        assert!(sx.x.is_finite() && (sx.x / px - 1.0).abs() < 1e-14, "d = {d:e}");
    }
}

#[test]
fn edges_corners_and_degenerate_are_finite() {
    let c = mat().compliance();
    let r = Rect::new(0.0, 1.0, 0.0, 2.0).unwrap();
    for (x, y) in [(0.0, 0.0), (1.0, 2.0), (0.0, 1.0), (0.5, 0.0), (1.0, 5.0), (0.5, 1.0)] {
        let k = kernel_integrals(&r, x, y);
        for v in [k.inv_r, k.xx_r3, k.yy_r3, k.xy_r3, k.x_r2, k.y_r2] {
            assert!(v.is_finite(), "({x}, {y}): {k:?}");
        }
    }
    let thin = Rect { x1: 0.0, x2: 0.0, y1: 0.0, y2: 1.0 };
    assert_eq!(pressure_uz(&c, &thin, 0.0, 0.5), 0.0);
    assert!(Rect::new(1.0, 0.0, 0.0, 1.0).is_err());
    assert!(Rect::new(0.0, f64::INFINITY, 0.0, 1.0).is_err());
    // two bodies: relative displacement of identical bodies is twice one body's, coupling 0
    let m = mat();
    let pair = Compliance::pair(&m, &m);
    let one = pressure_displacement(&m.compliance(), &r, 0.3, 0.7);
    let two = pressure_displacement(&pair, &r, 0.3, 0.7);
    assert!((two.z - 2.0 * one.z).abs() <= 1e-15 * one.z.abs());
    assert_eq!(two.x, 0.0);
    // rigid body: no displacement
    assert_eq!(pressure_uz(&Material::rigid().compliance(), &r, 0.3, 0.7), 0.0);
}

#[test]
fn timing_per_influence_coefficient() {
    let c = mat().compliance();
    let n = 400usize;
    let h = 1.0 / n as f64;
    let src = Rect::centered(0.0, 0.0, h / 2.0, h / 2.0).unwrap();
    let pts: Vec<(f64, f64)> =
        (0..n * n).map(|k| (((k % n) as f64 - 200.0) * h, ((k / n) as f64 - 200.0) * h)).collect();
    let time = |name: &str, f: &dyn Fn(f64, f64) -> f64| {
        let t0 = Instant::now();
        let mut s = 0.0;
        for &(x, y) in &pts {
            s += f(black_box(x), black_box(y));
        }
        let ns = t0.elapsed().as_nanos() as f64 / pts.len() as f64;
        black_box(s);
        println!("[timing] {name}: {ns:.1} ns per coefficient ({} evaluations)", pts.len());
    };
    time("pressure_uz", &|x, y| pressure_uz(&c, &src, x, y));
    time("shear_x_ux", &|x, y| shear_x_ux(&c, &src, x, y));
    time("pressure_displacement (3 comps)", &|x, y| pressure_displacement(&c, &src, x, y).z);
    time("shear_x_displacement (3 comps)", &|x, y| shear_x_displacement(&c, &src, x, y).x);
    // a coarse gross check only, so that the timing line is not a test that asserts nothing
    let v = gk(|x| pressure_uz(&c, &src, x, 0.3), -1.0, 1.0, &[], 1e-12, 0.0);
    assert!(v.is_finite() && v > 0.0);
}
