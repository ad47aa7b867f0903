//! The robustness sweep of the fast partial-slip solver (issue 20, item 2): the cases and
//! their independent checks, shared by the CI suite `tests/stability_fast.rs` (16 to 256
//! cells across) and the example `fast_large` (512 and 1024 across, run once outside CI).
//!
//! Every case solves, then checks what does not come from the solver: the residual against
//! the request, Coulomb admissibility cell by cell (|q_k| <= f p_k up to the bound the
//! converged residual implies), equilibrium summed here from the element tractions, and,
//! where a closed form is exact for the problem posed, Mindlin (force alone, FORMULAS.md E)
//! or Lubkin (moment alone, FORMULAS.md G): stick radius, rigid shift or rotation, traction.

use std::f64::consts::PI;
use std::time::Instant;
use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
use stickslip_traction::Load;
use stickslip_traction::{closed::Lubkin, closed::Mindlin};
use stickslip_traction::{
    fast::FastConfig, fast::FastProblem, fast::FastSolution, fast::TractionDirections,
};

/// Tolerances of the sweep, each with its reason. `h` is the cell width, `a` the contact
/// radius.
pub mod tol {
    /// The requested relative residual (the solver's default, `Tolerance::default`).
    pub const RESIDUAL: f64 = 1e-10;
    /// Stick radius (area-equivalent radius of the stick cells) against the closed form, in
    /// cell widths: the stick/slip boundary is resolved to a cell. Measured <= 0.36.
    pub const STICK_CELLS: f64 = 1.0;
    /// Rigid shift (Mindlin) or rotation (Lubkin), relative, as `C (h/a)^(3/2)`: the closed
    /// forms' tractions have square-root edges at the contact and stick radii, which limit
    /// the cell-centred discretisation to order 3/2. Measured C <= 0.3 (shift) and <= 0.9
    /// (rotation) over the sweep.
    pub const RIGID: f64 = 1.0;
    /// RMS traction error over the cells relative to f p0 (p0 = 3P/(2 pi a^2)), as
    /// `C h/a`: an O(sqrt(h/a)) error on the band of O(h/a) of the cells at the edges.
    /// Measured C <= 0.23.
    pub const TRACTION_RMS: f64 = 0.5;
    /// Largest traction error of one cell relative to f p0, as `C sqrt(h/a)` (the square
    /// root edge inside one cell). Measured C <= 0.53.
    pub const TRACTION_MAX: f64 = 1.0;
    /// Rounding of the resultants, relative to the sum of the magnitudes of their terms:
    /// compensated (Neumaier) summation errs by at most 2 eps of it, plus the rounding of
    /// each term (products of three numbers).
    pub const SUM_EPS: f64 = 8.0 * f64::EPSILON;
}

/// Normal load; seed 002 Example 1 proportions (FORMULAS.md E): P = 2160, f = 0.1, E = 30e6.
pub const P: f64 = 2160.0;
/// Friction coefficient.
pub const F: f64 = 0.1;
/// The load fractions of the sweep (of f P, of the full-slip moment).
pub const RATIOS: [f64; 5] = [0.05, 0.5, 0.9, 0.99, 0.999];

/// The bodies: two of this material (E = 30e6, Poisson ratio `nu`).
#[must_use]
pub fn body(nu: f64) -> Material {
    Material::new(30e6, nu).unwrap()
}

/// Hertz radius of a unit sphere on a flat of the same material, a = (3 P R / (4 E*))^(1/3).
pub fn hertz_radius(m: &Material) -> f64 {
    (3.0 * P * (2.0 * m.normal_compliance()) / 4.0).cbrt()
}

/// A Hertz circle of `n` cells across and its contact radius.
pub fn circle(n: usize, m: &Material) -> (ContactGrid, f64) {
    let a = hertz_radius(m);
    (ContactGrid::hertz_circle(a, P, n).unwrap(), a)
}

/// Area-equivalent radius of the stick cells.
pub fn stick_radius(g: &ContactGrid, s: &FastSolution) -> f64 {
    (s.stick_count() as f64 * g.element_area() / PI).sqrt()
}

/// A failed check, or the case's summary line.
pub type Outcome = Result<String, String>;

/// Solve, then check the residual, admissibility and equilibrium against the load.
pub fn solve_checked(
    g: &ContactGrid,
    m: Material,
    load: Load,
    dirs: TractionDirections,
) -> Result<(FastSolution, String), String> {
    let config = FastConfig::new(
        stickslip_quad::Tolerance::relative(tol::RESIDUAL).map_err(|e| e.to_string())?,
        100,
    )
    .map_err(|e| e.to_string())?;
    let t0 = Instant::now();
    let s = FastProblem::new(g, [m, m], F, load)
        .and_then(|p| p.with_directions(dirs))
        .map(|p| p.with_config(config))
        .and_then(|p| p.solve())
        .map_err(|e| format!("failed mid-solve: {e}"))?;
    let secs = t0.elapsed().as_secs_f64();
    if !(s.info.residual <= tol::RESIDUAL && s.info.load_residual <= tol::RESIDUAL) {
        return Err(format!(
            "residual {:.2e} / load residual {:.2e} above {:.0e}",
            s.info.residual,
            s.info.load_residual,
            tol::RESIDUAL
        ));
    }
    // Admissibility: the natural residual bounds every element's distance from its disc,
    // dist(q_k, D_k) <= |r_k| <= ||r|| <= eps ||q||.
    let qnorm = s.traction.iter().map(|q| q.0 * q.0 + q.1 * q.1).sum::<f64>().sqrt();
    let bound = tol::RESIDUAL * qnorm;
    let (mut worst, mut at) = (f64::NEG_INFINITY, 0);
    for (k, q) in s.traction.iter().enumerate() {
        let excess = q.0.hypot(q.1) - F * g.pressure[k];
        if excess > worst {
            (worst, at) = (excess, k);
        }
    }
    if worst > bound {
        return Err(format!(
            "cell {at} at ({:.3e}, {:.3e}) exceeds its Coulomb disc by {worst:.3e} (bound {bound:.3e})",
            g.x[at], g.y[at]
        ));
    }
    // Equilibrium, summed here (compensated sums, so rounding stays at a few eps of the
    // sum of magnitudes); the moment about the force centroid (the load's centre). Force
    // and moment are held to the requested tolerance each, on the scales |T| + |M|/r and
    // |M| + |T| r with r the largest lever arm.
    let area = g.element_area();
    let c = g.force_centroid();
    let (mut rx, mut ry, mut mz) = (Sum::default(), Sum::default(), Sum::default());
    let (mut sf, mut sm, mut r) = (0.0, 0.0, 0.0f64);
    for (k, q) in s.traction.iter().enumerate() {
        let (dx, dy) = (g.x[k] - c.0, g.y[k] - c.1);
        rx.add(area * q.0);
        ry.add(area * q.1);
        mz.add(area * (dx * q.1 - dy * q.0));
        sf += area * q.0.hypot(q.1);
        sm += area * dx.hypot(dy) * q.0.hypot(q.1);
        r = r.max(dx.hypot(dy));
    }
    let (tx, ty) = load.force_components();
    let mw = load.moment_value().unwrap_or(0.0);
    let (t, m) = (tx.hypot(ty), mw.abs());
    let ferr = (rx.value() - tx).hypot(ry.value() - ty);
    let fbound = tol::RESIDUAL * (t + m / r) + tol::SUM_EPS * sf;
    if ferr > fbound {
        return Err(format!("resultant force off by {ferr:.3e} (bound {fbound:.3e})"));
    }
    // Without a prescribed moment the rotation is held at zero and the moment is a reaction.
    if load.moment_value().is_some() {
        let merr = (mz.value() - mw).abs();
        let mbound = tol::RESIDUAL * (m + t * r) + tol::SUM_EPS * sm;
        if merr > mbound {
            return Err(format!("resultant moment off by {merr:.3e} (bound {mbound:.3e})"));
        }
    }
    let line = format!(
        "{} Newton, {} CG, residual {:.1e}, admissibility {:+.1e} f p, {:.2} s",
        s.info.iterations,
        s.info.cg_iterations,
        s.info.residual,
        worst / (F * g.pressure.iter().copied().fold(0.0, f64::max)),
        secs
    );
    Ok((s, line))
}

/// Check an error against its bound, naming it.
pub fn within(what: &str, err: f64, bound: f64) -> Result<(), String> {
    if err <= bound {
        Ok(())
    } else {
        Err(format!("{what} error {err:.3e} above {bound:.3e}"))
    }
}

/// A force alone at `ratio` of f P: admissibility and equilibrium, and Mindlin's solution
/// when it is exact for the problem posed (`exact`).
pub fn force_case(n: usize, nu: f64, ratio: f64, dirs: TractionDirections, exact: bool) -> Outcome {
    let m = body(nu);
    let (g, a) = circle(n, &m);
    let t = ratio * F * g.total_normal_force();
    let (s, line) = solve_checked(&g, m, Load::polar(t, 0.0).unwrap(), dirs)?;
    let mi = Mindlin::new(a, P, F, t).map_err(|e| e.to_string())?;
    let (h, q0) = (g.hx, 3.0 * F * P / (2.0 * PI * a * a));
    let stick = (stick_radius(&g, &s) - mi.stick_radius()) / h;
    let shift = s.shift.0 / mi.compliance_relative(&m, &m) - 1.0;
    let (mut emax, mut e2) = (0.0f64, 0.0);
    for (k, q) in s.traction.iter().enumerate() {
        let e = (q.0 - mi.traction(g.x[k].hypot(g.y[k]))).hypot(q.1) / q0;
        emax = emax.max(e);
        e2 += e * e;
    }
    let erms = (e2 / g.len() as f64).sqrt();
    let summary = format!(
        "{line}; vs Mindlin: stick radius {stick:+.2} cells, shift {shift:+.1e}, traction rms {erms:.1e} max {emax:.1e}"
    );
    if exact {
        let ha = h / a;
        within("stick radius (cells)", stick.abs(), tol::STICK_CELLS)?;
        within("Mindlin shift", shift.abs(), tol::RIGID * ha.powf(1.5))?;
        within("traction rms", erms, tol::TRACTION_RMS * ha)?;
        within("traction max", emax, tol::TRACTION_MAX * ha.sqrt())?;
        Ok(summary)
    } else {
        Ok(format!("{summary} (not exact at nu = {nu}: printed only)"))
    }
}

/// A moment alone at `ratio` of the grid's full-slip moment against Lubkin at the same
/// fraction of his.
pub fn moment_case(n: usize, ratio: f64) -> Outcome {
    let m = body(0.3);
    let (g, a) = circle(n, &m);
    let cap = g.spin_capacity(F);
    let load = Load::moment(ratio * cap, None).unwrap();
    let (s, line) = solve_checked(&g, m, load, TractionDirections::Free)?;
    let l = Lubkin::from_moment(a, P, F, ratio * Lubkin::gross_slip_moment_of(a, P, F))
        .map_err(|e| e.to_string())?;
    let (h, q0) = (g.hx, 3.0 * F * P / (2.0 * PI * a * a));
    let stick = (stick_radius(&g, &s) - l.stick_radius()) / h;
    let rot = s.rotation / l.rotation_relative(&m, &m) - 1.0;
    let (mut emax, mut e2) = (0.0f64, 0.0);
    for (k, q) in s.traction.iter().enumerate() {
        let (x, y) = (g.x[k] - s.centre.0, g.y[k] - s.centre.1);
        let r = x.hypot(y);
        let (tau, rad) = ((x * q.1 - y * q.0) / r, (x * q.0 + y * q.1) / r);
        let want = l.traction(r).map_err(|e| e.to_string())?;
        let e = (tau - want).hypot(rad) / q0;
        emax = emax.max(e);
        e2 += e * e;
    }
    let erms = (e2 / g.len() as f64).sqrt();
    let ha = h / a;
    within("stick radius (cells)", stick.abs(), tol::STICK_CELLS)?;
    within("Lubkin rotation", rot.abs(), tol::RIGID * ha.powf(1.5))?;
    within("traction rms", erms, tol::TRACTION_RMS * ha)?;
    within("traction max", emax, tol::TRACTION_MAX * ha.sqrt())?;
    Ok(format!(
        "{line}; vs Lubkin: stick radius {stick:+.2} cells, rotation {rot:+.1e}, traction rms {erms:.1e} max {emax:.1e}"
    ))
}

/// A force along x and a moment, their mix `mix` of the two pure capacities, scaled to
/// `s` of the limit surface.
pub fn combined_case(n: usize, mix: f64, s: f64) -> Outcome {
    let m = body(0.3);
    let (g, _) = circle(n, &m);
    let (t, mo) = ((1.0 - mix) * F * g.total_normal_force(), mix * g.spin_capacity(F));
    let lam = g.load_capacity_factor(F, (t, 0.0), mo);
    let load = Load::polar(s * lam * t, 0.0).unwrap().with_moment(s * lam * mo, None).unwrap();
    let (sol, line) = solve_checked(&g, m, load, TractionDirections::Free)?;
    Ok(format!("{line}; limit factor {lam:.4}, {} stick cells", sol.stick_count()))
}

/// Neumaier's compensated sum.
#[derive(Default)]
struct Sum {
    s: f64,
    c: f64,
}

impl Sum {
    fn add(&mut self, v: f64) {
        let t = self.s + v;
        if self.s.abs() >= v.abs() {
            self.c += (self.s - t) + v;
        } else {
            self.c += (v - t) + self.s;
        }
        self.s = t;
    }

    fn value(&self) -> f64 {
        self.s + self.c
    }
}
