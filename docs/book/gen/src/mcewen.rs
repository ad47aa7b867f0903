//! Numbers of the chapter "The Muskhelishvili potential, McEwen's field and 2D
//! Cattaneo–Mindlin" (FORMULAS.md C).

use crate::fmt::{num, resid, Table};
use crate::{check, tol, Context, Error};
use stickslip_halfspace::cattaneo2d::Cattaneo2d;
use stickslip_halfspace::flamant::line_load_stress;
use stickslip_halfspace::mcewen::{stress_mn, stress_potential};
use stickslip_halfspace::Stress2;
use stickslip_quad::{algebraic_endpoints, gauss_kronrod, AdaptiveConfig, Tolerance};

const PAGE: &str = "mcewen.md";

/// $\int_{-b}^{b} \sqrt{1-s^2/b^2}\;\sigma^{\rm Flamant}(x-s, y; p_0, q_0)\,ds$, by the
/// endpoint-weighted integrator (the square root is the Jacobi weight).
fn flamant_patch(b: f64, p0: f64, q0: f64, x: f64, y: f64) -> Result<Stress2, Error> {
    // Absolute part: some components vanish at some points.
    let scale = p0.abs().max(q0.abs());
    let cfg = AdaptiveConfig::new(Tolerance::new(1e-13 * scale, 1e-12).ctx(PAGE, "tolerance")?);
    let comp = |c: usize| {
        algebraic_endpoints(
            |s| {
                let st = line_load_stress(p0, q0, x - s, y);
                [st.xx, st.yy, st.xy][c] / b
            },
            -b,
            b,
            0.5,
            0.5,
            &cfg,
        )
        .ctx(PAGE, "Flamant quadrature")
    };
    Ok(Stress2 { xx: comp(0)?.value, yy: comp(1)?.value, xy: comp(2)?.value })
}

fn max_diff(a: &Stress2, b: &Stress2) -> f64 {
    (a.xx - b.xx).abs().max((a.yy - b.yy).abs()).max((a.xy - b.xy).abs())
}

/// The page.
///
/// # Errors
/// A failed library call or check.
pub fn page() -> Result<String, Error> {
    let mut out = String::new();
    let (a, p0, q0) = (1.0, 1.0, 0.3);
    let pts =
        [(0.0, 0.5), (0.5, 0.5), (-0.7, 0.3), (1.2, 0.4), (0.3, 1.5), (-2.0, 0.8), (0.0, 0.786)];
    let mut t = Table::new(&[
        "(x, y)/a",
        "σ_xx/p0 (potential)",
        "σ_yy/p0",
        "σ_xy/p0",
        "m,n form − potential",
        "Flamant quadrature − potential",
    ]);
    let mut worst: f64 = 0.0;
    for (x, y) in pts {
        let pot = stress_potential(a, p0, q0, x, y);
        let mn = stress_mn(a, p0, q0, x, y);
        let quad = flamant_patch(a, p0, q0, x, y)?;
        let (d1, d2) = (max_diff(&mn, &pot), max_diff(&quad, &pot));
        worst = worst.max(d1).max(d2);
        t.row(vec![
            format!("({}, {})", num(x), num(y)),
            num(pot.xx),
            num(pot.yy),
            num(pot.xy),
            resid(d1, p0),
            resid(d2, p0),
        ]);
    }
    check(PAGE, "McEwen three ways", worst, tol::CLOSED_VS_QUAD)?;
    out.push_str("#### McEwen's field three ways (a = 1, p0 = 1, q0 = 0.3)\n\n");
    out.push_str(
        "Largest absolute difference over the three components, in units of p0: McEwen's \
         real m, n form (`mcewen::stress_mn`) and the direct superposition of Flamant line \
         loads (`flamant::line_load_stress` integrated by `algebraic_endpoints` at 1e-12) \
         against Muskhelishvili's potential (`mcewen::stress_potential`).\n\n",
    );
    out.push_str(&t.render());

    let mut t = Table::new(&["x/a", "σ_xx(x, 0)/p0", "−p − 2q0x/a", "difference"]);
    let mut worst_s: f64 = 0.0;
    for x in [-1.0, -0.5, 0.0, 0.5, 0.9] {
        let s = stress_potential(a, p0, q0, x, 0.0);
        let want = -p0 * (1.0 - x * x).sqrt() - 2.0 * q0 * x / a;
        worst_s = worst_s.max((s.xx - want).abs());
        t.row(vec![num(x), num(s.xx), num(want), resid(s.xx - want, p0)]);
    }
    check(PAGE, "surface sigma_xx", worst_s, tol::IDENTITY)?;
    out.push_str("On the surface, $\\sigma_{xx} = -p(x) - 2q_0x/a$, with the largest tension $+2q_0$ at the trailing edge:\n\n");
    out.push_str(&t.render());

    // 2D Cattaneo–Mindlin.
    let (f, ratio) = (0.3, 0.5);
    let p_line = std::f64::consts::PI * a * p0 / 2.0;
    let q = ratio * f * p_line;
    let cm = Cattaneo2d::new(a, p0, f, q).ctx(PAGE, "Cattaneo2d")?;
    let c = cm.stick_half_width();
    let cfg = AdaptiveConfig::new(Tolerance::new(0.0, 1e-12).ctx(PAGE, "tolerance")?)
        .with_breakpoints(vec![-c, c])
        .ctx(PAGE, "breakpoints")?;
    let total = gauss_kronrod(|x| cm.traction(x), -a, a, &cfg).ctx(PAGE, "∫q")?;
    let dq = total.value / q - 1.0;
    check(PAGE, "Cattaneo resultant", dq.abs(), tol::CLOSED_VS_QUAD)?;
    let mut t = Table::new(&[
        "(x, y)/a",
        "σ (superposition of McEwen fields)",
        "Flamant quadrature of q",
        "max difference / p0",
    ]);
    let mut worst_c: f64 = 0.0;
    for (x, y) in [(0.0, 0.3), (-0.8, 0.2), (0.6, 1.0)] {
        let s = cm.stress(x, y).ctx(PAGE, "Cattaneo stress")?;
        let full = flamant_patch(a, p0, f * p0, x, y)?;
        let corr = flamant_patch(c, 0.0, -f * p0 * c / a, x, y)?;
        let quad = Stress2 { xx: full.xx + corr.xx, yy: full.yy + corr.yy, xy: full.xy + corr.xy };
        let d = max_diff(&s, &quad);
        worst_c = worst_c.max(d);
        t.row(vec![
            format!("({}, {})", num(x), num(y)),
            format!("({}, {}, {})", num(s.xx), num(s.yy), num(s.xy)),
            format!("({}, {}, {})", num(quad.xx), num(quad.yy), num(quad.xy)),
            resid(d, p0),
        ]);
    }
    check(PAGE, "Cattaneo stress", worst_c, tol::CLOSED_VS_QUAD)?;
    out.push_str("#### 2D Cattaneo–Mindlin (a = 1, p0 = 1, f = 0.3, Q = 0.5 fP)\n\n");
    out.push_str(&format!(
        "Stick half-width c/a = {} (√(1 − Q/fP) = {}); the traction integrates to Q = {} \
         (gauss_kronrod: {}, rel. diff {}, {} evals). Subsurface stress \
         (σ_xx, σ_yy, σ_xy)/p0 from `Cattaneo2d::stress` against Flamant quadrature of the \
         two traction patches:\n\n",
        num(c / a),
        num((1.0 - ratio).sqrt()),
        num(q),
        num(total.value),
        resid(dq, 1.0),
        total.evals
    ));
    out.push_str(&t.render());
    Ok(out)
}
