//! The cost estimate of a plan (evaluations, seconds, memory) and the refusals of grids
//! too large for the machine.

use super::refusal::issue;
use super::{Cost, Effect, EffectPlan, Issue, Technique, MAX_LP_ELEMENTS, SURFACE_POINTS};
use stickslip_scene::{ErrorKind, Geometry, Scene, Substrate};

/// Points along the surface, grid elements and the cost of `scene` with `effects`; a
/// refusal when a grid needs more memory than a run may use.
#[allow(clippy::too_many_lines)]
pub(crate) fn estimate(
    scene: &Scene,
    effects: &[EffectPlan],
) -> Result<(usize, usize, Cost), Issue> {
    use Effect as E;
    use Technique as T;
    let two_d = scene.geometry.is_2d();
    let grading = matches!(scene.substrate, Substrate::Graded { k, .. } if k > 0.0);
    let visco = match scene.substrate {
        Substrate::Viscoelastic { alpha, beta, .. } => Some(alpha != beta),
        _ => None,
    };
    let elements = if two_d { 0 } else { lattice_elements(scene) };
    let surface_points = if two_d && scene.outputs.surface { SURFACE_POINTS } else { 0 };
    let grid_elements = elements;
    let lp = effects.iter().any(|e| matches!(e.technique, Some(T::LpForce | T::LpMoment)));
    let fast = effects.iter().any(|e| matches!(e.technique, Some(T::Fast | T::LoadHistory)));
    let steady =
        effects.iter().any(|e| matches!(e.technique, Some(T::SteadyRolling | T::TransientRolling)));
    if lp && grid_elements > MAX_LP_ELEMENTS {
        return Err(issue(
            ErrorKind::OutOfRange,
            "solver.grid",
            format!("the dense LP on about {grid_elements} elements needs about {} of memory and minutes of pivoting", human_bytes(lp_memory(grid_elements))),
            format!("use a grid with at most {MAX_LP_ELEMENTS} contact elements (solver.grid about {} for a circle), or method = \"fast\"", ((MAX_LP_ELEMENTS as f64) / std::f64::consts::FRAC_PI_4).sqrt() as usize),
        ));
    }
    let cells = if two_d { 0 } else { lattice_cells(scene) };
    // Memory of the 3D lattice arrays (result, JSON and CSV text) and of the fast solver.
    let grid_memory = cells as u64 * OUTPUT_BYTES_PER_CELL
        + if fast || steady { fast_memory(cells, grid_elements) } else { 0 };
    if grid_memory > MEMORY_LIMIT_BYTES {
        let side = scene.solver.grid;
        let max_side =
            (side as f64 * (MEMORY_LIMIT_BYTES as f64 / grid_memory as f64).sqrt()) as usize;
        return Err(issue(
            ErrorKind::OutOfRange,
            "solver.grid",
            format!(
                "grid = {side} gives a lattice of {cells} cells ({grid_elements} contact elements) needing about {} of memory, more than the {} a run may use",
                human_bytes(grid_memory),
                human_bytes(MEMORY_LIMIT_BYTES)
            ),
            format!("use solver.grid <= {max_side} for this scene"),
        ));
    }
    let mut evals: u64 = 1;
    let mut secs = 1e-5;
    let mut mem: u64 = 1 << 20;
    if surface_points > 0 {
        let per = if grading {
            800
        } else if visco == Some(true) {
            600
        } else {
            4
        };
        evals += (surface_points * per) as u64;
        secs += (surface_points * per) as f64 * 2e-8;
    }
    if let Some(fg) = scene.outputs.field {
        let nz = fg.z.map_or(1, |z| z.2) as u64;
        let n = (fg.x.2 * fg.y.2) as u64 * nz;
        match effects[E::SubsurfaceField.index()].technique {
            Some(T::LatticeField) => {
                // The contact lattice (cells of 2a/grid) extended over the box, one FFT layer
                // per depth. Measured (2 cores): 8e-7 s and 90 bytes per cell and layer (Hertz,
                // grid 128, 196 x 130 cells, 100 layers: 2.0 s, 222 MB).
                let cells_along = |lo: f64, hi: f64| -> f64 {
                    match fg.scale {
                        stickslip_scene::FieldScale::HalfWidth => {
                            (hi.max(1.0) - lo.min(-1.0)) * scene.solver.grid as f64 / 2.0 + 3.0
                        }
                        stickslip_scene::FieldScale::Metres => scene.solver.grid as f64 + 3.0,
                    }
                };
                let cells = (cells_along(fg.x.0, fg.x.1) * cells_along(fg.y.0, fg.y.1)) as u64;
                evals += cells * nz;
                secs += (cells * nz) as f64 * 8e-7;
                mem += cells * nz * 90;
            }
            t => {
                // The ellipsoidal-coordinate integral: about 1,200 evaluations of a 200-term
                // integrand per point; measured (benches/subsurface_field.rs, hertz_point_field)
                // 40 us per point for the sliding sphere, 18 us for the frictionless ellipse:
                // costed as 1,600 closed-form evaluations of 25 ns.
                let per = match t {
                    Some(T::StressQuadrature) => 1200,
                    Some(T::HamiltonSlidingField | T::HertzEllipseField) => 1600,
                    _ => 6,
                };
                evals += n * per;
                secs += (n * per) as f64 * 2.5e-8;
            }
        }
        // 12 numbers per point in the result, its JSON/CSV text
        mem += n * 12 * 8 * 4;
    }
    if let Geometry::Surface(s) = &scene.geometry {
        // The normal solve (nested, preconditioned; issue 30): measured on 2 cores, residual
        // 1e-8, set-up included, 0.03 s at 256^2, 0.5 s at 1024^2, 2.4 s at 2048^2, 10 s at
        // 4096^2 (rough periodic and free Hertz alike, docs/peers.md), growing as cells^1.05
        // to 1.1; taken a third higher for a shared machine and tighter tolerances.
        let n = (s.cells[0] * s.cells[1]) as f64;
        // An approach path solves every point, warm from the one before; an adhesive solve
        // is a few contact solves over its cohesive zone (measured 1.1 to 2.4 times an
        // elastic one, docs/peers.md; taken as 3).
        let points = scene.load.approach_path.as_ref().map_or(1, |p| p.approaches().len());
        let per = if scene.interface.adhesion.is_some() { 3.0 } else { 1.0 };
        secs += points as f64 * per * 0.04 * (n / 65536.0).powf(1.1);
        // The solver's own estimate of its working memory, and the initial gap.
        let boundary = match s.boundary {
            stickslip_scene::SurfaceBoundary::Free => stickslip_normal::Boundary::Free,
            stickslip_scene::SurfaceBoundary::Periodic => stickslip_normal::Boundary::Periodic,
        };
        mem += stickslip_normal::NormalProblem::memory_bytes(s.cells[0], s.cells[1], boundary)
            + (n * 8.0) as u64;
        evals += n as u64;
    }
    if grid_elements > 0 {
        let n = grid_elements as u64;
        evals += n;
        if lp {
            evals += n * n * 4;
            secs += (n * n) as f64 * 2e-7 + (n * n * n) as f64 * 2e-9;
            mem += lp_memory(grid_elements);
        } else if effects.iter().any(|e| e.technique == Some(T::TransientRolling)) {
            // Transient rolling: one warm fast solve per element length rolled; two contact
            // lengths are about twice the lattice side in steps, each a few Newton steps of
            // about ten FFT products (an estimate, not a measurement). At prescribed
            // creepages the default is ten lengths, each step one to three solves of the
            // secant on the force (23 to 28 products a step measured, transient_creepage.rs).
            let lengths = match scene.motion {
                stickslip_scene::Motion::RollingCreepage {
                    transient: Some(stickslip_scene::Transient { creepage_control: true, .. }),
                    ..
                } => 10,
                _ => 2,
            };
            let steps = lengths * (cells as f64).sqrt().ceil() as u64;
            evals += n * 30 * steps;
            secs += (30 * steps) as f64 * 1e-7 * (4 * cells) as f64;
        } else if steady {
            // Exact steady rolling: a few Newton steps of GMRES, one padded FFT product per
            // GMRES step, from a nested start. Measured with `rolling_probe nx ny` (ellipse
            // with creepage and spin, default tolerance): 95 products at 940 elements, 260 at
            // 5,024 and 7,549, 426 at 30,176, about 100 (elements/1000)^0.45, and a fifth
            // more in the shipped wheel-rail scene (295 at 5,024, a tighter residual); on one
            // thread a product costs 2 to 4e-8 s per padded cell (0.83 ms at 80 x 80, 5.9 ms
            // at 226 x 170, on a machine at load 6), taken as 2.5e-8 s plus 2e-5 s of GMRES
            // work. The old model (300 products of 1e-7 s a cell) overestimated 3 to 7 times.
            let products = 120.0 * (n as f64 / 1000.0).powf(0.45);
            evals += n * products.ceil() as u64;
            secs += products * (2e-5 + 2.5e-8 * (4 * cells) as f64);
        } else if fast {
            // Each Newton step takes tens of CG iterations, one FFT product each; the count
            // grows slowly with the grid (measured: see fast_seconds).
            evals += n * FAST_PRODUCTS;
            secs += fast_seconds(cells);
        } else if effects[E::Twist.index()].technique == Some(T::Lubkin) {
            evals += n * 200;
            secs += n as f64 * 4e-6;
        }
    }
    if let Some(c) = scene.outputs.cycle {
        evals += 2 * c.points as u64 + 1;
    }
    if let Some(h) = &scene.load.history {
        // Each step is one warm fast solve, measured at 0.6 to 0.9 of a cold one and 46 to 62
        // products (benches/examples/history_speed.rs, 128 and 256 across); under shift
        // control a step searches the force, about 5 solves. A surface whose normal load
        // changes adds a warm normal solve per step (costed at a third of a cold one). The
        // path state is about 25 doubles per cell.
        let steps = ((h.tangential.len().max(1) - 1) * h.steps + 1) as f64;
        let solves = match h.control {
            stickslip_scene::HistoryControl::Force => steps,
            stickslip_scene::HistoryControl::Shift => 5.0 * steps,
        };
        secs += solves * 0.9 * fast_seconds(cells);
        evals += (solves as u64) * grid_elements as u64 * 60;
        mem += cells as u64 * 25 * 8;
        if let (Geometry::Surface(sf), Some(_)) = (&scene.geometry, &h.normal) {
            let n = (sf.cells[0] * sf.cells[1]) as f64;
            secs += steps * 0.34 * (n / 65536.0).powf(1.45) / 3.0;
        }
    }
    Ok((
        surface_points,
        grid_elements,
        Cost { evaluations: evals, seconds: secs, memory_bytes: mem + grid_memory },
    ))
}

/// The most memory a run may plan for: two thirds of a 24 GiB machine, leaving room for the
/// operating system and for the error of the estimate. With the fast solver this admits
/// grids up to about 5100 per side (about 12 GB at the measured rate) and refuses larger ones.
pub const MEMORY_LIMIT_BYTES: u64 = 16 << 30;

/// Result arrays per lattice cell of a 3D run: p, qx, qy and the stick flag in the result,
/// their JSON tree for the finiteness check and the pretty JSON and CSV text.
///
/// Calibration (peak resident memory of `stickslip run --out` on the Mindlin sphere with the
/// fast solver): 36 MB at grid 256, 129 MB at 512, 498 MB at 1024, i.e. 475 bytes per
/// lattice cell in all. This constant and those of [`fast_memory`] add up to about 1.4
/// times that, so the refusal errs on the safe side.
const OUTPUT_BYTES_PER_CELL: u64 = 250;

/// FFT products of a fast solve, roughly (for the evaluation count): 70 to 110 on the
/// fine lattice of the Mindlin sphere from 256^2 to 1024^2, plus the coarse levels'.
const FAST_PRODUCTS: u64 = 150;

/// Working memory of the fast solver for a lattice of `cells` cells with `elements` contact
/// elements: the padded FFT lattice has about 4 cells per lattice cell (each side at least
/// 2n - 1, rounded up to a 5-smooth size), holding three real kernel spectra and the
/// convolution scratch; the Newton and CG vectors are per element. Calibrated with
/// [`OUTPUT_BYTES_PER_CELL`] on measured peak memory.
fn fast_memory(cells: usize, elements: usize) -> u64 {
    cells as u64 * 200 + elements as u64 * 250
}

/// Seconds of a fast solve on a lattice of `cells` cells: measured on the Mindlin sphere
/// (`scenes/fast_mindlin_sphere_256.toml` at grids 256, 512 and 1024, T/(fP) = 2/3, default
/// tolerance, `solver.solve_seconds` on 2 idle cores) 0.41 s at 256^2, 2.03 s at 512^2,
/// 10.3 s at 1024^2, i.e. about $0.41\,(N/256^2)^{1.16}$ s (FFT products cost N log N;
/// with the nested start the number of Newton steps no longer grows with the grid and the
/// CG iterations grow slowly).
fn fast_seconds(cells: usize) -> f64 {
    0.41 * (cells as f64 / 65536.0).powf(1.16)
}

/// Lattice cells of a 3D scene: `grid` x `grid` over the bounding box of a circle or
/// ellipse; for patches, cells of side (largest extent)/`grid` over their bounding box.
pub(crate) fn lattice_cells(scene: &Scene) -> usize {
    let n = scene.solver.grid;
    match &scene.geometry {
        Geometry::Patches(ps) => {
            let (lo, hi) = stickslip_scene::patch_bounds(ps);
            let h = (hi[0] - lo[0]).max(hi[1] - lo[1]) / n as f64;
            let nx = ((hi[0] - lo[0]) / h).round().max(1.0) as usize;
            let ny = ((hi[1] - lo[1]) / h).round().max(1.0) as usize;
            nx * ny
        }
        Geometry::Surface(s) => s.cells[0] * s.cells[1],
        _ => n * n,
    }
}

fn lp_memory(n: usize) -> u64 {
    // two projected n x n matrices plus the tableau (about 2n x 3n)
    (8 * n * n * 8) as u64
}

/// Elements of the lattice a 3D scene is solved or sampled on.
pub(crate) fn lattice_elements(scene: &Scene) -> usize {
    let n = scene.solver.grid;
    match &scene.geometry {
        // elements whose centres lie inside the circle / ellipse of the bounding box
        Geometry::Sphere { .. } | Geometry::Ellipsoid(_) => {
            (std::f64::consts::FRAC_PI_4 * (n * n) as f64).round() as usize
        }
        Geometry::Patches(ps) => {
            let (lo, hi) = stickslip_scene::patch_bounds(ps);
            let h = (hi[0] - lo[0]).max(hi[1] - lo[1]) / n as f64;
            let area: f64 = ps.iter().map(|p| p.shape.area()).sum();
            (area / (h * h)).round() as usize
        }
        // The contact is not known before the normal solve: at most the lattice.
        Geometry::Surface(s) => s.cells[0] * s.cells[1],
        _ => 0,
    }
}

/// A duration for people: "under a millisecond", "250 ms", "12.5 s".
pub fn human_seconds(s: f64) -> String {
    if s < 1e-3 {
        "under a millisecond".to_string()
    } else if s < 1.0 {
        format!("{:.0} ms", s * 1e3)
    } else {
        format!("{s:.1} s")
    }
}

/// An amount of memory for people, in decimal units: "512 kB", "30 MB", "1.5 GB".
pub fn human_bytes(b: u64) -> String {
    let b = b as f64;
    if b < 1e6 {
        format!("{:.0} kB", b / 1e3)
    } else if b < 1e9 {
        format!("{:.0} MB", b / 1e6)
    } else {
        format!("{:.1} GB", b / 1e9)
    }
}
