//! Stage 3, twist: Lubkin's torsion of a Hertz circle (a moment alone on a sphere). Grid
//! solutions of a moment, alone or with a force, are in [`super::grid`].

use stickslip_traction::closed::Lubkin;

use super::friction::TangentialOut;
use super::lattice::Lattice;
use super::normal::ContactSolution;
use super::outcome::{RigidOut, Zones};
use super::{solver_err, Ctx};
use crate::error::SceneError;
use crate::plan::recipe::ContactRecipe;

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
    let total = lat.x.len();
    for i in 0..lat.x.len() {
        for j in 0..lat.y.len() {
            if lat.stick[i][j] >= 0 {
                let (x, y) = (lat.x[i], lat.y[j]);
                let rr = x.hypot(y);
                let tau = m.traction(rr).map_err(|e| solver_err("Lubkin traction", e))?;
                cx.ev.twist += 1;
                cx.ev.friction += 1;
                if rr > 0.0 {
                    lat.qx[i][j] = -sign * tau * y / rr;
                    lat.qy[i][j] = sign * tau * x / rr;
                }
                lat.stick[i][j] = i8::from(rr < c);
            }
        }
        cx.progress("Lubkin traction", i + 1, total);
    }
    let [sub, ind] = &r.bodies;
    let w = [m.rotation_per_body(sub), m.rotation_per_body(ind)];
    Ok(TangentialOut {
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
