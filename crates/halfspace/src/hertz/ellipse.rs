//! Hertz contact with an elliptic contact area (general point contact): Hertz (1882);
//! Johnson, *Contact Mechanics*, eqs 3.39–3.41 and 4.40. FORMULAS.md covers only the circular
//! case (section E), which is the limit $R'_x = R'_y$ of this one.

use crate::error::{positive, Error};
use std::f64::consts::{FRAC_PI_2, PI};

/// Hertz contact of two bodies whose gap is $h = x^2/(2R'_x) + y^2/(2R'_y)$ (principal relative
/// radii $R'_x, R'_y$ along the axes), pressed by $P$:
/// $$p(x, y) = p_0\sqrt{1 - x^2/a_x^2 - y^2/a_y^2},\qquad p_0 = \frac{3P}{2\pi a_xa_y}.$$
///
/// With $a \ge b$ the semi-axes along the directions of the larger and smaller relative radius,
/// $e^2 = m = 1 - b^2/a^2$, and $K, E$ the complete elliptic integrals of parameter $m$, the
/// contact condition $\bar u_z = \delta - x^2/(2R'_x) - y^2/(2R'_y)$ requires (Johnson eqs
/// 3.39–3.41 and 4.40)
/// $$\frac{1}{2R'_{\text{major}}} = \frac{p_0 b}{E^*a^2e^2}(K-E),\qquad
/// \frac{1}{2R'_{\text{minor}}} = \frac{p_0 b}{E^*a^2e^2}\left(\frac{a^2}{b^2}E - K\right),
/// \qquad \delta = \frac{p_0 b}{E^*}K.$$
/// Hence the eccentricity solves
/// $$g(m) = \frac{E - (1-m)K}{(1-m)(K-E)} = \frac{R'_{\text{major}}}{R'_{\text{minor}}} \ge 1,$$
/// and then $a^3 = \frac{3PR'_{\text{major}}}{\pi E^*}\frac{K-E}{m}$, $b = a\sqrt{1-m}$,
/// $\delta = \frac{3PK}{2\pi aE^*}$. The root is found by a bracketed search on
/// $\ln(b/a)$ (Illinois regula falsi with bisection safeguard), and $(K-E)/m$ and
/// $(E-(1-m)K)/m$ are summed from their power series for $m \le 1/4$ so the circle limit
/// ($R'_x = R'_y$: $m = 0$, $(K-E)/m = \pi/4$) is exact and the near-circle ratio carries no
/// cancellation. Sources: Hertz (1882); Johnson, *Contact Mechanics*, §3.4 and §4.2; the
/// circular case is FORMULAS.md E.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzEllipse {
    ax: f64,
    ay: f64,
    p0: f64,
    delta: f64,
    m: f64,
    iterations: u32,
}

/// Series coefficient $c_n = [(1/2)_n/n!]^2$ recursion: $c_n = c_{n-1}((2n-1)/(2n))^2$.
///
/// Returns $((K-E)/m, (E-(1-m)K)/m)$ for $0 \le m \le 1/4$ by their power series:
/// $(K-E)/m = \frac\pi2\sum_{n\ge1} c_n m^{n-1}\frac{2n}{2n-1}$,
/// $(E-(1-m)K)/m = \frac\pi2\sum_{n\ge1} c_n m^{n-1}\frac{2n}{(2n-1)^2}$
/// (term-by-term from the hypergeometric series of $K$ and $E$, Abramowitz & Stegun 17.3.11–12).
fn ke_ratios_series(m: f64) -> (f64, f64) {
    let mut c = 1.0; // c_0
    let mut mp = 1.0; // m^(n-1)
    let (mut sn, mut sm) = (0.0, 0.0);
    for n in 1..200 {
        let nf = f64::from(n);
        let r = (2.0 * nf - 1.0) / (2.0 * nf);
        c *= r * r;
        let tn = c * mp * 2.0 * nf / (2.0 * nf - 1.0);
        let tm = tn / (2.0 * nf - 1.0);
        sn += tn;
        sm += tm;
        if tn < 1e-18 * sn {
            break;
        }
        mp *= m;
    }
    (FRAC_PI_2 * sn, FRAC_PI_2 * sm)
}

/// $(K, (K-E)/m, (E-(1-m)K)/m)$ as functions of $m_1 = 1 - m = b^2/a^2 \in (0, 1]$.
fn ke_parts(m1: f64) -> (f64, f64, f64) {
    let m = 1.0 - m1;
    if m <= 0.25 {
        let (n, mm) = ke_ratios_series(m);
        // K = N m + M m + (1 - m) K  =>  K = N + M  (since E = K - N m, E - (1-m)K = M m
        // gives m K = N m + M m).
        (n + mm, n, mm)
    } else {
        let k = stickslip_special::ellipk(m);
        let e = stickslip_special::ellipe(m);
        (k, (k - e) / m, (e - m1 * k) / m)
    }
}

impl HertzEllipse {
    /// Solve the contact for principal relative radii $R'_x, R'_y$ (finite, positive), load $P$
    /// and composite modulus $E^*$.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for non-finite or non-positive input, or a radius ratio so
    /// extreme (beyond about $10^{12}$) that $b/a$ underflows the elliptic-integral arguments.
    pub fn new(rx: f64, ry: f64, load: f64, e_star: f64) -> Result<Self, Error> {
        positive("rx", rx)?;
        positive("ry", ry)?;
        positive("load", load)?;
        positive("e_star", e_star)?;
        let (r_major, r_minor) = if rx >= ry { (rx, ry) } else { (ry, rx) };
        let lambda = r_major / r_minor;
        if lambda.is_nan() || lambda > 1e12 {
            return Err(Error::OutOfDomain {
                name: "rx/ry",
                value: rx / ry,
                allowed: "radius ratio within [1e-12, 1e12]",
            });
        }
        let (kp, iterations) = solve_axis_ratio(lambda);
        let m1 = kp * kp;
        let (k, n, _) = ke_parts(m1);
        let a = (3.0 * load * r_major * n / (PI * e_star)).cbrt();
        let b = a * kp;
        let p0 = 3.0 * load / (2.0 * PI * a * b);
        let delta = 3.0 * load * k / (2.0 * PI * a * e_star);
        let (ax, ay) = if rx >= ry { (a, b) } else { (b, a) };
        Ok(Self { ax, ay, p0, delta, m: 1.0 - m1, iterations })
    }

    /// Same as [`HertzEllipse::new`] from principal relative curvatures
    /// $\kappa_x = 1/R'_x$, $\kappa_y = 1/R'_y$.
    ///
    /// # Errors
    /// As [`HertzEllipse::new`].
    pub fn from_curvatures(kx: f64, ky: f64, load: f64, e_star: f64) -> Result<Self, Error> {
        positive("kx", kx)?;
        positive("ky", ky)?;
        Self::new(1.0 / kx, 1.0 / ky, load, e_star)
    }

    /// Semi-axis along $x$.
    #[must_use]
    pub fn semi_axis_x(&self) -> f64 {
        self.ax
    }

    /// Semi-axis along $y$.
    #[must_use]
    pub fn semi_axis_y(&self) -> f64 {
        self.ay
    }

    /// Peak pressure $p_0 = 3P/(2\pi a_xa_y)$.
    #[must_use]
    pub fn max_pressure(&self) -> f64 {
        self.p0
    }

    /// Approach of distant points of the two bodies, $\delta = p_0 bK(m)/E^*$.
    #[must_use]
    pub fn approach(&self) -> f64 {
        self.delta
    }

    /// Squared eccentricity $m = e^2 = 1 - b^2/a^2$ (the parameter of $K$ and $E$).
    #[must_use]
    pub fn eccentricity_sq(&self) -> f64 {
        self.m
    }

    /// Root-finder iterations used.
    #[must_use]
    pub fn iterations(&self) -> u32 {
        self.iterations
    }

    /// Pressure $p_0\sqrt{1 - x^2/a_x^2 - y^2/a_y^2}$, zero outside the ellipse, with
    /// $p_0 = 3P/(2\pi a_xa_y)$ (Johnson eqs 3.39–3.41, 4.40; circular limit FORMULAS.md E).
    #[must_use]
    pub fn pressure(&self, x: f64, y: f64) -> f64 {
        let s = 1.0 - (x / self.ax).powi(2) - (y / self.ay).powi(2);
        if s > 0.0 {
            self.p0 * s.sqrt()
        } else {
            0.0
        }
    }
}

/// $\ln g(m)$ as a function of $t = \ln(b/a) \le 0$, where $g = M / ((1-m) N)$.
fn ln_g(t: f64) -> f64 {
    let m1 = (2.0 * t).exp();
    let (_, n, mm) = ke_parts(m1);
    (mm / (m1 * n)).ln()
}

/// Find $b/a \in (0, 1]$ with $g = \lambda$; returns it and the iteration count.
fn solve_axis_ratio(lambda: f64) -> (f64, u32) {
    if lambda == 1.0 {
        return (1.0, 0);
    }
    let target = lambda.ln();
    // ln g is decreasing in t and ~ -2t for small b/a: bracket [t_lo, 0].
    let mut hi = 0.0_f64; // f(hi) = ln g - target < 0
    let mut f_hi = -target;
    let mut lo = -(2.0 / 3.0) * target - 0.5; // Greenwood-like first guess, pushed out
    let mut f_lo = ln_g(lo) - target;
    let mut iterations = 1;
    while f_lo < 0.0 {
        hi = lo;
        f_hi = f_lo;
        lo = 2.0 * lo - 1.0;
        f_lo = ln_g(lo) - target;
        iterations += 1;
    }
    // Illinois regula falsi on [lo, hi] with f(lo) >= 0 > f(hi).
    let mut side = 0;
    for _ in 0..200 {
        let mut t = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        if !(t > lo && t < hi) {
            t = 0.5 * (lo + hi);
        }
        let f = ln_g(t) - target;
        iterations += 1;
        if f == 0.0 {
            return (t.exp(), iterations);
        }
        if f > 0.0 {
            lo = t;
            f_lo = f;
            if side == 1 {
                f_hi *= 0.5;
            }
            side = 1;
        } else {
            hi = t;
            f_hi = f;
            if side == -1 {
                f_lo *= 0.5;
            }
            side = -1;
        }
        if hi - lo <= 4.0 * f64::EPSILON * lo.abs().max(1e-300) {
            break;
        }
    }
    (((lo * f_hi - hi * f_lo) / (f_hi - f_lo)).exp(), iterations)
}
