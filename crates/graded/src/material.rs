//! The graded substrate $E(y) = E_0 y^k$ and its constants $\beta$, $I_k$, $J_k$
//! (Giannakopoulos & Pallot 2000, seed 000 eqs 12–14; FORMULAS.md A1).

use crate::error::{require, Error};
use stickslip_special::ln_gamma;

/// Text used in errors about the grading exponent.
const K_ALLOWED: &str = "0 <= k < 1";

fn check_k(k: f64) -> Result<(), Error> {
    require(k.is_finite() && (0.0..1.0).contains(&k), "k", k, K_ALLOWED)
}

fn check_nu(nu: f64, k: f64) -> Result<(), Error> {
    require(nu.is_finite() && nu > -1.0, "nu", nu, "-1 < nu < 1/(1+k)")?;
    let limit = 1.0 / (1.0 + k);
    if nu < limit {
        Ok(())
    } else {
        Err(Error::BetaNotReal { nu, k, limit })
    }
}

/// Exponent $\beta$ of the radial line-load field in plane strain (seed 000 eq 13;
/// FORMULAS.md A1):
///
/// $$\beta(\nu,k) = \sqrt{(1+k)\Bigl(1 - \frac{k\nu}{1-\nu}\Bigr)}
///   = \sqrt{\frac{(1+k)\,(1-(1+k)\nu)}{1-\nu}} .$$
///
/// Real only for $\nu < 1/(1+k)$; outside the domain of [`checked_beta`] this returns NaN.
#[must_use]
pub fn beta(nu: f64, k: f64) -> f64 {
    checked_beta(nu, k).unwrap_or(f64::NAN)
}

/// [`beta`] with its domain checked: $0 \le k < 1$, $-1 < \nu < 1/(1+k)$.
///
/// # Errors
/// [`Error::OutOfDomain`] for `k` or `nu` outside the ranges above (or not finite), and
/// [`Error::BetaNotReal`] when $\nu \ge 1/(1+k)$.
pub fn checked_beta(nu: f64, k: f64) -> Result<f64, Error> {
    check_k(k)?;
    check_nu(nu, k)?;
    Ok(((1.0 + k) * (1.0 - (1.0 + k) * nu) / (1.0 - nu)).sqrt())
}

/// The half-range integral $I_k$ (seed 000 eq 12, which is correct; FORMULAS.md A1):
///
/// $$I_k = \int_0^{\pi/2} \cos^{k+1}\theta\,\cos\beta\theta\,d\theta
///   = \frac{\pi\,\Gamma(k+2)}{2^{k+2}\,\Gamma\bigl(\tfrac{3+k+\beta}{2}\bigr)\,
///     \Gamma\bigl(\tfrac{3+k-\beta}{2}\bigr)} ,$$
///
/// evaluated through $\ln\Gamma$. $I_0 = \pi/4$. NaN outside the domain of [`checked_i_k`].
#[must_use]
pub fn i_k(nu: f64, k: f64) -> f64 {
    checked_i_k(nu, k).unwrap_or(f64::NAN)
}

/// [`i_k`] with its domain checked (same domain as [`checked_beta`]).
///
/// # Errors
/// As [`checked_beta`].
pub fn checked_i_k(nu: f64, k: f64) -> Result<f64, Error> {
    let b = checked_beta(nu, k)?;
    Ok(i_k_from_beta(b, k))
}

/// $I_k$ for an already computed $\beta$ (no checks).
pub(crate) fn i_k_from_beta(b: f64, k: f64) -> f64 {
    let ln = ln_gamma(k + 2.0) - ln_gamma(0.5 * (3.0 + k + b)) - ln_gamma(0.5 * (3.0 + k - b));
    std::f64::consts::PI * (ln - (k + 2.0) * std::f64::consts::LN_2).exp()
}

/// The half-range integral $J_k$ (seed 000 eq 14, correct; FORMULAS.md A1):
///
/// $$J_k = \int_0^{\pi/2} \cos^{k}\theta\,\sin\theta\,\sin\beta\theta\,d\theta
///   = \frac{\beta\,I_k}{1+k} ,$$
///
/// (integration by parts; boundary terms vanish). NaN outside the domain of [`checked_j_k`].
#[must_use]
pub fn j_k(nu: f64, k: f64) -> f64 {
    checked_j_k(nu, k).unwrap_or(f64::NAN)
}

/// [`j_k`] with its domain checked (same domain as [`checked_beta`]).
///
/// # Errors
/// As [`checked_beta`].
pub fn checked_j_k(nu: f64, k: f64) -> Result<f64, Error> {
    let b = checked_beta(nu, k)?;
    Ok(b * i_k_from_beta(b, k) / (1.0 + k))
}

/// A power-law graded half-plane, $E(y) = E_0\,y^k$ with constant $\nu$, in plane strain
/// (G&P 2000; FORMULAS.md A).
///
/// $E_0$ carries units of stress/length$^k$ (e.g. Pa·m$^{-k}$); every length given to this
/// crate must use the same length unit. The constants $\beta$, $I_k$, $J_k$ are computed once
/// here.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GradedMaterial {
    e0: f64,
    k: f64,
    nu: f64,
    beta: f64,
    i_k: f64,
    j_k: f64,
}

impl GradedMaterial {
    /// Validate and build: $E_0 > 0$ finite, $0 \le k < 1$, $-1 < \nu < 1/(1+k)$ (so that
    /// $\beta$ is real and positive; FORMULAS.md A1).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] naming the offending argument, or [`Error::BetaNotReal`].
    pub fn new(e0: f64, k: f64, nu: f64) -> Result<Self, Error> {
        require(e0.is_finite() && e0 > 0.0, "e0", e0, "0 < e0 < inf (units stress/length^k)")?;
        let beta = checked_beta(nu, k)?;
        let i_k = i_k_from_beta(beta, k);
        Ok(Self { e0, k, nu, beta, i_k, j_k: beta * i_k / (1.0 + k) })
    }

    /// Modulus prefactor $E_0$ (stress/length$^k$).
    #[must_use]
    pub fn e0(&self) -> f64 {
        self.e0
    }
    /// Grading exponent $k$.
    #[must_use]
    pub fn k(&self) -> f64 {
        self.k
    }
    /// Poisson ratio $\nu$.
    #[must_use]
    pub fn poisson_ratio(&self) -> f64 {
        self.nu
    }
    /// $\beta$, see [`beta`].
    #[must_use]
    pub fn beta(&self) -> f64 {
        self.beta
    }
    /// $I_k$, see [`i_k`].
    #[must_use]
    pub fn i_k(&self) -> f64 {
        self.i_k
    }
    /// $J_k$, see [`j_k`].
    #[must_use]
    pub fn j_k(&self) -> f64 {
        self.j_k
    }
}
