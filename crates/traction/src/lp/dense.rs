//! The plain full-tableau implementation of the modified simplex: every column of
//! $[F, Y_1, Y_2, \beta \mid \text{rhs}]$ stored row-major and updated in every pivot. It is
//! the naive reference that [`super::condensed`] must reproduce pivot for pivot.

use super::{LpConfig, Simplex};

/// Full phase-1 tableau: $2N+1$ constraint rows and one reduced-cost row, each
/// $3N+2$ wide (columns $F$, $Y_1$, $Y_2$, $\beta$, right-hand side), row-major.
pub(super) struct Tableau {
    n: usize,
    /// Row width, $3N + 2$.
    w: usize,
    /// Constraint rows $2N+1$ plus the reduced-cost row.
    t: Vec<f64>,
    /// Basic variable of each constraint row; `>= 3N+1` marks the row's artificial.
    basic: Vec<usize>,
    /// Row in which a real variable is basic.
    row_of: Vec<Option<usize>>,
    /// Scratch: the normalised pivot row.
    prow: Vec<f64>,
    /// Scratch: non-zero columns of the pivot row.
    nz: Vec<usize>,
    /// Scratch: tied rows of the ratio test.
    ties: Vec<usize>,
    /// Sum of the scaled right-hand sides (for the relative stopping test).
    rhs_sum: f64,
}

impl Tableau {
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
        let w = 3 * n + 2;
        let rhs_col = w - 1;
        let beta = 3 * n;
        let mut t = vec![0.0; (m + 1) * w];
        for k in 0..n {
            let row = &mut t[k * w..(k + 1) * w];
            for (dst, src) in row[..n].iter_mut().zip(&a[k * n..(k + 1) * n]) {
                *dst = src / as_;
            }
            row[n + k] = 1.0;
            row[beta] = -g[k] / gs;
        }
        for k in 0..n {
            let row = &mut t[(n + k) * w..(n + k + 1) * w];
            row[k] = 1.0;
            row[2 * n + k] = 1.0;
            row[rhs_col] = cap[k] / fs;
        }
        {
            let row = &mut t[2 * n * w..(2 * n + 1) * w];
            for j in 0..n {
                row[j] = g[j] / gs;
            }
            row[rhs_col] = load / (fs * gs);
        }
        // Phase-1 reduced costs: minus the column sums over the (all artificial) basis.
        let mut obj = vec![0.0; w];
        for r in 0..m {
            for (o, v) in obj.iter_mut().zip(&t[r * w..(r + 1) * w]) {
                *o -= v;
            }
        }
        let rhs_sum = -obj[rhs_col];
        t[m * w..].copy_from_slice(&obj);
        Self {
            n,
            w,
            t,
            basic: (0..m).map(|r| 3 * n + 1 + r).collect(),
            row_of: vec![None; 3 * n + 1],
            prow: vec![0.0; w],
            nz: Vec::with_capacity(w),
            ties: Vec::new(),
            rhs_sum: rhs_sum.max(f64::MIN_POSITIVE),
        }
    }

    fn m(&self) -> usize {
        2 * self.n + 1
    }

    fn is_artificial(&self, v: usize) -> bool {
        v > 3 * self.n
    }

    /// The complementary partner of a slack column, if `s` is a slack.
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

    /// Entering column by Bland's rule with the modified entry rule, and its leaving row.
    fn choose_impl(&mut self, cfg: &LpConfig, rejected: &mut usize) -> Option<(usize, usize)> {
        let w = self.w;
        let obj_off = self.m() * w;
        let mut jstart = 0;
        while jstart <= 3 * self.n {
            // Bland: lowest admissible index with a negative reduced cost.
            let s = (jstart..=3 * self.n)
                .find(|&j| self.row_of[j].is_none() && self.t[obj_off + j] < -cfg.cost_tol)?;
            if let Some(r) = self.ratio_test(s, cfg) {
                return Some((r, s));
            }
            *rejected += 1;
            jstart = s + 1;
        }
        None
    }

    /// Minimum-ratio row for column `s` honouring the modified entry rule, or `None` if
    /// the column may not enter.
    fn ratio_test(&mut self, s: usize, cfg: &LpConfig) -> Option<usize> {
        let w = self.w;
        let mut best = f64::INFINITY;
        self.ties.clear();
        for r in 0..self.m() {
            let col = self.t[r * w + s];
            if col > cfg.pivot_tol {
                let ratio = self.t[r * w + w - 1].max(0.0) / col;
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
        if let Some(p) = self.partner(s) {
            if let Some(pr) = self.row_of[p] {
                // The partner is basic: it must be the variable that leaves.
                return self.ties.contains(&pr).then_some(pr);
            }
        }
        // Artificial rows first, then the lowest basic index (Bland).
        self.ties.iter().copied().min_by_key(|&r| {
            let v = self.basic[r];
            if self.is_artificial(v) {
                (0, v)
            } else {
                (1, v)
            }
        })
    }

    /// Jordan exchange on element $(r, s)$, skipping rows whose column-$s$ entry is zero
    /// and, when the pivot row is sparse, columns where it is zero.
    fn pivot_impl(&mut self, r: usize, s: usize) {
        let w = self.w;
        let rows = self.m() + 1;
        let inv = 1.0 / self.t[r * w + s];
        self.nz.clear();
        for (j, (dst, src)) in self.prow.iter_mut().zip(&mut self.t[r * w..(r + 1) * w]).enumerate()
        {
            *src *= inv;
            *dst = *src;
            if *src != 0.0 {
                self.nz.push(j);
            }
        }
        self.t[r * w + s] = 1.0;
        self.prow[s] = 1.0;
        let dense = 2 * self.nz.len() > w;
        for i in 0..rows {
            if i == r {
                continue;
            }
            let row = &mut self.t[i * w..(i + 1) * w];
            let f = row[s];
            if f == 0.0 {
                continue;
            }
            if dense {
                for (x, p) in row.iter_mut().zip(&self.prow) {
                    *x -= f * p;
                }
            } else {
                for &j in &self.nz {
                    row[j] -= f * self.prow[j];
                }
            }
            row[s] = 0.0;
        }
        let old = self.basic[r];
        if old <= 3 * self.n {
            self.row_of[old] = None;
        }
        self.basic[r] = s;
        self.row_of[s] = Some(r);
    }
}

impl Simplex for Tableau {
    fn rhs_sum(&self) -> f64 {
        self.rhs_sum
    }

    fn rhs(&self, r: usize) -> f64 {
        self.t[r * self.w + self.w - 1]
    }

    fn objective(&self) -> f64 {
        -self.t[self.m() * self.w + self.w - 1]
    }

    fn choose(&mut self, cfg: &LpConfig, rejected: &mut usize) -> Option<(usize, usize)> {
        self.choose_impl(cfg, rejected)
    }

    fn pivot(&mut self, r: usize, s: usize) {
        self.pivot_impl(r, s);
    }

    fn basic(&self) -> &[usize] {
        &self.basic
    }
}
