//! The modified simplex on a condensed, column-major tableau.
//!
//! Only the columns of NON-basic real variables are stored (a basic variable's column is a
//! unit vector and carries no information); when a real variable leaves the basis its
//! column takes the place of the entering one, and when an artificial variable leaves, its
//! column is dropped, because artificial variables never re-enter in phase 1 (Fig. 3.5).
//! Each column holds the $2N+1$ constraint rows and the reduced-cost row, contiguously, so
//! the ratio test of a candidate (run for every candidate the entry rule refuses) reads
//! memory in order and the Jordan exchange is one contiguous `axpy` per touched column.
//!
//! Every arithmetic operation is the one the full tableau ([`super::dense`]) performs on the
//! same entry, in the same order, so the pivot sequence and the answer are those of the
//! plain implementation (checked by a test).

use super::{LpConfig, Simplex};
use rayon::prelude::*;

/// Column height ($2N+2$, so about 250 elements) from which the exchange is spread over the
/// rayon pool; below it a pivot is too cheap to pay for the fork and join.
const PARALLEL_HEIGHT: usize = 512;

/// Condensed phase-1 tableau: non-basic real columns, column-major, each $2N+2$ long.
pub(super) struct Tableau {
    n: usize,
    /// Constraint rows, $2N + 1$.
    m: usize,
    /// Column height: the constraint rows plus the reduced-cost row, $m + 1$.
    h: usize,
    /// Stored columns, `cols[c * h + i]`.
    cols: Vec<f64>,
    /// Right-hand side of each row (index `m`: minus the artificial sum).
    rhs: Vec<f64>,
    /// Variable held by each stored column.
    var_of_col: Vec<usize>,
    /// Stored column of each real variable (`None` while it is basic).
    col_of: Vec<Option<usize>>,
    /// Basic variable of each constraint row; `> 3N` marks the row's artificial.
    basic: Vec<usize>,
    /// Row in which a real variable is basic.
    row_of: Vec<Option<usize>>,
    /// Scratch: copy of the pivot column.
    pcol: Vec<f64>,
    /// Scratch: rows where the pivot column is non-zero.
    nzr: Vec<usize>,
    /// Scratch: tied rows of the ratio test.
    ties: Vec<usize>,
    /// Sum of the scaled right-hand sides at the start.
    rhs_sum: f64,
}

impl Tableau {
    /// The all-artificial starting tableau of the scaled problem (see [`super`]).
    pub(super) fn new(
        n: usize,
        a: &[f64],
        g: &[f64],
        cap: &[f64],
        load: f64,
        fs: f64,
        gs: f64,
        as_: f64,
    ) -> Self {
        let m = 2 * n + 1;
        let h = m + 1;
        let nvar = 3 * n + 1;
        let mut cols = vec![0.0; nvar * h];
        for j in 0..n {
            let col = &mut cols[j * h..(j + 1) * h];
            for (k, v) in col[..n].iter_mut().enumerate() {
                *v = a[k * n + j] / as_;
            }
            col[n + j] = 1.0;
            col[2 * n] = g[j] / gs;
        }
        for k in 0..n {
            cols[(n + k) * h + k] = 1.0;
            cols[(2 * n + k) * h + n + k] = 1.0;
        }
        for k in 0..n {
            cols[3 * n * h + k] = -g[k] / gs;
        }
        let mut rhs = vec![0.0; h];
        for k in 0..n {
            rhs[n + k] = cap[k] / fs;
        }
        rhs[2 * n] = load / (fs * gs);
        // Phase-1 reduced costs: minus the column sums over the all-artificial basis,
        // accumulated row by row as the full tableau does.
        for col in cols.chunks_exact_mut(h) {
            let mut o = 0.0;
            for v in &col[..m] {
                o -= v;
            }
            col[m] = o;
        }
        let mut o = 0.0;
        for v in &rhs[..m] {
            o -= v;
        }
        rhs[m] = o;
        Self {
            n,
            m,
            h,
            cols,
            rhs,
            var_of_col: (0..nvar).collect(),
            col_of: (0..nvar).map(Some).collect(),
            basic: (0..m).map(|r| nvar + r).collect(),
            row_of: vec![None; nvar],
            pcol: vec![0.0; h],
            nzr: Vec::with_capacity(h),
            ties: Vec::new(),
            rhs_sum: (-o).max(f64::MIN_POSITIVE),
        }
    }

    fn is_artificial(&self, v: usize) -> bool {
        v > 3 * self.n
    }

    /// The complementary partner of a slack variable, if `s` is a slack.
    fn partner(&self, s: usize) -> Option<usize> {
        let n = self.n;
        if (n..2 * n).contains(&s) {
            Some(s + n)
        } else if (2 * n..3 * n).contains(&s) {
            Some(s - n)
        } else {
            None
        }
    }

    /// Minimum-ratio row for variable `s` honouring the modified entry rule, or `None` if
    /// it may not enter.
    ///
    /// When the partner slack is basic in row `pr`, `s` may enter only if `pr` ties for the
    /// minimum ratio. Two early refusals give the same answer as the full scan: `pr` has
    /// no admissible pivot, or some row's ratio $q$ satisfies
    /// $\rho_{pr} > q(1 + 10^{-11}) + 10^{-300}$; the tie window of the full scan is
    /// $10^{-12}$ relative to the running minimum, so `pr` could not tie.
    fn ratio_test(&mut self, s: usize, cfg: &LpConfig) -> Option<usize> {
        let c = self.col_of[s]?;
        let h = self.h;
        let col = &self.cols[c * h..c * h + self.m];
        let partner_row = self.partner(s).and_then(|p| self.row_of[p]);
        let refuse_above = match partner_row {
            Some(pr) => {
                if col[pr] <= cfg.pivot_tol {
                    return None;
                }
                Some(self.rhs[pr].max(0.0) / col[pr])
            }
            None => None,
        };
        let mut best = f64::INFINITY;
        self.ties.clear();
        for (r, (&v, &b)) in col.iter().zip(&self.rhs[..self.m]).enumerate() {
            if v > cfg.pivot_tol {
                let ratio = b.max(0.0) / v;
                if let Some(rp) = refuse_above {
                    if rp > ratio * (1.0 + 1e-11) + 1e-300 {
                        return None;
                    }
                }
                let slack = if best.is_finite() { 1e-12 * best.max(1e-300) } else { 0.0 };
                if self.ties.is_empty() || ratio < best - slack {
                    best = ratio;
                    self.ties.clear();
                    self.ties.push(r);
                } else if ratio <= best + slack {
                    self.ties.push(r);
                }
            }
        }
        if self.ties.is_empty() {
            return None;
        }
        if let Some(pr) = partner_row {
            // The partner is basic: it must be the variable that leaves.
            return self.ties.contains(&pr).then_some(pr);
        }
        // Artificial rows first, then the lowest basic index (Bland).
        self.ties.iter().copied().min_by_key(|&r| {
            let v = self.basic[r];
            (usize::from(!self.is_artificial(v)), v)
        })
    }
}

impl Simplex for Tableau {
    fn rhs_sum(&self) -> f64 {
        self.rhs_sum
    }

    fn rhs(&self, r: usize) -> f64 {
        self.rhs[r]
    }

    fn objective(&self) -> f64 {
        -self.rhs[self.m]
    }

    /// Bland's rule (lowest variable index with a negative reduced cost) with the modified
    /// entry rule: a refused candidate moves `JSTART` past it.
    fn choose(&mut self, cfg: &LpConfig, rejected: &mut usize) -> Option<(usize, usize)> {
        let last = 3 * self.n;
        let (h, m) = (self.h, self.m);
        let mut jstart = 0;
        while jstart <= last {
            let s = (jstart..=last)
                .find(|&j| self.col_of[j].is_some_and(|c| self.cols[c * h + m] < -cfg.cost_tol))?;
            if let Some(r) = self.ratio_test(s, cfg) {
                return Some((r, s));
            }
            *rejected += 1;
            jstart = s + 1;
        }
        None
    }

    /// Jordan exchange: variable `s` enters in row `r`. Columns whose row-`r` entry is zero
    /// are untouched; when the pivot column is sparse only its non-zero rows are updated.
    fn pivot(&mut self, r: usize, s: usize) {
        let h = self.h;
        let cs = self.col_of[s].expect("entering variable is non-basic");
        self.pcol.copy_from_slice(&self.cols[cs * h..(cs + 1) * h]);
        let inv = 1.0 / self.pcol[r];
        self.nzr.clear();
        self.nzr.extend((0..h).filter(|&i| i != r && self.pcol[i] != 0.0));
        let sparse = 4 * self.nzr.len() < h;
        let (pcol, nzr) = (&self.pcol, &self.nzr);
        let update = |col: &mut [f64]| {
            let e = col[r];
            if e == 0.0 {
                return;
            }
            let p = e * inv;
            if sparse {
                for &i in nzr {
                    col[i] -= pcol[i] * p;
                }
            } else {
                for (x, &f) in col.iter_mut().zip(pcol) {
                    *x -= f * p;
                }
            }
            col[r] = p;
        };
        // Columns are independent, so splitting them over threads changes no result.
        if h >= PARALLEL_HEIGHT {
            self.cols.par_chunks_exact_mut(h).enumerate().with_min_len(8).for_each(|(c, col)| {
                if c != cs {
                    update(col);
                }
            });
        } else {
            for (c, col) in self.cols.chunks_exact_mut(h).enumerate() {
                if c != cs {
                    update(col);
                }
            }
        }
        update(&mut self.rhs);
        // The leaving variable's column (a unit vector before the exchange).
        let leaving = self.basic[r];
        {
            let col = &mut self.cols[cs * h..(cs + 1) * h];
            for (x, &f) in col.iter_mut().zip(pcol) {
                *x = -(f * inv);
            }
            col[r] = inv;
        }
        self.col_of[s] = None;
        if self.is_artificial(leaving) {
            // Artificial variables never re-enter: drop the column (swap with the last).
            let last = self.var_of_col.len() - 1;
            if cs != last {
                self.cols.copy_within(last * h..(last + 1) * h, cs * h);
                let moved = self.var_of_col[last];
                self.var_of_col[cs] = moved;
                self.col_of[moved] = Some(cs);
            }
            self.var_of_col.pop();
            self.cols.truncate(last * h);
        } else {
            self.var_of_col[cs] = leaving;
            self.col_of[leaving] = Some(cs);
            self.row_of[leaving] = None;
        }
        self.basic[r] = s;
        self.row_of[s] = Some(r);
    }

    fn basic(&self) -> &[usize] {
        &self.basic
    }
}
