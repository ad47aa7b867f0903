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
//!
//! # Storage
//!
//! [`modified_lp`] keeps only the columns of non-basic variables, column-major, and drops
//! an artificial column when it leaves (it never re-enters); [`modified_lp_reference`] keeps
//! the plain full tableau. They perform the same floating-point operations on every entry
//! and so follow the same pivot sequence to the last bit (tested). Measured on Example 1
//! (exact coefficients, 2 shared cores): N = 1020 from 6.6 s to 0.9-2.3 s, N = 1976 from
//! 62 s to 16.6 s.

use crate::error::{Error, Result};

mod condensed;
mod dense;

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

/// Solve seed 002 eq. (3.13) by the modified simplex of Fig. 3.5: find $F, Y_1, Y_2 \ge 0$ and
/// $\beta \ge 0$ with
/// $$AF + Y_1 - \beta g = 0,\qquad F + Y_2 = c,\qquad g^{\mathsf T}F = L,\qquad
///   Y_{1k}Y_{2k} = 0$$
/// (see the [module docs](self) for the entry rule and tolerances).
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
/// [`Error::NotConverged`] if the pivot budget is exhausted.
pub fn modified_lp(
    a: &[f64],
    g: &[f64],
    cap: &[f64],
    load: f64,
    cfg: &LpConfig,
) -> Result<LpSolution> {
    let (n, fs, gs, as_) = validate(a, g, cap, load)?;
    let tab = condensed::Tableau::new(n, a, g, cap, load, fs, gs, as_);
    run(tab, n, cfg, fs, gs, as_)
}

/// The same algorithm on the plain full tableau: every column, basic or not, is
/// stored and updated. It is kept as the naive reference of [`modified_lp`], which must
/// reproduce its pivot sequence and answer; it costs about three times as much per pivot.
///
/// Same problem (seed 002 eq. (3.13), Fig. 3.5); arguments, result and errors as
/// [`modified_lp`].
///
/// # Errors
/// As [`modified_lp`].
pub fn modified_lp_reference(
    a: &[f64],
    g: &[f64],
    cap: &[f64],
    load: f64,
    cfg: &LpConfig,
) -> Result<LpSolution> {
    let (n, fs, gs, as_) = validate(a, g, cap, load)?;
    let tab = dense::Tableau::new(n, a, g, cap, load, fs, gs, as_);
    run(tab, n, cfg, fs, gs, as_)
}

/// The operations the phase-1 driver needs from a tableau. Variables are numbered
/// $F_0..F_{N-1}$, $Y_{1,0}..$, $Y_{2,0}..$, $\beta$ ($0..3N$); indices $> 3N$ are the
/// artificial variables of the rows.
trait Simplex {
    /// Sum of the scaled right-hand sides at the start.
    fn rhs_sum(&self) -> f64;
    /// Right-hand side of constraint row `r`.
    fn rhs(&self, r: usize) -> f64;
    /// Current artificial sum.
    fn objective(&self) -> f64;
    /// Entering variable and leaving row, or `None` if no column may enter.
    fn choose(&mut self, cfg: &LpConfig, rejected: &mut usize) -> Option<(usize, usize)>;
    /// Exchange: variable `s` enters the basis in row `r`.
    fn pivot(&mut self, r: usize, s: usize);
    /// Basic variable of each constraint row.
    fn basic(&self) -> &[usize];
}

/// Validate the input and return $N$ and the scales of force, mode and influence.
fn validate(a: &[f64], g: &[f64], cap: &[f64], load: f64) -> Result<(usize, f64, f64, f64)> {
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
    Ok((n, fs, gs, as_))
}

/// Phase 1 with the modified entry rule (Fig. 3.5), then read out and unscale.
fn run<T: Simplex>(
    mut tab: T,
    n: usize,
    cfg: &LpConfig,
    fs: f64,
    gs: f64,
    as_: f64,
) -> Result<LpSolution> {
    let max_pivots = cfg.max_pivots.unwrap_or(20 * (2 * n + 1));
    let rhs_sum = tab.rhs_sum();
    let mut iterations = 0usize;
    let mut degenerate_pivots = 0usize;
    let mut run_len = 0usize;
    let mut longest = 0usize;
    let mut rejected = 0usize;
    loop {
        let objective = tab.objective();
        if objective <= cfg.feasibility_tol * rhs_sum {
            break;
        }
        if iterations >= max_pivots {
            return Err(Error::NotConverged {
                solver: "modified LP",
                iterations,
                residual: if rhs_sum > 0.0 { objective / rhs_sum } else { objective },
                tolerance: cfg.feasibility_tol,
            });
        }
        let Some((r, s)) = tab.choose(cfg, &mut rejected) else {
            return Err(Error::Infeasible { iterations, objective });
        };
        let step = tab.rhs(r).max(0.0);
        if step <= cfg.pivot_tol {
            degenerate_pivots += 1;
            run_len += 1;
            longest = longest.max(run_len);
        } else {
            run_len = 0;
        }
        tab.pivot(r, s);
        iterations += 1;
    }

    // Read out the basic solution and undo the scaling.
    let mut vals = vec![0.0; 3 * n + 1];
    for (r, &v) in tab.basic().iter().enumerate() {
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
