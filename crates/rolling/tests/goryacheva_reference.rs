//! Goryacheva's l, d, m, C2, Q, M1 against the mpmath reference (unscaled eqs 19-28 at 50
//! digits, scripts/rolling_reference.py), over alpha, beta in [1e-6, 1e6] s, w in
//! [0.01, 100] m/s, three materials, Bessel arguments up to ~1e7.

mod common;
use common::{reference_rows, rel_err, tol, Stats};
use stickslip_rolling::{solve, GoryachevaParams, Regime, Response};

#[test]
fn matches_mpmath_reference() {
    let rows = reference_rows();
    assert!(rows.len() >= 150, "reference table has only {} rows", rows.len());
    let names = ["l", "d", "m", "C2", "Q", "M1"];
    let mut stats: Vec<Stats> = names.iter().map(|_| Stats::new()).collect();
    let mut max_x1: f64 = 0.0;
    let mut max_iter = (0, 0);
    for (i, r) in rows.iter().enumerate() {
        let p = GoryachevaParams::new(r.e, r.nu, r.r, r.p, r.rho, r.delta, r.alpha, r.beta, r.w)
            .unwrap();
        let s = solve(&p).unwrap();
        assert_eq!(s.regime, Regime::StickSlip, "row {i}");
        assert_eq!(s.response, Response::Viscoelastic, "row {i}");
        let got =
            [s.contact_length, s.shift, s.stick_length, s.c2, s.tangential_force, s.moment_m1];
        let want = [r.l, r.d, r.m, r.c2, r.q, r.m1];
        for k in 0..6 {
            assert!(got[k].is_finite(), "row {i}: {} not finite", names[k]);
            stats[k].add(i, rel_err(got[k], want[k]));
        }
        max_x1 = max_x1.max(s.info.bessel_args[0]);
        max_iter.0 = max_iter.0.max(s.info.length_iterations);
        max_iter.1 = max_iter.1.max(s.info.stick_iterations);
    }
    println!("{} rows; largest Bessel argument x1 = {max_x1:.3e}; max Brent iterations: eq19 {}, eq24 {}",
        rows.len(), max_iter.0, max_iter.1);
    for (k, st) in stats.iter().enumerate() {
        let r = &rows[st.worst];
        println!(
            "{:>2}: max rel err {:.3e}, rms {:.3e}, worst row {} ({} alpha={:e} beta={:e} w={})",
            names[k],
            st.max,
            st.rms(),
            st.worst,
            r.material,
            r.alpha,
            r.beta,
            r.w
        );
    }
    for (k, st) in stats.iter().enumerate() {
        assert!(st.max <= tol::REFERENCE_REL, "{}: max rel err {:e}", names[k], st.max);
    }
    assert!(max_x1 > 1e6, "table must include Bessel arguments above 1e6");
}
