//! The constrained conjugate-gradient iteration on one lattice (module docs of
//! [`crate::solver`]).

use super::passes::{in_order, project_sum, rescale, BLOCK};
use super::solution::NormalSolution;
use super::{
    Boundary, NormalLoad, NormalProblem, Preconditioner, DIRECT_CHANGES, PROJECTION_SLACK, REFRESH,
    SOLVER_NAME,
};
use crate::error::{Error, Result};
use rayon::prelude::*;
use std::time::Instant;
use stickslip_lattice::NormalOperator;

impl NormalProblem<'_> {
    /// The iteration of the module docs on this lattice from `start`; also returns whether
    /// it started warm.
    pub(super) fn run(
        &self,
        op: &NormalOperator,
        load: NormalLoad,
        tol: f64,
        force: Option<f64>,
        start: Start<'_>,
    ) -> Result<(NormalSolution, bool)> {
        if let (Some(_), Some(pf)) = (self.hardness, force) {
            return self.run_capped_force(op, pf, tol, start);
        }
        self.iterate(op, load, tol, force, start, self.max_iterations)
    }

    /// The iteration itself, at most `max_iterations` steps. Under a cap and a force, the
    /// force is kept by the projection onto the capped pressures of that force
    /// ([`project_sum`]) instead of a rescaling.
    pub(super) fn iterate(
        &self,
        op: &NormalOperator,
        load: NormalLoad,
        tol: f64,
        force: Option<f64>,
        start: Start<'_>,
        max_iterations: usize,
    ) -> Result<(NormalSolution, bool)> {
        let warm = !matches!(start, Start::Cold);
        let (nx, n) = (self.nx, self.nx * self.ny);
        let t0 = Instant::now();
        let area = self.hx * self.hy;
        let g0 = self.gap;
        let gmin = g0.par_iter().copied().reduce(|| f64::INFINITY, f64::min);

        // Displacement control where the gap never closes: zero load, said so.
        if let NormalLoad::Approach(d) = load {
            if d <= gmin {
                let info = self.info(op, 0, 0, 0, (0.0, 0.0, 0.0, 0.0), 0.0, t0);
                return Ok((
                    self.finish(vec![0.0; n], g0.iter().map(|g| g - d).collect(), d, info),
                    false,
                ));
            }
        }

        // The hardness: cells at p = cap are plastic (infinite without a cap, where every
        // test against it below is true or false throughout and changes nothing).
        let cap = self.hardness.unwrap_or(f64::INFINITY);
        let capped = cap.is_finite();
        let mut p = match (start, load) {
            (Start::Owned(mut w), _) => {
                w.par_iter_mut().for_each(|p| *p = p.max(0.0));
                w
            }
            (Start::Borrowed(w), _) => w.par_iter().map(|w| w.max(0.0)).collect(),
            (Start::Cold, NormalLoad::Approach(d)) => {
                let k0 = op.self_term();
                g0.par_iter().map(|g| ((d - g) / k0).max(0.0)).collect()
            }
            (Start::Cold, NormalLoad::Force(_)) => vec![1.0; n],
        };
        if let (NormalLoad::Approach(d), true) = (load, warm) {
            // A warm start without a pressed cell gives the iteration no contact set and so
            // no direction: begin from the rigid interference instead, as a cold start does.
            if !p.par_iter().any(|&p| p > 0.0) {
                let k0 = op.self_term();
                p.par_iter_mut().zip(g0).for_each(|(p, g)| *p = ((d - g) / k0).max(0.0));
            }
        }
        if let (Some(pf), false) = (force, capped) {
            if !rescale(&mut p, pf / area) {
                // A zero warm start: begin uniform.
                p.fill(1.0);
                rescale(&mut p, pf / area);
            }
        }
        if capped {
            // Under a force, the nearest capped pressure of that force (a rescaling would
            // move the plastic cells off the cap).
            let fitted = force.is_some_and(|pf| project_sum(&mut p, cap, pf / area).is_some());
            if !fitted {
                p.par_iter_mut().for_each(|p| *p = p.min(cap));
            }
        }

        let spectral = self.preconditioner == Preconditioner::Spectral;
        let (mx, my) = op.fft_size();
        let direct = DIRECT_CHANGES * (mx * my).div_ceil(n);
        // Periodic displacement control: the smallest non-zero eigenvalue of K, c_1 / |q|_max
        // at the corner of the lattice's wave vectors (the mean mode's is zero).
        let null_mode = match (load, self.boundary) {
            (NormalLoad::Approach(_), Boundary::Periodic) => {
                let qmax = std::f64::consts::PI * (self.hx.powi(-2) + self.hy.powi(-2)).sqrt();
                Some(op.planned().2 / qmax)
            }
            _ => None,
        };
        let mut scratch = op.make_scratch();
        let mut u = vec![0.0; n];
        // The gap without the approach, g0 + u (the approach is subtracted where it is used).
        let mut g = vec![0.0; n];
        // The search direction, and the residual z (preconditioned) and K t in turn.
        let mut t = vec![0.0; n];
        let mut r = vec![0.0; n];
        // The previous gap on the contact set, for the Polak-Ribiere coefficient (single
        // precision: it only enters the coefficient).
        let mut gp = vec![0.0f32; n];
        let mut rz_old = 0.0;
        let mut conjugate = false;
        let (mut iterations, mut products, mut pre) = (0, 0, 0);
        // `u = Kp` is updated from the products of the step (one convolution per iteration
        // when few cells are clipped or re-enter); `stale` says it must be recomputed by a
        // full product before the next pass, `exact` that it is a full product of the
        // current p, which the certified stop requires.
        let (mut stale, mut exact) = (true, false);
        // Force control: the factor that rescales p (and u) to the load. The arrays hold
        // p / scale and u / scale until the step writes them anyway.
        let mut scale = 1.0;
        let mut delta;
        let mut res;
        let sum_target = force.map(|f| f / area);
        loop {
            if stale {
                if scale != 1.0 {
                    let f = scale;
                    p.par_iter_mut().for_each(|p| *p *= f);
                    scale = 1.0;
                }
                op.apply(&p, &mut u, &mut scratch);
                products += 1;
                (stale, exact) = (false, true);
            }
            // The gap without the approach, and what the approach and the residuals need, in
            // one pass.
            let f = scale;
            let a = in_order(
                g.par_chunks_mut(BLOCK)
                    .zip(u.par_chunks(BLOCK))
                    .zip(g0.par_chunks(BLOCK).zip(p.par_chunks(BLOCK)))
                    .map(|((g, u), (g0, p))| {
                        let mut a = GapSums::EMPTY;
                        for (g, (u, (g0, p))) in g.iter_mut().zip(u.iter().zip(g0.iter().zip(p))) {
                            *g = f * u + g0;
                            a.add(*g, f * p, *p >= cap);
                        }
                        a
                    }),
            )
            .into_iter()
            .fold(GapSums::EMPTY, GapSums::merge);
            delta = match load {
                NormalLoad::Approach(d) => d,
                NormalLoad::Force(_) if a.cells == 0 && a.max_plastic.is_finite() => {
                    // Every pressed cell plastic: the approach that best closes the plastic
                    // gaps without penetration elsewhere.
                    if a.max_plastic <= a.min_out {
                        a.max_plastic
                    } else {
                        0.5 * (a.max_plastic + a.min_out)
                    }
                }
                NormalLoad::Force(_) => a.sum / a.cells.max(1) as f64,
            };
            res = a.residuals(delta, delta - gmin, sum_target);
            // The complementarity residual is at most the gap residual (module docs), so the
            // gap and force residuals decide the stop; it is computed at the end.
            if res.0.max(res.1) <= tol {
                if exact {
                    break;
                }
                // Certify with a full product.
                stale = true;
                continue;
            }
            if iterations >= max_iterations {
                return Err(Error::NotConverged {
                    solver: SOLVER_NAME,
                    iterations,
                    residual: res.0.max(res.1),
                    tolerance: tol,
                });
            }
            iterations += 1;
            let (c, mean_force) = (a.cells, force.is_some());
            // The preconditioned residual z = M (g - delta) on the contact set, into r, with
            // its sums: sum z, sum (g - delta) z, sum gp z, sum gp over the contact set.
            let zs = if spectral {
                pre += 1;
                let (p, g, gp) = (&p, &g, &gp);
                op.precondition_rows(
                    |j, row| {
                        let (p, g) = (&p[j * nx..(j + 1) * nx], &g[j * nx..(j + 1) * nx]);
                        for (v, (p, g)) in row.iter_mut().zip(p.iter().zip(g)) {
                            *v = if *p > 0.0 && *p < cap { (g - delta) as f32 } else { 0.0 };
                        }
                    },
                    &mut r,
                    |j, z| {
                        let cells = p[j * nx..(j + 1) * nx]
                            .iter()
                            .zip(&g[j * nx..(j + 1) * nx])
                            .zip(&gp[j * nx..(j + 1) * nx]);
                        let mut acc = [0.0; 4];
                        for (z, ((p, g), gp)) in z.iter_mut().zip(cells) {
                            free_cell(z, *p, *g, *gp, cap, delta, &mut acc);
                        }
                        acc
                    },
                    &mut scratch,
                )
            } else {
                in_order(
                    r.par_chunks_mut(BLOCK)
                        .zip(p.par_chunks(BLOCK).zip(g.par_chunks(BLOCK).zip(gp.par_chunks(BLOCK))))
                        .map(|(z, (p, (g, gp)))| {
                            let mut acc = [0.0; 4];
                            for (z, (p, (g, gp))) in
                                z.iter_mut().zip(p.iter().zip(g.iter().zip(gp)))
                            {
                                // Unpreconditioned: the direction is the residual itself.
                                *z = g - delta;
                                free_cell(z, *p, *g, *gp, cap, delta, &mut acc);
                            }
                            acc
                        }),
                )
            }
            .into_iter()
            .fold([0.0; 4], |x, y| [x[0] + y[0], x[1] + y[1], x[2] + y[2], x[3] + y[3]]);
            // Force control keeps sum p: the direction has zero sum on the contact set.
            let m = if mean_force { zs[0] / c.max(1) as f64 } else { 0.0 };
            let gd_sum = a.sum - delta * c as f64;
            let rz = zs[1] - m * gd_sum;
            let zgp = zs[2] - m * zs[3];
            // Polak-Ribiere, clipped at zero (a restart when the contact set has turned the
            // new residual against the old direction).
            let beta = if conjugate && rz_old > 0.0 { ((rz - zgp) / rz_old).max(0.0) } else { 0.0 };
            rz_old = rz;
            // The direction t = (z - m) + beta t on the contact set, gp = g - delta there, and
            // sum t, sum t^2, sum (g - delta) t, and the first breakpoint min p / t (t > 0).
            let e = in_order(
                t.par_chunks_mut(BLOCK)
                    .zip(gp.par_chunks_mut(BLOCK))
                    .zip(r.par_chunks(BLOCK).zip(g.par_chunks(BLOCK).zip(p.par_chunks(BLOCK))))
                    .map(|((t, gp), (z, (g, p)))| {
                        let mut acc = [0.0, 0.0, 0.0, f64::INFINITY];
                        for ((t, gp), (z, (g, p))) in
                            t.iter_mut().zip(gp.iter_mut()).zip(z.iter().zip(g.iter().zip(p)))
                        {
                            if *p > 0.0 && *p < cap {
                                let gd = g - delta;
                                *t = (z - m) + beta * *t;
                                *gp = gd as f32;
                                acc = [acc[0] + *t, acc[1] + *t * *t, acc[2] + gd * *t, acc[3]];
                                if *t > 0.0 {
                                    acc[3] = acc[3].min(f * p / *t);
                                } else if *t < 0.0 && capped {
                                    acc[3] = acc[3].min((f * p - cap) / *t);
                                }
                            } else {
                                *t = 0.0;
                                *gp = 0.0;
                            }
                        }
                        acc
                    }),
            )
            .into_iter()
            .fold([0.0, 0.0, 0.0, f64::INFINITY], |x, y| {
                [x[0] + y[0], x[1] + y[1], x[2] + y[2], x[3].min(y[3])]
            });
            // r = K t, with sum r and sum r t over the contact set.
            let kt = {
                let (p, t) = (&p, &t);
                op.apply_rows(
                    |j, row| row[..nx].copy_from_slice(&t[j * nx..(j + 1) * nx]),
                    &mut r,
                    |j, r| {
                        let cells = p[j * nx..(j + 1) * nx].iter().zip(&t[j * nx..(j + 1) * nx]);
                        let mut acc = [0.0; 2];
                        for (r, (p, t)) in r.iter().zip(cells) {
                            if *p > 0.0 && *p < cap {
                                acc = [acc[0] + r, acc[1] + r * t];
                            }
                        }
                        acc
                    },
                    &mut scratch,
                )
            }
            .into_iter()
            .fold([0.0; 2], |x, y| [x[0] + y[0], x[1] + y[1]]);
            products += 1;
            // tau = sum (g - delta) t / sum (r - rbar) t over I_c (force control: rbar the
            // mean of r there); re-entering cells take -(g - delta) sum t^2 / sum (r - rbar) t,
            // the step's own inverse stiffness, which does not depend on the
            // preconditioner's scale.
            let rbar = if mean_force { kt[0] / c.max(1) as f64 } else { 0.0 };
            let den = kt[1] - rbar * e[0];
            let num = e[2];
            if !(den > 0.0 && num > 0.0 && den.is_finite() && num.is_finite()) {
                // Not a descent direction (the contact set turned it): restart from the
                // residual; without a previous direction there is no step to take.
                if beta == 0.0 {
                    return Err(Error::NotConverged {
                        solver: SOLVER_NAME,
                        iterations,
                        residual: res.0.max(res.1),
                        tolerance: tol,
                    });
                }
                conjugate = false;
                continue;
            }
            let (mut tau, mut tau_e) = (num / den, e[1] / den);
            if let Some(kmin) = null_mode {
                // Periodic, displacement control: a uniform pressure moves nothing, so near
                // full contact the direction's mean has no curvature and the quadratic step
                // runs away. Below the smallest curvature of the other modes, step to the first
                // cell that leaves the contact instead (an active-set step), and let cells
                // re-enter with at most the softest mode's inverse stiffness.
                if den < kmin * e[1] {
                    tau = tau.min(e[3]);
                    tau_e = tau_e.min(1.0 / kmin);
                }
            }
            // Step, projection, re-entry of penetrating cells, u -= tau K t, and the new force,
            // in one pass; `changes` the departures from p - tau t (clipped or re-entered
            // cells), whose columns correct u.
            let blocks = if capped {
                in_order(
                    p.par_chunks_mut(BLOCK)
                        .zip(u.par_chunks_mut(BLOCK))
                        .zip(g.par_chunks(BLOCK).zip(t.par_chunks(BLOCK).zip(r.par_chunks(BLOCK))))
                        .enumerate()
                        .map(|(b, ((p, u), (g, (t, r))))| {
                            step_capped(b * BLOCK, p, u, g, t, r, tau, tau_e, delta, cap)
                        }),
                )
            } else {
                in_order(
                    p.par_chunks_mut(BLOCK)
                        .zip(u.par_chunks_mut(BLOCK))
                        .zip(g.par_chunks(BLOCK).zip(t.par_chunks(BLOCK).zip(r.par_chunks(BLOCK))))
                        .enumerate()
                        .map(|(b, ((p, u), (g, (t, r))))| {
                            let (mut ch, mut sum) = (Vec::new(), 0.0);
                            let cells =
                                p.iter_mut().zip(u.iter_mut().zip(g.iter().zip(t.iter().zip(r))));
                            for (i, (p, (u, (g, (t, r))))) in cells.enumerate() {
                                let k = b * BLOCK + i;
                                *u = f * *u - tau * r;
                                if *p > 0.0 {
                                    let free = f * *p - tau * t;
                                    *p = free.max(0.0);
                                    if free < 0.0 {
                                        ch.push((k, -free));
                                    }
                                } else if *g < delta {
                                    *p = tau_e * (delta - g);
                                    ch.push((k, *p));
                                }
                                sum += *p;
                            }
                            Step { changes: ch, sum }
                        }),
                )
            };
            scale = 1.0;
            let sum = blocks.iter().fold(0.0, |a, b| a + b.sum);
            let changes: Vec<(usize, f64)> = blocks.into_iter().flat_map(|b| b.changes).collect();
            conjugate = true;
            // Under a cap and a force: back to the force by the projection when the step
            // has moved it off by more than PROJECTION_SLACK of the tolerance (the stop
            // checks the force residual all the same); u then needs a full product.
            let projected = match (force, capped) {
                (Some(pf), true) => {
                    let target = pf / area;
                    (sum - target).abs() > PROJECTION_SLACK * tol * target && {
                        // The cells off the contact at the gradient step's value (negative:
                        // the nearest enter first if the pressed cells cannot carry the
                        // force).
                        p.par_iter_mut().zip(g.par_iter()).for_each(|(p, g)| {
                            if *p == 0.0 {
                                *p = tau_e * (delta - g).min(0.0);
                            }
                        });
                        project_sum(&mut p, cap, target).is_some()
                    }
                }
                _ => false,
            };
            // Few changes: add their columns to u; many: a full product at the next check
            // (the same cost as correcting by one convolution, and exact).
            let incremental = !projected && changes.len() <= direct;
            if incremental {
                op.add_columns(&changes, &mut u);
            }
            stale = !incremental || iterations % REFRESH == 0;
            exact = false;
            match force {
                Some(_) if capped => {
                    if sum == 0.0 {
                        // Everything left the contact (the projection spread the force
                        // over all cells): start the directions again.
                        conjugate = false;
                    }
                }
                Some(pf) => {
                    if sum > 0.0 {
                        // Applied by the next step (or before the next product).
                        scale = pf / area / sum;
                    } else {
                        // Everything left the contact: restart uniform.
                        p.fill(1.0);
                        rescale(&mut p, pf / area);
                        conjugate = false;
                        stale = true;
                    }
                }
                None => {
                    if sum == 0.0 {
                        // Everything left the contact: restart from the rigid interference.
                        let (k0, d) = (op.self_term(), delta);
                        p.par_iter_mut()
                            .zip(g0)
                            .for_each(|(p, g)| *p = ((d - g) / k0).max(0.0).min(cap));
                        conjugate = false;
                        stale = true;
                    }
                }
            }
        }
        drop((u, t, r, gp, scratch));
        if scale != 1.0 {
            p.par_iter_mut().for_each(|p| *p *= scale);
        }
        // The gap with the approach, and the complementarity residual.
        let (pg, ps) = in_order(g.par_chunks_mut(BLOCK).zip(p.par_chunks(BLOCK)).map(|(g, p)| {
            let mut acc = (0.0, 0.0);
            for (g, p) in g.iter_mut().zip(p) {
                *g -= delta;
                if *p > 0.0 && *p < cap {
                    acc = (acc.0 + p * g.abs(), acc.1 + p);
                } else if *p >= cap {
                    acc.1 += p;
                }
            }
            acc
        }))
        .into_iter()
        .fold((0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1));
        let scale = (delta - gmin).max(f64::MIN_POSITIVE);
        let rc = if ps > 0.0 { pg / (ps * scale) } else { 0.0 };
        let residuals = (res.0, rc, res.1, res.0.max(res.1).max(rc));
        let info = self.info(op, iterations, products, pre, residuals, delta - gmin, t0);
        let s = self.finish(p, g, delta, info);
        if s.contact_cells < self.min_contact_cells {
            return Err(Error::UnresolvedContact {
                cells: s.contact_cells,
                minimum: self.min_contact_cells,
            });
        }
        Ok((s, warm))
    }
}

/// Where [`NormalProblem::run`] starts: cold, or from a pressure (borrowed: a caller's warm
/// start, copied; owned: the nested start's, used in place).
pub(super) enum Start<'b> {
    Cold,
    Borrowed(&'b [f64]),
    Owned(Vec<f64>),
}

/// What one step's pass over a block gives: the departures from $p - \tau t$ whose kernel
/// columns correct $u$, and the pressure sum.
struct Step {
    changes: Vec<(usize, f64)>,
    sum: f64,
}

/// The step of the iteration on one block under a cap (approach control; the block's first
/// cell `k0`): the step along $-t$ on the cells strictly between 0 and the cap, projected
/// onto $[0, \text{cap}]$; a cell off the contact whose gap is negative re-enters with
/// $\tau_e(\delta - g)$, a plastic cell whose gap is open leaves the cap by
/// $\tau_e(g - \delta)$ (both kept in $[0, \text{cap}]$).
#[allow(clippy::too_many_arguments)]
fn step_capped(
    k0: usize,
    p: &mut [f64],
    u: &mut [f64],
    g: &[f64],
    t: &[f64],
    r: &[f64],
    tau: f64,
    tau_e: f64,
    delta: f64,
    cap: f64,
) -> Step {
    let mut s = Step { changes: Vec::new(), sum: 0.0 };
    let cells = p.iter_mut().zip(u.iter_mut().zip(g.iter().zip(t.iter().zip(r))));
    for (i, (p, (u, (g, (t, r))))) in cells.enumerate() {
        let k = k0 + i;
        *u -= tau * r;
        if *p >= cap {
            if *g > delta {
                let new = (cap - tau_e * (g - delta)).max(0.0);
                s.changes.push((k, new - cap));
                *p = new;
            }
        } else if *p > 0.0 {
            let free = *p - tau * t;
            if free < 0.0 {
                *p = 0.0;
                s.changes.push((k, -free));
            } else if free >= cap {
                *p = cap;
                s.changes.push((k, cap - free));
            } else {
                *p = free;
            }
        } else if *g < delta {
            *p = (tau_e * (delta - g)).min(cap);
            s.changes.push((k, *p));
        }
        s.sum += *p;
    }
    s
}

/// What one pass over the gap $g^0 + u$ gathers for the approach and the residuals: over the
/// cells strictly between 0 and the cap the sum, count, largest and smallest gap; at the cap
/// (plastic) the largest gap; off the contact the smallest gap; and the pressure sum.
#[derive(Debug, Clone, Copy)]
struct GapSums {
    sum: f64,
    cells: usize,
    max_in: f64,
    min_in: f64,
    min_out: f64,
    pressure: f64,
    max_plastic: f64,
}

impl GapSums {
    const EMPTY: Self = Self {
        sum: 0.0,
        cells: 0,
        max_in: f64::NEG_INFINITY,
        min_in: f64::INFINITY,
        min_out: f64::INFINITY,
        pressure: 0.0,
        max_plastic: f64::NEG_INFINITY,
    };

    /// A cell of gap (without the approach) `g` and pressure `p`, at the cap if `plastic`.
    fn add(&mut self, g: f64, p: f64, plastic: bool) {
        if plastic {
            self.max_plastic = self.max_plastic.max(g);
            self.pressure += p;
        } else if p > 0.0 {
            self.sum += g;
            self.cells += 1;
            self.max_in = self.max_in.max(g);
            self.min_in = self.min_in.min(g);
            self.pressure += p;
        } else {
            self.min_out = self.min_out.min(g);
        }
    }

    fn merge(a: Self, b: Self) -> Self {
        Self {
            sum: a.sum + b.sum,
            cells: a.cells + b.cells,
            max_in: a.max_in.max(b.max_in),
            min_in: a.min_in.min(b.min_in),
            min_out: a.min_out.min(b.min_out),
            pressure: a.pressure + b.pressure,
            max_plastic: a.max_plastic.max(b.max_plastic),
        }
    }

    /// The gap residual $r_g$ and the force residual $r_F$ of the module docs at the approach
    /// `delta`, `scale` the gap scale, `sum` the prescribed $\sum_k p_k$ (force control).
    fn residuals(&self, delta: f64, scale: f64, sum: Option<f64>) -> (f64, f64) {
        let scale = if scale > 0.0 { scale } else { f64::MIN_POSITIVE };
        // |g - delta| on the contact set below the cap, penetration delta - g off it, an
        // open gap g - delta at the cap.
        let e = (self.max_in - delta)
            .max(delta - self.min_in)
            .max(delta - self.min_out)
            .max(self.max_plastic - delta)
            .max(0.0);
        let rf = sum.map_or(0.0, |s| (self.pressure - s).abs() / s);
        (e / scale, rf)
    }
}

/// One cell of the search-direction pass: on the free set ($0 < p < H$) add the direction
/// `z`, its product with the residual $g - \delta$, and the preconditioner's weight to the
/// block sums `acc`; elsewhere zero the direction.
#[inline]
fn free_cell(z: &mut f64, p: f64, g: f64, gp: f32, cap: f64, delta: f64, acc: &mut [f64; 4]) {
    if p > 0.0 && p < cap {
        let gp = f64::from(gp);
        *acc = [acc[0] + *z, acc[1] + (g - delta) * *z, acc[2] + gp * *z, acc[3] + gp];
    } else {
        *z = 0.0;
    }
}
