//! Numbers of the chapter "Goryacheva's viscoelastic rolling" (FORMULAS.md D).

use crate::fmt::{err, num, resid, Table};
use crate::{check, tol, Context, Error};
use stickslip_quad::{gauss_kronrod, AdaptiveConfig, Tolerance};
use stickslip_rolling::{
    carter, claim_sweep, solve, CarterParams, GoryachevaParams, Response, StressConfig,
    SweepMaterial,
};
use stickslip_special::{
    bessel_i0, bessel_i0e, bessel_i1_over_i0, bessel_i1e, bessel_k0_over_k1, bessel_k0e, bessel_k1,
    bessel_k1e,
};

const PAGE: &str = "rolling.md";

/// The rubber-like material of the examples: $E$ \[Pa\], $\nu$, $R$ \[m\], $P$ \[N/m\],
/// friction $\rho$, creep $\delta$.
const RUBBER: (f64, f64, f64, f64, f64, f64) = (5.0e6, 0.49, 0.05, 1.0e3, 0.5, 2.0e-3);

/// The page.
///
/// # Errors
/// A failed library call or check.
pub fn page() -> Result<String, Error> {
    let mut out = String::new();
    wronskian(&mut out)?;
    elastic_limit(&mut out)?;
    viscoelastic(&mut out)?;
    claim(&mut out)?;
    Ok(out)
}

/// $x[I_0(x)K_1(x) + I_1(x)K_0(x)] = 1$ from the scaled functions, where the exponentials
/// cancel exactly.
fn wronskian(out: &mut String) -> Result<(), Error> {
    let n = 1201;
    let (mut worst, mut sum2) = (0.0f64, 0.0);
    for i in 0..n {
        let x = 10f64.powf(-6.0 + 12.0 * i as f64 / (n - 1) as f64);
        let w = x * (bessel_i0e(x) * bessel_k1e(x) + bessel_i1e(x) * bessel_k0e(x)) - 1.0;
        sum2 += w * w;
        worst = worst.max(w.abs());
    }
    check(PAGE, "Wronskian", worst, tol::IDENTITY)?;
    out.push_str("#### The Wronskian that gives the elastic limit\n\n");
    out.push_str(&format!(
        "$x[I_0(x)K_1(x) + I_1(x)K_0(x)] - 1$ on {n} log-spaced points of $[10^{{-6}}, 10^{{6}}]$, \
         from the exponentially scaled functions of `stickslip-special` ($e^{{x}}$ and \
         $e^{{-x}}$ cancel exactly): max {}, RMS {}.\n\n",
        resid(worst, 1.0),
        resid((sum2 / n as f64).sqrt(), 1.0)
    ));
    let x = 1.0e4;
    out.push_str(&format!(
        "Why the scaled forms are needed: at x = 1e4, `bessel_i0` = {} and `bessel_k1` = {}, \
         while the ratios used by the solver are finite: I1/I0 = {}, K0/K1 = {}.\n\n",
        num(bessel_i0(x)),
        num(bessel_k1(x)),
        num(bessel_i1_over_i0(x)),
        num(bessel_k0_over_k1(x))
    ));
    Ok(())
}

/// Goryacheva at $\alpha = \beta(1+\varepsilon)$ against Carter.
fn elastic_limit(out: &mut String) -> Result<(), Error> {
    let (e, nu, r, p, rho, delta) = RUBBER;
    let (beta, w) = (1.0e-3, 1.0);
    let cp = CarterParams::new(e, nu, r, p, rho, delta).ctx(PAGE, "Carter params")?;
    let cs = carter(&cp);
    let a = cs.half_width;
    let mut t = Table::new(&[
        "α/β − 1",
        "l/(2a)",
        "d/a",
        "c (stick start) [m]",
        "Q [N/m]",
        "abs(Δc)/a",
        "Q/Q_Carter − 1",
    ]);
    let mut at_small = f64::NAN;
    for eps in [1e-2, 1e-4, 1e-6, 0.0] {
        let alpha = beta * (1.0 + eps);
        let gp = GoryachevaParams::new(e, nu, r, p, rho, delta, alpha, beta, w)
            .ctx(PAGE, "Goryacheva params")?;
        let s = solve(&gp).ctx(PAGE, "Goryacheva solve")?;
        let dc = (s.stick_start - cs.stick_start).abs() / a;
        let dq = s.tangential_force / cs.tangential_force - 1.0;
        let dl = (s.contact_length / (2.0 * a) - 1.0).abs();
        if eps == 1e-6 {
            at_small = dc.max(dq.abs()).max(dl);
        }
        let label = if s.response == Response::Elastic {
            "0 (solved as Carter)".to_owned()
        } else {
            num(eps)
        };
        t.row(vec![
            label,
            num(s.contact_length / (2.0 * a)),
            num(s.shift / a),
            num(s.stick_start),
            num(s.tangential_force),
            err(dc),
            err(dq),
        ]);
    }
    check(PAGE, "elastic limit", at_small, tol::ELASTIC_LIMIT)?;
    out.push_str("#### The elastic limit α → β against Carter\n\n");
    out.push_str(&format!(
        "Rubber-like rollers: E = {} Pa, ν = {}, R = {} m, P = {} N/m, ρ = {}, δ = {}; \
         β = {} s, w = {} m/s. Carter (closed form): a = {} m, c = −a + 2δR/ρ = {} m, \
         Q = {} N/m.\n\n",
        num(e),
        num(nu),
        num(r),
        num(p),
        num(rho),
        num(delta),
        num(beta),
        num(w),
        num(a),
        num(cs.stick_start),
        num(cs.tangential_force)
    ));
    out.push_str(&t.render());
    Ok(())
}

/// The stresses of a viscoelastic case integrated over the contact: $\int\sigma_y$,
/// $\int\tau$, $\int x\sigma_y$, with the inner evaluation count.
pub(crate) struct Resultants {
    pub(crate) solution: stickslip_rolling::GoryachevaSolution,
    pub(crate) integrals: [f64; 3],
    pub(crate) rel: [f64; 3],
    pub(crate) inner_evals: usize,
}

/// $\alpha$, $\beta$ \[s\], $w$ \[m/s\] of the viscoelastic example.
const VISCO: (f64, f64, f64) = (2.0e-2, 5.0e-3, 1.0);

pub(crate) fn resultants() -> Result<Resultants, Error> {
    let (e, nu, r, p, rho, delta) = RUBBER;
    let (alpha, beta, w) = VISCO;
    let gp = GoryachevaParams::new(e, nu, r, p, rho, delta, alpha, beta, w).ctx(PAGE, "params")?;
    let s = solve(&gp).ctx(PAGE, "solve")?;
    let scfg = StressConfig {
        tol: Tolerance::new(0.0, 1e-12).ctx(PAGE, "tolerance")?,
        max_subdivisions: 400,
    };
    let cfg = AdaptiveConfig::new(Tolerance::new(0.0, 1e-10).ctx(PAGE, "tolerance")?)
        .with_breakpoints(vec![s.stick_start])
        .ctx(PAGE, "breakpoints")?;
    let (lo, hi) = (-s.rear, s.front);
    let mut bad = None;
    let mut inner = 0usize;
    let mut sig = |x: f64, which: usize| {
        let r = if which == 1 { s.shear(x, &scfg) } else { s.pressure(x, &scfg) };
        match r {
            Ok(v) => {
                inner += v.evals;
                v.value
            }
            Err(err) => {
                bad = Some(err.to_string());
                f64::NAN
            }
        }
    };
    let ip = gauss_kronrod(|x| sig(x, 0), lo, hi, &cfg);
    let iq = gauss_kronrod(|x| sig(x, 1), lo, hi, &cfg);
    let im = gauss_kronrod(|x| x * sig(x, 0), lo, hi, &cfg);
    if let Some(m) = bad {
        return Err(Error::Compute { page: PAGE, what: "stress", message: m });
    }
    let (ip, iq, im) = (ip.ctx(PAGE, "∫σ")?, iq.ctx(PAGE, "∫τ")?, im.ctx(PAGE, "∫xσ")?);
    let rel =
        [ip.value / p - 1.0, iq.value / s.tangential_force - 1.0, im.value / s.moment_m1 - 1.0];
    Ok(Resultants {
        solution: s,
        integrals: [ip.value, iq.value, im.value],
        rel,
        inner_evals: inner,
    })
}

/// A viscoelastic case: the resultants of the computed stresses against eqs 27–28, and a
/// hard case with Bessel arguments near $10^4$.
fn viscoelastic(out: &mut String) -> Result<(), Error> {
    let (e, nu, r, p, rho, delta) = RUBBER;
    let (alpha, beta, w) = VISCO;
    let res = resultants()?;
    let s = &res.solution;
    let d = res.rel;
    let inner = res.inner_evals;
    let (ip, iq, im) = (res.integrals[0], res.integrals[1], res.integrals[2]);
    let worst = d.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    check(PAGE, "rolling resultants", worst, tol::ROLLING_RESULTANTS)?;
    let mut t =
        Table::new(&["resultant", "integral of the computed stress", "equation", "rel. diff"]);
    t.row(vec!["∫σ_y dx = P".into(), num(ip), num(p), resid(d[0], 1.0)]);
    t.row(vec!["∫τ dx = Q (eq 27)".into(), num(iq), num(s.tangential_force), resid(d[1], 1.0)]);
    t.row(vec!["∫xσ_y dx = M1 (eq 28)".into(), num(im), num(s.moment_m1), resid(d[2], 1.0)]);
    out.push_str("#### A viscoelastic case: stresses against the resultants\n\n");
    out.push_str(&format!(
        "Same rollers, α = {} s, β = {} s, w = {} m/s: l = {} m (l/l_H = {}), d = {} m, \
         m = {} m, c = {} m, Bessel arguments x1, x2, y1, y2 = {}, {}, {}, {}; \
         eq 19 residual {}, eq 24 residual {} m; {} + {} Brent iterations. The pressure \
         (eq 12) and shear (eq 13) in their bounded-weight forms, integrated over the contact \
         (`gauss_kronrod` at 1e-10 of quadratures at 1e-12, {} inner evaluations):\n\n",
        num(alpha),
        num(beta),
        num(w),
        num(s.contact_length),
        num(s.contact_length / s.hertz_length),
        num(s.shift),
        num(s.stick_length),
        num(s.stick_start),
        num(s.info.bessel_args[0]),
        num(s.info.bessel_args[1]),
        num(s.info.bessel_args[2]),
        num(s.info.bessel_args[3]),
        resid(s.info.length_residual, 1.0),
        resid(s.info.stick_residual, s.contact_length),
        s.info.length_iterations,
        s.info.stick_iterations,
        inner
    ));
    out.push_str(&t.render());

    // Hard case of FORMULAS.md D: alpha = 1e-5 s, beta = 1e-6 s, w = 10 cm/s.
    let gp =
        GoryachevaParams::new(e, nu, r, p, rho, delta, 1.0e-5, 1.0e-6, 0.1).ctx(PAGE, "params")?;
    let s = solve(&gp).ctx(PAGE, "solve")?;
    let pmid = s.pressure(0.0, &StressConfig::default()).ctx(PAGE, "pressure")?;
    let slow = ((8.0 * gp.compliance() * r * p + (1.0e-5 - 1.0e-6_f64).powi(2) * 0.01).sqrt()
        - (1.0e-5 - 1.0e-6) * 0.1)
        / s.hertz_length;
    out.push_str(&format!(
        "Hard case (FORMULAS.md D: α = 1e-5 s, β = 1e-6 s, w = 0.1 m/s, where the unscaled \
         eq 19 overflows): x1 = {}, x2 = {}; l/l_H = {} (slow asymptote \
         √(8KRP + (α−β)²w²) − (α−β)w gives {}), d = {} m, m = {} m, Q = {} N/m, \
         M* = {} N, σ_y(0) = {} Pa (quadrature error estimate {} Pa).\n\n",
        num(s.info.bessel_args[0]),
        num(s.info.bessel_args[1]),
        num(s.contact_length / s.hertz_length),
        num(slow),
        num(s.shift),
        num(s.stick_length),
        num(s.tangential_force),
        num(s.rolling_moment),
        num(pmid.value),
        resid(pmid.error, pmid.value)
    ));
    Ok(())
}

/// The seed's claim $l \approx \sqrt{8KRP\beta/\alpha}$ over its grid.
fn claim(out: &mut String) -> Result<(), Error> {
    let mut t = Table::new(&[
        "material",
        "grid points",
        "claim within 1 %",
        "rows with x1 < 0.1",
        "worst abs(l/l_claim − 1)",
        "its x1",
        "min d/l",
    ]);
    for mat in [SweepMaterial::RUBBER_LIKE, SweepMaterial::POLYMER_LIKE] {
        let rows = claim_sweep(&mat, 2).ctx(PAGE, "claim sweep")?;
        let holds = rows.iter().filter(|r| r.claim_holds(0.01)).count();
        let small = rows.iter().filter(|r| r.x1 < 0.1).count();
        let worst = rows
            .iter()
            .max_by(|a, b| a.claim_error.abs().total_cmp(&b.claim_error.abs()))
            .ok_or(Error::Compute { page: PAGE, what: "claim sweep", message: "empty".into() })?;
        let min_d = rows.iter().map(|r| r.shift / r.length).fold(f64::INFINITY, f64::min);
        t.row(vec![
            mat.name.to_owned(),
            rows.len().to_string(),
            holds.to_string(),
            small.to_string(),
            num(worst.claim_error.abs()),
            num(worst.x1),
            num(min_d),
        ]);
    }
    out.push_str("#### The seed's claim l ≈ √(8KRPβ/α)\n\n");
    out.push_str(
        "Eqs 19–20 solved on the seed's grid (α > β from 0.1 s to 1e6 s, two points per \
         decade, w = 0.1, 1, 10 m/s; `rolling::claim_sweep`):\n\n",
    );
    out.push_str(&t.render());
    Ok(())
}
