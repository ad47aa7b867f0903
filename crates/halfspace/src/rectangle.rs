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
//! (cancellation of the four corner terms). Beyond [`FAR_FIELD`] element sizes the integrals
//! are therefore taken by a Gauss–Legendre product rule of the point kernels instead, which
//! are smooth there ($6\times6$ points up to 40 sizes, $4\times4$ to 200, $3\times3$ beyond;
//! the rule's error behaves like $(4d/h)^{-2n}$, below $10^{-16}$ relative everywhere), and the corner sum's own cancellation there is about $36\,\epsilon\approx8\times
//! 10^{-15}$. The far-field rule is evaluated in coordinates scaled by the distance, so field
//! points far beyond $10^{154}$ do not overflow.

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

/// Corner $(X_i, Y_j)$ values and their signs, with a power-of-two scale $l$ by which they
/// have been divided (1 for ordinary coordinates). Every corner sum of the module table is
/// homogeneous of degree 1 in $(X, Y)$ (the $\ln\rho$ parts cancel in the alternating sum), so
/// a caller multiplies its sums by $l$. Scaling only happens when a coordinate exceeds
/// $10^{100}$, where squares would overflow; a power of two keeps it exact.
#[inline(always)]
fn corners(r: &Rect, x: f64, y: f64) -> ([(f64, f64, f64); 4], f64) {
    let (xa, xb) = (x - r.x1, x - r.x2);
    let (ya, yb) = (y - r.y1, y - r.y2);
    let big = xa.abs().max(xb.abs()).max(ya.abs()).max(yb.abs());
    let l = if big > 1e100 { 2f64.powi(big.log2().ceil() as i32) } else { 1.0 };
    let (xa, xb, ya, yb) = (xa / l, xb / l, ya / l, yb / l);
    ([(xa, ya, 1.0), (xa, yb, -1.0), (xb, ya, -1.0), (xb, yb, 1.0)], l)
}

/// Distance from the element centre, in units of the element's larger side, beyond which the
/// kernel integrals use the Gauss–Legendre far-field rule instead of the corner sums.
pub const FAR_FIELD: f64 = 6.0;

/// Nodes and weights of the `n`-point Gauss–Legendre rule on $[-1, 1]$ for the far-field
/// orders used here ($n = 3, 4, 6$), from `stickslip-quad`, each built once.
fn gauss(n: usize) -> (&'static [f64], &'static [f64]) {
    use std::sync::OnceLock;
    type Pair = (Vec<f64>, Vec<f64>);
    static R3: OnceLock<Pair> = OnceLock::new();
    static R4: OnceLock<Pair> = OnceLock::new();
    static R6: OnceLock<Pair> = OnceLock::new();
    let cell = match n {
        3 => &R3,
        4 => &R4,
        _ => &R6,
    };
    let (t, w) = cell.get_or_init(|| {
        use stickslip_quad::Rule;
        let rule = stickslip_quad::GaussLegendre::new(n).expect("small Gauss rules exist");
        (rule.nodes().to_vec(), rule.weights().to_vec())
    });
    (t, w)
}

/// Order of the far-field rule at distance `d` (in element sizes): the product rule's error
/// behaves like $(4d/h)^{-2n}$ (nearest singularity of the kernels at the field point), which
/// is below $10^{-16}$ for $n = 6$ from 6 sizes, $n = 4$ from 40 and $n = 3$ from 200.
fn far_order(d_over_h: f64) -> usize {
    if d_over_h > 200.0 {
        3
    } else if d_over_h > 40.0 {
        4
    } else {
        6
    }
}

/// The kernel integrals by a Gauss–Legendre product rule (order from [`far_order`]) when the
/// field point is farther than [`FAR_FIELD`] element sizes from the element centre; `None`
/// otherwise. `1/rho` is always summed; `XX` adds $X^2/\rho^3$, `ALL` the other $1/\rho^3$
/// kernels and `LOG` the two $1/\rho^2$ kernels of the normal coupling (what is not summed is
/// left at 0; each kernel has its own accumulator, so leaving some out does not change the
/// others by a bit).
///
/// Every kernel is homogeneous in $(X, Y)$: with $s = 1/d$ the scaled offsets $sX, sY$ are
/// $O(1)$, and $1/\rho$, $X^2/\rho^3$, $Y^2/\rho^3$, $XY/\rho^3$ carry one factor $s$ while
/// $X/\rho^2$, $Y/\rho^2$ do too; nothing overflows or underflows early.
#[inline]
fn far_field<const XX: bool, const ALL: bool, const LOG: bool>(
    r: &Rect,
    x: f64,
    y: f64,
) -> Option<KernelIntegrals> {
    let (hx, hy) = (r.x2 - r.x1, r.y2 - r.y1);
    let (cx, cy) = (0.5 * (r.x1 + r.x2), 0.5 * (r.y1 + r.y2));
    let (dx, dy) = (x - cx, y - cy);
    let d = dx.abs().max(dy.abs());
    let h = hx.abs().max(hy.abs());
    let far = d.is_finite() && d > FAR_FIELD * h;
    if !far {
        return None;
    }
    let s = 1.0 / d;
    let (t, w) = gauss(far_order(d / h));
    let mut k = KernelIntegrals::default();
    for (ti, wi) in t.iter().zip(w) {
        let a = (dx - 0.5 * hx * ti) * s;
        for (tj, wj) in t.iter().zip(w) {
            let b = (dy - 0.5 * hy * tj) * s;
            let wij = wi * wj;
            let rho2 = a * a + b * b;
            let inv_r = 1.0 / rho2.sqrt();
            k.inv_r += wij * inv_r;
            // Only the kernels the caller uses are summed (the generic flags are constants,
            // so each instance is a branch-free loop).
            if XX || ALL {
                let inv_r3 = inv_r / rho2;
                k.xx_r3 += wij * a * a * inv_r3;
                if ALL {
                    k.yy_r3 += wij * b * b * inv_r3;
                    k.xy_r3 += wij * a * b * inv_r3;
                    if LOG {
                        k.x_r2 += wij * a / rho2;
                        k.y_r2 += wij * b / rho2;
                    }
                }
            }
        }
    }
    // Jacobian of the map to [-1, 1]^2, and the factor 1/s = d of the homogeneous kernels
    // (all of degree -1): each kernel integral is (hx hy / 4) * d^{-1} * sum.
    let scale = 0.25 * (hx * s) * hy;
    k.inv_r *= scale;
    k.xx_r3 *= scale;
    k.yy_r3 *= scale;
    k.xy_r3 *= scale;
    k.x_r2 *= scale;
    k.y_r2 *= scale;
    Some(k)
}

/// Love's integral $\iint_{\text{rect}} \frac{d\xi\,d\eta}{\sqrt{(x-\xi)^2+(y-\eta)^2}}$ as the
/// corner sum of $X\,\mathrm{asinh}(Y/|X|) + Y\,\mathrm{asinh}(X/|Y|)$ (Love 1929; Johnson
/// eq. 3.25; FORMULAS.md F). Finite everywhere, including the element's edges and corners.
#[inline]
#[must_use]
pub fn inv_r_integral(r: &Rect, x: f64, y: f64) -> f64 {
    if let Some(k) = far_field::<false, false, false>(r, x, y) {
        return k.inv_r;
    }
    let mut s = 0.0;
    let (cs, l) = corners(r, x, y);
    for (a, b, sign) in cs {
        let rho = (a * a + b * b).sqrt();
        s += sign * (a_asinh(a, b, rho) + a_asinh(b, a, rho));
    }
    s * l
}

/// All six kernel integrals of the module table at once (shares the square roots and logs):
/// each is the corner sum $\iint k\,d\xi\,d\eta = \sum_{i,j}(-1)^{i+j}F(X_i, Y_j)$ of the
/// antiderivative $F$ in the table (Love 1929 and Johnson eq. 3.25 for $1/\rho$; FORMULAS.md F
/// for the shear rows), or the far-field Gauss–Legendre rule beyond [`FAR_FIELD`].
#[inline]
#[must_use]
pub fn kernel_integrals(r: &Rect, x: f64, y: f64) -> KernelIntegrals {
    integrals::<true>(r, x, y)
}

/// [`kernel_integrals`], with the two $1/\rho^2$ kernels (`x_r2`, `y_r2`) only when `LOG`
/// (left at 0 otherwise; the others are the same to the bit either way).
#[inline(always)]
fn integrals<const LOG: bool>(r: &Rect, x: f64, y: f64) -> KernelIntegrals {
    if let Some(k) = far_field::<true, true, LOG>(r, x, y) {
        return k;
    }
    let mut k = KernelIntegrals::default();
    let (cs, l) = corners(r, x, y);
    for (a, b, sign) in cs {
        let rho = (a * a + b * b).sqrt();
        let fa = a_asinh(a, b, rho); // kernel Y^2/rho^3
        let fb = a_asinh(b, a, rho); // kernel X^2/rho^3
        k.inv_r += sign * (fa + fb);
        k.xx_r3 += sign * fb;
        k.yy_r3 += sign * fa;
        k.xy_r3 -= sign * rho;
        if LOG {
            let ln_rho = if rho > 0.0 { rho.ln() } else { 0.0 };
            k.x_r2 += sign * log_atan(a, b, ln_rho);
            k.y_r2 += sign * log_atan(b, a, ln_rho);
        }
    }
    if l != 1.0 {
        k.inv_r *= l;
        k.xx_r3 *= l;
        k.yy_r3 *= l;
        k.xy_r3 *= l;
        k.x_r2 *= l;
        k.y_r2 *= l;
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
    let k = kernel_integrals(r, x, y);
    let f = 1.0 / (2.0 * PI);
    Displacement3 {
        x: f * (c.one_minus_nu * k.inv_r + c.nu * k.xx_r3),
        y: f * c.nu * k.xy_r3,
        z: 0.5 * f * c.one_minus_two_nu * k.x_r2,
    }
}

/// Tangential part only, $u_x$ due to a unit shear along $+x$: the fast path of
/// [`shear_x_displacement`] used by uncoupled traction solvers,
/// $$u_x = \frac{1}{2\pi}\sum_{i,j}(-1)^{i+j}\left[c_1 X_i\,\mathrm{asinh}\frac{Y_j}{|X_i|} +
/// (c_1 + c_2)\,Y_j\,\mathrm{asinh}\frac{X_i}{|Y_j|}\right]$$
/// (Cerruti integrated over the rectangle; FORMULAS.md F, element-to-point formula).
#[inline]
#[must_use]
pub fn shear_x_ux(c: &Compliance, r: &Rect, x: f64, y: f64) -> f64 {
    if let Some(k) = far_field::<true, false, false>(r, x, y) {
        return (c.one_minus_nu * k.inv_r + c.nu * k.xx_r3) / (2.0 * PI);
    }
    let mut s1 = 0.0;
    let mut s2 = 0.0;
    let (cs, l) = corners(r, x, y);
    for (a, b, sign) in cs {
        let rho = (a * a + b * b).sqrt();
        let fa = a_asinh(a, b, rho);
        let fb = a_asinh(b, a, rho);
        s1 += sign * fa;
        s2 += sign * fb;
    }
    // c1 (fa + fb) + c2 fb
    l * (c.one_minus_nu * s1 + (c.one_minus_nu + c.nu) * s2) / (2.0 * PI)
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

/// The in-plane displacements due to unit uniform shear along $+x$ and along $+y$ on the
/// rectangle, from one evaluation of the kernel integrals: `[ux(τx), uy(τx), uy(τy)]`, where
/// $u_y(\tau_x) = u_x(\tau_y) = \frac{c_2}{2\pi}\iint XY/\rho^3$ (Cerruti integrated over
/// the rectangle; FORMULAS.md F, element-to-point formula). The same values, to the bit, as
/// the in-plane components of [`shear_x_displacement`] and [`shear_y_displacement`], at half
/// their cost or less (the kernels of the normal coupling are not formed): the tangential
/// influence coefficients of a lattice are this at every offset.
#[inline]
#[must_use]
pub fn shear_in_plane(c: &Compliance, r: &Rect, x: f64, y: f64) -> [f64; 3] {
    let k = integrals::<false>(r, x, y);
    let f = 1.0 / (2.0 * PI);
    [
        f * (c.one_minus_nu * k.inv_r + c.nu * k.xx_r3),
        f * c.nu * k.xy_r3,
        f * (c.one_minus_nu * k.inv_r + c.nu * k.yy_r3),
    ]
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
