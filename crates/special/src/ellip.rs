//! Complete elliptic integrals $K(m)$ and $E(m)$ in the *parameter* convention $m = k^2$.
//!
//! FORMULAS.md (sections E and G) writes $K(k)$, $E(k)$ with the *modulus* $k$; call
//! [`ellipk`]`(k * k)` for those. Methods: the arithmetic-geometric mean (DLMF 19.8.1, 19.8.6),
//! the imaginary-modulus transformation for $m<0$ (DLMF 19.7.5), and the logarithmic
//! series about $m=1$ (DLMF 19.12.1-2) where the AGM form of $E$ loses digits.

use crate::error::{out_of_domain, Error};
use std::f64::consts::{FRAC_PI_2, LN_2};

/// Arithmetic-geometric mean of $1$ and $b>0$, with the sum
/// $\sum_{n\ge1}2^{n-1}c_n^2$, $c_{n}=(a_{n-1}-b_{n-1})/2$ (DLMF 19.8.6).
fn agm(b0: f64) -> (f64, f64) {
    let (mut a, mut b) = (1.0_f64, b0);
    let mut sum = 0.0;
    let mut w = 1.0;
    for _ in 0..64 {
        let c = 0.5 * (a - b);
        if c.abs() <= 2.0 * f64::EPSILON * a {
            break;
        }
        sum += w * c * c;
        w *= 2.0;
        let an = 0.5 * (a + b);
        b = (a * b).sqrt();
        a = an;
    }
    (0.5 * (a + b), sum)
}

/// $K$ from the complementary parameter $m_c = 1-m > 0$: $K = \pi/(2\,\mathrm{AGM}(1,\sqrt{m_c}))$.
fn k_from_mc(mc: f64) -> f64 {
    if mc.is_infinite() {
        return 0.0;
    }
    FRAC_PI_2 / agm(mc.sqrt()).0
}

/// $E$ for $0\le m\le 1$, given both $m$ and $m_c = 1-m$ accurately.
fn e_from(m: f64, mc: f64) -> f64 {
    if mc == 0.0 {
        return 1.0;
    }
    if mc < 0.1 {
        // DLMF 19.12.2: E = 1 + 1/2 sum_j t_j mc^{j+1} (ln(1/k') + d_j - 1/((2j+1)(2j+2))),
        // t_j = (1/2)_j (3/2)_j / ((2)_j j!), d_0 = ln 4, d_j = d_{j-1} - 2/((2j-1)2j).
        // Every term is positive for mc < 0.1, so there is no cancellation.
        let lk = -0.5 * mc.ln();
        let mut t = 1.0;
        let mut d = 2.0 * LN_2;
        let mut p = mc;
        let mut sum = 0.0;
        for j in 0..80 {
            let jf = j as f64;
            if j > 0 {
                t *= (jf - 0.5) * (jf + 0.5) / ((jf + 1.0) * jf);
                d -= 2.0 / ((2.0 * jf - 1.0) * (2.0 * jf));
            }
            let term = t * p * (lk + d - 1.0 / ((2.0 * jf + 1.0) * (2.0 * jf + 2.0)));
            sum += term;
            if term.abs() <= 1e-18 * sum.abs() {
                break;
            }
            p *= mc;
        }
        return 1.0 + 0.5 * sum;
    }
    // DLMF 19.8.6: E = K (1 - m/2 - sum 2^{n-1} c_n^2); cancellation at most ~K/E < 2.4 here.
    let (g, s) = agm(mc.sqrt());
    (FRAC_PI_2 / g) * ((1.0 - 0.5 * m) - s)
}

/// Complete elliptic integral of the first kind, parameter $m=k^2$.
///
/// $$K(m) = \int_0^{\pi/2}\frac{d\theta}{\sqrt{1-m\sin^2\theta}}
///        = \frac{\pi}{2\,\mathrm{AGM}\bigl(1,\sqrt{1-m}\bigr)}.$$
///
/// Domain: $m<1$, including $m\to1^-$ (where $K\approx\tfrac12\ln(16/(1-m))$) and
/// $m\to-\infty$ (where $K\approx\ln(4\sqrt{-m})/\sqrt{-m}$). NaN for $m\ge1$ and NaN.
/// Source: DLMF 19.2.8, 19.8.5; FORMULAS.md §E (Cattaneo compliance) and §G (Lubkin)
/// use $K$ of the modulus $k$: pass $m=k^2$.
pub fn ellipk(m: f64) -> f64 {
    if m.is_nan() || m >= 1.0 {
        return f64::NAN;
    }
    // 1 - m is exact for m >= 1/2 (Sterbenz); below, its rounding moves K by < 1e-16.
    k_from_mc(1.0 - m)
}

/// Complete elliptic integral of the second kind, parameter $m=k^2$.
///
/// $$E(m) = \int_0^{\pi/2}\sqrt{1-m\sin^2\theta}\,d\theta,\qquad E(1)=1,\qquad
///   E(m) = \sqrt{1-m}\;E\!\left(\frac{-m}{1-m}\right)\ (m<0).$$
///
/// Domain: $m\le1$ (NaN for $m>1$ and NaN); $E(-\infty)=+\infty$.
/// AGM form (DLMF 19.8.6) for $m\le 0.9$, logarithmic series DLMF 19.12.2 for $m>0.9$,
/// imaginary-modulus transformation DLMF 19.7.5 for $m<0$.
/// Source: DLMF 19.2.8; FORMULAS.md §E and §G (modulus $k$: pass $m=k^2$).
pub fn ellipe(m: f64) -> f64 {
    if m.is_nan() || m > 1.0 {
        return f64::NAN;
    }
    if m >= 0.0 {
        return e_from(m, 1.0 - m);
    }
    if m == f64::NEG_INFINITY {
        return f64::INFINITY;
    }
    // m < 0: m' = -m/(1-m) in (0, 1), m'_c = 1/(1-m).
    let s = 1.0 - m;
    let mc = 1.0 / s;
    let mp = -m * mc;
    s.sqrt() * e_from(mp, mc)
}

/// Checked [`ellipk`]: rejects $m\ge1$ and NaN.
///
/// # Errors
/// [`Error::OutOfDomain`] for those arguments.
pub fn checked_ellipk(m: f64) -> Result<f64, Error> {
    if m < 1.0 {
        Ok(ellipk(m))
    } else {
        Err(out_of_domain("ellipk", m, "m < 1"))
    }
}

/// Checked [`ellipe`]: rejects $m>1$ and NaN.
///
/// # Errors
/// [`Error::OutOfDomain`] for those arguments.
pub fn checked_ellipe(m: f64) -> Result<f64, Error> {
    if m <= 1.0 {
        Ok(ellipe(m))
    } else {
        Err(out_of_domain("ellipe", m, "m <= 1"))
    }
}

/// Carlson's symmetric integral $R_D(x,y,z)=\tfrac32\int_0^\infty
/// \frac{dt}{\sqrt{(t+x)(t+y)}\,(t+z)^{3/2}}$ by the duplication theorem (Carlson 1995,
/// Numer. Algorithms 10, algorithm for $R_D$; DLMF 19.36.2 gives the fifth-order series used
/// at the end). With the stopping rule $\max|\Delta|<1.5\times10^{-3}$ the truncated series
/// errs by about $\Delta^6<10^{-17}$ relative.
fn carlson_rd(mut x: f64, mut y: f64, mut z: f64) -> f64 {
    const ERRTOL: f64 = 1.5e-3;
    const C1: f64 = 3.0 / 14.0;
    const C2: f64 = 1.0 / 6.0;
    const C3: f64 = 9.0 / 22.0;
    const C4: f64 = 3.0 / 26.0;
    const C5: f64 = 0.25 * C3;
    const C6: f64 = 1.5 * C4;
    let mut sum = 0.0;
    let mut fac = 1.0;
    // Each step divides the spread of the arguments by about 4; 200 steps is far more than
    // any f64 input needs (huge ratios collapse by a square root in the first steps).
    for _ in 0..200 {
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lam = sx * (sy + sz) + sy * sz;
        sum += fac / (sz * (z + lam));
        fac *= 0.25;
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
        let ave = 0.2 * (x + y + 3.0 * z);
        let (dx, dy, dz) = ((ave - x) / ave, (ave - y) / ave, (ave - z) / ave);
        if dx.abs().max(dy.abs()).max(dz.abs()) < ERRTOL {
            let ea = dx * dy;
            let eb = dz * dz;
            let ec = ea - eb;
            let ed = ea - 6.0 * eb;
            let ee = ed + ec + ec;
            let series = 1.0
                + ed * (-C1 + C5 * ed - C6 * dz * ee)
                + dz * (C2 * ee + dz * (-C3 * ec + dz * C4 * ea));
            return 3.0 * sum + fac * series / (ave * ave.sqrt());
        }
    }
    f64::NAN
}

/// The combination $D(m)=\dfrac{K(m)-E(m)}{m}$, parameter $m=k^2$, without cancellation.
///
/// $$D(m)=\int_0^{\pi/2}\frac{\sin^2\theta\,d\theta}{\sqrt{1-m\sin^2\theta}}
///       =\tfrac13 R_D(0,\,1-m,\,1),\qquad D(0)=\pi/4 .$$
///
/// Computing $(K-E)/m$ from [`ellipk`] and [`ellipe`] loses about $\log_{10}(1/|m|)$ digits as
/// $m\to0$; this form keeps full relative accuracy there, and $K-E = m\,D(m)$ is then accurate
/// too. It appears in Cattaneo's compliance $\Lambda$ (FORMULAS.md §E) and in Lubkin's torsion
/// solution, where $K(k)-E(k)$ with $k\to0$ is needed (FORMULAS.md §G).
///
/// Domain: $m<1$ (logarithmic growth as $m\to1^-$; $D\approx1/\sqrt{-m}$ as
/// $m\to-\infty$, where $E$ dominates). NaN for $m\ge1$ and NaN. Source: DLMF 19.2.8, 19.25.1; Carlson (1995).
pub fn ellipd(m: f64) -> f64 {
    if m.is_nan() || m >= 1.0 {
        return f64::NAN;
    }
    if m == f64::NEG_INFINITY {
        return 0.0;
    }
    carlson_rd(0.0, 1.0 - m, 1.0) / 3.0
}

/// [`ellipd`] with an error for $m\ge1$ or NaN.
pub fn checked_ellipd(m: f64) -> Result<f64, Error> {
    if m < 1.0 {
        Ok(ellipd(m))
    } else {
        Err(out_of_domain("ellipd", m, "m < 1"))
    }
}
