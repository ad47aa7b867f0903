//! Composite Gauss–Jacobi rules on a patch $t \in [-1,1]$, graded geometrically about a
//! field point $X$ so that a kernel peak of width $Y$ at $X$ (stresses near the surface) or an
//! integrable power singularity $|X-t|^{-k}$ at $X$ (surface displacements) is resolved, and
//! with the patch's edge factor $(1-t^2)^\gamma$ put in the Jacobi weight of the end panels.
//!
//! This is a problem-specific arrangement of the fixed rules of `stickslip-quad`: the panel
//! next to each algebraic singularity carries it in its weight, every other panel sees a
//! function analytic in a Bernstein ellipse around it (the nearest singularity is at least
//! about half a panel length away), so a fixed `n`-point rule converges geometrically; the
//! worst panels measured (merged end panels) go like $2.3^{-2n}$.

use crate::error::Error;

/// Nodes and weights on $[-1,1]$ for the weight $(1-\xi)^\alpha(1+\xi)^\beta$.
#[derive(Debug, Clone)]
pub(crate) struct Rule {
    pub(crate) x: Vec<f64>,
    pub(crate) w: Vec<f64>,
}

/// What sits at a panel end: nothing, the patch edge ($\gamma$), the field point ($-k$), or
/// both at once ($\gamma - k$, field point exactly on the patch edge).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum EndKind {
    Plain = 0,
    Edge = 1,
    Point = 2,
    EdgePoint = 3,
}

/// The 16 Jacobi rules needed for one patch exponent $\gamma$ and one point exponent $-k$.
#[derive(Debug, Clone)]
pub(crate) struct RuleSet {
    gamma: f64,
    point_exp: f64,
    /// `table[hi_kind][lo_kind]`: weight $(hi-t)^{e(hi)} (t-lo)^{e(lo)}$.
    table: Vec<Rule>,
}

fn exponent(kind: EndKind, gamma: f64, point_exp: f64) -> f64 {
    match kind {
        EndKind::Plain => 0.0,
        EndKind::Edge => gamma,
        EndKind::Point => point_exp,
        EndKind::EdgePoint => gamma + point_exp,
    }
}

const KINDS: [EndKind; 4] = [EndKind::Plain, EndKind::Edge, EndKind::Point, EndKind::EdgePoint];

impl RuleSet {
    /// Rules with `n` nodes for edge exponent `gamma` and point exponent `point_exp`
    /// (`-k` for displacements, `0` for stresses).
    pub(crate) fn new(n: usize, gamma: f64, point_exp: f64) -> Result<Self, Error> {
        let mut table = Vec::with_capacity(16);
        for hi in KINDS {
            for lo in KINDS {
                let a = exponent(hi, gamma, point_exp);
                let b = exponent(lo, gamma, point_exp);
                table.push(crate::rules::jacobi(n, a, b)?);
            }
        }
        Ok(Self { gamma, point_exp, table })
    }

    fn rule(&self, hi: EndKind, lo: EndKind) -> &Rule {
        &self.table[4 * hi as usize + lo as usize]
    }
}

/// Grading of the composite rule.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Grading {
    /// Ratio of successive panel lengths away from the field point.
    pub(crate) ratio: f64,
    /// An end panel shorter than `merge` times its neighbour is merged into it.
    pub(crate) merge: f64,
}

impl Default for Grading {
    fn default() -> Self {
        Self { ratio: 2.0, merge: 0.5 }
    }
}

/// Breakpoints on $[-1,1]$ graded about `x` with first scale `h0` (sorted, deduplicated).
pub(crate) fn breakpoints(x: f64, h0: f64, g: Grading, buf: &mut Vec<f64>) {
    buf.clear();
    buf.push(-1.0);
    buf.push(1.0);
    if x > -1.0 && x < 1.0 {
        buf.push(x);
    }
    let mut d = h0;
    for _ in 0..400 {
        let l = x - d;
        let r = x + d;
        if l > -1.0 && l < 1.0 {
            buf.push(l);
        }
        if r > -1.0 && r < 1.0 {
            buf.push(r);
        }
        if l <= -1.0 && r >= 1.0 {
            break;
        }
        d *= g.ratio;
    }
    buf.sort_by(f64::total_cmp);
    buf.dedup();
    // Merge a short end panel into its neighbour (keeps the edge singularity away from the
    // end of a plain Gauss–Legendre panel), but never remove the field point.
    while buf.len() >= 3 {
        let m = buf.len() - 2;
        let (a, b) = (buf[m - 1], buf[m]);
        if b != x && (1.0 - b) < g.merge * (b - a) {
            buf.remove(m);
        } else {
            break;
        }
    }
    while buf.len() >= 3 {
        let (a, b) = (buf[1], buf[2]);
        if a != x && (a + 1.0) < g.merge * (b - a) {
            buf.remove(1);
        } else {
            break;
        }
    }
}

/// $\int_{-1}^{1} (1-t^2)^\gamma\,|X-t|^{e}\,g(t, X-t)\,dt$ on the panels in `bps`, where
/// $e$ is the rule set's point exponent (0 for stresses: then `g` carries the whole kernel).
/// `g` returns `N` integrands at once.
#[inline]
pub(crate) fn integrate<const N: usize>(
    rules: &RuleSet,
    x: f64,
    bps: &[f64],
    mut g: impl FnMut(f64, f64) -> [f64; N],
) -> [f64; N] {
    let gamma = rules.gamma;
    let pe = rules.point_exp;
    let mut total = [0.0; N];
    for win in bps.windows(2) {
        let (lo, hi) = (win[0], win[1]);
        let lo_edge = lo == -1.0;
        let hi_edge = hi == 1.0;
        let lo_point = pe != 0.0 && lo == x;
        let hi_point = pe != 0.0 && hi == x;
        let kind = |edge: bool, point: bool| match (edge, point) {
            (false, false) => EndKind::Plain,
            (true, false) => EndKind::Edge,
            (false, true) => EndKind::Point,
            (true, true) => EndKind::EdgePoint,
        };
        let khi = kind(hi_edge, hi_point);
        let klo = kind(lo_edge, lo_point);
        let rule = rules.rule(khi, klo);
        let half = 0.5 * (hi - lo);
        let ahi = exponent(khi, gamma, pe);
        let alo = exponent(klo, gamma, pe);
        let scale = half.powf(1.0 + ahi + alo);
        // Distances of the panel ends from the patch edges and from the field point.
        let one_minus_hi = 1.0 - hi;
        let one_plus_lo = 1.0 + lo;
        let x_minus_lo = x - lo;
        let mut acc = [0.0; N];
        for (&xi, &wi) in rule.x.iter().zip(&rule.w) {
            let from_lo = half * (1.0 + xi);
            let to_hi = half * (1.0 - xi);
            let t = lo + from_lo;
            let u = one_minus_hi + to_hi; // 1 - t
            let v = one_plus_lo + from_lo; // 1 + t
            let d = x_minus_lo - from_lo; // X - t
            let mut f = 1.0;
            if gamma != 0.0 {
                f = match (hi_edge, lo_edge) {
                    (false, false) => (u * v).powf(gamma),
                    (true, false) => v.powf(gamma),
                    (false, true) => u.powf(gamma),
                    (true, true) => 1.0,
                };
            }
            if pe != 0.0 && !lo_point && !hi_point {
                f *= d.abs().powf(pe);
            }
            let vals = g(t, d);
            let fw = f * wi;
            for (a, v) in acc.iter_mut().zip(vals) {
                *a += fw * v;
            }
        }
        for (tt, a) in total.iter_mut().zip(acc) {
            *tt += scale * a;
        }
    }
    total
}
