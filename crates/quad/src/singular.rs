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

use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;

use crate::kronrod::gauss_kronrod_checked;
use crate::rules::{jacobi_apply, GaussJacobi};
use crate::types::{check_ordered, checked};
use crate::{AdaptiveConfig, Estimate, QuadError, Tolerance};

thread_local! {
    /// Planned Jacobi rules, keyed by (n, alpha bits, beta bits). Bounded: cleared when large.
    static RULES: RefCell<HashMap<(usize, u64, u64), Rc<GaussJacobi>>> =
        RefCell::new(HashMap::new());
}

fn cached_jacobi(n: usize, alpha: f64, beta: f64) -> Result<Rc<GaussJacobi>, QuadError> {
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

fn check_exponent(name: &'static str, v: f64) -> Result<(), QuadError> {
    if !(v.is_finite() && v > -1.0) {
        return Err(QuadError::OutOfDomain { name, value: v, allowed: "> -1, finite" });
    }
    Ok(())
}

/// Which end of a piece carries the singular weight.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Side {
    Left,
    Right,
}

/// $\int_{lo}^{hi} g(x)\,w(x)\,dx$ with $w = (x-lo)^\gamma$ (Left) or $(hi-x)^\gamma$ (Right).
fn end_piece(
    g: &mut dyn FnMut(f64) -> Result<f64, QuadError>,
    lo: f64,
    hi: f64,
    gamma: f64,
    side: Side,
    cfg: &AdaptiveConfig,
    tol: Tolerance,
    depth: usize,
) -> Result<Estimate, QuadError> {
    if gamma == 0.0 {
        let c = AdaptiveConfig { tol, breakpoints: Vec::new(), ..cfg.clone() };
        return gauss_kronrod_checked(g, lo, hi, &c);
    }
    // Jacobi convention: (1-t)^alpha at the right end, (1+t)^beta at the left end.
    let (ja, jb) = match side {
        Side::Left => (0.0, gamma),
        Side::Right => (gamma, 0.0),
    };
    let mut evals = 0;
    let mut prev: Option<f64> = None;
    let mut best = Estimate { value: 0.0, error: f64::INFINITY, evals: 0 };
    let mut n = 8;
    while n <= cfg.max_order.max(8) {
        let rule = cached_jacobi(n, ja, jb)?;
        let (q, qa) = jacobi_apply(&rule, g, lo, hi)?;
        evals += n;
        if let Some(p) = prev {
            let err = (q - p).abs() + 50.0 * f64::EPSILON * qa;
            best = Estimate { value: q, error: err, evals };
            if tol.accepts(q, err) {
                return Ok(best);
            }
        }
        prev = Some(q);
        n *= 2;
    }
    best.evals = evals;
    let len = hi - lo;
    if depth >= 40 || len <= 64.0 * f64::EPSILON * lo.abs().max(hi.abs()) {
        return Err(QuadError::NotConverged { estimate: best, requested: tol.target(best.value) });
    }
    // Keep the singular end on a shorter piece; the rest is regular.
    let (s_lo, s_hi, r_lo, r_hi) = match side {
        Side::Left => (lo, lo + 0.125 * len, lo + 0.125 * len, hi),
        Side::Right => (hi - 0.125 * len, hi, lo, hi - 0.125 * len),
    };
    let half = Tolerance { abs: 0.5 * tol.abs, rel: tol.rel };
    let inner = end_piece(g, s_lo, s_hi, gamma, side, cfg, half, depth + 1)
        .map_err(|e| add_evals(e, evals))?;
    let mut weighted = |x: f64| -> Result<f64, QuadError> {
        let w = match side {
            Side::Left => (x - lo).powf(gamma),
            Side::Right => (hi - x).powf(gamma),
        };
        Ok(g(x)? * w)
    };
    let c = AdaptiveConfig { tol: half, breakpoints: Vec::new(), ..cfg.clone() };
    let rest = gauss_kronrod_checked(&mut weighted, r_lo, r_hi, &c)
        .map_err(|e| add_evals(e, evals + inner.evals))?;
    let mut total = inner.combine(rest);
    total.evals += evals;
    Ok(total)
}

/// Add spent evaluations to a `NotConverged` error on its way up.
fn add_evals(e: QuadError, extra: usize) -> QuadError {
    match e {
        QuadError::NotConverged { mut estimate, requested } => {
            estimate.evals += extra;
            QuadError::NotConverged { estimate, requested }
        }
        other => other,
    }
}

/// Sum two pieces and check the total against the tolerance.
fn finish(parts: &[Result<Estimate, QuadError>], tol: Tolerance) -> Result<Estimate, QuadError> {
    let mut total = Estimate { value: 0.0, error: 0.0, evals: 0 };
    let mut not_converged = false;
    for p in parts {
        match p {
            Ok(e) => total = total.combine(*e),
            Err(QuadError::NotConverged { estimate, .. }) => {
                total = total.combine(*estimate);
                not_converged = true;
            }
            Err(e) => return Err(e.clone()),
        }
    }
    if not_converged || !tol.accepts(total.value, total.error) {
        return Err(QuadError::NotConverged {
            estimate: total,
            requested: tol.target(total.value),
        });
    }
    Ok(total)
}

fn algebraic_checked(
    f: &mut dyn FnMut(f64) -> Result<f64, QuadError>,
    a: f64,
    b: f64,
    alpha: f64,
    beta: f64,
    cfg: &AdaptiveConfig,
) -> Result<Estimate, QuadError> {
    let m = 0.5 * (a + b);
    let tol = Tolerance { abs: 0.5 * cfg.tol.abs, rel: cfg.tol.rel };
    let left = {
        let mut g = |x: f64| -> Result<f64, QuadError> {
            let v = f(x)?;
            Ok(if beta == 0.0 { v } else { v * (b - x).powf(beta) })
        };
        end_piece(&mut g, a, m, alpha, Side::Left, cfg, tol, 0)
    };
    if let Err(e) = &left {
        if !matches!(e, QuadError::NotConverged { .. }) {
            return Err(e.clone());
        }
    }
    let right = {
        let mut g = |x: f64| -> Result<f64, QuadError> {
            let v = f(x)?;
            Ok(if alpha == 0.0 { v } else { v * (x - a).powf(alpha) })
        };
        end_piece(&mut g, m, b, beta, Side::Right, cfg, tol, 0)
    };
    finish(&[left, right], cfg.tol)
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
/// [`QuadError::InvalidInterval`] unless $a<b$ finite; [`QuadError::OutOfDomain`] for
/// $\alpha \le -1$ or $\beta \le -1$; [`QuadError::NonFinite`]; [`QuadError::NotConverged`].
pub fn algebraic_endpoints<F: FnMut(f64) -> f64>(
    f: F,
    a: f64,
    b: f64,
    alpha: f64,
    beta: f64,
    cfg: &AdaptiveConfig,
) -> Result<Estimate, QuadError> {
    check_ordered(a, b)?;
    check_exponent("alpha", alpha)?;
    check_exponent("beta", beta)?;
    let mut g = checked(f);
    algebraic_checked(&mut g, a, b, alpha, beta, cfg)
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
) -> Result<Estimate, QuadError> {
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
/// [`QuadError::InvalidInterval`] unless $a<b$ finite; [`QuadError::OutOfDomain`] for $k$
/// outside $[0,1)$, non-finite $x$, or an exponent $\le -1$; [`QuadError::NonFinite`];
/// [`QuadError::NotConverged`].
pub fn weakly_singular_weighted<F: FnMut(f64) -> f64>(
    f: F,
    a: f64,
    b: f64,
    x: f64,
    k: f64,
    alpha: f64,
    beta: f64,
    cfg: &AdaptiveConfig,
) -> Result<Estimate, QuadError> {
    check_ordered(a, b)?;
    if !(k.is_finite() && (0.0..1.0).contains(&k)) {
        return Err(QuadError::OutOfDomain { name: "k", value: k, allowed: "0 <= k < 1" });
    }
    if !x.is_finite() {
        return Err(QuadError::OutOfDomain { name: "x", value: x, allowed: "finite" });
    }
    check_exponent("alpha", alpha)?;
    check_exponent("beta", beta)?;
    let mut f = checked(f);
    if k == 0.0 {
        return algebraic_checked(&mut f, a, b, alpha, beta, cfg);
    }
    if x == a {
        check_exponent("alpha - k", alpha - k)?;
        return algebraic_checked(&mut f, a, b, alpha - k, beta, cfg);
    }
    if x == b {
        check_exponent("beta - k", beta - k)?;
        return algebraic_checked(&mut f, a, b, alpha, beta - k, cfg);
    }
    if x < a || x > b {
        let mut g = |s: f64| -> Result<f64, QuadError> { Ok(f(s)? * (x - s).abs().powf(-k)) };
        return algebraic_checked(&mut g, a, b, alpha, beta, cfg);
    }
    let half = AdaptiveConfig {
        tol: Tolerance { abs: 0.5 * cfg.tol.abs, rel: cfg.tol.rel },
        ..cfg.clone()
    };
    let left = {
        let mut g = |s: f64| -> Result<f64, QuadError> {
            let v = f(s)?;
            Ok(if beta == 0.0 { v } else { v * (b - s).powf(beta) })
        };
        algebraic_checked(&mut g, a, x, alpha, -k, &half)
    };
    if let Err(e) = &left {
        if !matches!(e, QuadError::NotConverged { .. }) {
            return Err(e.clone());
        }
    }
    let right = {
        let mut g = |s: f64| -> Result<f64, QuadError> {
            let v = f(s)?;
            Ok(if alpha == 0.0 { v } else { v * (s - a).powf(alpha) })
        };
        algebraic_checked(&mut g, x, b, -k, beta, &half)
    };
    finish(&[left, right], cfg.tol)
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
/// [`QuadError::InvalidInterval`] unless $a<b$ finite; [`QuadError::OutOfDomain`] unless
/// $a<x<b$; [`QuadError::NonFinite`]; [`QuadError::NotConverged`].
pub fn cauchy_pv<F: FnMut(f64) -> f64>(
    f: F,
    a: f64,
    b: f64,
    x: f64,
    cfg: &AdaptiveConfig,
) -> Result<Estimate, QuadError> {
    check_ordered(a, b)?;
    if !(x > a && x < b) {
        return Err(QuadError::OutOfDomain { name: "x", value: x, allowed: "a < x < b" });
    }
    let mut f = checked(f);
    let fx = f(x)?;
    let log = ((b - x) / (x - a)).ln();
    let mut g = |t: f64| -> Result<f64, QuadError> {
        if t == x {
            return Ok(0.0);
        }
        let v = (f(t)? - fx) / (t - x);
        if v.is_finite() {
            Ok(v)
        } else {
            Err(QuadError::NonFinite { x: t, value: v })
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
                Err(QuadError::NotConverged { estimate: e, requested: cfg.tol.target(e.value) })
            }
        }
        Err(QuadError::NotConverged { estimate, .. }) => {
            let e = add(estimate);
            Err(QuadError::NotConverged { estimate: e, requested: cfg.tol.target(e.value) })
        }
        Err(e) => Err(e),
    }
}
