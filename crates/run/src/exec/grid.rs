//! Stage 2/3 on a grid: partial slip and twist without a closed form, through the traction
//! crate's grid-solver contract ([`GridSolver`]): the modified LP (one load mode) or the fast
//! FFT solver (a force, a moment, or both). Failures arrive as typed errors.

use stickslip_lattice::PeriodicLattice;

use stickslip_traction::{
    Error as TractionError, FastSolver, GridProblem, GridSolver, Load, LoadKind, ModifiedLp,
    Tolerance,
};

use super::friction::TangentialOut;
use super::lattice::Lattice;
use super::normal::ContactSolution;
use super::outcome::{GridZones, RigidOut, Zones};
use super::{solver_err, Ctx};
use crate::plan::recipe::{ContactNormal, ContactRecipe, Force, GridMethod};
use stickslip_scene::eng::{eng, eng_beside, eng_scaled};
use stickslip_scene::{ErrorKind, SceneError, SurfaceBoundary};

/// The grid solve of `method` under a force, a moment, or both.
#[allow(clippy::too_many_lines, clippy::too_many_arguments)]
pub(crate) fn solve(
    lat: &mut Lattice,
    r: &ContactRecipe,
    n: &ContactSolution,
    method: GridMethod,
    force: Option<Force>,
    dir: f64,
    moment: Option<f64>,
    tolerance: f64,
    cx: &mut Ctx<'_>,
) -> Result<TangentialOut, SceneError> {
    let grid = &n.grid;
    let load = match (force, moment) {
        (Some(f), None) => Load::polar(f.magnitude, f.direction),
        (None, Some(m)) => Load::moment(m, None),
        (Some(f), Some(m)) => {
            Load::polar(f.magnitude, f.direction).and_then(|l| l.with_moment(m, None))
        }
        (None, None) => Load::polar(0.0, dir),
    }
    .map_err(|e| solver_err("grid solver load", e))?;
    let tolerance = Tolerance::relative(tolerance).map_err(|e| solver_err("tolerance", e))?;
    let mut problem = GridProblem::new(grid, r.bodies.pair(), r.friction)
        .map_err(|e| grid_err(method, e))?
        .with_tolerance(tolerance);
    // A periodic surface: the tangential operator has the same period as the normal one.
    if let Some(lattice) = periodic_lattice(r) {
        problem = problem.with_periodic(lattice);
    }
    let (stage, solver): (&'static str, Box<dyn GridSolver>) = match method {
        GridMethod::Lp => ("modified LP", Box::new(ModifiedLp::default())),
        GridMethod::Fast => ("fast solver", Box::new(FastSolver::default())),
    };
    cx.progress(stage, 0, 1);
    let sol = solver.solve(&problem, &load).map_err(|e| grid_err(method, e))?;
    cx.progress(stage, 1, 1);
    cx.ev.friction += grid.len() as u64;
    if moment.is_some() {
        cx.ev.twist += grid.len() as u64;
    }
    let with_force = force.is_some();
    // The rigid motion: the shift along the force, or the rotation.
    let e = (dir.cos(), dir.sin());
    let total = if with_force { sol.shift.0 * e.0 + sol.shift.1 * e.1 } else { sol.rotation };
    let per_body = match sol.rigid_per_body {
        Some(p) => p,
        None => {
            let share = sol
                .substrate_share(grid, &r.bodies.pair(), r.bodies.identical, with_force)
                .map_err(|e| solver_err("substrate operator", e))?;
            [share * total, (1.0 - share) * total]
        }
    };
    cx.solve_seconds += sol.info.setup_seconds + sol.info.solve_seconds;
    cx.elements = grid.len();
    cx.iterations = sol.info.iterations;
    cx.inner_iterations = sol.info.inner_iterations;
    cx.residual = sol.info.residual;
    for kk in 0..grid.len() {
        if let Some((i, j)) = lat.index(grid.x[kk], grid.y[kk]) {
            (lat.qx[i][j], lat.qy[i][j]) = sol.traction[kk];
            lat.stick[i][j] = i8::from(sol.state[kk] == stickslip_traction::ElementState::Stick);
        }
    }
    let gz = GridZones::from_states(&sol.state);
    let across = -sol.shift.0 * e.1 + sol.shift.1 * e.0;
    // Scales for the note: what is below 1e-12 of them is rounding and is written 0.
    let reach = grid.x.iter().chain(&grid.y).fold(0.0f64, |m, v| m.max(v.abs()));
    let force_scale = sol.resultant.0.hypot(sol.resultant.1).max(sol.moment.abs() / reach);
    let moment_scale = sol.moment.abs().max(force_scale * reach);
    let shift_scale = sol.shift.0.hypot(sol.shift.1).max(sol.rotation.abs() * reach);
    let note = match method {
        GridMethod::Lp => format!(
            "modified LP on {} elements ({} stick, {} slip), {} pivots; per-patch forces: {}",
            grid.len(),
            gz.stick,
            gz.slip,
            sol.info.iterations,
            sol.patch_summaries(grid, r.friction)
                .iter()
                .map(|p| format!(
                    "{:.6e} of capacity {:.6e} ({} of {} slipping)",
                    p.force, p.capacity, p.slipping, p.elements
                ))
                .collect::<Vec<_>>()
                .join("; ")
        ),
        GridMethod::Fast => format!(
            "fast solver on {} elements ({} stick, {} slip; {:?}): {} Newton steps, {} CG iterations; residual {:.3e}; set-up {:.3} s, iteration {:.3} s; resultant ({}, {}), moment {} about ({}, {}); shift across the load {}{}",
            grid.len(),
            gz.stick,
            gz.slip,
            sol.regime,
            sol.info.iterations,
            sol.info.inner_iterations,
            sol.info.residual,
            sol.info.setup_seconds,
            sol.info.solve_seconds,
            eng_scaled(sol.resultant.0, force_scale, "N"),
            eng_scaled(sol.resultant.1, force_scale, "N"),
            eng_scaled(sol.moment, moment_scale, "N m"),
            eng_scaled(sol.centre.0, reach, "m"),
            eng_scaled(sol.centre.1, reach, "m"),
            eng_scaled(across, shift_scale, "m"),
            if with_force && moment.is_some() {
                "; per-body shares are of the shift (both the shift and the rotation are reported)"
            } else {
                ""
            }
        ),
    };
    cx.notes.push(note);
    Ok(TangentialOut {
        creep: None,
        tangential: force.map_or(0.0, |f| f.signed),
        moment: moment.unwrap_or(0.0),
        rigid: RigidOut {
            tangential: with_force.then_some(total),
            rotation: moment.is_some().then_some(sol.rotation),
            per_body: Some(per_body),
        },
        zones: Zones { stick: vec![], slip: vec![], coordinate: "grid", grid: Some(gz) },
    })
}

/// A grid-solver error as a scene error, by its variant: a load beyond the friction capacity
/// is an impossible scene (key `load.tangential` or `load.moment`), a load at gross slip
/// names the load, an unconverged iteration names `solver.tolerance`; anything else is a
/// solver failure.
fn grid_err(method: GridMethod, e: TractionError) -> SceneError {
    use TractionError as E;
    let name = match method {
        GridMethod::Lp => "modified LP",
        GridMethod::Fast => "fast solver",
    };
    match &e {
        E::CapacityExceeded { load, requested, capacity } => {
            let key = if *load == LoadKind::Moment { "load.moment" } else { "load.tangential" };
            let msg = match load {
                LoadKind::Force | LoadKind::Moment => {
                    let unit = if *load == LoadKind::Moment { "N m" } else { "N" };
                    format!(
                        "{load} {} exceeds the friction capacity {}: the bodies slide (gross slip)",
                        eng_beside(*requested, &[*capacity], unit),
                        eng(*capacity, unit)
                    )
                }
                LoadKind::Combined => e.to_string(),
            };
            SceneError::new(
                ErrorKind::Impossible,
                format!("the load exceeds what friction can carry: {msg}"),
            )
            .key(key)
            .hint("reduce the load: a force alone is carried up to f P, a moment alone up to the spin capacity, and less of each when both act")
        }
        E::NoStickLeft { .. } => SceneError::new(
            ErrorKind::Solver,
            format!("the load is at or near what friction can carry: {e}"),
        )
        .key("load.tangential")
        .hint("reduce load.tangential or load.moment: together they are carried only below gross slip, which comes before f P and the spin capacity are each reached"),
        E::NotConverged { .. } | E::ToleranceOutOfRange { .. } => {
            SceneError::new(ErrorKind::Solver, format!("{name}: {e}"))
                .key("solver.tolerance")
                .hint("raise solver.tolerance (e.g. 1e-8), or change solver.grid")
        }
        E::Infeasible { .. } => SceneError::new(
            ErrorKind::Solver,
            format!("{name}: {e}"),
        )
        .key("solver.grid")
        .hint("the modified LP finds no complementary solution on lattices this coarse (seen at 5 elements across under a moment); raise solver.grid, or use method = \"fast\""),
        _ => solver_err(name, e),
    }
}

/// The period of a periodic surface as the tangential solvers take it (every cell of the
/// surface's lattice, the first cell's centre as origin); `None` for any other contact.
pub(crate) fn periodic_lattice(r: &ContactRecipe) -> Option<PeriodicLattice> {
    match &r.normal {
        ContactNormal::Surface { surface, .. } if surface.boundary == SurfaceBoundary::Periodic => {
            let [nx, ny] = surface.cells;
            let (hx, hy) = (surface.size[0] / nx as f64, surface.size[1] / ny as f64);
            let origin = (-0.5 * surface.size[0] + 0.5 * hx, -0.5 * surface.size[1] + 0.5 * hy);
            Some(PeriodicLattice { cells: (nx, ny), origin })
        }
        _ => None,
    }
}
