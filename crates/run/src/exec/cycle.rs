//! Stage 5, load cycle: the Mindlin–Deresiewicz hysteresis loop of a Hertz circle and the
//! energy dissipated per cycle, per body.

use stickslip_traction::closed::Deresiewicz;

use super::normal::ContactSolution;
use super::outcome::CycleOut;
use super::{solver_err, Ctx};
use crate::plan::recipe::{ContactRecipe, CycleRecipe};
use stickslip_scene::SceneError;

/// The loop at amplitude `c.amplitude` f P with `c.points` points.
pub(crate) fn run(
    c: CycleRecipe,
    r: &ContactRecipe,
    n: &ContactSolution,
    cx: &mut Ctx<'_>,
) -> Result<CycleOut, SceneError> {
    let f = r.friction;
    let amp = c.amplitude * f * n.load;
    let d =
        Deresiewicz::new(n.ax, n.load, f, amp).map_err(|e| solver_err("Mindlin-Deresiewicz", e))?;
    let half = (c.points / 2).max(1);
    let [sub, ind] = &r.bodies.pair();
    let lsub = d.hysteresis_loop(sub, half).map_err(|e| solver_err("hysteresis loop", e))?;
    let lind = d.hysteresis_loop(ind, half).map_err(|e| solver_err("hysteresis loop", e))?;
    cx.ev.hysteresis += (lsub.len() + lind.len()) as u64;
    Ok(CycleOut {
        amplitude: amp,
        t: lsub.iter().map(|p| p.0).collect(),
        delta: lsub.iter().zip(&lind).map(|(a, b)| a.1 + b.1).collect(),
        energy_per_cycle: [d.energy_per_cycle(sub), d.energy_per_cycle(ind)],
    })
}
