//! Seed 001 (Goryacheva 1973, viscoelastic cylinder rolling on the same material): the
//! Wronskian identity, the elastic limit, the contact-length claim and the stick/slip
//! solution, all through `stickslip-rolling` (FORMULAS.md D). SI units.

use crate::fmt::{num, sig};
use crate::record::{Check, Claim, Figure, Row, Series, Source, Style, Table};
use crate::Error;
use stickslip_rolling::{
    carter, claim_sweep, solve, CarterParams, GoryachevaParams, Regime, StressConfig, SweepMaterial,
};
use stickslip_special::{bessel_i0, bessel_i0e, bessel_i1e, bessel_k0e, bessel_k1, bessel_k1e};

const SEED: &str = "001";

fn src(place: &'static str, words: &'static str) -> Source {
    Source { seed: SEED, place, words }
}

/// G-W: $I_0(x)K_1(x) + I_1(x)K_0(x) = 1/x$ over $x \in [10^{-6}, 10^6]$, in the scaled form
/// $x\,[\hat I_0\hat K_1 + \hat I_1\hat K_0] = 1$ ($\hat I = e^{-x}I$, $\hat K = e^{x}K$).
///
/// # Errors
/// Never (kept for the uniform builder signature).
pub fn g_w() -> Result<Check, Error> {
    let xs: Vec<f64> = (0..=120).map(|i| 10f64.powf(-6.0 + i as f64 / 10.0)).collect();
    let w = |x: f64| x * (bessel_i0e(x) * bessel_k1e(x) + bessel_i1e(x) * bessel_k0e(x));
    let worst = xs.iter().map(|&x| (w(x) - 1.0).abs()).fold(0.0, f64::max);
    let mut rows = Vec::new();
    for x in [1e-6, 1e-3, 1.0, 1e3, 1e6] {
        rows.push(Row::closed(
            format!("x (I0 K1 + I1 K0) at x = {}, scaled", sig(x, 3)),
            "Wronskian, A&S 9.6.15",
            1.0,
            w(x),
            1e-13,
        ));
    }
    rows.push(Row::value(
        "unscaled I0(x) K1(x) at x = 1000, as printed in eqs 19, 24 (overflow times underflow)",
        bessel_i0(1e3) * bessel_k1(1e3),
    ));
    Ok(Check {
        id: "G-W",
        seed: SEED,
        title: "The identity I0(x)K1(x) + I1(x)K0(x) = 1/x".into(),
        how: vec!["121 log-spaced x in [1e-6, 1e6] with the exponentially scaled Bessel functions of stickslip-special".into()],
        rows,
        claims: vec![Claim {
            claim: "I0(x)K1(x) + I1(x)K0(x) = 1/x".into(),
            source: src("Elastic limit, before eq 29", "Let us use the relationship"),
            holds: worst < 1e-13,
            deciding: format!("max |x W(x) - 1| over the 121 points below 1e-13: {}", if worst < 1e-13 { "yes" } else { "no" }),
            expected: Some(true),
        }],
        ..Check::default()
    })
}

/// Rubber-like test material of the rolling checks: $E$ = 5 MPa, $\nu$ = 0.49, $R$ = 5 cm,
/// $P$ = 1 kN/m, friction 0.8 (the same as `SweepMaterial::RUBBER_LIKE`).
const E: f64 = 5.0e6;
const NU: f64 = 0.49;
const R: f64 = 0.05;
const P: f64 = 1.0e3;
const RHO: f64 = 0.8;

/// G-E: the elastic limit $\alpha \to \beta$ against the paper's closed forms (Carter).
///
/// # Errors
/// From `stickslip-rolling`.
pub fn g_e() -> Result<Check, Error> {
    let (beta, w, delta) = (0.1, 1.0, 0.01);
    let alpha = beta * (1.0 + 1e-9);
    let s = solve(&GoryachevaParams::new(E, NU, R, P, RHO, delta, alpha, beta, w)?)?;
    let cp = CarterParams::new(E, NU, R, P, RHO, delta)?;
    let c = carter(&cp);
    let k = cp.compliance();
    let a = (2.0 * k * R * P).sqrt();
    let tol = 1e-6;
    let mut rows = vec![
        Row::closed(
            "contact length l (m)",
            "l = sqrt(8KRP)",
            (8.0 * k * R * P).sqrt(),
            s.contact_length,
            tol,
        ),
        Row::closed("shift d / l_H", "d = 0", 0.0, s.shift / s.hertz_length, tol).zero_below(1e3),
        Row::closed(
            "stick start c (m)",
            "c = -a + 2 delta R / rho",
            -a + 2.0 * delta * R / RHO,
            s.stick_start,
            tol,
        ),
        Row::closed(
            "Q (N/m)",
            "Q = -rho P [1 - (1 - delta R/(rho a))^2]",
            -RHO * P * (1.0 - (1.0 - delta * R / (RHO * a)).powi(2)),
            s.tangential_force,
            tol,
        ),
        Row::closed(
            "C2 (N/m)",
            "C2 = -rho m alpha w/(2KR)",
            -RHO * s.stick_length * alpha * w / (2.0 * k * R),
            s.c2,
            tol,
        ),
    ];
    let cfg = StressConfig::default();
    let mut pts_p = Vec::new();
    let mut pts_t = Vec::new();
    let mut curve_p = Vec::new();
    let mut curve_t = Vec::new();
    for i in 1..40 {
        let x = -a + 2.0 * a * i as f64 / 40.0;
        pts_p.push((x / a, s.pressure(x, &cfg)?.value));
        pts_t.push((x / a, s.shear(x, &cfg)?.value));
        curve_p.push((x / a, c.pressure(x)));
        curve_t.push((x / a, c.shear(x)));
    }
    for t in [-0.75, -0.25, 0.25, 0.75] {
        let x = t * a;
        rows.push(Row::closed(
            format!("pressure at x/a = {t} (Pa)"),
            "p0 sqrt(1-x^2/a^2)",
            c.pressure(x),
            s.pressure(x, &cfg)?.value,
            tol,
        ));
        rows.push(Row::closed(
            format!("shear at x/a = {t} (Pa)"),
            "Carter",
            c.shear(x),
            s.shear(x, &cfg)?.value,
            tol,
        ));
    }
    Ok(Check {
        id: "G-E",
        seed: SEED,
        title: "Elastic limit alpha = beta: l = sqrt(8KRP), d = 0, Carter's c, creep law and tractions".into(),
        how: vec![format!(
            "viscoelastic solver at alpha = beta (1 + 1e-9), beta = {beta} s, w = {w} m/s, creep delta = {delta}; rubber-like E = 5 MPa, nu = 0.49, R = 5 cm, P = 1 kN/m, rho = 0.8; references are the paper's elastic-limit formulas (FORMULAS.md D)"
        )],
        rows,
        figures: vec![Figure {
            name: "seed001_GE".into(),
            caption: "Elastic limit: pressure and shear, solver (points) vs Carter (lines)".into(),
            x_label: "x/a".into(),
            y_label: "stress (Pa)".into(),
            series: vec![
                Series { label: "Carter pressure".into(), style: Style::Line, points: curve_p },
                Series { label: "Carter shear".into(), style: Style::Line, points: curve_t },
                Series { label: "solver pressure".into(), style: Style::Points, points: pts_p },
                Series { label: "solver shear".into(), style: Style::Points, points: pts_t },
            ],
        }],
        ..Check::default()
    })
}

/// G-L: the claim $l \approx \sqrt{8KRP\beta/\alpha}$ over the seed's grid.
///
/// # Errors
/// From `stickslip-rolling`.
pub fn g_l() -> Result<Check, Error> {
    const TOL: f64 = 0.01;
    let mut tab = Table {
        caption: format!("claim sweep, 2 points per decade of alpha and beta in [0.1, 1e6] s, alpha > beta, w = 0.1, 1, 10 m/s; 'fails' = |l/l_claim - 1| > {TOL}"),
        header: ["material", "l_H (m)", "rows", "fails", "min x1 among fails", "max |err| at x1 <= 0.02", "min d (m)", "worst: alpha, beta, w, l/l_claim, l/l_H, x1"]
            .map(String::from)
            .to_vec(),
        rows: Vec::new(),
    };
    let mut all_forward = true;
    let mut fails_only_large = true;
    let mut universal = true;
    let mut series = Vec::new();
    let mut deciding = Vec::new();
    for mat in [SweepMaterial::RUBBER_LIKE, SweepMaterial::POLYMER_LIKE] {
        let rows = claim_sweep(&mat, 2)?;
        let fails: Vec<_> = rows.iter().filter(|r| !r.claim_holds(TOL)).collect();
        let min_x1 = fails.iter().map(|r| r.x1).fold(f64::INFINITY, f64::min);
        let small =
            rows.iter().filter(|r| r.x1 <= 0.02).map(|r| r.claim_error.abs()).fold(0.0, f64::max);
        let min_d = rows.iter().map(|r| r.shift).fold(f64::INFINITY, f64::min);
        let worst = rows.iter().max_by(|a, b| a.claim_error.abs().total_cmp(&b.claim_error.abs()));
        all_forward &= rows.iter().all(|r| r.shift > 0.0);
        fails_only_large &= fails.iter().all(|r| r.x1 > 0.05);
        universal &= fails.is_empty();
        deciding.push(format!(
            "{}: {} of {} rows off by more than 1 %, all with x1 >= {}",
            mat.name,
            fails.len(),
            rows.len(),
            sig(min_x1, 4)
        ));
        tab.rows.push(vec![
            mat.name.into(),
            num(mat.hertz_length()),
            rows.len().to_string(),
            fails.len().to_string(),
            sig(min_x1, 4),
            sig(small, 3),
            sig(min_d, 3),
            worst.map_or("-".into(), |r| {
                format!(
                    "{}, {}, {}, {}, {}, {}",
                    sig(r.alpha, 4),
                    sig(r.beta, 4),
                    r.speed,
                    sig(r.claim_error + 1.0, 6),
                    sig(r.length_over_hertz, 6),
                    sig(r.x1, 6)
                )
            }),
        ]);
        series.push(Series {
            label: format!("{}: l/l_claim", mat.name),
            style: Style::Points,
            points: rows.iter().map(|r| (r.x1.log10(), r.claim_error + 1.0)).collect(),
        });
    }
    let words =
        "In all these cases the length of the contact area was close to sqrt(8KRP beta)/alpha";
    Ok(Check {
        id: "G-L",
        seed: SEED,
        title: "The claim l ~ sqrt(8KRP beta/alpha) for alpha, beta in [1e-1, 1e6] s, w = 10, 100, 1000 cm/s".into(),
        how: vec!["stickslip_rolling::claim_sweep (eqs 19, 20 scaled, FORMULAS.md D) for the rubber-like and polymer-like materials of that crate".into()],
        claims: vec![
            Claim {
                claim: "l is within 1 % of sqrt(8KRP beta/alpha) over the whole grid".into(),
                source: src("after eq 25", words),
                holds: universal,
                deciding: deciding.join("; "),
                expected: None,
            },
            Claim {
                claim: "the claim fails only where l is not small compared with 2 beta w (x1 = l/(2 beta w) > 0.05)".into(),
                source: src("after eq 25", words),
                holds: fails_only_large,
                deciding: deciding.join("; "),
                expected: Some(true),
            },
            Claim {
                claim: "d > 0: the contact shifts forward".into(),
                source: src("after eq 25", "It is hence seen that d > 0"),
                holds: all_forward,
                deciding: "min d over both sweeps in the table".into(),
                expected: Some(true),
            },
        ],
        tables: vec![tab],
        figures: vec![Figure {
            name: "seed001_GL".into(),
            caption: "l / sqrt(8KRP beta/alpha) against log10 x1, x1 = l/(2 beta w)".into(),
            x_label: "log10 x1".into(),
            y_label: "l / l_claim".into(),
            series,
        }],
        ..Check::default()
    })
}

/// G-S: the contact and stick/slip solution for documented cases, including the hard ones.
///
/// # Errors
/// From `stickslip-rolling`.
pub fn g_s() -> Result<Check, Error> {
    // Creep at which the stick zone vanishes, for the large-argument case, by bisection on
    // the regime (m -> 0 case).
    let sat = |alpha: f64, beta: f64, w: f64| -> Result<f64, Error> {
        let (mut lo, mut hi) = (0.0f64, 1.0f64);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            let s = solve(&GoryachevaParams::new(E, NU, R, P, RHO, mid, alpha, beta, w)?)?;
            if s.regime == Regime::FullSlip {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        Ok(lo)
    };
    let d_sat = sat(0.2, 0.1, 1.0)?;
    let cases: [(&str, f64, f64, f64, f64); 5] = [
        ("baseline", 0.2, 0.1, 1.0, 0.005),
        ("Bessel arguments ~ 4e4 (alpha 1e-5, beta 1e-6 s, w 0.1 m/s)", 1e-5, 1e-6, 0.1, 0.005),
        ("slow: alpha 1e6, beta 1e5 s, w 10 m/s", 1e6, 1e5, 10.0, 0.005),
        ("m -> 0: creep 0.999 999 of saturation", 0.2, 0.1, 1.0, d_sat * (1.0 - 1e-6)),
        ("m -> l: creep 1e-9", 0.2, 0.1, 1.0, 1e-9),
    ];
    let mut tab = Table {
        caption: "solution per case (SI): l, d, a, b, m, c, C2, Q, M1, M*; x1, y1 Bessel arguments"
            .into(),
        header: ["case", "regime", "l", "d", "a", "b", "m", "c", "C2", "Q", "M1", "M*", "x1", "y1"]
            .map(String::from)
            .to_vec(),
        rows: Vec::new(),
    };
    let mut rows = Vec::new();
    for (name, alpha, beta, w, delta) in cases {
        let s = solve(&GoryachevaParams::new(E, NU, R, P, RHO, delta, alpha, beta, w)?)?;
        tab.rows.push(vec![
            name.into(),
            format!("{:?}", s.regime),
            num(s.contact_length),
            sig(s.shift, 4),
            num(s.rear),
            num(s.front),
            num(s.stick_length),
            num(s.stick_start),
            num(s.c2),
            num(s.tangential_force),
            num(s.moment_m1),
            num(s.rolling_moment),
            num(s.info.bessel_args[0]),
            num(s.info.bessel_args[2]),
        ]);
        rows.push(Row::closed(
            format!("{name}: a + b"),
            "l",
            s.contact_length,
            s.rear + s.front,
            1e-12,
        ));
        rows.push(Row::closed(
            format!("{name}: M1 + Q R"),
            "M*",
            s.rolling_moment,
            s.moment_m1 + s.tangential_force * R,
            1e-12,
        ));
        rows.push(Row::value(
            format!("{name}: |Q|/(rho P) (<= 1)"),
            s.tangential_force.abs() / (RHO * P),
        ));
    }
    rows.push(Row::value("saturation creep of the baseline (full slip beyond)", d_sat));
    Ok(Check {
        id: "G-S",
        seed: SEED,
        title: "Contact and stick/slip solution: l, d, a, b, m, c, C2, Q, M1, M*".into(),
        how: vec!["stickslip_rolling::solve (eqs 19, 20, 24, 25, 27, 28, scaled; FORMULAS.md D), rubber-like E = 5 MPa, nu = 0.49, R = 5 cm, P = 1 kN/m, rho = 0.8".into()],
        rows,
        tables: vec![tab],
        ..Check::default()
    })
}
