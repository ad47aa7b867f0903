//! The Gamma-function pieces the Gauss–Jacobi rules need, from `stickslip-special`
//! (which owns the accuracy of $\ln\Gamma$: at most 1.8 ulp on its golden table).

use stickslip_special::ln_gamma;

/// Total mass of the Jacobi weight on $[-1,1]$:
/// $$\mu_0 = \int_{-1}^{1}(1-t)^\alpha(1+t)^\beta\,dt = 2^{\alpha+\beta+1}\frac{\Gamma(\alpha+1)\Gamma(\beta+1)}{\Gamma(\alpha+\beta+2)}.$$
pub(crate) fn jacobi_mass(alpha: f64, beta: f64) -> f64 {
    let l = (alpha + beta + 1.0) * std::f64::consts::LN_2
        + ln_gamma(alpha + 1.0)
        + ln_gamma(beta + 1.0)
        - ln_gamma(alpha + beta + 2.0);
    l.exp()
}
