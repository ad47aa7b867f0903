//! The modified linear program of seed 002, §3.3 and Fig. 3.5, on a dense `f64` tableau.
//!
//! # The problem
//!
//! With $N$ elements, influence matrix $A$ (displacement along the traction direction of
//! element $k$ per unit force on element $j$), force capacity $c_k = f P_k$, rigid-body mode
//! $g_k$ (1 for a translation; the lever arm for a rotation) and load $L$, find
//! $F, Y_1, Y_2 \ge 0$ and $\beta \ge 0$ with
//!
//! $$ A F + Y_1 - \beta g = 0, \qquad F + Y_2 = c, \qquad g^{\mathsf T} F = L,
//!    \qquad Y_{1k} Y_{2k} = 0 . $$
//!
//! This is seed 002 eq. (3.13) (there with $g = e$). $Y_{1k}$ is the slip of element $k$
//! (zero in the stick zone), $Y_{2k}$ its unused friction reserve (zero in the slip zone).
//!
//! # The algorithm (Fig. 3.5, as written)
//!
//! Phase 1 of the simplex method with one artificial variable per row
//! ($Z_1$, $Z_2$, $Z_{2N+1}$), minimising $\sum Z_i$ from the all-artificial basis, with:
//!
//! * Bland's rule for the entering column: the lowest index $s \ge$ `JSTART` with negative
//!   reduced cost (artificial columns are never candidates, so they are not stored);
//! * the modified entry rule: $Y_{1s}$ may enter only if $Y_{2s}$ is not basic, or if
//!   $Y_{2s}$ is the variable that leaves (and symmetrically for $Y_{2s}$); otherwise
//!   `JSTART` $= s + 1$ and the next column is tried;
//! * the leaving row by the minimum-ratio test, ties broken first in favour of the partner
//!   slack named by the entry rule, then artificial rows, then the lowest basic index
//!   (Bland);
//! * stop when the artificial sum is (almost) zero: the basic solution then satisfies all
//!   constraints and, through the entry rule, the complementarity condition.
//!
//! # Tolerance policy
//!
//! The tableau is scaled so that every entry is of order one: forces by $\max_k c_k$, the
//! influence matrix by its largest diagonal entry, the mode by $\max_k |g_k|$. On the scaled
//! tableau: a pivot must exceed [`LpConfig::pivot_tol`] in magnitude, a reduced cost must be
//! below $-$[`LpConfig::cost_tol`] to enter, and phase 1 succeeds when the scaled artificial
//! sum is below [`LpConfig::feasibility_tol`] times the scaled right-hand side sum.

use crate::error::{Error, Result};

/// Tolerances and limits of the modified simplex.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LpConfig {
    /// Smallest admissible pivot magnitude on the scaled tableau.
    pub pivot_tol: f64,
    /// A reduced cost must be below `-cost_tol` for its column to enter.
    pub cost_tol: f64,
    /// Phase 1 succeeds when the artificial sum is below `feasibility_tol` times the
    /// right-hand-side sum (both scaled).
    pub feasibility_tol: f64,
    /// Pivot budget; `None` means $20 (2N+1)$.
    pub max_pivots: Option<usize>,
}

impl Default for LpConfig {
    fn default() -> Self {
        Self { pivot_tol: 1e-11, cost_tol: 1e-13, feasibility_tol: 1e-11, max_pivots: None }
    }
}

/// What the modified simplex returns, in the caller's units.
#[derive(Debug, Clone, PartialEq)]
pub struct LpSolution {
    /// Force per element $F_k$.
    pub force: Vec<f64>,
    /// Slack $Y_{1k} = \beta g_k - u_k$: the slip of element $k$.
    pub slip: Vec<f64>,
    /// Slack $Y_{2k} = c_k - F_k$: the unused friction capacity of element $k$.
    pub reserve: Vec<f64>,
    /// The rigid-body movement $\beta$ (a displacement, or a rotation when $g$ is a lever arm).
    pub rigid: f64,
    /// Pivots performed.
    pub iterations: usize,
    /// Pivots whose step length was zero (degenerate pivots).
    pub degenerate_pivots: usize,
    /// Longest run of consecutive degenerate pivots.
    pub longest_degenerate_run: usize,
    /// Entering candidates rejected by the modified entry rule.
    pub rejected_entries: usize,
    /// Final scaled artificial sum (phase-1 objective).
    pub phase1_objective: f64,
}

impl LpSolution {
    /// Whether a degenerate pivot sequence was met (at least one zero-length pivot).
    #[must_use]
    pub fn degenerate(&self) -> bool {
        self.degenerate_pivots > 0
    }
}

/// Solve seed 002 eq. (3.13) by the modified simplex of Fig. 3.5.
///
/// * `a`: the $N \times N$ influence matrix, row-major (`a[k * n + j]`), any consistent units;
/// * `g`: the rigid-body mode (length $N$; all ones for a translation);
/// * `cap`: the friction capacities $c_k = f P_k \ge 0$;
/// * `load`: $L \ge 0$, which must not exceed $g^{\mathsf T} c$ (callers handle gross slip
///   before calling; see [`crate::solve`]).
///
/// Source: seed 002 §3.3.2, eq. (3.13) and Fig. 3.5; FORMULAS.md section F for $A$.
///
/// # Errors
/// [`Error::LengthMismatch`], [`Error::OutOfDomain`] for bad input,
/// [`Error::Infeasible`] if phase 1 ends with a positive artificial sum,
/// [`Error::IterationLimit`] if the pivot budget is exhausted.
pub fn modified_lp(
    a: &[f64],
    g: &[f64],
    cap: &[f64],
    load: f64,
    cfg: &LpConfig,
) -> Result<LpSolution> {
    let n = cap.len();
    if n == 0 {
        return Err(Error::EmptyGrid { reason: "no element passed to the LP" });
    }
    if a.len() != n * n {
        return Err(Error::LengthMismatch {
            name: "influence matrix",
            expected: n * n,
            got: a.len(),
        });
    }
    if g.len() != n {
        return Err(Error::LengthMismatch { name: "rigid-body mode", expected: n, got: g.len() });
    }
    for &c in cap {
        crate::error::non_negative("friction capacity", c)?;
    }
    for &v in a.iter().chain(g) {
        if !v.is_finite() {
            return Err(Error::OutOfDomain {
                name: "influence/mode entry",
                value: v,
                allowed: "finite",
            });
        }
    }
    crate::error::non_negative("load", load)?;

    // Scales.
    let fs = cap.iter().copied().fold(0.0_f64, f64::max);
    let gs = g.iter().map(|v| v.abs()).fold(0.0_f64, f64::max);
    let as_ = (0..n).map(|k| a[k * n + k].abs()).fold(0.0_f64, f64::max);
    if fs <= 0.0 || gs <= 0.0 || as_ <= 0.0 {
        let (name, value) = if fs <= 0.0 {
            ("max friction capacity", fs)
        } else if gs <= 0.0 {
            ("max |rigid-body mode|", gs)
        } else {
            ("max influence diagonal", as_)
        };
        return Err(Error::OutOfDomain { name, value, allowed: "> 0" });
    }

    let mut tab = Tableau::new(n, a, g, cap, load, fs, gs, as_);
    let max_pivots = cfg.max_pivots.unwrap_or(20 * (2 * n + 1));
    let rhs_sum = tab.rhs_sum;
    let mut iterations = 0usize;
    let mut degenerate_pivots = 0usize;
    let mut run = 0usize;
    let mut longest = 0usize;
    let mut rejected = 0usize;

    loop {
        let objective = tab.objective();
        if objective <= cfg.feasibility_tol * rhs_sum {
            break;
        }
        if iterations >= max_pivots {
            return Err(Error::IterationLimit { iterations, objective });
        }
        let Some((r, s)) = tab.choose(cfg, &mut rejected) else {
            return Err(Error::Infeasible { iterations, objective });
        };
        let step = tab.rhs(r).max(0.0);
        if step <= cfg.pivot_tol {
            degenerate_pivots += 1;
            run += 1;
            longest = longest.max(run);
        } else {
            run = 0;
        }
        tab.pivot(r, s);
        iterations += 1;
    }

    // Read out the basic solution and undo the scaling.
    let mut vals = vec![0.0; 3 * n + 1];
    for (r, &v) in tab.basic.iter().enumerate() {
        if v < 3 * n + 1 {
            vals[v] = tab.rhs(r).max(0.0);
        }
    }
    let force: Vec<f64> = vals[..n].iter().map(|v| v * fs).collect();
    let slip: Vec<f64> = vals[n..2 * n].iter().map(|v| v * as_ * fs).collect();
    let reserve: Vec<f64> = vals[2 * n..3 * n].iter().map(|v| v * fs).collect();
    let rigid = vals[3 * n] * as_ * fs / gs;
    Ok(LpSolution {
        force,
        slip,
        reserve,
        rigid,
        iterations,
        degenerate_pivots,
        longest_degenerate_run: longest,
        rejected_entries: rejected,
        phase1_objective: tab.objective(),
    })
}

/// Dense phase-1 tableau: $2N+1$ constraint rows and one reduced-cost row, each
/// $3N+2$ wide (columns $F$, $Y_1$, $Y_2$, $\beta$, right-hand side), row-major.
struct Tableau {
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
    #[allow(clippy::too_many_arguments)]
    fn new(
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

    fn rhs(&self, r: usize) -> f64 {
        self.t[r * self.w + self.w - 1]
    }

    /// Current artificial sum, $-$(reduced-cost row right-hand side).
    fn objective(&self) -> f64 {
        -self.t[self.m() * self.w + self.w - 1]
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
    fn choose(&mut self, cfg: &LpConfig, rejected: &mut usize) -> Option<(usize, usize)> {
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
    fn pivot(&mut self, r: usize, s: usize) {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Two elements, symmetric influence, equal capacities: by symmetry each carries half.
    #[test]
    fn two_element_symmetric_split() {
        let a = [2.0, 0.5, 0.5, 2.0];
        let s = modified_lp(&a, &[1.0, 1.0], &[1.0, 1.0], 1.0, &LpConfig::default()).unwrap();
        assert!((s.force[0] - 0.5).abs() < 1e-14 && (s.force[1] - 0.5).abs() < 1e-14);
        assert!((s.rigid - 1.25).abs() < 1e-14, "rigid {}", s.rigid);
    }

    /// Two elements with unequal capacity: the weak one saturates, the other sticks.
    #[test]
    fn two_element_one_slips() {
        let a = [2.0, 0.5, 0.5, 2.0];
        let s = modified_lp(&a, &[1.0, 1.0], &[0.2, 5.0], 1.0, &LpConfig::default()).unwrap();
        // Element 0 slips at F0 = 0.2; F1 = 0.8; beta = u1 = 0.5*0.2 + 2*0.8 = 1.7.
        assert!((s.force[0] - 0.2).abs() < 1e-14, "{:?}", s.force);
        assert!((s.force[1] - 0.8).abs() < 1e-14);
        assert!((s.rigid - 1.7).abs() < 1e-13, "rigid {}", s.rigid);
        // Slip of element 0: beta - u0 = 1.7 - (0.4 + 0.4) = 0.9.
        assert!((s.slip[0] - 0.9).abs() < 1e-13);
        assert!(s.slip[1].abs() < 1e-14 && s.reserve[0].abs() < 1e-14);
    }
}
