//! Numbers of the chapter "Errata of the seeds": each published value beside ours, with the
//! check that decided it, and the full divergence list of the verification crate.
//!
//! The published values are not typed here: they live, each with its source (seed, place,
//! the printed words), in `stickslip_verification::published`, and the seeds' formulas as
//! printed in `stickslip_verification::as_published`. This page reads both, computes our
//! side with the physics crates, and lists every row that the verification checks record
//! as a divergence ([`stickslip_verification::all_divergences`]).

use crate::fmt::{num, num_or_zero, pct, resid, Table};
use crate::graded::table1;
use crate::mindlin::{example1, example1_inputs};
use crate::{Context, Error};
use std::f64::consts::{FRAC_PI_2, PI};
use stickslip_graded::{
    Accuracy, GradedMaterial, RigidCylinder, StressField, SurfaceDisplacement, SurfaceLoad,
};
use stickslip_halfspace::hertz::HertzSphere;
use stickslip_halfspace::material::composite_modulus;
use stickslip_halfspace::rectangle::shear_self_term;
use stickslip_halfspace::Material;
use stickslip_lattice::{ContactGrid, InfluenceModel};
use stickslip_quad::{gauss_kronrod, AdaptiveConfig, Tolerance};
use stickslip_rolling::contact_length;
use stickslip_special::{bessel_i0e, bessel_i1e, bessel_k0e, bessel_k1e, gamma};
use stickslip_traction::{closed::Deresiewicz, closed::Mindlin};
use stickslip_traction::{Load, TractionProblem};
use stickslip_verification::published::{seed000 as pub000, seed002 as pub002};
use stickslip_verification::{as_published, Published};

const PAGE: &str = "errata.md";

/// A published value as printed, with its place: `<as printed> (<table or example>)`.
fn printed(p: &Published) -> String {
    format!("{} ({})", p.text, p.source.place)
}

/// The page.
///
/// # Errors
/// A failed library call.
pub fn page() -> Result<String, Error> {
    let mut out = String::new();
    seed000(&mut out)?;
    seed001(&mut out)?;
    seed002(&mut out)?;
    divergences(&mut out)?;
    Ok(out)
}

fn cfg(rel: f64) -> Result<AdaptiveConfig, Error> {
    Ok(AdaptiveConfig::new(Tolerance::new(0.0, rel).ctx(PAGE, "tolerance")?))
}

fn seed000(out: &mut String) -> Result<(), Error> {
    let (nu, k, r, a, e0) = table1();
    let m = GradedMaterial::new(e0, k, nu).ctx(PAGE, "material")?;
    let b = m.beta();
    let c = cfg(1e-14)?;
    let iq = gauss_kronrod(|t| t.cos().powf(k + 1.0) * (b * t).cos(), 0.0, FRAC_PI_2, &c)
        .ctx(PAGE, "I_k")?;
    let jq = gauss_kronrod(|t| t.cos().powf(k) * t.sin() * (b * t).sin(), 0.0, FRAC_PI_2, &c)
        .ctx(PAGE, "J_k")?;
    let cyl = RigidCylinder::from_half_width(&m, r, a).ctx(PAGE, "cylinder")?;
    let h = cyl.indentation().ctx(PAGE, "h")?;
    let disp =
        SurfaceDisplacement::new(&m, cyl.surface_load(0.0).ctx(PAGE, "load")?, Accuracy::default())
            .ctx(PAGE, "displacement")?;
    let uy0 = disp.parts(0.0).ctx(PAGE, "u_y(0)")?.uy_from_p;
    let missing = gamma(0.5 * (3.0 + k - b));

    // Equilibrium at depth with the corrected exponent (3+k)/2.
    let unit = RigidCylinder::from_half_width(&m, 1.0, 1.0).ctx(PAGE, "cylinder")?;
    let load = SurfaceLoad::cylinder(1.0, unit.p0() / unit.load(), k, 0.0).ctx(PAGE, "load")?;
    let field = StressField::new(&m, load, Accuracy::default()).ctx(PAGE, "field")?;
    let syy = gauss_kronrod(
        |x| field.stress(x, 2.0).map_or(f64::NAN, |s| s.yy),
        f64::NEG_INFINITY,
        f64::INFINITY,
        &cfg(1e-10)?,
    )
    .ctx(PAGE, "∫σ_yy")?;

    // Eq 21: derivative of the angle factor by central differences.
    let (y, xs) = (0.5, 0.3);
    let f = |s: f64| (b * ((xs - s) / y).atan()).cos();
    let hstep = 1e-5;
    let fd = (f(hstep) - f(-hstep)) / (2.0 * hstep);
    let th = (xs / y).atan();
    let ours = b * y * (b * th).sin() / (y * y + xs * xs);
    let seeds = b * y * (b * th).sin() / (y * y - xs * xs);

    // Eqs 28–31: the slope of the pressure at the edge.
    let slope = |eps: f64| {
        let t: f64 = 1.0 - eps;
        (1.0 + k) * t * (1.0 - t * t).powf(0.5 * (k - 1.0))
    };

    // Eq 32 and its omitted part at x = -a.
    let disp_mu =
        SurfaceDisplacement::new(&m, cyl.surface_load(1.0).ctx(PAGE, "load")?, Accuracy::default())
            .ctx(PAGE, "displacement")?;
    let parts = disp_mu.parts(-a).ctx(PAGE, "u_x")?;
    let e32 = cyl.slip_displacement_eq32(-a, 1.0).ctx(PAGE, "eq 32")?;

    // Eqs 10–11: the argument and the ratio.
    let fr = 0.3_f64;
    let (re, im) = (-2.0 * fr, 2.0 * fr * fr);
    // (re + i im)/(1 - i f) = (re + i im)(1 + i f)/(1 + f^2).
    let den = 1.0 + fr * fr;
    let ratio_re_exact = (re - im * fr) / den;
    let ratio_im = (im + re * fr) / den;

    let mut t = Table::new(&["item (seed 000)", "published", "ours", "the check that decided it"]);
    t.row(vec![
        "Table 1, I_k (eq 12)".into(),
        printed(&pub000::I_K),
        num(m.i_k()),
        format!(
            "quadrature of ∫cos^(k+1)θ cos βθ dθ = {} (rel. diff {}); the published value is eq 12 with every Γ(·) set to 1: π/(2^(k+2)(k+2)) = {}",
            num(iq.value),
            resid(m.i_k() / iq.value - 1.0, 1.0),
            num(as_published::i_k_gamma_one(k))
        ),
    ]);
    t.row(vec![
        "Table 1, J_k (eq 14)".into(),
        printed(&pub000::J_K),
        num(m.j_k()),
        format!(
            "quadrature = {} (rel. diff {}); the published value is eq 14, J_k = βI_k/(1+k), on the Γ ≡ 1 value of I_k: {}",
            num(jq.value),
            resid(m.j_k() / jq.value - 1.0, 1.0),
            num(as_published::j_k_gamma_one(k, b))
        ),
    ]);
    t.row(vec![
        "Table 1, h (eq 16, correct)".into(),
        printed(&pub000::H),
        num(h),
        format!(
            "full integration u_y(0) = {} (rel. diff {}); the table rounds it",
            num(uy0),
            resid(uy0 / h - 1.0, 1.0)
        ),
    ]);
    t.row(vec![
        "Eq 15: factor Γ((3+k−β)/2) missing".into(),
        format!(
            "P = {} kgf/m for a = {} m",
            num(as_published::load_eq15_printed(nu, k, b, e0, r, a, false)),
            pub000::A.text
        ),
        format!("P = {} kgf/m", num(cyl.load())),
        format!(
            "the missing factor is {}; with it the pressure meets u_y = h − x²/2R to the digits on the graded page, and k → 0 gives 2D Hertz",
            num(missing)
        ),
    ]);
    t.row(vec![
        "Eq 17: exponent (5+k)/2".into(),
        "(5+k)/2".into(),
        "(3+k)/2".into(),
        format!(
            "∫σ_yy dx at depth 2a under unit load = {} (must be −1); (5+k)/2 would make σ ~ length⁻³ for a line load",
            num(syy.value)
        ),
    ]);
    t.row(vec![
        "Eqs 21/23/25: derivative denominator".into(),
        format!("y² − (x−s)²: {}", num(seeds)),
        format!("y² + (x−s)²: {}", num(ours)),
        format!("central difference of cos(β arctan((x−s)/y)) at x−s = 0.3, y = 0.5: {}", num(fd)),
    ]);
    t.row(vec![
        "Eqs 28–31: by-parts evaluation".into(),
        "finite boundary terms".into(),
        "invalid".into(),
        format!(
            "a·p′/p0 at the edge grows without bound: {} at 1e-4 a inside, {} at 1e-8 a inside",
            num(slope(1e-4)),
            num(slope(1e-8))
        ),
    ]);
    t.row(vec![
        "Eq 32 (correct for q = μp)".into(),
        "omits the p-induced part".into(),
        format!("u_x(−a): eq 32 {} m, omitted part {} m", num(e32), num(parts.ux_from_p)),
        format!(
            "full integration of the q-part = {} (rel. diff {}); the omitted part is {} of eq 32",
            num(parts.ux_from_q),
            resid(parts.ux_from_q / e32 - 1.0, 1.0),
            pct(parts.ux_from_p / e32)
        ),
    ]);
    t.row(vec![
        "Eqs 10–11: arg(−f + if²) and the sign".into(),
        format!("arctan(−f) = {}", num((-fr).atan())),
        format!("π − arctan f = {}", num(PI - fr.atan())),
        format!(
            "f = 0.3: (−2f + 2if²)/(1 − if) = {} + {}i, i.e. −2f: the result −(2f/π)∫… has the opposite sign of eq 11",
            num(ratio_re_exact),
            num_or_zero(ratio_im, 1.0)
        ),
    ]);
    out.push_str("#### Seed 000 (graded roller, after Giannakopoulos & Pallot 2000)\n\n");
    out.push_str(&t.render());
    Ok(())
}

fn seed001(out: &mut String) -> Result<(), Error> {
    let n = 601;
    let worst = (0..n)
        .map(|i| {
            let x = 10f64.powf(-6.0 + 12.0 * i as f64 / (n - 1) as f64);
            (x * (bessel_i0e(x) * bessel_k1e(x) + bessel_i1e(x) * bessel_k0e(x)) - 1.0).abs()
        })
        .fold(0.0, f64::max);
    // Fast regime of eq 19: alpha = 1e3 s, beta = 1e2 s, w = 0.1 m/s, l_H = 1 cm.
    let (alpha, beta) = (1.0e3, 1.0e2);
    let cl = contact_length(alpha, beta, 0.1, 0.01).ctx(PAGE, "contact length")?;
    let res = crate::rolling::resultants()?;
    let worst_res = res.rel.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let mut t = Table::new(&[
        "item (seed 001, Goryacheva 1973)",
        "printed",
        "corrected",
        "the check that decided it",
    ]);
    t.row(vec![
        "text after eq 25: contact length".into(),
        "√(8KRPβ)/α".into(),
        "√(8KRPβ/α)".into(),
        format!(
            "eq 19 solved at x1 = {}: l/l_H = {}, √(β/α) = {} (the printed form is not even a length)",
            num(cl.x1),
            num(cl.ratio),
            num((beta / alpha).sqrt())
        ),
    ]);
    t.row(vec![
        "elastic limit (eqs 17–24 at α = β)".into(),
        "—".into(),
        "Carter".into(),
        format!(
            "the Wronskian x[I0K1 + I1K0] − 1 is {} on [1e-6, 1e6]; see the elastic-limit table of the rolling chapter",
            resid(worst, 1.0)
        ),
    ]);
    t.row(vec![
        "OCR: (4) upper limit, (7) exponent, (13) upper limit, (16) lower limit".into(),
        "a, 1/a, ∞, 1".into(),
        "b, 1/2, x, b".into(),
        format!(
            "with the corrected forms the computed stresses integrate to P, Q (eq 27) and M1 (eq 28), rel. diff {} (rolling chapter)",
            resid(worst_res, 1.0)
        ),
    ]);
    t.row(vec![
        "OCR: first M1, elastic-limit shear".into(),
        "(l²/2)(αw − d); p/(πKR)".into(),
        "l²(αw − d)/(8KR); ρ/(πKR)".into(),
        "eq 28 reproduced by ∫xσ_y dx above; the shear by Carter's limit".into(),
    ]);
    out.push_str("#### Seed 001 (Goryacheva 1973)\n\n");
    out.push_str(&t.render());
    Ok(())
}

fn seed002(out: &mut String) -> Result<(), Error> {
    let (s, a, _, m) = example1()?;
    let (_, r, p, t_load, f) = example1_inputs()?;
    let nu = s.poisson_ratio();
    let per_body = m.compliance_per_body(&s);
    let grid = ContactGrid::hertz_circle(a, p, 10).ctx(PAGE, "grid")?;
    let lp = TractionProblem::new(&grid, [s, s], f, Load::Force { magnitude: t_load, angle: 0.0 })
        .ctx(PAGE, "problem")?
        .with_model(InfluenceModel::PointLoad)
        .solve()
        .ctx(PAGE, "LP")?;
    let lp_body = lp.rigid_per_body[0];
    let (pub_mindlin, pub_lp) = (pub002::EX1_DELTA_MINDLIN, pub002::EX1_DELTA_LP);

    // Example 2: the same steel sphere on the "rubber" of FORMULAS.md E.
    let rub = stickslip_verification::seed002::rubber().ctx(PAGE, "rubber")?;
    let (p2, t2, f2) = (pub002::EX2_P.value, pub002::EX2_T.value, pub002::EX2_F.value);
    let h2 = HertzSphere::new(p2, r, composite_modulus(&s, &rub)).ctx(PAGE, "Hertz")?;
    let m2 = Mindlin::new(h2.contact_radius(), p2, f2, t2).ctx(PAGE, "Mindlin")?;
    let (d_r, d_s) = (m2.compliance_per_body(&rub), m2.compliance_per_body(&s));
    let (pub_r, pub_s) = (pub002::EX2_DELTA_RUBBER, pub002::EX2_DELTA_STEEL);

    // Energy per cycle at a = P = f = G = 1: the sign in the bracket.
    let tt = 0.1_f64;
    let body = Material::new(2.6, 0.3).ctx(PAGE, "body")?;
    let w = Deresiewicz::new(1.0, 1.0, 1.0, tt).ctx(PAGE, "Deresiewicz")?.energy_per_cycle(&body);
    let minus = as_published::energy_eq35_printed(
        body.poisson_ratio(),
        body.shear_modulus(),
        1.0,
        1.0,
        1.0,
        tt,
    );
    let at_gross = Mindlin::new(a, p, f, f * p).ctx(PAGE, "Mindlin at fP")?.compliance_per_body(&s);
    let g = s.shear_modulus();
    let h = 1.0;
    let akk = shear_self_term(&s.compliance(), 0.5 * h, 0.5 * h);

    let mut t = Table::new(&[
        "item (seed 002, handbook chapter 3)",
        "published",
        "ours",
        "the check that decided it",
    ]);
    t.row(vec![
        "Example 1: Mindlin δ".into(),
        printed(&pub_mindlin),
        format!("{} per body ({} for both)", num(per_body), num(m.compliance_relative(&s, &s))),
        format!(
            "Cerruti quadrature of the Mindlin traction (Mindlin chapter): the published value is per body, with E = {} psi, ν = {} (FORMULAS.md E)",
            crate::fmt::sig(s.youngs_modulus(), 4),
            num(nu)
        ),
    ]);
    t.row(vec![
        format!("Example 1: LP δ ({} elements)", pub002::EX1_N.text),
        format!("{}, \"{} %\" below Mindlin", printed(&pub_lp), pub002::EX1_DEVIATION.text),
        format!(
            "{} ({}, the seed's point-load coefficients)",
            num(lp_body),
            pct(lp_body / per_body - 1.0)
        ),
        format!(
            "published LP / published Mindlin − 1 = {}",
            pct(pub_lp.value / pub_mindlin.value - 1.0)
        ),
    ]);
    t.row(vec![
        "Example 2: the quoted movements".into(),
        format!("rubber {}, steel {}", printed(&pub_r), printed(&pub_s)),
        format!("Mindlin per body: rubber {}, steel {}", num(d_r), num(d_s)),
        format!(
            "with E_rubber = {} psi, ν = {} the quoted values are {} and {} from Mindlin, i.e. LP results (ratio rubber/steel {})",
            crate::fmt::sig(rub.youngs_modulus(), 4),
            num(rub.poisson_ratio()),
            pct(pub_r.value / d_r - 1.0),
            pct(pub_s.value / d_s - 1.0),
            num(d_r / d_s)
        ),
    ]);
    t.row(vec![
        "Compliance 'for any load T > fP'".into(),
        "T > fP".into(),
        "T < fP".into(),
        format!(
            "at T = fP the per-body compliance is finite, 3(2−ν)fP/(16Ga) = {} in; `Mindlin::new` refuses T > fP (gross slip)",
            num(at_gross)
        ),
    ]);
    t.row(vec![
        "Eq 3.5 energy per cycle, sign in the last bracket".into(),
        format!("−: W = {}", num(minus)),
        format!("+: W = {}", num(w)),
        format!(
            "area of the hysteresis loop by quadrature equals the '+' form (Mindlin chapter); the '−' form is {} times too large at T*/fP = 0.1",
            num((minus / w).round())
        ),
    ]);
    t.row(vec![
        "Influence coefficient k = j".into(),
        "not given".into(),
        format!("A_kk = {} in/lbf for a 1 in steel square", num(akk)),
        format!(
            "closed form (2−ν)ln(1+√2)/(πGh) = {} (Influence chapter)",
            num((2.0 - nu) * (1.0 + 2f64.sqrt()).ln() / (PI * g * h))
        ),
    ]);
    out.push_str("#### Seed 002 (handbook chapter 3, traction and microslip)\n\n");
    out.push_str(&t.render());
    Ok(())
}

/// A table cell from free text: `|` escaped, line breaks as spaces.
fn cell(s: &str) -> String {
    s.replace('|', "\\|").replace('\n', " ")
}

/// Every divergence recorded by the verification crate's checks, with its cause.
fn divergences(out: &mut String) -> Result<(), Error> {
    let list = stickslip_verification::all_divergences().ctx(PAGE, "verification checks")?;
    let mut t = Table::new(&[
        "id",
        "quantity",
        "reference",
        "reference value",
        "computed",
        "computed / reference − 1",
        "cause",
    ]);
    for d in &list {
        let rel = d.computed / d.published - 1.0;
        let rel = if rel.is_finite() { pct(rel) } else { "n/a".to_owned() };
        let cause = d.cause.as_ref().map_or_else(|| "UNATTRIBUTED".to_owned(), |c| c.line());
        t.row(vec![
            d.id.to_owned(),
            cell(&d.quantity),
            cell(&d.reference),
            num(d.published),
            num(d.computed),
            rel,
            cell(&cause),
        ]);
    }
    out.push_str("#### Every divergence recorded by the verification crate\n\n");
    out.push_str(&format!(
        "The {} rows of the checks of `stickslip-verification` (one per VERIFICATION.md id) \
         that differ from their reference by more than its precision, each with its cause \
         (`stickslip_verification::all_divergences`). Two kinds: a published number (the \
         reference, with its seed and place) against our computed value; or a formula as \
         published, evaluated (computed), against the corrected quantity (the reference). The \
         same list, with the figures, is `docs/verification/divergences.md`.\n\n",
        list.len()
    ));
    out.push_str(&t.render());
    Ok(())
}
