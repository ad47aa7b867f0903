//! A wheel on its rail: one call of `stickslip-wheelrail` (placement, contact search, each
//! patch's normal contact under the vertical wheel load, creepages and creep forces), its
//! patches reported in result.json's `wheel_rail`.

use super::outcome::{
    ContactOut, CreepageOut, Field, Forces, NormalSolverOut, PatchLatticeOut, PatchMaps, RigidOut,
    TangentialSolveOut, TrackForce, WheelRailOut, WheelRailPatchOut, Zones,
};
use super::{lattice, solver_err, Ctx, Parts};
use crate::plan::recipe::WheelRailRecipe;
use stickslip_scene::{ErrorKind, SceneError};
use stickslip_wheelrail as wr;

/// The wheel-rail library's refusal as a scene error on the key a user changes.
fn refusal(e: wr::Error) -> SceneError {
    match e {
        wr::Error::NoContact { .. } => SceneError::new(ErrorKind::Impossible, e.to_string())
            .key("position.lateral")
            .hint("the profiles are placed apart: check geometry.gauge, flange_back_distance, flange_back_position, profile_unit and the sides of the profile files"),
        wr::Error::FlangeClimb { .. } => SceneError::new(ErrorKind::Impossible, e.to_string())
            .key("position.lateral")
            .hint("reduce position.lateral (or the yaw): the wheel has climbed the rail's flange"),
        wr::Error::NotConverged { .. } => SceneError::new(ErrorKind::Solver, e.to_string())
            .key("load.normal")
            .hint("the vertical load could not be met; try load.approach, or a different load"),
        wr::Error::OutOfDomain { name: "motion.creepage", value, .. } => {
            SceneError::new(ErrorKind::Unsupported, format!("creepages given directly are taken for a position with one contact patch; this position has {value} patches, each with its own creepages"))
                .key("motion.creepage")
                .hint("remove motion.creepage and give motion.pitch_rate: each patch then takes the creepages of the wheelset's motion")
        }
        wr::Error::OutOfDomain { .. } => SceneError::new(ErrorKind::OutOfRange, e.to_string())
            .key("position")
            .hint("check [position] and [motion]"),
        e => solver_err("the wheel-rail solve", e),
    }
}

/// A patch's maps on its lattice: the normal solution's pressure and contact, the
/// undeformed gap, and the tangential solution's tractions and stick, placed from its
/// element centres into the lattice cells.
fn maps(p: &wr::PatchSolution) -> Result<PatchMaps, SceneError> {
    let n = &p.normal;
    let (nx, ns) = (n.nx, n.ny);
    let cells = nx * ns;
    if n.pressure.len() != cells || n.contact.len() != cells || p.gap.len() != cells {
        return Err(solver_err("the wheel-rail maps", "a patch's arrays do not fill its lattice"));
    }
    let x: Vec<f64> = (0..nx).map(|i| n.origin.0 + (i as f64 + 0.5) * n.hx).collect();
    let s: Vec<f64> = (0..ns).map(|j| n.origin.1 + (j as f64 + 0.5) * n.hy).collect();
    let mut stick: Vec<i8> = n.contact.iter().map(|&c| if c { 0 } else { -1 }).collect();
    let (mut qx, mut qs) = (None, None);
    if let Some(r) = &p.rolling {
        let (mut mx, mut ms) = (vec![0.0; cells], vec![0.0; cells]);
        for k in 0..r.x.len() {
            // The element's cell from its centre.
            let fi = (r.x[k] - n.origin.0) / n.hx - 0.5;
            let fj = (r.y[k] - n.origin.1) / n.hy - 0.5;
            let (i, j) = (fi.round(), fj.round());
            if !(0.0..nx as f64).contains(&i)
                || !(0.0..ns as f64).contains(&j)
                || (fi - i).abs() > 1e-6
                || (fj - j).abs() > 1e-6
            {
                return Err(solver_err(
                    "the wheel-rail maps",
                    format!(
                        "a tangential element at ({}, {}) m is off the patch lattice",
                        r.x[k], r.y[k]
                    ),
                ));
            }
            let c = j as usize * nx + i as usize;
            mx[c] = r.qx[k];
            ms[c] = r.qy[k];
            stick[c] = i8::from(r.stick[k]);
        }
        qx = Some(mx);
        qs = Some(ms);
    }
    Ok(PatchMaps { x, s, pressure: n.pressure.clone(), gap: p.gap.clone(), qx, qs, stick })
}

/// `solver.normal` of a wheel on its rail: the final normal solves of the patches (the
/// wheelset's last trial height), their iterations, products and coarse iterations summed
/// over the patches and their residuals the largest; `steps` counts every normal solve of
/// the load iteration (all patches, all trial heights) and `solve_seconds` is their time.
fn normal_figures(sol: &wr::Solution) -> NormalSolverOut {
    let mut n = NormalSolverOut {
        iterations: 0,
        levels: 0,
        coarse_iterations: 0,
        products: 0,
        preconditioner_products: 0,
        gap_residual: 0.0,
        complementarity_residual: 0.0,
        force_residual: 0.0,
        residual: 0.0,
        steps: sol.info.normal_solves,
        setup_seconds: 0.0,
        solve_seconds: sol.info.normal_seconds,
    };
    for p in &sol.patches {
        let i = &p.normal.info;
        n.iterations += i.iterations;
        n.levels = n.levels.max(i.levels);
        n.coarse_iterations += i.coarse_iterations;
        n.products += i.products;
        n.preconditioner_products += i.preconditioner_products;
        n.gap_residual = n.gap_residual.max(i.gap_residual);
        n.complementarity_residual = n.complementarity_residual.max(i.complementarity_residual);
        n.force_residual = n.force_residual.max(i.force_residual);
        n.residual = n.residual.max(i.residual);
        n.setup_seconds += i.setup_seconds;
    }
    n
}

/// The wheel-rail library's caches kept between the runs of one process (the points of a
/// sweep, issue 29 item 9), each under the cell size and the materials its operators were
/// made for (the library keys its operators by lattice size alone, which holds within one
/// problem only). A run takes one out and puts it back; points running at once each have
/// their own; at most 8 are kept.
static CACHES: std::sync::Mutex<Vec<(String, wr::Cache)>> = std::sync::Mutex::new(Vec::new());

/// A cache for the problem `key`: a kept one with its previous position forgotten (so a
/// run's result does not depend on the runs before it: only the operators, which depend on
/// the lattice, the cell and the materials alone, carry over), or a new one.
fn take_cache(key: &str) -> wr::Cache {
    let mut kept = CACHES.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    match kept.iter().position(|(k, _)| k == key) {
        Some(i) => {
            let mut c = kept.swap_remove(i).1;
            c.forget();
            c
        }
        None => wr::Cache::new(),
    }
}

/// Keep `cache` for the next run of the problem `key`, unless it has planned more than 64
/// operators (one per lattice size: a long sweep over many sizes starts a new one rather
/// than grow).
fn put_cache(key: String, cache: wr::Cache) {
    if cache.misses > 64 {
        return;
    }
    let mut kept = CACHES.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    if kept.len() >= 8 {
        kept.remove(0);
    }
    kept.push((key, cache));
}

/// Solve the wheel on its rail.
pub(crate) fn run(r: &WheelRailRecipe, cx: &mut Ctx<'_>) -> Result<Parts, SceneError> {
    cx.progress("wheel-rail", 0, 1);
    let pb = wr::WheelRail::new(
        r.side,
        r.track.clone(),
        r.wheelset.clone(),
        r.bodies.substrate,
        r.bodies.indenter,
        r.friction,
        r.cell,
    )
    .map_err(refusal)?;
    let motion = r.motion.unwrap_or_else(|| wr::Motion::rolling(1.0, 0.0));
    let key = format!("{:?}", (r.cell, r.bodies.substrate, r.bodies.indenter));
    let mut cache = take_cache(&key);
    let sol = pb.solve(&r.position, &motion, r.load, r.tangential, &mut cache);
    put_cache(key, cache);
    let sol = sol.map_err(refusal)?;
    cx.progress("wheel-rail", 1, 1);
    if sol.patches.is_empty() {
        return Err(solver_err("the wheel-rail solve", "no contact patch was found"));
    }
    let f = r.friction;
    let mut patches = Vec::with_capacity(sol.patches.len());
    let (mut iterations, mut products, mut residual, mut elements) = (0usize, 0, 0.0f64, 0usize);
    for p in &sol.patches {
        let coulomb = p.rolling.as_ref().filter(|_| f > 0.0).map(|s| {
            s.pressure
                .iter()
                .zip(s.qx.iter().zip(&s.qy))
                .map(|(&pk, (&qx, &qy))| (qx.hypot(qy) - f * pk) / (f * p.pmax))
                .fold(f64::NEG_INFINITY, f64::max)
        });
        let tangential = p.rolling.as_ref().map(|s| {
            iterations += s.info.iterations;
            products += s.info.products;
            residual = residual.max(s.info.residual);
            TangentialSolveOut { iterations: s.info.iterations, residual: s.info.residual }
        });
        elements += p.lattice.nx * p.lattice.ns;
        patches.push(WheelRailPatchOut {
            y_rail: p.rail_point[0],
            z_rail: p.rail_point[1],
            y_wheel: p.wheel_point[0],
            z_wheel: p.wheel_point[1],
            reference: p.reference,
            contact_angle: p.contact_angle,
            rolling_radius: p.rolling_radius,
            creepage: CreepageOut {
                longitudinal: p.creepage.longitudinal,
                lateral: p.creepage.lateral,
                spin: p.creepage.spin,
            },
            fn_: p.normal_force,
            fx: p.fx,
            fs: p.fs,
            mn: p.mn,
            pmax: p.pmax,
            area: p.area,
            stick_fraction: p.stick_fraction,
            force_on_rail: TrackForce {
                fx: p.force_on_rail[0],
                fy: p.force_on_rail[1],
                fz: p.force_on_rail[2],
            },
            contact_cells: p.contact_cells,
            lattice: PatchLatticeOut {
                nx: p.lattice.nx,
                ns: p.lattice.ns,
                hx: p.lattice.hx,
                hs: p.lattice.hs,
                origin: [p.lattice.origin.0, p.lattice.origin.1],
            },
            tangential,
            coulomb,
            maps: maps(p)?,
        });
    }
    cx.normal = Some(normal_figures(&sol));
    // The figures of the last solver that ran, each its own: the creep-force solves summed
    // over the patches (Newton steps, FFT products, the largest residual), or the normal
    // solver's (its final solves) when no creep forces were asked.
    if sol.patches.iter().any(|p| p.rolling.is_some()) {
        (cx.iterations, cx.inner_iterations, cx.residual) = (iterations, products, residual);
    } else if let Some(n) = &cx.normal {
        (cx.iterations, cx.inner_iterations, cx.residual) = (n.iterations, n.products, n.residual);
    }
    cx.elements = elements;
    cx.solve_seconds = sol.info.total_seconds;
    cx.ev.normal_contact += 1;
    if !matches!(r.tangential, wr::Tangential::None) {
        cx.ev.rolling += 1;
        cx.ev.friction += 1;
    }
    // The contact of result.json's `contact`: the half-lengths along x and across of the
    // patch carrying the largest normal force (its contact cells' extent), the largest peak
    // pressure, the sum of the normal forces and of the areas.
    let main = sol
        .patches
        .iter()
        .max_by(|a, b| a.normal_force.total_cmp(&b.normal_force))
        .ok_or_else(|| solver_err("the wheel-rail solve", "no patch"))?;
    let n = &main.normal;
    let (mut i0, mut i1, mut j0, mut j1) = (usize::MAX, 0usize, usize::MAX, 0usize);
    for j in 0..n.ny {
        for i in 0..n.nx {
            if n.contact[j * n.nx + i] {
                i0 = i0.min(i);
                i1 = i1.max(i);
                j0 = j0.min(j);
                j1 = j1.max(j);
            }
        }
    }
    let (a, b) = if i0 <= i1 {
        (0.5 * (i1 - i0 + 1) as f64 * n.hx, 0.5 * (j1 - j0 + 1) as f64 * n.hy)
    } else {
        (0.0, 0.0)
    };
    let normal_load: f64 = sol.patches.iter().map(|p| p.normal_force).sum();
    let p0 = sol.patches.iter().map(|p| p.pmax).fold(0.0, f64::max);
    let area: f64 = sol.patches.iter().map(|p| p.area).sum();
    let normal_vertical: f64 =
        sol.patches.iter().map(|p| p.normal_force * p.contact_angle.cos()).sum();
    let total =
        TrackForce { fx: sol.total_on_rail[0], fy: sol.total_on_rail[1], fz: sol.total_on_rail[2] };
    cx.notes.push(format!(
        "wheel on rail: {} patch(es); `contact` a and b are the half-lengths along x and across of the patch with the largest normal force, p0 the largest peak pressure; the patches are in `wheel_rail`",
        sol.patches.len()
    ));
    Ok(Parts {
        contact: ContactOut {
            a,
            b,
            p0,
            indentation: Some(sol.approach),
            normal_load,
            area: Some(area),
            fraction: None,
            plastic_fraction: None,
            pull_off: None,
            pull_off_reached: None,
        },
        zones: Zones { stick: vec![], slip: vec![], coordinate: "grid", grid: None },
        forces: Forces {
            normal: normal_load,
            tangential: total.fx.hypot(total.fy),
            moment: 0.0,
            rolling_moment: 0.0,
            fx: None,
            fy: None,
            mz: None,
        },
        rigid: RigidOut { tangential: None, rotation: None, per_body: None },
        surface: lattice::Lattice::empty().into_surface(None),
        field: Field::default(),
        rolling: None,
        cycle: None,
        history: None,
        load_curve: None,
        wheel_rail: Some(WheelRailOut {
            side: match r.side {
                wr::Side::Left => "left",
                wr::Side::Right => "right",
            },
            z_wheelset: sol.z_wheelset,
            approach: sol.approach,
            total_on_rail: total,
            vertical_load: match r.load {
                wr::VerticalLoad::Force(p) | wr::VerticalLoad::TotalForce(p) => Some(p),
                wr::VerticalLoad::Approach(_) => None,
            },
            vertical: match r.load {
                wr::VerticalLoad::Force(_) => Some("normal"),
                wr::VerticalLoad::TotalForce(_) => Some("total"),
                wr::VerticalLoad::Approach(_) => None,
            },
            normal_vertical,
            patches,
            profiles: {
                let (rail, wheel) = pb.profiles_at(&r.position, sol.z_wheelset);
                [rail, wheel]
            },
        }),
    })
}
