//! Cattaneo-type partial slip of a rigid cylinder on the power-law graded half-plane
//! (FORMULAS.md A4; derived in the book's graded chapter).
//!
//! Under the pressure $p(x) = p_0(1-x^2/a^2)^{(1+k)/2}$ of the rigid cylinder, a tangential
//! load $T < fP$ is carried by the difference of two such shapes: full slip $f\,p(x)$ less a
//! corrective traction of the same form on the stick zone $|x| < c$, scaled so that the
//! shear-induced $u_x$ is uniform there (as in Cattaneo–Mindlin; the pressure-induced odd part
//! of $u_x$ is neglected). The resultant of a shape of half-width $c$ scales as
//! $c^{2+k}$, which fixes $c$.

/// The stick half-width $c = a\,(1 - |T|/(fP))^{1/(2+k)}$; `load_ratio` $= |T|/(fP)$ is
/// capped at 1 (gross slip, $c = 0$).
#[must_use]
pub fn stick_half_width(a: f64, k: f64, load_ratio: f64) -> f64 {
    a * (1.0 - load_ratio.min(1.0)).powf(1.0 / (2.0 + k))
}

/// The shear traction at $x$,
/// $$q(x) = \mu p_0 (1-x^2/a^2)^{(1+k)/2} - \mu p_0 (c/a)^{1+k} (1-x^2/c^2)^{(1+k)/2},$$
/// the second term only on $|x| < c$ (and only when `stick` is `Some(c)`); zero outside the
/// contact. $\mu$ is the friction coefficient with the sign of $T$.
#[must_use]
pub fn traction(x: f64, a: f64, stick: Option<f64>, p0: f64, k: f64, mu: f64) -> f64 {
    let t = x / a;
    if t.abs() >= 1.0 {
        return 0.0;
    }
    let g = 0.5 * (1.0 + k);
    let mut q = mu * p0 * ((1.0 - t) * (1.0 + t)).powf(g);
    if let Some(c) = stick {
        let u = x / c;
        if u.abs() < 1.0 {
            q -= mu * p0 * (c / a).powf(1.0 + k) * ((1.0 - u) * (1.0 + u)).powf(g);
        }
    }
    q
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The resultant of the traction, by a fine midpoint sum, is the applied load
    /// $T = fP(1 - (c/a)^{2+k})$ with $P = p_0 a \sqrt\pi\,\Gamma(\frac{3+k}{2})/\Gamma(2+\frac k2)$
    /// (the integral of the pressure shape), for several k.
    #[test]
    fn resultant_is_the_applied_load() {
        for k in [0.0, 0.1, 0.5, 0.9] {
            let (a, p0, mu) = (1.0, 1.0, 0.3);
            let ratio = 0.6;
            let c = stick_half_width(a, k, ratio);
            let n = 400_000;
            let h = 2.0 * a / n as f64;
            let (mut q_sum, mut p_sum) = (0.0, 0.0);
            for i in 0..n {
                let x = -a + (i as f64 + 0.5) * h;
                q_sum += traction(x, a, Some(c), p0, k, mu) * h;
                p_sum += traction(x, a, None, p0, k, 1.0) * h;
            }
            let want = ratio * mu * p_sum;
            assert!((q_sum - want).abs() <= 2e-6 * want, "k = {k}: {q_sum} vs {want}");
        }
    }

    #[test]
    fn gross_slip_has_no_stick_zone() {
        assert_eq!(stick_half_width(2.0, 0.3, 1.0), 0.0);
        assert_eq!(stick_half_width(2.0, 0.3, 1.5), 0.0);
        assert_eq!(stick_half_width(2.0, 0.3, 0.0), 2.0);
    }
}
