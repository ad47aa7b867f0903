//! Integrals with algebraic end singularities, weak interior singularities and Cauchy
//! principal values.
//!
//! Building block ([`algebraic_endpoints`], QUADPACK QAWS's task, done differently): split
//! $\lbrack a,b\rbrack$ at its midpoint; on each half only one end carries a singular weight, which is
//! integrated by Gauss–Jacobi rules of order $n = 8, 16, 32, \dots$ up to
//! [`AdaptiveConfig::max_order`], the smooth remainder of the integrand being the Jacobi
//! rule's $f$. The error of $Q_n$ is estimated by $|Q_n - Q_{n/2}|$ (conservative: it is the
//! error of the coarser rule when the sequence converges). If the orders are exhausted (the
//! smooth factor is not smooth enough, e.g. a nearby singularity), the half is split again: a
//! piece of one eighth of its length keeps the singular end and recurses, the rest goes to
//! adaptive Gauss–Kronrod with the weight folded into the integrand, which is harmless away
//! from the singular end.
//!
//! Every half works in the offset $u$ from its singular end, and every algebraic factor
//! $|s-p|^e$ of the weight is evaluated from offsets (`half_piece`), so a singular point close
//! to another one (e.g. $x$ at $5\cdot10^{-4}$ from $b$) costs no accuracy. The error of a
//! Jacobi sum has the floor $10\varepsilon\sum|w_i f_i|$; when two orders agree to within that
//! floor and the tolerance is still not met, the request is below rounding and the integrator
//! stops with [`Error::NotConverged`] instead of subdividing. A piece that does not converge
//! keeps its estimate, which is added to the others: a `NotConverged` always carries the whole
//! integral with an error bound that covers its true error.

use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;

use crate::kronrod::gauss_kronrod_checked;
use crate::rules::{jacobi_apply, GaussJacobi};
use crate::types::{check_ordered, checked};
use crate::{AdaptiveConfig, Error, Estimate, Tolerance};

thread_local! {
    /// Planned Jacobi rules, keyed by (n, alpha bits, beta bits). Bounded: cleared when large.
    static RULES: RefCell<HashMap<(usize, u64, u64), Rc<GaussJacobi>>> =
        RefCell::new(HashMap::new());
}

fn cached_jacobi(n: usize, alpha: f64, beta: f64) -> Result<Rc<GaussJacobi>, Error> {
    let key = (n, alpha.to_bits(), beta.to_bits());
    if let Some(r) = RULES.with(|c| c.borrow().get(&key).cloned()) {
        return Ok(r);
    }
    let r = Rc::new(GaussJacobi::new(n, alpha, beta)?);
    RULES.with(|c| {
        let mut c = c.borrow_mut();
        if c.len() > 256 {
            c.clear();
        }
        c.insert(key, Rc::clone(&r));
    });
    Ok(r)
}

fn check_exponent(name: &'static str, v: f64) -> Result<(), Error> {
    if !(v.is_finite() && v > -1.0) {
        return Err(Error::OutOfDomain { name, value: v, allowed: "> -1, finite" });
    }
    Ok(())
}

/// Rounding floor of one Jacobi sum, as a multiple of $\varepsilon\sum_i|w_i f(x_i)|$: the
/// computed nodes and weights carry a few ulps each and the integrand values about one ulp
/// (the measured worst true error over `tests/tight.rs` stays below this floor). It equals the
/// Gauss–Kronrod floor, so a relative request of $10^{-14}$ is reachable and $10^{-15}$ is
/// reported as not converged.
const JACOBI_FLOOR: f64 = 10.0 * f64::EPSILON;

/// The estimate of one piece of the range, and whether that piece met its share of the
/// tolerance. A piece that did not converge still carries its best estimate and an honest
/// error, so the caller adds it to the others: the whole integral is never replaced by one of
/// its pieces (the defect behind a `NotConverged` of $6.5\cdot10^{-22}$ for an integral of
/// $1.75$).
#[derive(Clone, Copy, Debug)]
struct Part {
    est: Estimate,
    converged: bool,
}

impl Part {
    const ZERO: Part = Part { est: Estimate { value: 0.0, error: 0.0, evals: 0 }, converged: true };

    /// Sum of two disjoint pieces, converged only if both are and the sum meets `tol`.
    fn join_checked(self, other: Part, tol: Tolerance) -> Part {
        let est = self.est.combine(other.est);
        let converged = self.converged && other.converged && tol.accepts(est.value, est.error);
        Part { est, converged }
    }

    /// The public result: `Ok` only for a converged part that meets `tol`.
    fn finish(self, tol: Tolerance) -> Result<Estimate, Error> {
        if self.converged && tol.accepts(self.est.value, self.est.error) {
            Ok(self.est)
        } else {
            Err(Error::NotConverged { estimate: self.est, requested: tol.target(self.est.value) })
        }
    }
}

/// Adaptive Gauss–Kronrod on a regular piece, a `NotConverged` outcome kept as a [`Part`].
fn regular_piece(
    g: &mut dyn FnMut(f64) -> Result<f64, Error>,
    lo: f64,
    hi: f64,
    cfg: &AdaptiveConfig,
    tol: Tolerance,
) -> Result<Part, Error> {
    let c = AdaptiveConfig { tol, breakpoints: Vec::new(), ..cfg.clone() };
    match gauss_kronrod_checked(g, lo, hi, &c) {
        Ok(est) => Ok(Part { est, converged: true }),
        Err(Error::NotConverged { estimate, .. }) => Ok(Part { est: estimate, converged: false }),
        Err(e) => Err(e),
    }
}

/// $\int_0^{L} g(u)\,u^\gamma\,du$ in the offset variable $u$ (distance from the singular
/// point), for $g$ smooth on $[0, L]$ or with a singularity at some distance beyond $L$.
///
/// Returns `Err` only for hard failures (non-finite integrand, rule construction); a piece that
/// misses `tol` comes back as a non-converged [`Part`] carrying the best estimate of the WHOLE
/// of $[0, L]$.
fn end_piece(
    g: &mut dyn FnMut(f64) -> Result<f64, Error>,
    len: f64,
    gamma: f64,
    cfg: &AdaptiveConfig,
    tol: Tolerance,
    depth: usize,
) -> Result<Part, Error> {
    if gamma == 0.0 {
        return regular_piece(g, 0.0, len, cfg, tol);
    }
    // Jacobi convention: (1+t)^beta at the left end, where u = 0.
    let mut evals = 0;
    let mut prev: Option<f64> = None;
    let mut best = Estimate { value: 0.0, error: f64::INFINITY, evals: 0 };
    let mut at_floor = false;
    let mut n = 8;
    while n <= cfg.max_order.max(8) {
        let rule = cached_jacobi(n, 0.0, gamma)?;
        let (q, qa) = jacobi_apply(&rule, g, 0.0, len)?;
        evals += n;
        match prev {
            None => best = Estimate { value: q, error: f64::INFINITY, evals },
            Some(p) => {
                let diff = (q - p).abs();
                let floor = JACOBI_FLOOR * qa;
                let err = diff + floor;
                if err <= best.error {
                    best = Estimate { value: q, error: err, evals };
                }
                best.evals = evals;
                if tol.accepts(q, err) {
                    return Ok(Part { est: best, converged: true });
                }
                // Two orders agree to rounding: the sequence has converged, and neither a
                // higher order nor a subdivision can beat the floor; the request is below it.
                if diff <= floor {
                    at_floor = true;
                    break;
                }
            }
        }
        prev = Some(q);
        n *= 2;
    }
    best.evals = evals;
    if at_floor || depth >= 40 || len < f64::MIN_POSITIVE / f64::EPSILON {
        return Ok(Part { est: best, converged: false });
    }
    // Keep the singular end on a piece of one eighth the length; the rest is regular.
    let cut = 0.125 * len;
    let half = Tolerance { abs: 0.5 * tol.abs, rel: tol.rel };
    let inner = end_piece(g, cut, gamma, cfg, half, depth + 1)?;
    let mut weighted = |u: f64| -> Result<f64, Error> { Ok(g(u)? * u.powf(gamma)) };
    let rest = regular_piece(&mut weighted, cut, len, cfg, half)?;
    let mut split = inner.join_checked(rest, tol);
    split.est.evals += evals;
    if split.converged || split.est.error <= best.error {
        Ok(split)
    } else {
        // The subdivision did worse than the plain Jacobi sequence: keep the better estimate
        // of the same piece, with everything spent on it.
        Ok(Part { est: Estimate { evals: split.est.evals, ..best }, converged: false })
    }
}

/// A factor $|s - p|^e$ of the weight.
#[derive(Clone, Copy, Debug)]
struct Factor {
    p: f64,
    e: f64,
}

/// $\int f(s)\prod_j|s-p_j|^{e_j}\,ds$ over the part of the range within `len` of `anchor`
/// on the side `dir` ($+1$: $s = \text{anchor} + u$, $-1$: $s = \text{anchor} - u$), with
/// $|s - \text{anchor}|^{\gamma}$ as the Jacobi weight.
///
/// Every weight factor is evaluated from offsets, $|s - p| = |(\text{anchor} - p) + \text{dir}\,u|$,
/// never from the rounded abscissa $s$: near a singular point at distance $d$ from another
/// one, $s$ itself carries an absolute error $\varepsilon|s|$, i.e. a relative error
/// $\varepsilon|s|/d$ in $s - p$ (2e-13 for $d = 5\cdot10^{-4}$), while $u$ is exact to
/// $\varepsilon u$. Only the caller's smooth $f$ sees $s$.
fn half_piece(
    f: &mut dyn FnMut(f64) -> Result<f64, Error>,
    anchor: f64,
    dir: f64,
    len: f64,
    gamma: f64,
    others: &[Factor],
    cfg: &AdaptiveConfig,
    tol: Tolerance,
) -> Result<Part, Error> {
    if len == 0.0 {
        return Ok(Part::ZERO);
    }
    let offsets: Vec<(f64, f64)> =
        others.iter().filter(|q| q.e != 0.0).map(|q| (anchor - q.p, q.e)).collect();
    let mut g = |u: f64| -> Result<f64, Error> {
        let mut v = f(anchor + dir * u)?;
        for &(d, e) in &offsets {
            v *= (d + dir * u).abs().powf(e);
        }
        if v.is_finite() {
            Ok(v)
        } else {
            Err(Error::NonFinite { x: anchor + dir * u, value: v })
        }
    };
    end_piece(&mut g, len, gamma, cfg, tol, 0)
}

/// $\int_a^b f(s)\prod_j|s-p_j|^{e_j}\,ds$ where the singular points inside $[a,b]$ are the
/// sorted `cuts` (including $a$ and $b$, each with its exponent) and `outside` holds the
/// factors whose points lie outside. Each interval between consecutive cuts is split at its
/// midpoint (in offsets: both halves have length $(p_{i+1}-p_i)/2$, so they meet without a
/// gap), and each half is a [`half_piece`] anchored at its singular end. The halves share the
/// tolerance: relative part unchanged, absolute part divided by their number.
fn singular_sum(
    f: &mut dyn FnMut(f64) -> Result<f64, Error>,
    cuts: &[Factor],
    outside: &[Factor],
    cfg: &AdaptiveConfig,
) -> Result<Estimate, Error> {
    let halves = 2 * (cuts.len() - 1);
    let share = Tolerance { abs: cfg.tol.abs / halves as f64, rel: cfg.tol.rel };
    let all: Vec<Factor> = cuts.iter().chain(outside).copied().collect();
    let others = |anchor: usize| -> Vec<Factor> {
        all.iter().enumerate().filter(|(j, _)| *j != anchor).map(|(_, q)| *q).collect()
    };
    let mut total = Estimate { value: 0.0, error: 0.0, evals: 0 };
    let mut converged = true;
    for (i, w) in cuts.windows(2).enumerate() {
        let len = 0.5 * (w[1].p - w[0].p);
        for part in [
            half_piece(f, w[0].p, 1.0, len, w[0].e, &others(i), cfg, share)?,
            half_piece(f, w[1].p, -1.0, len, w[1].e, &others(i + 1), cfg, share)?,
        ] {
            total = total.combine(part.est);
            converged &= part.converged;
        }
    }
    Part { est: total, converged }.finish(cfg.tol)
}

/// $$\int_a^b f(x)\,(x-a)^\alpha\,(b-x)^\beta\,dx,\qquad \alpha,\beta > -1,$$
/// for smooth $f$ (QUADPACK QAWS's integral; Piessens et al. 1983, §2.2.4), by the
/// Jacobi-order growth and end-subdivision scheme of the [module docs](self). Note the
/// convention: $\alpha$ belongs to the **left** end here (as in QAWS), unlike
/// [`GaussJacobi`].
///
/// Uses `cfg.tol`, `cfg.max_order` (Jacobi orders) and `cfg.max_subdivisions`/`cfg.rule` (for
/// the regular parts); `cfg.breakpoints` is ignored.
///
/// # Errors
/// [`Error::InvalidInterval`] unless $a<b$ finite; [`Error::OutOfDomain`] for
/// $\alpha \le -1$ or $\beta \le -1$; [`Error::NonFinite`]; [`Error::NotConverged`].
pub fn algebraic_endpoints<F: FnMut(f64) -> f64>(
    f: F,
    a: f64,
    b: f64,
    alpha: f64,
    beta: f64,
    cfg: &AdaptiveConfig,
) -> Result<Estimate, Error> {
    check_ordered(a, b)?;
    check_exponent("alpha", alpha)?;
    check_exponent("beta", beta)?;
    let mut g = checked(f);
    singular_sum(&mut g, &[Factor { p: a, e: alpha }, Factor { p: b, e: beta }], &[], cfg)
}

/// $$\int_a^b f(s)\,|x-s|^{-k}\,ds,\qquad 0 \le k < 1,$$
/// for smooth $f$ and any finite $x$ (inside, at an end, or outside $\lbrack a,b\rbrack$). This is the
/// kernel of the graded half-plane displacements, FORMULAS.md §A3 (Giannakopoulos & Pallot
/// 2000, eqs 26–27). Same as [`weakly_singular_weighted`] with $\alpha=\beta=0$.
///
/// # Errors
/// As [`weakly_singular_weighted`].
pub fn weakly_singular<F: FnMut(f64) -> f64>(
    f: F,
    a: f64,
    b: f64,
    x: f64,
    k: f64,
    cfg: &AdaptiveConfig,
) -> Result<Estimate, Error> {
    weakly_singular_weighted(f, a, b, x, k, 0.0, 0.0, cfg)
}

/// $$\int_a^b f(s)\,(s-a)^\alpha\,(b-s)^\beta\,|x-s|^{-k}\,ds,\qquad 0\le k<1,\ \alpha,\beta>-1,$$
/// e.g. the graded contact pressure $(1-s^2)^{(1+k)/2}$ against the kernel $|x-s|^{-k}$
/// (FORMULAS.md §A4). For $a<x<b$ the range is split at $x$ and each side is an
/// [`algebraic_endpoints`] integral with exponent $-k$ at $x$; for $x$ at an end the exponents
/// add ($\alpha - k > -1$ is required); for $x$ outside, $|x-s|^{-k}$ is folded into $f$ (a
/// nearby $x$ is handled by the end subdivision).
///
/// # Errors
/// [`Error::InvalidInterval`] unless $a<b$ finite; [`Error::OutOfDomain`] for $k$
/// outside $[0,1)$, non-finite $x$, or an exponent $\le -1$; [`Error::NonFinite`];
/// [`Error::NotConverged`].
pub fn weakly_singular_weighted<F: FnMut(f64) -> f64>(
    f: F,
    a: f64,
    b: f64,
    x: f64,
    k: f64,
    alpha: f64,
    beta: f64,
    cfg: &AdaptiveConfig,
) -> Result<Estimate, Error> {
    check_ordered(a, b)?;
    if !(k.is_finite() && (0.0..1.0).contains(&k)) {
        return Err(Error::OutOfDomain { name: "k", value: k, allowed: "0 <= k < 1" });
    }
    if !x.is_finite() {
        return Err(Error::OutOfDomain { name: "x", value: x, allowed: "finite" });
    }
    check_exponent("alpha", alpha)?;
    check_exponent("beta", beta)?;
    let mut f = checked(f);
    let (fa, fb) = (Factor { p: a, e: alpha }, Factor { p: b, e: beta });
    let fx = Factor { p: x, e: -k };
    if k == 0.0 {
        return singular_sum(&mut f, &[fa, fb], &[], cfg);
    }
    if x == a {
        check_exponent("alpha - k", alpha - k)?;
        return singular_sum(&mut f, &[Factor { p: a, e: alpha - k }, fb], &[], cfg);
    }
    if x == b {
        check_exponent("beta - k", beta - k)?;
        return singular_sum(&mut f, &[fa, Factor { p: b, e: beta - k }], &[], cfg);
    }
    if x < a || x > b {
        return singular_sum(&mut f, &[fa, fb], &[fx], cfg);
    }
    // Split at x: each of the four halves has one singular end.
    singular_sum(&mut f, &[fa, fx, fb], &[], cfg)
}

/// Cauchy principal value
/// $$\mathrm{PV}\!\int_a^b \frac{f(t)}{t-x}\,dt
/// = \int_a^b \frac{f(t)-f(x)}{t-x}\,dt + f(x)\ln\frac{b-x}{x-a},\qquad a<x<b,$$
/// by singularity subtraction (Kythe & Schäferkotter, *Handbook of Computational Methods for
/// Integration*, §6.1; the kernel of FORMULAS.md §C). The regular integral is done by
/// [`gauss_kronrod`](crate::gauss_kronrod()) with a breakpoint at $x$ (plus `cfg.breakpoints`),
/// so no node falls on $x$; near $x$ the difference quotient loses only about
/// $\varepsilon|f(x)|/|t-x|$, a few $\varepsilon|f|$ in total for Kronrod nodes. Works for
/// $x$ arbitrarily close to an end (the logarithm is exact).
///
/// # Errors
/// [`Error::InvalidInterval`] unless $a<b$ finite; [`Error::OutOfDomain`] unless
/// $a<x<b$; [`Error::NonFinite`]; [`Error::NotConverged`].
pub fn cauchy_pv<F: FnMut(f64) -> f64>(
    f: F,
    a: f64,
    b: f64,
    x: f64,
    cfg: &AdaptiveConfig,
) -> Result<Estimate, Error> {
    check_ordered(a, b)?;
    if !(x > a && x < b) {
        return Err(Error::OutOfDomain { name: "x", value: x, allowed: "a < x < b" });
    }
    let mut f = checked(f);
    let fx = f(x)?;
    let log = ((b - x) / (x - a)).ln();
    let mut g = |t: f64| -> Result<f64, Error> {
        if t == x {
            return Ok(0.0);
        }
        let v = (f(t)? - fx) / (t - x);
        if v.is_finite() {
            Ok(v)
        } else {
            Err(Error::NonFinite { x: t, value: v })
        }
    };
    let mut bps = cfg.breakpoints.clone();
    bps.push(x);
    let c = AdaptiveConfig { breakpoints: bps, ..cfg.clone() };
    let add = |mut e: Estimate| {
        e.value += fx * log;
        e.error += 4.0 * f64::EPSILON * (fx * log).abs();
        e.evals += 1;
        e
    };
    match gauss_kronrod_checked(&mut g, a, b, &c) {
        Ok(e) => {
            let e = add(e);
            if cfg.tol.accepts(e.value, e.error) {
                Ok(e)
            } else {
                Err(Error::NotConverged { estimate: e, requested: cfg.tol.target(e.value) })
            }
        }
        Err(Error::NotConverged { estimate, .. }) => {
            let e = add(estimate);
            Err(Error::NotConverged { estimate: e, requested: cfg.tol.target(e.value) })
        }
        Err(e) => Err(e),
    }
}
