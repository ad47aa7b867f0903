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

/// The buffers of the Newton steps of one solve: the Newton system (its dofs in element
/// order, each element's dof range, $D$ and the right-hand side), the increment $x$, and
/// the PCG's vectors. Allocated at the first Newton step and reused by the later ones: a
/// fresh set of zeroed O(n) vectors at every step cost page faults and a memset (about a
/// seventh of a history step at 256 cells across, measured with perf before this change).
/// Every buffer is resized to the step's length and then written in full before it is
/// read, so what a buffer held at the last step never enters this one.
#[derive(Default)]
pub(super) struct Work {
    pub(super) dofs: Vec<Dof>,
    /// `first[k]..first[k + 1]` are element $k$'s dofs; `first[n]` is their count.
    pub(super) first: Vec<usize>,
    pub(super) diag_d: Vec<f64>,
    pub(super) rhs: Vec<f64>,
    /// The Newton increment of the dofs (the PCG's solution).
    pub(super) x: Vec<f64>,
    /// The dof counts of the element blocks, then their offsets (the system build).
    pub(super) blocks: Vec<usize>,
    rows: Vec<[f64; 3]>,
    minv: Vec<f64>,
    wt: Vec<f64>,
    gb: Vec<Vec<f64>>,
    bj: Vec<f64>,
    y: Vec<f64>,
    r: Vec<f64>,
    z: Vec<f64>,
    p: Vec<f64>,
    hp: Vec<f64>,
}

/// Resize `v` to `n` entries without writing those it keeps (for buffers written in full
/// before they are read).
fn sized(v: &mut Vec<f64>, n: usize) {
    v.resize(n, 0.0);
}

impl Solver<'_, '_> {
    /// $H x$ with $H = P^{\mathsf T}KP + D$; `first[k]..first[k + 1]` are the dofs of
    /// element $k$ (dofs are in element order). With `extra` = $\Delta\mathbf q$ (element
    /// tractions), $P^{\mathsf T}K(Px + \Delta\mathbf q) + Dx$ in the same product. Returns
    /// $x\cdot Hx$ (without `extra`'s share: meant for `extra = None`), summed in the fixed
    /// blocks of [`Reducer`] as it is written.
    #[allow(clippy::too_many_arguments)]
    fn h_apply(
        &mut self,
        red: &mut Reducer,
        dofs: &[Dof],
        first: &[usize],
        diag_d: &[f64],
        x: &[f64],
        extra: Option<(&[f64], &[f64])>,
        out: &mut [f64],
    ) -> f64 {
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
        let (ux, uy) = (&vx, &vy);
        out.par_chunks_mut(REDUCE_CHUNK)
            .zip(dofs.par_chunks(REDUCE_CHUNK))
            .zip(diag_d.par_chunks(REDUCE_CHUNK).zip(x.par_chunks(REDUCE_CHUNK)))
            .map(|((oc, dc), (ddc, xc))| {
                let mut s = 0.0;
                for ((o, d), (dd, xv)) in oc.iter_mut().zip(dc).zip(ddc.iter().zip(xc)) {
                    *o = d.e.0 * ux[d.k as usize] + d.e.1 * uy[d.k as usize] + dd * xv;
                    s += xv * *o;
                }
                [s, 0.0, 0.0]
            })
            .collect_into_vec(&mut red.parts);
        self.wx = px;
        self.wy = py;
        self.vx = vx;
        self.vy = vy;
        red.total()[0]
    }

    /// $z = G^{-1} r$: the Fourier preconditioner $M$ on every component, each scaled by its
    /// weight $w_i$, plus the weighted Jacobi term on the slip tangents,
    /// $G^{-1} = W P^{\mathsf T} M P W + c\,(I - W^2)\,J$ (see [`SLIP_JACOBI`]), or Jacobi
    /// throughout when no Fourier preconditioner is planned. Stick components have
    /// $w_i = 1$, so their block is the Fourier inverse unchanged. With `rows`, also returns
    /// $Bz$ (`rows[i][j]` $= B_{ji}$), summed in the fixed blocks of [`Reducer`] as $z$ is
    /// written (zero without).
    #[allow(clippy::too_many_arguments)]
    fn g_apply(
        &mut self,
        red: &mut Reducer,
        dofs: &[Dof],
        first: &[usize],
        minv: &[f64],
        wt: &[f64],
        rows: Option<&[[f64; 3]]>,
        r: &[f64],
        z: &mut [f64],
    ) -> [f64; 3] {
        let Some(op) = &self.prec else {
            return fill_tallied(red, z, rows, |i| minv[i] * r[i]);
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
        fill_tallied(red, z, rows, |i| {
            let (d, w) = (dofs[i], wt[i]);
            let fourier = w * (d.e.0 * vx[d.k as usize] + d.e.1 * vy[d.k as usize]);
            if d.stick {
                fourier
            } else {
                fourier + SLIP_JACOBI * (1.0 - w * w) * minv[i] * r[i]
            }
        })
    }

    /// Preconditioned projected CG for
    /// $Hx - B^{\mathsf T}\lambda = \text{rhs},\ Bx = b$ (Gould, Hribar & Nocedal 2001,
    /// Algorithm II with a constraint preconditioner $G$: $\mathrm{diag}(H)$, or the Fourier
    /// preconditioner on the stick block), for the system in `w` (dofs, their element
    /// ranges, $D$ and rhs). Stops when the projected preconditioned residual falls below
    /// `eta` times its start or below `abs_floor` (traction units). Leaves $x$ in `w.x` and
    /// returns $\lambda$ (the rigid-mode increments) and the iteration count. With `dq`, the
    /// state's traction has changed by $\Delta\mathbf q$ since `rhs` was evaluated (not all
    /// zero: the caller leaves it out then): the start residual is
    /// $\text{rhs} - P^{\mathsf T}K\Delta\mathbf q - Hx_0$, from one product. The
    /// displacement of the step, $K(\Delta\mathbf q + Px)$, is left in `dux`, `duy`.
    #[allow(clippy::too_many_arguments, clippy::needless_range_loop)]
    pub(super) fn pcg(
        &mut self,
        w: &mut Work,
        b: &[f64],
        dq: Option<(&[f64], &[f64])>,
        eta: f64,
        abs_floor: f64,
    ) -> Result<(Vec<f64>, usize)> {
        let g = self.p.grid;
        let Work { dofs, first, diag_d, rhs, x, rows, minv, wt, gb, bj, y, r, z, p, hp, .. } = w;
        let (dofs, first, diag_d, rhs) = (&dofs[..], &first[..], &diag_d[..], &rhs[..]);
        let nd = dofs.len();
        let nm = self.modes.len();
        let modes = self.modes.clone();
        // Constraint row j at dof d: B_jd = m_j(x_k) . e_d.
        let mut red = Reducer::new(nd);
        // The constraint rows, evaluated once: the projection streams them at every CG step.
        dofs.par_iter()
            .map(|d| {
                let mut row = [0.0; 3];
                for (j, m) in modes.iter().enumerate() {
                    let v = m.at(g.x[d.k as usize], g.y[d.k as usize]);
                    row[j] = v.0 * d.e.0 + v.1 * d.e.1;
                }
                row
            })
            .collect_into_vec(rows);
        let rows = &rows[..];
        let k0 = self.k0;
        // Jacobi values 1/(K_dd(0) + D_d) and the preconditioner's weights
        // w_d = 1 / sqrt(1 + (D_d / K_dd(0))^2) (1 on stick components).
        dofs.par_iter()
            .zip(diag_d.par_iter())
            .map(|(d, dd)| {
                let kd = d.e.0 * (k0[0] * d.e.0 + k0[1] * d.e.1)
                    + d.e.1 * (k0[1] * d.e.0 + k0[2] * d.e.1);
                let m = 1.0 / (kd + dd);
                let x = dd / kd;
                (m, if d.stick { 1.0 } else { (1.0 + x * x).sqrt().recip() })
            })
            .unzip_into_vecs(minv, wt);
        let (minv, wt) = (&minv[..], &wt[..]);
        // G^-1 b_j and W = B G^-1 B^T.
        gb.resize_with(nm, Vec::new);
        for (j, gj) in gb.iter_mut().enumerate() {
            rows.par_iter().map(|row| row[j]).collect_into_vec(bj);
            sized(gj, nd);
            self.g_apply(&mut red, dofs, first, minv, wt, None, bj, gj);
        }
        let gb = &gb[..nm];
        let mut wm = [[0.0; 3]; 3];
        for i in 0..nm {
            for j in 0..nm {
                let gj = &gb[j];
                wm[i][j] = red.sum(nd, |r| r.map(|k| rows[k][i] * gj[k]).sum());
            }
        }
        // Symmetrise (G^-1 is symmetric up to rounding).
        for i in 0..nm {
            for j in 0..i {
                let v = 0.5 * (wm[i][j] + wm[j][i]);
                wm[i][j] = v;
                wm[j][i] = v;
            }
        }
        let no_stick = || Error::NoStickLeft {
            solver: SOLVER_NAME,
            load: self.p.load.kind(),
            iteration: 0,
            free_components: nd,
        };
        if small_spd_solve(&wm, nm, &[1.0; 3][..nm]).is_none() {
            return Err(no_stick());
        }
        // Projection: y = G^-1 r, l = W^-1 B y, r <- r - B^T l, z = y - G^-1 B^T l. The
        // residual itself is replaced by r - B^T l (the "residual update" of Gould, Hribar &
        // Nocedal, §6): it leaves the iteration unchanged in exact arithmetic and keeps z in
        // the null space of B to rounding; the l are summed into the multiplier. Returns
        // (r.z, |z|^2).
        sized(y, nd);
        let mut project = |this: &mut Self,
                           red: &mut Reducer,
                           r: &mut [f64],
                           z: &mut [f64],
                           acc: &mut [f64; 3]|
         -> Option<(f64, f64)> {
            let c = this.g_apply(red, dofs, first, minv, wt, Some(rows), r, y);
            let l = small_spd_solve(&wm, nm, &c[..nm])?;
            for j in 0..nm {
                acc[j] += l[j];
            }
            let yr = &*y;
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
                        for (j, gj) in gb.iter().enumerate() {
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
        let l0 = small_spd_solve(&wm, nm, b).ok_or_else(no_stick)?;
        (0..nd)
            .into_par_iter()
            .map(|i| gb.iter().zip(&l0).map(|(gj, l)| l * gj[i]).sum())
            .collect_into_vec(x);
        // The displacement of the step, K P x, is kept beside x (the displacement is linear
        // in the traction: each CG product K P p also moves it by alpha K P p), so the Newton
        // loop needs no product after the step.
        let mut dux = std::mem::take(&mut self.dux);
        let mut duy = std::mem::take(&mut self.duy);
        sized(hp, nd);
        // With b = 0 (and no traction change) the start is x0 = 0 and its product is skipped.
        if dq.is_none() && b.iter().all(|v| *v == 0.0) {
            dux.par_iter_mut().zip(duy.par_iter_mut()).for_each(|(a, b)| {
                *a = 0.0;
                *b = 0.0;
            });
            r.clear();
            r.extend_from_slice(rhs);
        } else {
            self.h_apply(&mut red, dofs, first, diag_d, x, dq, hp);
            dux.copy_from_slice(&self.vx);
            duy.copy_from_slice(&self.vy);
            rhs.par_iter().zip(hp.par_iter()).map(|(a, b)| a - b).collect_into_vec(r);
        }
        sized(z, nd);
        let mut acc = [0.0; 3];
        let (mut rz, zz) = project(self, &mut red, r, z, &mut acc).ok_or_else(no_stick)?;
        let stop = (eta * zz.sqrt()).max(abs_floor);
        let mut znorm = zz.sqrt();
        p.clear();
        p.extend_from_slice(z);
        let mut its = 0;
        while znorm > stop && its < self.p.config.max_cg() {
            let php = self.h_apply(&mut red, dofs, first, diag_d, p, None, hp);
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
            let (rz_new, zz) = project(self, &mut red, r, z, &mut acc).ok_or_else(no_stick)?;
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
        Ok((lam, its))
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

/// `z[i] = value(i)` for every `i`, written in the fixed blocks of [`Reducer`] (in parallel),
/// and with `rows` the sums $\sum_i$ `rows[i][j]` $z_i$ taken as $z$ is written (each block's
/// in index order, the blocks' added in order); zero without `rows`.
fn fill_tallied(
    red: &mut Reducer,
    z: &mut [f64],
    rows: Option<&[[f64; 3]]>,
    value: impl Fn(usize) -> f64 + Sync + Send,
) -> [f64; 3] {
    z.par_chunks_mut(REDUCE_CHUNK)
        .enumerate()
        .map(|(b, zc)| {
            let mut c = [0.0; 3];
            for (o, zv) in zc.iter_mut().enumerate() {
                let i = b * REDUCE_CHUNK + o;
                *zv = value(i);
                if let Some(rows) = rows {
                    for (cj, rj) in c.iter_mut().zip(rows[i]) {
                        *cj += rj * *zv;
                    }
                }
            }
            c
        })
        .collect_into_vec(&mut red.parts);
    red.total()
}

/// Block length of the deterministic reductions: the sums of the CG iteration are taken in
/// fixed blocks (in parallel) and the block sums added in order, so a solve gives the same
/// bits whatever the number of threads and however rayon splits the work.
pub(super) const REDUCE_CHUNK: usize = 4096;

/// Deterministic parallel reductions: `f` over fixed blocks of `0..n` (in parallel), the
/// block results added in order, so the sum does not depend on how rayon splits the work
/// (unlike a rayon `sum`, whose tree follows work stealing). The buffer of block results is
/// reused, so the CG loop does not allocate.
pub(super) struct Reducer {
    pub(super) parts: Vec<[f64; 3]>,
}

impl Reducer {
    pub(super) fn new(n: usize) -> Self {
        Self { parts: Vec::with_capacity(n.div_ceil(REDUCE_CHUNK)) }
    }

    pub(super) fn reduce(
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

    pub(super) fn sum(
        &mut self,
        n: usize,
        f: impl Fn(std::ops::Range<usize>) -> f64 + Sync + Send,
    ) -> f64 {
        self.reduce(n, |r| [f(r), 0.0, 0.0])[0]
    }

    /// The block results in `parts`, added in order.
    pub(super) fn total(&self) -> [f64; 3] {
        self.parts.iter().fold([0.0; 3], |a, b| [a[0] + b[0], a[1] + b[1], a[2] + b[2]])
    }
}
