//! Numbers of the chapter "The modified LP and its entry rule" (seed 002 §3.3; FORMULAS.md E,
//! F).

use crate::fmt::{num, pct, resid, Table};
use crate::mindlin::example1;
use crate::{check, tol, Context, Error};
use stickslip_lattice::{ContactGrid, InfluenceModel};
use stickslip_traction::{ElementState, Load, Regime, TractionProblem};
use stickslip_verification::published::seed002 as pub002;

const PAGE: &str = "lp.md";

/// The page.
///
/// # Errors
/// A failed library call or check.
pub fn page() -> Result<String, Error> {
    let (s, a, _, m) = example1()?;
    let (_, _, p, t_load, f) = crate::mindlin::example1_inputs()?;
    let want = m.compliance_per_body(&s);
    let grid = ContactGrid::hertz_circle(a, p, 10).ctx(PAGE, "grid")?;
    let normal = grid.normal_force();
    let mut t = Table::new(&[
        "influence model",
        "elements",
        "δ_LP per body [in]",
        "Mindlin [in]",
        "LP / Mindlin − 1",
        "outer stick radius / a*",
        "pivots",
        "degenerate pivots",
        "entries refused by the rule",
        "ΣF/T − 1",
        "max F/(fP_k) − 1",
        "max min(slip, reserve)",
    ]);
    let mut exact_rel = f64::NAN;
    for model in [InfluenceModel::PointLoad, InfluenceModel::ExactRectangle] {
        let sol =
            TractionProblem::new(&grid, [s, s], f, Load::Force { magnitude: t_load, angle: 0.0 })
                .ctx(PAGE, "problem")?
                .with_model(model)
                .solve()
                .ctx(PAGE, "LP")?;
        if sol.regime != Regime::PartialSlip {
            return Err(Error::Compute {
                page: PAGE,
                what: "regime",
                message: format!("{:?}", sol.regime),
            });
        }
        let got = sol.rigid_per_body[0];
        let rel = got / want - 1.0;
        if model == InfluenceModel::ExactRectangle {
            exact_rel = rel.abs();
        }
        let total: f64 = sol.force.iter().sum();
        let over = (0..grid.len())
            .map(|k| sol.force[k] / (f * normal[k]) - 1.0)
            .fold(f64::NEG_INFINITY, f64::max);
        let compl = (0..grid.len())
            .map(|k| {
                let reserve = f * normal[k] - sol.force[k];
                (sol.slip[k].abs() / sol.rigid.abs()).min(reserve.abs() / (f * normal[k]))
            })
            .fold(0.0, f64::max);
        check(PAGE, "LP equilibrium", (total / t_load - 1.0).abs(), tol::LP_OPTIMALITY)?;
        check(PAGE, "LP friction cone", over, tol::LP_OPTIMALITY)?;
        check(PAGE, "LP complementarity", compl, tol::LP_OPTIMALITY)?;
        let r_stick = (0..grid.len())
            .filter(|&k| sol.state[k] == ElementState::Stick)
            .map(|k| grid.x[k].hypot(grid.y[k]))
            .fold(0.0, f64::max);
        t.row(vec![
            format!("{model:?}"),
            grid.len().to_string(),
            num(got),
            num(want),
            pct(rel),
            num(r_stick / m.stick_radius()),
            sol.info.iterations.to_string(),
            sol.info.degenerate_pivots.to_string(),
            sol.info.rejected_entries.to_string(),
            resid(total / t_load - 1.0, 1.0),
            resid(over.max(0.0), 1.0),
            resid(compl, 1.0),
        ]);
    }
    check(PAGE, "Example 1 vs Mindlin", exact_rel, tol::LP_EXAMPLE1)?;
    let mut out = String::new();
    out.push_str("#### Seed 002 Example 1 on its 80-element grid\n\n");
    out.push_str(&format!(
        "Hertz circle a = {} in, 10 elements across (h = {} in), {}, solved by \
         `TractionProblem` (the modified LP). The seed reports δ_LP = {} in, {} % below \
         Mindlin. Slip and reserve are relative to the rigid movement and to the element \
         capacity; their elementwise minimum is the complementarity residual.\n\n",
        num(a),
        num(2.0 * a / 10.0),
        crate::mindlin::example1_text()?,
        pub002::EX1_DELTA_LP.text,
        pub002::EX1_DEVIATION.text
    ));
    out.push_str(&t.render());
    Ok(out)
}
