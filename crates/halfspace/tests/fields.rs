//! Point loads (Boussinesq, Cerruti), Flamant, 2D Cattaneo–Mindlin, materials, and the elliptic
//! Hertz integral equation: checks by Hooke's law on finite-difference strains, force balance,
//! line integrals of the 3D solutions, and quadrature.
mod common;
use common::quad::gk;
use common::{tol, ErrStats};
use std::f64::consts::PI;
use stickslip_halfspace::cattaneo2d::Cattaneo2d;
use stickslip_halfspace::flamant::{
    checked_line_load_stress, checked_surface_displacement, line_load_stress, surface_displacement,
};
use stickslip_halfspace::hertz::{HertzEllipse, HertzLine};
use stickslip_halfspace::material::{
    checked_composite_modulus, composite_modulus, composite_shear_compliance, dundurs_beta,
};
use stickslip_halfspace::mcewen::stress_potential;
use stickslip_halfspace::point_load::*;
use stickslip_halfspace::{Displacement3, Error, Material, Stress3};
use stickslip_quad::{GaussJacobi, Rule};

fn hooke_check(
    name: &str,
    m: &Material,
    u: impl Fn(f64, f64, f64) -> Displacement3,
    s: impl Fn(f64, f64, f64) -> Stress3,
) {
    let (g, nu) = (m.shear_modulus(), m.poisson_ratio());
    let lam = 2.0 * g * nu / (1.0 - 2.0 * nu);
    let mut st = ErrStats::new(name);
    for &(x, y, z) in &[
        (0.3, -0.7, 0.45),
        (1.0, 0.5, 0.1),
        (-0.2, 0.1, 2.0),
        (0.0, 0.0, 1.0),
        (2.0, -3.0, 0.05),
        (-0.5, 0.25, 0.75),
    ] {
        // step small against both the distance to the load and the depth
        let h = 1e-4 * f64::sqrt(x * x + y * y + z * z).min(z);
        let d = |i: usize| {
            let (mut p, mut q) = ([x, y, z], [x, y, z]);
            p[i] += h;
            q[i] -= h;
            let (a, b) = (u(p[0], p[1], p[2]), u(q[0], q[1], q[2]));
            [(a.x - b.x) / (2.0 * h), (a.y - b.y) / (2.0 * h), (a.z - b.z) / (2.0 * h)]
        };
        let (dx, dy, dz) = (d(0), d(1), d(2)); // d_i u_j = d(i)[j]
        let tr = dx[0] + dy[1] + dz[2];
        let want = Stress3 {
            xx: lam * tr + 2.0 * g * dx[0],
            yy: lam * tr + 2.0 * g * dy[1],
            zz: lam * tr + 2.0 * g * dz[2],
            xy: g * (dx[1] + dy[0]),
            xz: g * (dx[2] + dz[0]),
            yz: g * (dy[2] + dz[1]),
        };
        let got = s(x, y, z);
        let sc = [got.xx, got.yy, got.zz, got.xy, got.xz, got.yz]
            .iter()
            .fold(0.0_f64, |a, v| a.max(v.abs()));
        let tag = format!("({x},{y},{z})");
        for (gv, wv) in [
            (got.xx, want.xx),
            (got.yy, want.yy),
            (got.zz, want.zz),
            (got.xy, want.xy),
            (got.xz, want.xz),
            (got.yz, want.yz),
        ] {
            // FD rounding is absolute at the scale of the largest component, or of the natural
            // stress scale 1/R^2 of a unit load where all components vanish (Cerruti's axis)
            let r2 = x * x + y * y + z * z;
            st.add(gv, wv, 1e-2 * sc.max(1.0 / r2), &tag);
        }
    }
    st.check(tol::FD);
}

#[test]
fn point_load_stresses_match_hooke_of_fd_strains() {
    let m = Material::new(3.0, 0.27).unwrap();
    let nu = m.poisson_ratio();
    hooke_check(
        "Boussinesq Hooke(FD strain)",
        &m,
        |x, y, z| boussinesq_displacement(&m, 1.5, x, y, z),
        |x, y, z| boussinesq_stress(nu, 1.5, x, y, z),
    );
    hooke_check(
        "Cerruti Hooke(FD strain)",
        &m,
        |x, y, z| cerruti_displacement(&m, 1.5, x, y, z),
        |x, y, z| cerruti_stress(nu, 1.5, x, y, z),
    );
}

#[test]
fn point_load_force_balance_and_free_surface() {
    // integral over the plane z = depth, in polar coordinates rho in (0, inf), phi in (0, 2 pi)
    let nu = 0.3;
    let z = 0.7;
    let plane = |f: &dyn Fn(f64, f64) -> f64| {
        gk(
            |rho| {
                rho * gk(
                    |phi| f(rho * phi.cos(), rho * phi.sin()),
                    0.0,
                    2.0 * PI,
                    &[PI],
                    1e-12,
                    1e-14,
                )
            },
            0.0,
            f64::INFINITY,
            &[z],
            1e-11,
            1e-13,
        )
    };
    let mut st = ErrStats::new("force balance on z = 0.7");
    st.add(
        plane(&|x, y| boussinesq_stress(nu, 2.0, x, y, z).zz),
        -2.0,
        1.0,
        "Boussinesq int szz = -P",
    );
    st.add(
        plane(&|x, y| boussinesq_stress(nu, 2.0, x, y, z).xz),
        0.0,
        1.0,
        "Boussinesq int sxz = 0",
    );
    st.add(plane(&|x, y| cerruti_stress(nu, 2.0, x, y, z).xz), -2.0, 1.0, "Cerruti int sxz = -Q");
    st.add(plane(&|x, y| cerruti_stress(nu, 2.0, x, y, z).zz), 0.0, 1.0, "Cerruti int szz = 0");
    st.add(plane(&|x, y| cerruti_stress(nu, 2.0, x, y, z).yz), 0.0, 1.0, "Cerruti int syz = 0");
    st.check(tol::QUAD);
    // traction-free surface away from the load
    for (x, y) in [(0.3, -0.7), (2.0, 1.0)] {
        let b = boussinesq_stress(nu, 1.0, x, y, 0.0);
        let c = cerruti_stress(nu, 1.0, x, y, 0.0);
        for v in [b.zz, b.xz, b.yz, c.zz, c.xz, c.yz] {
            assert_eq!(v, 0.0);
        }
    }
    // on the axis: finite and symmetric
    let s = boussinesq_stress(nu, 1.0, 0.0, 0.0, 1.0);
    assert!((s.xx - s.yy).abs() < 1e-16 && s.xx.is_finite());
    assert!(matches!(
        checked_boussinesq_stress(nu, 1.0, 0.0, 0.0, 0.0),
        Err(Error::Singular { .. })
    ));
    assert!(checked_cerruti_displacement(&Material::new(1.0, 0.3).unwrap(), 1.0, 0.0, 0.0, -1.0)
        .is_err());
    assert!(checked_cerruti_stress(0.7, 1.0, 1.0, 0.0, 1.0).is_err());
}

#[test]
fn surface_point_load_reciprocity() {
    // Betti: u_z at B due to a tangential force at A equals u_x at A due to a normal force at B
    let m = Material::new(1.0, 0.2).unwrap();
    let (dx, dy) = (0.4, -0.3);
    let uz_from_q = cerruti_displacement(&m, 1.0, dx, dy, 0.0).z;
    let ux_from_p = boussinesq_displacement(&m, 1.0, -dx, -dy, 0.0).x;
    println!("[reciprocity] Cerruti u_z = {uz_from_q:e}, Boussinesq u_x = {ux_from_p:e}");
    assert!((uz_from_q - ux_from_p).abs() <= 1e-15 * uz_from_q.abs());
}

#[test]
fn flamant_is_the_line_integral_of_boussinesq_and_cerruti() {
    let nu = 0.3;
    let mut st = ErrStats::new("Flamant vs integral over y of 3D point loads");
    for &(x, y) in &[(0.3, 0.7), (-1.5, 0.2), (0.0, 1.0), (2.0, 0.05)] {
        let f = line_load_stress(1.25, -0.75, x, y);
        let line = |k: usize| {
            gk(
                |eta| {
                    let b = boussinesq_stress(nu, 1.25, x, eta, y);
                    let c = cerruti_stress(nu, -0.75, x, eta, y);
                    [b.xx + c.xx, b.zz + c.zz, b.xz + c.xz, b.yy + c.yy][k]
                },
                f64::NEG_INFINITY,
                f64::INFINITY,
                &[0.0],
                1e-12,
                1e-13,
            )
        };
        let tag = format!("({x},{y})");
        let sc = f.xx.abs().max(f.yy.abs()).max(f.xy.abs());
        st.add(line(0), f.xx, 1e-3 * sc, &format!("{tag} xx"));
        st.add(line(1), f.yy, 1e-3 * sc, &format!("{tag} yy"));
        st.add(line(2), f.xy, 1e-3 * sc, &format!("{tag} xy"));
        // plane strain: out-of-plane stress nu (sxx + syy)
        st.add(line(3), nu * (f.xx + f.yy), 1e-3 * sc, &format!("{tag} zz plane strain"));
    }
    st.check(tol::QUAD);
    // Equilibrium at depth 0.8: int syy = -P, int sxy = -Q
    let (p, q, y) = (1.25, -0.75, 0.8);
    let mut eq = ErrStats::new("Flamant equilibrium at depth");
    let i = |k: usize| {
        gk(
            |x| {
                let s = line_load_stress(p, q, x, y);
                [s.yy, s.xy][k]
            },
            f64::NEG_INFINITY,
            f64::INFINITY,
            &[0.0],
            1e-12,
            1e-13,
        )
    };
    eq.add(i(0), -p, 1.0, "int syy = -P");
    eq.add(i(1), -q, 1.0, "int sxy = -Q");
    eq.check(tol::QUAD);
    assert!(matches!(checked_line_load_stress(1.0, 0.0, 0.0, 0.0), Err(Error::Singular { .. })));
    assert!(checked_line_load_stress(1.0, 0.0, 1.0, -1.0).is_err());
    let s = line_load_stress(0.0, 2.0, 0.5, 0.0);
    assert!((s.xx + 2.0 * 2.0 / (PI * 0.5)).abs() < 1e-15);
}

#[test]
fn flamant_surface_displacement_vs_boussinesq_line() {
    let m = Material::new(2.0, 0.3).unwrap();
    let (e, nu) = (m.youngs_modulus(), m.poisson_ratio());
    let mut st = ErrStats::new("Flamant surface displacement vs Boussinesq/Cerruti line");
    let (x, x0) = (0.35, 1.75);
    // u_y(x) - u_y(x0) from P and u_x(x) - u_x(x0) from Q by line integrals of the 3D solutions
    let diff = |f: &dyn Fn(f64, f64) -> f64| {
        gk(|eta| f(x, eta) - f(x0, eta), f64::NEG_INFINITY, f64::INFINITY, &[0.0], 1e-12, 1e-16)
    };
    let uy = diff(&|xx, eta| boussinesq_displacement(&m, 1.0, xx, eta, 0.0).z);
    let ux = diff(&|xx, eta| cerruti_displacement(&m, 1.0, xx, eta, 0.0).x);
    let d = surface_displacement(&m, 1.0, 0.0, x, x0);
    st.add(uy, d.y, 1e-300, "u_y(P) relative to x0");
    let d = surface_displacement(&m, 0.0, 1.0, x, x0);
    st.add(ux, d.x, 1e-300, "u_x(Q) relative to x0");
    // step terms: u_x due to P and u_y due to Q
    let ux_p = gk(
        |eta| boussinesq_displacement(&m, 1.0, x, eta, 0.0).x,
        f64::NEG_INFINITY,
        f64::INFINITY,
        &[0.0],
        1e-12,
        1e-16,
    );
    let uy_q = gk(
        |eta| cerruti_displacement(&m, 1.0, x, eta, 0.0).z,
        f64::NEG_INFINITY,
        f64::INFINITY,
        &[0.0],
        1e-12,
        1e-16,
    );
    st.add(ux_p, surface_displacement(&m, 1.0, 0.0, x, x0).x, 1e-300, "u_x(P) step");
    st.add(uy_q, surface_displacement(&m, 0.0, 1.0, x, x0).y, 1e-300, "u_y(Q) step");
    st.add(
        surface_displacement(&m, 0.0, 1.0, x, x0).y,
        (1.0 - 2.0 * nu) * (1.0 + nu) / (2.0 * e),
        1e-300,
        "Johnson 2.20",
    );
    st.check(tol::QUAD);
    assert_eq!(surface_displacement(&m, 1.0, 0.0, x0, x0).y, 0.0);
    assert!(checked_surface_displacement(&m, 1.0, 0.0, 0.0, 1.0).is_err());
    assert!(checked_surface_displacement(&m, 1.0, 0.0, 1.0, 0.0).is_err());
}

#[test]
fn materials() {
    let steel = Material::new(210e9, 0.3).unwrap();
    let rubber = Material::new(1e7, 0.5).unwrap();
    let es = composite_modulus(&steel, &rubber);
    let want = 1.0 / ((1.0 - 0.09) / 210e9 + 0.75 / 1e7);
    assert!((es / want - 1.0).abs() < 1e-15);
    assert!((composite_modulus(&steel, &Material::rigid()) / (210e9 / 0.91) - 1.0).abs() < 1e-15);
    assert!(matches!(
        checked_composite_modulus(&Material::rigid(), &Material::rigid()),
        Err(Error::BothRigid)
    ));
    assert!(
        Material::new(1.0, 0.51).is_err()
            && Material::new(1.0, -1.0).is_err()
            && Material::new(0.0, 0.3).is_err()
    );
    assert!(Material::new(1.0, 0.5).is_ok() && Material::new(1.0, -0.99).is_ok());
    // FORMULAS.md E example 2: steel 30e6 psi / rubber 1e6 psi, nu 0.3: Dundurs beta = -0.267
    let s = Material::new(30e6, 0.3).unwrap();
    let r = Material::new(1e6, 0.3).unwrap();
    let b = dundurs_beta(&s, &r);
    println!(
        "[materials] Dundurs beta (example 2) = {b:.4}, E* = {:.5e}",
        composite_modulus(&s, &r)
    );
    assert!((b + 0.2673).abs() < 5e-4);
    assert!((composite_modulus(&s, &r) / 1.0635e6 - 1.0).abs() < 1e-4);
    assert_eq!(dundurs_beta(&s, &s), 0.0);
    let g = s.shear_modulus();
    assert!((composite_shear_compliance(&s, &s) - 2.0 * 1.7 / g).abs() < 1e-15 / g);
}

#[test]
fn cattaneo_traction_integrates_to_q_and_limits() {
    let h = HertzLine::new(2.0, 1.5, 3.0).unwrap();
    let (a, p0, f) = (h.half_width(), h.max_pressure(), 0.3);
    let fp = f * h.load();
    let mut st = ErrStats::new("Cattaneo 2D int q = Q");
    for ratio in [1e-6, 1e-3, 0.25, 0.5, 0.9, 1.0] {
        for sign in [1.0, -1.0] {
            let q = sign * ratio * fp;
            let c = Cattaneo2d::new(a, p0, f, q).unwrap();
            let cc = c.stick_half_width();
            let integ = gk(|x| c.traction(x), -a, a, &[-cc, cc], 1e-13, 1e-15 * q.abs());
            st.add(integ, q, 1e-300, &format!("Q/fP = {ratio} sign {sign}"));
            assert!((cc - a * (1.0 - ratio).sqrt()).abs() <= 1e-15 * a);
            // friction cone: |q| <= f p everywhere, equality in the slip zone
            for k in 0..=200 {
                let x = -a + 2.0 * a * f64::from(k) / 200.0;
                assert!(c.traction(x).abs() <= f * c.pressure(x) * (1.0 + 1e-14) + 1e-300);
            }
        }
    }
    st.check(1e-12);
    // Q/fP = 1e-12: c = a sqrt(1 - 1e-12) cannot carry a - c = 5e-13 a to better than ~1e-4,
    // which moves the thin slip zone's share (~2e-7 of Q) by ~4e-11 relative.
    let c = Cattaneo2d::new(a, p0, f, 1e-12 * fp).unwrap();
    let cc = c.stick_half_width();
    let integ = gk(|x| c.traction(x), -a, a, &[-cc, cc], 1e-8, 1e-9 * 1e-12 * fp);
    println!("[Cattaneo] Q/fP = 1e-12: int q / Q - 1 = {:.2e}", integ / (1e-12 * fp) - 1.0);
    assert!((integ / (1e-12 * fp) - 1.0).abs() < 1e-8);
    // Q = fP: c = 0 and q = f p; Q = 0: c = a, q = 0; Q > fP: error
    let full = Cattaneo2d::new(a, p0, f, fp).unwrap();
    assert_eq!(full.stick_half_width(), 0.0);
    assert!((full.traction(0.3 * a) - f * full.pressure(0.3 * a)).abs() < 1e-15);
    let none = Cattaneo2d::new(a, p0, f, 0.0).unwrap();
    assert_eq!(none.stick_half_width(), a);
    assert_eq!(none.traction(0.1), 0.0);
    assert!(matches!(Cattaneo2d::new(a, p0, f, fp * (1.0 + 1e-12)), Err(Error::GrossSlip { .. })));
    assert!(Cattaneo2d::new(a, p0, -0.1, 0.0).is_err());
    assert!(Cattaneo2d::new(a, p0, 0.0, 0.0).is_ok());
    // sliding field equals McEwen with q0 = f p0
    let s1 = full.stress(0.2, 0.3).unwrap();
    let s2 = stress_potential(a, p0, f * p0, 0.2, 0.3);
    assert!((s1.xx - s2.xx).abs() + (s1.yy - s2.yy).abs() + (s1.xy - s2.xy).abs() < 1e-14);
}

#[test]
fn cattaneo_field_vs_flamant_quadrature() {
    let (a, p0, f) = (1.0, 1.0, 0.4);
    let c = Cattaneo2d::new(a, p0, f, 0.5 * f * PI / 2.0).unwrap();
    let cc = c.stick_half_width();
    let mut st = ErrStats::new("Cattaneo field vs Flamant quadrature");
    for &(x, y) in &[
        (0.0, 0.5),
        (0.5, 0.2),
        (-0.8, 0.1),
        (cc, 0.01),
        (-1.0, 0.05),
        (1.0, 0.001),
        (3.0, 2.0),
        (0.3, 1e-3),
    ] {
        let s = c.stress(x, y).unwrap();
        let quad = |k: usize| {
            gk(
                |t| {
                    let l = line_load_stress(c.pressure(t), c.traction(t), x - t, y);
                    [l.xx, l.yy, l.xy][k]
                },
                -a,
                a,
                &[-cc, cc, x - 10.0 * y, x - y, x, x + y, x + 10.0 * y],
                1e-12,
                1e-15,
            )
        };
        let tag = format!("({x:.4},{y})");
        let sc = s.xx.abs().max(s.yy.abs()).max(s.xy.abs());
        st.add(s.xx, quad(0), 1e-3 * sc, &format!("{tag} xx"));
        st.add(s.yy, quad(1), 1e-3 * sc, &format!("{tag} yy"));
        st.add(s.xy, quad(2), 1e-3 * sc, &format!("{tag} xy"));
    }
    st.check(tol::MCEWEN_VS_QUAD);
    // near the surface, inside the stick and slip zones: syy -> -p, sxy -> -q
    for x in [0.1, -0.5, 0.8] {
        let s = c.stress(x, 1e-6).unwrap();
        let (p, q) = (c.pressure(x), c.traction(x));
        println!("[Cattaneo] x = {x}: syy + p = {:.2e}, sxy + q = {:.2e}", s.yy + p, s.xy + q);
        assert!((s.yy + p).abs() < 1e-5 && (s.xy + q).abs() < 1e-5);
    }
}

#[test]
fn ellipse_pressure_satisfies_the_hertz_integral_equation() {
    // u(x, y) = (1/(pi E*)) iint p / |r - r'| dA = delta - x^2/(2Rx) - y^2/(2Ry) inside the
    // ellipse; polar coordinates about the field point remove the singularity, and along each
    // ray p = p0 sqrt(gamma) sqrt(rho_max - rho) sqrt(rho - rho_min): Gauss–Jacobi weight
    // (rho_max - rho)^(1/2) on [0, rho_max], adaptive Gauss–Kronrod over the angle.
    let (rx, ry, load, es) = (3.0, 0.75, 2.0, 1.5);
    let el = HertzEllipse::new(rx, ry, load, es).unwrap();
    let (ax, ay, p0) = (el.semi_axis_x(), el.semi_axis_y(), el.max_pressure());
    let gj = GaussJacobi::new(40, 0.5, 0.0).unwrap();
    let mut st = ErrStats::new("ellipse: Boussinesq quadrature of Hertz pressure");
    for &(fx, fy) in &[(0.0, 0.0), (0.5, 0.2), (-0.9, 0.1), (0.2, -0.5), (0.95, 0.0)] {
        let (x, y) = (fx * ax, fy * ay);
        let u = gk(
            |phi| {
                let (c, s) = (phi.cos(), phi.sin());
                let gam = c * c / (ax * ax) + s * s / (ay * ay);
                let bet = x * c / (ax * ax) + y * s / (ay * ay);
                let alp = 1.0 - x * x / (ax * ax) - y * y / (ay * ay);
                let disc = (bet * bet + alp * gam).sqrt();
                let rmax = alp / (bet + disc);
                let rmin = -(bet + disc) / gam;
                gj.integrate(|rho| p0 * gam.sqrt() * (rho - rmin).sqrt(), 0.0, rmax).unwrap().value
            },
            0.0,
            2.0 * PI,
            &[],
            1e-13,
            1e-300,
        ) / (PI * es);
        let want = el.approach() - x * x / (2.0 * rx) - y * y / (2.0 * ry);
        st.add(u, want, 1e-300, &format!("({fx}a, {fy}b)"));
    }
    st.check(1e-12);
}
