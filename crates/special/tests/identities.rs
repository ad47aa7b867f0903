//! Second layer: identities, each cited, evaluated with the crate's own functions.

mod common;
use common::{rel_err, tol};
use std::f64::consts::{FRAC_PI_2, PI};
use stickslip_special as sp;

fn logspace(lo: f64, hi: f64, n: usize) -> impl Iterator<Item = f64> {
    let (a, b) = (lo.ln(), hi.ln());
    (0..n).map(move |i| (a + (b - a) * i as f64 / (n - 1) as f64).exp())
}

/// Wronskian $I_0K_1 + I_1K_0 = 1/x$ (DLMF 10.28.2), from the scaled functions only:
/// $x(\mathrm{i0e}\,\mathrm{k1e} + \mathrm{i1e}\,\mathrm{k0e}) = 1$ (the exponentials cancel).
#[test]
fn wronskian_from_scaled_functions() {
    let mut max = 0.0_f64;
    let mut sum2 = 0.0;
    let mut worst = 0.0;
    let n = 4000;
    for x in logspace(1e-6, 1e6, n) {
        let w = x * (sp::bessel_i0e(x) * sp::bessel_k1e(x) + sp::bessel_i1e(x) * sp::bessel_k0e(x));
        let e = (w - 1.0).abs();
        sum2 += e * e;
        if e > max {
            max = e;
            worst = x;
        }
    }
    println!(
        "wronskian: n = {n}, max |x W - 1| = {max:.2e} ({:.1} ulp) at x = {worst:e}, rms = {:.2e}",
        max / f64::EPSILON,
        (sum2 / n as f64).sqrt()
    );
    assert!(max <= tol::IDENTITY, "Wronskian error {max:e} at x = {worst:e}");
}

/// Legendre's relation $EK' + E'K - KK' = \pi/2$ (DLMF 19.7.1) with $K' = K(1-m)$.
/// Inputs are chosen so that $1-m$ is exact. Near $m\to0$ or $1$ the three terms grow like
/// $\ln(1/m)$ and cancel, so the error is judged against the sum of their magnitudes.
#[test]
fn legendre_relation() {
    let mut ms: Vec<f64> = (1..1024).map(|j| f64::from(j) / 1024.0).collect();
    ms.extend((1..=52).map(|k| 2.0_f64.powi(-k)));
    ms.extend((1..=52).map(|k| 1.0 - 2.0_f64.powi(-k)));
    let (mut max_scaled, mut max_rel, mut worst) = (0.0_f64, 0.0_f64, 0.0);
    for &m in &ms {
        let mc = 1.0 - m;
        let (k, e, kp, ep) = (sp::ellipk(m), sp::ellipe(m), sp::ellipk(mc), sp::ellipe(mc));
        let lhs = e * kp + ep * k - k * kp;
        let scale = (e * kp).abs() + (ep * k).abs() + (k * kp).abs();
        let err = (lhs - FRAC_PI_2).abs();
        max_rel = max_rel.max(err / FRAC_PI_2);
        if err / scale > max_scaled {
            max_scaled = err / scale;
            worst = m;
        }
    }
    println!(
        "legendre: n = {}, max err/scale = {max_scaled:.2e} at m = {worst:e}; max err/(pi/2) = {max_rel:.2e}",
        ms.len()
    );
    assert!(max_scaled <= tol::IDENTITY);
}

/// $\Gamma(x+1) = x\Gamma(x)$ (DLMF 5.5.1) on a grid with $x+1$ exact, both signs.
#[test]
fn gamma_recurrence() {
    let mut max = 0.0_f64;
    let mut worst = 0.0;
    for j in -170 * 64..170 * 64 {
        let x = f64::from(j) / 64.0 + 1.0 / 128.0; // never an integer
        let e = rel_err(sp::gamma(x + 1.0), x * sp::gamma(x));
        if e > max {
            max = e;
            worst = x;
        }
    }
    println!(
        "gamma recurrence: max rel = {max:.2e} ({:.1} ulp) at x = {worst}",
        max / f64::EPSILON
    );
    assert!(max <= tol::IDENTITY);
}

/// Reflection $\Gamma(x)\Gamma(1-x) = \pi/\sin(\pi x)$ (DLMF 5.5.3), $x$ on a grid with $1-x$ exact.
#[test]
fn gamma_reflection() {
    let mut max = 0.0_f64;
    let mut worst = 0.0;
    for j in -150 * 32..150 * 32 {
        let x = f64::from(j) / 32.0 + 1.0 / 64.0;
        let n = x.round();
        let s = (PI * (x - n)).sin() * if n % 2.0 == 0.0 { 1.0 } else { -1.0 };
        let e = rel_err(sp::gamma(x) * sp::gamma(1.0 - x), PI / s);
        if e > max {
            max = e;
            worst = x;
        }
    }
    println!(
        "gamma reflection: max rel = {max:.2e} ({:.1} ulp) at x = {worst}",
        max / f64::EPSILON
    );
    assert!(max <= tol::IDENTITY);
}

/// $\ln\Gamma(x)$ agrees with $\ln(\Gamma(x))$ on $(0, 171]$ in absolute terms scaled by
/// $\max(1, |\ln\Gamma|)$ (the log of a relative error is an absolute error).
#[test]
fn ln_gamma_matches_log_of_gamma() {
    let mut max = 0.0_f64;
    for x in logspace(1e-3, 171.0, 3000) {
        let a = sp::ln_gamma(x);
        let e = (a - sp::gamma(x).ln()).abs() / a.abs().max(1.0);
        max = max.max(e);
    }
    println!("ln_gamma vs ln(gamma): max = {max:.2e}");
    assert!(max <= tol::IDENTITY);
}

/// Parity: $I_0$ even, $I_1$ odd, exactly (DLMF 10.27.1); the ratio is odd too.
#[test]
fn bessel_parity_is_exact() {
    for x in logspace(1e-300, 1e300, 500) {
        assert_eq!(sp::bessel_i0(-x).to_bits(), sp::bessel_i0(x).to_bits());
        assert_eq!(sp::bessel_i1(-x).to_bits(), (-sp::bessel_i1(x)).to_bits());
        assert_eq!(sp::bessel_i0e(-x).to_bits(), sp::bessel_i0e(x).to_bits());
        assert_eq!(sp::bessel_i1e(-x).to_bits(), (-sp::bessel_i1e(x)).to_bits());
        assert_eq!(sp::bessel_i1_over_i0(-x).to_bits(), (-sp::bessel_i1_over_i0(x)).to_bits());
    }
}

/// The ratios agree with quotients of the plain functions where those are normal numbers.
#[test]
fn ratios_match_quotients_of_plain_functions() {
    let mut max = 0.0_f64;
    for x in logspace(1e-3, 700.0, 2000) {
        max = max.max(rel_err(sp::bessel_i1_over_i0(x), sp::bessel_i1(x) / sp::bessel_i0(x)));
        max = max.max(rel_err(sp::bessel_k0_over_k1(x), sp::bessel_k0(x) / sp::bessel_k1(x)));
    }
    println!("ratios vs quotients: max rel = {max:.2e}");
    assert!(max <= tol::IDENTITY);
}

/// $D(m)=(K-E)/m$ against the difference of [`sp::ellipk`] and [`sp::ellipe`] where that
/// difference does not cancel ($|m|\ge 0.5$), and $K - E = m D$ as $m\to1$; at $m = 0$,
/// $D = \pi/4$ exactly in the limit.
#[test]
fn ellipd_consistent_with_k_and_e() {
    let mut worst = 0.0_f64;
    for i in 0..=400 {
        let m = -1e3 + (1.0 - 1e-9 + 1e3) * f64::from(i) / 400.0;
        if m.abs() < 0.5 {
            continue;
        }
        let direct = (sp::ellipk(m) - sp::ellipe(m)) / m;
        let e = ((sp::ellipd(m) - direct) / direct).abs();
        worst = worst.max(e);
    }
    println!("ellipd vs (K-E)/m for |m| >= 0.5: max rel diff {worst:.2e}");
    // (K - E) loses at most a factor K/(K-E) <= 3 of accuracy on this range: 3 x 2 x 4 ulp.
    assert!(worst < 1e-14, "{worst}");
    assert!((sp::ellipd(0.0) - std::f64::consts::FRAC_PI_4).abs() <= f64::EPSILON);
    assert!((sp::ellipd(1e-300) - std::f64::consts::FRAC_PI_4).abs() <= f64::EPSILON);
    // Extremes: finite, positive, and on the asymptote D ~ E/(-m) ~ 1/sqrt(-m) for m -> -inf
    // (E grows like sqrt(-m), K only like ln(-m)/sqrt(-m), DLMF 19.12).
    let m = -f64::MAX;
    let asym = 1.0 / (-m).sqrt();
    let d = sp::ellipd(m);
    assert!(d.is_finite() && d > 0.0 && ((d - asym) / asym).abs() < 1e-12, "{d} vs {asym}");
    assert!(sp::ellipd(1.0 - f64::EPSILON / 2.0).is_finite());
}
