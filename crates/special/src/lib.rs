//! Special functions for stickslip: $\Gamma$, $\ln\Gamma$, the modified Bessel functions
//! $I_0, I_1, K_0, K_1$ (plain, exponentially scaled, and stable ratios), and the complete
//! elliptic integrals $K(m)$, $E(m)$ in the **parameter** convention $m=k^2$.
//!
//! This crate knows nothing about contact mechanics. Every function is a plain
//! `f64 -> f64` that returns NaN outside its domain; each has a `checked_` twin returning
//! [`Error::OutOfDomain`] instead. Where the true value of a finite argument exceeds
//! `f64::MAX` (thresholds documented below) the plain function returns $\pm\infty$ and the
//! checked twin returns [`Error::Overflow`], pointing to the scaled or logarithmic form.
//!
//! ```
//! use stickslip_special::{ellipk, gamma, bessel_k0_over_k1};
//! assert!((gamma(0.5) - std::f64::consts::PI.sqrt()).abs() < 1e-15);
//! assert_eq!(ellipk(0.0), std::f64::consts::FRAC_PI_2);
//! assert!(bessel_k0_over_k1(1e-300) > 0.0); // ~ x ln(2/x), no underflow, no NaN
//! ```
//!
//! # Functions, domains, measured accuracy
//!
//! Relative error against mpmath (60 digits) on the golden tables in `tests/data/`
//! (a few hundred points each, log-spaced plus linear over the whole domain); the contract,
//! asserted by the tests, is $10^{-14}$. 1 ulp $=2^{-52}\approx2.2\times10^{-16}$.
//!
//! | function | domain (NaN outside) | table range | max rel. err. | RMS |
//! |---|---|---|---|---|
//! | [`gamma`] | $x\notin\{0,-1,-2,\dots\}$; $+\infty$ for $x>171.6243769563$ ([`GAMMA_MAX_ARG`]) | $[-170.5, 171.62]$, $10^{-300}$ | 5.8e-16 (2.6 ulp) | 0.65 ulp |
//! | [`ln_gamma`] | $x>0$; $+\infty$ above $\approx2.55\times10^{305}$ | $(10^{-300}, 10^{305}]$, near 1 and 2 | 3.9e-16 (1.8 ulp) | 0.36 ulp |
//! | [`bessel_i0`], [`bessel_i1`] | all $x$; $\pm\infty$ for $\lvert x\rvert\gtrsim713.98$ | $\lvert x\rvert\le713.9$ | 3.8e-16 (1.7 ulp) | 0.83 ulp |
//! | [`bessel_k0`], [`bessel_k1`] | $x>0$; subnormal/0 beyond $\approx705$ | $[10^{-300}, 705]$ | 7.6e-16 (3.4 ulp) | 0.54 ulp |
//! | [`bessel_i0e`], [`bessel_i1e`] | all $x$ | $\lvert x\rvert\in[10^{-300},10^{300}]$ | 8.0e-16 (3.6 ulp) | 0.77 ulp |
//! | [`bessel_k0e`], [`bessel_k1e`] | $x>0$ | $[10^{-300},10^{300}]$ | 6.4e-16 (2.9 ulp) | 0.51 ulp |
//! | [`bessel_i1_over_i0`] | all $x$ (odd) | $[10^{-300},10^{300}]$ | 8.3e-16 (3.8 ulp) | 0.48 ulp |
//! | [`bessel_k0_over_k1`] | $x>0$, subnormals included | $[5\times10^{-324},10^{300}]$ | 9.0e-16 (4.0 ulp) | 0.53 ulp |
//! | [`ellipk`] | $m<1$ | $[-10^{300}, 1-2^{-53}]$ | 4.0e-16 (1.8 ulp) | 0.52 ulp |
//! | [`ellipe`] | $m\le1$ | $[-10^{300}, 1]$ | 3.8e-16 (1.7 ulp) | 0.37 ulp |
//! | [`ellipd`] $=(K-E)/m$ | $m<1$ | $[-10^{300}, 1-2^{-53}]$ | 4.8e-16 (2.1 ulp) | 0.68 ulp |
//!
//! Identities (tests/identities.rs): Wronskian $x(\mathrm{i0e}\,\mathrm{k1e}+\mathrm{i1e}\,
//! \mathrm{k0e})=1$ on $[10^{-6},10^6]$ (4000 points) to 1.0e-15; Legendre's relation to
//! 1.6e-16 of the magnitude of its terms; $\Gamma(x+1)=x\Gamma(x)$ and the reflection formula
//! on $(-170,170)$ to 9.6e-16.
//!
//! # Methods and sources
//!
//! - $\Gamma$, $\ln\Gamma$: own implementation. Taylor series of $\ln\Gamma$ about 1 and 2
//!   (DLMF 5.7.3) on $[0.75, 2.5]$, recurrence (DLMF 5.5.1), Stirling (DLMF 5.11.1) with the
//!   power split so nothing overflows early, reflection with exact $\sin\pi x$ reduction
//!   (DLMF 5.5.3).
//! - Bessel: the scaled functions are Cephes' Chebyshev expansions (via `spec_math`); plain
//!   $I$ multiplies by a split $e^{x/2}e^{x/2}$; the ratios use small-argument series
//!   (A&S 9.6.10-13) for $x<10^{-5}$ and Hankel's expansion (DLMF 10.40.1-2) for $x\ge10^3$.
//! - $K$, $E$: own implementation. AGM (DLMF 19.8.5-6), imaginary-modulus transformation for
//!   $m<0$ (DLMF 19.7.5), logarithmic series about $m=1$ (DLMF 19.12.2) for $E$ when $m>0.9$.
//!
//! FORMULAS.md has no special-function section; its sections E and G use $K$, $E$ of the
//! **modulus** $k$: call `ellipk(k * k)`.
//!
//! # Regenerating the reference data
//!
//! `python3 scripts/special_golden.py` (mpmath, `mp.dps = 60`) rewrites `tests/data/*.tsv`;
//! `python3 scripts/special_coeffs.py > crates/special/src/gamma_coeffs.rs` regenerates the
//! series coefficients (`mp.dps = 50`). Tests never run Python.

mod bessel;
mod ellip;
mod error;
mod gamma;
mod gamma_coeffs;

pub use bessel::{
    bessel_i0, bessel_i0e, bessel_i1, bessel_i1_over_i0, bessel_i1e, bessel_k0, bessel_k0_over_k1,
    bessel_k0e, bessel_k1, bessel_k1e, checked_bessel_i0, checked_bessel_i0e, checked_bessel_i1,
    checked_bessel_i1_over_i0, checked_bessel_i1e, checked_bessel_k0, checked_bessel_k0_over_k1,
    checked_bessel_k0e, checked_bessel_k1, checked_bessel_k1e,
};
pub use ellip::{checked_ellipd, checked_ellipe, checked_ellipk, ellipd, ellipe, ellipk};
pub use error::Error;
pub use gamma::{checked_gamma, checked_ln_gamma, gamma, ln_gamma, GAMMA_MAX_ARG};
