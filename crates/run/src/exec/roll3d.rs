//! Stage 2 of a 3D contact in steady rolling: creep forces, spin moment, traction, stick and
//! slip and micro-slip from the creepages, by the exact theory, FASTSIM or Polach's law
//! (`stickslip_rolling::steady3d`), on the normal stage's contact grid.
//!
//! The rolling theories give the traction on body 1 (the indenter, Kalker's convention) and
//! the creep forces on it; the lattice carries, as for every 3D contact, the traction on the
//! substrate, its negative, which the subsurface field stage loads the substrate with.

use stickslip_rolling::Error as RollingError;
use stickslip_rolling::{
    steady3d::fastsim, steady3d::polach, steady3d::RollingMethod, steady3d::RollingSolution,
    steady3d::SteadyRolling,
};

use super::friction::TangentialOut;
use super::lattice::Lattice;
use super::normal::ContactSolution;
use super::outcome::{GridZones, RigidOut, Zones};
use super::{solver_err, Ctx};
use crate::plan::recipe::{ContactRecipe, RollingStep};
use stickslip_halfspace::material::Compliance;
use stickslip_scene::eng::eng;
use stickslip_scene::{ErrorKind, SceneError};

/// The combined shear modulus and Poisson ratio of Kalker's normalisation:
/// $1/G = \tfrac12(1/G_1 + 1/G_2)$, $\nu/G = \tfrac12(\nu_1/G_1 + \nu_2/G_2)$.
fn combined(r: &ContactRecipe) -> (f64, f64) {
    let c = Compliance::pair(&r.bodies.substrate, &r.bodies.indenter);
    let sum = c.one_minus_nu + c.nu;
    (2.0 / sum, c.nu / sum)
}

/// Solve the rolling step and fill the lattice.
pub(crate) fn solve(
    lat: &mut Lattice,
    r: &ContactRecipe,
    n: &ContactSolution,
    step: &RollingStep,
    cx: &mut Ctx<'_>,
) -> Result<TangentialOut, SceneError> {
    let (g, nu) = combined(r);
    let grid = &n.grid;
    let creep = step.creepage;
    let t0 = std::time::Instant::now();
    cx.progress("rolling", 0, 1);
    let sol: Option<RollingSolution> = match step.method {
        RollingMethod::Polach => None,
        RollingMethod::Fastsim => {
            Some(fastsim::solve(grid, n.ax, n.ay, g, nu, r.friction, &creep).map_err(method_err)?)
        }
        _ => {
            let p = SteadyRolling::new(grid, r.bodies.pair(), r.friction)
                .and_then(|p| p.with_tolerance(step.tolerance))
                .map_err(|e| solver_err("exact steady rolling", e))?;
            Some(p.solve(&creep).map_err(exact_err)?)
        }
    };
    cx.progress("rolling", 1, 1);
    cx.ev.rolling += 1;
    cx.ev.friction += grid.len() as u64;
    cx.solve_seconds += t0.elapsed().as_secs_f64();
    cx.elements = grid.len();
    let Some(sol) = sol else {
        let (fx, fy) =
            polach::forces(n.ax, n.ay, g, nu, n.load, r.friction, &creep).map_err(method_err)?;
        // No distribution: the lattice carries the pressure only, no zones.
        for row in &mut lat.stick {
            for s in row.iter_mut().filter(|s| **s == 1) {
                *s = 0;
            }
        }
        cx.notes.push(format!(
            "Polach's creep-force law: forces only (no traction, stick or slip map); G = {}, nu = {nu}",
            eng(g, "Pa")
        ));
        return Ok(TangentialOut {
            creep: Some([fx, fy, 0.0]),
            tangential: fx.hypot(fy),
            moment: 0.0,
            rigid: RigidOut { tangential: None, rotation: None, per_body: None },
            zones: Zones { stick: vec![], slip: vec![], coordinate: "grid", grid: None },
        });
    };
    cx.iterations = sol.info.iterations;
    cx.inner_iterations = sol.info.products;
    cx.residual = sol.info.residual;
    let zones = fill_lattice(lat, &sol, step.speed);
    let stick = zones.stick;
    let capacity = r.friction * n.load;
    let ratio = sol.fx.hypot(sol.fy) / capacity;
    cx.notes.push(format!(
        "{} on {} elements: {} stick, {} slip{}; |F|/(fN) = {ratio:.6}; G = {}, nu = {nu}{}",
        match step.method {
            RollingMethod::Fastsim => "FASTSIM".to_string(),
            _ => format!(
                "exact steady rolling ({} Newton steps, {} FFT products, residual {:.3e})",
                sol.info.iterations, sol.info.products, sol.info.residual
            ),
        },
        sol.x.len(),
        stick,
        sol.stick.len() - stick,
        if stick == 0 {
            " (full slip: every element slides; the creepage is beyond saturation)"
        } else {
            ""
        },
        eng(g, "Pa"),
        if r.bodies.identical {
            ""
        } else {
            "; bodies treated as quasi-identical (normal-tangential coupling neglected)"
        },
    ));
    Ok(TangentialOut {
        creep: Some([sol.fx, sol.fy, sol.mz]),
        tangential: sol.fx.hypot(sol.fy),
        moment: 0.0,
        rigid: RigidOut { tangential: None, rotation: None, per_body: None },
        zones: Zones { stick: vec![], slip: vec![], coordinate: "grid", grid: Some(zones) },
    })
}

/// A rolling solution on the lattice: the traction on the substrate (minus body 1's), the
/// stick flags and the micro-slip velocity `speed` times the slip; the zone counts. Shared
/// by steady and transient rolling.
pub(crate) fn fill_lattice(lat: &mut Lattice, sol: &RollingSolution, speed: f64) -> GridZones {
    let (nx, ny) = (lat.x.len(), lat.y.len());
    let mut slip = [vec![vec![0.0; ny]; nx], vec![vec![0.0; ny]; nx]];
    for k in 0..sol.x.len() {
        if let Some((i, j)) = lat.index(sol.x[k], sol.y[k]) {
            lat.qx[i][j] = -sol.qx[k];
            lat.qy[i][j] = -sol.qy[k];
            lat.stick[i][j] = i8::from(sol.stick[k]);
            slip[0][i][j] = speed * sol.sx[k];
            slip[1][i][j] = speed * sol.sy[k];
        }
    }
    lat.slip = Some(slip);
    let stick = sol.stick.iter().filter(|&&s| s).count();
    GridZones { stick, slip: sol.stick.len() - stick, stick_area_fraction: sol.stick_fraction() }
}

/// FASTSIM's and Polach's parameters come from Kalker's table: a contact outside it is
/// refused with the method key.
fn method_err(e: RollingError) -> SceneError {
    match e {
        RollingError::OutOfDomain { .. } => SceneError::new(
            ErrorKind::Unsupported,
            format!("the approximate rolling theory cannot take this contact: {e}"),
        )
        .key("solver.method")
        .hint("FASTSIM and Polach need a/b in [0.1, 10] and nu in [0, 0.5] (Kalker's table); use method = \"fast\" for the exact theory"),
        other => solver_err("rolling", other),
    }
}

fn exact_err(e: RollingError) -> SceneError {
    match e {
        RollingError::NotConverged { .. } => {
            SceneError::new(ErrorKind::Solver, format!("exact steady rolling: {e}"))
                .key("solver.tolerance")
                .hint("raise solver.tolerance (e.g. 1e-6) or change solver.grid")
        }
        other => solver_err("exact steady rolling", other),
    }
}
