//! The semismooth Newton / projected conjugate-gradient iteration of the fast solver
//! ([`FastProblem::solve_with`] runs it; the method is described in the module
//! documentation of [`crate::fast`]).

use super::solver::{
    resultant_moment, FastInfo, FastProblem, FastSolution, TractionDirections, WarmStart,
    SOLVER_NAME,
};
use crate::contract::{Load, LoadKind};
use crate::error::{Error, Result};
use crate::solve::{ElementState, Regime};
use rayon::prelude::*;
use std::time::Instant;
use stickslip_lattice::{ConvScratch, TensorConvolution};

mod pcg;

use pcg::{small_spd_solve, Reducer, Work, REDUCE_CHUNK};

/// $\sqrt{a^2 + b^2}$ without `hypot`'s cost where the squares are safe. The solver's
/// vectors are tractions (bounded by the capacities $fp_k$) and trial tractions
/// $\mathbf q + \rho\,\mathbf s$ (a displacement times a stiffness): in Pa, far from
/// $10^{\pm 154}$, where squaring would overflow or lose precision to subnormals. A sum of
/// squares outside the normal range (zero, subnormal, infinite or NaN) goes to `hypot`
/// itself, so the result is `hypot`'s to rounding (within an ulp or two) for every input.
#[inline]
fn norm(a: f64, b: f64) -> f64 {
    let s = a * a + b * b;
    if s.is_normal() {
        s.sqrt()
    } else {
        a.hypot(b)
    }
}
/// A rigid-body mode evaluated at a point.
#[derive(Debug, Clone, Copy)]
enum Mode {
    Ex,
    Ey,
    Rot(f64, f64),
    Along(f64, f64),
}

impl Mode {
    #[inline]
    fn at(self, x: f64, y: f64) -> (f64, f64) {
        match self {
            Mode::Ex => (1.0, 0.0),
            Mode::Ey => (0.0, 1.0),
            Mode::Rot(cx, cy) => (-(y - cy), x - cx),
            Mode::Along(tx, ty) => (tx, ty),
        }
    }
}

/// One free component of the Newton system: element and unit vector.
#[derive(Debug, Clone, Copy, Default)]
struct Dof {
    /// Element index (32 bits: the dof list is streamed several times per CG step, and a
    /// 24-byte dof moves a quarter less memory than a 32-byte one).
    k: u32,
    e: (f64, f64),
    stick: bool,
}

pub(super) struct Solver<'p, 'a> {
    p: &'p FastProblem<'a>,
    op: &'p TensorConvolution,
    scratch: &'p mut ConvScratch,
    n: usize,
    area: f64,
    cap: Vec<f64>,
    dirs: Option<Vec<(f64, f64)>>,
    modes: Vec<Mode>,
    loads: Vec<f64>,
    centre: (f64, f64),
    k0: [f64; 3],
    rho: f64,
    products: usize,
    /// The Fourier preconditioner of the stick block (None: Jacobi); it shares the
    /// operator's scratch, which is at least as large.
    prec: Option<TensorConvolution>,
    // Work fields.
    wx: Vec<f64>,
    wy: Vec<f64>,
    vx: Vec<f64>,
    vy: Vec<f64>,
    /// The displacement $KP\,x$ of the last Newton step's increment $x$, accumulated by the
    /// PCG from its own products.
    dux: Vec<f64>,
    duy: Vec<f64>,
}

impl<'p, 'a> Solver<'p, 'a> {
    pub(super) fn new(
        p: &'p FastProblem<'a>,
        op: &'p TensorConvolution,
        scratch: &'p mut ConvScratch,
    ) -> Self {
        let g = p.grid;
        let n = g.len();
        let cap: Vec<f64> = g.pressure.iter().map(|pk| p.friction * pk).collect();
        let centre = p.load.centre().unwrap_or_else(|| g.force_centroid());
        let (tx, ty) = p.load.force_components();
        let tmag = tx.hypot(ty);
        // A zero force keeps its direction (a load path passing through zero under fixed
        // directions constrains the component along the path, not along +x).
        let that = match p.load {
            _ if tmag > 0.0 => (tx / tmag, ty / tmag),
            Load::Force { angle, .. } => (angle.cos(), angle.sin()),
            _ => (1.0, 0.0),
        };
        let dirs = match &p.directions {
            TractionDirections::Free => None,
            TractionDirections::ParallelToForce => Some(vec![that; n]),
            TractionDirections::Fixed(d) => Some(d.clone()),
        };
        let (modes, loads) = match (&dirs, p.load.moment_value()) {
            (None, None) => (vec![Mode::Ex, Mode::Ey], vec![tx, ty]),
            (None, Some(m)) => {
                (vec![Mode::Ex, Mode::Ey, Mode::Rot(centre.0, centre.1)], vec![tx, ty, m])
            }
            (Some(_), Some(m)) => (vec![Mode::Rot(centre.0, centre.1)], vec![m]),
            (Some(_), None) => (vec![Mode::Along(that.0, that.1)], vec![tmag]),
        };
        let k0 = op.self_term();
        Self {
            p,
            op,
            scratch,
            n,
            area: g.element_area(),
            cap,
            dirs,
            modes,
            loads,
            centre,
            k0,
            rho: 2.0 / (k0[0] + k0[2]),
            products: 0,
            prec: TensorConvolution::inverse_symbol(g, &p.compliance(), k0[0]).ok(),
            wx: vec![0.0; n],
            wy: vec![0.0; n],
            vx: vec![0.0; n],
            vy: vec![0.0; n],
            dux: vec![0.0; n],
            duy: vec![0.0; n],
        }
    }

    /// $\mathbf u = K*\mathbf q$ into `(ux, uy)`.
    fn product(&mut self, qx: &[f64], qy: &[f64], ux: &mut [f64], uy: &mut [f64]) {
        self.op.apply(qx, qy, ux, uy, self.scratch);
        self.products += 1;
    }

    /// The state's displacement: $K*\mathbf q$ plus the prescribed $\mathbf u^0$, if any
    /// (linear products of search directions use [`Solver::product`] alone).
    fn state_product(&mut self, qx: &[f64], qy: &[f64], ux: &mut [f64], uy: &mut [f64]) {
        self.product(qx, qy, ux, uy);
        if let Some(u0) = self.p.prescribed {
            for ((a, b), u) in ux.iter_mut().zip(uy.iter_mut()).zip(u0) {
                *a += u.0;
                *b += u.1;
            }
        }
    }

    /// Rigid motion at element k for mode coefficients `mv`.
    #[inline]
    fn rigid(&self, mv: &[f64], k: usize) -> (f64, f64) {
        let (x, y) = (self.p.grid.x[k], self.p.grid.y[k]);
        let mut w = (0.0, 0.0);
        for (m, c) in self.modes.iter().zip(mv) {
            let v = m.at(x, y);
            w.0 += c * v.0;
            w.1 += c * v.1;
        }
        w
    }

    /// Project a vector on element k's admitted space.
    #[inline]
    fn proj(&self, k: usize, v: (f64, f64)) -> (f64, f64) {
        match &self.dirs {
            None => v,
            Some(d) => {
                let t = d[k];
                let s = t.0 * v.0 + t.1 * v.1;
                (s * t.0, s * t.1)
            }
        }
    }

    /// Capacity-weighted starting traction meeting the load constraints:
    /// $\mathbf q_k = c_k\,\Pi_k\sum_j\alpha_j\mathbf m_j(\mathbf x_k)$, clamped to the disc.
    fn initial(&self) -> (Vec<f64>, Vec<f64>) {
        let g = self.p.grid;
        let nm = self.modes.len();
        let mut gram = [[0.0; 3]; 3];
        for k in 0..self.n {
            let pm: Vec<(f64, f64)> =
                self.modes.iter().map(|m| self.proj(k, m.at(g.x[k], g.y[k]))).collect();
            for i in 0..nm {
                for j in 0..nm {
                    gram[i][j] += self.area * self.cap[k] * (pm[i].0 * pm[j].0 + pm[i].1 * pm[j].1);
                }
            }
        }
        let alpha = small_spd_solve(&gram, nm, &self.loads).unwrap_or([0.0; 3]);
        let mut qx = vec![0.0; self.n];
        let mut qy = vec![0.0; self.n];
        for k in 0..self.n {
            let mut v = (0.0, 0.0);
            for (m, a) in self.modes.iter().zip(&alpha) {
                let w = m.at(g.x[k], g.y[k]);
                v.0 += a * w.0;
                v.1 += a * w.1;
            }
            let v = self.proj(k, v);
            let (mut a, mut b) = (self.cap[k] * v.0, self.cap[k] * v.1);
            let r = a.hypot(b);
            if r > self.cap[k] {
                a *= self.cap[k] / r;
                b *= self.cap[k] / r;
            }
            qx[k] = a;
            qy[k] = b;
        }
        (qx, qy)
    }

    /// Relative complementarity residual and relative load residual of a state.
    /// Summed in the fixed blocks of [`Reducer`] (in parallel), so the value does not depend
    /// on the number of threads.
    fn residuals(
        &self,
        red: &mut Reducer,
        qx: &[f64],
        qy: &[f64],
        ux: &[f64],
        uy: &[f64],
        mv: &[f64],
    ) -> (f64, f64) {
        let [rr, qq, _] = red.reduce(self.n, |range| {
            let (mut rr, mut qq) = (0.0, 0.0);
            for k in range {
                let w = self.rigid(mv, k);
                let s = self.proj(k, (w.0 - ux[k], w.1 - uy[k]));
                let z = (qx[k] + self.rho * s.0, qy[k] + self.rho * s.1);
                let zr = norm(z.0, z.1);
                let pz = if zr > self.cap[k] {
                    let f = self.cap[k] / zr;
                    (z.0 * f, z.1 * f)
                } else {
                    z
                };
                rr += (qx[k] - pz.0).powi(2) + (qy[k] - pz.1).powi(2);
                qq += qx[k] * qx[k] + qy[k] * qy[k];
            }
            [rr, qq, 0.0]
        });
        let res = if qq > 0.0 { (rr / qq).sqrt() } else { rr.sqrt() };
        (res, self.load_residual(qx, qy))
    }

    /// The load error relative to the larger of the load and the sum of the tractions'
    /// absolute contributions to it. The two are equal when every cell pushes the same way
    /// (a monotonic load); a self-equilibrated part (the traction a reversal locks in) makes
    /// the sum the larger, and the rounding of that sum (its ulp) is what an error can be
    /// measured against. Continuous at zero load: a load of 1e-14 N on locked-in tractions
    /// of 480 N is held to the same absolute accuracy as a load of exactly zero.
    fn load_residual(&self, qx: &[f64], qy: &[f64]) -> f64 {
        let (got, scale) = self.load_values(qx, qy);
        self.load_error(&got, scale)
    }

    /// [`Solver::load_residual`] from the load values and their scale
    /// ([`Solver::load_values`]).
    fn load_error(&self, got: &[f64], scale: f64) -> f64 {
        let lnorm = self.loads.iter().map(|l| l * l).sum::<f64>().sqrt();
        let err = got.iter().zip(&self.loads).map(|(a, b)| (a - b).powi(2)).sum::<f64>().sqrt();
        err / lnorm.max(scale).max(f64::MIN_POSITIVE)
    }

    /// $h_xh_y\sum_k\mathbf m_j\cdot\mathbf q_k$ per mode, and a magnitude scale.
    /// Summed in fixed blocks of [`REDUCE_CHUNK`] elements (in parallel), the block sums
    /// added in order.
    fn load_values(&self, qx: &[f64], qy: &[f64]) -> (Vec<f64>, f64) {
        let g = self.p.grid;
        let nm = self.modes.len();
        let parts: Vec<[f64; 4]> = (0..self.n.div_ceil(REDUCE_CHUNK))
            .into_par_iter()
            .map(|b| {
                let mut acc = [0.0; 4];
                for k in b * REDUCE_CHUNK..((b + 1) * REDUCE_CHUNK).min(self.n) {
                    for (j, m) in self.modes.iter().enumerate() {
                        let v = m.at(g.x[k], g.y[k]);
                        let t = self.area * (v.0 * qx[k] + v.1 * qy[k]);
                        acc[j] += t;
                        acc[3] += t.abs();
                    }
                }
                acc
            })
            .collect();
        let total = parts
            .iter()
            .fold([0.0; 4], |a, b| [a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]]);
        (total[..nm].to_vec(), total[3])
    }

    /// Element tractions projected on the admitted directions and clamped to the discs.
    fn admissible(&self, t: &[(f64, f64)]) -> (Vec<f64>, Vec<f64>) {
        (0..self.n)
            .into_par_iter()
            .map(|k| {
                let (a, b) = self.proj(k, t[k]);
                let r = norm(a, b);
                let f = if r > self.cap[k] { self.cap[k] / r } else { 1.0 };
                if r.is_finite() {
                    (a * f, b * f)
                } else {
                    (0.0, 0.0)
                }
            })
            .unzip()
    }

    /// Mode coefficients of a rigid shift and rotation (the inverse of
    /// [`Solver::shift_rotation`]).
    fn mode_coefficients(&self, shift: (f64, f64), rotation: f64) -> Vec<f64> {
        self.modes
            .iter()
            .map(|m| match m {
                Mode::Ex => shift.0,
                Mode::Ey => shift.1,
                Mode::Rot(..) => rotation,
                Mode::Along(tx, ty) => shift.0 * tx + shift.1 * ty,
            })
            .collect()
    }

    /// Run the iteration from the capacity-weighted start (`None`) or from a warm start.
    pub(super) fn run(mut self, start: Option<&WarmStart>) -> Result<FastSolution> {
        let t0 = Instant::now();
        let n = self.n;
        let g = self.p.grid;
        let tol = self.p.config.tolerance().rel();
        if let Some(s) = self.trivial_or_gross()? {
            return Ok(s);
        }
        let mut ux = vec![0.0; n];
        let mut uy = vec![0.0; n];
        let (mut qx, mut qy, mut mv, mut first) = match start {
            None => {
                let (qx, qy) = self.initial();
                (qx, qy, vec![0.0; self.modes.len()], true)
            }
            Some(w) => {
                let (qx, qy) = self.admissible(&w.traction);
                (qx, qy, self.mode_coefficients(w.shift, w.rotation), true)
            }
        };
        let mut stick = vec![true; n];
        let mut iterations = 0usize;
        let mut cg_total = 0usize;
        let mut res = f64::INFINITY;
        let mut load_res;
        let incremental = self.p.increment && start.is_some();
        let mut best = f64::INFINITY;
        let mut tighten = 1.0;
        let mut nvec: Vec<(f64, f64)> = vec![(0.0, 0.0); n];
        // The traction change of the classification's projection (after the first step).
        let mut dqx = vec![0.0; n];
        let mut dqy = vec![0.0; n];
        // The Newton system's and the PCG's buffers, reused from step to step.
        let mut work = Work::default();
        let mut red = Reducer::new(n);
        loop {
            // Whether no element changed between stick and slip in this classification.
            let mut settled = !first;
            // Classification and projection of the slip elements; `moved`: some traction
            // changed in the projection.
            let mut moved = false;
            if !first {
                let (same, m) = self.classify(
                    &mv,
                    (&ux, &uy),
                    (&mut qx, &mut qy),
                    &mut stick,
                    &mut nvec,
                    (&mut dqx, &mut dqy),
                );
                settled &= same;
                moved = m;
            } else if let Some(w) = start {
                // Warm start: the start's stick/slip state is the first active set, each slip
                // element at its capacity along the start's traction. The first Newton step
                // then finds the traction and rigid motion consistent with it on this grid
                // (classifying by the start's slip instead is fragile when the start comes
                // from another lattice, whose displacements differ by the discretisation).
                for k in 0..n {
                    let r = qx[k].hypot(qy[k]);
                    let slipping = w.state.get(k) == Some(&ElementState::Slip) && r > 0.0;
                    stick[k] = self.cap[k] > 0.0 && !slipping;
                    if self.cap[k] == 0.0 {
                        qx[k] = 0.0;
                        qy[k] = 0.0;
                    } else if slipping {
                        let nk = (qx[k] / r, qy[k] / r);
                        nvec[k] = nk;
                        qx[k] = self.cap[k] * nk.0;
                        qy[k] = self.cap[k] * nk.1;
                    }
                }
            } else {
                for k in 0..n {
                    stick[k] = self.cap[k] > 0.0;
                    if !stick[k] {
                        qx[k] = 0.0;
                        qy[k] = 0.0;
                    }
                }
            }
            // Once the active set has stopped moving, the displacement is not renewed here:
            // the projection's change dq (then only the slip cells' return to their discs,
            // second order in the step) rides along with the PCG's start product,
            // K (dq + P x0), so the right-hand side P^T s is exact from the start residual
            // on. Only the slip cells' D_k = n.s / c (the curvature of their discs) are
            // taken at the displacement before the projection, which then differs from the
            // exact one by K dq. While cells still change state, dq is first order and that
            // approximation cost Newton steps (measured: 4 -> 5 on the shipped 256-across
            // sphere), so those steps renew the displacement with a product of their own.
            if !settled {
                self.state_product(&qx, &qy, &mut ux, &mut uy);
            }
            // Newton system.
            self.system(&mut work, &stick, &nvec, &mv, (&ux, &uy));
            let (have, scale) = self.load_values(&qx, &qy);
            // Once the load is met far inside the tolerance (after the first step of an
            // increment), the step keeps it (b = 0) and the PCG saves the product of its
            // load-correcting start.
            let b: Vec<f64> =
                if incremental && !first && self.load_error(&have, scale) <= 1e-3 * tol {
                    vec![0.0; self.loads.len()]
                } else {
                    self.loads.iter().zip(&have).map(|(l, h)| (l - h) / self.area).collect()
                };
            // Inner (CG) tolerance, relative to the projected residual's start, in the manner
            // of Eisenstat and Walker: the outer residual itself while that is large (the
            // forcing term of Dembo, Eisenstat & Steihaug that keeps Newton's convergence
            // quadratic; early steps only need the active set to move the right way, and
            // while it moves the residual falls by about ten whatever the inner accuracy:
            // measured 4.8e-3 -> 4.3e-4 at 512 across with eta 4.8e-4 and with 4.8e-3, 18
            // and 13 CG), and near the target no more than takes it below the tolerance (once
            // the active set has settled a Newton step is exact up to the linear solve, so
            // the residual falls by about eta); kept in [1e-6, 1e-2], and tightened further
            // whenever the residual failed to decrease (inexact steps can make the active set
            // wander).
            let eta = res.max(0.3 * tol / res).clamp(1e-6, 1e-2) * tighten;
            let qnorm = red.sum(n, |r| r.map(|k| qx[k] * qx[k] + qy[k] * qy[k]).sum()).sqrt();
            let abs_floor = 0.05 * tol * qnorm;
            let (dm, its) = self
                .pcg(&mut work, &b, (settled && moved).then_some((&dqx, &dqy)), eta, abs_floor)
                .map_err(|e| match e {
                    Error::NoStickLeft { solver, load, free_components, .. } => {
                        Error::NoStickLeft {
                            solver,
                            load,
                            iteration: iterations + 1,
                            free_components,
                        }
                    }
                    e => e,
                })?;
            cg_total += its;
            let (dofs, dof_first, x) = (&work.dofs, &work.first, &work.x);
            qx.par_iter_mut().zip(qy.par_iter_mut()).enumerate().for_each(|(k, (a, b))| {
                for i in dof_first[k]..dof_first[k + 1] {
                    *a += x[i] * dofs[i].e.0;
                    *b += x[i] * dofs[i].e.1;
                }
            });
            for (m, d) in mv.iter_mut().zip(&dm) {
                *m += d;
            }
            // The step's displacement came with the PCG's products (the displacement is
            // linear in the traction); the state is certified below with a product of its own.
            ux.par_iter_mut()
                .zip(uy.par_iter_mut())
                .zip(self.dux.par_iter().zip(&self.duy))
                .for_each(|((a, b), (da, db))| {
                    *a += da;
                    *b += db;
                });
            iterations += 1;
            let (mut r, mut lr) = self.residuals(&mut red, &qx, &qy, &ux, &uy, &mv);
            if r <= tol && lr <= tol {
                // Certification: the residual of the state's own product, not of the
                // accumulated one (which carries the rounding of every CG update).
                self.state_product(&qx, &qy, &mut ux, &mut uy);
                (r, lr) = self.residuals(&mut red, &qx, &qy, &ux, &uy, &mv);
            }
            if r >= best {
                tighten = (tighten * 0.01).max(1e-6);
            }
            best = best.min(r);
            res = r;
            load_res = lr;
            if res <= tol && load_res <= tol {
                break;
            }
            if iterations >= self.p.config.max_iterations() {
                return Err(Error::NotConverged {
                    solver: SOLVER_NAME,
                    iterations,
                    residual: res.max(load_res),
                    tolerance: tol,
                });
            }
            first = false;
        }

        // Final state.
        let (state, slip): (Vec<ElementState>, Vec<(f64, f64)>) = (0..n)
            .into_par_iter()
            .map(|k| {
                let w = self.rigid(&mv, k);
                let s = self.proj(k, (w.0 - ux[k], w.1 - uy[k]));
                let z = (qx[k] + self.rho * s.0, qy[k] + self.rho * s.1);
                let st = if norm(z.0, z.1) > self.cap[k] && self.cap[k] > 0.0
                    || self.cap[k] == 0.0 && norm(s.0, s.1) > 0.0
                {
                    ElementState::Slip
                } else {
                    ElementState::Stick
                };
                (st, s)
            })
            .unzip();
        let n_slip = state.iter().filter(|s| **s == ElementState::Slip).count();
        let regime = if n_slip == 0 { Regime::FullStick } else { Regime::PartialSlip };
        let (shift, rotation) = self.shift_rotation(&mv);
        let (resultant, moment) = resultant_moment(g, &qx, &qy, self.centre);
        let info = FastInfo {
            iterations,
            cg_iterations: cg_total,
            products: self.products,
            residual: res,
            load_residual: load_res,
            solve_seconds: t0.elapsed().as_secs_f64(),
            setup_seconds: 0.0,
            fft_size: self.op.fft_size(),
            levels: 0,
            coarse_seconds: 0.0,
        };
        Ok(FastSolution {
            regime,
            traction: qx.par_iter().zip(&qy).map(|(a, b)| (*a, *b)).collect(),
            state,
            slip,
            displacement: ux.par_iter().zip(&uy).map(|(a, b)| (*a, *b)).collect(),
            shift,
            rotation,
            centre: self.centre,
            resultant,
            moment,
            info,
        })
    }

    /// The classification of a Newton step (after the first) at the state `q`, `u`, `mv`:
    /// an element with $|\mathbf q_k + \rho\,\mathbf s_k| \le c_k$ sticks, the others slip
    /// and their traction is projected on the disc along that vector (its unit vector in
    /// `nvec`); `dq` gets each element's traction change. In parallel over fixed blocks,
    /// each element on its own. Returns whether no element changed between stick and slip,
    /// and whether any traction changed.
    fn classify(
        &self,
        mv: &[f64],
        (ux, uy): (&[f64], &[f64]),
        (qx, qy): (&mut [f64], &mut [f64]),
        stick: &mut [bool],
        nvec: &mut [(f64, f64)],
        (dqx, dqy): (&mut [f64], &mut [f64]),
    ) -> (bool, bool) {
        const C: usize = REDUCE_CHUNK;
        qx.par_chunks_mut(C)
            .zip(qy.par_chunks_mut(C))
            .zip(stick.par_chunks_mut(C).zip(nvec.par_chunks_mut(C)))
            .zip(dqx.par_chunks_mut(C).zip(dqy.par_chunks_mut(C)))
            .enumerate()
            .map(|(blk, (((qx, qy), (stick, nvec)), (dqx, dqy)))| {
                let (mut same, mut moved) = (true, false);
                for o in 0..qx.len() {
                    let k = blk * C + o;
                    let w = self.rigid(mv, k);
                    let s = self.proj(k, (w.0 - ux[k], w.1 - uy[k]));
                    let z = (qx[o] + self.rho * s.0, qy[o] + self.rho * s.1);
                    let zr = norm(z.0, z.1);
                    let old = (qx[o], qy[o]);
                    let was_stick = stick[o];
                    if self.cap[k] == 0.0 {
                        stick[o] = false;
                        qx[o] = 0.0;
                        qy[o] = 0.0;
                    } else if zr <= self.cap[k] {
                        stick[o] = true;
                    } else {
                        stick[o] = false;
                        let nk = (z.0 / zr, z.1 / zr);
                        nvec[o] = nk;
                        qx[o] = self.cap[k] * nk.0;
                        qy[o] = self.cap[k] * nk.1;
                    }
                    dqx[o] = qx[o] - old.0;
                    dqy[o] = qy[o] - old.1;
                    moved |= dqx[o] != 0.0 || dqy[o] != 0.0;
                    same &= stick[o] == was_stick;
                }
                (same, moved)
            })
            .reduce(|| (true, false), |a, b| (a.0 && b.0, a.1 || b.1))
    }

    /// The Newton system at the state `u`, `mv` with the active set `stick` (slip elements
    /// along `nvec`), into `w`: the free components (dofs, in element order: both axes of a
    /// stick element, or its admitted direction; the tangent of a slip element with
    /// capacity), each element's dof range, $D$ and the right-hand side $P^{\mathsf T}\mathbf
    /// s$. Two passes over fixed blocks of elements, in parallel: the blocks' dof counts
    /// (their offsets follow in order), then each block fills its own range.
    fn system(
        &self,
        w: &mut Work,
        stick: &[bool],
        nvec: &[(f64, f64)],
        mv: &[f64],
        (ux, uy): (&[f64], &[f64]),
    ) {
        const C: usize = REDUCE_CHUNK;
        let n = self.n;
        let count = |k: usize| match (&self.dirs, stick[k]) {
            (None, true) => 2,
            (Some(_), true) => 1,
            (None, false) if self.cap[k] > 0.0 => 1,
            _ => 0,
        };
        (0..n.div_ceil(C))
            .into_par_iter()
            .map(|b| (b * C..((b + 1) * C).min(n)).map(count).sum::<usize>())
            .collect_into_vec(&mut w.blocks);
        let total: usize = w.blocks.iter().sum();
        w.dofs.resize(total, Dof::default());
        w.diag_d.resize(total, 0.0);
        w.rhs.resize(total, 0.0);
        w.first.resize(n + 1, 0);
        w.first[n] = total;
        // Each block's slices of the dof arrays and of `first`, with its first dof's index.
        let mut parts = Vec::with_capacity(w.blocks.len());
        let (mut dofs, mut dd, mut rhs) = (&mut w.dofs[..], &mut w.diag_d[..], &mut w.rhs[..]);
        let mut first = &mut w.first[..n];
        let mut offset = 0;
        for (b, &len) in w.blocks.iter().enumerate() {
            let (d0, d1) = std::mem::take(&mut dofs).split_at_mut(len);
            let (e0, e1) = std::mem::take(&mut dd).split_at_mut(len);
            let (r0, r1) = std::mem::take(&mut rhs).split_at_mut(len);
            let (f0, f1) = std::mem::take(&mut first).split_at_mut(C.min(n - b * C));
            (dofs, dd, rhs, first) = (d1, e1, r1, f1);
            parts.push((b, offset, d0, e0, r0, f0));
            offset += len;
        }
        parts.into_par_iter().for_each(|(b, offset, dofs, dd, rhs, first)| {
            let mut i = 0;
            for (o, f) in first.iter_mut().enumerate() {
                let k = b * C + o;
                *f = offset + i;
                let w = self.rigid(mv, k);
                let s = self.proj(k, (w.0 - ux[k], w.1 - uy[k]));
                let st = stick[k];
                let mut push = |e: (f64, f64), d: f64| {
                    dofs[i] = Dof { k: k as u32, e, stick: st };
                    dd[i] = d;
                    rhs[i] = e.0 * s.0 + e.1 * s.1;
                    i += 1;
                };
                match (&self.dirs, st) {
                    (None, true) => {
                        push((1.0, 0.0), 0.0);
                        push((0.0, 1.0), 0.0);
                    }
                    (Some(d), true) => push(d[k], 0.0),
                    (None, false) if self.cap[k] > 0.0 => {
                        let nk = nvec[k];
                        let ns = (nk.0 * s.0 + nk.1 * s.1).max(0.0);
                        push((-nk.1, nk.0), ns / self.cap[k]);
                    }
                    _ => {}
                }
            }
        });
    }

    /// Shift and rotation from the mode coefficients.
    fn shift_rotation(&self, mv: &[f64]) -> ((f64, f64), f64) {
        let mut shift = (0.0, 0.0);
        let mut rot = 0.0;
        for (m, c) in self.modes.iter().zip(mv) {
            match m {
                Mode::Ex => shift.0 += c,
                Mode::Ey => shift.1 += c,
                Mode::Rot(..) => rot += c,
                Mode::Along(tx, ty) => {
                    shift.0 += c * tx;
                    shift.1 += c * ty;
                }
            }
        }
        (shift, rot)
    }

    /// Zero load (zero traction) and gross slip under a force alone (every element at
    /// $c_k$ along the force); loads beyond the capacity are errors.
    fn trivial_or_gross(&mut self) -> Result<Option<FastSolution>> {
        let n = self.n;
        let g = self.p.grid;
        let t0 = Instant::now();
        let all_zero = self.loads.iter().all(|l| *l == 0.0);
        // Capacity of each mode: the largest load the discs can carry in it alone.
        for (j, m) in self.modes.iter().enumerate() {
            let lone = self.loads.iter().enumerate().all(|(i, l)| i == j || *l == 0.0);
            let capj: f64 = (0..n)
                .map(|k| {
                    let v = self.proj(k, m.at(g.x[k], g.y[k]));
                    self.area * self.cap[k] * v.0.hypot(v.1)
                })
                .sum();
            let ratio = self.loads[j].abs() / capj;
            if lone && ratio >= 1.0 - 1e-12 || ratio > 1.0 + 1e-12 {
                let is_force = matches!(m, Mode::Ex | Mode::Ey | Mode::Along(..));
                let force_only = is_force && self.p.load.moment_value().is_none();
                if force_only && ratio <= 1.0 + 1e-12 {
                    break; // gross slip under a force: handled below
                }
                return Err(Error::CapacityExceeded {
                    load: if is_force { LoadKind::Force } else { LoadKind::Moment },
                    requested: self.loads[j].abs(),
                    capacity: capj,
                });
            }
        }
        let (tx, ty) = self.p.load.force_components();
        let tmag = tx.hypot(ty);
        let fcap: f64 = self.cap.iter().map(|c| c * self.area).sum();
        let gross = self.p.load.moment_value().is_none() && tmag >= fcap * (1.0 - 1e-12);
        if gross && tmag > fcap * (1.0 + 1e-12) {
            return Err(Error::CapacityExceeded {
                load: LoadKind::Force,
                requested: tmag,
                capacity: fcap,
            });
        }
        // A prescribed displacement drives traction even at zero load.
        if (!all_zero || self.p.prescribed.is_some()) && !gross {
            return Ok(None);
        }
        let that = if tmag > 0.0 { (tx / tmag, ty / tmag) } else { (1.0, 0.0) };
        let mut qx = vec![0.0; n];
        let mut qy = vec![0.0; n];
        if gross {
            for k in 0..n {
                let v = self.proj(k, that);
                let r = v.0.hypot(v.1);
                if r > 0.0 {
                    qx[k] = self.cap[k] * v.0 / r;
                    qy[k] = self.cap[k] * v.1 / r;
                }
            }
        }
        let mut ux = vec![0.0; n];
        let mut uy = vec![0.0; n];
        self.state_product(&qx.clone(), &qy.clone(), &mut ux, &mut uy);
        // Onset of sliding: the rigid shift along T that first makes every slip non-negative.
        let beta = if gross {
            (0..n).map(|k| that.0 * ux[k] + that.1 * uy[k]).fold(f64::NEG_INFINITY, f64::max)
        } else {
            0.0
        };
        let shift = (beta * that.0, beta * that.1);
        let slip: Vec<(f64, f64)> =
            (0..n).map(|k| self.proj(k, (shift.0 - ux[k], shift.1 - uy[k]))).collect();
        let state = vec![if gross { ElementState::Slip } else { ElementState::Stick }; n];
        let (resultant, moment) = resultant_moment(g, &qx, &qy, self.centre);
        Ok(Some(FastSolution {
            regime: if gross { Regime::GrossSlip } else { Regime::FullStick },
            traction: qx.iter().zip(&qy).map(|(a, b)| (*a, *b)).collect(),
            state,
            slip,
            displacement: ux.iter().zip(&uy).map(|(a, b)| (*a, *b)).collect(),
            shift,
            rotation: 0.0,
            centre: self.centre,
            resultant,
            moment,
            info: FastInfo {
                iterations: 0,
                cg_iterations: 0,
                products: self.products,
                residual: 0.0,
                load_residual: self.load_residual(&qx, &qy),
                solve_seconds: t0.elapsed().as_secs_f64(),
                setup_seconds: 0.0,
                fft_size: self.op.fft_size(),
                levels: 0,
                coarse_seconds: 0.0,
            },
        }))
    }
}
