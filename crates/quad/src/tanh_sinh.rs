//! Double-exponential (tanh–sinh) quadrature through the `quadrature` crate, made honest.
//!
//! Rule (Takahasi & Mori, Publ. RIMS 9 (1974)): $x = \tanh(\tfrac{\pi}{2}\sinh\tau)$,
//! trapezoidal in $\tau$ on $[-3,3]$ with step halving, at most 7 levels (about 385
//! evaluations). The `quadrature` crate (a port of J. D. Cook's code) has two habits that this
//! wrapper removes:
//!
//! * it replaces a non-finite integrand value by $0$. Here every value passes through a check
//!   and the first non-finite one is returned as [`Error::NonFinite`];
//! * its error estimate ignores the truncation of the $\tau$ range at $\pm3$ (the outermost
//!   nodes lie $\delta \approx 4.3\times10^{-14}\,h$ from the ends, $h = (b-a)/2$) and can be optimistic.
//!   Here the estimate is
//!   $$E = \max\big(E_{\text{crate}},\ |Q_A - Q_B|\big) + T + 10\,\varepsilon|Q|,$$
//!   where $Q_A$ is the run at the requested tolerance and $Q_B$ a second run at a
//!   tolerance $10^{-4}$ times smaller (its value is returned), and $T$ bounds the two
//!   neglected end pieces: at each end the local power $\kappa = \max(0,
//!   \log_2|f(a+\delta)/f(a+2\delta)|)$ is measured and, modelling $f \sim (x-a)^{-\kappa}$,
//!   the piece is $\int_a^{a+\delta}|f| = \delta|f(a+\delta)|/(1-\kappa)$; for
//!   $\kappa \ge 0.99$ the tail is unbounded and the result is reported as not converged.

use std::cell::{Cell, RefCell};

use crate::types::check_finite_ends;
use crate::{Error, Estimate, Tolerance};

/// $1 - \tanh(\tfrac{\pi}{2}\sinh 3)$: distance of the crate's outermost node from $\pm1$.
fn end_gap() -> f64 {
    let u = std::f64::consts::FRAC_PI_2 * 3.0f64.sinh();
    2.0 / ((2.0 * u).exp() + 1.0)
}

/// Tanh–sinh integration of $\int_a^b f(x)\,dx$ on a finite interval, with the honest error
/// estimate of the [module docs](self). $a > b$ gives $-\int_b^a$; $a = b$ gives $0$.
///
/// With $c = (a+b)/2$, $h = (b-a)/2$ and $x = \tanh(\tfrac\pi2\sinh\tau)$ the integral becomes
/// $$\int_a^b f\,dx = h\int_{-\infty}^{\infty} f\big(c + h\tanh(\tfrac\pi2\sinh\tau)\big)\,
///   \frac{\tfrac\pi2\cosh\tau}{\cosh^2(\tfrac\pi2\sinh\tau)}\,d\tau,$$
/// whose integrand decays double-exponentially; it is cut to $|\tau| \le 3$ and summed by the
/// trapezoidal rule with step halving (Takahasi & Mori, *Publ. RIMS* 9 (1974), the
/// double-exponential formula; as implemented by the `quadrature` crate). Not a FORMULAS.md
/// item: it is a general integrator.
///
/// Suited to analytic integrands and to mild end singularities (e.g. $\sqrt{1-x^2}$, $\ln x$);
/// strong ones such as $x^{-1/2}$ are beyond the fixed $\tau$ range and come back as
/// [`Error::NotConverged`] rather than as a wrong number.
///
/// # Errors
/// [`Error::NonFinite`], [`Error::NotConverged`] (best estimate attached),
/// [`Error::InvalidInterval`] for NaN or infinite ends.
pub fn tanh_sinh<F: FnMut(f64) -> f64>(
    f: F,
    a: f64,
    b: f64,
    tol: Tolerance,
) -> Result<Estimate, Error> {
    check_finite_ends(a, b)?;
    if a == b {
        return Ok(Estimate { value: 0.0, error: 0.0, evals: 0 });
    }
    let (lo, hi, sign) = if a < b { (a, b, 1.0) } else { (b, a, -1.0) };
    let f = RefCell::new(f);
    let evals = Cell::new(0usize);
    let bad: Cell<Option<(f64, f64)>> = Cell::new(None);
    let g = |x: f64| {
        evals.set(evals.get() + 1);
        let v = (f.borrow_mut())(x);
        if v.is_finite() {
            v
        } else {
            if bad.get().is_none() {
                bad.set(Some((x, v)));
            }
            0.0
        }
    };
    let fail = || bad.get().map(|(x, value)| Error::NonFinite { x, value });

    // Magnitude probe (first convergence check of the crate, ~13 evaluations).
    let probe = quadrature::integrate(g, lo, hi, f64::INFINITY);
    if let Some(e) = fail() {
        return Err(e);
    }
    let target = tol.target(probe.integral).max(f64::MIN_POSITIVE);
    let ra = quadrature::integrate(g, lo, hi, target);
    let rb = quadrature::integrate(g, lo, hi, 1e-4 * target);
    if let Some(e) = fail() {
        return Err(e);
    }
    // The outermost node sits end_gap() from +-1 in the reference variable, i.e. end_gap() * h
    // from each end with h = (hi - lo)/2 the half-length.
    let delta = end_gap() * 0.5 * (hi - lo);
    let mut tail = 0.0;
    for (e1, e2) in [(lo + delta, lo + 2.0 * delta), (hi - delta, hi - 2.0 * delta)] {
        let (f1, f2) = (g(e1).abs(), g(e2).abs());
        let kappa = if f1 > 0.0 && f2 > 0.0 { (f1 / f2).log2().max(0.0) } else { 0.0 };
        tail += if kappa >= 0.99 { f64::INFINITY } else { delta * f1 / (1.0 - kappa) };
    }
    if let Some(e) = fail() {
        return Err(e);
    }
    let value = rb.integral;
    let error = ra.error_estimate.max(rb.error_estimate).max((ra.integral - rb.integral).abs())
        + tail
        + 10.0 * f64::EPSILON * value.abs();
    let est = Estimate { value: sign * value, error, evals: evals.get() };
    if !error.is_finite() || !tol.accepts(value, error) {
        return Err(Error::NotConverged { estimate: est, requested: tol.target(value) });
    }
    Ok(est)
}
