//! Stage 2 of a load path (`[load.history]`): the path solved step by step from the previous
//! state by `stickslip_traction::history` (docs/load-histories.md). It replaces the
//! tangential step: the run's state is the path's final state (its pressure, traction and
//! stick/slip map on the lattice, its loads and rigid shift), and `history` in result.json
//! carries one value per step, the loops and their energies; the lattice gains the energy
//! dissipated per area and the slip range of every cell.
//!
//! The lattice covers the largest contact along the path: for a Hertz sphere or ellipse a
//! box over the contact at the largest normal load (`solver.grid` cells across), each step's
//! pressure Hertz's at its load sampled at the cell centres and scaled so the cell forces sum
//! to the load; for given semi-axes the same shape scaled; for patches the patches' pressures
//! scaled to the load; for a surface the normal-contact solver at each load (warm-started).

use std::cell::RefCell;
use std::f64::consts::PI;

use stickslip_halfspace::hertz::{HertzEllipse, HertzSphere};
use stickslip_lattice::ContactGrid;
use stickslip_normal::{NormalLoad as TNormalLoad, NormalProblem, NormalSolution};
use stickslip_traction::history::{HistoryProblem, LoadPath, PathControl, PathCoupling};
use stickslip_traction::{ElementState, Error as TractionError, FastConfig, LoadKind, Tolerance};

use super::friction::TangentialOut;
use super::lattice::Lattice;
use super::normal::{surface_err, surface_solution, ContactSolution};
use super::outcome::{
    CouplingOut, GridZones, HistoryLoopOut, HistoryOut, RigidOut, RuizMaxOut, Zones,
};
use super::{solver_err, Ctx};
use crate::plan::recipe::{ContactNormal, ContactRecipe, HistoryRecipe};
use stickslip_scene::eng::eng;
use stickslip_scene::{ErrorKind, HistoryControl, SceneError, SurfaceBoundary};

/// Errors of the pressure model and of the history, kept apart until they are located.
enum Fail {
    Scene(SceneError),
    Traction(TractionError),
}

impl From<TractionError> for Fail {
    fn from(e: TractionError) -> Self {
        Fail::Traction(e)
    }
}

/// Relative margin within which two cells' Ruiz values count as the same peak: above the
/// solvers' tolerances (the traction and slip it is made of are converged to 1e-8 and finer,
/// so mirror cells of a symmetric contact differ by about that), far below what a Ruiz peak
/// is read to.
const RUIZ_TIE: f64 = 1e-6;

/// The semi-axes of a Hertz contact under a normal load.
type SemiAxes<'a> = Box<dyn Fn(f64) -> Result<(f64, f64), SceneError> + 'a>;

/// The normal-contact solver of a path (a surface's, or a Hertz body's on the history's box
/// between dissimilar bodies): its lattice, initial gap and operator, the last pressure (the
/// next solve's start), the last solution, and the number of solves of the path with their
/// iterations and wall time (for `solver.normal` and `solver.coupling`).
struct SurfaceSolver {
    cells: (usize, usize),
    cell: (f64, f64),
    gap: Vec<f64>,
    bodies: [stickslip_halfspace::Material; 2],
    boundary: stickslip_normal::Boundary,
    tolerance: Tolerance,
    op: stickslip_normal::NormalOperator,
    warm: RefCell<Option<Vec<f64>>>,
    last: RefCell<Option<NormalSolution>>,
    solves: std::cell::Cell<usize>,
    iterations: std::cell::Cell<usize>,
    seconds: std::cell::Cell<f64>,
}

impl SurfaceSolver {
    #[allow(clippy::too_many_arguments)]
    fn new(
        cells: (usize, usize),
        cell: (f64, f64),
        gap: Vec<f64>,
        bodies: [stickslip_halfspace::Material; 2],
        boundary: stickslip_normal::Boundary,
        tolerance: Tolerance,
    ) -> Result<Self, SceneError> {
        let problem = NormalProblem::new(cells.0, cells.1, cell, &gap, bodies, boundary)
            .map_err(surface_err)?
            .with_tolerance(tolerance);
        let op = problem.operator();
        Ok(Self {
            cells,
            cell,
            gap,
            bodies,
            boundary,
            tolerance,
            op,
            warm: RefCell::new(None),
            last: RefCell::new(None),
            solves: std::cell::Cell::new(0),
            iterations: std::cell::Cell::new(0),
            seconds: std::cell::Cell::new(0.0),
        })
    }

    /// The pressure under the normal load `p` with the traction's normal displacement `un`
    /// (row-major on the lattice) added to the initial gap, warm from the last solve.
    fn solve(&self, p: f64, un: Option<&[f64]>) -> Result<Vec<f64>, SceneError> {
        let shifted: Vec<f64>;
        let gap = match un {
            Some(u) => {
                shifted = self.gap.iter().zip(u).map(|(g, u)| g + u).collect();
                &shifted
            }
            None => &self.gap,
        };
        let problem = NormalProblem::new(
            self.cells.0,
            self.cells.1,
            self.cell,
            gap,
            self.bodies,
            self.boundary,
        )
        .map_err(surface_err)?
        .with_tolerance(self.tolerance);
        let w = self.warm.borrow().clone();
        let s = problem
            .solve_with(&self.op, TNormalLoad::Force(p), w.as_deref())
            .map_err(surface_err)?;
        if s.touches_boundary && self.boundary == stickslip_normal::Boundary::Free {
            return Err(SceneError::new(
                ErrorKind::Solver,
                format!(
                    "the contact at the normal load {} reaches the edge of the load path's lattice",
                    eng(p, "N")
                ),
            )
            .key("solver.grid")
            .hint("the lattice covers the Hertz contact at the path's largest load with a margin of an eighth; keep the loads within it, or report this scene"));
        }
        *self.warm.borrow_mut() = Some(s.pressure.clone());
        self.solves.set(self.solves.get() + 1);
        self.iterations.set(self.iterations.get() + s.info.iterations);
        self.seconds.set(self.seconds.get() + s.info.solve_seconds);
        let out = s.pressure.clone();
        *self.last.borrow_mut() = Some(s);
        Ok(out)
    }
}

/// How each step's pressure is made on the history's lattice.
enum Pressure<'a> {
    /// A Hertz ellipse (a circle when the radii are equal) whose semi-axes follow the load.
    Hertz { semi_axes: SemiAxes<'a> },
    /// A fixed shape scaled to the load (given semi-axes; patches).
    Scaled { shape: Vec<f64> },
    /// The normal-contact solver (a surface's; a Hertz body's between dissimilar bodies).
    Surface(Box<SurfaceSolver>),
}

/// The history's lattice: its grid (every cell that may touch), the result lattice it maps
/// to, and the pressure model.
struct Setup<'a> {
    grid: ContactGrid,
    lattice: Lattice,
    pressure: Pressure<'a>,
}

/// Hertz pressure of semi-axes (a, b) on `grid`'s cells, scaled so the cell forces sum to
/// `load` (as `ContactGrid::hertz_ellipse` samples it).
fn hertz_on(grid: &ContactGrid, a: f64, b: f64, load: f64) -> Result<Vec<f64>, SceneError> {
    let mut p: Vec<f64> = grid
        .x
        .iter()
        .zip(&grid.y)
        .map(|(x, y)| (1.0 - (x / a).powi(2) - (y / b).powi(2)).max(0.0).sqrt())
        .collect();
    let sum: f64 = p.iter().sum::<f64>() * grid.element_area();
    if sum <= 0.0 {
        return Err(SceneError::new(
            ErrorKind::Solver,
            format!(
                "the contact at the normal load {} (semi-axes {} x {}) holds no cell centre of the lattice",
                eng(load, "N"),
                eng(a, "m"),
                eng(b, "m")
            ),
        )
        .key("solver.grid")
        .hint("raise solver.grid, or keep the path's smallest normal load closer to its largest"));
    }
    p.iter_mut().for_each(|v| *v *= load / sum);
    Ok(p)
}

/// A box of `n` x `n` cells over [-ax, ax] x [-ay, ay], every cell an element.
fn box_grid(ax: f64, ay: f64, n: usize) -> Result<(ContactGrid, Lattice), SceneError> {
    let (hx, hy) = (2.0 * ax / n as f64, 2.0 * ay / n as f64);
    let grid =
        ContactGrid::from_mask(hx, hy, (-ax, -ay), n, n, &vec![true; n * n], &vec![0.0; n * n])
            .map_err(|e| solver_err("history lattice", e))?;
    Ok((grid, Lattice::new(-ax, -ay, hx, hy, n, n)))
}

/// The lattice and pressure model of the path; `gap` is a surface's initial gap
/// ([`stickslip_scene::Surface::initial_gap`]), empty otherwise.
fn setup<'a>(
    r: &'a ContactRecipe,
    n0: &ContactSolution,
    pmax: f64,
    gap: &'a [f64],
    tolerance: f64,
) -> Result<Setup<'a>, SceneError> {
    let n = r.grid;
    // Dissimilar bodies on a Hertz body: the normal solver on a box an eighth wider than
    // the Hertz contact at the largest load (the traction's normal displacement moves the
    // contact edge), `solver.grid` cells across the Hertz contact.
    let two_way = r.bodies.beta != 0.0;
    let radii = match &r.normal {
        ContactNormal::Sphere { radius, .. } => Some((*radius, *radius)),
        ContactNormal::Ellipse { rx, ry, .. } => Some((*rx, *ry)),
        _ => None,
    };
    if let (true, Some((rx, ry))) = (two_way, radii) {
        let (a, b) = match &r.normal {
            ContactNormal::Sphere { radius, e_star, .. } => {
                let h = HertzSphere::new(pmax, *radius, *e_star)
                    .map_err(|e| solver_err("Hertz sphere", e))?;
                (h.contact_radius(), h.contact_radius())
            }
            ContactNormal::Ellipse { rx, ry, e_star, .. } => {
                let h = HertzEllipse::new(*rx, *ry, pmax, *e_star)
                    .map_err(|e| solver_err("Hertz ellipse", e))?;
                (h.semi_axis_x(), h.semi_axis_y())
            }
            _ => unreachable!("radii only for Hertz bodies"),
        };
        let cells = n + n.div_ceil(8) * 2;
        let (hx, hy) = (2.0 * a / n as f64, 2.0 * b / n as f64);
        let (ax, ay) = (0.5 * cells as f64 * hx, 0.5 * cells as f64 * hy);
        let (grid, lattice) = box_grid(ax, ay, cells)?;
        let gap: Vec<f64> = (0..cells * cells)
            .map(|k| {
                let (x, y) = (grid.x[k], grid.y[k]);
                x * x / (2.0 * rx) + y * y / (2.0 * ry)
            })
            .collect();
        let tol = Tolerance::relative(tolerance).map_err(|e| solver_err("tolerance", e))?;
        let solver = SurfaceSolver::new(
            (cells, cells),
            (hx, hy),
            gap,
            r.bodies.pair(),
            stickslip_normal::Boundary::Free,
            tol,
        )?;
        return Ok(Setup { grid, lattice, pressure: Pressure::Surface(Box::new(solver)) });
    }
    Ok(match &r.normal {
        ContactNormal::Sphere { radius, e_star, .. } => {
            let axes = move |p: f64| {
                HertzSphere::new(p, *radius, *e_star)
                    .map(|h| (h.contact_radius(), h.contact_radius()))
                    .map_err(|e| solver_err("Hertz sphere", e))
            };
            let (a, _) = axes(pmax)?;
            let (grid, lattice) = box_grid(a, a, n)?;
            Setup { grid, lattice, pressure: Pressure::Hertz { semi_axes: Box::new(axes) } }
        }
        ContactNormal::Ellipse { rx, ry, e_star, .. } => {
            let axes = move |p: f64| {
                HertzEllipse::new(*rx, *ry, p, *e_star)
                    .map(|h| (h.semi_axis_x(), h.semi_axis_y()))
                    .map_err(|e| solver_err("Hertz ellipse", e))
            };
            let (a, b) = axes(pmax)?;
            let (grid, lattice) = box_grid(a, b, n)?;
            Setup { grid, lattice, pressure: Pressure::Hertz { semi_axes: Box::new(axes) } }
        }
        ContactNormal::EllipseGiven { a, b, .. } => {
            let (grid, lattice) = box_grid(*a, *b, n)?;
            let shape = hertz_on(&grid, *a, *b, 1.0)?;
            Setup { grid, lattice, pressure: Pressure::Scaled { shape } }
        }
        ContactNormal::Patches(_) => {
            let total = n0.grid.total_normal_force();
            let shape = n0.grid.pressure.iter().map(|p| p / total).collect();
            let mut lattice = n0.lattice.clone();
            for row in &mut lattice.stick {
                row.fill(-1);
            }
            Setup { grid: n0.grid.clone(), lattice, pressure: Pressure::Scaled { shape } }
        }
        ContactNormal::Surface { surface, tolerance, .. } => {
            let [nx, ny] = surface.cells;
            let (hx, hy) = (surface.size[0] / nx as f64, surface.size[1] / ny as f64);
            let (x0, y0) = (-0.5 * surface.size[0], -0.5 * surface.size[1]);
            let tol = Tolerance::relative(*tolerance).map_err(|e| solver_err("tolerance", e))?;
            let boundary = match surface.boundary {
                SurfaceBoundary::Free => stickslip_normal::Boundary::Free,
                SurfaceBoundary::Periodic => stickslip_normal::Boundary::Periodic,
            };
            let solver = SurfaceSolver::new(
                (nx, ny),
                (hx, hy),
                gap.to_vec(),
                r.bodies.pair(),
                boundary,
                tol,
            )?;
            let grid = ContactGrid::from_mask(
                hx,
                hy,
                (x0, y0),
                nx,
                ny,
                &vec![true; nx * ny],
                &vec![0.0; nx * ny],
            )
            .map_err(|e| solver_err("history lattice", e))?;
            Setup {
                grid,
                lattice: Lattice::new(x0, y0, hx, hy, nx, ny),
                pressure: Pressure::Surface(Box::new(solver)),
            }
        }
    })
}

impl Pressure<'_> {
    /// The pressure of every history cell under the normal load `p`, with the traction's
    /// normal displacement `un` in the gap of a normal solve (a prescribed pressure ignores
    /// it).
    fn at(&self, grid: &ContactGrid, p: f64, un: Option<&[f64]>) -> Result<Vec<f64>, SceneError> {
        match self {
            Pressure::Hertz { semi_axes } => {
                let (a, b) = semi_axes(p)?;
                hertz_on(grid, a, b, p)
            }
            Pressure::Scaled { shape } => Ok(shape.iter().map(|s| s * p).collect()),
            Pressure::Surface(sv) => sv.solve(p, un),
        }
    }
}

/// Solve the path of `h` and return the final state as the run's normal solution, lattice
/// and tangential result, with `history` for result.json.
#[allow(clippy::too_many_lines)]
pub(crate) fn run(
    r: &ContactRecipe,
    h: &HistoryRecipe,
    n0: &ContactSolution,
    cx: &mut Ctx<'_>,
) -> Result<(ContactSolution, Lattice, TangentialOut, HistoryOut), SceneError> {
    let pmax = h.normal.iter().copied().fold(0.0, f64::max);
    let gap = match &r.normal {
        ContactNormal::Surface { surface, .. } => surface.initial_gap(),
        _ => Vec::new(),
    };
    let st = setup(r, n0, pmax, &gap, h.tolerance.clamp(1e-12, 1e-1))?;
    let control = match h.control {
        HistoryControl::Force => PathControl::Force,
        HistoryControl::Shift => PathControl::Shift,
    };
    let mut path = LoadPath::new(control, h.tangential.clone(), h.normal.clone(), h.steps)
        .map_err(|e| history_err(h, e))?;
    if let Some(m) = &h.moment {
        path = path.with_moment(m.clone()).map_err(|e| history_err(h, e))?;
    }
    let config = FastConfig::new(
        Tolerance::relative(h.tolerance).map_err(|e| solver_err("tolerance", e))?,
        FastConfig::default().max_iterations(),
    )
    .map_err(|e| solver_err("fast solver configuration", e))?;
    let mut problem = HistoryProblem::new(&st.grid, r.bodies.pair(), r.friction)
        .and_then(|p| p.with_angle(h.direction))
        .map_err(|e| history_err(h, e))?
        .with_config(config);
    // A periodic surface: the tangential operator has the period of the normal one (the
    // history's grid is every cell of the period).
    if let Some(lattice) = super::grid::periodic_lattice(r) {
        problem = problem.with_periodic(lattice);
    }
    let total = path.points().len();
    cx.progress("load path", 0, total);
    // The Ruiz parameter needs the surface stress at the turning points (free boundary
    // only, exec/ruiz.rs).
    let mut ruiz = match super::grid::periodic_lattice(r) {
        None if r.friction > 0.0 => Some(super::ruiz::RuizTracker::new(
            &st.grid,
            r.bodies.substrate.poisson_ratio(),
            h.direction,
        )?),
        _ => None,
    };
    let t_path = std::time::Instant::now();
    let mut observe = |_, corner, state: &stickslip_traction::history::LoadHistory<'_>| match (
        ruiz.as_mut(),
        corner,
    ) {
        (Some(t), Some(_)) => t.corner(state.pressure(), state.traction()).map_err(Fail::Scene),
        _ => Ok(()),
    };
    // Dissimilar bodies: every step coupled through Dundurs' beta (the cross operators on
    // the history's lattice); a prescribed pressure (given semi-axes, patches) one way.
    let coupling = if r.bodies.beta != 0.0 {
        let (nx, ny) = (st.lattice.x.len(), st.lattice.y.len());
        let origin = (st.lattice.x[0] - 0.5 * st.grid.hx, st.lattice.y[0] - 0.5 * st.grid.hy);
        let periodic = super::grid::periodic_lattice(r).is_some();
        let mut c = PathCoupling::new(&st.grid, r.bodies.pair(), (nx, ny), origin, periodic)
            .and_then(|c| c.with_tolerance(h.tolerance.clamp(1e-14, 1e-1)))
            .map_err(|e| solver_err("load path coupling", e))?;
        if !matches!(st.pressure, Pressure::Surface(_)) {
            c = c.one_way();
        }
        Some(c)
    } else {
        None
    };
    let out = match &coupling {
        Some(c) => problem.run_coupled(
            &path,
            c,
            |p, un| st.pressure.at(&st.grid, p, un).map_err(Fail::Scene),
            &mut observe,
        ),
        None => problem.run_observed(
            &path,
            |p| st.pressure.at(&st.grid, p, None).map_err(Fail::Scene),
            &mut observe,
        ),
    }
    .map_err(|e| match e {
        Fail::Scene(e) => e,
        Fail::Traction(e) => history_err(h, e),
    })?;
    let ruiz_values = ruiz.as_ref().map(|t| t.parameter(&out.slip_range));
    cx.progress("load path", total, total);
    let steps = &out.steps;
    let last = *steps.last().ok_or_else(|| solver_err("load path", "no step"))?;
    let cells = st.grid.len() as u64;
    cx.ev.friction += cells * steps.len() as u64;
    cx.ev.hysteresis += steps.len() as u64;
    if h.moment.is_some() {
        cx.ev.twist += cells * steps.len() as u64;
    }
    // Added to the normal solver's time when a surface's normal solve ran before the path:
    // the whole path, the normal solves at its loads included (some run before its first
    // step, to check the corners).
    let path_seconds: f64 = steps.iter().map(|s| s.seconds).sum();
    cx.solve_seconds += t_path.elapsed().as_secs_f64();
    cx.elements = st.grid.len();
    cx.iterations = steps.iter().map(|s| s.newton_iterations).sum();
    cx.inner_iterations = steps.iter().map(|s| s.products).sum();
    cx.residual = steps.iter().map(|s| s.residual).fold(0.0, f64::max);

    // The final state on the result lattice.
    let mut lat = st.lattice.clone();
    let (nx, ny) = (lat.x.len(), lat.y.len());
    let mut dissipation = vec![vec![0.0; ny]; nx];
    let mut slip_range = vec![vec![0.0; ny]; nx];
    let mut states = Vec::new();
    for k in 0..st.grid.len() {
        let Some((i, j)) = lat.index(st.grid.x[k], st.grid.y[k]) else { continue };
        let p = out.pressure[k];
        lat.p[i][j] = p;
        (lat.qx[i][j], lat.qy[i][j]) = out.traction[k];
        lat.stick[i][j] = if p > 0.0 { i8::from(out.state[k] == ElementState::Stick) } else { -1 };
        dissipation[i][j] = out.dissipation[k];
        slip_range[i][j] = out.slip_range[k];
        if p > 0.0 {
            states.push(out.state[k]);
        }
    }
    lat.dissipation = Some(dissipation);
    lat.slip_range = Some(slip_range);
    let mut ruiz_max = None;
    if let Some(v) = &ruiz_values {
        let mut map = vec![vec![0.0; ny]; nx];
        let mut on_lattice = Vec::with_capacity(v.len());
        for (k, &f2) in v.iter().enumerate() {
            let Some((i, j)) = lat.index(st.grid.x[k], st.grid.y[k]) else { continue };
            map[i][j] = f2;
            on_lattice.push(k);
        }
        // The largest value, and the first cell (in the lattice's order) within RUIZ_TIE of
        // it: on a symmetric contact the peak sits on mirror cells whose values differ only
        // by rounding, and the cell reported must not flip between them from run to run.
        let top = on_lattice.iter().map(|&k| v[k]).fold(0.0, f64::max);
        let mut best = RuizMaxOut { value: top, x: 0.0, y: 0.0 };
        if let Some(&k) = on_lattice.iter().find(|&&k| top > 0.0 && v[k] >= top * (1.0 - RUIZ_TIE))
        {
            (best.x, best.y) = (st.grid.x[k], st.grid.y[k]);
        }
        lat.ruiz = Some(map);
        ruiz_max = Some(best);
    }

    // The final contact: Hertz's at the final load, or the surface's last normal solve.
    let pfinal = last.normal;
    let contact_grid = {
        let keep: Vec<usize> = (0..st.grid.len()).filter(|&k| out.pressure[k] > 0.0).collect();
        ContactGrid {
            hx: st.grid.hx,
            hy: st.grid.hy,
            x: keep.iter().map(|&k| st.grid.x[k]).collect(),
            y: keep.iter().map(|&k| st.grid.y[k]).collect(),
            pressure: keep.iter().map(|&k| out.pressure[k]).collect(),
            patch: keep.iter().map(|&k| st.grid.patch[k]).collect(),
        }
    };
    let pmax_final = out.pressure.iter().copied().fold(0.0, f64::max);
    let n = match (&r.normal, &st.pressure) {
        (ContactNormal::Sphere { radius, e_star, .. }, _) => {
            let hz = HertzSphere::new(pfinal, *radius, *e_star)
                .map_err(|e| solver_err("Hertz sphere", e))?;
            ContactSolution {
                ax: hz.contact_radius(),
                ay: hz.contact_radius(),
                p0: hz.max_pressure(),
                load: pfinal,
                indentation: Some(hz.approach()),
                grid: contact_grid,
                lattice: lat.clone(),
                surface: None,
            }
        }
        (ContactNormal::Ellipse { rx, ry, e_star, .. }, _) => {
            let hz = HertzEllipse::new(*rx, *ry, pfinal, *e_star)
                .map_err(|e| solver_err("Hertz ellipse", e))?;
            ContactSolution {
                ax: hz.semi_axis_x(),
                ay: hz.semi_axis_y(),
                p0: hz.max_pressure(),
                load: pfinal,
                indentation: Some(hz.approach()),
                grid: contact_grid,
                lattice: lat.clone(),
                surface: None,
            }
        }
        (ContactNormal::EllipseGiven { a, b, .. }, _) => ContactSolution {
            ax: *a,
            ay: *b,
            p0: 3.0 * pfinal / (2.0 * PI * a * b),
            load: pfinal,
            indentation: None,
            grid: contact_grid,
            lattice: lat.clone(),
            surface: None,
        },
        (ContactNormal::Patches(_), _) => ContactSolution {
            ax: n0.ax,
            ay: n0.ay,
            p0: pmax_final,
            load: pfinal,
            indentation: None,
            grid: contact_grid,
            lattice: lat.clone(),
            surface: None,
        },
        (ContactNormal::Surface { surface, tolerance, .. }, Pressure::Surface(sv)) => {
            let sol = sv
                .last
                .borrow_mut()
                .take()
                .ok_or_else(|| solver_err("load path", "no normal solve"))?;
            // The path's figures stay the run's (`solver.iterations` and the rest, and its
            // time, which holds these normal solves); `solver.normal` is the last normal
            // solve's, with the count and time of all of them, the surface's first included.
            let (iterations, inner, residual, elements, seconds, first) = (
                cx.iterations,
                cx.inner_iterations,
                cx.residual,
                cx.elements,
                cx.solve_seconds,
                cx.normal,
            );
            let mut s = surface_solution(surface, &sol, *tolerance, None, cx)?;
            (cx.iterations, cx.inner_iterations, cx.residual, cx.elements, cx.solve_seconds) =
                (iterations, inner, residual, elements, seconds);
            if let Some(n) = cx.normal.as_mut() {
                let (steps0, seconds0) = first.map_or((0, 0.0), |f| (f.steps, f.solve_seconds));
                n.steps = steps0 + sv.solves.get();
                n.solve_seconds = seconds0 + sv.seconds.get();
            }
            s.lattice = lat.clone();
            s.grid = contact_grid;
            s
        }
        (ContactNormal::Surface { .. }, _) => {
            return Err(solver_err("load path", "a surface without its normal solver"))
        }
    };

    // The moment about the final centre of pressure (the audit's), from the prescribed one
    // about the history's centre: M_cp = M_c + (c - c_p) x F.
    let moment = if h.moment.is_some() {
        let (sp, spx, spy) = out.pressure.iter().enumerate().fold((0.0, 0.0, 0.0), |a, (k, p)| {
            (a.0 + p, a.1 + p * st.grid.x[k], a.2 + p * st.grid.y[k])
        });
        let cp = if sp > 0.0 { (spx / sp, spy / sp) } else { (0.0, 0.0) };
        let area = st.grid.element_area();
        out.traction
            .iter()
            .enumerate()
            .map(|(k, q)| area * ((st.grid.x[k] - cp.0) * q.1 - (st.grid.y[k] - cp.1) * q.0))
            .sum()
    } else {
        0.0
    };
    let gz = GridZones::from_states(&states);
    let loops: Vec<HistoryLoopOut> = out
        .loops
        .iter()
        .map(|l| HistoryLoopOut {
            first_step: l.first_step,
            last_step: l.last_step,
            energy: l.energy,
            work: l.work,
            force_range: l.force_range,
            shift_range: l.shift_range,
            shift_drift: l.shift_drift,
        })
        .collect();
    if let Some(c) = &coupling {
        let normal_iterations = match &st.pressure {
            Pressure::Surface(sv) => sv.iterations.get(),
            _ => 0,
        };
        let passes: usize = steps.iter().map(|s| s.coupling_passes).sum();
        let most = steps.iter().map(|s| s.coupling_passes).max().unwrap_or(0);
        let dp = steps.iter().map(|s| s.coupling_pressure_change).fold(0.0, f64::max);
        let dq = steps.iter().map(|s| s.coupling_residual).fold(0.0, f64::max);
        cx.coupling = Some(CouplingOut {
            beta: c.beta(),
            passes,
            pressure_change: dp,
            traction_change: dq,
            residual: dp.max(dq),
            normal_iterations,
            tangential_iterations: cx.iterations,
            steps: Some(steps.len()),
            most_passes: Some(most),
        });
        cx.notes.push(if c.alternates() {
            format!(
                "load path between dissimilar bodies (Dundurs beta = {:.4}): each step coupled, alternating normal and tangential solves until the traction settles (tolerance {:.1e}): {passes} passes over {} steps (at most {most} in one), {normal_iterations} normal iterations; largest last change of pressure {dp:.2e}, of traction {dq:.2e}",
                c.beta(),
                c.tolerance(),
                steps.len()
            )
        } else {
            format!(
                "load path between dissimilar bodies (Dundurs beta = {:.4}): the pressure is prescribed (it does not respond to the traction), so only the tangential displacement of its change enters the slip; one pass per step",
                c.beta()
            )
        });
    }
    cx.notes.push(format!(
        "load path: {} steps ({} corners, {} between), {} fast solves, {} Newton steps, {} operator products, largest residual {:.2e}; the steps took {:.3} s; {} loop{}{}; energy dissipated over the path {}",
        steps.len(),
        h.tangential.len(),
        h.steps,
        steps.iter().map(|s| s.solves).sum::<usize>(),
        cx.iterations,
        cx.inner_iterations,
        cx.residual,
        path_seconds,
        loops.len(),
        if loops.len() == 1 { "" } else { "s" },
        if loops.is_empty() {
            String::new()
        } else {
            format!(
                " (energy per cycle {})",
                loops.iter().map(|l| eng(l.energy, "J")).collect::<Vec<_>>().join(", ")
            )
        },
        eng(last.dissipated, "J")
    ));
    if steps.iter().any(|s| s.regime == stickslip_traction::Regime::GrossSlip) {
        cx.notes.push(format!(
            "load path: the contact slides (gross slip) in {} of its steps",
            steps.iter().filter(|s| s.regime == stickslip_traction::Regime::GrossSlip).count()
        ));
    }
    let hist = HistoryOut {
        control: match h.control {
            HistoryControl::Force => "force",
            HistoryControl::Shift => "shift",
        },
        direction_deg: h.direction.to_degrees(),
        corners: (0..h.tangential.len()).map(|i| path.corner_step(i)).collect(),
        tangential: steps.iter().map(|s| s.tangential).collect(),
        normal: steps.iter().map(|s| s.normal).collect(),
        moment: steps.iter().map(|s| s.moment).collect(),
        shift: steps.iter().map(|s| s.shift).collect(),
        rotation: steps.iter().map(|s| s.rotation).collect(),
        stick_fraction: steps.iter().map(|s| s.stick_fraction).collect(),
        dissipated: steps.iter().map(|s| s.dissipated).collect(),
        work: steps.iter().map(|s| s.work).collect(),
        elastic_energy: steps.iter().map(|s| s.elastic_energy).collect(),
        gross_slip: steps
            .iter()
            .map(|s| s.regime == stickslip_traction::Regime::GrossSlip)
            .collect(),
        loops,
        ruiz_max,
        distance: Vec::new(),
        fx: Vec::new(),
        fy: Vec::new(),
        mz: Vec::new(),
        creepage_longitudinal: Vec::new(),
        creepage_lateral: Vec::new(),
        coupling_passes: if coupling.is_some() {
            steps.iter().map(|s| s.coupling_passes).collect()
        } else {
            Vec::new()
        },
    };
    let t = TangentialOut {
        creep: None,
        tangential: last.tangential,
        moment,
        rigid: RigidOut {
            tangential: Some(last.shift),
            rotation: h.moment.is_some().then_some(last.rotation),
            per_body: None,
        },
        zones: Zones { stick: vec![], slip: vec![], coordinate: "grid", grid: Some(gz) },
    };
    Ok((n, lat, t, hist))
}

/// A history error as a scene error: a corner beyond the capacity or a step the solver
/// cannot carry names the path's key; non-convergence names `solver.tolerance`.
fn history_err(h: &HistoryRecipe, e: TractionError) -> SceneError {
    use TractionError as E;
    let list = match h.control {
        HistoryControl::Force => "tangential",
        HistoryControl::Shift => "shift",
    };
    match e {
        E::PathCorner { corner, .. } => SceneError::new(
            ErrorKind::Impossible,
            format!(
                "the load path cannot be solved at corner {corner}{}: {e}",
                stickslip_scene::PathSource::origin(h.source.as_ref(), corner)
            ),
        )
        .key(format!("load.history.{list}[{corner}]"))
        .hint("keep the load within what friction carries at every corner (a force and a moment together are carried only below gross slip), or prescribe the shift"),
        E::HistoryStep { step, source } => {
            let corner = step / h.steps.max(1);
            let key = format!("load.history.{list}[{}]", (corner + 1).min(h.tangential.len() - 1));
            match *source {
                E::CapacityExceeded { load, .. } | E::NoStickLeft { load, .. } => SceneError::new(
                    ErrorKind::Impossible,
                    format!(
                        "step {step} of the load path (after corner {corner}): the {} is at or beyond what friction carries: {source}",
                        if load == LoadKind::Moment { "moment" } else { "load" }
                    ),
                )
                .key(key)
                .hint("reduce the load along the path below gross slip, or prescribe the shift (shift = [...]) to slide"),
                E::NotConverged { .. } => SceneError::new(
                    ErrorKind::Solver,
                    format!("step {step} of the load path (after corner {corner}): {source}"),
                )
                .key("solver.tolerance")
                .hint("raise solver.tolerance (e.g. 1e-8), or use more steps between corners"),
                other => solver_err(&format!("load path step {step}"), other),
            }
        }
        other => solver_err("load path", other),
    }
}
