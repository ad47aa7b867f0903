//! Stage 2 of a 3D contact rolled in time steps (`[motion.transient]`): from rest, or from a
//! Cattaneo shift under the creep force, the contact rolls one element length per step under
//! that force and the spin creepage (`stickslip_rolling::steady3d::TransientRolling`); the
//! creepages that carry the force are found at every step. When the longitudinal or lateral
//! creepage is given instead, the contact rolls at those creepages and the creep force is
//! found at every step. Each step goes into `history` (`control` = "rolling"); the final
//! state fills the lattice as a steady rolling stage does.
//!
//! Under a creep force the state is the steady one after about two contact lengths (the
//! default distance); under prescribed creepages the start's memory decays more slowly (by 4
//! to 9 per contact length), so the default is ten lengths (docs/load-histories.md,
//! "Transient rolling").

use stickslip_rolling::steady3d::TransientRolling;
use stickslip_rolling::Error as RollingError;
use stickslip_traction::{Error as TractionError, FastConfig, Tolerance};

use super::friction::TangentialOut;
use super::lattice::Lattice;
use super::normal::ContactSolution;
use super::outcome::{HistoryOut, RigidOut, Zones};
use super::{solver_err, Ctx};
use crate::plan::recipe::{ContactRecipe, RollingStep, TransientRecipe};
use stickslip_scene::eng::eng;
use stickslip_scene::{ErrorKind, SceneError};

/// The most steps one run takes (element lengths rolled).
pub(crate) const MAX_STEPS: usize = 20_000;

/// A failed step, located at its key.
fn step_err(e: RollingError, step: usize) -> SceneError {
    match e {
        RollingError::Tangential(TractionError::CapacityExceeded { .. }) => SceneError::new(
            ErrorKind::Impossible,
            format!("transient rolling, step {step}: the creep force exceeds what friction carries on this contact ({e})"),
        )
        .key("load.tangential")
        .hint("reduce load.tangential below f P (a creep force at f P is full sliding, which has no partial-slip state)"),
        RollingError::Tangential(TractionError::NotConverged { .. }) => SceneError::new(
            ErrorKind::Solver,
            format!("transient rolling, step {step}: the fast solver did not converge ({e})"),
        )
        .key("solver.tolerance")
        .hint("raise solver.tolerance (e.g. 1e-8) or change solver.grid"),
        other => solver_err(&format!("transient rolling, step {step}"), other),
    }
}

/// Roll the contact as `tr` says and fill the lattice with the final state; the history
/// holds every step.
pub(crate) fn solve(
    lat: &mut Lattice,
    r: &ContactRecipe,
    n: &ContactSolution,
    step: &RollingStep,
    tr: &TransientRecipe,
    cx: &mut Ctx<'_>,
) -> Result<(TangentialOut, HistoryOut), SceneError> {
    let grid = &n.grid;
    let h = grid.hx;
    let lengths = if tr.creepage.is_some() { 10.0 } else { 2.0 };
    let distance = tr.distance.unwrap_or(2.0 * lengths * n.ax);
    let rolls = (distance / h).round().max(1.0);
    if rolls > MAX_STEPS as f64 {
        return Err(SceneError::new(
            ErrorKind::OutOfRange,
            format!(
                "rolling {} in steps of one element length ({}) takes {rolls:.0} steps, more than {MAX_STEPS}",
                eng(distance, "m"),
                eng(h, "m")
            ),
        )
        .key("motion.transient.distance")
        .hint("roll a shorter distance (two contact lengths reach the steady state) or use a coarser solver.grid"));
    }
    let rolls = rolls as usize;
    let config = FastConfig::new(
        Tolerance::relative(step.tolerance).map_err(|e| solver_err("tolerance", e))?,
        FastConfig::default().max_iterations(),
    )
    .map_err(|e| solver_err("fast solver configuration", e))?;
    let t0 = std::time::Instant::now();
    let mut problem = TransientRolling::new(grid, r.bodies.pair(), r.friction)
        .map_err(|e| solver_err("transient rolling", e))?
        .with_config(config);
    let spin = step.creepage.spin;
    let total = rolls + usize::from(tr.shift_first);
    let e = tr.direction_deg.to_radians();
    let e = (e.cos(), e.sin());
    let mut hist = HistoryOut {
        control: "rolling",
        direction_deg: tr.direction_deg,
        corners: vec![0],
        tangential: Vec::with_capacity(total),
        normal: Vec::with_capacity(total),
        moment: Vec::with_capacity(total),
        shift: Vec::with_capacity(total),
        rotation: Vec::with_capacity(total),
        stick_fraction: Vec::with_capacity(total),
        dissipated: Vec::with_capacity(total),
        work: Vec::with_capacity(total),
        elastic_energy: Vec::with_capacity(total),
        gross_slip: Vec::with_capacity(total),
        loops: Vec::new(),
        ruiz_max: None,
        distance: Vec::with_capacity(total),
        fx: Vec::with_capacity(total),
        fy: Vec::with_capacity(total),
        mz: Vec::with_capacity(total),
        creepage_longitudinal: Vec::with_capacity(total),
        creepage_lateral: Vec::with_capacity(total),
        coupling_passes: Vec::new(),
    };
    let (mut shift, mut dissipated, mut work) = (0.0, 0.0, 0.0);
    let (mut iterations, mut products, mut residual) = (0usize, 0usize, 0.0f64);
    for k in 0..total {
        cx.progress("rolling", k, total);
        let at_rest = tr.shift_first && k == 0;
        let s = match (at_rest, tr.creepage) {
            (true, _) => problem.shift(tr.force),
            (false, Some(c)) => problem.roll_at_creepage(c, spin),
            (false, None) => problem.roll(tr.force, spin),
        }
        .map_err(|e| step_err(e, k))?;
        let along = s.shift.0 * e.0 + s.shift.1 * e.1;
        shift += along;
        dissipated += s.dissipated;
        work += s.force.0 * s.shift.0 + s.force.1 * s.shift.1;
        iterations += s.newton_iterations;
        products += s.products;
        residual = residual.max(s.residual);
        hist.tangential.push(s.force.0 * e.0 + s.force.1 * e.1);
        hist.normal.push(n.load);
        hist.moment.push(s.mz);
        hist.shift.push(shift);
        hist.rotation.push(0.0);
        hist.stick_fraction.push(s.stick_fraction);
        hist.dissipated.push(dissipated);
        hist.work.push(work);
        hist.elastic_energy.push(s.elastic_energy);
        hist.gross_slip.push(s.stick_fraction == 0.0);
        hist.distance.push(s.distance);
        hist.fx.push(s.force.0);
        hist.fy.push(s.force.1);
        hist.mz.push(s.mz);
        // The step at rest does not roll: its creepage column reads 0 (its distance is 0).
        hist.creepage_longitudinal.push(s.creepage.map_or(0.0, |c| c.0));
        hist.creepage_lateral.push(s.creepage.map_or(0.0, |c| c.1));
    }
    if tr.shift_first {
        hist.corners.push(1);
    }
    cx.progress("rolling", total, total);
    cx.ev.rolling += total as u64;
    cx.ev.friction += (grid.len() * total) as u64;
    cx.solve_seconds += t0.elapsed().as_secs_f64();
    cx.elements = grid.len();
    cx.iterations = iterations;
    cx.inner_iterations = products;
    cx.residual = residual;

    // The final state on the lattice: the traction on the substrate (minus body 1's), the
    // stick flags and the micro-slip velocity V s of the last rolling step.
    let sol = problem.solution();
    let zones = super::roll3d::fill_lattice(lat, &sol, step.speed);
    let last = hist.creepage_longitudinal.len() - 1;
    cx.notes.push(format!(
        "transient rolling on {} elements: {} steps ({}{} rolled in steps of {}{}), {} Newton steps, {} FFT products, largest residual {:.2e}; final creepages xi = {}, eta = {} under Fx = {}, Fy = {}; energy dissipated {}",
        grid.len(),
        total,
        if tr.shift_first { "a Cattaneo shift at rest, then " } else { "" },
        eng(hist.distance[last], "m"),
        eng(h, "m"),
        if tr.creepage.is_some() { " at the prescribed creepages" } else { " under the creep force" },
        iterations,
        products,
        residual,
        eng(hist.creepage_longitudinal[last], ""),
        eng(hist.creepage_lateral[last], ""),
        eng(sol.fx, "N"),
        eng(sol.fy, "N"),
        eng(dissipated, "J"),
    ));
    let t = TangentialOut {
        creep: Some([sol.fx, sol.fy, sol.mz]),
        tangential: sol.fx.hypot(sol.fy),
        moment: 0.0,
        rigid: RigidOut { tangential: None, rotation: None, per_body: None },
        zones: Zones { stick: vec![], slip: vec![], coordinate: "grid", grid: Some(zones) },
    };
    Ok((t, hist))
}
