//! Mindlin–Deresiewicz: oscillating tangential force on a Hertz circle.

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
    /// $b \le \rho \le a$ while unloading from $T^*$ to $T$ (the seed's $h^*$).
    ///
    /// # Errors
    /// [`crate::Error::OutOfDomain`] if $|T| > T^*$.
    pub fn reversal_radius(&self, t: f64) -> Result<f64> {
        self.check_t(t)?;
        Ok(self.a * (1.0 - (self.amplitude - t) / (2.0 * self.fp())).max(0.0).cbrt())
    }

    /// Traction while unloading from $T^*$ to $T$ (FORMULAS.md E):
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
    /// $q_{\uparrow}(\rho; T) = -q_{\downarrow}(\rho; -T)$.
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

    /// Per-body displacement while unloading from $T^*$ (FORMULAS.md E):
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

    /// Per-body displacement while reloading from $-T^*$: $\delta_i(T) = -\delta_d(-T)$.
    ///
    /// # Errors
    /// [`crate::Error::OutOfDomain`] if $|T| > T^*$.
    pub fn delta_reloading(&self, t: f64, body: &Material) -> Result<f64> {
        Ok(-self.delta_unloading(-t, body)?)
    }

    /// The hysteresis loop as `2 n + 1` points $(T, \delta)$: unloading from $T^*$ to $-T^*$
    /// ($n$ steps), then reloading back to $T^*$ ($n$ steps). Per body.
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
    /// $$W = \frac{9(2-\nu)f^2P^2}{10\,G a}\Big[1-(1-t)^{5/3} -
    ///   \frac{5t}{6}\big(1+(1-t)^{2/3}\big)\Big],\quad t = T^*/fP .$$
    /// The bracket behaves like $5t^3/162$ for small $t$; it is summed as a power series for
    /// $t < 0.05$ so the small-amplitude value $W \approx (2-\nu)T^{*3}/(36 G a fP)$ keeps
    /// full relative accuracy.
    #[must_use]
    pub fn energy_per_cycle(&self, body: &Material) -> f64 {
        if body.is_rigid() {
            return 0.0;
        }
        let t = self.ratio;
        let bracket = if t < 0.05 {
            energy_bracket_series(t)
        } else {
            let s23 = (1.0 - t).powf(2.0 / 3.0);
            1.0 - (1.0 - t).powf(5.0 / 3.0) - 5.0 * t / 6.0 * (1.0 + s23)
        };
        9.0 * (2.0 - body.poisson_ratio()) * self.fp().powi(2)
            / (10.0 * body.shear_modulus() * self.a)
            * bracket
    }
}

/// Taylor series of $1-(1-t)^{5/3} - \frac{5t}{6}(1+(1-t)^{2/3})$ about $t = 0$.
/// With $\binom{\alpha}{n}$ the binomial coefficients, the $t^n$ coefficient is
/// $-\binom{5/3}{n}(-1)^n - \frac56\binom{2/3}{n-1}(-1)^{n-1}$ for $n \ge 2$; the $t^0$, $t^1$ and
/// $t^2$ coefficients vanish.
fn energy_bracket_series(t: f64) -> f64 {
    let mut b53 = 1.0; // binom(5/3, n), n = 0
    let mut b23 = 1.0; // binom(2/3, n - 1), starts at n = 1
    let mut sum = 0.0;
    let mut pow = t; // t^n
    for n in 1..80 {
        let nf = n as f64;
        b53 *= (5.0 / 3.0 - nf + 1.0) / nf;
        if n >= 2 {
            b23 *= (2.0 / 3.0 - (nf - 1.0) + 1.0) / (nf - 1.0);
        }
        let sign = if n % 2 == 0 { 1.0 } else { -1.0 };
        let coeff = if n == 1 {
            // -(5/3)(-1) - (5/6)(1 + 1): the two constant parts cancel at first order.
            -b53 * sign - 5.0 / 6.0 * 2.0
        } else {
            -b53 * sign + 5.0 / 6.0 * b23 * sign
        };
        let term = coeff * pow;
        sum += term;
        if n > 3 && term.abs() < 1e-18 * sum.abs() {
            break;
        }
        pow *= t;
    }
    sum
}

#[cfg(test)]
mod tests {
    #[test]
    fn series_matches_direct_at_switch() {
        let t: f64 = 0.05;
        let s23 = (1.0 - t).powf(2.0 / 3.0);
        let direct = 1.0 - (1.0 - t).powf(5.0 / 3.0) - 5.0 * t / 6.0 * (1.0 + s23);
        let series = super::energy_bracket_series(t);
        // The direct form cancels O(1) terms down to 4e-6: its own rounding is about
        // eps / 4e-6 = 3e-11 relative, so that is the resolution of this comparison.
        assert!((series - direct).abs() < 1e-10 * direct.abs(), "{series} {direct}");
        let small = super::energy_bracket_series(1e-4);
        assert!((small / 1e-12 - 5.0 / 162.0).abs() < 1e-4 * 5.0 / 162.0, "{small}");
    }
}
