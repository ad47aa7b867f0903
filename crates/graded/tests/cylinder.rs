//! Constants, rigid-cylinder contact and surface displacements: Table 1 of seed 000
//! (recomputed in FORMULAS.md A1, A4), the spectral relation (A4), mpmath references (A3, A4),
//! eq 32 and its omitted odd part (A5), the homogeneous limit (B).

mod common;
use common::{read_table, rel, tol, ErrStats};
use std::f64::consts::PI;
use stickslip_graded::{
    beta, checked_beta, i_k, j_k, Accuracy, Error, GradedMaterial, RigidCylinder,
    SurfaceDisplacement, SurfaceLoad,
};

fn table1() -> (GradedMaterial, RigidCylinder) {
    let m = GradedMaterial::new(1_767_600.0, 0.1, 0.3).unwrap();
    let c = RigidCylinder::from_half_width(&m, 0.3, 0.0178).unwrap();
    (m, c)
}

#[test]
fn table1_recomputed() {
    let (m, c) = table1();
    let h = c.indentation().unwrap();
    println!(
        "Table 1: beta = {:.9}, I_k = {:.9}, J_k = {:.9}, h = {:.9}, P = {:.6}, p0 = {:.3}",
        m.beta(),
        m.i_k(),
        m.j_k(),
        h,
        c.load(),
        c.p0()
    );
    assert!((m.beta() - 1.026088).abs() < tol::TABLE1_BETA_ABS);
    assert!((m.i_k() - 0.760992).abs() < 5e-7);
    assert!((m.j_k() - 0.709859).abs() < 5e-7);
    assert!((h - 0.0052807).abs() < 5e-8);
    assert!((c.load() - 986.39).abs() < 5e-3);
    // FORMULAS.md A4 quotes p0 = 35 954 kgf/m^2 for these data.
    assert!((c.p0() - 35954.0).abs() < 0.5);
    // plain functions agree with the struct
    assert_eq!(beta(0.3, 0.1), m.beta());
    assert_eq!(i_k(0.3, 0.1), m.i_k());
    assert!(rel(j_k(0.3, 0.1), m.j_k()) < 1e-15);
    // round trip a -> P -> a
    let c2 = RigidCylinder::from_load(&m, 0.3, c.load()).unwrap();
    let e = rel(c2.half_width(), 0.0178);
    println!("round trip a -> P -> a: rel err {e:.2e}");
    assert!(e < 1e-14);
}

#[test]
fn i_k_closed_form_identities() {
    // I_0 = J_0 = pi/4 (FORMULAS.md A1, B).
    let e0 = rel(i_k(0.3, 0.0), PI / 4.0);
    let e1 = rel(j_k(0.3, 0.0), PI / 4.0);
    println!("I_0 - pi/4: {e0:.2e}, J_0 - pi/4: {e1:.2e}");
    assert!(e0 < 4.0 * f64::EPSILON && e1 < 4.0 * f64::EPSILON);
    // beta^2 both forms
    for &(nu, k) in &[(0.1, 0.01), (0.3, 0.5), (0.45, 0.95), (-0.5, 0.3)] {
        let b: f64 = beta(nu, k);
        let alt = ((1.0 + k) * (1.0 - k * nu / (1.0 - nu))).sqrt();
        assert!(rel(b, alt) < 1e-15, "nu {nu} k {k}");
    }
}

#[test]
fn domain_errors_are_clear() {
    assert!(matches!(
        GradedMaterial::new(1.0, 1.0, 0.3),
        Err(Error::OutOfDomain { name: "k", .. })
    ));
    assert!(matches!(
        GradedMaterial::new(1.0, -0.1, 0.3),
        Err(Error::OutOfDomain { name: "k", .. })
    ));
    assert!(matches!(
        GradedMaterial::new(0.0, 0.1, 0.3),
        Err(Error::OutOfDomain { name: "e0", .. })
    ));
    // nu = 0.6 with k = 0.9: 1/(1+k) = 0.526 -> beta not real
    let e = GradedMaterial::new(1.0, 0.9, 0.6).unwrap_err();
    println!("{e}");
    assert!(matches!(e, Error::BetaNotReal { .. }));
    assert!(checked_beta(-1.0, 0.1).is_err());
    assert!(beta(0.6, 0.9).is_nan());
    assert!(i_k(f64::NAN, 0.5).is_nan());
    // k = 0: no absolute indentation, but a relative approach
    let m0 = GradedMaterial::new(1.0, 0.0, 0.3).unwrap();
    let c0 = RigidCylinder::from_load(&m0, 1.0, 1.0).unwrap();
    let err = c0.indentation().unwrap_err();
    println!("{err}");
    assert_eq!(err, Error::NoAbsoluteIndentation);
    assert!(c0.relative_approach(10.0).unwrap().is_finite());
    assert!(RigidCylinder::from_load(&m0, -1.0, 1.0).is_err());
    assert!(RigidCylinder::from_load(&m0, 1.0, f64::INFINITY).is_err());
}

/// FORMULAS.md A4: int (1-t^2)^((1+k)/2) |x-t|^-k dt = pi(1+k)/(2cos(k pi/2)) (1 - k x^2).
#[test]
fn spectral_relation() {
    let mut st = ErrStats::default();
    for &k in &[1e-6, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.95] {
        let m = GradedMaterial::new(1.0, k, 0.3).unwrap();
        let load = SurfaceLoad::cylinder(1.0, 1.0, k, 0.0).unwrap();
        let d = SurfaceDisplacement::new(
            &m,
            load,
            Accuracy::new(stickslip_graded::Tolerance::relative(1e-13).unwrap()).unwrap(),
        )
        .unwrap();
        for &x in &[0.0, 0.1, -0.37, 0.5, 0.9, -0.99, 0.999999, 1.0, -1.0] {
            let got = d.integrals(x).unwrap().p_even;
            let want = PI * (1.0 + k) / (2.0 * (k * PI / 2.0).cos()) * (1.0 - k * x * x);
            st.add(rel(got, want), || format!("k={k} x={x} got={got:e} want={want:e}"));
        }
    }
    st.report("spectral relation A4");
    assert!(st.max < tol::SPECTRAL_REL);
}

/// The odd surface integral against mpmath (graded_odd_integral.txt).
#[test]
fn odd_integral_vs_mpmath() {
    let mut st = ErrStats::default();
    for row in read_table("graded_odd_integral.txt") {
        let (k, x, want) = (row[0], row[1], row[2]);
        let m = GradedMaterial::new(1.0, k, 0.3).unwrap();
        let load = SurfaceLoad::cylinder(1.0, 1.0, k, 0.0).unwrap();
        let d = SurfaceDisplacement::new(
            &m,
            load,
            Accuracy::new(stickslip_graded::Tolerance::relative(1e-13).unwrap()).unwrap(),
        )
        .unwrap();
        let got = d.integrals(x).unwrap().p_odd;
        // scale: the integral is O(1); use absolute error where it vanishes (x = 0)
        let e = if want.abs() < 1e-3 { (got - want).abs() } else { rel(got, want) };
        st.add(e, || format!("k={k} x={x} got={got:e} want={want:e}"));
    }
    st.report("odd surface integral vs mpmath");
    assert!(st.max < tol::SURFACE_REL);
}

/// Relative approach delta(L) against mpmath quadrature (graded_approach.txt), including the
/// exact homogeneous form at k = 0 and its continuity to k = 1e-6.
#[test]
fn relative_approach_vs_mpmath() {
    let mut st = ErrStats::default();
    let mut st_small = ErrStats::default();
    for row in read_table("graded_approach.txt") {
        let (k, l, want) = (row[0], row[1], row[2]);
        let m = GradedMaterial::new(1.0, k, 0.3).unwrap();
        let (radius, a) = (2.0, 0.5);
        let c = RigidCylinder::from_half_width(&m, radius, a).unwrap();
        let got = c.relative_approach(l * a).unwrap() / (a * a / (2.0 * radius));
        let e = rel(got, want);
        if std::env::var("GRADED_DEBUG").is_ok() {
            println!("approach k={k} l={l} rel err {e:.2e}");
        }
        let line = || format!("k={k} l={l} got={got:.15} want={want:.15}");
        if k > 0.0 && k < 1e-2 {
            st_small.add(e, line);
        } else {
            st.add(e, line);
        }
    }
    st.report("relative approach (k = 0 and k >= 0.1)");
    st_small.report("relative approach (k = 1e-6, 1e-3)");
    assert!(st.max < tol::SURFACE_REL);
    assert!(st_small.max < tol::APPROACH_SMALL_K_REL);
}

/// FORMULAS.md A4: delta(L) -> (a^2/2R)(ln(2L/a) + 1/2) for L >> a; 0.010122 at k = 1e-4 vs
/// 0.010126 homogeneous (the spec's check, same data as Table 1 except k).
#[test]
fn relative_approach_limits() {
    let m0 = GradedMaterial::new(1.0, 0.0, 0.3).unwrap();
    let c0 = RigidCylinder::from_half_width(&m0, 1.0, 0.01).unwrap();
    let l: f64 = 1e4 * 0.01;
    let asym = 0.01f64.powi(2) / 2.0 * ((2.0 * l / 0.01).ln() + 0.5);
    let got = c0.relative_approach(l).unwrap();
    println!("k = 0, L = 1e4 a: delta = {got:.12e}, asymptote {asym:.12e}");
    assert!(rel(got, asym) < 1e-8); // next term O((a/L)^2)
                                    // inside the contact: L^2/(2R); continuous at L = a
    assert_eq!(c0.relative_approach(0.005).unwrap(), 0.005 * 0.005 / 2.0);
    let above = c0.relative_approach(0.01 * (1.0 + 1e-12)).unwrap();
    assert!(rel(above, 0.01 * 0.01 / 2.0) < 1e-5);
}

/// FORMULAS.md A5: eq 32 values (mu = 1, exact h) and the omitted pressure-induced odd part.
#[test]
fn eq32_and_pressure_odd_part() {
    let (m, c) = table1();
    let a = c.half_width();
    let xs = [-a, -0.01, 0.0, 0.01, a];
    let want32 = [0.005462, 0.005877, 0.006069, 0.005877, 0.005462];
    let d =
        SurfaceDisplacement::new(&m, c.surface_load(0.0).unwrap(), Accuracy::default()).unwrap();
    let dq =
        SurfaceDisplacement::new(&m, c.surface_load(1.0).unwrap(), Accuracy::default()).unwrap();
    for (&x, &w) in xs.iter().zip(&want32) {
        let u32 = c.slip_displacement_eq32(x, 1.0).unwrap();
        // eq 32 is the q-induced u_x computed by full integration (A3 with q = mu p)
        let full_q = dq.parts(x).unwrap().ux_from_q;
        let ux_p = d.parts(x).unwrap().ux_from_p;
        println!(
            "x = {x:+.4}: eq32 = {u32:.7}, A3 integral = {full_q:.7} (rel diff {:.1e}), \
             pressure odd part = {ux_p:+.4e}",
            rel(full_q, u32)
        );
        assert!((u32 - w).abs() < 5e-7);
        assert!(rel(full_q, u32) < 1e-12);
    }
    let odd = |x: f64| d.parts(x).unwrap().ux_from_p;
    assert!((odd(-0.01) - 1.448e-4).abs() < 5e-8, "{}", odd(-0.01));
    assert!((odd(0.01) + 1.448e-4).abs() < 5e-8);
    assert!((odd(-a) - 2.089e-4).abs() < 5e-8, "{}", odd(-a));
    assert!((odd(a) + 2.089e-4).abs() < 5e-8);
    // u_y of the cylinder pressure is h - x^2/(2R) inside the contact (FORMULAS.md A4)
    let h = c.indentation().unwrap();
    for &x in &[0.0, 0.005, -0.0123, a] {
        let uy = d.displacement(x).unwrap().y;
        let want = h - x * x / (2.0 * c.radius());
        println!("u_y({x}) = {uy:.12e}, h - x^2/2R = {want:.12e}");
        assert!(rel(uy, want) < 1e-12);
    }
}

/// FORMULAS.md B: at k = 1e-6 the contact is 2D Hertz (a, p0, p(x)) to 1e-6 relative.
#[test]
fn homogeneous_limit_contact() {
    use stickslip_halfspace::hertz::HertzLine;
    let (e0, nu, radius, load) = (2.0e11, 0.3, 0.05, 1.0e5);
    let m = GradedMaterial::new(e0, 1e-6, nu).unwrap();
    let c = RigidCylinder::from_load(&m, radius, load).unwrap();
    let hz = HertzLine::new(load, radius, e0 / (1.0 - nu * nu)).unwrap();
    // Lengths: a^(2+k) mixes units at k != 0; use metres throughout, a ~ 1e-4.
    let ea = rel(c.half_width(), hz.half_width());
    let ep = rel(c.p0(), hz.max_pressure());
    let x = 0.3 * hz.half_width();
    let epx = rel(c.pressure(x), hz.max_pressure() * (1.0 - 0.09f64).sqrt());
    println!("k = 1e-6 vs Hertz: a rel {ea:.2e}, p0 rel {ep:.2e}, p(0.3a) rel {epx:.2e}");
    // the spec's number: a_corr(P = R = E = 1) = 1.0764055 at k = 1e-6 vs Hertz 1.0764051
    let m1 = GradedMaterial::new(1.0, 1e-6, 0.3).unwrap();
    let a1 = RigidCylinder::from_load(&m1, 1.0, 1.0).unwrap().half_width();
    println!("a(P=R=E0=1, k=1e-6) = {a1:.8}");
    assert!((a1 - 1.0764055).abs() < 5e-8);
    // k = 1e-6 with lengths ~1e-4: a^(2+k) carries a factor a^k = 1 - 9e-6 relative, so the
    // comparison is made at unit length scale where that factor is 1.
    let m = GradedMaterial::new(1.0, 1e-6, nu).unwrap();
    let c = RigidCylinder::from_load(&m, 1.0, 1.0).unwrap();
    let hz = HertzLine::new(1.0, 1.0, 1.0 / (1.0 - nu * nu)).unwrap();
    let ea = rel(c.half_width(), hz.half_width());
    let ep = rel(c.p0(), hz.max_pressure());
    println!("k = 1e-6 vs Hertz (unit scale): a rel {ea:.2e}, p0 rel {ep:.2e}");
    assert!(ea < tol::HOMOGENEOUS_REL && ep < tol::HOMOGENEOUS_REL);
    // k = 0 exactly is Hertz to rounding
    let m0 = GradedMaterial::new(1.0, 0.0, nu).unwrap();
    let c0 = RigidCylinder::from_load(&m0, 1.0, 1.0).unwrap();
    let e0a = rel(c0.half_width(), hz.half_width());
    println!("k = 0 vs Hertz: a rel {e0a:.2e}");
    assert!(e0a < 1e-14);
    // relative approach: k = 1e-6 vs exact homogeneous at L = 5a
    let d1 = c.relative_approach(5.0 * c.half_width()).unwrap();
    let d0 = c0.relative_approach(5.0 * c0.half_width()).unwrap();
    println!("delta(5a): k=1e-6 {d1:.12e}, k=0 {d0:.12e}, rel {:.2e}", rel(d1, d0));
    assert!(rel(d1, d0) < tol::HOMOGENEOUS_REL);
}

/// FORMULAS.md B: u_x from the pressure at k = 1e-6 against Flamant's step term integrated
/// over the Hertz pressure: u_x(x) = -(1-2nu)(1+nu)/(2E) int p sgn(x-s) ds.
#[test]
fn homogeneous_limit_displacement() {
    let (nu, k) = (0.3, 1e-6);
    let m = GradedMaterial::new(1.0, k, nu).unwrap();
    let c = RigidCylinder::from_load(&m, 1.0, 1.0).unwrap();
    let a = c.half_width();
    let d =
        SurfaceDisplacement::new(&m, c.surface_load(0.5).unwrap(), Accuracy::default()).unwrap();
    let mut st = ErrStats::default();
    let mut st_out = ErrStats::default();
    // |x - s| <= 3a ~ 3: the graded kernel differs from Flamant by ~k ln|x - s| (physical).
    for &xr in &[-2.0, -1.0, -0.5, 0.2, 0.9, 1.7] {
        let x = xr * a;
        // int_{-a}^{x} p0 sqrt(1 - s^2/a^2) ds (x clipped to [-a, a]) with Hertz p0
        let t = xr.clamp(-1.0, 1.0);
        let p0 = 2.0 / (PI * a);
        let left = p0 * a * 0.5 * (t * (1.0 - t * t).sqrt() + t.asin() + PI / 2.0);
        let signed = left - (1.0 - left); // int p sgn(x - s) ds, total P = 1
        let step = (1.0 - 2.0 * nu) * (1.0 + nu) / 2.0;
        let ux_want = -step * signed;
        let uy_want = -step * 0.5 * signed; // u_y from q = 0.5 p: +step * int q sgn(s - x)
        let parts = d.parts(x).unwrap();
        let st = if xr.abs() <= 1.0 { &mut st } else { &mut st_out };
        st.add(rel(parts.ux_from_p, ux_want), || {
            format!("ux_p x/a={xr} got={:e} want={ux_want:e}", parts.ux_from_p)
        });
        st.add(rel(parts.uy_from_q, -uy_want), || {
            format!("uy_q x/a={xr} got={:e} want={:e}", parts.uy_from_q, -uy_want)
        });
    }
    st.report("k = 1e-6 odd displacement parts vs Flamant, |x| <= a");
    st_out.report("k = 1e-6 odd displacement parts vs Flamant, a < |x| <= 2a");
    assert!(st.max < tol::HOMOGENEOUS_REL);
    assert!(st_out.max < tol::HOMOGENEOUS_O_K * k);
}
