//! Numbers of the chapter "The fast solver" (`stickslip_traction::fast`; FORMULAS.md E, F):
//! the FFT product against the dense influence matrix, the Cattaneo–Mindlin sphere on
//! $64^2$ and $128^2$ lattices with the Newton convergence history, agreement with the
//! modified LP when the LP's one-direction assumption is imposed, and what that assumption
//! changes.
//!
//! Sizes are chosen so that the whole page takes well under a second of solves; the
//! $256^2$ and $512^2$ cases of issue 6 are in the traction crate's tests and in the
//! accuracy report.

/// Scale for [`resid`] of the fast solver's own final residuals: bounds at 1e-11, ten times
/// below the default tolerance 1e-10 (noise of an inexact-CG iteration, not rounding).
const SOLVER_SCALE: f64 = 100.0;
/// Scale for [`resid`] of optimality defects recomputed from a converged solve: bounds at
/// 1e-12 (they inherit the solver's stopping residual, a little below it).
const OPTIMALITY_SCALE: f64 = 10.0;

use crate::fmt::{err, num, pct, resid, sig, Table};
use crate::mindlin::{example1, example1_inputs};
use crate::{check, tol, Context, Error};
use std::f64::consts::PI;
use stickslip_halfspace::Material;
use stickslip_lattice::TensorConvolution;
use stickslip_lattice::{influence::tensor_matrix, influence::Compliance};
use stickslip_lattice::{ContactGrid, InfluenceModel};
use stickslip_traction::closed::Mindlin;
use stickslip_traction::{
    ElementState, FastConfig, FastProblem, FastSolution, Load, TractionDirections, TractionProblem,
};

const PAGE: &str = "fast.md";

/// The page.
///
/// # Errors
/// A failed library call or check.
pub fn page() -> Result<String, Error> {
    let mut out = String::new();
    operator(&mut out)?;
    let sphere = mindlin(&mut out)?;
    history(&mut out)?;
    versus_lp(&mut out)?;
    one_direction(&mut out, &sphere)?;
    Ok(out)
}

/// Deterministic numbers in $[-1, 1)$: a 64-bit linear congruential generator (Knuth's
/// MMIX constants), so that the page needs no random-number crate and never changes.
fn lcg(state: &mut u64) -> f64 {
    *state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
    ((*state >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
}

/// The FFT convolution against the dense matrix of the same kernel entries (the naive
/// $O(N^2)$ reference kept beside the fast product).
fn operator(out: &mut String) -> Result<(), Error> {
    let (s, a, _, _) = example1()?;
    let (_, _, p, _, _) = example1_inputs()?;
    // A soft, nearly incompressible body of our choosing (E = 1e6, ν = 0.45), for a
    // dissimilar pair.
    let soft = Material::new(1.0e6, 0.45).ctx(PAGE, "soft body")?;
    let cases = [
        (
            "Hertz circle, 36 across, steel/steel",
            ContactGrid::hertz_circle(a, p, 36).ctx(PAGE, "grid")?,
            Compliance::pair(&s, &s),
            InfluenceModel::ExactRectangle,
        ),
        (
            "ellipse 30 × 12 cells, steel/soft (E = 1e6, ν = 0.45)",
            ContactGrid::hertz_ellipse(2.0 * a, 0.8 * a, p, 30, 12).ctx(PAGE, "grid")?,
            Compliance::pair(&s, &soft),
            InfluenceModel::ExactRectangle,
        ),
        (
            "ellipse 14 × 26 cells (rectangular cells), point-load model",
            ContactGrid::hertz_ellipse(a, a, p, 14, 26).ctx(PAGE, "grid")?,
            Compliance::pair(&s, &s),
            InfluenceModel::PointLoad,
        ),
    ];
    let mut t = Table::new(&[
        "grid",
        "elements N",
        "lattice",
        "FFT size",
        "max abs(FFT − dense) / max abs(u)",
        "RMS / max abs(u)",
    ]);
    let mut worst_all: f64 = 0.0;
    for (name, grid, c, model) in &cases {
        let n = grid.len();
        let op = TensorConvolution::new(grid, c, *model).ctx(PAGE, "operator")?;
        let mut scratch = op.make_scratch();
        let mut seed = 2024u64;
        let qx: Vec<f64> = (0..n).map(|_| lcg(&mut seed)).collect();
        let qy: Vec<f64> = (0..n).map(|_| lcg(&mut seed)).collect();
        let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
        op.apply(&qx, &qy, &mut ux, &mut uy, &mut scratch);
        // Dense matrix: displacement per unit element force, rows/columns (x, y) per element.
        let m = tensor_matrix(grid, c, *model);
        let area = grid.element_area();
        let dense: Vec<f64> = (0..2 * n)
            .map(|r| {
                let row = &m[r * 2 * n..(r + 1) * 2 * n];
                (0..n).map(|j| (row[2 * j] * qx[j] + row[2 * j + 1] * qy[j]) * area).sum()
            })
            .collect();
        let umax = dense.iter().fold(0.0f64, |acc, v| acc.max(v.abs()));
        let (mut worst, mut sum2) = (0.0f64, 0.0);
        for k in 0..n {
            for (got, want) in [(ux[k], dense[2 * k]), (uy[k], dense[2 * k + 1])] {
                let e = (got - want).abs() / umax;
                worst = worst.max(e);
                sum2 += e * e;
            }
        }
        worst_all = worst_all.max(worst);
        let (lx, ly) = op.lattice();
        let (fx, fy) = op.fft_size();
        t.row(vec![
            (*name).to_owned(),
            n.to_string(),
            format!("{lx} × {ly}"),
            format!("{fx} × {fy}"),
            resid(worst, 1.0),
            resid((sum2 / (2 * n) as f64).sqrt(), 1.0),
        ]);
    }
    check(PAGE, "FFT product vs dense", worst_all, tol::FFT_VS_DENSE)?;
    out.push_str("#### The FFT product against the dense influence matrix\n\n");
    out.push_str(
        "`TensorConvolution::apply` on deterministic pseudo-random tractions in [−1, 1) \
         (both components) against the plain product with the dense matrix \
         `influence::tensor_matrix` of the same grid, bodies and influence model:\n\n",
    );
    out.push_str(&t.render());
    Ok(())
}

/// A `side` × `side` lattice centred on the contact, every cell an element, carrying the
/// Hertz pressure of radius `a` = `cells` cells inside the circle and none outside; scaled so
/// that the element forces add up to `p` exactly on the grid.
fn hertz_box(side: usize, cells: usize, a: f64, p: f64) -> Result<ContactGrid, Error> {
    let h = a / cells as f64;
    let half = 0.5 * side as f64;
    let mut pr: Vec<f64> = (0..side * side)
        .map(|idx| {
            let (i, j) = (idx % side, idx / side);
            let x = (i as f64 + 0.5 - half) * h;
            let y = (j as f64 + 0.5 - half) * h;
            (1.0 - (x * x + y * y) / (a * a)).max(0.0).sqrt()
        })
        .collect();
    let total: f64 = pr.iter().sum::<f64>() * h * h;
    pr.iter_mut().for_each(|v| *v *= p / total);
    ContactGrid::from_mask(h, h, (-half * h, -half * h), side, side, &vec![true; side * side], &pr)
        .ctx(PAGE, "lattice grid")
}

/// A solved sphere case, kept for the one-direction comparison.
struct Sphere {
    grid: ContactGrid,
    bodies: [Material; 2],
    f: f64,
    p: f64,
    t: f64,
    a: f64,
    free: FastSolution,
}

/// Seed 002 Example 1's contact and load on a lattice.
struct Case {
    grid: ContactGrid,
    steel: Material,
    mindlin: Mindlin,
    p: f64,
    f: f64,
    t: f64,
}

/// Example 1's sphere (steel, $R$, $P$, $T$, $f$ of seed 002; $T = \tfrac23 fP$) on a
/// `side`² lattice with the contact radius `cells` cells.
fn sphere_problem(side: usize, cells: usize) -> Result<Case, Error> {
    let (steel, a, _, mindlin) = example1()?;
    let (_, _, p, t, f) = example1_inputs()?;
    let grid = hertz_box(side, cells, a, p)?;
    Ok(Case { grid, steel, mindlin, p, f, t })
}

/// The optimality conditions of a free-direction solution, computed here from the returned
/// traction and slip: equilibrium, the Coulomb disc, zero slip on stick elements, slip
/// along the traction on slip elements ($\mathbf s_k = \lambda_k\mathbf q_k$). Returns
/// `[equilibrium, cone, stick slip, slip direction]`, each relative (see the table text).
fn optimality(grid: &ContactGrid, f: f64, t: (f64, f64), sol: &FastSolution) -> [f64; 4] {
    let area = grid.element_area();
    let (sx, sy) = sol.traction.iter().fold((0.0, 0.0), |acc, q| (acc.0 + q.0, acc.1 + q.1));
    let tnorm = t.0.hypot(t.1);
    let equilibrium = (area * sx - t.0).hypot(area * sy - t.1) / tnorm;
    let fp0 = f * grid.pressure.iter().fold(0.0f64, |acc, v| acc.max(*v));
    let shift = sol.shift.0.hypot(sol.shift.1);
    let (mut cone, mut stick, mut dir) = (0.0f64, 0.0f64, 0.0f64);
    for k in 0..grid.len() {
        let (q, s) = (sol.traction[k], sol.slip[k]);
        let (qn, sn) = (q.0.hypot(q.1), s.0.hypot(s.1));
        cone = cone.max((qn - f * grid.pressure[k]) / fp0);
        match sol.state[k] {
            ElementState::Stick => stick = stick.max(sn / shift),
            ElementState::Slip if qn > 0.0 && sn > 0.0 => {
                dir = dir.max(1.0 - (q.0 * s.0 + q.1 * s.1) / (qn * sn));
            }
            ElementState::Slip => {}
        }
    }
    [equilibrium, cone.max(0.0), stick, dir]
}

/// Cattaneo–Mindlin on $64^2$ and $128^2$ lattices.
fn mindlin(out: &mut String) -> Result<Sphere, Error> {
    let mut t = Table::new(&[
        "lattice (a in cells)",
        "N",
        "FFT size",
        "Newton steps",
        "CG iterations",
        "FFT products",
        "residual",
        "load residual",
        "stick radius − a* [cells]",
        "shift / Mindlin − 1",
    ]);
    let mut o = Table::new(&[
        "lattice",
        "equilibrium",
        "Coulomb disc",
        "slip on stick elements",
        "slip ∦ traction on slip elements",
    ]);
    let mut kept = None;
    for (side, cells) in [(64, 25), (128, 50)] {
        let Case { grid, steel: s, mindlin: m, p, f, t: tl } = sphere_problem(side, cells)?;
        let load = Load::force(tl, 0.0).ctx(PAGE, "load")?;
        let sol = FastProblem::new(&grid, [s, s], f, load)
            .ctx(PAGE, "problem")?
            .solve()
            .ctx(PAGE, "fast solve")?;
        let h = grid.hx;
        let n_stick = sol.stick_count();
        let r_stick = (n_stick as f64 * h * h / PI).sqrt();
        let cells_off = (r_stick - m.stick_radius()) / h;
        let delta = m.compliance_relative(&s, &s);
        let shift_rel = sol.shift.0.hypot(sol.shift.1) / delta - 1.0;
        check(PAGE, "fast solver residual", sol.info.residual, tol::FAST_RESIDUAL)?;
        check(PAGE, "stick radius vs Mindlin (cells)", cells_off.abs(), tol::STICK_CELLS)?;
        check(PAGE, "shift vs Mindlin", shift_rel.abs(), tol::FAST_SHIFT_MINDLIN)?;
        let opt = optimality(&grid, f, (tl, 0.0), &sol);
        for (v, what) in opt.iter().zip(["equilibrium", "cone", "stick slip", "slip direction"]) {
            check(PAGE, what, *v, tol::FAST_OPTIMALITY)?;
        }
        let (fx, fy) = sol.info.fft_size;
        t.row(vec![
            format!("{side}² ({cells})"),
            grid.len().to_string(),
            format!("{fx} × {fy}"),
            sol.info.iterations.to_string(),
            sol.info.cg_iterations.to_string(),
            sol.info.products.to_string(),
            // A converged solve stops once its residual is below the tolerance (1e-10); where
            // in the last decades it lands moves with the last bits of the kernels, so the
            // page states the bound 1e-11 (SOLVER_SCALE x ROUNDING) the solves are checked at.
            resid(sol.info.residual, SOLVER_SCALE),
            resid(sol.info.load_residual, SOLVER_SCALE),
            format!("{:+.2}", cells_off),
            pct(shift_rel),
        ]);
        o.row(vec![
            format!("{side}²"),
            resid(opt[0], OPTIMALITY_SCALE),
            resid(opt[1], OPTIMALITY_SCALE),
            resid(opt[2], OPTIMALITY_SCALE),
            resid(opt[3], OPTIMALITY_SCALE),
        ]);
        kept = Some(Sphere { grid, bodies: [s, s], f, p, t: tl, a: m.radius(), free: sol });
    }
    let (_, _, p, tl, f) = example1_inputs()?;
    out.push_str("#### The Cattaneo–Mindlin sphere\n\n");
    out.push_str(&format!(
        "Seed 002 Example 1's sphere ({}; T/fP = {}) on a square lattice centred on the \
         contact, every cell an element, the Hertz pressure inside the circle of radius a \
         (normalised so that the element forces add up to P) and none outside. Default \
         `FastConfig` (relative residual 1e-10), both traction components free. The stick \
         radius is the area-equivalent radius of the stick elements, √(N_stick h²/π), \
         against Mindlin's a* = a(1 − T/fP)^(1/3); the shift is the relative rigid \
         displacement of the two bodies against Mindlin's 3(2 − ν)fP[1 − (1 − T/fP)^(2/3)]/(16Ga) per body, \
         doubled.\n\n",
        crate::mindlin::example1_text()?,
        sig(tl / (f * p), 4)
    ));
    out.push_str(&t.render());
    out.push_str(
        "The optimality conditions, recomputed here from the returned tractions and slips: \
         equilibrium |h²Σq − T|/T; the Coulomb disc max(|q_k| − fp_k)/(fp0); the slip of \
         stick elements, max |s_k|/|δ|; and on slip elements the misalignment of slip and \
         traction, max (1 − cos∠(q_k, s_k)):\n\n",
    );
    out.push_str(&o.render());
    kept.ok_or(Error::Compute { page: PAGE, what: "sphere", message: "no case".into() })
}

/// The residual after each Newton step: the solve is deterministic, so stopping it after
/// $k$ steps (`FastConfig::new(tol, k)`, which reports the residual reached in
/// `Error::NotConverged`) reproduces the $k$-th iterate of the full solve.
fn history(out: &mut String) -> Result<(), Error> {
    let c = sphere_problem(64, 25)?;
    let load = Load::force(c.t, 0.0).ctx(PAGE, "load")?;
    let base = FastProblem::new(&c.grid, [c.steel, c.steel], c.f, load).ctx(PAGE, "problem")?;
    let full = base.solve().ctx(PAGE, "fast solve")?;
    let tol_default = FastConfig::default().tolerance();
    let op = base.operator().ctx(PAGE, "operator")?;
    let mut scratch = op.make_scratch();
    let mut steps = Vec::new();
    for k in 1..full.info.iterations {
        let cfg = FastConfig::new(tol_default, k).ctx(PAGE, "config")?;
        match base.clone().with_config(cfg).solve_with(&op, &mut scratch) {
            Err(stickslip_traction::Error::NotConverged { residual, .. }) => steps.push(residual),
            Ok(_) => {
                return Err(Error::Compute {
                    page: PAGE,
                    what: "convergence history",
                    message: format!("converged at step {k} of {}", full.info.iterations),
                })
            }
            Err(e) => return Err(e).ctx(PAGE, "truncated solve"),
        }
    }
    steps.push(full.info.residual.max(full.info.load_residual));
    let mut t = Table::new(&["Newton step", "relative residual (max of complementarity and load)"]);
    for (k, r) in steps.iter().enumerate() {
        t.row(vec![(k + 1).to_string(), resid(*r, 1.0)]);
    }
    out.push_str("#### Convergence of the semismooth Newton iteration (64² case)\n\n");
    out.push_str(&format!(
        "The residual after each step, from solves stopped after k steps (the iteration is \
         deterministic, so these are the iterates of the full solve). The first step treats \
         every loaded element as stick; the inner CG tolerance is the outer \
         residual, no tighter than the last step needs, within [1e-6, 1e-2]. {} steps, {} CG iterations in all.\n\n",
        full.info.iterations, full.info.cg_iterations
    ));
    out.push_str(&t.render());
    Ok(())
}

/// The modified LP and the fast solver with the LP's one-direction assumption, on the same
/// grid: they solve the same discrete equations.
fn versus_lp(out: &mut String) -> Result<(), Error> {
    let (s, a, _, _) = example1()?;
    let (_, _, p, _, f) = example1_inputs()?;
    let mut t = Table::new(&[
        "elements",
        "T/fP",
        "load angle [rad]",
        "max abs(F_fast − F_LP) / max F_LP",
        "shift / LP rigid − 1",
        "stick/slip differences",
        "LP pivots",
        "fast: Newton, CG",
    ]);
    let mut worst: f64 = 0.0;
    for (across, ratio, angle) in [(20, 2.0 / 3.0, 0.0), (30, 2.0 / 3.0, 0.0), (30, 0.3, 0.6)] {
        let grid = ContactGrid::hertz_circle(a, p, across).ctx(PAGE, "grid")?;
        let tl = ratio * f * p;
        let lp = TractionProblem::new(&grid, [s, s], f, Load::Force { magnitude: tl, angle })
            .ctx(PAGE, "LP problem")?
            .solve()
            .ctx(PAGE, "LP")?;
        let fast = FastProblem::new(&grid, [s, s], f, Load::polar(tl, angle).ctx(PAGE, "load")?)
            .ctx(PAGE, "fast problem")?
            .with_directions(TractionDirections::ParallelToForce)
            .ctx(PAGE, "directions")?
            .solve()
            .ctx(PAGE, "fast solve")?;
        let (c, sn) = (angle.cos(), angle.sin());
        let area = grid.element_area();
        let fmax = lp.force.iter().fold(0.0f64, |acc, v| acc.max(v.abs()));
        let mut dmax: f64 = 0.0;
        let mut states = 0usize;
        for k in 0..grid.len() {
            let ff = area * (fast.traction[k].0 * c + fast.traction[k].1 * sn);
            dmax = dmax.max((ff - lp.force[k]).abs() / fmax);
            states += usize::from(fast.state[k] != lp.state[k]);
        }
        let shift = fast.shift.0 * c + fast.shift.1 * sn;
        let dshift = shift / lp.rigid - 1.0;
        worst = worst.max(dmax).max(dshift.abs());
        t.row(vec![
            grid.len().to_string(),
            sig(ratio, 4),
            num(angle),
            resid(dmax, 1.0),
            resid(dshift, 1.0),
            states.to_string(),
            lp.info.iterations.to_string(),
            format!("{}, {}", fast.info.iterations, fast.info.cg_iterations),
        ]);
    }
    check(PAGE, "fast (one direction) vs LP", worst, tol::FAST_VS_LP)?;
    out.push_str("#### Agreement with the modified LP (one direction imposed)\n\n");
    out.push_str(
        "Example 1's sphere on `ContactGrid::hertz_circle` grids (20 and 30 elements across); \
         the LP (`TractionProblem`, exact-rectangle coefficients) against \
         `FastProblem::with_directions(TractionDirections::ParallelToForce)` on the same grid. \
         F is the element force along the load; the LP's rigid movement is relative (two \
         bodies), as the fast solver's shift:\n\n",
    );
    out.push_str(&t.render());
    Ok(())
}

/// Complementary energy $\tfrac12 h_xh_y\sum_k \mathbf q_k\cdot\mathbf u_k$ of a solution.
fn energy(grid: &ContactGrid, sol: &FastSolution) -> f64 {
    0.5 * grid.element_area()
        * sol
            .traction
            .iter()
            .zip(&sol.displacement)
            .map(|(q, u)| q.0 * u.0 + q.1 * u.1)
            .sum::<f64>()
}

/// The effect of the one-direction assumption on the $128^2$ sphere.
fn one_direction(out: &mut String, sp: &Sphere) -> Result<(), Error> {
    let load = Load::force(sp.t, 0.0).ctx(PAGE, "load")?;
    let par = FastProblem::new(&sp.grid, sp.bodies, sp.f, load)
        .ctx(PAGE, "problem")?
        .with_directions(TractionDirections::ParallelToForce)
        .ctx(PAGE, "directions")?
        .solve()
        .ctx(PAGE, "fast solve (parallel)")?;
    let free = &sp.free;
    let fp0 = sp.f * 3.0 * sp.p / (2.0 * PI * sp.a * sp.a);
    let (mut qy, mut dq) = (0.0f64, 0.0f64);
    for (qf, qp) in free.traction.iter().zip(&par.traction) {
        qy = qy.max(qf.1.abs() / fp0);
        dq = dq.max((qf.0 - qp.0).hypot(qf.1 - qp.1) / fp0);
    }
    let (ef, ep) = (energy(&sp.grid, free), energy(&sp.grid, &par));
    // The free problem is the less constrained minimisation of the same energy.
    check(PAGE, "free energy <= parallel energy", ef / ep - 1.0, tol::ENERGY_ORDER)?;
    let mut t = Table::new(&["quantity (128² sphere, T/fP = 2/3)", "value"]);
    t.row(vec!["max abs(q_y) / (f p0), free".into(), sig(qy, 4)]);
    t.row(vec!["max abs(q_free − q_parallel) / (f p0)".into(), sig(dq, 4)]);
    t.row(vec![
        "stick elements: free, parallel".into(),
        format!("{}, {}", free.stick_count(), par.stick_count()),
    ]);
    t.row(vec!["shift: free [in]".into(), num(free.shift.0)]);
    t.row(vec!["shift: parallel [in]".into(), num(par.shift.0)]);
    t.row(vec!["shift free / parallel − 1".into(), pct(free.shift.0 / par.shift.0 - 1.0)]);
    t.row(vec!["complementary energy free / parallel − 1".into(), err(ef / ep - 1.0)]);
    t.row(vec![
        "parallel: Newton steps, CG iterations".into(),
        format!("{}, {}", par.info.iterations, par.info.cg_iterations),
    ]);
    out.push_str("#### What the one-direction assumption changes\n\n");
    out.push_str(
        "The 128² sphere above solved again with every traction parallel to the load (the \
         LP's assumption). With both components free a small transverse traction q_y appears \
         (antisymmetric about the load axis, so it has no resultant); the free problem \
         minimises the same complementary energy ½h²Σq·u under fewer constraints, so its \
         energy is not larger.\n\n",
    );
    out.push_str(&t.render());
    Ok(())
}
