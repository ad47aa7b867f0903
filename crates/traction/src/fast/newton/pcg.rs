//! The linear algebra inside a Newton step of the fast solver: the Newton matrix
//! $H = P^{\mathsf T}KP + D$ applied with one FFT product, the preconditioner $G$ (Fourier on
//! the stick components, Jacobi on the rest), the preconditioned projected conjugate
//! gradients for the step with the load constraints, and deterministic parallel sums.

use super::{Dof, Solver};
use crate::error::{Error, Result};
use crate::fast::solver::SOLVER_NAME;
use rayon::prelude::*;

// Index loops read best for a 3 x 3 Cholesky factorisation.
#[allow(clippy::needless_range_loop)]
/// Small dense Cholesky solve for the $\le 3$ load constraints; `None` if not positive
/// definite (relative pivot below $10^{-13}$).
pub(super) fn small_spd_solve(a: &[[f64; 3]; 3], m: usize, b: &[f64]) -> Option<[f64; 3]> {
    let mut l = [[0.0; 3]; 3];
    let scale = (0..m).map(|i| a[i][i].abs()).fold(0.0, f64::max);
    for i in 0..m {
        for j in 0..=i {
            let mut s = a[i][j];
            for p in 0..j {
                s -= l[i][p] * l[j][p];
            }
            if i == j {
                if s.is_nan() || s <= 1e-13 * scale {
                    return None;
                }
                l[i][i] = s.sqrt();
            } else {
                l[i][j] = s / l[j][j];
            }
        }
    }
    let mut y = [0.0; 3];
    for i in 0..m {
        let mut s = b[i];
        for p in 0..i {
            s -= l[i][p] * y[p];
        }
        y[i] = s / l[i][i];
    }
    let mut x = [0.0; 3];
    for i in (0..m).rev() {
        let mut s = y[i];
        for p in i + 1..m {
            s -= l[p][i] * x[p];
        }
        x[i] = s / l[i][i];
    }
    Some(x)
}

impl Solver<'_, '_> {
    /// $H x$ with $H = P^{\mathsf T}KP + D$; `first[k]..first[k + 1]` are the dofs of
    /// element $k$ (dofs are in element order). With `extra` = $\Delta\mathbf q$ (element
    /// tractions), $P^{\mathsf T}K(Px + \Delta\mathbf q) + Dx$ in the same product.
    #[allow(clippy::too_many_arguments)]
    fn h_apply(
        &mut self,
        dofs: &[Dof],
        first: &[usize],
        diag_d: &[f64],
        x: &[f64],
        extra: Option<(&[f64], &[f64])>,
        out: &mut [f64],
    ) {
        let mut px = std::mem::take(&mut self.wx);
        let mut py = std::mem::take(&mut self.wy);
        let mut vx = std::mem::take(&mut self.vx);
        let mut vy = std::mem::take(&mut self.vy);
        px.par_iter_mut().zip(py.par_iter_mut()).enumerate().for_each(|(k, (a, b))| {
            let (mut sa, mut sb) = (0.0, 0.0);
            for i in first[k]..first[k + 1] {
                sa += x[i] * dofs[i].e.0;
                sb += x[i] * dofs[i].e.1;
            }
            if let Some((ex, ey)) = extra {
                sa += ex[k];
                sb += ey[k];
            }
            *a = sa;
            *b = sb;
        });
        self.product(&px, &py, &mut vx, &mut vy);
        out.par_iter_mut().zip(dofs.par_iter()).zip(diag_d.par_iter().zip(x.par_iter())).for_each(
            |((o, d), (dd, xv))| *o = d.e.0 * vx[d.k as usize] + d.e.1 * vy[d.k as usize] + dd * xv,
        );
        self.wx = px;
        self.wy = py;
        self.vx = vx;
        self.vy = vy;
    }

    /// $z = G^{-1} r$: the Fourier preconditioner $M$ on every component, each scaled by its
    /// weight $w_i$, plus the weighted Jacobi term on the slip tangents,
    /// $G^{-1} = W P^{\mathsf T} M P W + c\,(I - W^2)\,J$ (see [`SLIP_JACOBI`]), or Jacobi
    /// throughout when no Fourier preconditioner is planned. Stick components have
    /// $w_i = 1$, so their block is the Fourier inverse unchanged.
    fn g_apply(
        &mut self,
        dofs: &[Dof],
        first: &[usize],
        minv: &[f64],
        wt: &[f64],
        r: &[f64],
        z: &mut [f64],
    ) {
        let Some(op) = &self.prec else {
            z.par_iter_mut().zip(minv.par_iter().zip(r.par_iter())).for_each(|(z, (m, r))| {
                *z = m * r;
            });
            return;
        };
        let (px, py, vx, vy) = (&mut self.wx, &mut self.wy, &mut self.vx, &mut self.vy);
        px.par_iter_mut().zip(py.par_iter_mut()).enumerate().for_each(|(k, (a, b))| {
            let (mut sa, mut sb) = (0.0, 0.0);
            for i in first[k]..first[k + 1] {
                let v = wt[i] * r[i];
                sa += v * dofs[i].e.0;
                sb += v * dofs[i].e.1;
            }
            *a = sa;
            *b = sb;
        });
        op.apply(px, py, vx, vy, self.scratch);
        let (vx, vy) = (&*vx, &*vy);
        z.par_iter_mut()
            .zip(dofs.par_iter().zip(wt.par_iter()))
            .zip(minv.par_iter().zip(r.par_iter()))
            .for_each(|((z, (d, w)), (m, r))| {
                let fourier = w * (d.e.0 * vx[d.k as usize] + d.e.1 * vy[d.k as usize]);
                *z = if d.stick { fourier } else { fourier + SLIP_JACOBI * (1.0 - w * w) * m * r };
            });
    }

    /// Preconditioned projected CG for
    /// $Hx - B^{\mathsf T}\lambda = \text{rhs},\ Bx = b$ (Gould, Hribar & Nocedal 2001,
    /// Algorithm II with a constraint preconditioner $G$: $\mathrm{diag}(H)$, or the Fourier
    /// preconditioner on the stick block). Stops when the projected preconditioned residual
    /// falls below `eta` times its start or below `abs_floor` (traction units). Returns $x$,
    /// $\lambda$ (the rigid-mode increments) and the iteration count. With `dq`, the state's
    /// traction has changed by $\Delta\mathbf q$ since `rhs` was evaluated: the start
    /// residual is $\text{rhs} - P^{\mathsf T}K\Delta\mathbf q - Hx_0$, from one product.
    /// The displacement of the step, $K(\Delta\mathbf q + Px)$, is left in `dux`, `duy`.
    #[allow(clippy::too_many_arguments, clippy::needless_range_loop)]
    pub(super) fn pcg(
        &mut self,
        dofs: &[Dof],
        diag_d: &[f64],
        rhs: &[f64],
        b: &[f64],
        dq: Option<(&[f64], &[f64])>,
        eta: f64,
        abs_floor: f64,
    ) -> Result<(Vec<f64>, Vec<f64>, usize)> {
        let g = self.p.grid;
        let nd = dofs.len();
        let nm = self.modes.len();
        // Element -> dof ranges (dofs come in element order).
        let mut first = vec![0usize; self.n + 1];
        for d in dofs {
            first[d.k as usize + 1] += 1;
        }
        for k in 0..self.n {
            first[k + 1] += first[k];
        }
        let modes = self.modes.clone();
        // Constraint row j at dof d: B_jd = m_j(x_k) . e_d.
        let mut red = Reducer::new(nd);
        // The constraint rows, evaluated once: the projection streams them at every CG step.
        let rows: Vec<[f64; 3]> = dofs
            .par_iter()
            .map(|d| {
                let mut row = [0.0; 3];
                for (j, m) in modes.iter().enumerate() {
                    let v = m.at(g.x[d.k as usize], g.y[d.k as usize]);
                    row[j] = v.0 * d.e.0 + v.1 * d.e.1;
                }
                row
            })
            .collect();
        let k0 = self.k0;
        // Jacobi values 1/(K_dd(0) + D_d) and the preconditioner's weights
        // w_d = 1 / sqrt(1 + (D_d / K_dd(0))^2) (1 on stick components).
        let (minv, wt): (Vec<f64>, Vec<f64>) = dofs
            .par_iter()
            .zip(diag_d.par_iter())
            .map(|(d, dd)| {
                let kd = d.e.0 * (k0[0] * d.e.0 + k0[1] * d.e.1)
                    + d.e.1 * (k0[1] * d.e.0 + k0[2] * d.e.1);
                let m = 1.0 / (kd + dd);
                let x = dd / kd;
                (m, if d.stick { 1.0 } else { (1.0 + x * x).sqrt().recip() })
            })
            .unzip();
        // G^-1 b_j and W = B G^-1 B^T.
        let mut gb: Vec<Vec<f64>> = Vec::with_capacity(nm);
        for j in 0..nm {
            let bj: Vec<f64> = rows.par_iter().map(|row| row[j]).collect();
            let mut y = vec![0.0; nd];
            self.g_apply(dofs, &first, &minv, &wt, &bj, &mut y);
            gb.push(y);
        }
        let mut w = [[0.0; 3]; 3];
        for i in 0..nm {
            for j in 0..nm {
                let gj = &gb[j];
                w[i][j] = red.sum(nd, |r| r.map(|k| rows[k][i] * gj[k]).sum());
            }
        }
        // Symmetrise (G^-1 is symmetric up to rounding).
        for i in 0..nm {
            for j in 0..i {
                let v = 0.5 * (w[i][j] + w[j][i]);
                w[i][j] = v;
                w[j][i] = v;
            }
        }
        let no_stick = || Error::NoStickLeft {
            solver: SOLVER_NAME,
            load: self.p.load.kind(),
            iteration: 0,
            free_components: nd,
        };
        if small_spd_solve(&w, nm, &[1.0; 3][..nm]).is_none() {
            return Err(no_stick());
        }
        // Projection: y = G^-1 r, l = W^-1 B y, r <- r - B^T l, z = y - G^-1 B^T l. The
        // residual itself is replaced by r - B^T l (the "residual update" of Gould, Hribar &
        // Nocedal, §6): it leaves the iteration unchanged in exact arithmetic and keeps z in
        // the null space of B to rounding; the l are summed into the multiplier. Returns
        // (r.z, |z|^2).
        let mut y = vec![0.0; nd];
        let mut project = |this: &mut Self,
                           red: &mut Reducer,
                           r: &mut [f64],
                           z: &mut [f64],
                           acc: &mut [f64; 3]|
         -> Option<(f64, f64)> {
            this.g_apply(dofs, &first, &minv, &wt, r, &mut y);
            let yr = &y;
            let c = red.reduce(nd, |range| {
                let mut c = [0.0; 3];
                for k in range {
                    let row = rows[k];
                    for (cj, rj) in c.iter_mut().zip(row) {
                        *cj += rj * yr[k];
                    }
                }
                c
            });
            let l = small_spd_solve(&w, nm, &c[..nm])?;
            for j in 0..nm {
                acc[j] += l[j];
            }
            let gbr = &gb;
            let yr = &y;
            r.par_chunks_mut(REDUCE_CHUNK)
                .zip(z.par_chunks_mut(REDUCE_CHUNK))
                .enumerate()
                .map(|(c, (rc, zc))| {
                    let mut acc = [0.0; 3];
                    for (o, (rv, zv)) in rc.iter_mut().zip(zc.iter_mut()).enumerate() {
                        let i = c * REDUCE_CHUNK + o;
                        let row = rows[i];
                        *rv -= row[0] * l[0] + row[1] * l[1] + row[2] * l[2];
                        let mut zi = yr[i];
                        for (j, gj) in gbr.iter().enumerate() {
                            zi -= l[j] * gj[i];
                        }
                        *zv = zi;
                        acc[0] += *rv * zi;
                        acc[1] += zi * zi;
                    }
                    acc
                })
                .collect_into_vec(&mut red.parts);
            let [rz, zz, _] = red.total();
            Some((rz, zz))
        };
        // x0 = G^-1 B^T W^-1 b.
        let l0 = small_spd_solve(&w, nm, b).ok_or_else(no_stick)?;
        let mut x: Vec<f64> = (0..nd)
            .into_par_iter()
            .map(|i| gb.iter().zip(&l0).map(|(gj, l)| l * gj[i]).sum())
            .collect();
        // The displacement of the step, K P x, is kept beside x (the displacement is linear
        // in the traction: each CG product K P p also moves it by alpha K P p), so the Newton
        // loop needs no product after the step.
        let mut dux = std::mem::take(&mut self.dux);
        let mut duy = std::mem::take(&mut self.duy);
        // With b = 0 (and no traction change) the start is x0 = 0 and its product is skipped.
        let dq = dq.filter(|(a, b)| a.iter().chain(b.iter()).any(|v| *v != 0.0));
        let mut r: Vec<f64> = if dq.is_none() && b.iter().all(|v| *v == 0.0) {
            dux.par_iter_mut().zip(duy.par_iter_mut()).for_each(|(a, b)| {
                *a = 0.0;
                *b = 0.0;
            });
            rhs.to_vec()
        } else {
            let mut hx = vec![0.0; nd];
            self.h_apply(dofs, &first, diag_d, &x, dq, &mut hx);
            dux.copy_from_slice(&self.vx);
            duy.copy_from_slice(&self.vy);
            rhs.par_iter().zip(hx.par_iter()).map(|(a, b)| a - b).collect()
        };
        let mut z = vec![0.0; nd];
        let mut acc = [0.0; 3];
        let (mut rz, zz) =
            project(self, &mut red, &mut r, &mut z, &mut acc).ok_or_else(no_stick)?;
        let stop = (eta * zz.sqrt()).max(abs_floor);
        let mut znorm = zz.sqrt();
        let mut p = z.clone();
        let mut hp = vec![0.0; nd];
        let mut its = 0;
        while znorm > stop && its < self.p.config.max_cg() {
            self.h_apply(dofs, &first, diag_d, &p, None, &mut hp);
            let php = red.sum(nd, |r| r.map(|k| p[k] * hp[k]).sum());
            if php.is_nan() || php <= 0.0 {
                return Err(Error::NotPositiveDefinite { index: its });
            }
            let alpha = rz / php;
            x.par_iter_mut().zip(r.par_iter_mut()).zip(p.par_iter().zip(hp.par_iter())).for_each(
                |((xv, rv), (pv, hv))| {
                    *xv += alpha * pv;
                    *rv -= alpha * hv;
                },
            );
            let (vx, vy) = (&self.vx, &self.vy);
            dux.par_chunks_mut(REDUCE_CHUNK)
                .zip(duy.par_chunks_mut(REDUCE_CHUNK))
                .zip(vx.par_chunks(REDUCE_CHUNK).zip(vy.par_chunks(REDUCE_CHUNK)))
                .for_each(|((a, b), (va, vb))| {
                    for (((a, b), va), vb) in a.iter_mut().zip(b.iter_mut()).zip(va).zip(vb) {
                        *a += alpha * va;
                        *b += alpha * vb;
                    }
                });
            let (rz_new, zz) =
                project(self, &mut red, &mut r, &mut z, &mut acc).ok_or_else(no_stick)?;
            let beta = rz_new / rz;
            rz = rz_new;
            znorm = zz.sqrt();
            p.par_iter_mut().zip(z.par_iter()).for_each(|(pv, zv)| *pv = zv + beta * *pv);
            its += 1;
        }
        self.dux = dux;
        self.duy = duy;
        // Multipliers: B^T lambda = H x - rhs = -(r + B^T acc). The last projection left r
        // G^-1-orthogonal to B (B G^-1 r = 0 up to rounding), so projecting it once more
        // would add nothing to acc but the cost of a preconditioner application.
        let lam: Vec<f64> = acc[..nm].iter().map(|v| -v).collect();
        Ok((x, lam, its))
    }
}

/// The weight $c$ of the Jacobi term on the slip tangents in the preconditioner
/// $G^{-1} = W P^{\mathsf T} M P W + c\,(I - W^2)\,J$, with
/// $w_d = (1 + (D_d/K_{tt}(0))^2)^{-1/2}$ on a slip tangent and 1 on a stick component.
///
/// A slip tangent's row of the Newton matrix is $K_{tt}(0) + D_d$ on the diagonal plus the
/// elastic coupling to every other component. A slip cell next to the stick zone (slip still
/// small, $D_d \ll K_{tt}(0)$) is coupled to its neighbours as a stick component is, and takes
/// the Fourier inverse ($w_d \approx 1$); far out in the slip zone ($D_d \gg K_{tt}(0)$) its
/// row is nearly diagonal and it takes the Jacobi term ($w_d \approx K_{tt}(0)/D_d$, the
/// Fourier part fading as its square). $M$ grows like $|\mathbf k|$, so it answers a smooth
/// residual with almost nothing: between the two regimes the Jacobi term supplies that smooth
/// part.
///
/// The form of the weight and $c$ were chosen by measurement, CG steps of the Cattaneo sphere
/// at residual $10^{-8}$ (`fast_probe N ratio`, nested start; the 256 and 512 across rows at
/// T/fP = 0.5, 0.9, 0.9999 and 0.99999):
///
/// | preconditioner on the slip tangents | 512 across | 256 across | 1024, 0.5 |
/// |---|---|---|---|
/// | Jacobi alone (before) | 53, 56, 14, 12 | 41, 45, 25, 23 | 75 |
/// | $w^2 = K/(K + D)$, $c = 1/4$ | 21, 21, 36, 53 | 19, 18, 49, 71 | 27 |
/// | $w^2 = K/(K + 4D)$, $c = 0.35$ | 25, 28, 10, 21 | 22, 23, 22, 34 | 36 |
/// | $w^2 = 1/(1 + (D/K)^2)$, $c = 1/4$ (this) | 23, 25, 12, 11 | 21, 20, 22, 21 | 31 |
/// | the same, $c = 0.35$ | 26, 27, 12, 11 | 20, 22, 22, 20 | 34 |
/// | the same, $c = 0.2$ | 26, 25, 12, 11 | 23, —, 24, 20 | — |
///
/// The first weight couples too many cells near gross slip (almost every cell slips, many
/// with $D_d$ near $K_{tt}(0)$), where Jacobi alone is already good; the sharper one keeps
/// the gain at moderate loads and is never worse than Jacobi alone. Other rows with this
/// choice: 24 at 256 across and T/fP = 0.1, 22 at 128 across and 0.3, 33 at 64 across and
/// 0.5 (Jacobi alone: 32 and 39 for the last two).
const SLIP_JACOBI: f64 = 0.25;

/// Block length of the deterministic reductions: the sums of the CG iteration are taken in
/// fixed blocks (in parallel) and the block sums added in order, so a solve gives the same
/// bits whatever the number of threads and however rayon splits the work.
const REDUCE_CHUNK: usize = 4096;

/// Deterministic parallel reductions: `f` over fixed blocks of `0..n` (in parallel), the
/// block results added in order, so the sum does not depend on how rayon splits the work
/// (unlike a rayon `sum`, whose tree follows work stealing). The buffer of block results is
/// reused, so the CG loop does not allocate.
struct Reducer {
    parts: Vec<[f64; 3]>,
}

impl Reducer {
    fn new(n: usize) -> Self {
        Self { parts: Vec::with_capacity(n.div_ceil(REDUCE_CHUNK)) }
    }

    fn reduce(
        &mut self,
        n: usize,
        f: impl Fn(std::ops::Range<usize>) -> [f64; 3] + Sync + Send,
    ) -> [f64; 3] {
        (0..n.div_ceil(REDUCE_CHUNK))
            .into_par_iter()
            .map(|b| f(b * REDUCE_CHUNK..((b + 1) * REDUCE_CHUNK).min(n)))
            .collect_into_vec(&mut self.parts);
        self.total()
    }

    fn sum(&mut self, n: usize, f: impl Fn(std::ops::Range<usize>) -> f64 + Sync + Send) -> f64 {
        self.reduce(n, |r| [f(r), 0.0, 0.0])[0]
    }

    /// The block results in `parts`, added in order.
    fn total(&self) -> [f64; 3] {
        self.parts.iter().fold([0.0; 3], |a, b| [a[0] + b[0], a[1] + b[1], a[2] + b[2]])
    }
}
