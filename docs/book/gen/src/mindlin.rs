//! Numbers of the chapter "Mindlin, Cattaneo, Mindlin–Deresiewicz and Lubkin"
//! (FORMULAS.md E, G).

use crate::fmt::{err, num, pct, resid, Table};
use crate::{check, tol, Context, Error};
use std::f64::consts::PI;
use stickslip_halfspace::hertz::HertzSphere;
use stickslip_halfspace::material::composite_modulus;
use stickslip_halfspace::Material;
use stickslip_quad::{gauss_kronrod, AdaptiveConfig, Tolerance};
use stickslip_special::{ellipe, ellipk};
use stickslip_traction::{
    closed::cattaneo_lambda, closed::Deresiewicz, closed::LoadAxis, closed::Lubkin, closed::Mindlin,
};
use stickslip_verification::published::seed002 as pub002;

const PAGE: &str = "mindlin.md";

/// Seed 002 Example 1's inputs `(steel, R, P, T, f)` in in, lbf, psi, from their one home in
/// the verification crate: $R$, $P$, $T$, $f$ as published
/// (`stickslip_verification::published::seed002`), the steel of FORMULAS.md E
/// (`stickslip_verification::seed002::steel`; the seed's OCR lost $E$ and $\nu$).
///
/// # Errors
/// A failed library call (not for these constants).
pub fn example1_inputs() -> Result<(Material, f64, f64, f64, f64), Error> {
    let s = stickslip_verification::seed002::steel().ctx(PAGE, "steel")?;
    Ok((s, pub002::EX1_R.value, pub002::EX1_P.value, pub002::EX1_T.value, pub002::EX1_F.value))
}

/// The inputs of Example 1 for the text of the pages (published values as printed).
///
/// # Errors
/// As [`example1_inputs`].
pub fn example1_text() -> Result<String, Error> {
    let (s, ..) = example1_inputs()?;
    Ok(format!(
        "steel on steel, E = {} psi, ν = {}, R = {} in, P = {} lbf, T = {} lbf, f = {}",
        crate::fmt::sig(s.youngs_modulus(), 4),
        num(s.poisson_ratio()),
        pub002::EX1_R.text,
        pub002::EX1_P.text,
        pub002::EX1_T.text,
        pub002::EX1_F.text
    ))
}

fn cfg(abs: f64, rel: f64) -> Result<AdaptiveConfig, Error> {
    Ok(AdaptiveConfig::new(Tolerance::new(abs, rel).ctx(PAGE, "tolerance")?))
}

/// Example 1 contact: (steel, a, p0, Mindlin).
///
/// # Errors
/// A failed library call.
pub fn example1() -> Result<(Material, f64, f64, Mindlin), Error> {
    let (s, r, p, t, f) = example1_inputs()?;
    let h = HertzSphere::new(p, r, composite_modulus(&s, &s)).ctx(PAGE, "Hertz")?;
    let m = Mindlin::new(h.contact_radius(), p, f, t).ctx(PAGE, "Mindlin")?;
    Ok((s, h.contact_radius(), h.max_pressure(), m))
}

/// The page.
///
/// # Errors
/// A failed library call or check.
pub fn page() -> Result<String, Error> {
    let mut out = String::new();
    mindlin(&mut out)?;
    cattaneo(&mut out)?;
    deresiewicz(&mut out)?;
    lubkin(&mut out)?;
    Ok(out)
}

/// Tangential displacement $u_x$ of one body at a surface point $(x_0, y_0)$ of the stick
/// zone, by 2D quadrature of Cerruti's kernel over the Mindlin traction, in polar
/// coordinates about the field point (the $1/r$ singularity cancels against $r\,dr$):
/// $u_x = \frac{1}{2\pi G}\int_0^{2\pi}[(1-\nu) + \nu\cos^2\varphi]\int_0^{R(\varphi)} q\,dr\,d\varphi$.
fn cerruti_ux(m: &Mindlin, body: &Material, x0: f64, y0: f64) -> Result<(f64, usize), Error> {
    let (a, astar) = (m.radius(), m.stick_radius());
    let nu = body.poisson_ratio();
    let g = body.shear_modulus();
    let qscale = m.traction(0.0).abs().max(m.traction(0.5 * (a + astar)));
    let inner_cfg = cfg(1e-14 * qscale * a, 1e-12)?;
    let outer_cfg = cfg(0.0, 1e-11)?;
    let mut evals = 0usize;
    let mut failed = None;
    let outer = gauss_kronrod(
        |phi| {
            let (c, s) = (phi.cos(), phi.sin());
            let pe = x0 * c + y0 * s;
            let p2 = x0 * x0 + y0 * y0;
            let exit = |rad: f64| -pe + (pe * pe - p2 + rad * rad).sqrt();
            let r_out = exit(a);
            let mut bp = Vec::new();
            if p2 < astar * astar {
                bp.push(exit(astar));
            }
            let icfg = match inner_cfg.clone().with_breakpoints(bp) {
                Ok(c) => c,
                Err(e) => {
                    failed = Some(e.to_string());
                    return f64::NAN;
                }
            };
            let inner = gauss_kronrod(
                |r| {
                    let (x, y) = (x0 + r * c, y0 + r * s);
                    m.traction(x.hypot(y))
                },
                0.0,
                r_out,
                &icfg,
            );
            match inner {
                Ok(v) => {
                    evals += v.evals;
                    ((1.0 - nu) + nu * c * c) * v.value
                }
                Err(e) => {
                    failed = Some(e.to_string());
                    f64::NAN
                }
            }
        },
        0.0,
        2.0 * PI,
        &outer_cfg,
    );
    if let Some(msg) = failed {
        return Err(Error::Compute { page: PAGE, what: "Cerruti inner quadrature", message: msg });
    }
    let v = outer.ctx(PAGE, "Cerruti outer quadrature")?;
    Ok((v.value / (2.0 * PI * g), evals))
}

fn mindlin(out: &mut String) -> Result<(), Error> {
    let (s, a, p0, m) = example1()?;
    let per_body = m.compliance_per_body(&s);
    let rel = m.compliance_relative(&s, &s);
    out.push_str("#### Seed 002 Example 1 by the closed forms\n\n");
    let mut t = Table::new(&["quantity", "value"]);
    t.row(vec!["contact radius a [in]".into(), num(a)]);
    t.row(vec!["stick radius a* [in]".into(), num(m.stick_radius())]);
    t.row(vec!["peak pressure p0 [psi]".into(), num(p0)]);
    t.row(vec!["Mindlin δ, one body [in]".into(), num(per_body)]);
    t.row(vec!["Mindlin δ, relative (two bodies) [in]".into(), num(rel)]);
    out.push_str(&format!("Seed 002 Example 1, {}:\n\n", example1_text()?));
    out.push_str(&t.render());

    let astar = m.stick_radius();
    let mut t = Table::new(&[
        "field point / a*",
        "u_x by Cerruti quadrature [in]",
        "Mindlin δ per body [in]",
        "rel. diff",
        "inner evals",
    ]);
    let mut worst: f64 = 0.0;
    for (x, y) in [(0.0, 0.0), (0.5, 0.0), (0.3, 0.6), (0.0, 0.9)] {
        let (ux, ev) = cerruti_ux(&m, &s, x * astar, y * astar)?;
        let d = ux / per_body - 1.0;
        worst = worst.max(d.abs());
        t.row(vec![
            format!("({}, {})", num(x), num(y)),
            num(ux),
            num(per_body),
            resid(d, 1.0),
            ev.to_string(),
        ]);
    }
    check(PAGE, "Mindlin vs Cerruti quadrature", worst, tol::CERRUTI_2D)?;
    out.push_str(
        "The compliance is the displacement of the stick zone: Cerruti's surface kernel \
         integrated over the Mindlin traction (nested `gauss_kronrod`, polar coordinates about \
         the field point, breakpoint where the ray crosses the stick circle) is uniform over \
         the stick zone and equals the per-body formula:\n\n",
    );
    out.push_str(&t.render());
    Ok(())
}

fn cattaneo(out: &mut String) -> Result<(), Error> {
    let nu = 0.3;
    let circle = PI * (2.0 - nu) / 4.0;
    let mut t = Table::new(&[
        "e²",
        "Λ (load on major axis)",
        "Λ (load on minor axis)",
        "circle value π(2−ν)/4",
    ]);
    let mut worst: f64 = 0.0;
    for e2 in [1e-12, 0.75, 0.984375] {
        let (l1, l2) =
            (cattaneo_lambda(e2, nu, LoadAxis::Major), cattaneo_lambda(e2, nu, LoadAxis::Minor));
        if e2 < 1e-6 {
            worst = worst.max((l1 / circle - 1.0).abs()).max((l2 / circle - 1.0).abs());
        }
        t.row(vec![num(e2), num(l1), num(l2), num(circle)]);
    }
    check(PAGE, "Cattaneo circle limit", worst, 1e-11)?;
    out.push_str("#### Cattaneo's Λ and its circle limit (ν = 0.3)\n\n");
    out.push_str("e² = 0.75 is a/b = 2 (or 1/2), e² = 0.984375 is a/b = 8. At e → 0 both axes give Mindlin's (2 − ν)π/4:\n\n");
    out.push_str(&t.render());
    Ok(())
}

fn deresiewicz(out: &mut String) -> Result<(), Error> {
    // a = P = f = 1 and G = 1 (E = 2.6, nu = 0.3).
    let body = Material::new(2.6, 0.3).ctx(PAGE, "body")?;
    let c = cfg(0.0, 1e-13)?;
    let mut t = Table::new(&[
        "T*/fP",
        "loop area by quadrature",
        "W (eq 3.5, corrected)",
        "rel. diff",
        "evals",
    ]);
    let mut worst: f64 = 0.0;
    for ts in [0.1, 0.5, 0.9, 1.0] {
        let d = Deresiewicz::new(1.0, 1.0, 1.0, ts).ctx(PAGE, "Deresiewicz")?;
        let mut failed = None;
        let area = gauss_kronrod(
            |t| match (d.delta_unloading(t, &body), d.delta_reloading(t, &body)) {
                (Ok(u), Ok(r)) => u - r,
                (Err(e), _) | (_, Err(e)) => {
                    failed = Some(e.to_string());
                    f64::NAN
                }
            },
            -ts,
            ts,
            &c,
        );
        if let Some(m) = failed {
            return Err(Error::Compute { page: PAGE, what: "loop branch", message: m });
        }
        let area = area.ctx(PAGE, "loop area")?;
        let w = d.energy_per_cycle(&body);
        let r = area.value / w - 1.0;
        worst = worst.max(r.abs());
        // The direct form of W sums O(1) terms to a bracket of size 5t³/162: its few-ulp
        // rounding is amplified by kappa = 162/(5t³) (see tol::DERESIEWICZ_W). Rounding level
        // here is therefore about 4.5 kappa eps = ROUNDING * kappa / 100 (measured 2.4e-12 at
        // t = 0.1, where the level is 3.2e-11).
        let kappa = 162.0 / (5.0 * ts * ts * ts);
        let scale = kappa / 100.0;
        t.row(vec![num(ts), num(area.value), num(w), resid(r, scale), area.evals.to_string()]);
    }
    check(PAGE, "Deresiewicz loop area", worst, tol::DERESIEWICZ_W)?;
    let small = Deresiewicz::new(1.0, 1.0, 1.0, 1e-3).ctx(PAGE, "Deresiewicz")?;
    let approx = (2.0 - 0.3) * 1e-9 / (36.0 * body.shear_modulus());
    out.push_str("#### Mindlin–Deresiewicz: energy per cycle against the loop area\n\n");
    out.push_str(
        "a = P = f = G = 1, ν = 0.3; area between the unloading and reloading branches by \
         `gauss_kronrod` at 1e-13. The direct form of W adds terms of order 1 to a bracket of \
         size 5t³/162 (t = T*/fP), so its rounding of a few ulp is amplified by 162/(5t³); \
         differences below that amplified rounding level are shown as a bound:\n\n",
    );
    out.push_str(&t.render());
    out.push_str(&format!(
        "Small amplitude T*/fP = 1e-3: W = {}, the asymptote (2 − ν)T*³/(36GafP) = {} \
         (rel. diff {}).\n\n",
        num(small.energy_per_cycle(&body)),
        num(approx),
        err(small.energy_per_cycle(&body) / approx - 1.0)
    ));
    Ok(())
}

fn lubkin(out: &mut String) -> Result<(), Error> {
    let (a, p, mu) = (1.0, 1.0, 1.0);
    let body = Material::new(2.6, 0.3).ctx(PAGE, "body")?;
    let l0 = Lubkin::from_stick_radius(a, p, mu, 0.0).ctx(PAGE, "Lubkin")?;
    let m0 = l0.moment().ctx(PAGE, "M(0)")?;
    let closed = 3.0 * PI * mu * p * a / 16.0;
    let d0 = m0 / closed - 1.0;
    check(PAGE, "Lubkin M(0)", d0.abs(), tol::CLOSED_VS_QUAD)?;
    let q = gauss_kronrod(
        |u| {
            let m = 1.0 - u * u;
            u * u * (ellipk(m) - ellipe(m))
        },
        0.0,
        1.0,
        &cfg(0.0, 1e-13)?,
    )
    .ctx(PAGE, "∫u²(K−E)")?;
    let dq = q.value / (PI * PI / 64.0) - 1.0;
    check(PAGE, "π²/64 identity", dq.abs(), tol::CLOSED_VS_QUAD)?;
    out.push_str("#### Lubkin's torsion\n\n");
    let mut t = Table::new(&["check", "computed", "closed form", "rel. diff"]);
    t.row(vec![
        "M(c = 0) (quadrature in `Lubkin::moment`)".into(),
        num(m0),
        format!("3πμPa/16 = {}", num(closed)),
        resid(d0, 1.0),
    ]);
    t.row(vec![
        format!("∫₀¹u²(K − E)du ({} evals)", q.evals),
        num(q.value),
        format!("π²/64 = {}", num(PI * PI / 64.0)),
        resid(dq, 1.0),
    ]);
    for ca in [0.99, 0.9999] {
        let l = Lubkin::from_stick_radius(a, p, mu, ca * a).ctx(PAGE, "Lubkin")?;
        let m = l.moment().ctx(PAGE, "M(c)")?;
        let om = l.rotation_per_body(&body);
        let rs = 3.0 * m / (16.0 * body.shear_modulus() * a.powi(3));
        t.row(vec![
            format!("c/a = {}: rotation ω per body", num(ca)),
            num(om),
            format!("Reissner–Sagoci 3M/(16Ga³) = {}", num(rs)),
            err(om / rs - 1.0),
        ]);
    }
    let l = Lubkin::from_stick_radius(a, p, mu, 0.5 * a).ctx(PAGE, "Lubkin")?;
    let inside = l.traction(0.5 * a * (1.0 - 1e-9)).ctx(PAGE, "τ")?;
    let slip = mu * 3.0 * p / (2.0 * PI * a.powi(3)) * (a * a - 0.25 * a * a).sqrt();
    t.row(vec![
        "c/a = 0.5: τ just inside the stick disc".into(),
        num(inside),
        format!("μp(c) = {}", num(slip)),
        err(inside / slip - 1.0),
    ]);
    out.push_str("a = P = μ = G = 1, ν = 0.3:\n\n");
    out.push_str(&t.render());
    out.push_str(&format!(
        "The deviation from Reissner–Sagoci shrinks like 1 − c/a (the full-stick limit); τ \
         approaches μp(c) like the square root of the distance to r = c ({} at 1e-9 c).\n\n",
        pct(inside / slip - 1.0)
    ));
    Ok(())
}
