//! The accuracy-versus-cost battery: integrands with known values (closed forms, or mpmath at
//! 40 digits from `scripts/quad_battery.py`, stored in `tests/data/battery.csv`), the methods
//! of this crate, and a runner that returns one [`Row`] per (method, integrand) pair.
//!
//! The integrands include the kernels of `docs/FORMULAS.md`: the graded spectral
//! relation of §A4, $I_k$ and $J_k$ of §A1, and the Cauchy integral of §C.

use std::f64::consts::{FRAC_PI_2, PI};
use std::sync::Arc;

use crate::{
    algebraic_endpoints, cauchy_pv, gauss_kronrod, tanh_sinh, weakly_singular_weighted,
    AdaptiveConfig, Error, Estimate, GaussChebyshev, GaussJacobi, GaussLegendre, KronrodRule, Rule,
    Tolerance,
};

const DATA: &str = include_str!("../tests/data/battery.csv");

/// A shareable integrand.
pub type Func = Arc<dyn Fn(f64) -> f64 + Send + Sync>;

/// The shape of an integral, which decides which methods apply.
#[derive(Clone)]
pub enum Kind {
    /// $\int_a^b f(x)\,dx$ (ends may be infinite).
    Plain {
        /// Integrand.
        f: Func,
        /// Lower end.
        a: f64,
        /// Upper end.
        b: f64,
    },
    /// $\int_a^b f(x)(x-a)^\alpha(b-x)^\beta\,dx$.
    Weighted {
        /// Smooth factor.
        f: Func,
        /// Lower end.
        a: f64,
        /// Upper end.
        b: f64,
        /// Exponent at $a$.
        alpha: f64,
        /// Exponent at $b$.
        beta: f64,
    },
    /// $\int_a^b f(s)(s-a)^\alpha(b-s)^\beta|x-s|^{-k}\,ds$.
    Weak {
        /// Smooth factor.
        f: Func,
        /// Lower end.
        a: f64,
        /// Upper end.
        b: f64,
        /// Singular point.
        x: f64,
        /// Kernel exponent.
        k: f64,
        /// Exponent at $a$.
        alpha: f64,
        /// Exponent at $b$.
        beta: f64,
    },
    /// $\mathrm{PV}\int_a^b f(t)/(t-x)\,dt$.
    Pv {
        /// Numerator.
        f: Func,
        /// Lower end.
        a: f64,
        /// Upper end.
        b: f64,
        /// Pole.
        x: f64,
    },
}

/// One integrand with its reference value.
#[derive(Clone)]
pub struct Problem {
    /// Short name (the key in `battery.csv`).
    pub name: &'static str,
    /// The integral.
    pub kind: Kind,
    /// Reference value.
    pub exact: f64,
}

/// A method of this crate, with its accuracy knob.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// [`gauss_kronrod`] with $G_{10}K_{21}$.
    Gk21,
    /// [`gauss_kronrod`] with $G_7K_{15}$.
    Gk15,
    /// [`tanh_sinh()`].
    TanhSinh,
    /// [`GaussLegendre`] with this many nodes.
    Legendre(usize),
    /// [`GaussJacobi`] with this many nodes (weighted problems).
    Jacobi(usize),
    /// [`GaussChebyshev`] with this many nodes (weights $(1-x^2)^{\pm1/2}$).
    Chebyshev(usize),
    /// [`algebraic_endpoints`].
    Algebraic,
    /// [`weakly_singular_weighted`].
    WeaklySingular,
    /// [`cauchy_pv`].
    CauchyPv,
}

impl Method {
    /// Every method, with the fixed-rule sizes used by the battery.
    #[must_use]
    pub fn all() -> Vec<Method> {
        vec![
            Method::Gk21,
            Method::Gk15,
            Method::TanhSinh,
            Method::Legendre(128),
            Method::Jacobi(128),
            Method::Chebyshev(128),
            Method::Algebraic,
            Method::WeaklySingular,
            Method::CauchyPv,
        ]
    }

    /// Display name.
    #[must_use]
    pub fn name(&self) -> String {
        match self {
            Method::Gk21 => "gauss_kronrod(G10K21)".into(),
            Method::Gk15 => "gauss_kronrod(G7K15)".into(),
            Method::TanhSinh => "tanh_sinh".into(),
            Method::Legendre(n) => format!("GaussLegendre({n})"),
            Method::Jacobi(n) => format!("GaussJacobi({n})"),
            Method::Chebyshev(n) => format!("GaussChebyshev({n})"),
            Method::Algebraic => "algebraic_endpoints".into(),
            Method::WeaklySingular => "weakly_singular".into(),
            Method::CauchyPv => "cauchy_pv".into(),
        }
    }
}

/// One line of the report.
#[derive(Debug, Clone)]
pub struct Row {
    /// Method name.
    pub method: String,
    /// Integrand name.
    pub problem: &'static str,
    /// The method's result (an error if it did not converge or failed).
    pub result: Result<Estimate, Error>,
    /// Reference value.
    pub exact: f64,
    /// Requested tolerance.
    pub tol: Tolerance,
}

impl Row {
    /// The estimate, whether or not the method claimed convergence.
    #[must_use]
    pub fn estimate(&self) -> Option<Estimate> {
        match &self.result {
            Ok(e) => Some(*e),
            Err(Error::NotConverged { estimate, .. }) => Some(*estimate),
            Err(_) => None,
        }
    }

    /// $|Q - I|$ (NaN if there is no estimate).
    #[must_use]
    pub fn true_error(&self) -> f64 {
        self.estimate().map_or(f64::NAN, |e| (e.value - self.exact).abs())
    }

    /// Whether the method converged, its true error meets the tolerance (measured against the
    /// exact value) and its error estimate is not smaller than the true error.
    #[must_use]
    pub fn passes(&self) -> bool {
        match &self.result {
            Ok(e) => {
                let t = self.true_error();
                t <= self.tol.target(self.exact) && e.error >= t
            }
            Err(_) => false,
        }
    }

    /// Fixed-width text line: method, integrand, evaluations, true error, estimate, status.
    #[must_use]
    pub fn format(&self) -> String {
        let (evals, est) = self.estimate().map_or((0, f64::NAN), |e| (e.evals, e.error));
        let status = match &self.result {
            Ok(_) if self.passes() => "ok".to_string(),
            Ok(_) => "tol not reached".to_string(),
            Err(Error::NotConverged { .. }) => "not converged".to_string(),
            Err(e) => format!("error: {e}"),
        };
        format!(
            "{:<24} {:<16} {:>7} {:>10.2e} {:>10.2e}  {}",
            self.method,
            self.problem,
            evals,
            self.true_error(),
            est,
            status
        )
    }
}

/// Header line matching [`Row::format`].
#[must_use]
pub fn header() -> String {
    format!(
        "{:<24} {:<16} {:>7} {:>10} {:>10}  status",
        "method", "integrand", "evals", "true err", "estimate"
    )
}

fn lookup(name: &str) -> (f64, f64) {
    for line in DATA.lines() {
        if line.starts_with('#') || line.starts_with("name,") {
            continue;
        }
        let mut it = line.split(',');
        if it.next() == Some(name) {
            let p: f64 = it.next().and_then(|s| s.parse().ok()).unwrap_or(f64::NAN);
            let v: f64 = it.next().and_then(|s| s.parse().ok()).unwrap_or(f64::NAN);
            return (p, v);
        }
    }
    (f64::NAN, f64::NAN)
}

fn func(f: impl Fn(f64) -> f64 + Send + Sync + 'static) -> Func {
    Arc::new(f)
}

/// The battery's integrands (43 of them), in a fixed order.
#[must_use]
pub fn problems() -> Vec<Problem> {
    let mut v = Vec::new();
    let mut push = |name: &'static str, kind: Kind| {
        let (_, exact) = lookup(name);
        v.push(Problem { name, kind, exact });
    };
    let plain = |f: Func, a: f64, b: f64| Kind::Plain { f, a, b };
    let one = || func(|_| 1.0);
    // smooth
    push("poly5", plain(func(|x| x.powi(5) - 3.0 * x * x + 1.0), -1.0, 2.0));
    push("exp01", plain(func(f64::exp), 0.0, 1.0));
    push("atan4", plain(func(|x| 1.0 / (1.0 + x * x)), 0.0, 4.0));
    push("runge", plain(func(|x| 1.0 / (1.0 + 25.0 * x * x)), -1.0, 1.0));
    push("cos50", plain(func(|x| (50.0 * x).cos()), 0.0, 1.0));
    push("xsin30", plain(func(|x| x * (30.0 * x).sin()), 0.0, 1.0));
    push("gauss3", plain(func(|x| (-x * x).exp()), -3.0, 3.0));
    // endpoint singular
    let w =
        |f: Func, a: f64, b: f64, alpha: f64, beta: f64| Kind::Weighted { f, a, b, alpha, beta };
    push("cheb1", w(one(), -1.0, 1.0, -0.5, -0.5));
    push("cheb2", w(one(), -1.0, 1.0, 0.5, 0.5));
    push("cheb1_exp", w(func(f64::exp), -1.0, 1.0, -0.5, -0.5));
    push("cheb2_cos", w(func(f64::cos), -1.0, 1.0, 0.5, 0.5));
    push("xpow09", w(one(), 0.0, 1.0, -0.9, 0.0));
    push("xpow09_cos", w(func(f64::cos), 0.0, 1.0, -0.9, 0.0));
    push("log01", plain(func(f64::ln), 0.0, 1.0));
    push("jac_mixed", w(func(f64::exp), 0.0, 1.0, -0.5, 0.3));
    // interior weak singularities
    let weak = |x: f64, k: f64| Kind::Weak {
        f: func(f64::cos),
        a: -1.0,
        b: 1.0,
        x,
        k,
        alpha: 0.0,
        beta: 0.0,
    };
    push("weak01_c", weak(0.0, 0.1));
    push("weak01_e", weak(0.9375, 0.1));
    push("weak09_c", weak(0.0, 0.9));
    push("weak09_e", weak(0.9375, 0.9));
    push("weak09_n", weak(0.99951171875, 0.9));
    push("weak09_end", weak(1.0, 0.9));
    push("weak05_out", weak(1.0078125, 0.5));
    // principal values
    let pv = |f: Func, x: f64| Kind::Pv { f, a: -1.0, b: 1.0, x };
    push("pv_exp_c", pv(func(f64::exp), 0.25));
    push("pv_exp_e", pv(func(f64::exp), 0.9990234375));
    push("pv_sqrt", pv(func(|t| ((1.0 - t) * (1.0 + t)).sqrt()), 0.375));
    push("pv_sqrt_e", pv(func(|t| ((1.0 - t) * (1.0 + t)).sqrt()), -0.99609375));
    // infinite ranges
    let inf = f64::INFINITY;
    push("expinf", plain(func(|x| (-x).exp()), 0.0, inf));
    push("lorentz_half", plain(func(|x| 1.0 / (1.0 + x * x)), 0.0, inf));
    push("lorentz_whole", plain(func(|x| 1.0 / (1.0 + x * x)), -inf, inf));
    push("xgauss", plain(func(|x| x * (-x * x).exp()), 0.0, inf));
    push("gauss_whole", plain(func(|x| (-x * x).exp()), -inf, inf));
    push("exp2_lower", plain(func(|x| (2.0 * x).exp()), -inf, 1.0));
    // FORMULAS.md A4 spectral relation
    for (name, k, x) in [
        ("a4_k01", 0.1, 0.375),
        ("a4_k05", 0.5, 0.375),
        ("a4_k09", 0.9, 0.375),
        ("a4_k09_e", 0.9, 0.9375),
    ] {
        let e = 0.5 * (1.0 + k);
        push(name, Kind::Weak { f: one(), a: -1.0, b: 1.0, x, k, alpha: e, beta: e });
    }
    // FORMULAS.md A1: I_k = int cos^{k+1} t cos(beta t), J_k = int cos^k t sin t sin(beta t) on
    // [0, pi/2]; written with the weight (pi/2 - t)^{k+1} resp. (pi/2 - t)^k explicit.
    for (ik, jk, k) in [("ik_01", "jk_01", 0.1), ("ik_05", "jk_05", 0.5)] {
        let (beta, _) = lookup(ik);
        let ratio = |t: f64| {
            let d = FRAC_PI_2 - t;
            if d == 0.0 {
                1.0
            } else {
                t.cos() / d
            }
        };
        let fi = func(move |t| ratio(t).powf(k + 1.0) * (beta * t).cos());
        let fj = func(move |t| ratio(t).powf(k) * t.sin() * (beta * t).sin());
        push(ik, w(fi, 0.0, FRAC_PI_2, 0.0, k + 1.0));
        push(jk, w(fj, 0.0, FRAC_PI_2, 0.0, k));
    }
    // FORMULAS.md C: (1/pi) int sqrt(1-t^2)/(t-z) dt for real z outside [-1, 1]
    for (name, z) in
        [("cauchy_out_15", 1.5), ("cauchy_out_m3", -3.0), ("cauchy_out_near", 1.0078125)]
    {
        push(name, w(func(move |t| 1.0 / (PI * (t - z))), -1.0, 1.0, 0.5, 0.5));
    }
    v
}

/// Sum of two pieces; not converged if either is not, or if the sum misses `tol`.
fn both(
    l: Result<Estimate, Error>,
    r: Result<Estimate, Error>,
    tol: Tolerance,
) -> Result<Estimate, Error> {
    let get = |x: Result<Estimate, Error>| match x {
        Ok(e) => Ok((e, true)),
        Err(Error::NotConverged { estimate, .. }) => Ok((estimate, false)),
        Err(e) => Err(e),
    };
    let (el, okl) = get(l)?;
    let (er, okr) = get(r)?;
    let e = el.combine(er);
    if okl && okr && tol.accepts(e.value, e.error) {
        Ok(e)
    } else {
        Err(Error::NotConverged { estimate: e, requested: tol.target(e.value) })
    }
}

fn weighted_fn(f: &Func, a: f64, b: f64, alpha: f64, beta: f64) -> impl Fn(f64) -> f64 + '_ {
    move |x| {
        let mut v = f(x);
        if alpha != 0.0 {
            v *= (x - a).powf(alpha);
        }
        if beta != 0.0 {
            v *= (b - x).powf(beta);
        }
        v
    }
}

/// Run one method on one problem at tolerance `tol`; `None` if the method does not apply to
/// that shape of integral (e.g. a principal value for a plain rule).
#[must_use]
pub fn run(method: Method, p: &Problem, tol: Tolerance) -> Option<Row> {
    let cfg = AdaptiveConfig::new(tol);
    let result = match (&p.kind, method) {
        (Kind::Plain { f, a, b }, Method::Gk21 | Method::Gk15) => {
            let rule =
                if method == Method::Gk21 { KronrodRule::G10K21 } else { KronrodRule::G7K15 };
            gauss_kronrod(|x| f(x), *a, *b, &cfg.with_rule(rule))
        }
        (Kind::Plain { f, a, b }, Method::TanhSinh) => tanh_sinh(|x| f(x), *a, *b, tol),
        (Kind::Plain { f, a, b }, Method::Legendre(n)) => {
            GaussLegendre::new(n).and_then(|r| r.integrate(|x| f(x), *a, *b))
        }
        (Kind::Weighted { f, a, b, alpha, beta }, m) => {
            let g = weighted_fn(f, *a, *b, *alpha, *beta);
            match m {
                Method::Gk21 | Method::Gk15 => {
                    let rule =
                        if m == Method::Gk21 { KronrodRule::G10K21 } else { KronrodRule::G7K15 };
                    gauss_kronrod(g, *a, *b, &cfg.with_rule(rule))
                }
                Method::TanhSinh => tanh_sinh(g, *a, *b, tol),
                Method::Legendre(n) => GaussLegendre::new(n).and_then(|r| r.integrate(g, *a, *b)),
                Method::Jacobi(n) => {
                    GaussJacobi::new(n, *beta, *alpha).and_then(|r| r.integrate(|x| f(x), *a, *b))
                }
                Method::Chebyshev(n) if alpha == beta && alpha.abs() == 0.5 => {
                    let r = if *alpha < 0.0 {
                        GaussChebyshev::first_kind(n)
                    } else {
                        GaussChebyshev::second_kind(n)
                    };
                    r.and_then(|r| r.integrate(|x| f(x), *a, *b))
                }
                Method::Algebraic => algebraic_endpoints(|x| f(x), *a, *b, *alpha, *beta, &cfg),
                Method::WeaklySingular => {
                    weakly_singular_weighted(|x| f(x), *a, *b, *a, 0.0, *alpha, *beta, &cfg)
                }
                _ => return None,
            }
        }
        (Kind::Weak { f, a, b, x, k, alpha, beta }, m) => {
            let g = move |s: f64| weighted_fn(f, *a, *b, *alpha, *beta)(s) * (x - s).abs().powf(-k);
            let inside = *x > *a && *x < *b;
            match m {
                Method::WeaklySingular => {
                    weakly_singular_weighted(|s| f(s), *a, *b, *x, *k, *alpha, *beta, &cfg)
                }
                Method::Gk21 | Method::Gk15 => {
                    let rule =
                        if m == Method::Gk21 { KronrodRule::G10K21 } else { KronrodRule::G7K15 };
                    let bps = if inside { vec![*x] } else { vec![] };
                    let c = cfg.with_rule(rule).with_breakpoints(bps).ok()?;
                    gauss_kronrod(g, *a, *b, &c)
                }
                Method::TanhSinh if inside => {
                    let half = Tolerance { abs: 0.5 * tol.abs, rel: tol.rel };
                    both(tanh_sinh(g, *a, *x, half), tanh_sinh(g, *x, *b, half), tol)
                }
                Method::TanhSinh => tanh_sinh(g, *a, *b, tol),
                _ => return None,
            }
        }
        (Kind::Pv { f, a, b, x }, Method::CauchyPv) => cauchy_pv(|t| f(t), *a, *b, *x, &cfg),
        _ => return None,
    };
    Some(Row { method: method.name(), problem: p.name, result, exact: p.exact, tol })
}
