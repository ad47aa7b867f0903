//! Closed forms (FORMULAS.md E, G) against quadrature of their own traction with the Cerruti
//! kernel (FORMULAS.md F): uniform displacement (or rigid rotation) over the stick zone equal
//! to the compliance formula, resultants, loop area, limits.

mod common;
use common::{steel, tol};
use std::f64::consts::PI;
use stickslip_halfspace::Material;
use stickslip_quad::{gauss_kronrod, AdaptiveConfig, GaussJacobi, GaussLegendre, Rule, Tolerance};
use stickslip_traction::{closed::Cattaneo, closed::Deresiewicz, closed::Lubkin, closed::Mindlin};

/// $\int_0^{s_R}\sqrt{\gamma+\beta s-\alpha s^2}\,ds$ from an interior point ($\gamma > 0$):
/// the quadratic is $\alpha(s_R-s)(s-s_m)$ with $s_m<0$, so Gauss–Jacobi with weight
/// $(s_R-s)^{1/2}$ integrates the smooth $\sqrt{\alpha(s-s_m)}$.
fn sqrt_quadratic_ray(gj: &GaussJacobi, alpha: f64, beta: f64, gamma: f64) -> f64 {
    let disc = (beta * beta + 4.0 * alpha * gamma).sqrt();
    let sr = (beta + disc) / (2.0 * alpha);
    let sm = (beta - disc) / (2.0 * alpha);
    gj.sum(|s| (alpha * (s - sm)).sqrt(), 0.0, sr).unwrap()
}

/// Ray coefficients of $1 - (x/A)^2 - (y/B)^2$ along $(x_0 + s\cos\theta, y_0 + s\sin\theta)$.
fn ellipse_ray(x0: f64, y0: f64, c: f64, s: f64, aa: f64, bb: f64) -> (f64, f64, f64) {
    let alpha = (c / aa).powi(2) + (s / bb).powi(2);
    let beta = -2.0 * (x0 * c / (aa * aa) + y0 * s / (bb * bb));
    let gamma = 1.0 - (x0 / aa).powi(2) - (y0 / bb).powi(2);
    (alpha, beta, gamma)
}

/// $u_x$ at a stick-zone point of ONE body under Cattaneo's (or Mindlin's) x-traction, by
/// polar quadrature about the field point: $u_x = \frac1{2\pi}\int_0^{2\pi}
/// (c_1 + c_2\cos^2\theta)\int_0^{s_{\max}} q\,ds\,d\theta$.
fn ux_cattaneo(m: &Material, a: f64, b: f64, fp0: f64, scale: f64, x0: f64, y0: f64) -> f64 {
    let c = m.compliance();
    let gj = GaussJacobi::new(40, 0.5, 0.0).unwrap();
    let gl = GaussLegendre::new(800).unwrap();
    let v = gl
        .sum(
            |th: f64| {
                let (co, si) = (th.cos(), th.sin());
                let (al, be, ga) = ellipse_ray(x0, y0, co, si, a, b);
                let outer = sqrt_quadratic_ray(&gj, al, be, ga);
                let (al, be, ga) = ellipse_ray(x0, y0, co, si, scale * a, scale * b);
                let inner = sqrt_quadratic_ray(&gj, al, be, ga);
                (c.one_minus_nu + c.nu * co * co) * fp0 * (outer - scale * inner)
            },
            0.0,
            2.0 * PI,
        )
        .unwrap();
    v / (2.0 * PI)
}

#[test]
fn mindlin_displacement_uniform_in_stick_zone() {
    let s = steel();
    let (a, p, f) = (0.046148, 2160.0, 0.1);
    let mut worst: f64 = 0.0;
    for ratio in [0.1, 0.6667, 0.99] {
        let m = Mindlin::new(a, p, f, ratio * f * p).unwrap();
        let want = m.compliance_per_body(&s);
        let astar = m.stick_radius();
        let fp0 = f * 3.0 * p / (2.0 * PI * a * a);
        for (u, v) in [(0.0, 0.0), (0.5, 0.2), (-0.3, 0.7), (0.9, 0.0)] {
            let got = ux_cattaneo(&s, a, a, fp0, astar / a, u * astar, v * astar);
            let rel = (got / want - 1.0).abs();
            worst = worst.max(rel);
            assert!(rel < tol::CLOSED_QUADRATURE, "T/fP {ratio} at ({u},{v}): {got} vs {want}");
        }
    }
    // Relative compliance of two steel bodies is twice the per-body value (FORMULAS.md E).
    let m = Mindlin::new(a, p, f, 144.0).unwrap();
    let rel2 = m.compliance_relative(&s, &s) / (2.0 * m.compliance_per_body(&s)) - 1.0;
    println!(
        "Mindlin: max rel error of u_x in the stick zone {worst:.3e}; per body {:.6e} in",
        m.compliance_per_body(&s)
    );
    assert!(rel2.abs() < 1e-15);
    assert!((m.compliance_per_body(&s) / 0.671394e-4 - 1.0).abs() < 1e-5);
}

#[test]
fn cattaneo_displacement_uniform_both_axes() {
    let s = steel();
    let mut worst: f64 = 0.0;
    for (a, b) in [(2.0, 1.0), (1.0, 2.0), (8.0, 1.0), (1.0, 8.0)] {
        let (p, f, ratio) = (1000.0, 0.2, 0.5);
        let cat = Cattaneo::new(a, b, p, f, ratio * f * p).unwrap();
        let want = cat.compliance_per_body(&s);
        let sc = cat.stick_scale();
        let fp0 = f * cat.peak_pressure();
        for (u, v) in [(0.0, 0.0), (0.4, 0.3), (-0.6, -0.5)] {
            let got = ux_cattaneo(&s, a, b, fp0, sc, u * sc * a, v * sc * b);
            let rel = (got / want - 1.0).abs();
            worst = worst.max(rel);
            assert!(rel < tol::CLOSED_QUADRATURE, "a/b {a}/{b} ({u},{v}): {got} vs {want}");
        }
    }
    println!("Cattaneo a/b = 2, 1/2, 8, 1/8: max rel error of u_x in the stick zone {worst:.3e}");
    // Circle limit: Cattaneo -> Mindlin.
    let c = Cattaneo::new(1.0, 1.0 - 1e-9, 10.0, 0.3, 1.0).unwrap();
    let m = Mindlin::new(1.0, 10.0, 0.3, 1.0).unwrap();
    assert!((c.compliance_per_body(&s) / m.compliance_per_body(&s) - 1.0).abs() < 1e-8);
}

#[test]
fn mindlin_resultant_and_extremes() {
    let gj = GaussJacobi::new(60, 0.5, 0.0).unwrap();
    for ratio in [0.0, 1e-9, 0.3, 1.0 - 1e-9, 1.0] {
        let (a, p, f) = (2.0, 5.0, 0.4);
        let m = Mindlin::new(a, p, f, ratio * f * p).unwrap();
        // Resultant 2 pi int q rho drho, split at a* (sqrt ends on both pieces).
        let astar = m.stick_radius();
        let qh = 3.0 * f * p / (2.0 * PI * a.powi(3));
        let outer = gj.sum(|r| r * (a + r).sqrt(), 0.0, a).unwrap();
        let inner =
            if astar > 0.0 { gj.sum(|r| r * (astar + r).sqrt(), 0.0, astar).unwrap() } else { 0.0 };
        let t = 2.0 * PI * qh * (outer - inner);
        assert!((t - ratio * f * p).abs() < 1e-13 * f * p, "{t}");
        assert!(m.traction(0.5 * a).is_finite());
        let d = m.compliance_per_body(&steel());
        assert!(d.is_finite() && d >= 0.0);
    }
    assert!(Mindlin::new(1.0, 1.0, 0.1, 0.1000001).is_err());
    // Small-load compliance keeps relative accuracy: 1-(1-t)^(2/3) ~ 2t/3.
    let m = Mindlin::new(1.0, 1.0, 1.0, 1e-12).unwrap();
    let s = steel();
    let lin = 3.0 * 1.7 / (16.0 * s.shear_modulus()) * (2.0 / 3.0) * 1e-12;
    assert!((m.compliance_per_body(&s) / lin - 1.0).abs() < 1e-11);
}

#[test]
fn deresiewicz_loop_area_and_traction_resultant() {
    let s = steel();
    let (a, p, f) = (0.05, 1000.0, 0.2);
    let cfg = AdaptiveConfig { tol: Tolerance::new(0.0, 1e-13).unwrap(), ..Default::default() };
    let mut worst: f64 = 0.0;
    for ratio in [0.1, 0.5, 0.9, 1.0] {
        let ts = ratio * f * p;
        let d = Deresiewicz::new(a, p, f, ts).unwrap();
        let area = gauss_kronrod(
            |t| d.delta_unloading(t, &s).unwrap() - d.delta_reloading(t, &s).unwrap(),
            -ts,
            ts,
            &cfg,
        )
        .unwrap()
        .value;
        let w = d.energy_per_cycle(&s);
        let rel = (area / w - 1.0).abs();
        worst = worst.max(rel);
        assert!(rel < tol::CLOSED_QUADRATURE, "T*/fP {ratio}: loop {area} vs W {w}");
        // Unloading traction resultant equals T at a few loads.
        for frac in [1.0, 0.3, -0.7, -1.0] {
            let t = frac * ts;
            let res = gauss_kronrod(
                |r| 2.0 * PI * r * d.unloading_traction(r, t).unwrap(),
                0.0,
                a,
                &AdaptiveConfig {
                    tol: Tolerance::new(1e-12 * f * p, 1e-12).unwrap(),
                    breakpoints: vec![
                        d.reversal_radius(t).unwrap().min(a * (1.0 - 1e-12)),
                        a * (1.0 - ratio).cbrt(),
                    ]
                    .into_iter()
                    .filter(|&b| b > 0.0 && b < a)
                    .collect(),
                    ..Default::default()
                },
            )
            .unwrap()
            .value;
            assert!((res - t).abs() < 1e-9 * f * p, "T*/fP {ratio}, T {t}: resultant {res}");
        }
        let pts = d.hysteresis_loop(&s, 50).unwrap();
        assert_eq!(pts.len(), 101);
        assert!((pts[0].1 - pts[100].1).abs() < 1e-15 * pts[0].1.abs().max(1e-300));
    }
    // Small amplitude: W ~ (2 - nu) T*^3 / (36 G a f P).
    let ts = 1e-4 * f * p;
    let d = Deresiewicz::new(a, p, f, ts).unwrap();
    let small = (2.0 - 0.3) * ts.powi(3) / (36.0 * s.shear_modulus() * a * f * p);
    let rel_small = d.energy_per_cycle(&s) / small - 1.0;
    println!(
        "Deresiewicz: max rel |loop area - W| {worst:.3e}; small-amplitude rel {rel_small:.3e}"
    );
    assert!(rel_small.abs() < 1e-3);
}

/// Deresiewicz energy per cycle against mpmath (scripts/traction_deresiewicz.py, mp.dps = 60)
/// at t = T*/fP from 1e-8 to 1, both sides of the former series switch at 0.05 included.
/// fP = 1 exactly (f = 0.5, P = 2), so t = T* is the exact double of the table.
#[test]
fn deresiewicz_energy_matches_mpmath() {
    let s = steel();
    let (a, p, f) = (0.05, 2.0, 0.5);
    let norm = 9.0 * (2.0 - s.poisson_ratio()) / (10.0 * s.shear_modulus() * a);
    let text = include_str!("data/deresiewicz_energy.tsv");
    let (mut max, mut sum2, mut rows, mut worst) = (0.0_f64, 0.0, 0usize, 0.0);
    for line in text.lines().filter(|l| !l.starts_with('#') && !l.trim().is_empty()) {
        let mut it = line.split('\t');
        let t: f64 = it.next().unwrap().parse().unwrap();
        let bracket: f64 = it.next().unwrap().parse().unwrap();
        let w = Deresiewicz::new(a, p, f, t).unwrap().energy_per_cycle(&s);
        assert!(w.is_finite() && w > 0.0, "t = {t}: W = {w}");
        let err = (w / norm / bracket - 1.0).abs();
        if err > max {
            worst = t;
        }
        max = max.max(err);
        sum2 += err * err;
        rows += 1;
    }
    let rms = (sum2 / rows as f64).sqrt();
    println!(
        "Deresiewicz W: {rows} rows, max rel error {max:.2e} ({:.1} eps) at t = {worst:e}, RMS {rms:.2e}",
        max / f64::EPSILON
    );
    assert_eq!(rows, 37);
    assert!(max < tol::DERESIEWICZ_ENERGY, "{max}");
    // T* = 0: no slip, no dissipation.
    assert_eq!(Deresiewicz::new(a, p, f, 0.0).unwrap().energy_per_cycle(&s), 0.0);
}

/// Lubkin: M(c) limits, the mpmath-free identities of FORMULAS.md G, and the traction's
/// moment equal to M(c).
#[test]
fn lubkin_limits_and_moment() {
    let (a, p, mu) = (0.05, 1000.0, 0.3);
    let full = Lubkin::from_stick_radius(a, p, mu, 0.0).unwrap();
    let m0 = full.moment().unwrap();
    let want0 = 3.0 * PI * mu * p * a / 16.0;
    println!("Lubkin M(0) rel error {:.3e}", m0 / want0 - 1.0);
    assert!((m0 / want0 - 1.0).abs() < 1e-12);
    // c -> a: Reissner–Sagoci, omega = 3M/(16 G a^3).
    let s = steel();
    let near = Lubkin::from_stick_radius(a, p, mu, a * (1.0 - 1e-6)).unwrap();
    let rs = 3.0 * near.moment().unwrap() / (16.0 * s.shear_modulus() * a.powi(3));
    let rel = near.rotation_per_body(&s) / rs - 1.0;
    println!("Lubkin c = a(1-1e-6): omega / Reissner-Sagoci - 1 = {rel:.3e}");
    assert!(rel.abs() < 1e-5);
    // M from the traction, 2 pi int tau r^2 dr, equals M(c).
    let cfg = |bp: Vec<f64>| AdaptiveConfig {
        tol: Tolerance::new(0.0, 1e-10).unwrap(),
        breakpoints: bp,
        ..Default::default()
    };
    for cf in [0.3, 0.6, 0.9] {
        let l = Lubkin::from_stick_radius(a, p, mu, cf * a).unwrap();
        let mt = gauss_kronrod(
            |r| 2.0 * PI * r * r * l.traction(r).unwrap(),
            0.0,
            a,
            &cfg(vec![cf * a]),
        )
        .unwrap()
        .value;
        let m = l.moment().unwrap();
        println!("Lubkin c/a = {cf}: M(c) = {m:.10e}, from traction {mt:.10e}");
        assert!((mt / m - 1.0).abs() < tol::CLOSED_QUADRATURE);
        // Round trip through from_moment.
        let back = Lubkin::from_moment(a, p, mu, m).unwrap();
        assert!((back.stick_radius() / (cf * a) - 1.0).abs() < 1e-12);
    }
    assert!(Lubkin::from_moment(a, p, mu, want0 * 1.001).is_err());
}

/// Lubkin's rigid rotation: $u_\theta = \omega r$ over the stick disc from Cerruti quadrature
/// of the traction.
#[test]
fn lubkin_rigid_rotation_by_quadrature() {
    let s = steel();
    let c = s.compliance();
    let (a, p, mu) = (1.0, 1.0, 0.5);
    let gl_th = GaussLegendre::new(256).unwrap();
    let gl = GaussLegendre::new(96).unwrap();
    let gj = GaussJacobi::new(48, 0.5, 0.0).unwrap();
    let mut worst: f64 = 0.0;
    for cf in [0.3, 0.6, 0.9] {
        let l = Lubkin::from_stick_radius(a, p, mu, cf * a).unwrap();
        let omega = l.rotation_per_body(&s);
        let k0 = 3.0 * mu * p / (2.0 * PI * a.powi(3));
        for rf in [0.2, 0.5, 0.8] {
            let x0 = rf * cf * a;
            // u_y at (x0, 0) = omega x0.
            let uy = gl_th
                .sum(
                    |th: f64| {
                        let (co, si) = (th.cos(), th.sin());
                        let ray = |rad: f64| {
                            let b = 2.0 * x0 * co;
                            let g = rad * rad - x0 * x0;
                            (-b + (b * b + 4.0 * g).sqrt()) / 2.0
                        };
                        let (sc, sa) = (ray(cf * a), ray(a));
                        // Integrand along the ray: c1 tau_y + c2 n_y (n . tau).
                        let kern = |sv: f64, tau: f64| {
                            let (x, y) = (x0 + sv * co, sv * si);
                            let r = x.hypot(y);
                            if r == 0.0 {
                                return 0.0;
                            }
                            let (tx, ty) = (-y / r * tau, x / r * tau);
                            c.one_minus_nu * ty + c.nu * si * (co * tx + si * ty)
                        };
                        // Stick part: cosine map handles sqrt behaviour at s = sc.
                        let stick = gl
                            .sum(
                                |v: f64| {
                                    let sv = sc * (1.0 - (0.5 * PI * v).cos());
                                    let x = x0 + sv * co;
                                    let y = sv * si;
                                    let tau = l.traction(x.hypot(y)).unwrap();
                                    kern(sv, tau) * sc * 0.5 * PI * (0.5 * PI * v).sin()
                                },
                                0.0,
                                1.0,
                            )
                            .unwrap();
                        // Slip part: tau = k0 sqrt(a^2 - r^2) = k0 sqrt((sa - s)(s - sm)).
                        let b = 2.0 * x0 * co;
                        let sm = (-b - (b * b + 4.0 * (a * a - x0 * x0)).sqrt()) / 2.0;
                        let slip =
                            gj.sum(|sv: f64| kern(sv, k0 * (sv - sm).sqrt()), sc, sa).unwrap();
                        stick + slip
                    },
                    0.0,
                    2.0 * PI,
                )
                .unwrap()
                / (2.0 * PI);
            let rel = (uy / (omega * x0) - 1.0).abs();
            worst = worst.max(rel);
            assert!(rel < 1e-6, "c/a {cf}, r/c {rf}: u_theta/(omega r) - 1 = {rel:e}");
        }
    }
    println!("Lubkin: max rel |u_theta/(omega r) - 1| over the stick disc {worst:.3e}");
}

/// `k_minus_e` (now `m * ellipd(m)`, with the logarithmic expansion for k'^2 < 1e-6)
/// against mpmath (`scripts/traction_k_minus_e.py`, mp.dps = 40).
#[test]
fn k_minus_e_against_mpmath() {
    let text = include_str!("data/k_minus_e.tsv");
    let (mut max, mut sum2, mut rows, mut worst) = (0.0_f64, 0.0, 0usize, 0.0);
    for line in text.lines().filter(|l| !l.starts_with('#') && !l.trim().is_empty()) {
        let mut it = line.split('\t');
        let kp2: f64 = it.next().unwrap().parse().unwrap();
        let want: f64 = it.next().unwrap().parse().unwrap();
        let got = stickslip_traction::closed::k_minus_e(kp2);
        let err = if want == 0.0 { got.abs() } else { (got / want - 1.0).abs() };
        if err > max {
            worst = kp2;
        }
        max = max.max(err);
        sum2 += err * err;
        rows += 1;
    }
    let rms = (sum2 / rows as f64).sqrt();
    println!("k_minus_e: {rows} rows, max rel error {max:.2e} (k'^2 = {worst:e}), RMS {rms:.2e}");
    assert!(max < tol::K_MINUS_E, "{max}");
}
