//! McEwen / Muskhelishvili: the two closed forms against each other and against mpmath
//! quadrature of Flamant's kernels (tests/data/mcewen_flamant.csv, scripts/halfspace_mcewen_ref.py).
mod common;
use common::{read_table, tol, ErrStats};
use stickslip_halfspace::mcewen::{stress_mn, stress_potential, HertzTraction};
use stickslip_halfspace::Stress2;

fn compare(st: &mut ErrStats, got: Stress2, want: [f64; 3], scale: f64, row: &str) {
    st.add(got.xx, want[0], scale, &format!("{row} sxx"));
    st.add(got.yy, want[1], scale, &format!("{row} syy"));
    st.add(got.xy, want[2], scale, &format!("{row} sxy"));
}

#[test]
fn both_forms_vs_mpmath_flamant_quadrature() {
    // a = 1, p0 = 1, q0 = 0.375. Relative error per component, floored at 1e-3 p0 (components
    // that vanish by symmetry are compared absolutely at that scale).
    let mut pot = ErrStats::new("McEwen potential vs mpmath Flamant quadrature");
    let mut mn = ErrStats::new("McEwen m,n vs mpmath Flamant quadrature");
    let mut mn_far = ErrStats::new("McEwen m,n vs mpmath, far points r/a > 20");
    for row in read_table("mcewen_flamant.csv") {
        let (x, y) = (row[0], row[1]);
        let want = [row[2], row[3], row[4]];
        let tag = format!("({x}, {y})");
        compare(&mut pot, stress_potential(1.0, 1.0, 0.375, x, y), want, 1e-3, &tag);
        let target = if x.hypot(y) > 20.0 { &mut mn_far } else { &mut mn };
        compare(target, stress_mn(1.0, 1.0, 0.375, x, y), want, 1e-3, &tag);
    }
    pot.check(tol::MCEWEN_VS_QUAD);
    mn.check(tol::MCEWEN_VS_QUAD);
    // Far away the m,n form cancels: about eps (r/a)^2 relative (stated in its docs).
    mn_far.check(1e-9);
}

#[test]
fn forms_agree_on_a_grid() {
    let mut st = ErrStats::new("m,n vs potential on a grid (|x|,y <= 3a)");
    for i in 0..=60 {
        for j in 0..=30 {
            let x = -3.0 + 0.1 * f64::from(i) + 1e-3;
            let y = 0.1 * f64::from(j);
            let a = stress_potential(1.0, 1.3, -0.4, x, y);
            let b = stress_mn(1.0, 1.3, -0.4, x, y);
            let tag = format!("({x:.3}, {y:.3})");
            st.add(b.xx, a.xx, 1.0, &tag);
            st.add(b.yy, a.yy, 1.0, &tag);
            st.add(b.xy, a.xy, 1.0, &tag);
        }
    }
    st.check(1e-13);
}

#[test]
fn surface_values_and_edges() {
    let t = HertzTraction::new(1.0, 1.0, 0.375).unwrap();
    let mut st = ErrStats::new("surface y=0 and y=1e-6: syy=-p, sxy=-q, sxx=-p-2q0x/a");
    // At y = 1e-6 the field differs from the surface values by O(y): e.g. the shear adds
    // -q0 x y/(a sqrt(a^2-x^2)) to syy and the pressure 2 p0 y/a to sxx, i.e. ~1e-6 to 1e-5
    // relative for |x| <= 0.75 a. Closer to the edges the exact values at y = 1e-6 are checked against mpmath
    // (previous test).
    for &x in &[-0.999_f64, -0.75, -0.5, 0.0, 0.25, 0.75, 0.9, 0.999999] {
        for &y in &[0.0, 1e-6] {
            if y > 0.0 && x.abs() > 0.75 {
                continue;
            }
            let s = t.stress(x, y).unwrap();
            let (p, q) = (t.pressure(x), t.shear(x));
            // 1e-6 depth changes the field by O(y/a) only.
            // first-order deviation: |d sigma| <~ 2 (p0 + q0) y / sqrt(a^2 - x^2), relative to p or q
            let tolr = if y == 0.0 { 1e-13 } else { 10.0 * y / (1.0 - x * x) };
            let tag = format!("x={x} y={y}");
            let e1 = st.add(s.yy, -p, 1e-3, &tag);
            let e2 = st.add(s.xy, -q, 1e-3, &tag);
            let e3 = st.add(s.xx, -p - 2.0 * 0.375 * x, 1e-3, &tag);
            assert!(e1.max(e2).max(e3) <= tolr, "{tag}: {e1:e} {e2:e} {e3:e}");
        }
    }
    st.check(2e-5);
    // Exact edges and beyond on the surface: finite; trailing edge tension 2 q0.
    for x in [-1.0, 1.0, -2.0, 5.0] {
        for f in [stress_mn, stress_potential] {
            let s = f(1.0, 1.0, 0.375, x, 0.0);
            assert!(s.xx.is_finite() && s.yy.is_finite() && s.xy.is_finite(), "edge {x}");
            assert_eq!(s.yy, 0.0);
        }
    }
    let s = stress_potential(1.0, 1.0, 0.375, -1.0, 0.0);
    println!("[surface] trailing edge sxx = {} (want +2 q0 = 0.75)", s.xx);
    assert!((s.xx - 0.75).abs() < 1e-15);
    assert!(t.stress(0.0, -1.0).is_err());
    assert!(HertzTraction::new(0.0, 1.0, 0.0).is_err());
}
