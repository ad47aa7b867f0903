//! The seeds' formulas **as published, wrong on purpose**, so that their divergence from the
//! corrected forms can be measured. Nothing outside this crate may use them; the solvers use
//! the corrected forms of FORMULAS.md (in `stickslip-graded` and `stickslip-traction`).
//!
//! - Seed 000 eq 12 and eq 14 with every $\Gamma(\cdot)$ set to 1 (how Table 1's $I_k$, $J_k$
//!   were obtained), and eq 15 as printed (missing $\Gamma(\tfrac{3+k-\beta}{2})$) and with
//!   every $\Gamma \equiv 1$.
//! - Seed 000 eqs 21, 23, 25: the "first two terms of the integration by parts" of the stress
//!   integrals, read as VERIFICATION.md describes, with each of its four faults switchable
//!   ([`Faults`]).
//! - Seed 000 eq 29: the boundary-term form of $u_x$, which needs $p'(\pm a)$ (infinite).
//! - Seed 002 eq 3.5 with the sign printed in the OCR ($-$ inside the last bracket).

use crate::Error;
use std::f64::consts::PI;
use stickslip_graded::Stress2;
use stickslip_quad::{gauss_kronrod, AdaptiveConfig, Tolerance};
use stickslip_special::gamma;

/// $I_k$ of seed 000 eq 12 with every $\Gamma(\cdot) = 1$:
/// $\pi / (2^{k+2}(k+2))$ (FORMULAS.md A1: this is Table 1's 0.3489).
#[must_use]
pub fn i_k_gamma_one(k: f64) -> f64 {
    PI / (2f64.powf(k + 2.0) * (k + 2.0))
}

/// $J_k = \beta I_k/(k+1)$ (seed 000 eq 14, correct in itself) applied to
/// [`i_k_gamma_one`] (Table 1's 0.3255).
#[must_use]
pub fn j_k_gamma_one(k: f64, beta: f64) -> f64 {
    beta * i_k_gamma_one(k) / (k + 1.0)
}

/// The load $P$ that seed 000 eq 15 **as printed** implies for half-width $a$:
///
/// $$a^{2+k} = \frac{(1-\nu^2)2RP\beta(k+2)\sin(\beta\pi/2)}{E_0(1-k^2)\pi}
///   \Gamma(\tfrac{3+k+\beta}{2})\frac{\Gamma(\tfrac{3-k}{2})}{\Gamma(\tfrac{3+k}{2})},$$
///
/// which lacks $\Gamma(\tfrac{3+k-\beta}{2})$ (FORMULAS.md A4). With `gamma_one` every
/// $\Gamma(\cdot)$ is replaced by 1, as the authors did for $I_k$.
#[must_use]
pub fn load_eq15_printed(
    nu: f64,
    k: f64,
    beta: f64,
    e0: f64,
    r: f64,
    a: f64,
    gamma_one: bool,
) -> f64 {
    let g = if gamma_one {
        1.0
    } else {
        gamma(0.5 * (3.0 + k + beta)) * gamma(0.5 * (3.0 - k)) / gamma(0.5 * (3.0 + k))
    };
    let c = (1.0 - nu * nu) * 2.0 * r * beta * (k + 2.0) * (beta * PI / 2.0).sin()
        / (e0 * (1.0 - k * k) * PI)
        * g;
    a.powf(2.0 + k) / c
}

/// The four faults of seed 000 eqs 21, 23, 25 (VERIFICATION.md, "Two-term partial
/// integration"); each `true` means the fault is present, as published.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Faults {
    /// (1) $I_k$, $J_k$ with every $\Gamma$ set to 1.
    pub gamma_one: bool,
    /// (2) The total load $P$ outside the integral instead of $p(s)$ inside.
    pub load_outside: bool,
    /// (3) The derivative denominator $y^2-(x-s)^2$ instead of $y^2+(x-s)^2$.
    pub minus_denominator: bool,
    /// (4) Truncation after two terms of the integration by parts (when `false`, the
    /// integral with the remaining faults is done by adaptive quadrature).
    pub two_terms: bool,
}

impl Faults {
    /// All four present: the formulas as printed.
    pub const AS_PUBLISHED: Faults =
        Faults { gamma_one: true, load_outside: true, minus_denominator: true, two_terms: true };
}

/// The inputs of the two-term expressions: material, half-width, load, friction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoTermInputs {
    /// $k$.
    pub k: f64,
    /// $\beta$.
    pub beta: f64,
    /// Correct $I_k$ (used when fault 1 is off).
    pub i_k: f64,
    /// Correct $J_k$ (used when fault 1 is off).
    pub j_k: f64,
    /// Half-width $a$.
    pub a: f64,
    /// Total load $P$ per unit length.
    pub load: f64,
    /// Peak pressure $p_0$ of $p(s) = p_0(1-s^2/a^2)^{(1+k)/2}$ (used when fault 2 is off).
    pub p0: f64,
    /// Friction coefficient $\mu$ ($Q = \mu P$).
    pub mu: f64,
}

impl TwoTermInputs {
    fn pressure(&self, s: f64) -> f64 {
        let t = s / self.a;
        if t.abs() >= 1.0 {
            0.0
        } else {
            self.p0 * ((1.0 - t) * (1.0 + t)).powf(0.5 * (1.0 + self.k))
        }
    }
    fn constants(&self, faults: Faults) -> (f64, f64) {
        if faults.gamma_one {
            (i_k_gamma_one(self.k), j_k_gamma_one(self.k, self.beta))
        } else {
            (self.i_k, self.j_k)
        }
    }
}

/// Bracket contents $[T_1 - T_2]$ of eqs 21, 23, 25 at one limit $s$: for each component
/// (xx, yy, xy) the cosine (P) part and the sine (Q) part.
fn bracket(inp: &TwoTermInputs, minus_den: bool, x: f64, y: f64, s: f64) -> [(f64, f64); 3] {
    let (k, b) = (inp.k, inp.beta);
    let n = 0.5 * (3.0 + k);
    let d = x - s;
    let r2 = d * d + y * y;
    let den = if minus_den { y * y - d * d } else { y * y + d * d };
    let th = (d / y).atan();
    let (c, sn) = ((b * th).cos(), (b * th).sin());
    let p1 = r2.powf(1.0 - n) / ((1.0 - n) * -2.0);
    let q2 = r2.powf(2.0 - n) / (4.0 * (1.0 - n) * (2.0 - n));
    // eq 21 (sigma_xx)
    let xx_c = d * c * p1 - (-2.0 * c + b * y * sn * d / den) * q2 / d;
    let xx_s = d * sn * p1 - (-2.0 * sn - b * y * c * d / den) * q2 / d;
    // eq 23 (sigma_yy): the sine part's second term is added, as printed
    let yy_c = c * p1 / d - (b * y / den) * sn * q2 / (d * d);
    let yy_s = sn * p1 / d + (b * y * c / den) * q2 / (d * d);
    // eq 25 (sigma_xy)
    let xy_c = c * p1 - (-c + y * b * sn * d / den) * q2 / (d * d);
    let xy_s = sn * p1 - (-sn - y * b * c * d / den) * q2 / (d * d);
    [(xx_c, xx_s), (yy_c, yy_s), (xy_c, xy_s)]
}

/// The stresses of seed 000 eqs 21, 23, 25 at $(x, y)$ with the chosen [`Faults`]:
///
/// $$\sigma_{xx} = -\frac{P y^k}{2I_k}\bigl[T_1^c - T_2^c\bigr]_{s=-a}^{s=a} -
///   \frac{\mu P y^k}{2J_k}\bigl[T_1^s - T_2^s\bigr]_{s=-a}^{s=a},$$
/// $$T_1^c = \frac{(x-s)\cos(\beta\theta_s)\,r_s^{2(1-n)}}{(1-n)(-2)},\quad
///   T_2^c = \frac{\bigl[-2\cos\beta\theta_s + \beta y\sin(\beta\theta_s)(x-s)/(y^2-(x-s)^2)\bigr]
///   r_s^{2(2-n)}}{4(1-n)(2-n)(x-s)},$$
///
/// $n = (3+k)/2$, $\theta_s = \arctan((x-s)/y)$, and eqs 23 and 25 read the same way from the
/// OCR (VERIFICATION.md). The powers of $y$ in the prefactors of eqs 23 and 25 are garbled;
/// we use $y^{2+k}$ and $y^{1+k}$, the powers that eqs 22 and 24 imply. With fault (2) off,
/// $P$ is replaced by $p(s)$ at the limits, which vanishes there: the two-term expression is
/// then identically zero. With fault (4) off, the integrals (with the remaining faults) are
/// done by adaptive Gauss–Kronrod; fault (3) then has no meaning.
///
/// The result carries the units of $P\cdot$length$^{0}$ when fault (2) is present: force per
/// unit length, not stress (FORMULAS.md A2).
///
/// # Errors
/// [`Error::Quadrature`] if the quadrature of the untruncated form fails.
pub fn two_term_stress(
    inp: &TwoTermInputs,
    faults: Faults,
    x: f64,
    y: f64,
) -> Result<Stress2, Error> {
    let (ik, jk) = inp.constants(faults);
    let k = inp.k;
    let a = inp.a;
    let pw = [y.powf(k), y.powf(2.0 + k), y.powf(1.0 + k)];
    if faults.two_terms {
        let mut out = [0.0; 3];
        for (sign, s) in [(1.0, a), (-1.0, -a)] {
            let w = if faults.load_outside { inp.load } else { inp.pressure(s) };
            let br = bracket(inp, faults.minus_denominator, x, y, s);
            for i in 0..3 {
                // 0 * inf is NaN: a vanishing weight multiplies the bracket only where it is
                // finite, so the singular lines stay visible.
                let (bc, bs) = br[i];
                let term = if w == 0.0 && bc.is_finite() && bs.is_finite() {
                    0.0
                } else {
                    -(w * pw[i] / (2.0 * ik)) * bc - (inp.mu * w * pw[i] / (2.0 * jk)) * bs
                };
                out[i] += sign * term;
            }
        }
        return Ok(Stress2 { xx: out[0], yy: out[1], xy: out[2] });
    }
    // Untruncated: -(P/2I) int K_c ds - (mu P / 2J) int K_s ds with P outside (fault 2), or
    // p(s) inside when fault 2 is off.
    let b = inp.beta;
    let cfg = AdaptiveConfig::new(
        Tolerance::relative(1e-11).map_err(|e| Error::Quadrature(e.to_string()))?,
    )
    .with_breakpoints(if x > -a && x < a { vec![x] } else { vec![] })
    .map_err(|e| Error::Quadrature(e.to_string()))?;
    let mut out = [0.0; 3];
    for (i, o) in out.iter_mut().enumerate() {
        let f = |s: f64| {
            let d = x - s;
            let r2 = d * d + y * y;
            let th = (d / y).atan();
            let w = if faults.load_outside { inp.load } else { inp.pressure(s) };
            let geom = match i {
                0 => y.powf(k) * d * d,
                1 => y.powf(2.0 + k),
                _ => y.powf(1.0 + k) * d,
            } / r2.powf(0.5 * (3.0 + k));
            -w * geom * ((b * th).cos() / (2.0 * ik) + inp.mu * (b * th).sin() / (2.0 * jk))
        };
        *o = gauss_kronrod(f, -a, a, &cfg).map_err(|e| Error::Quadrature(e.to_string()))?.value;
    }
    Ok(Stress2 { xx: out[0], yy: out[1], xy: out[2] })
}

/// Seed 000 eq 29 (boundary-term form of $u_x$, $q = \mu p$) at $x$, as far as the OCR can be
/// read: with $B(s_0, d) = \frac{p(s_0)d^{1-k}}{1-k} - \frac{p'(s_0)d^{2-k}}{(1-k)(2-k)}
/// + \frac{p''(s_0)d^{3-k}}{(1-k)(2-k)(3-k)}$,
///
/// $$u_x = -\frac{(1-\nu^2)\cos(\beta\pi/2)}{E_0k\,2I_k}\bigl[-B_p(-a,x+a) - B_p(a,a-x)\bigr]
///   + \frac{(1-\nu^2)\sin(\beta\pi/2)}{E_0k\,2J_k}\bigl[B_q(a,|x-a|) - B_q(-a,|x+a|)\bigr].$$
///
/// For the actual pressure $p = p_0(1-s^2/a^2)^{(1+k)/2}$, $p'(\pm a)$ and $p''(\pm a)$ are
/// infinite (FORMULAS.md A3), so the value is not finite whatever the signs; it is returned
/// as computed (infinite or NaN) to show exactly that.
#[must_use]
pub fn ux_eq29(inp: &TwoTermInputs, nu: f64, e0: f64, x: f64) -> f64 {
    let (k, a, p0) = (inp.k, inp.a, inp.p0);
    let g = 0.5 * (1.0 + k);
    // p(s) = p0 u^g with u = 1 - s^2/a^2; p' = -2 g p0 s/a^2 u^(g-1);
    // p'' = -2 g p0/a^2 u^(g-1) + 4 g (g-1) p0 s^2/a^4 u^(g-2).
    let p = |s: f64| p0 * (1.0 - s * s / (a * a)).max(0.0).powf(g);
    let dp = |s: f64| {
        let u = (1.0 - s * s / (a * a)).max(0.0);
        -2.0 * g * p0 * s / (a * a) * u.powf(g - 1.0)
    };
    let d2p = |s: f64| {
        let u = (1.0 - s * s / (a * a)).max(0.0);
        -2.0 * g * p0 / (a * a) * u.powf(g - 1.0)
            + 4.0 * g * (g - 1.0) * p0 * s * s / (a * a * a * a) * u.powf(g - 2.0)
    };
    let bterm = |scale: f64, s0: f64, d: f64| {
        scale
            * (p(s0) * d.powf(1.0 - k) / (1.0 - k)
                - dp(s0) * d.powf(2.0 - k) / ((1.0 - k) * (2.0 - k))
                + d2p(s0) * d.powf(3.0 - k) / ((1.0 - k) * (2.0 - k) * (3.0 - k)))
    };
    let (ik, jk) = inp.constants(Faults::AS_PUBLISHED);
    let b = inp.beta;
    let cc = (1.0 - nu * nu) * (b * PI / 2.0).cos() / (e0 * k * 2.0 * ik);
    let cs = (1.0 - nu * nu) * (b * PI / 2.0).sin() / (e0 * k * 2.0 * jk);
    -cc * (-bterm(1.0, -a, x + a) - bterm(1.0, a, a - x))
        + cs * (bterm(inp.mu, a, (x - a).abs()) - bterm(inp.mu, -a, (x + a).abs()))
}

/// Seed 002 eq 3.5 with the sign printed in the OCR (per body):
/// $W = \frac{9(2-\nu)f^2P^2}{10Ga}\bigl[1-(1-t)^{5/3} - \frac{5t}{6}\bigl(1-(1-t)^{2/3}\bigr)\bigr]$,
/// $t = T^*/fP$. FORMULAS.md E: the inner sign must be $+$; this form is off by a factor
/// of about 4700 at $t = 0.1$.
#[must_use]
pub fn energy_eq35_printed(nu: f64, g: f64, a: f64, f: f64, p: f64, t_star: f64) -> f64 {
    let t = t_star / (f * p);
    9.0 * (2.0 - nu) * f * f * p * p / (10.0 * g * a)
        * (1.0 - (1.0 - t).powf(5.0 / 3.0) - 5.0 * t / 6.0 * (1.0 - (1.0 - t).powf(2.0 / 3.0)))
}
