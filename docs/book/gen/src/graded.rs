//! Numbers of the chapter "The power-law graded half-plane" (FORMULAS.md A, B).

use crate::fmt::{err, num, num_or_zero, pct, resid, Table};
use crate::{check, tol, Context, Error};
use std::f64::consts::{FRAC_PI_2, PI};
use stickslip_graded::{Accuracy, GradedMaterial, RigidCylinder, StressField, SurfaceDisplacement};
use stickslip_halfspace::hertz::HertzLine;
use stickslip_quad::{gauss_kronrod, weakly_singular_weighted, AdaptiveConfig, Tolerance};
use stickslip_verification::published::seed000 as pub000;

const PAGE: &str = "graded.md";

/// The inputs of seed 000's Table 1, $(\nu, k, R, a, E_0)$ with $R$, $a$ in m and $E_0$ in
/// kgf/m$^{2.1}$, read from their one home, `stickslip_verification::published::seed000`.
#[must_use]
pub fn table1() -> (f64, f64, f64, f64, f64) {
    (pub000::NU.value, pub000::K.value, pub000::R.value, pub000::A.value, pub000::E0.value)
}

/// The same inputs as printed in the seed, for the text of the pages.
#[must_use]
pub fn table1_text() -> String {
    format!(
        "ν = {}, k = {}, R = {} m, a = {} m, E0 = {} kgf/m^2.1",
        pub000::NU.text,
        pub000::K.text,
        pub000::R.text,
        pub000::A.text,
        pub000::E0.text
    )
}

fn rel_cfg(rel: f64) -> Result<AdaptiveConfig, Error> {
    Ok(AdaptiveConfig::new(Tolerance::new(0.0, rel).ctx(PAGE, "tolerance")?))
}

/// The page.
///
/// # Errors
/// A failed library call or check.
pub fn page() -> Result<String, Error> {
    let mut out = String::new();
    constants(&mut out)?;
    spectral(&mut out)?;
    table1_section(&mut out)?;
    equilibrium(&mut out)?;
    small_k(&mut out)?;
    eq32(&mut out)?;
    Ok(out)
}

/// $\beta$, $I_k$, $J_k$: closed forms of the graded crate against quadrature of their
/// defining integrals.
fn constants(out: &mut String) -> Result<(), Error> {
    let cfg = rel_cfg(1e-14)?;
    let mut t = Table::new(&[
        "ν",
        "k",
        "β",
        "I_k (Γ form)",
        "I_k (quadrature)",
        "rel. diff",
        "J_k = βI_k/(1+k)",
        "J_k (quadrature)",
        "rel. diff",
        "evals",
    ]);
    let mut worst: f64 = 0.0;
    for (nu, k) in [(0.3, 0.1), (0.3, 0.5), (0.25, 0.9), (0.45, 0.01)] {
        let m = GradedMaterial::new(1.0, k, nu).ctx(PAGE, "material")?;
        let b = m.beta();
        let iq = gauss_kronrod(|t| t.cos().powf(k + 1.0) * (b * t).cos(), 0.0, FRAC_PI_2, &cfg)
            .ctx(PAGE, "I_k quadrature")?;
        let jq = gauss_kronrod(|t| t.cos().powf(k) * t.sin() * (b * t).sin(), 0.0, FRAC_PI_2, &cfg)
            .ctx(PAGE, "J_k quadrature")?;
        let ri = m.i_k() / iq.value - 1.0;
        let rj = m.j_k() / jq.value - 1.0;
        worst = worst.max(ri.abs()).max(rj.abs());
        t.row(vec![
            num(nu),
            num(k),
            num(b),
            num(m.i_k()),
            num(iq.value),
            resid(ri, 1.0),
            num(m.j_k()),
            num(jq.value),
            resid(rj, 1.0),
            (iq.evals + jq.evals).to_string(),
        ]);
    }
    check(PAGE, "I_k, J_k vs quadrature", worst, tol::CLOSED_VS_QUAD)?;
    out.push_str("#### β, I_k, J_k against quadrature of their definitions\n\n");
    out.push_str(
        "Closed forms from `stickslip_graded::GradedMaterial`; quadrature by \
         `stickslip_quad::gauss_kronrod` at 1e-14 relative.\n\n",
    );
    out.push_str(&t.render());
    out.push_str(&format!("Largest relative difference: {}.\n\n", resid(worst, 1.0)));
    Ok(())
}

/// The spectral relation of FORMULAS.md A4 by weakly singular quadrature.
fn spectral(out: &mut String) -> Result<(), Error> {
    // 1e-13: at 1e-14 the endpoint integrator of stickslip-quad does not converge (and the
    // estimate it attaches to the error is wrong; reported to the lead).
    let cfg = rel_cfg(1e-13)?;
    let xs = [0.0, 0.25, 0.5, 0.75, 0.95, 0.999];
    let mut t = Table::new(&["k", "points x", "max rel. residual", "evals"]);
    let mut worst_all: f64 = 0.0;
    for k in [0.1, 0.5, 0.9] {
        let g = 0.5 * (1.0 + k);
        let d0 = PI * (1.0 + k) / (2.0 * (k * FRAC_PI_2).cos());
        let (mut worst, mut evals) = (0.0f64, 0usize);
        for &x in &xs {
            let lhs = weakly_singular_weighted(|_| 1.0, -1.0, 1.0, x, k, g, g, &cfg)
                .ctx(PAGE, "spectral relation quadrature")?;
            let rhs = d0 * (1.0 - k * x * x);
            evals += lhs.evals;
            worst = worst.max((lhs.value / rhs - 1.0).abs());
        }
        worst_all = worst_all.max(worst);
        t.row(vec![num(k), xs.len().to_string(), resid(worst, 1.0), evals.to_string()]);
    }
    check(PAGE, "spectral relation", worst_all, tol::CLOSED_VS_QUAD)?;
    out.push_str("#### The spectral relation behind the pressure\n\n");
    out.push_str(
        "Residual of $\\int_{-1}^{1}(1-t^2)^{(1+k)/2}|x-t|^{-k}dt = \\frac{\\pi(1+k)}{2\\cos(k\\pi/2)}(1-kx^2)$, \
         left side by `stickslip_quad::weakly_singular_weighted` at 1e-13 relative, at \
         x = 0, 0.25, 0.5, 0.75, 0.95, 0.999.\n\n",
    );
    out.push_str(&t.render());
    Ok(())
}

/// Table 1 of seed 000 recomputed, and the contact condition by full integration.
fn table1_section(out: &mut String) -> Result<(), Error> {
    let (nu, k, r, a, e0) = table1();
    let m = GradedMaterial::new(e0, k, nu).ctx(PAGE, "material")?;
    let cyl = RigidCylinder::from_half_width(&m, r, a).ctx(PAGE, "cylinder")?;
    let h = cyl.indentation().ctx(PAGE, "h")?;
    let mut t = Table::new(&["quantity", "value"]);
    t.row(vec!["β".into(), num(m.beta())]);
    t.row(vec!["I_k".into(), num(m.i_k())]);
    t.row(vec!["J_k".into(), num(m.j_k())]);
    t.row(vec!["P implied by a (corrected eq 15) [kgf/m]".into(), num(cyl.load())]);
    t.row(vec!["p0 [kgf/m²]".into(), num(cyl.p0())]);
    t.row(vec!["Hertz-like estimate 2P/(πa) [kgf/m²]".into(), num(2.0 * cyl.load() / (PI * a))]);
    t.row(vec!["h = a²/(2Rk) (eq 16) [m]".into(), num(h)]);
    out.push_str("#### Table 1 of seed 000, recomputed\n\n");
    out.push_str(&format!(
        "{} (as published; `RigidCylinder::from_half_width`).\n\n",
        table1_text()
    ));
    out.push_str(&t.render());

    // Contact condition: u_y(x) = h - x^2/(2R) on the contact, by full integration.
    let disp =
        SurfaceDisplacement::new(&m, cyl.surface_load(0.0).ctx(PAGE, "load")?, Accuracy::default())
            .ctx(PAGE, "displacement plan")?;
    let mut t =
        Table::new(&["x [m]", "u_y by full integration [m]", "h − x²/(2R) [m]", "rel. diff"]);
    let mut worst: f64 = 0.0;
    for x in [0.0, 0.005, 0.01, 0.015, 0.0175] {
        let uy = disp.parts(x).ctx(PAGE, "u_y")?.uy_from_p;
        let want = h - x * x / (2.0 * r);
        let d = uy / want - 1.0;
        worst = worst.max(d.abs());
        t.row(vec![num(x), num(uy), num(want), resid(d, 1.0)]);
    }
    check(PAGE, "contact condition", worst, tol::FULL_INTEGRATION)?;
    out.push_str(
        "The contact condition $u_y(x) = h - x^2/(2R)$ with this pressure and this $h$, the \
         displacement by full integration of the A3 kernel (`SurfaceDisplacement`, default \
         accuracy):\n\n",
    );
    out.push_str(&t.render());
    Ok(())
}

/// $\int\sigma_{yy}dx = -P$ and $\int\sigma_{xy}dx = -Q$ at depth: the $1/(2I_k)$, $1/(2J_k)$
/// normalisation and the exponent $(3+k)/2$.
fn equilibrium(out: &mut String) -> Result<(), Error> {
    let cfg = rel_cfg(1e-10)?;
    let (a, p, mu, y) = (1.0, 1.0, 0.5, 2.0);
    let mut t = Table::new(&[
        "k",
        "∫σ_yy dx",
        "−P",
        "rel. diff",
        "∫σ_xy dx",
        "−μP",
        "rel. diff",
        "stress evals",
    ]);
    let mut worst: f64 = 0.0;
    for k in [0.1, 0.5] {
        let m = GradedMaterial::new(1.0, k, 0.3).ctx(PAGE, "material")?;
        let cyl = RigidCylinder::from_half_width(&m, 1.0, a).ctx(PAGE, "cylinder")?;
        let p0 = cyl.p0() * p / cyl.load();
        let load = stickslip_graded::SurfaceLoad::cylinder(a, p0, k, mu).ctx(PAGE, "load")?;
        let field = StressField::new(&m, load, Accuracy::default()).ctx(PAGE, "field")?;
        let mut bad = false;
        let mut comp = |c: usize| {
            gauss_kronrod(
                |x| match field.stress(x, y) {
                    Ok(s) => [s.yy, s.xy][c],
                    Err(_) => {
                        bad = true;
                        f64::NAN
                    }
                },
                f64::NEG_INFINITY,
                f64::INFINITY,
                &cfg,
            )
        };
        let syy = comp(0).ctx(PAGE, "∫σ_yy")?;
        let sxy = comp(1).ctx(PAGE, "∫σ_xy")?;
        let (dy, dx) = (syy.value / -p - 1.0, sxy.value / (-mu * p) - 1.0);
        worst = worst.max(dy.abs()).max(dx.abs());
        t.row(vec![
            num(k),
            num(syy.value),
            num(-p),
            resid(dy, 1.0),
            num(sxy.value),
            num(-mu * p),
            resid(dx, 1.0),
            (syy.evals + sxy.evals).to_string(),
        ]);
    }
    check(PAGE, "equilibrium at depth", worst, tol::FULL_INTEGRATION)?;
    out.push_str("#### Equilibrium at depth y = 2a\n\n");
    out.push_str(
        "Graded-cylinder pressure with P = 1, a = 1 and sliding friction q = 0.5 p; each \
         stress by full integration (A2, `StressField`), then integrated over the whole line \
         by `gauss_kronrod` (infinite range, 1e-10).\n\n",
    );
    out.push_str(&t.render());
    Ok(())
}

/// The homogeneous limit: half-width, and the approach relative to a datum.
fn small_k(out: &mut String) -> Result<(), Error> {
    let nu = 0.3;
    let e_star = 1.0 / (1.0 - nu * nu);
    let hertz = HertzLine::new(1.0, 1.0, e_star).ctx(PAGE, "Hertz line")?;
    let mut t =
        Table::new(&["k", "a (corrected eq 15)", "2D Hertz a", "rel. diff", "p0 a/P", "2/π"]);
    let mut last = f64::NAN;
    for k in [1e-2, 1e-4, 1e-6, 0.0] {
        let m = GradedMaterial::new(1.0, k, nu).ctx(PAGE, "material")?;
        let cyl = RigidCylinder::from_load(&m, 1.0, 1.0).ctx(PAGE, "cylinder")?;
        let d = cyl.half_width() / hertz.half_width() - 1.0;
        if k == 1e-6 {
            last = d.abs();
        }
        t.row(vec![
            num(k),
            num(cyl.half_width()),
            num(hertz.half_width()),
            err(d),
            num(cyl.p0() * cyl.half_width()),
            num(2.0 / PI),
        ]);
    }
    check(PAGE, "a at k = 1e-6 vs Hertz", last, tol::SMALL_K)?;
    out.push_str("#### The homogeneous limit k → 0\n\n");
    out.push_str("Half-width for P = R = E0 = 1, ν = 0.3 against 2D Hertz for a rigid cylinder (`HertzLine`):\n\n");
    out.push_str(&t.render());

    let (_, _, r, a, e0) = table1();
    let datum = 10.0 * a;
    let h0 = HertzLine::from_half_width(a, r, e0 / (1.0 - nu * nu)).ctx(PAGE, "Hertz")?;
    let want0 = h0.approach_relative(datum);
    let mut t = Table::new(&["k", "h = a²/(2Rk) [m]", "h − u_y(10a) [m]", "rel. diff to k = 0"]);
    let mut at_small = f64::NAN;
    for k in [0.1, 1e-2, 1e-4, 1e-6, 0.0] {
        let m = GradedMaterial::new(e0, k, nu).ctx(PAGE, "material")?;
        let cyl = RigidCylinder::from_half_width(&m, r, a).ctx(PAGE, "cylinder")?;
        let h = cyl.indentation().map_or_else(|_| "∞ (no absolute indentation)".to_owned(), num);
        let rel = cyl.relative_approach(datum).ctx(PAGE, "relative approach")?;
        let d = rel / want0 - 1.0;
        if k == 1e-6 {
            at_small = d.abs();
        }
        t.row(vec![num(k), h, num(rel), err(d)]);
    }
    check(PAGE, "relative approach k = 1e-6", at_small, tol::SMALL_K)?;
    out.push_str(&format!(
        "Table 1 geometry (a = {} m, R = {} m) held fixed while k → 0: the absolute \
         indentation h diverges, the approach relative to the surface point at 10a \
         (`RigidCylinder::relative_approach`) converges to the 2D Hertz value \
         (`HertzLine::approach_relative`).\n\n",
        pub000::A.text,
        pub000::R.text
    ));
    out.push_str(&t.render());

    // Independent check of the closed form of the relative approach at k = 0.1.
    let m = GradedMaterial::new(e0, 0.1, nu).ctx(PAGE, "material")?;
    let cyl = RigidCylinder::from_half_width(&m, r, a).ctx(PAGE, "cylinder")?;
    let disp =
        SurfaceDisplacement::new(&m, cyl.surface_load(0.0).ctx(PAGE, "load")?, Accuracy::default())
            .ctx(PAGE, "displacement")?;
    let by_int = cyl.indentation().ctx(PAGE, "h")? - disp.parts(datum).ctx(PAGE, "u_y")?.uy_from_p;
    let closed = cyl.relative_approach(datum).ctx(PAGE, "relative approach")?;
    let d = by_int / closed - 1.0;
    check(PAGE, "relative approach closed form vs integration", d.abs(), tol::FULL_INTEGRATION)?;
    out.push_str(&format!(
        "At k = 0.1 the closed form (hypergeometric) gives h − u_y(10a) = {} m; $h$ minus the \
         fully integrated $u_y(10a)$ gives {} m (rel. diff {}).\n\n",
        num(closed),
        num(by_int),
        resid(d, 1.0)
    ));
    Ok(())
}

/// Eq 32 against the full-integration $u_x$ of the friction traction, and the omitted part.
fn eq32(out: &mut String) -> Result<(), Error> {
    let (nu, k, r, a, e0) = table1();
    let m = GradedMaterial::new(e0, k, nu).ctx(PAGE, "material")?;
    let cyl = RigidCylinder::from_half_width(&m, r, a).ctx(PAGE, "cylinder")?;
    let mu = 1.0;
    let disp =
        SurfaceDisplacement::new(&m, cyl.surface_load(mu).ctx(PAGE, "load")?, Accuracy::default())
            .ctx(PAGE, "displacement")?;
    let mut t = Table::new(&[
        "x [m]",
        "eq 32 [m]",
        "u_x from q = μp, full integration [m]",
        "rel. diff",
        "u_x from p (omitted by eq 32) [m]",
        "omitted / eq 32",
    ]);
    let mut worst: f64 = 0.0;
    for x in [-a, -0.01, 0.0, 0.01, a] {
        let e32 = cyl.slip_displacement_eq32(x, mu).ctx(PAGE, "eq 32")?;
        let parts = disp.parts(x).ctx(PAGE, "u_x")?;
        let d = parts.ux_from_q / e32 - 1.0;
        worst = worst.max(d.abs());
        let ratio = if x == 0.0 { "≈ 0".to_owned() } else { pct(parts.ux_from_p / e32) };
        t.row(vec![
            num(x),
            num(e32),
            num(parts.ux_from_q),
            resid(d, 1.0),
            num_or_zero(parts.ux_from_p, e32),
            ratio,
        ]);
    }
    check(PAGE, "eq 32 vs full integration", worst, tol::FULL_INTEGRATION)?;
    out.push_str("#### Eq 32 (slip-zone tangential displacement), Table 1 data, μ = 1\n\n");
    out.push_str(&t.render());
    Ok(())
}
