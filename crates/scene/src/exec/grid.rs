//! Stage 2/3 on a grid: the modified LP (one load mode) and the fast FFT solver (a force, a
//! moment, or both), for partial slip and twist without a closed form.

use std::time::Instant;

use stickslip_halfspace::Material;
use stickslip_traction::fast::TensorConvolution;
use stickslip_traction::{
    ContactGrid, ElementState, FastConfig, FastLoad, FastProblem, FastSolution, InfluenceModel,
    Load as LpLoad, TractionProblem,
};

use super::friction::TangentialOut;
use super::lattice::Lattice;
use super::normal::ContactSolution;
use super::outcome::{GridZones, RigidOut, Zones};
use super::{solver_err, Ctx};
use crate::error::{ErrorKind, SceneError};
use crate::plan::recipe::{ContactRecipe, Force, LpMode};

/// The modified LP of seed 002 in one load mode.
pub(crate) fn lp(
    lat: &mut Lattice,
    r: &ContactRecipe,
    n: &ContactSolution,
    mode: LpMode,
    cx: &mut Ctx<'_>,
) -> Result<TangentialOut, SceneError> {
    let grid = &n.grid;
    let load_mode = match mode {
        LpMode::Moment(moment) => LpLoad::Moment { moment, centre: None },
        LpMode::Force(f) => LpLoad::Force { magnitude: f.magnitude, angle: f.direction },
    };
    cx.progress("modified LP", 0, 1);
    let ts = Instant::now();
    let sol = TractionProblem::new(grid, r.bodies, r.friction, load_mode)
        .map_err(|e| solver_err("traction problem", e))?
        .solve()
        .map_err(|e| solver_err("modified LP", e))?;
    cx.solve_seconds = ts.elapsed().as_secs_f64();
    cx.elements = grid.len();
    cx.progress("modified LP", 1, 1);
    cx.ev.friction += grid.len() as u64;
    if matches!(mode, LpMode::Moment(_)) {
        cx.ev.twist += grid.len() as u64;
    }
    cx.iterations = sol.info.iterations;
    cx.residual = sol.excess_load;
    for kk in 0..grid.len() {
        if let Some((i, j)) = lat.index(grid.x[kk], grid.y[kk]) {
            let (dx, dy) = sol.direction[kk];
            lat.qx[i][j] = sol.traction[kk] * dx;
            lat.qy[i][j] = sol.traction[kk] * dy;
            lat.stick[i][j] = i8::from(sol.state[kk] == ElementState::Stick);
        }
    }
    let (tangential, moment, rigid) = match mode {
        LpMode::Moment(moment) => (
            0.0,
            moment,
            RigidOut {
                tangential: None,
                rotation: Some(moment.signum() * sol.rigid),
                per_body: Some(sol.rigid_per_body),
            },
        ),
        LpMode::Force(f) => (
            f.signed,
            0.0,
            RigidOut {
                tangential: Some(sol.rigid),
                rotation: None,
                per_body: Some(sol.rigid_per_body),
            },
        ),
    };
    let nstick = sol.state.iter().filter(|s| **s == ElementState::Stick).count();
    cx.notes.push(format!(
        "modified LP on {} elements ({} stick, {} slip), {} pivots; per-patch forces: {}",
        grid.len(),
        nstick,
        grid.len() - nstick,
        sol.info.iterations,
        sol.patches
            .iter()
            .map(|p| format!(
                "{:.6e} of capacity {:.6e} ({} of {} slipping)",
                p.force, p.capacity, p.slipping, p.elements
            ))
            .collect::<Vec<_>>()
            .join("; ")
    ));
    Ok(TangentialOut {
        tangential,
        moment,
        rigid,
        zones: Zones {
            stick: vec![],
            slip: vec![],
            coordinate: "grid",
            grid: Some(GridZones::from_states(&sol.state)),
        },
    })
}

/// The fast solver under a force, a moment, or both.
#[allow(clippy::too_many_lines)]
pub(crate) fn fast(
    lat: &mut Lattice,
    r: &ContactRecipe,
    n: &ContactSolution,
    force: Option<Force>,
    dir: f64,
    moment: Option<f64>,
    tolerance: f64,
    cx: &mut Ctx<'_>,
) -> Result<TangentialOut, SceneError> {
    let grid = &n.grid;
    // With a moment alone the force is zero along the scene's direction.
    let tmag = force.map_or(0.0, |f| f.magnitude);
    let mut load = FastLoad::polar(tmag, dir).map_err(|e| solver_err("fast solver load", e))?;
    if let Some(m) = moment {
        load = load.with_moment(m, None).map_err(|e| solver_err("fast solver load", e))?;
    }
    let config =
        FastConfig::new(tolerance, 100).map_err(|e| solver_err("fast solver configuration", e))?;
    cx.progress("fast solver", 0, 1);
    let ts = Instant::now();
    let sol = FastProblem::new(grid, r.bodies, r.friction, load)
        .map_err(fast_err)?
        .with_config(config)
        .solve()
        .map_err(fast_err)?;
    cx.progress("fast solver", 1, 1);
    cx.ev.friction += grid.len() as u64;
    if moment.is_some() {
        cx.ev.twist += grid.len() as u64;
    }
    let with_force = force.is_some();
    // The rigid motion: the shift along the force, or the rotation.
    let e = (dir.cos(), dir.sin());
    let total = if with_force { sol.shift.0 * e.0 + sol.shift.1 * e.1 } else { sol.rotation };
    let share = substrate_share(grid, &sol, &r.bodies, r.identical, with_force)?;
    cx.solve_seconds = ts.elapsed().as_secs_f64();
    cx.elements = grid.len();
    cx.iterations = sol.info.iterations;
    cx.inner_iterations = sol.info.cg_iterations;
    cx.residual = sol.info.residual;
    for kk in 0..grid.len() {
        if let Some((i, j)) = lat.index(grid.x[kk], grid.y[kk]) {
            (lat.qx[i][j], lat.qy[i][j]) = sol.traction[kk];
            lat.stick[i][j] = i8::from(sol.state[kk] == ElementState::Stick);
        }
    }
    let gz = GridZones::from_states(&sol.state);
    let across = -sol.shift.0 * e.1 + sol.shift.1 * e.0;
    cx.notes.push(format!(
        "fast solver on {} elements ({} stick, {} slip; {:?}): {} Newton steps, {} CG iterations, {} FFT products on a {} x {} padded lattice; residual {:.3e}, load residual {:.3e}; set-up {:.3} s, iteration {:.3} s; resultant ({:.6e}, {:.6e}) N, moment {:.6e} N m about ({:.6e}, {:.6e}) m; shift across the load {:.3e} m{}",
        grid.len(),
        gz.stick,
        gz.slip,
        sol.regime,
        sol.info.iterations,
        sol.info.cg_iterations,
        sol.info.products,
        sol.info.fft_size.0,
        sol.info.fft_size.1,
        sol.info.residual,
        sol.info.load_residual,
        sol.info.setup_seconds,
        sol.info.seconds,
        sol.resultant.0,
        sol.resultant.1,
        sol.moment,
        sol.centre.0,
        sol.centre.1,
        across,
        if with_force && moment.is_some() {
            "; per-body shares are of the shift (both the shift and the rotation are reported)"
        } else {
            ""
        }
    ));
    Ok(TangentialOut {
        tangential: force.map_or(0.0, |f| f.signed),
        moment: moment.unwrap_or(0.0),
        rigid: RigidOut {
            tangential: with_force.then_some(total),
            rotation: moment.is_some().then_some(sol.rotation),
            per_body: Some([share * total, (1.0 - share) * total]),
        },
        zones: Zones { stick: vec![], slip: vec![], coordinate: "grid", grid: Some(gz) },
    })
}

/// A fast-solver error as a scene error: a load beyond the friction capacity is an impossible
/// scene (key `load.tangential` or `load.moment`), an unconverged iteration names
/// `solver.tolerance`; anything else is a solver failure.
fn fast_err(e: stickslip_traction::Error) -> SceneError {
    use stickslip_traction::Error as E;
    match &e {
        E::OutOfDomain { name, .. } if name.contains("capacity") || name.contains("(f P)") => {
            let key = if name.contains("moment") { "load.moment" } else { "load.tangential" };
            SceneError::new(
                ErrorKind::Impossible,
                format!("the load exceeds what friction can carry: {e}"),
            )
            .key(key)
            .hint("reduce the load: a force alone is carried up to f P, a moment alone up to the spin capacity, and less of each when both act")
        }
        E::OutOfDomain { name, .. } if name.contains("no stick component") => {
            SceneError::new(
                ErrorKind::Solver,
                format!("the load is at or near what friction can carry: {e}"),
            )
            .key("load.tangential")
            .hint("reduce load.tangential or load.moment: together they are carried only below gross slip, which comes before f P and the spin capacity are each reached")
        }
        E::NotConverged { .. } => {
            SceneError::new(ErrorKind::Solver, format!("fast solver: {e}"))
                .key("solver.tolerance")
                .hint("raise solver.tolerance (e.g. 1e-8), or change solver.grid")
        }
        _ => solver_err("fast solver", e),
    }
}

/// The substrate's share of the rigid shift (force) or rotation (moment) of a fast solution:
/// $\sum_{stick} \mathbf m\cdot\mathbf u^{(1)}_k / \sum_{stick} \mathbf m\cdot\mathbf u_k$,
/// with $\mathbf m$ the unit load direction (force) or $\hat z\times(\mathbf x_k-\mathbf c)/
/// |\mathbf x_k-\mathbf c|^2$ (moment), $\mathbf u^{(1)}$ the substrate's own displacement
/// and $\mathbf u$ the relative one: on the stick zone $\mathbf u$ is the rigid motion, so
/// this is the per-body mean the LP reports (FORMULAS.md F: $A = A^{(1)} + A^{(2)}$). Exactly
/// 1/2 for identical bodies, 1 under a rigid indenter; otherwise one extra FFT product.
fn substrate_share(
    grid: &ContactGrid,
    sol: &FastSolution,
    bodies: &[Material; 2],
    identical: bool,
    force: bool,
) -> Result<f64, SceneError> {
    if bodies[1].is_rigid() {
        return Ok(1.0);
    }
    if bodies[0].is_rigid() {
        return Ok(0.0);
    }
    if identical {
        return Ok(0.5);
    }
    let op = TensorConvolution::new(grid, &bodies[0].compliance(), InfluenceModel::default())
        .map_err(|e| solver_err("substrate operator", e))?;
    let mut scratch = op.make_scratch();
    let n = grid.len();
    let qx: Vec<f64> = sol.traction.iter().map(|q| q.0).collect();
    let qy: Vec<f64> = sol.traction.iter().map(|q| q.1).collect();
    let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
    op.apply(&qx, &qy, &mut ux, &mut uy, &mut scratch);
    let (c, s) = {
        let t = sol.shift.0.hypot(sol.shift.1);
        if t > 0.0 {
            (sol.shift.0 / t, sol.shift.1 / t)
        } else {
            (1.0, 0.0)
        }
    };
    let any_stick = sol.state.contains(&ElementState::Stick);
    let (mut own, mut all) = (0.0, 0.0);
    for k in 0..n {
        if any_stick && sol.state[k] != ElementState::Stick {
            continue;
        }
        let m = if force {
            (c, s)
        } else {
            let (dx, dy) = (grid.x[k] - sol.centre.0, grid.y[k] - sol.centre.1);
            let r2 = dx * dx + dy * dy;
            if r2 == 0.0 {
                continue;
            }
            (-dy / r2, dx / r2)
        };
        own += m.0 * ux[k] + m.1 * uy[k];
        all += m.0 * sol.displacement[k].0 + m.1 * sol.displacement[k].1;
    }
    Ok(if all != 0.0 { own / all } else { 0.5 })
}
