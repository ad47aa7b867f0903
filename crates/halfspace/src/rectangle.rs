//! Surface displacement due to a uniform traction on a rectangle of the half-space surface: the
//! influence coefficients of the 3D traction solvers.
//!
//! The rectangle is $[\xi_1, \xi_2]\times[\eta_1, \eta_2]$ on the surface $z = 0$; the field
//! point $(x, y)$ is any surface point (inside, on an edge or corner, or outside). With
//! $X_i = x - \xi_i$, $Y_j = y - \eta_j$, every integral of a point-load kernel $k(X, Y)$ over the
//! rectangle is the alternating corner sum of an antiderivative $F$ with
//! $\partial^2 F/\partial X\partial Y = k$:
//! $$\iint k\,d\xi\,d\eta = \sum_{i,j\in\{1,2\}} (-1)^{i+j} F(X_i, Y_j).$$
//! The antiderivatives used (terms whose denominator vanishes are taken as their limit 0):
//!
//! | kernel $k$ | $F(X, Y)$ |
//! |---|---|
//! | $1/\rho$ | $X\,\mathrm{asinh}(Y/\lvert X\rvert) + Y\,\mathrm{asinh}(X/\lvert Y\rvert)$ |
//! | $X^2/\rho^3$ | $Y\,\mathrm{asinh}(X/\lvert Y\rvert)$ |
//! | $Y^2/\rho^3$ | $X\,\mathrm{asinh}(Y/\lvert X\rvert)$ |
//! | $XY/\rho^3$ | $-\rho$ |
//! | $X/\rho^2$ | $Y\ln\rho + X\arctan(Y/X)$ |
//! | $Y/\rho^2$ | $X\ln\rho + Y\arctan(X/Y)$ |
//!
//! with $\rho = \sqrt{X^2+Y^2}$. The $1/\rho$ row is Love's (1929) uniform-pressure result
//! (Johnson, *Contact Mechanics*, eq. 3.25); the shear rows are the exact element-to-point
//! formulas of FORMULAS.md F (they agree with the Pohrt & Li 2014 closed forms).
//!
//! The elastic constants enter through [`Compliance`] ($c_1 = (1-\nu)/G$, $c_2 = \nu/G$,
//! $c_3 = (1-2\nu)/G$): [`Material::compliance`](crate::Material::compliance) for one body,
//! [`Compliance::pair`] for the relative displacement of two bodies. All results are per unit
//! traction; $u_z > 0$ is into the body, shear acts on the body in $+x$ (or $+y$).
//!
//! The functions are plain, allocation-free and `#[inline]`. Accuracy: the corner sum loses
//! about $\epsilon\,(d/h)^2$ relative accuracy at distance $d$ from an element of size $h$
//! (cancellation of the four corner terms); the crate's tests state the measured figures.

use crate::error::{finite, Error};
pub use crate::material::Compliance;
use crate::Displacement3;
use std::f64::consts::PI;

/// An axis-aligned rectangle $[\xi_1, \xi_2]\times[\eta_1, \eta_2]$ of the surface.
///
/// The fields are public for use in hot loops; [`Rect::new`] validates. A reversed interval
/// flips the sign of every result, a degenerate one gives zero.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    /// Lower $x$ edge $\xi_1$.
    pub x1: f64,
    /// Upper $x$ edge $\xi_2$.
    pub x2: f64,
    /// Lower $y$ edge $\eta_1$.
    pub y1: f64,
    /// Upper $y$ edge $\eta_2$.
    pub y2: f64,
}

impl Rect {
    /// A rectangle with finite edges and $\xi_1 < \xi_2$, $\eta_1 < \eta_2$.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for non-finite edges or empty intervals.
    pub fn new(x1: f64, x2: f64, y1: f64, y2: f64) -> Result<Self, Error> {
        finite("x1", x1)?;
        finite("x2", x2)?;
        finite("y1", y1)?;
        finite("y2", y2)?;
        if x1 >= x2 {
            return Err(Error::OutOfDomain { name: "x2", value: x2, allowed: "x2 > x1" });
        }
        if y1 >= y2 {
            return Err(Error::OutOfDomain { name: "y2", value: y2, allowed: "y2 > y1" });
        }
        Ok(Self { x1, x2, y1, y2 })
    }

    /// The rectangle with centre $(c_x, c_y)$ and half-sides $h_x, h_y > 0$.
    ///
    /// # Errors
    /// As [`Rect::new`].
    pub fn centered(cx: f64, cy: f64, hx: f64, hy: f64) -> Result<Self, Error> {
        Self::new(cx - hx, cx + hx, cy - hy, cy + hy)
    }

    /// Area $(\xi_2-\xi_1)(\eta_2-\eta_1)$.
    #[must_use]
    pub fn area(&self) -> f64 {
        (self.x2 - self.x1) * (self.y2 - self.y1)
    }
}

/// $a\,\mathrm{asinh}(b/|a|)$, with the limit 0 at $a = 0$; `rho` $= \sqrt{a^2+b^2}$.
#[inline(always)]
fn a_asinh(a: f64, b: f64, rho: f64) -> f64 {
    if a == 0.0 {
        0.0
    } else {
        // asinh(|b|/|a|) = ln((|b| + rho)/|a|): no cancellation for either sign of b.
        let l = ((b.abs() + rho) / a.abs()).ln();
        if b < 0.0 {
            -a * l
        } else {
            a * l
        }
    }
}

/// $b\ln\rho + a\arctan(b/a)$ (antiderivative of $a/\rho^2$), limits 0 where undefined.
#[inline(always)]
fn log_atan(a: f64, b: f64, ln_rho: f64) -> f64 {
    let t = if b == 0.0 { 0.0 } else { b * ln_rho };
    let u = if a == 0.0 { 0.0 } else { a * (b / a).atan() };
    t + u
}

/// The six rectangle integrals of the point-load kernels (per unit traction, no material
/// constants), see the module table.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct KernelIntegrals {
    /// $\iint 1/\rho$.
    pub inv_r: f64,
    /// $\iint X^2/\rho^3$.
    pub xx_r3: f64,
    /// $\iint Y^2/\rho^3$.
    pub yy_r3: f64,
    /// $\iint XY/\rho^3$.
    pub xy_r3: f64,
    /// $\iint X/\rho^2$.
    pub x_r2: f64,
    /// $\iint Y/\rho^2$.
    pub y_r2: f64,
}

/// Corner (X_i, Y_j) values and their signs.
#[inline(always)]
fn corners(r: &Rect, x: f64, y: f64) -> [(f64, f64, f64); 4] {
    let (xa, xb) = (x - r.x1, x - r.x2);
    let (ya, yb) = (y - r.y1, y - r.y2);
    [(xa, ya, 1.0), (xa, yb, -1.0), (xb, ya, -1.0), (xb, yb, 1.0)]
}

/// Love's integral $\iint_{\text{rect}} \frac{d\xi\,d\eta}{\sqrt{(x-\xi)^2+(y-\eta)^2}}$ as the
/// corner sum of $X\,\mathrm{asinh}(Y/|X|) + Y\,\mathrm{asinh}(X/|Y|)$ (Love 1929; Johnson
/// eq. 3.25; FORMULAS.md F). Finite everywhere, including the element's edges and corners.
#[inline]
#[must_use]
pub fn inv_r_integral(r: &Rect, x: f64, y: f64) -> f64 {
    let mut s = 0.0;
    for (a, b, sign) in corners(r, x, y) {
        let rho = (a * a + b * b).sqrt();
        s += sign * (a_asinh(a, b, rho) + a_asinh(b, a, rho));
    }
    s
}

/// All six kernel integrals of the module table at once (shares the square roots and logs).
#[inline]
#[must_use]
pub fn kernel_integrals(r: &Rect, x: f64, y: f64) -> KernelIntegrals {
    let mut k = KernelIntegrals::default();
    for (a, b, sign) in corners(r, x, y) {
        let rho = (a * a + b * b).sqrt();
        let fa = a_asinh(a, b, rho); // kernel Y^2/rho^3
        let fb = a_asinh(b, a, rho); // kernel X^2/rho^3
        let ln_rho = if rho > 0.0 { rho.ln() } else { 0.0 };
        k.inv_r += sign * (fa + fb);
        k.xx_r3 += sign * fb;
        k.yy_r3 += sign * fa;
        k.xy_r3 -= sign * rho;
        k.x_r2 += sign * log_atan(a, b, ln_rho);
        k.y_r2 += sign * log_atan(b, a, ln_rho);
    }
    k
}

/// Normal surface displacement $u_z(x, y)$ due to a unit uniform pressure on the rectangle
/// (Love 1929; Johnson eq. 3.25; FORMULAS.md F):
/// $$u_z = \frac{c_1}{2\pi}\iint\frac{d\xi\,d\eta}{\rho} = \frac{1-\nu}{2\pi G}\sum_{i,j}(-1)^{i+j}
/// \left[X_i\,\mathrm{asinh}\frac{Y_j}{|X_i|} + Y_j\,\mathrm{asinh}\frac{X_i}{|Y_j|}\right].$$
/// For one body $c_1/(2\pi) = (1-\nu^2)/(\pi E)$. This is the fast path of
/// [`pressure_displacement`].
#[inline]
#[must_use]
pub fn pressure_uz(c: &Compliance, r: &Rect, x: f64, y: f64) -> f64 {
    c.one_minus_nu / (2.0 * PI) * inv_r_integral(r, x, y)
}

/// Surface displacement (all three components) due to a unit uniform pressure on the rectangle:
/// $u_z$ as in [`pressure_uz`] and the in-plane part from Boussinesq's radial displacement
/// $-(1-2\nu)/(4\pi G\rho)$ (towards the load):
/// $$u_x = -\frac{c_3}{4\pi}\iint\frac{X}{\rho^2},\qquad u_y = -\frac{c_3}{4\pi}\iint
/// \frac{Y}{\rho^2}$$
/// (Johnson eq. 3.22 at $z = 0$; by Betti reciprocity these are also Cerruti's $u_z$ of
/// FORMULAS.md F with the opposite sign).
#[inline]
#[must_use]
pub fn pressure_displacement(c: &Compliance, r: &Rect, x: f64, y: f64) -> Displacement3 {
    let k = kernel_integrals(r, x, y);
    let cc = -c.one_minus_two_nu / (4.0 * PI);
    Displacement3 { x: cc * k.x_r2, y: cc * k.y_r2, z: c.one_minus_nu / (2.0 * PI) * k.inv_r }
}

/// Surface displacement due to a unit uniform shear traction along $+x$ on the rectangle
/// (Cerruti integrated exactly; FORMULAS.md F, element-to-point formula):
/// $$u_x = \frac{1}{2\pi}\sum_{i,j}(-1)^{i+j}\left[c_1 X_i\,\mathrm{asinh}\frac{Y_j}{|X_i|} +
/// (c_1 + c_2)\,Y_j\,\mathrm{asinh}\frac{X_i}{|Y_j|}\right],\qquad
/// u_y = -\frac{c_2}{2\pi}\sum_{i,j}(-1)^{i+j}\sqrt{X_i^2+Y_j^2},$$
/// $$u_z = \frac{c_3}{4\pi}\iint\frac{X}{\rho^2}$$
/// (for one body $c_1 = (1-\nu)/G$, $c_2 = \nu/G$, which is FORMULAS.md F's
/// $\frac{\tau}{2\pi G}[(1-\nu)X\,\mathrm{asinh}(Y/|X|) + Y\,\mathrm{asinh}(X/|Y|)]$).
/// At the centre of a square of side $h$: $u_x = (2-\nu)\ln(1+\sqrt2)\,h/(\pi G)$ per unit
/// traction.
#[inline]
#[must_use]
pub fn shear_x_displacement(c: &Compliance, r: &Rect, x: f64, y: f64) -> Displacement3 {
    let mut s1 = 0.0; // 1/rho
    let mut s2 = 0.0; // X^2/rho^3
    let mut s3 = 0.0; // XY/rho^3
    let mut s4 = 0.0; // X/rho^2
    for (a, b, sign) in corners(r, x, y) {
        let rho = (a * a + b * b).sqrt();
        let fa = a_asinh(a, b, rho);
        let fb = a_asinh(b, a, rho);
        let ln_rho = if rho > 0.0 { rho.ln() } else { 0.0 };
        s1 += sign * (fa + fb);
        s2 += sign * fb;
        s3 -= sign * rho;
        s4 += sign * log_atan(a, b, ln_rho);
    }
    let k = 1.0 / (2.0 * PI);
    Displacement3 {
        x: k * (c.one_minus_nu * s1 + c.nu * s2),
        y: k * c.nu * s3,
        z: 0.5 * k * c.one_minus_two_nu * s4,
    }
}

/// Tangential part only, $u_x$ due to a unit shear along $+x$: the fast path of
/// [`shear_x_displacement`] used by uncoupled traction solvers.
#[inline]
#[must_use]
pub fn shear_x_ux(c: &Compliance, r: &Rect, x: f64, y: f64) -> f64 {
    let mut s1 = 0.0;
    let mut s2 = 0.0;
    for (a, b, sign) in corners(r, x, y) {
        let rho = (a * a + b * b).sqrt();
        let fa = a_asinh(a, b, rho);
        let fb = a_asinh(b, a, rho);
        s1 += sign * fa;
        s2 += sign * fb;
    }
    // c1 (fa + fb) + c2 fb
    (c.one_minus_nu * s1 + (c.one_minus_nu + c.nu) * s2) / (2.0 * PI)
}

/// Surface displacement due to a unit uniform shear traction along $+y$ on the rectangle: the
/// mirror image of [`shear_x_displacement`] under $x \leftrightarrow y$ (FORMULAS.md F):
/// $$u_y = \frac{1}{2\pi}\left[c_1\iint\frac1\rho + c_2\iint\frac{Y^2}{\rho^3}\right],\quad
/// u_x = \frac{c_2}{2\pi}\iint\frac{XY}{\rho^3},\quad u_z = \frac{c_3}{4\pi}\iint\frac{Y}{\rho^2}.$$
#[inline]
#[must_use]
pub fn shear_y_displacement(c: &Compliance, r: &Rect, x: f64, y: f64) -> Displacement3 {
    let k = kernel_integrals(r, x, y);
    let f = 1.0 / (2.0 * PI);
    Displacement3 {
        x: f * c.nu * k.xy_r3,
        y: f * (c.one_minus_nu * k.inv_r + c.nu * k.yy_r3),
        z: 0.5 * f * c.one_minus_two_nu * k.y_r2,
    }
}

/// Centre self-term of a rectangle of half-sides $c_x$ (along the shear) and $c_y$, per unit
/// **force** $F = 4c_xc_y\tau$ (FORMULAS.md F, $A_{kk}$; Pohrt & Li 2014):
/// $$A_{kk} = \frac{(1-\nu)c_x\,\mathrm{asinh}(c_y/c_x) + c_y\,\mathrm{asinh}(c_x/c_y)}{2\pi G
/// c_xc_y},$$
/// written with the compliance constants as $[c_1 c_x\,\mathrm{asinh}(c_y/c_x) + (c_1 + c_2)c_y
/// \,\mathrm{asinh}(c_x/c_y)]/(2\pi c_xc_y)$. For a square of side $h$ this is
/// $(2-\nu)\ln(1+\sqrt2)/(\pi G h)$.
#[must_use]
pub fn shear_self_term(c: &Compliance, cx: f64, cy: f64) -> f64 {
    (c.one_minus_nu * cx * (cy / cx).asinh() + (c.one_minus_nu + c.nu) * cy * (cx / cy).asinh())
        / (2.0 * PI * cx * cy)
}
