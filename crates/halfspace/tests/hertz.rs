//! Hertz contacts: closed forms, limits, mpmath tables.
mod common;
use common::{read_table, tol, ErrStats};
use std::f64::consts::PI;
use stickslip_halfspace::hertz::{HertzEllipse, HertzLine, HertzSphere};
use stickslip_halfspace::Error;

#[test]
fn line_contact_closed_form() {
    let h = HertzLine::new(2.5, 0.75, 3.0e3).unwrap();
    let a = h.half_width();
    let mut st = ErrStats::new("line a, p0, P");
    st.add(a * a, 4.0 * 2.5 * 0.75 / (PI * 3.0e3), 1e-300, "a^2 = 4PR/(pi E*)");
    st.add(h.max_pressure(), a * 3.0e3 / (2.0 * 0.75), 1e-300, "p0 = aE*/2R");
    // the pressure integrates to P: int p0 sqrt(1-x^2/a^2) = pi a p0 / 2
    st.add(PI * a * h.max_pressure() / 2.0, 2.5, 1e-300, "int p = P");
    let back = HertzLine::from_half_width(a, 0.75, 3.0e3).unwrap();
    st.add(back.load(), 2.5, 1e-300, "from_half_width");
    st.check(tol::IDENTITY);
    assert_eq!(h.pressure(a), 0.0);
    assert_eq!(h.pressure(-2.0 * a), 0.0);
    assert!(HertzLine::new(-1.0, 1.0, 1.0).is_err());
    assert!(HertzLine::new(1.0, f64::NAN, 1.0).is_err());
}

#[test]
fn line_relative_approach_vs_mpmath() {
    // a = R = E* = 1 (P = pi/4)
    let h = HertzLine::from_half_width(1.0, 1.0, 1.0).unwrap();
    let mut st = ErrStats::new("line approach vs mpmath");
    for row in read_table("hertz_line_approach.csv") {
        st.add(h.approach_relative(row[0]), row[1], 1e-300, &format!("x0 = {}", row[0]));
        st.add(h.approach_relative(-row[0]), row[1], 1e-300, &format!("x0 = -{}", row[0]));
    }
    st.check(tol::MPMATH);
    // FORMULAS.md A4 asymptote (a^2/2R)(ln(2L/a) + 1/2) for L >> a.
    let l: f64 = 1e6;
    let asym = 0.5 * ((2.0 * l).ln() + 0.5);
    let e = (h.approach_relative(l) - asym).abs() / asym;
    println!("[line approach] asymptote rel diff at L/a = 1e6: {e:.2e}");
    assert!(e < 1e-12);
}

#[test]
fn sphere_closed_form() {
    let s = HertzSphere::new(2160.0, 1.0, 30e6 / (2.0 * (1.0 - 0.09))).unwrap();
    // FORMULAS.md E, seed 002 example 1: a = 0.046148 in, p0 = 484 ksi.
    println!("[sphere] example 1: a = {:.6}, p0 = {:.1}", s.contact_radius(), s.max_pressure());
    assert!((s.contact_radius() - 0.046148).abs() < 5e-7);
    assert!((s.max_pressure() / 1e3 - 484.0).abs() < 0.5);
    let a = s.contact_radius();
    let mut st = ErrStats::new("sphere identities");
    st.add(s.approach(), a * a / 1.0, 1e-300, "delta = a^2/R");
    st.add(2.0 * PI * a * a * s.max_pressure() / 3.0, 2160.0, 1e-300, "int p dA = P");
    st.check(tol::IDENTITY);
}

#[test]
fn ellipse_circle_limit_is_exact() {
    for &(r, p, e) in &[(1.0, 1.0, 1.0), (0.02, 350.0, 1.1e11), (3.0, 1e-3, 2.0)] {
        let el = HertzEllipse::new(r, r, p, e).unwrap();
        let sp = HertzSphere::new(p, r, e).unwrap();
        let mut st = ErrStats::new("ellipse circle limit");
        st.add(el.semi_axis_x(), sp.contact_radius(), 1e-300, "a");
        st.add(el.semi_axis_y(), sp.contact_radius(), 1e-300, "b");
        st.add(el.max_pressure(), sp.max_pressure(), 1e-300, "p0");
        st.add(el.approach(), sp.approach(), 1e-300, "delta");
        st.check(4.0 * f64::EPSILON);
        assert_eq!(el.eccentricity_sq(), 0.0);
    }
}

#[test]
fn ellipse_vs_mpmath() {
    let mut st = ErrStats::new("ellipse vs mpmath");
    let mut worst_iter = 0;
    for row in read_table("hertz_ellipse.csv") {
        let lam = row[0];
        for swap in [false, true] {
            let el = if swap {
                HertzEllipse::new(1.0 / lam, 1.0, 1.0, 1.0).unwrap()
            } else {
                HertzEllipse::new(1.0, 1.0 / lam, 1.0, 1.0).unwrap()
            };
            worst_iter = worst_iter.max(el.iterations());
            let (a, b) = if swap {
                (el.semi_axis_y(), el.semi_axis_x())
            } else {
                (el.semi_axis_x(), el.semi_axis_y())
            };
            let tag = format!("ratio {lam} swap {swap}");
            st.add(a, row[2], 1e-300, &format!("{tag} a"));
            st.add(b, row[3], 1e-300, &format!("{tag} b"));
            st.add(el.max_pressure(), row[4], 1e-300, &format!("{tag} p0"));
            st.add(el.approach(), row[5], 1e-300, &format!("{tag} delta"));
            st.add(1.0 - el.eccentricity_sq(), 1.0 - row[1], 1e-300, &format!("{tag} 1-m"));
        }
    }
    println!("[ellipse] max root-finder iterations {worst_iter}");
    st.check(tol::HERTZ_ELLIPSE);
}

#[test]
fn ellipse_greenwood_sanity_and_scaling() {
    // Sanity only: b/a ~ (R'_minor/R'_major)^(2/3) within ~10 % for moderate ratios.
    for lam in [2.0, 4.0, 16.0] {
        let el = HertzEllipse::new(lam, 1.0, 1.0, 1.0).unwrap();
        let ratio = el.semi_axis_y() / el.semi_axis_x();
        let approx = lam.powf(-2.0 / 3.0);
        println!("[ellipse] ratio {lam}: b/a = {ratio:.6}, (1/ratio)^(2/3) = {approx:.6}");
        assert!((ratio / approx - 1.0).abs() < 0.1);
    }
    // Scaling: a ~ (P R / E*)^(1/3), delta ~ (P^2 / (R E*^2))^(1/3).
    let e1 = HertzEllipse::new(2.0, 0.5, 1.0, 1.0).unwrap();
    let e2 = HertzEllipse::new(2.0, 0.5, 8.0, 1.0).unwrap();
    assert!((e2.semi_axis_x() / e1.semi_axis_x() - 2.0).abs() < 1e-14);
    assert!((e2.approach() / e1.approach() - 4.0).abs() < 1e-14);
    // extreme ratios: finite or a clear error
    let e = HertzEllipse::new(1.0, 1e-10, 1.0, 1.0).unwrap();
    assert!(e.semi_axis_x().is_finite() && e.semi_axis_y() > 0.0 && e.approach().is_finite());
    assert!(matches!(HertzEllipse::new(1.0, 1e-13, 1.0, 1.0), Err(Error::OutOfDomain { .. })));
    assert!(HertzEllipse::new(1.0, 0.0, 1.0, 1.0).is_err());
}
