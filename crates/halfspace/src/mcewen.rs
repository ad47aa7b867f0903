//! Subsurface stresses in a half-plane loaded by a Hertz pressure and a proportional (Hertz
//! shaped) shear traction: McEwen (1949) in real form and Muskhelishvili's complex potential.
//!
//! Loading on the surface $y = 0$ of the body $y > 0$ ($y$ is depth, plane strain):
//! $$p(x) = p_0\sqrt{1 - x^2/a^2},\qquad q(x) = q_0\sqrt{1 - x^2/a^2}\quad(|x| \le a),$$
//! $p$ pushing into the body and $q$ acting on the body in $+x$ (for sliding friction
//! $q_0 = f p_0$, with the sign of $q_0$ the direction of the friction force on this body).
//! Hence $\sigma_{yy}(x, 0) = -p(x)$ and $\sigma_{xy}(x, 0) = -q(x)$; on the surface
//! $\sigma_{xx} = -p(x) - 2q_0x/a$ inside the contact and $-2q_0(x - \mathrm{sgn}(x)\sqrt{x^2-a^2})/a$
//! outside, with the largest tension $+2q_0$ at the trailing edge $x = -a$.
//!
//! Two independent forms are provided (FORMULAS.md C; the tests check that they agree with
//! each other and with direct quadrature of Flamant's kernels over the traction):
//! - [`stress_mn`]: McEwen's $m, n$ form as in Johnson, *Contact Mechanics*, eqs 7.5 and 7.6
//!   (signs as fixed in FORMULAS.md C for $q$ acting in $+x$, $z \equiv y$ depth).
//! - [`stress_potential`]: Muskhelishvili's complex potential,
//!   $\Phi(z) = \frac{p_0 + iq_0}{2ia}\left(\sqrt{z^2-a^2} - z\right)$. FORMULAS.md C states it for
//!   a body in $y_C < 0$ with $\sigma_{xy}(x,0) = +q$; this crate maps $y_C = -y$, $z = x - iy$,
//!   keeps $\sigma_{xx}, \sigma_{yy}$ and flips the sign of $\sigma_{xy}$ (reflection in the
//!   surface), which turns $\sigma_{xy}(x, 0) = +q$ into our $-q$.

use crate::error::{finite, positive, Error};
use crate::Stress2;

/// Stress at $(x, y)$, $y \ge 0$, under Hertz pressure of half-width $a$ and peak $p_0$ plus a
/// Hertz-shaped shear of peak $q_0$, by McEwen's real form (Johnson eqs 7.5–7.6; FORMULAS.md C):
/// $$\sigma_{xx} = -\frac{p_0}{a}\left[m\left(1 + \frac{y^2+n^2}{m^2+n^2}\right) - 2y\right] +
/// \frac{q_0}{a}\left[n\left(2 - \frac{y^2-m^2}{m^2+n^2}\right) - 2x\right],$$
/// $$\sigma_{yy} = -\frac{p_0}{a}m\left(1 - \frac{y^2+n^2}{m^2+n^2}\right) -
/// \frac{q_0}{a}\,n\,\frac{m^2-y^2}{m^2+n^2},\qquad
/// \sigma_{xy} = -\frac{p_0}{a}\,n\,\frac{m^2-y^2}{m^2+n^2} -
/// \frac{q_0}{a}\left[m\left(1 + \frac{y^2+n^2}{m^2+n^2}\right) - 2y\right],$$
/// $m^2, n^2 = \tfrac12\left[\sqrt{(a^2-x^2+y^2)^2 + 4x^2y^2} \pm (a^2-x^2+y^2)\right]$,
/// $\mathrm{sgn}\,m = \mathrm{sgn}\,y$, $\mathrm{sgn}\,n = \mathrm{sgn}\,x$; $m$ and $n$ are
/// computed without cancellation ($mn = xy$). Far from the contact ($r \gg a$) the bracketed
/// differences cancel and about $\epsilon(r/a)^2$ relative accuracy is lost; prefer
/// [`stress_potential`] there.
#[must_use]
pub fn stress_mn(a: f64, p0: f64, q0: f64, x: f64, y: f64) -> Stress2 {
    let d = a * a - x * x + y * y;
    let s = d.hypot(2.0 * x * y); // = m^2 + n^2
    let (m, n) = if d >= 0.0 {
        let m = (0.5 * (s + d)).sqrt();
        (m, if m > 0.0 { x * y / m } else { 0.0 })
    } else {
        let n = (0.5 * (s - d)).sqrt().copysign(x);
        (x * y / n, n)
    };
    let (r1, r2) = if s > 0.0 { ((y * y + n * n) / s, (m * m - y * y) / s) } else { (0.0, 0.0) };
    let pa = p0 / a;
    let qa = q0 / a;
    let big = m * (1.0 + r1) - 2.0 * y;
    Stress2 {
        xx: -pa * big + qa * (n * (2.0 + r2) - 2.0 * x),
        yy: -pa * m * (1.0 - r1) - qa * n * r2,
        xy: -pa * n * r2 - qa * big,
    }
}

/// Minimal complex arithmetic for the potential (private, problem-specific).
#[derive(Debug, Clone, Copy)]
struct C {
    re: f64,
    im: f64,
}

impl C {
    fn new(re: f64, im: f64) -> Self {
        Self { re, im }
    }
    fn add(self, o: Self) -> Self {
        Self::new(self.re + o.re, self.im + o.im)
    }
    fn mul(self, o: Self) -> Self {
        Self::new(self.re * o.re - self.im * o.im, self.re * o.im + self.im * o.re)
    }
    fn scale(self, k: f64) -> Self {
        Self::new(self.re * k, self.im * k)
    }
    fn conj(self) -> Self {
        Self::new(self.re, -self.im)
    }
    fn recip(self) -> Self {
        // Smith's algorithm avoids overflow of |z|^2.
        if self.re.abs() >= self.im.abs() {
            let r = self.im / self.re;
            let d = self.re + self.im * r;
            Self::new(1.0 / d, -r / d)
        } else {
            let r = self.re / self.im;
            let d = self.re * r + self.im;
            Self::new(r / d, -1.0 / d)
        }
    }
    /// Principal square root, honouring the sign of a zero imaginary part (so that the limit
    /// from below the cut is taken when `im == -0.0`).
    fn sqrt(self) -> Self {
        let t = ((self.re.hypot(self.im) + self.re.abs()) * 0.5).sqrt();
        if t == 0.0 {
            Self::new(0.0, self.im)
        } else if self.re >= 0.0 {
            Self::new(t, self.im / (2.0 * t))
        } else {
            Self::new(self.im.abs() / (2.0 * t), t.copysign(self.im))
        }
    }
}

/// $(w, 1/(w+z))$ with $w = \sqrt{z-a}\sqrt{z+a}$ ($\sim z$ at infinity, cut on $[-a, a]$).
fn branch(z: C, a: f64) -> (C, C) {
    let w = C::new(z.re - a, z.im).sqrt().mul(C::new(z.re + a, z.im).sqrt());
    (w, w.add(z).recip())
}

/// Stress at $(x, y)$, $y \ge 0$, for the same loading as [`stress_mn`], from Muskhelishvili's
/// complex potential (FORMULAS.md C):
/// $$\Phi(z) = \frac{p_0 + iq_0}{2ia}\left(\sqrt{z^2-a^2} - z\right)
/// = -\frac{(p_0 + iq_0)\,a}{2i\left(\sqrt{z^2-a^2} + z\right)},$$
/// $$\sigma_{xx} = \mathrm{Re}\left[3\Phi + \bar\Phi - (\bar z - z)\Phi'\right],\quad
/// \sigma_{yy} = \mathrm{Re}\left[\Phi - \bar\Phi + (\bar z - z)\Phi'\right],\quad
/// \sigma_{xy} = -\mathrm{Im}\left[(\bar z - z)\Phi' - \Phi - \bar\Phi\right],$$
/// $\bar\Phi(z) := \overline{\Phi(\bar z)}$, evaluated at $z = x - iy$ (the body of FORMULAS.md C
/// lies in $\mathrm{Im}\,z < 0$; the leading minus of $\sigma_{xy}$ converts to this crate's
/// convention). Written without cancellation, so accurate also far from the contact. On the
/// surface ($y = 0$) the $(\bar z - z)\Phi'$ term is exactly zero and is dropped, which keeps
/// the contact edges finite.
#[must_use]
pub fn stress_potential(a: f64, p0: f64, q0: f64, x: f64, y: f64) -> Stress2 {
    // k = (p0 + i q0) / (2 i a) = (q0 - i p0) / (2a)
    let k = C::new(q0, -p0).scale(0.5 / a);
    // Body point z = x - i y; use -0.0 on the surface so the cut is approached from below.
    let z = C::new(x, -y);
    let (w, inv_wz) = branch(z, a);
    // Phi = k (w - z) = -k a^2 / (w + z)
    let phi = k.mul(inv_wz).scale(-a * a);
    // Phibar(z) = conj(Phi(conj z))
    let zc = z.conj();
    let (_, inv_wzc) = branch(zc, a);
    let phibar = k.mul(inv_wzc).scale(-a * a).conj();
    // (zbar - z) Phi' with Phi' = k (z/w - 1) = k a^2 / (w (w + z)); zbar - z = 2 i y.
    let t = if y == 0.0 {
        C::new(0.0, 0.0)
    } else {
        let dphi = k.mul(w.mul(w.add(z)).recip()).scale(a * a);
        C::new(0.0, 2.0 * y).mul(dphi)
    };
    let s_xx = 3.0 * phi.re + phibar.re - t.re;
    let s_yy = phi.re - phibar.re + t.re;
    let s_xy_c = t.im - phi.im - phibar.im;
    Stress2 { xx: s_xx, yy: s_yy, xy: -s_xy_c }
}

/// The Hertz-shaped traction of this module, validated: half-width $a > 0$, peaks $p_0$, $q_0$
/// finite. Convenience wrapper over [`stress_potential`] and [`stress_mn`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzTraction {
    a: f64,
    p0: f64,
    q0: f64,
}

impl HertzTraction {
    /// Validated constructor.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `a` is not finite and positive or a peak is not finite.
    pub fn new(a: f64, p0: f64, q0: f64) -> Result<Self, Error> {
        Ok(Self { a: positive("a", a)?, p0: finite("p0", p0)?, q0: finite("q0", q0)? })
    }

    /// Sliding friction on a Hertz contact: $q_0 = f p_0$.
    ///
    /// # Errors
    /// As [`HertzTraction::new`].
    pub fn sliding(a: f64, p0: f64, friction: f64) -> Result<Self, Error> {
        Self::new(a, p0, friction * p0)
    }

    /// Pressure $p(x) = p_0\sqrt{1-x^2/a^2}$ ($0$ outside) (Hertz; FORMULAS.md C).
    #[must_use]
    pub fn pressure(&self, x: f64) -> f64 {
        self.p0 * ellipse_factor(x, self.a)
    }

    /// Shear traction $q(x) = q_0\sqrt{1-x^2/a^2}$ ($0$ outside), acting on the body in $+x$
    /// (McEwen 1949; FORMULAS.md C, $q = fp$ for sliding).
    #[must_use]
    pub fn shear(&self, x: f64) -> f64 {
        self.q0 * ellipse_factor(x, self.a)
    }

    /// Stress at $(x, y)$ from Muskhelishvili's potential
    /// $\Phi(z) = \frac{p_0 + iq_0}{2ia}(\sqrt{z^2-a^2} - z)$ ([`stress_potential`], which
    /// states the stress formulas; FORMULAS.md C).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for non-finite input or $y < 0$.
    pub fn stress(&self, x: f64, y: f64) -> Result<Stress2, Error> {
        finite("x", x)?;
        if !(y >= 0.0 && y.is_finite()) {
            return Err(Error::OutOfDomain { name: "y", value: y, allowed: "finite, >= 0" });
        }
        Ok(stress_potential(self.a, self.p0, self.q0, x, y))
    }
}

/// $\sqrt{1 - x^2/a^2}$ for $|x| < a$, else 0, computed as $\sqrt{(1-x/a)(1+x/a)}$.
#[inline]
pub(crate) fn ellipse_factor(x: f64, a: f64) -> f64 {
    let t = x / a;
    if t.abs() >= 1.0 {
        0.0
    } else {
        ((1.0 - t) * (1.0 + t)).sqrt()
    }
}
