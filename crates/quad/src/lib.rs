//! Quadrature for stickslip: fixed Gauss rules, adaptive integrators and singular integrals,
//! every one of them returning an [`Estimate`] whose `error` is an honest bound, and never
//! silently accepting a non-finite integrand value or an unmet tolerance.
//!
//! | task | function / type |
//! |---|---|
//! | fixed rule, planned once | [`GaussLegendre`], [`GaussJacobi`], [`GaussChebyshev`] (trait [`Rule`]) |
//! | adaptive, smooth or piecewise smooth, finite or infinite range | [`gauss_kronrod`] |
//! | double exponential | [`tanh_sinh()`] |
//! | $\int f\,(x-a)^\alpha(b-x)^\beta$ | [`algebraic_endpoints`] |
//! | $\int f(s)\,|x-s|^{-k}$ | [`weakly_singular`], [`weakly_singular_weighted`] |
//! | $\mathrm{PV}\int f(t)/(t-x)$ | [`cauchy_pv`] |
//!
//! Tolerances are [`Tolerance`]: accept when $|I-Q| \le \max(\text{abs}, \text{rel}|Q|)$.
//! The [`battery`] module holds the accuracy-versus-cost test battery (closed forms and mpmath
//! values) used by the tests and the project's report.
//!
//! ```
//! use stickslip_quad::{gauss_kronrod, AdaptiveConfig};
//! // The integral of sin over [0, pi] is 2; the estimate brackets it.
//! let est = gauss_kronrod(f64::sin, 0.0, std::f64::consts::PI, &AdaptiveConfig::default())
//!     .unwrap();
//! assert!((est.value - 2.0).abs() <= est.error.max(4.0 * f64::EPSILON));
//! assert!(est.error < 1e-10 && est.evals > 0);
//! ```
//!
//! This crate knows nothing about contact mechanics (ARCHITECTURE.md); the kernels of
//! `docs/FORMULAS.md` appear only as test integrands.

mod error;
mod gamma;
pub mod kronrod;
pub mod rules;
pub mod singular;
pub mod tanh_sinh;
mod types;

pub mod battery;

pub use error::Error;
pub use kronrod::{gauss_kronrod, AdaptiveConfig, KronrodRule};
pub use rules::{ChebyshevKind, GaussChebyshev, GaussJacobi, GaussLegendre, Rule};
pub use singular::{algebraic_endpoints, cauchy_pv, weakly_singular, weakly_singular_weighted};
pub use tanh_sinh::tanh_sinh;
pub use types::{Estimate, Tolerance};
