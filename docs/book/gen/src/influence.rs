//! Numbers of the chapter "Influence coefficients of uniform rectangles" (FORMULAS.md F).

use crate::fmt::{num, pct, resid, Table};
use crate::{check, tol, Context, Error};
use std::f64::consts::PI;
use stickslip_halfspace::rectangle::{shear_self_term, shear_x_displacement, shear_x_ux, Rect};
use stickslip_halfspace::Material;
use stickslip_quad::{gauss_kronrod, AdaptiveConfig, Tolerance};

const PAGE: &str = "influence.md";

/// The page.
///
/// # Errors
/// A failed library call or check.
pub fn page() -> Result<String, Error> {
    let mut out = String::new();
    // One body with G = 1, nu = 0.3.
    let nu = 0.3;
    let body = Material::new(2.0 * (1.0 + nu), nu).ctx(PAGE, "body")?;
    let c = body.compliance();
    let g = body.shear_modulus();
    let h = 1.0;

    // Self term of a unit square.
    let exact = shear_self_term(&c, 0.5 * h, 0.5 * h);
    let closed = (2.0 - nu) * (1.0 + 2f64.sqrt()).ln() / (PI * g * h);
    let circle = (2.0 - nu) / (2.0 * PI.sqrt() * g * h);
    let d = exact / closed - 1.0;
    check(PAGE, "square self term", d.abs(), tol::IDENTITY)?;
    out.push_str("#### The self term A_kk (the seed's missing k = j formula)\n\n");
    let mut t = Table::new(&["quantity (G = 1, ν = 0.3, square of side 1)", "value"]);
    t.row(vec!["`rectangle::shear_self_term`".into(), num(exact)]);
    t.row(vec!["(2 − ν) ln(1 + √2)/(πGh)".into(), num(closed)]);
    t.row(vec!["rel. diff".into(), resid(d, 1.0)]);
    t.row(vec!["equal-area circle (2 − ν)/(2√π G h)".into(), num(circle)]);
    t.row(vec!["circle / exact − 1".into(), pct(circle / exact - 1.0)]);
    out.push_str(&t.render());

    // Element-to-point formula against 2D quadrature of Cerruti's kernel (points outside).
    let rect = Rect::new(-0.5, 0.5, -0.5, 0.5).ctx(PAGE, "rect")?;
    let cfg = AdaptiveConfig::new(Tolerance::new(0.0, 1e-12).ctx(PAGE, "tolerance")?);
    let mut t = Table::new(&[
        "field point",
        "u_x exact",
        "u_x quadrature",
        "rel. diff",
        "u_y exact",
        "u_y quadrature",
        "rel. diff",
    ]);
    let mut worst: f64 = 0.0;
    for (x, y) in [(1.5, 0.2), (0.9, 1.3), (-2.0, -1.0)] {
        let ex = shear_x_displacement(&c, &rect, x, y);
        let fast = shear_x_ux(&c, &rect, x, y);
        let quad = |comp: usize| {
            gauss_kronrod(
                |xi| {
                    let inner = gauss_kronrod(
                        |eta| {
                            let (dx, dy) = (x - xi, y - eta);
                            let r2 = dx * dx + dy * dy;
                            let r = r2.sqrt();
                            if comp == 0 {
                                (c.one_minus_nu / r + c.nu * dx * dx / (r2 * r)) / (2.0 * PI)
                            } else {
                                c.nu * dx * dy / (r2 * r) / (2.0 * PI)
                            }
                        },
                        -0.5,
                        0.5,
                        &cfg,
                    );
                    inner.map_or(f64::NAN, |e| e.value)
                },
                -0.5,
                0.5,
                &cfg,
            )
        };
        let qx = quad(0).ctx(PAGE, "u_x quadrature")?.value;
        let qy = quad(1).ctx(PAGE, "u_y quadrature")?.value;
        let (dx, dy) = (ex.x / qx - 1.0, ex.y / qy - 1.0);
        worst = worst.max(dx.abs()).max(dy.abs()).max((fast / ex.x - 1.0).abs());
        t.row(vec![
            format!("({}, {})", num(x), num(y)),
            num(ex.x),
            num(qx),
            resid(dx, 1.0),
            num(ex.y),
            num(qy),
            resid(dy, 1.0),
        ]);
    }
    check(PAGE, "rectangle vs quadrature", worst, tol::CLOSED_VS_QUAD)?;
    out.push_str("#### Element-to-point formula against quadrature\n\n");
    out.push_str(
        "Unit uniform shear along +x on the square [−0.5, 0.5]², displacement at outside \
         points (`rectangle::shear_x_displacement`; the fast path `shear_x_ux` agrees) against \
         nested `gauss_kronrod` of Cerruti's surface kernel at 1e-12:\n\n",
    );
    out.push_str(&t.render());

    // Point-load approximation of the nearest neighbours.
    let mut t = Table::new(&[
        "neighbour",
        "exact rectangle",
        "point load at the centre",
        "point / exact − 1",
    ]);
    for (dx, dy, name) in [(1.0, 0.0, "along the load (x)"), (0.0, 1.0, "across the load (y)")] {
        let ex = shear_x_ux(&c, &rect, dx, dy);
        let r2: f64 = dx * dx + dy * dy;
        let r = r2.sqrt();
        let pt = (c.one_minus_nu + c.nu * dx * dx / r2) / (2.0 * PI * r);
        t.row(vec![name.into(), num(ex), num(pt), pct(pt / ex - 1.0)]);
    }
    out.push_str("#### The seed's point-load approximation for the nearest neighbours\n\n");
    out.push_str(&t.render());
    Ok(out)
}
