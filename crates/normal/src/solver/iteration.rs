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
        // The free set 0 < p < cap, one byte a cell (written with the gap; read by the
        // passes that only need the set, instead of the pressure).
        let mut free = vec![0u8; n];
        // The search direction, and K t.
        let mut t = vec![0.0; n];
        let mut r = vec![0.0; n];
        // The residual z (preconditioned), and the previous gap on the contact set, for the
        // Polak-Ribiere coefficient; both in single precision (the preconditioner's transforms
        // are, and the previous gap only enters the coefficient).
        let mut z = vec![0.0f32; n];
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
        // The gap, the free set and their sums written by the step itself (elastic, when it
        // neither clipped nor re-entered a cell, so that nothing corrects u after it), and
        // whether the step should try: it does after a step without changes.
        let mut fresh: Option<GapSums> = None;
        let mut fuse = false;
        let mut delta;
        let mut res;
        let sum_target = force.map(|f| f / area);
        loop {
            if stale {
                // u = K p, the pending scale applied to p on the way in.
                let f = scale;
                op.apply_rows(
                    &mut p,
                    |_, p, row| {
                        if f != 1.0 {
                            p.iter_mut().for_each(|p| *p *= f);
                        }
                        row.copy_from_slice(p);
                    },
                    &mut u,
                    |_, _, _| (),
                    &mut scratch,
                );
                scale = 1.0;
                products += 1;
                (stale, exact) = (false, true);
                fresh = None;
            }
            // The gap without the approach, the free set, and what the approach and the
            // residuals need, in one pass (unless the step wrote them).
            let f = scale;
            let a = match fresh.take() {
                Some(a) => a,
                None => in_order(
                    g.par_chunks_mut(BLOCK)
                        .zip(free.par_chunks_mut(BLOCK))
                        .zip(u.par_chunks(BLOCK).zip(g0.par_chunks(BLOCK).zip(p.par_chunks(BLOCK))))
                        .map(|((g, fr), (u, (g0, p)))| {
                            let mut a = GapSums::EMPTY;
                            let cells = g.iter_mut().zip(fr).zip(u.iter().zip(g0.iter().zip(p)));
                            for ((g, fr), (u, (g0, p))) in cells {
                                *g = f * u + g0;
                                *fr = u8::from(*p > 0.0 && *p < cap);
                                a.add(*g, f * p, *p >= cap);
                            }
                            a
                        }),
                )
                .into_iter()
                .fold(GapSums::EMPTY, GapSums::merge),
            };
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
            // The preconditioned residual z = M (g - delta) on the free set, with its sums:
            // sum z, sum (g - delta) z, sum gp z, sum gp over the free set; gp then becomes
            // this residual, in the same pass.
            let zs = if spectral {
                pre += 1;
                let (g, fr) = (&g, &free);
                op.precondition_rows(
                    &mut gp,
                    |j, _, row| {
                        let cells = fr[j * nx..(j + 1) * nx].iter().zip(&g[j * nx..(j + 1) * nx]);
                        for (v, (fr, g)) in row.iter_mut().zip(cells) {
                            *v = if *fr != 0 { (g - delta) as f32 } else { 0.0 };
                        }
                    },
                    &mut z,
                    |j, gp, z| {
                        let cells = fr[j * nx..(j + 1) * nx].iter().zip(&g[j * nx..(j + 1) * nx]);
                        let mut acc = [0.0; 4];
                        for (z, ((fr, g), gp)) in z.iter_mut().zip(cells.zip(gp.iter_mut())) {
                            free_cell(z, *fr != 0, *g, gp, delta, &mut acc);
                        }
                        acc
                    },
                    &mut scratch,
                )
                .1
            } else {
                in_order(
                    z.par_chunks_mut(BLOCK)
                        .zip(gp.par_chunks_mut(BLOCK))
                        .zip(free.par_chunks(BLOCK).zip(g.par_chunks(BLOCK)))
                        .map(|((z, gp), (fr, g))| {
                            let mut acc = [0.0; 4];
                            for ((z, gp), (fr, g)) in z.iter_mut().zip(gp).zip(fr.iter().zip(g)) {
                                // Unpreconditioned: the direction is the residual itself.
                                *z = (g - delta) as f32;
                                free_cell(z, *fr != 0, *g, gp, delta, &mut acc);
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
            // r = K t for the direction t = (z - m) + beta t on the free set, written row by
            // row as the product's input: with sum t, sum t^2, sum (g - delta) t, and (where
            // the step may stop at it) the first breakpoint min p / t (t > 0), and from the
            // product sum r and sum r t over the free set.
            let breakpoint = null_mode.is_some();
            let (dir, kt) = {
                let (p, g, fr, z) = (&p, &g, &free, &z);
                op.apply_rows(
                    &mut t,
                    |j, t, row| {
                        let span = j * nx..(j + 1) * nx;
                        let cells =
                            fr[span.clone()].iter().zip(&g[span.clone()]).zip(&z[span.clone()]);
                        let mut acc = [0.0, 0.0, 0.0, f64::INFINITY];
                        for (i, ((t, v), ((fr, g), z))) in
                            t.iter_mut().zip(row.iter_mut()).zip(cells).enumerate()
                        {
                            if *fr != 0 {
                                let gd = g - delta;
                                *t = (f64::from(*z) - m) + beta * *t;
                                acc = [acc[0] + *t, acc[1] + *t * *t, acc[2] + gd * *t, acc[3]];
                                if breakpoint {
                                    let p = p[j * nx + i];
                                    if *t > 0.0 {
                                        acc[3] = acc[3].min(f * p / *t);
                                    } else if *t < 0.0 && capped {
                                        acc[3] = acc[3].min((f * p - cap) / *t);
                                    }
                                }
                            } else {
                                *t = 0.0;
                            }
                            *v = *t;
                        }
                        acc
                    },
                    &mut r,
                    |j, t, r| {
                        let cells = fr[j * nx..(j + 1) * nx].iter().zip(t.iter());
                        let mut acc = [0.0; 2];
                        for (r, (fr, t)) in r.iter().zip(cells) {
                            if *fr != 0 {
                                acc = [acc[0] + r, acc[1] + r * t];
                            }
                        }
                        acc
                    },
                    &mut scratch,
                )
            };
            let e = dir.into_iter().fold([0.0, 0.0, 0.0, f64::INFINITY], |x, y| {
                [x[0] + y[0], x[1] + y[1], x[2] + y[2], x[3].min(y[3])]
            });
            let kt = kt.into_iter().fold([0.0; 2], |x, y| [x[0] + y[0], x[1] + y[1]]);
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
            // Elastic: the factor that will bring the force back to the load if the step
            // changes no cell (the pressure sum then moves by -tau sum t), with which the
            // step can write the next gap itself.
            let next = match sum_target {
                Some(target) if a.pressure - tau * e[0] > 0.0 => target / (a.pressure - tau * e[0]),
                _ => 1.0,
            };
            // Step, projection, re-entry of penetrating cells, u -= tau K t, and the new force,
            // in one pass; `changes` the departures from p - tau t (clipped or re-entered
            // cells), whose columns correct u. With `fuse`, also the next gap, free set and
            // sums at the scale `next`.
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
                let fuse = fuse;
                in_order(
                    p.par_chunks_mut(BLOCK)
                        .zip(u.par_chunks_mut(BLOCK))
                        .zip(g.par_chunks_mut(BLOCK).zip(free.par_chunks_mut(BLOCK)))
                        .zip(t.par_chunks(BLOCK).zip(r.par_chunks(BLOCK).zip(g0.par_chunks(BLOCK))))
                        .enumerate()
                        .map(|(b, (((p, u), (g, fr)), (t, (r, g0))))| {
                            let (mut ch, mut sum, mut a) = (Vec::new(), 0.0, GapSums::EMPTY);
                            let cells = p
                                .iter_mut()
                                .zip(u.iter_mut())
                                .zip(g.iter_mut().zip(fr.iter_mut()))
                                .zip(t.iter().zip(r.iter().zip(g0)));
                            for (i, (((p, u), (g, fr)), (t, (r, g0)))) in cells.enumerate() {
                                let k = b * BLOCK + i;
                                *u = f * *u - tau * r;
                                if *p > 0.0 {
                                    let free = f * *p - tau * t;
                                    *p = free.max(0.0);
                                    if free < 0.0 {
                                        ch.push((k, -free));
                                    }
                                } else if *g < delta {
                                    *p = tau_e * (delta - *g);
                                    ch.push((k, *p));
                                }
                                sum += *p;
                                if fuse {
                                    *g = next * *u + g0;
                                    *fr = u8::from(*p > 0.0);
                                    a.add(*g, next * *p, false);
                                }
                            }
                            Step { changes: ch, sum, sums: a }
                        }),
                )
            };
            scale = 1.0;
            let sum = blocks.iter().fold(0.0, |a, b| a + b.sum);
            let sums = blocks.iter().fold(GapSums::EMPTY, |a, b| GapSums::merge(a, b.sums));
            let changes: Vec<(usize, f64)> = blocks.into_iter().flat_map(|b| b.changes).collect();
            conjugate = true;
            // A step without changes that wrote the next gap: it stands at the scale `next`
            // (the load's, to rounding) and needs no gap pass; the next step tries again.
            let wrote = fuse && !capped && changes.is_empty();
            fuse = !capped && changes.is_empty();
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
            if wrote && !stale {
                if force.is_some() {
                    scale = next;
                }
                fresh = Some(sums);
            }
        }
        drop((u, t, r, z, gp, free, scratch));
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
    /// The next gap's sums, when the step wrote it.
    sums: GapSums,
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
    let mut s = Step { changes: Vec::new(), sum: 0.0, sums: GapSums::EMPTY };
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

/// One cell of the preconditioned residual's pass: on the free set add the residual `z`, its
/// product with the gap $g - \delta$ and with the previous gap `gp`, and `gp`, to the block
/// sums `acc`, and make `gp` this gap; elsewhere zero both.
#[inline]
fn free_cell(z: &mut f32, free: bool, g: f64, gp: &mut f32, delta: f64, acc: &mut [f64; 4]) {
    if free {
        let (zz, old, gd) = (f64::from(*z), f64::from(*gp), g - delta);
        *acc = [acc[0] + zz, acc[1] + gd * zz, acc[2] + old * zz, acc[3] + old];
        *gp = gd as f32;
    } else {
        *z = 0.0;
        *gp = 0.0;
    }
}
