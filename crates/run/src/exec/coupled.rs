//! Stages 1 and 2 together for dissimilar bodies on a surface: the normal and tangential
//! problems coupled through Dundurs' beta, solved by the traction crate's alternating
//! process ([`stickslip_normal::coupled`]). Used only when the plan says so
//! (`ContactRecipe::coupling`); with beta = 0 the separate stages run and this file is not
//! involved.

use stickslip_normal::CoupledProblem;
use stickslip_normal::NormalLoad as TNormalLoad;
use stickslip_traction::{ElementState, Load, Tolerance};

use super::friction::TangentialOut;
use super::lattice::Lattice;
use super::normal::{surface_err, surface_solution, ContactSolution};
use super::outcome::{CouplingOut, GridZones, RigidOut, Zones};
use super::{solver_err, Ctx};
use crate::plan::recipe::{ContactNormal, ContactRecipe, GridStep, SurfaceLoad, Tangential};
use stickslip_scene::SceneError;

/// The coupled solve: the normal solution, the lattice with pressure and traction filled, and
/// the tangential outcome.
pub(crate) fn solve(
    r: &ContactRecipe,
    beta: f64,
    cx: &mut Ctx<'_>,
) -> Result<(ContactSolution, Lattice, TangentialOut), SceneError> {
    let (ContactNormal::Surface { surface: s, load, tolerance, .. }, Some(Tangential::Grid(step))) =
        (&r.normal, r.tangential)
    else {
        return Err(solver_err("coupled solve", "planned without a surface and a grid step"));
    };
    let GridStep { force, moment, direction, .. } = step;
    let tload = match (force, moment) {
        (Some(f), None) => Load::polar(f.magnitude, f.direction),
        (None, Some(m)) => Load::moment(m, None),
        (Some(f), Some(m)) => {
            Load::polar(f.magnitude, f.direction).and_then(|l| l.with_moment(m, None))
        }
        (None, None) => Load::polar(0.0, direction),
    }
    .map_err(|e| solver_err("grid solver load", e))?;
    let [nx, ny] = s.cells;
    let (hx, hy) = (s.size[0] / nx as f64, s.size[1] / ny as f64);
    let gap = s.initial_gap();
    let tol = Tolerance::relative(*tolerance).map_err(|e| solver_err("tolerance", e))?;
    let nload = match load {
        SurfaceLoad::Force(p) => TNormalLoad::Force(*p),
        SurfaceLoad::Approach(d) => TNormalLoad::Approach(*d),
    };
    cx.progress("coupled normal-tangential solve", 0, 1);
    let sol = CoupledProblem::new(nx, ny, (hx, hy), &gap, r.bodies.pair(), r.friction, tload)
        .map_err(surface_err)?
        .with_origin((-0.5 * s.size[0], -0.5 * s.size[1]))
        .with_tolerance(tol)
        .with_boundary(match s.boundary {
            stickslip_scene::SurfaceBoundary::Free => stickslip_normal::Boundary::Free,
            stickslip_scene::SurfaceBoundary::Periodic => stickslip_normal::Boundary::Periodic,
        })
        .solve(nload)
        .map_err(|e| match e {
            stickslip_normal::Error::Tangential(stickslip_traction::Error::CapacityExceeded {
                ..
            }) => solver_err(
                "coupled solve (the tangential load exceeds the friction capacity f P)",
                e,
            ),
            e => surface_err(e),
        })?;
    cx.progress("coupled normal-tangential solve", 1, 1);
    let n = surface_solution(s, &sol.normal, *tolerance, None, cx)?;
    let mut lat = n.lattice.clone();
    let t = &sol.tangential;
    let grid = &n.grid;
    for kk in 0..grid.len() {
        if let Some((i, j)) = lat.index(grid.x[kk], grid.y[kk]) {
            (lat.qx[i][j], lat.qy[i][j]) = t.traction[kk];
            lat.stick[i][j] = i8::from(t.state[kk] == ElementState::Stick);
        }
    }
    cx.ev.friction += grid.len() as u64;
    if moment.is_some() {
        cx.ev.twist += grid.len() as u64;
    }
    let info = sol.info;
    cx.solve_seconds = info.seconds;
    cx.elements = grid.len();
    cx.iterations = info.tangential_iterations;
    cx.inner_iterations = t.info.cg_iterations;
    cx.residual = t.info.residual;
    cx.coupling = Some(CouplingOut {
        beta,
        passes: info.passes,
        pressure_change: info.pressure_change,
        traction_change: info.traction_change,
        residual: info.residual,
        normal_iterations: info.normal_iterations,
        tangential_iterations: info.tangential_iterations,
        steps: None,
        most_passes: None,
    });
    let gz = GridZones::from_states(&t.state);
    cx.notes.push(format!(
        "Dundurs coupling (beta = {beta:.4}): {} alternating passes ({} normal CCG iterations, {} Newton steps in all); last change of pressure {:.2e}, of traction {:.2e} (tolerance {:.1e}); final tangential solve on {} elements ({} stick, {} slip), residual {:.3e}",
        info.passes,
        info.normal_iterations,
        info.tangential_iterations,
        info.pressure_change,
        info.traction_change,
        tolerance,
        grid.len(),
        gz.stick,
        gz.slip,
        t.info.residual,
    ));
    let with_force = force.is_some();
    let e = (direction.cos(), direction.sin());
    let total = if with_force { t.shift.0 * e.0 + t.shift.1 * e.1 } else { t.rotation };
    let out = TangentialOut {
        creep: None,
        tangential: force.map_or(0.0, |f| f.signed),
        moment: moment.unwrap_or(0.0),
        rigid: RigidOut {
            tangential: with_force.then_some(total),
            rotation: moment.is_some().then_some(t.rotation),
            // the per-body split of a coupled solution is not computed
            per_body: None,
        },
        zones: Zones { stick: vec![], slip: vec![], coordinate: "grid", grid: Some(gz) },
    };
    Ok((n, lat, out))
}
