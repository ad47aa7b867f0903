//! Mindlin–Deresiewicz: oscillating tangential force on a Hertz circle (Mindlin & Deresiewicz
//! 1953; seed 002 §3.2.1 and eq. 3.5; FORMULAS.md E, which corrects the sign in eq. 3.5).

use super::{load_ratio, one_minus_pow};
use crate::error::{positive, Error, Result};
use std::f64::consts::PI;
use stickslip_halfspace::Material;

/// A Hertz circle (radius $a$, normal load $P$, friction $f$) first loaded to $T^* \le fP$,
/// then cycled between $+T^*$ and $-T^*$ (Mindlin & Deresiewicz 1953; seed 002 §3.2.1,
/// Figs 3.3–3.4 and eq. 3.5; FORMULAS.md E, which corrects the sign in eq. 3.5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Deresiewicz {
    a: f64,
    normal: f64,
    friction: f64,
    amplitude: f64,
    ratio: f64,
}

impl Deresiewicz {
    /// Validate $a, P, f > 0$ and $0 \le T^* \le fP$.
    ///
    /// # Errors
    /// [`crate::Error::OutOfDomain`] naming the offending input.
    pub fn new(a: f64, normal: f64, friction: f64, amplitude: f64) -> Result<Self> {
        positive("contact radius a", a)?;
        let ratio = load_ratio(normal, friction, amplitude)?;
        Ok(Self { a, normal, friction, amplitude, ratio })
    }

    fn check_t(&self, t: f64) -> Result<()> {
        if t.is_finite() && t.abs() <= self.amplitude {
            Ok(())
        } else {
            Err(Error::OutOfDomain { name: "tangential load T", value: t, allowed: "[-T*, T*]" })
        }
    }

    fn fp(&self) -> f64 {
        self.friction * self.normal
    }

    /// Radius $b = a\,(1 - (T^*-T)/(2fP))^{1/3}$ bounding the reversed-slip annulus
    /// $b \le \rho \le a$ while unloading from $T^*$ to $T$ (the seed's $h^*$; Mindlin &
    /// Deresiewicz 1953; FORMULAS.md E).
    ///
    /// # Errors
    /// [`crate::Error::OutOfDomain`] if $|T| > T^*$.
    pub fn reversal_radius(&self, t: f64) -> Result<f64> {
        self.check_t(t)?;
        Ok(self.a * (1.0 - (self.amplitude - t) / (2.0 * self.fp())).max(0.0).cbrt())
    }

    /// Traction while unloading from $T^*$ to $T$ (Mindlin & Deresiewicz 1953; FORMULAS.md E):
    /// $q = q^*(\rho) - 2q_M(\rho; b)$ with $q_M(\rho;b) = q_h[\sqrt{a^2-\rho^2} -
    /// \sqrt{b^2-\rho^2}H(b-\rho)]$, $q_h = 3fP/(2\pi a^3)$, $q^*$ the Mindlin traction at $T^*$.
    ///
    /// # Errors
    /// [`crate::Error::OutOfDomain`] if $|T| > T^*$.
    pub fn unloading_traction(&self, rho: f64, t: f64) -> Result<f64> {
        let b = self.reversal_radius(t)?;
        let a = self.a;
        let rho = rho.abs();
        if rho >= a {
            return Ok(0.0);
        }
        let qh = 3.0 * self.fp() / (2.0 * PI * a.powi(3));
        let root = |r: f64| if rho < r { ((r - rho) * (r + rho)).sqrt() } else { 0.0 };
        let astar = a * (1.0 - self.ratio).max(0.0).cbrt();
        // q* - 2 q_M(b) = qh[(√(a²-ρ²) - √(a*²-ρ²)) - 2(√(a²-ρ²) - √(b²-ρ²))].
        Ok(qh * (-root(a) + 2.0 * root(b) - root(astar)))
    }

    /// Traction while reloading from $-T^*$ to $T$: by symmetry
    /// $q_{\uparrow}(\rho; T) = -q_{\downarrow}(\rho; -T)$, with $q_{\downarrow}$ of
    /// [`Deresiewicz::unloading_traction`] (Mindlin & Deresiewicz 1953; FORMULAS.md E).
    ///
    /// # Errors
    /// [`crate::Error::OutOfDomain`] if $|T| > T^*$.
    pub fn reloading_traction(&self, rho: f64, t: f64) -> Result<f64> {
        Ok(-self.unloading_traction(rho, -t)?)
    }

    /// Per-body tangential stiffness factor $K_t = 3(2-\nu)/(16 G a)$ (0 if rigid).
    fn kt(&self, body: &Material) -> f64 {
        if body.is_rigid() {
            0.0
        } else {
            3.0 * (2.0 - body.poisson_ratio()) / (16.0 * body.shear_modulus() * self.a)
        }
    }

    /// Per-body displacement while unloading from $T^*$ (Mindlin & Deresiewicz 1953;
    /// FORMULAS.md E), $K_t = 3(2-\nu)/(16Ga)$:
    /// $$\delta_d(T) = K_t fP\Big[2\Big(1-\frac{T^*-T}{2fP}\Big)^{2/3} -
    ///   \Big(1-\frac{T^*}{fP}\Big)^{2/3} - 1\Big].$$
    ///
    /// # Errors
    /// [`crate::Error::OutOfDomain`] if $|T| > T^*$.
    pub fn delta_unloading(&self, t: f64, body: &Material) -> Result<f64> {
        self.check_t(t)?;
        let fp = self.fp();
        // 2(1-x)^{2/3} - (1-r)^{2/3} - 1 = (1 - (1-r)^{2/3}) - 2(1 - (1-x)^{2/3}).
        let x = (self.amplitude - t) / (2.0 * fp);
        let bracket = one_minus_pow(self.ratio, 2.0 / 3.0) - 2.0 * one_minus_pow(x, 2.0 / 3.0);
        Ok(self.kt(body) * fp * bracket)
    }

    /// Per-body displacement while reloading from $-T^*$ (FORMULAS.md E):
    /// $$\delta_i(T) = -\delta_d(-T) = -K_t fP\Big[2\Big(1-\frac{T^*+T}{2fP}\Big)^{2/3} -
    ///   \Big(1-\frac{T^*}{fP}\Big)^{2/3} - 1\Big],\qquad K_t = \frac{3(2-\nu)}{16Ga}.$$
    ///
    /// # Errors
    /// [`crate::Error::OutOfDomain`] if $|T| > T^*$.
    pub fn delta_reloading(&self, t: f64, body: &Material) -> Result<f64> {
        Ok(-self.delta_unloading(-t, body)?)
    }

    /// The hysteresis loop as `2 n + 1` points $(T, \delta)$: unloading from $T^*$ to $-T^*$
    /// ($n$ steps), then reloading back to $T^*$ ($n$ steps), on equally spaced $T$. Per body;
    /// the branches are [`Deresiewicz::delta_unloading`] and [`Deresiewicz::delta_reloading`]
    /// (Mindlin & Deresiewicz 1953; FORMULAS.md E).
    ///
    /// # Errors
    /// [`crate::Error::OutOfDomain`] if `n` is zero.
    pub fn hysteresis_loop(&self, body: &Material, n: usize) -> Result<Vec<(f64, f64)>> {
        if n == 0 {
            return Err(Error::OutOfDomain { name: "loop steps n", value: 0.0, allowed: ">= 1" });
        }
        let ts = self.amplitude;
        let mut pts = Vec::with_capacity(2 * n + 1);
        for i in 0..=n {
            let t = (ts - 2.0 * ts * i as f64 / n as f64).clamp(-ts, ts);
            pts.push((t, self.delta_unloading(t, body)?));
        }
        for i in 1..=n {
            let t = (-ts + 2.0 * ts * i as f64 / n as f64).clamp(-ts, ts);
            pts.push((t, self.delta_reloading(t, body)?));
        }
        Ok(pts)
    }

    /// Energy dissipated per cycle, per body (seed 002 eq. 3.5 with FORMULAS.md E's '+'):
    /// $$W = \frac{9(2-\nu)f^2P^2}{10\,G a}\,B(t),\qquad
    ///   B(t) = 1-(1-t)^{5/3} - \frac{5t}{6}\big(1+(1-t)^{2/3}\big),\quad t = T^*/fP .$$
    /// The bracket is evaluated in a cancellation-free form: with $s=(1-t)^{1/3}$,
    /// $B = t^3(s^2+3s+1)/\big(6(1+s+s^2)^3\big)$, all terms positive (relative accuracy of a few ulp for every $t \in [0, 1]$, no switch point); for small
    /// $t$ it gives $W \approx (2-\nu)T^{*3}/(36 G a fP)$.
    #[must_use]
    pub fn energy_per_cycle(&self, body: &Material) -> f64 {
        if body.is_rigid() {
            return 0.0;
        }
        9.0 * (2.0 - body.poisson_ratio()) * self.fp().powi(2)
            / (10.0 * body.shear_modulus() * self.a)
            * energy_bracket(self.ratio)
    }
}

/// The energy bracket of [`Deresiewicz::energy_per_cycle`] without cancellation.
///
/// With $s = (1-t)^{1/3}$ (so $1 - t = s^3$) the bracket is a polynomial in $s$,
/// $$B = \tfrac16\big(1 - 5s^2 + 5s^3 - s^5\big) = \tfrac16(1-s)^3(s^2+3s+1),$$
/// and $1 - s = t/(1+s+s^2)$ because $1 - s^3 = (1-s)(1+s+s^2)$; hence
/// $$B(t) = \frac{t^3\,(s^2+3s+1)}{6\,(1+s+s^2)^3}.$$
/// Every term is positive, so the only rounding is that of a handful of operations and of
/// $s$ (whose own error enters with a weight below 1): a few ulp relative for all
/// $t\in[0,1]$. Limits: $B \to 5t^3/162$ as $t\to0$ ($s\to1$), $B(1) = 1/6$ ($s=0$).
/// The direct form of the seed loses $\varepsilon/(5t^3/162)$ relative (2.4e-12 at $t = 0.1$).
fn energy_bracket(t: f64) -> f64 {
    let s = (1.0 - t).cbrt();
    let q = 1.0 + s * (1.0 + s);
    t * t * t * (1.0 + s * (3.0 + s)) / (6.0 * q * q * q)
}

#[cfg(test)]
mod tests {
    /// The two limits of the bracket, exactly as stated in its docs.
    #[test]
    fn bracket_limits() {
        assert_eq!(super::energy_bracket(0.0), 0.0);
        assert!((super::energy_bracket(1.0) - 1.0 / 6.0).abs() <= f64::EPSILON / 6.0);
        let t = 1e-6;
        let lead = 5.0 * t * t * t / 162.0;
        // next term of the expansion is O(t^4): relative 1e-6 here
        assert!((super::energy_bracket(t) / lead - 1.0).abs() < 2e-6);
    }
}
