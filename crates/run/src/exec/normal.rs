//! Stage 1, normal contact: the contact size, peak pressure and load, in 2D from the line
//! recipe, in 3D together with the lattice the later stages fill.

use std::f64::consts::PI;

use stickslip_graded::{GradedMaterial, RigidCylinder};
use stickslip_halfspace::hertz::{HertzEllipse, HertzLine, HertzSphere};
use stickslip_lattice::ContactGrid;
use stickslip_normal::{Boundary, NormalLoad as TNormalLoad, NormalProblem};
use stickslip_traction::Tolerance;

use super::lattice::Lattice;
use super::outcome::{LoadCurve, NormalSolverOut};
use super::{solver_err, Ctx};
use crate::plan::recipe::{ContactNormal, ContactRecipe, LineLoad, LineNormal, SurfaceLoad};
use stickslip_scene::eng::eng;
use stickslip_scene::{patch_bounds, ErrorKind, NormalSweep, Patch, SceneError, SurfaceBoundary};

/// The normal solution of a line contact.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LineContact {
    /// Half-width (m).
    pub a: f64,
    /// Peak pressure (Pa); for the punch, the pressure scale $P/(\pi a)$.
    pub p0: f64,
    /// Load per unit length (N/m).
    pub load: f64,
    /// Absolute indentation (graded only).
    pub indentation: Option<f64>,
    /// The graded material, on a graded substrate.
    pub graded: Option<GradedMaterial>,
    /// Pressure exponent: $p = p_0(1-x^2/a^2)^{(1+k)/2}$ (k = 0 for Hertz).
    pub k: f64,
    /// A flat punch: $p = p_0/\sqrt{1-x^2/a^2}$.
    pub punch: bool,
    /// Whether any friction acts (for the zones when no traction stage runs).
    pub friction_possible: bool,
}

impl LineContact {
    /// The pressure at $x$.
    pub fn pressure(&self, x: f64) -> f64 {
        let t = x / self.a;
        if t.abs() >= 1.0 {
            0.0
        } else if self.punch {
            self.p0 / ((1.0 - t) * (1.0 + t)).sqrt()
        } else {
            self.p0 * ((1.0 - t) * (1.0 + t)).powf(0.5 * (1.0 + self.k))
        }
    }
}

/// The normal contact of a line recipe.
pub(crate) fn line(
    normal: &LineNormal,
    friction: f64,
    cx: &mut Ctx<'_>,
) -> Result<LineContact, SceneError> {
    let friction_possible = friction > 0.0;
    let out = match *normal {
        LineNormal::Graded { radius, load, material } => {
            let cyl = match load {
                LineLoad::HalfWidth(a) => RigidCylinder::from_half_width(&material, radius, a),
                LineLoad::Force(p) => RigidCylinder::from_load(&material, radius, p),
            }
            .map_err(|e| solver_err("rigid cylinder (corrected eq 15)", e))?;
            let h = cyl.indentation().map_err(|e| solver_err("indentation (eq 16)", e))?;
            LineContact {
                a: cyl.half_width(),
                p0: cyl.p0(),
                load: cyl.load(),
                indentation: Some(h),
                graded: Some(material),
                k: material.k(),
                punch: false,
                friction_possible,
            }
        }
        LineNormal::Hertz { radius, load, bodies } => {
            let es = bodies.e_star;
            let h = match load {
                LineLoad::HalfWidth(a) => HertzLine::from_half_width(a, radius, es),
                LineLoad::Force(p) => HertzLine::new(p, radius, es),
            }
            .map_err(|e| solver_err("2D Hertz", e))?;
            cx.notes.push(format!(
                "2D contact: no absolute indentation exists; the approach relative to the surface point at 10 a is {}",
                eng(h.approach_relative(10.0 * h.half_width()), "m")
            ));
            LineContact {
                a: h.half_width(),
                p0: h.max_pressure(),
                load: h.load(),
                indentation: None,
                graded: None,
                k: 0.0,
                punch: false,
                friction_possible,
            }
        }
        LineNormal::Punch { half_width, force } => LineContact {
            a: half_width,
            p0: force / (PI * half_width),
            load: force,
            indentation: None,
            graded: None,
            k: 0.0,
            punch: true,
            friction_possible,
        },
    };
    cx.ev.normal_contact += 1;
    Ok(out)
}

/// The normal solution of a 3D contact, with its grid and lattice.
#[derive(Debug, Clone)]
pub(crate) struct ContactSolution {
    /// Semi-axis along x (m).
    pub ax: f64,
    /// Semi-axis along y (m).
    pub ay: f64,
    /// Peak pressure (Pa).
    pub p0: f64,
    /// Normal force (N).
    pub load: f64,
    /// Approach of distant points (Hertz), when defined.
    pub indentation: Option<f64>,
    /// The contact elements with their pressure.
    pub grid: ContactGrid,
    /// The lattice over the contact, pressure filled, every contact element marked stick.
    pub lattice: Lattice,
    /// A surface's contact area (m^2), fraction of the lattice in contact and gap map
    /// (`gap[i][j]`, m); None for closed forms and patches.
    pub surface: Option<SurfaceContact>,
}

/// The plastic part of a capped surface solution.
#[derive(Debug, Clone)]
pub(crate) struct Plastic {
    pub fraction: f64,
    pub mask: Vec<Vec<f64>>,
    pub displacement: Vec<Vec<f64>>,
}

/// What the normal solve of a surface adds.
#[derive(Debug, Clone)]
pub(crate) struct SurfaceContact {
    pub area: f64,
    pub fraction: f64,
    pub gap: Vec<Vec<f64>>,
    /// Under a hardness: the share of the contact at the hardness, the plastic mask (1 at
    /// the hardness, else 0) and the plastic displacement (m), `[i][j]`.
    pub plastic: Option<Plastic>,
    /// The load sweep's curves, when the scene asks for one.
    pub curve: Option<LoadCurve>,
    /// Under adhesion: the pull-off along the approach path.
    pub adhesion: Option<super::adhesion::PullOff>,
}

/// The normal contact of a 3D recipe, and the lattice of `r.grid` elements per side.
pub(crate) fn contact(r: &ContactRecipe, cx: &mut Ctx<'_>) -> Result<ContactSolution, SceneError> {
    let n = r.grid;
    // (semi-axes, peak pressure, load, approach) and the grid with its lattice corner and size
    let ((ax, ay, p0, load, indentation), (grid, x0, y0, nx, ny)) = match &r.normal {
        ContactNormal::Surface {
            surface,
            load,
            tolerance,
            sweep,
            hardness,
            approaches,
            adhesion,
        } => {
            let path = SurfacePath {
                sweep: *sweep,
                approaches: approaches.as_deref(),
                hardness: *hardness,
                adhesion: *adhesion,
            };
            return surface_contact(surface, *load, *tolerance, &path, r, cx);
        }
        ContactNormal::Sphere { radius, force, e_star } => {
            let h = HertzSphere::new(*force, *radius, *e_star)
                .map_err(|e| solver_err("Hertz sphere", e))?;
            let a = h.contact_radius();
            (
                (a, a, h.max_pressure(), *force, Some(h.approach())),
                (ContactGrid::hertz_circle(a, *force, n), -a, -a, n, n),
            )
        }
        ContactNormal::Ellipse { rx, ry, force, e_star } => {
            let h = HertzEllipse::new(*rx, *ry, *force, *e_star)
                .map_err(|e| solver_err("Hertz ellipse", e))?;
            let (a, b) = (h.semi_axis_x(), h.semi_axis_y());
            (
                (a, b, h.max_pressure(), *force, Some(h.approach())),
                (ContactGrid::hertz_ellipse(a, b, *force, n, n), -a, -b, n, n),
            )
        }
        ContactNormal::EllipseGiven { a, b, force } => (
            (*a, *b, 3.0 * force / (2.0 * PI * a * b), *force, None),
            (ContactGrid::hertz_ellipse(*a, *b, *force, n, n), -a, -b, n, n),
        ),
        ContactNormal::Patches(ps) => {
            let (lo, hi) = patch_bounds(ps);
            let pmax = ps.iter().map(|p| p.pressure).fold(0.0, f64::max);
            let p: f64 = ps.iter().map(Patch::force).sum();
            let h = (hi[0] - lo[0]).max(hi[1] - lo[1]) / n as f64;
            let grid = ContactGrid::from_patches(
                h,
                h,
                (lo[0], lo[1]),
                &crate::plan::patches::grid_patches(ps),
            );
            let nx = ((hi[0] - lo[0]) / h).round() as usize;
            let ny = ((hi[1] - lo[1]) / h).round() as usize;
            (
                (0.5 * (hi[0] - lo[0]), 0.5 * (hi[1] - lo[1]), pmax, p, None),
                (grid, lo[0], lo[1], nx, ny),
            )
        }
    };
    cx.ev.normal_contact += 1;
    let grid = grid.map_err(|e| solver_err("contact grid", e))?;
    let mut lat = Lattice::new(x0, y0, grid.hx, grid.hy, nx.max(1), ny.max(1));
    for kk in 0..grid.len() {
        if let Some((i, j)) = lat.index(grid.x[kk], grid.y[kk]) {
            lat.p[i][j] = grid.pressure[kk];
            lat.stick[i][j] = 1;
        }
    }
    cx.ev.normal_contact += grid.len() as u64;
    Ok(ContactSolution { ax, ay, p0, load, indentation, grid, lattice: lat, surface: None })
}

/// How a surface is loaded beyond one force or approach: a load sweep, an approach path,
/// a hardness cap, adhesion.
pub(crate) struct SurfacePath<'a> {
    pub sweep: Option<NormalSweep>,
    pub approaches: Option<&'a [f64]>,
    pub hardness: Option<f64>,
    pub adhesion: Option<stickslip_scene::AdhesionKeys>,
}

/// The normal contact of a surface: its initial gap (profile plus roughness) on the lattice,
/// solved by the normal-contact solver under force or displacement control.
fn surface_contact(
    s: &stickslip_scene::Surface,
    load: SurfaceLoad,
    tolerance: f64,
    path: &SurfacePath<'_>,
    r: &ContactRecipe,
    cx: &mut Ctx<'_>,
) -> Result<ContactSolution, SceneError> {
    let [nx, ny] = s.cells;
    let (hx, hy) = (s.size[0] / nx as f64, s.size[1] / ny as f64);
    let gap = s.initial_gap();
    let boundary = match s.boundary {
        SurfaceBoundary::Free => Boundary::Free,
        SurfaceBoundary::Periodic => Boundary::Periodic,
    };
    let tol = Tolerance::relative(tolerance).map_err(|e| solver_err("tolerance", e))?;
    let mut problem = NormalProblem::new(nx, ny, (hx, hy), &gap, r.bodies.pair(), boundary)
        .map_err(surface_err)?
        .with_tolerance(tol);
    if let Some(h) = path.hardness {
        problem = problem.with_hardness(h);
    }
    let last = match load {
        SurfaceLoad::Force(p) => TNormalLoad::Force(p),
        SurfaceLoad::Approach(d) => TNormalLoad::Approach(d),
    };
    if let Some(a) = path.adhesion {
        let SurfaceLoad::Approach(d) = load else {
            return Err(solver_err("adhesive contact", "adhesion is solved under an approach"));
        };
        let approaches = path.approaches.map_or_else(|| vec![d], <[f64]>::to_vec);
        let sol =
            super::adhesion::path(s, &problem, &approaches, a, (r.bodies.e_star, tolerance), cx)?;
        if r.tangential.is_some() && !sol.grid.pressure.iter().any(|&p| p > 0.0) {
            // Tension carries no friction: the tangential stage needs compression.
            return Err(SceneError::new(
                ErrorKind::Impossible,
                format!(
                    "the tangential load acts at the last point of the approach path, the approach {}, where the adhesive contact carries no compression ({}): friction has nothing to act on",
                    eng(approaches[approaches.len() - 1], "m"),
                    if sol.grid.pressure.is_empty() {
                        "the surfaces have let go".to_string()
                    } else {
                        format!("only the cohesive zone, which pulls with {}", eng(sol.load, "N"))
                    }
                ),
            )
            .key("load.approach")
            .hint("end the approach path pressed (a last corner of load.approach where the bodies touch), or remove the tangential load"));
        }
        return Ok(sol);
    }
    // A load sweep or an approach path: each step warm-started from the one before; the
    // last is the scene's load and goes on to the later stages.
    let steps: Vec<TNormalLoad> = match (path.sweep, path.approaches, load) {
        (_, Some(ds), _) => ds.iter().map(|&d| TNormalLoad::Approach(d)).collect(),
        (Some(sw), None, SurfaceLoad::Force(p)) => {
            sw.forces(p).into_iter().map(TNormalLoad::Force).collect()
        }
        _ => vec![last],
    };
    let sweep = path.sweep.is_some() || path.approaches.is_some();
    let op = problem.operator();
    let mut curve = sweep.then(LoadCurve::default);
    let mut warm: Option<Vec<f64>> = None;
    let mut sol = None;
    let mut seconds = 0.0;
    for (i, step) in steps.iter().enumerate() {
        cx.progress("normal contact", i, steps.len());
        let s = problem.solve_with(&op, *step, warm.as_deref()).map_err(surface_err)?;
        seconds += s.info.solve_seconds;
        if let Some(c) = curve.as_mut() {
            c.normal.push(s.force);
            c.approach.push(s.approach);
            c.area.push(s.area);
            c.fraction.push(s.fraction);
            c.p0.push(s.peak_pressure);
            c.iterations.push(s.info.iterations);
        }
        // A step without contact (an approach path above the surface) starts the next cold.
        warm = s.pressure.iter().any(|&p| p > 0.0).then(|| s.pressure.clone());
        sol = Some(s);
    }
    cx.progress("normal contact", steps.len(), steps.len());
    let Some(sol) = sol else { return Err(solver_err("normal-contact solver", "no load step")) };
    let out = surface_solution(s, &sol, tolerance, curve, cx)?;
    if let stickslip_scene::Profile::Punch { radius, edge_radius } = s.profile {
        if edge_radius == 0.0 && s.roughness.is_none() {
            sharp_punch(s, radius, &sol, r.bodies.e_star, cx);
        }
    }
    // The record of the last step, with the time and the count of all of them.
    if let Some(n) = cx.normal.as_mut() {
        cx.solve_seconds += seconds - n.solve_seconds;
        n.solve_seconds = seconds;
        n.steps = steps.len();
    }
    Ok(out)
}

/// The sharp punch against Boussinesq (`PunchOut`): the force at the area-equivalent radius
/// of the face cells, the pressure away from the edge, and a note that the peak pressure
/// is the edge singularity's.
fn sharp_punch(
    s: &stickslip_scene::Surface,
    radius: f64,
    sol: &stickslip_normal::NormalSolution,
    e_star: f64,
    cx: &mut Ctx<'_>,
) {
    let [nx, ny] = s.cells;
    let (hx, hy) = (s.size[0] / nx as f64, s.size[1] / ny as f64);
    let (x0, y0) = (-0.5 * s.size[0], -0.5 * s.size[1]);
    let centre = |k: usize| {
        let (i, j) = (k % nx, k / nx);
        (x0 + (i as f64 + 0.5) * hx, y0 + (j as f64 + 0.5) * hy)
    };
    let face: Vec<usize> = (0..nx * ny)
        .filter(|&k| {
            let (x, y) = centre(k);
            x.hypot(y) <= radius
        })
        .collect();
    let a = (face.len() as f64 * hx * hy / PI).sqrt();
    let d = sol.approach;
    let force = 2.0 * a * e_star * d;
    let mut interior = 0.0f64;
    for &k in &face {
        let (x, y) = centre(k);
        let r = x.hypot(y);
        if r <= 0.5 * a {
            let exact = e_star * d / (PI * (a * a - r * r).sqrt());
            interior = interior.max((sol.pressure[k] - exact).abs() / exact);
        }
    }
    let out = super::outcome::PunchOut {
        face_cells: face.len(),
        radius,
        equivalent_radius: a,
        cells_across: 2.0 * radius / hx,
        boussinesq_force: force,
        force_error: (sol.force - force) / force,
        interior_pressure_error: interior,
        peak_pressure_grid_dependent: true,
    };
    cx.notes.push(format!(
        "sharp-edged flat punch: the pressure is singular at the edge, p ~ 1/sqrt(a^2 - r^2) (Boussinesq), so the peak pressure {} is that of the edge cells and grows as the cells shrink: it depends on the lattice, not on the contact. Against Boussinesq at the area-equivalent radius a = {} ({} face cells, {:.0} cells across): force {:+.3e} relative, pressure within r <= a/2 {:.3e} relative (see `punch` in result.json)",
        eng(sol.peak_pressure, "Pa"),
        eng(a, "m"),
        out.face_cells,
        out.cells_across,
        out.force_error,
        out.interior_pressure_error
    ));
    cx.punch = Some(out);
}

/// The stage-1 solution of a surface from the normal solver's answer: refusal of no contact,
/// the solver note, the contact grid and the lattice.
pub(crate) fn surface_solution(
    s: &stickslip_scene::Surface,
    sol: &stickslip_normal::NormalSolution,
    tolerance: f64,
    curve: Option<LoadCurve>,
    cx: &mut Ctx<'_>,
) -> Result<ContactSolution, SceneError> {
    let [nx, ny] = s.cells;
    let (hx, hy) = (s.size[0] / nx as f64, s.size[1] / ny as f64);
    let (x0, y0) = (-0.5 * s.size[0], -0.5 * s.size[1]);
    if sol.no_contact {
        return Err(SceneError::new(
            ErrorKind::Impossible,
            format!(
                "the approach {} does not close the gap: zero load, no contact",
                eng(sol.approach, "m")
            ),
        )
        .key("load.approach")
        .hint("raise load.approach above the smallest initial gap, or give load.normal"));
    }
    cx.ev.normal_contact += (nx * ny) as u64;
    let info = &sol.info;
    cx.normal = Some(NormalSolverOut {
        iterations: info.iterations,
        levels: info.levels,
        coarse_iterations: info.coarse_iterations,
        products: info.products,
        preconditioner_products: info.preconditioner_products,
        gap_residual: info.gap_residual,
        complementarity_residual: info.complementarity_residual,
        force_residual: info.force_residual,
        residual: info.residual,
        steps: 1,
        setup_seconds: info.setup_seconds,
        solve_seconds: info.solve_seconds,
    });
    // The solver's figures until a grid solver (a later stage) gives its own.
    cx.iterations = info.iterations;
    cx.inner_iterations = info.products;
    cx.residual = info.residual;
    cx.elements = nx * ny;
    cx.solve_seconds += info.setup_seconds + info.solve_seconds;
    let start = match info.levels {
        0 => "from a cold or warm start".to_string(),
        l => format!(
            "nested start from {l} coarser lattice{} ({} iterations)",
            if l == 1 { "" } else { "s" },
            info.coarse_iterations
        ),
    };
    cx.notes.push(format!(
        "normal contact of the surface: {} x {} cells, {} in contact ({:.4} of the lattice{}); {} iterations ({} FFT products, {} preconditioner products), {}; residuals gap {:.2e}, complementarity {:.2e}, force {:.2e} (tolerance {:.1e})",
        nx,
        ny,
        sol.contact_cells,
        sol.fraction,
        if sol.touches_boundary { "; the contact reaches the lattice edge, which truncates the surface" } else { "" },
        sol.info.iterations,
        sol.info.products,
        sol.info.preconditioner_products,
        start,
        sol.info.gap_residual,
        sol.info.complementarity_residual,
        sol.info.force_residual,
        tolerance
    ));
    if let Some(h) = sol.hardness {
        let wmax = sol.plastic_displacement.iter().copied().fold(0.0, f64::max);
        cx.notes.push(format!(
            "hardness cap {} (interface.hardness): {} plastic cells, {:.4} of the contact, largest plastic displacement {}{}; later stages take the capped pressure",
            eng(h, "Pa"),
            sol.plastic_cells,
            sol.plastic_fraction,
            eng(wmax, "m"),
            match sol.info.approach_steps {
                0 => String::new(),
                k => format!("; force control by {k} approach-controlled solves (secant on the approach)"),
            }
        ));
    }
    let grid = sol.contact_grid().map_err(surface_err)?;
    let mut lat = Lattice::new(x0, y0, hx, hy, nx, ny);
    // gap[i][j] at (x[i], y[j]) from the solver's row-major j * nx + i
    let gaps: Vec<Vec<f64>> =
        (0..nx).map(|i| (0..ny).map(|j| sol.gap[j * nx + i]).collect()).collect();
    let (mut xmax, mut ymax) = (0.0f64, 0.0f64);
    for k in 0..nx * ny {
        let (i, j) = (k % nx, k / nx);
        if sol.contact[k] {
            lat.p[i][j] = sol.pressure[k];
            lat.stick[i][j] = 1;
            xmax = xmax.max(lat.x[i].abs() + 0.5 * hx);
            ymax = ymax.max(lat.y[j].abs() + 0.5 * hy);
        }
    }
    Ok(ContactSolution {
        ax: xmax,
        ay: ymax,
        p0: sol.peak_pressure,
        load: sol.force,
        indentation: Some(sol.approach),
        grid,
        lattice: lat,
        surface: Some(SurfaceContact {
            area: sol.area,
            fraction: sol.fraction,
            gap: gaps,
            curve,
            adhesion: None,
            plastic: sol.hardness.map(|_| {
                let map = |v: &dyn Fn(usize) -> f64| -> Vec<Vec<f64>> {
                    (0..nx).map(|i| (0..ny).map(|j| v(j * nx + i)).collect()).collect()
                };
                Plastic {
                    fraction: sol.plastic_fraction,
                    mask: map(&|k| f64::from(u8::from(sol.plastic[k]))),
                    displacement: map(&|k| sol.plastic_displacement[k]),
                }
            }),
        }),
    })
}

/// A normal-solver error as a scene error, by its variant.
pub(crate) fn surface_err(e: stickslip_normal::Error) -> SceneError {
    use stickslip_normal::Error as E;
    match &e {
        E::UnresolvedContact { minimum, .. } => SceneError::new(
            ErrorKind::Solver,
            format!("the contact is not resolved by the lattice: {e}"),
        )
        .key("geometry.cells")
        .hint(format!("use more cells (at least {minimum} must be in contact), or a smaller size, or a larger load")),
        E::NotConverged { .. } | E::ToleranceOutOfRange { .. } => {
            SceneError::new(ErrorKind::Solver, format!("normal-contact solver: {e}"))
                .key("solver.tolerance")
                .hint("raise solver.tolerance (e.g. 1e-8)")
        }
        _ => solver_err("normal-contact solver", e),
    }
}
