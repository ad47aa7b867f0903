//! Stage 3, twist: Lubkin's torsion of a Hertz circle (a moment alone on a sphere). Grid
//! solutions of a moment, alone or with a force, are in [`super::grid`].

use stickslip_traction::closed::Lubkin;

use super::friction::TangentialOut;
use super::lattice::Lattice;
use super::normal::ContactSolution;
use super::outcome::{RigidOut, Zones};
use super::{solver_err, Ctx};
use crate::plan::recipe::ContactRecipe;
use stickslip_scene::SceneError;

/// Lubkin's torsion under the signed `moment`.
pub(crate) fn lubkin(
    lat: &mut Lattice,
    r: &ContactRecipe,
    n: &ContactSolution,
    moment: f64,
    cx: &mut Ctx<'_>,
) -> Result<TangentialOut, SceneError> {
    let m = Lubkin::from_moment(n.ax, n.load, r.friction, moment.abs())
        .map_err(|e| solver_err("Lubkin", e))?;
    cx.ev.twist += 1;
    cx.ev.friction += 1;
    let c = m.stick_radius();
    let sign = moment.signum();
    let (a, p0, f) = (n.ax, n.p0, r.friction);
    // The ratio q/p of the closed form at each cell centre (its traction needs a
    // quadrature per point, so the stage reports progress).
    let total = lat.x.len();
    let mut ratio = vec![vec![f; lat.y.len()]; total];
    for (i, row) in ratio.iter_mut().enumerate() {
        for (j, cell) in row.iter_mut().enumerate() {
            if lat.stick[i][j] >= 0 {
                let (x, y) = (lat.x[i], lat.y[j]);
                let rr = x.hypot(y);
                let tau = m.traction(rr).map_err(|e| solver_err("Lubkin traction", e))?;
                let p = p0 * ((1.0 - rr / a) * (1.0 + rr / a)).max(0.0).sqrt();
                if p > 0.0 {
                    *cell = tau / p;
                }
                cx.ev.twist += 1;
                cx.ev.friction += 1;
                lat.stick[i][j] = i8::from(rr < c);
            }
        }
        cx.progress("Lubkin traction", i + 1, total);
    }
    let (x0, hx) = (lat.x[0], if total > 1 { lat.x[1] - lat.x[0] } else { 1.0 });
    let (y0, hy) = (lat.y[0], if lat.y.len() > 1 { lat.y[1] - lat.y[0] } else { 1.0 });
    let at = |x: f64, y: f64| {
        let i = ((x - x0) / hx).round() as usize;
        let j = ((y - y0) / hy).round() as usize;
        ratio[i][j]
    };
    cx.sampling = Some(super::friction::sample_consistently(
        lat,
        f,
        n.grid.element_area(),
        moment.abs(),
        |x, y| {
            let rr = x.hypot(y);
            // the centre cell carries no torsion (no direction); its weight is 0
            let dir = if rr > 0.0 { (-sign * y / rr, sign * x / rr) } else { (0.0, 0.0) };
            (at(x, y), rr, dir)
        },
    ));
    let [sub, ind] = &r.bodies.pair();
    let w = [m.rotation_per_body(sub), m.rotation_per_body(ind)];
    Ok(TangentialOut {
        creep: None,
        tangential: 0.0,
        moment,
        rigid: RigidOut {
            tangential: None,
            rotation: Some(sign * (w[0] + w[1])),
            per_body: Some([sign * w[0], sign * w[1]]),
        },
        zones: Zones {
            stick: vec![[0.0, c]],
            slip: vec![[c, n.ax]],
            coordinate: "radius",
            grid: None,
        },
    })
}
