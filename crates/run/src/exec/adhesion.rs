//! Stage 1 for an adhesive surface (`interface.adhesion`, Maugis–Dugdale): every point of
//! the approach path solved from the one before (so the contact stays on its branch and
//! jumps in and out where the branch ends), the load curve with the force (negative when
//! the bodies pull) and the contact area, the pull-off, and the last point's state for
//! result.json and the arrays.

use std::f64::consts::PI;

use stickslip_halfspace::adhesion::MaugisSphere;
use stickslip_lattice::ContactGrid;
use stickslip_normal::{Adhesion, AdhesiveSolution, NormalProblem};
use stickslip_scene::eng::eng;
use stickslip_scene::{AdhesionKeys, ErrorKind, Profile, SceneError, Surface};

use super::lattice::Lattice;
use super::normal::{surface_err, ContactSolution, SurfaceContact};
use super::outcome::{LoadCurve, NormalSolverOut};
use super::{solver_err, Ctx};

/// The pull-off of an approach path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PullOff {
    /// The most tensile force along the path (N).
    pub pull_off: f64,
    /// Whether the path passed it: a later point, further retracted, has no contact.
    pub reached: bool,
    /// The approach at which it was found (m).
    pub approach: f64,
    /// Its point on the path (0-based).
    pub point: usize,
}

impl PullOff {
    /// The pull-off of a curve of forces, approaches and contact cells per point: the most
    /// tensile force, passed when a later point at a smaller approach has lost the contact.
    pub fn of(force: &[f64], approach: &[f64], contact_cells: &[usize]) -> Self {
        let mut k = 0;
        for (i, &f) in force.iter().enumerate() {
            if f < force[k] {
                k = i;
            }
        }
        let reached = force[k] < 0.0
            && (k + 1..force.len()).any(|j| contact_cells[j] == 0 && approach[j] < approach[k]);
        PullOff { pull_off: force[k], reached, approach: approach[k], point: k }
    }
}

/// The adhesive contact of `s` along `approaches` (m), each point warm from the one before
/// (E* and the solver's relative tolerance for the notes).
pub(crate) fn path(
    s: &Surface,
    problem: &NormalProblem<'_>,
    approaches: &[f64],
    keys: AdhesionKeys,
    (e_star, tolerance): (f64, f64),
    cx: &mut Ctx<'_>,
) -> Result<ContactSolution, SceneError> {
    let adhesion = Adhesion::new(keys.work, keys.range)
        .map_err(|e| solver_err("adhesion", e).key("interface.adhesion"))?;
    let [nx, ny] = s.cells;
    let (hx, hy) = (s.size[0] / nx as f64, s.size[1] / ny as f64);
    let op = problem.operator();
    let mut curve = LoadCurve { zone_area: Some(Vec::new()), ..LoadCurve::default() };
    let mut cells = Vec::with_capacity(approaches.len());
    let mut prev: Option<AdhesiveSolution> = None;
    let (mut seconds, mut updates, mut products, mut iterations) = (0.0, 0, 0, 0);
    let (mut residual, mut zone_residual, mut pre) = (0.0f64, 0.0f64, 0);
    let mut edge: Option<(f64, usize)> = None;
    let n = approaches.len();
    for (i, &d) in approaches.iter().enumerate() {
        cx.progress("adhesive contact", i, n);
        let sol = problem
            .solve_adhesive(
                &op,
                adhesion,
                d,
                prev.as_ref(),
                stickslip_normal::solver::DEFAULT_MAX_ZONE_UPDATES,
            )
            .map_err(|e| adhesive_err(e, d))?;
        cx.ev.normal_contact += (nx * ny * sol.zone_updates) as u64;
        seconds += sol.normal.info.solve_seconds;
        updates += sol.zone_updates;
        products += sol.normal.info.products;
        pre += sol.normal.info.preconditioner_products;
        iterations += sol.normal.info.iterations;
        residual = residual.max(sol.normal.info.residual);
        zone_residual = zone_residual.max(sol.zone_residual);
        curve.normal.push(sol.normal.force);
        curve.approach.push(d);
        curve.area.push(sol.normal.area);
        curve.fraction.push(sol.normal.fraction);
        curve.p0.push(sol.normal.peak_pressure);
        curve.iterations.push(sol.normal.info.iterations);
        if let Some(z) = curve.zone_area.as_mut() {
            // the cells' covered shares (the zone's edge runs through cells)
            z.push(sol.zone_share.iter().sum::<f64>() * hx * hy);
        }
        cells.push(sol.normal.contact_cells);
        if sol.normal.touches_boundary {
            edge.get_or_insert((d, 0)).1 += 1;
        }
        prev = Some(sol);
    }
    cx.progress("adhesive contact", n, n);
    let Some(last) = prev else { return Err(solver_err("adhesive contact", "no approach")) };
    let pull = PullOff::of(&curve.normal, &curve.approach, &cells);
    notes(s, &last, &curve, pull, (updates, products, e_star, zone_residual, tolerance), cx);
    if let Some((d, count)) = edge {
        cx.notes.push(format!(
            "the contact reaches the edge of the free lattice at {count} of {n} points (the first at the approach {}): the lattice truncates the surface there, and the forces are those of the truncated body (a larger geometry.size)",
            eng(d, "m")
        ));
    }
    // The path's record: every point's iterations and products summed, the largest
    // residual of any point (each point of the curve is a certified solve).
    let info = &last.normal.info;
    cx.normal = Some(NormalSolverOut {
        iterations,
        levels: info.levels,
        coarse_iterations: info.coarse_iterations,
        products,
        preconditioner_products: pre,
        gap_residual: info.gap_residual,
        complementarity_residual: info.complementarity_residual,
        force_residual: info.force_residual,
        residual,
        steps: n,
        setup_seconds: info.setup_seconds,
        solve_seconds: seconds,
    });
    cx.iterations = iterations;
    cx.inner_iterations = products;
    cx.residual = residual;
    cx.elements = nx * ny;
    cx.solve_seconds += info.setup_seconds + seconds;
    state(s, &last, curve, pull)
}

/// The last point of the path as the stage-1 solution: the total pressure on the lattice
/// (negative where the adhesion pulls), the stick flag on the cells that carry compression
/// (tension carries no friction), and the contact grid of those cells.
fn state(
    s: &Surface,
    sol: &AdhesiveSolution,
    curve: LoadCurve,
    pull: PullOff,
) -> Result<ContactSolution, SceneError> {
    let [nx, ny] = s.cells;
    let (hx, hy) = (s.size[0] / nx as f64, s.size[1] / ny as f64);
    let (x0, y0) = (-0.5 * s.size[0], -0.5 * s.size[1]);
    let n = &sol.normal;
    let grid = if n.contact_cells > 0 {
        n.contact_grid().map_err(surface_err)?
    } else {
        ContactGrid { hx, hy, x: vec![], y: vec![], pressure: vec![], patch: vec![] }
    };
    let mut lat = Lattice::new(x0, y0, hx, hy, nx, ny);
    let (mut xmax, mut ymax) = (0.0f64, 0.0f64);
    for k in 0..nx * ny {
        let (i, j) = (k % nx, k / nx);
        lat.p[i][j] = n.pressure[k];
        if n.contact[k] {
            xmax = xmax.max(lat.x[i].abs() + 0.5 * hx);
            ymax = ymax.max(lat.y[j].abs() + 0.5 * hy);
            if n.pressure[k] > 0.0 {
                lat.stick[i][j] = 1;
            }
        }
    }
    let gaps: Vec<Vec<f64>> =
        (0..nx).map(|i| (0..ny).map(|j| n.gap[j * nx + i]).collect()).collect();
    Ok(ContactSolution {
        ax: xmax,
        ay: ymax,
        p0: n.peak_pressure,
        load: n.force,
        indentation: Some(n.approach),
        grid,
        lattice: lat,
        surface: Some(SurfaceContact {
            area: n.area,
            fraction: n.fraction,
            gap: gaps,
            plastic: None,
            curve: Some(curve),
            adhesion: Some(pull),
        }),
    })
}

/// The notes of an adhesive path (`counts`: zone updates, FFT products, E*): the interface
/// and its regime, the solver's work, the
/// pull-off (or why it was not reached) and how many cells resolve the cohesive zone there.
fn notes(
    s: &Surface,
    last: &AdhesiveSolution,
    curve: &LoadCurve,
    pull: PullOff,
    (updates, products, e_star, zone_residual, tolerance): (usize, usize, f64, f64, f64),
    cx: &mut Ctx<'_>,
) {
    let a = last.adhesion;
    let [nx, ny] = s.cells;
    let h = (s.size[0] / nx as f64).max(s.size[1] / ny as f64);
    let mut regime = String::new();
    if let Profile::Sphere { radius } = s.profile {
        if let Ok(m) = MaugisSphere::new(radius, a.work(), a.range(), e_star) {
            regime = format!(
                "; sphere R = {}: Maugis parameter lambda = {:.3} (JKR pull-off 1.5 pi R w = {}, DMT 2 pi R w = {})",
                eng(radius, "m"),
                m.lambda(),
                eng(-m.jkr_pull_off(), "N"),
                eng(-m.dmt_pull_off(), "N"),
            );
        }
    }
    cx.notes.push(format!(
        "adhesion (Maugis-Dugdale, interface.adhesion): work {}, range {}, attraction w/h0 = {} wherever the gap is below the range (a cell pulls by the share of it under the range){regime}; {} points of the approach path, each from the one before: {updates} contact solves over their cohesive zones, {products} FFT products, the largest last change of a cell's share {zone_residual:.1e} (stop at {:.1e}); last point: {} contact cells, {} cells in the cohesive zone",
        eng(a.work(), "J/m^2"),
        eng(a.range(), "m"),
        eng(a.stress(), "Pa"),
        curve.normal.len(),
        stickslip_normal::solver::zone_tolerance(tolerance),
        last.normal.contact_cells,
        last.zone_cells,
    ));
    let ring = curve.zone_area.as_ref().map_or(0.0, |z| {
        // The width of the ring of cohesion around the contact at the pull-off, in cells.
        let (ac, az) = (curve.area[pull.point], z[pull.point]);
        ((az / PI).sqrt() - (ac / PI).sqrt()) / h
    });
    if pull.reached {
        cx.notes.push(format!(
            "pull-off {} at the approach {} (point {} of {}); the contact has let go at a later point{}",
            eng(pull.pull_off, "N"),
            eng(pull.approach, "m"),
            pull.point + 1,
            curve.normal.len(),
            if ring > 0.0 && ring < 4.0 {
                format!(": there the cohesive zone is about {ring:.1} cells wide, too few to resolve it, so the lattice's pull-off errs (finer geometry.cells or a smaller geometry.size)")
            } else {
                String::new()
            }
        ));
    } else {
        cx.notes.push(format!(
            "pull-off not reached: the most tensile force along the path is {} at the approach {} (point {} of {}), but no later point, further retracted, has let go of the contact; contact.pull_off is that force, not the pull-off (retract further: a lower last corner of load.approach)",
            eng(pull.pull_off, "N"),
            eng(pull.approach, "m"),
            pull.point + 1,
            curve.normal.len()
        ));
    }
}

/// A solver error of an adhesive point as a scene error.
fn adhesive_err(e: stickslip_normal::Error, approach: f64) -> SceneError {
    match e {
        stickslip_normal::Error::NotConverged { .. } => SceneError::new(
            ErrorKind::Solver,
            format!("adhesive contact at the approach {}: {e}", eng(approach, "m")),
        )
        .key("load.approach")
        .hint("smaller steps along the path (more steps in load.approach), or a longer interface.adhesion.range"),
        e => surface_err(e),
    }
}
