//! The exact subsurface stress tensor below a uniformly loaded rectangle of the half-space
//! surface: uniform pressure $p$, uniform shear $q_x$ and uniform shear $q_y$ (each per unit
//! area), at any point $(x, y, z)$ with depth $z > 0$.
//!
//! Conventions (as in the whole crate): $z$ is the depth into the body, compression is
//! negative, $p > 0$ pushes into the body ($+z$), $q_x$ ($q_y$) acts on the body in $+x$
//! ($+y$). Hence, at $z \to 0^+$ under the interior of the rectangle,
//! $\sigma_{zz} \to -p$, $\sigma_{xz} \to -q_x$, $\sigma_{yz} \to -q_y$ (the outward normal of
//! the surface is $-z$).
//!
//! # Method (closed form)
//!
//! Love's potential solution (Love 1929, *Phil. Trans. R. Soc. A* 228; Johnson, *Contact
//! Mechanics*, §3.2, eqs 3.6–3.7) writes the field of surface tractions $(q_x, q_y, p)$
//! through the potentials $F_1 = q_x\Phi$, $G_1 = q_y\Phi$, $H_1 = p\Phi$ of the single
//! harmonic function
//! $$\Phi(x, y, z) = \iint_{\text{rect}} \Omega(x-\xi, y-\eta, z)\,d\xi\,d\eta,\qquad
//! \Omega = z\ln(R+z) - R,\quad R = \sqrt{X^2+Y^2+z^2}.$$
//! With $\psi_1 = q_x\Phi_x + q_y\Phi_y + p\Phi_z$ and $\psi = \partial_z\psi_1$, the
//! displacement is $u = U/(4\pi G)$,
//! $$U_x = 2q_x\Phi_{zz} - p\Phi_{xz} + 2\nu\partial_x\psi_1 - z\partial_x\psi,\quad
//! U_y = 2q_y\Phi_{zz} - p\Phi_{yz} + 2\nu\partial_y\psi_1 - z\partial_y\psi,$$
//! $$U_z = p\Phi_{zz} + (1-2\nu)\psi - z\partial_z\psi,$$
//! and Hooke's law (with $\nabla\cdot U = 2(1-2\nu)\partial_z\psi$) gives
//! $$\sigma_{ij} = \frac{1}{4\pi}\left(\partial_jU_i + \partial_iU_j\right) +
//! \frac{\nu}{\pi}\,\delta_{ij}\,\partial_z\psi .$$
//! These reproduce Boussinesq's and Cerruti's point-force fields
//! ([`crate::point_load`], Johnson eqs 3.21–3.22, 3.86–3.87) for $\Omega$ in place of
//! $\Phi$, which the tests check. Every stress is therefore a combination of third and fourth
//! derivatives of $\Phi$, and each of those is the alternating corner sum
//! $$\partial^\alpha\Phi = \sum_{i,j\in\{1,2\}}(-1)^{i+j}\,\partial^\alpha W(X_i, Y_j, z),
//! \qquad \frac{\partial^2W}{\partial X\,\partial Y} = \Omega,$$
//! with $X_i = x - \xi_i$, $Y_j = y - \eta_j$ (the same corner sum as
//! [`crate::rectangle`]). Terms of $W$ that depend on only one of $X$, $Y$ cancel in the
//! corner sum, so only the following antiderivatives are needed ($s_x = \sqrt{X^2+z^2}$,
//! $s_y = \sqrt{Y^2+z^2}$; $W_{abc} = \partial_X^a\partial_Y^b\partial_z^cW$; where $a, b
//! \ge 1$, $W_{abc} = \Omega_{a-1,b-1,c}$, the point kernel's derivatives):
//!
//! | $W_{abc}$ | antiderivative |
//! |---|---|
//! | $W_{300}$ | $Y/(R+z) - \mathrm{asinh}(Y/s_x)$ |
//! | $W_{201}$ | $\arctan\dfrac{XY(R-z)}{X^2R + zY^2}$ |
//! | $W_{102}$ | $\mathrm{asinh}(Y/s_x)$ |
//! | $W_{003}$ | $-\arctan\dfrac{XY}{zR}$ |
//! | $W_{400}$ | $-\Omega_{XY} + XY/(s_x^2R)$ |
//! | $W_{301}$ | $Y(Rz - X^2)/(R(R+z)s_x^2)$ |
//! | $W_{202}$ | $-XY/(s_x^2R)$ |
//! | $W_{103}$ | $-zY/(s_x^2R)$ |
//! | $W_{004}$ | $XY(1/s_x^2 + 1/s_y^2)/R$ |
//!
//! and their mirror images under $X \leftrightarrow Y$. For $z > 0$ every entry is finite and
//! continuous for all real $X, Y$ (the denominators $R$, $R+z$, $s_x$, $s_y$, $X^2R + zY^2$ are
//! positive), so the corner sum holds for field points inside, on the edges of, and outside the
//! rectangle alike. The pressure rows reduce to Love's (1929) uniform-rectangle stresses; the
//! shear rows are Cerruti's field integrated in closed form (derived here and stated in
//! FORMULAS.md F, "Subsurface stresses below a uniformly loaded rectangle"; checked against
//! adaptive quadrature of [`crate::point_load::cerruti_stress`] in the tests).
//!
//! # Accuracy
//!
//! The corner sum loses about $\epsilon\,(d/h)^2$ relative accuracy at distance $d$ from an
//! element of size $h$ (cancellation of the four corner terms). Beyond
//! [`crate::rectangle::FAR_FIELD`] element sizes (distance measured as
//! $\max(|x - x_c|, |y - y_c|, z)$) the stresses are taken instead by a Gauss–Legendre product
//! rule ($6\times6$ up to 40 sizes, $4\times4$ to 200, $3\times3$ beyond) of the point-force
//! stresses, which are smooth there: the rule's error behaves like $(4d/h)^{-2n}$, below
//! $10^{-16}$ relative. Both paths are accurate to about $10^{-14}$ relative to the largest
//! stress component; the tests check $10^{-10}$ against nested adaptive quadrature.

use crate::error::{finite, Error};
use crate::point_load::{boussinesq_stress, cerruti_stress};
use crate::rectangle::{Rect, FAR_FIELD};
use crate::{Material, Stress3};
use std::f64::consts::PI;

/// Uniform surface traction on a rectangle, per unit area: pressure `p` (into the body,
/// $+z$) and shears `qx`, `qy` acting on the body along $+x$, $+y$.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Traction {
    /// Normal pressure $p$ (positive pushes into the body).
    pub p: f64,
    /// Shear traction along $+x$ on the body.
    pub qx: f64,
    /// Shear traction along $+y$ on the body.
    pub qy: f64,
}

impl Traction {
    /// Unit pressure.
    pub const PRESSURE: Self = Self { p: 1.0, qx: 0.0, qy: 0.0 };
    /// Unit shear along $+x$.
    pub const SHEAR_X: Self = Self { p: 0.0, qx: 1.0, qy: 0.0 };
    /// Unit shear along $+y$.
    pub const SHEAR_Y: Self = Self { p: 0.0, qx: 0.0, qy: 1.0 };
}

/// Position of the multi-index $(a, b, c)$, $a + b + c = n$, in the derivative arrays of
/// [`PotentialDerivatives`]: $a$ descending, then $b$ descending.
#[inline(always)]
const fn slot(n: usize, a: usize, b: usize) -> usize {
    // entries with a' > a: sum_{a'=a+1}^{n} (n - a' + 1) = (n - a)(n - a + 1)/2
    let before = (n - a) * (n - a + 1) / 2;
    before + (n - a - b)
}

/// The third and fourth partial derivatives of a corner value $W(X, Y, z)$ (or of the
/// rectangle potential $\Phi$, their corner sum): `d3[slot]` for $\partial_X^a\partial_Y^b
/// \partial_z^c$ with $a + b + c = 3$ (10 entries), `d4` for order 4 (15 entries), ordered by
/// $a$ descending, then $b$ descending.
///
/// Used by lattice codes (`stickslip-traction`'s subsurface field) that share corners between
/// neighbouring elements: evaluate [`corner_derivatives`] once per lattice node, form the
/// alternating corner sums with [`PotentialDerivatives::add_scaled`], and turn the sums into
/// stresses with [`stress_from_potential`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PotentialDerivatives {
    /// Third derivatives.
    pub d3: [f64; 10],
    /// Fourth derivatives.
    pub d4: [f64; 15],
}

impl PotentialDerivatives {
    /// `self + s * other`, component-wise (corner sums and superposition).
    #[inline]
    #[must_use]
    pub fn add_scaled(mut self, other: &Self, s: f64) -> Self {
        for (a, b) in self.d3.iter_mut().zip(&other.d3) {
            *a += s * b;
        }
        for (a, b) in self.d4.iter_mut().zip(&other.d4) {
            *a += s * b;
        }
        self
    }

    #[inline(always)]
    fn get3(&self, a: usize, b: usize) -> f64 {
        self.d3[slot(3, a, b)]
    }

    #[inline(always)]
    fn get4(&self, a: usize, b: usize) -> f64 {
        self.d4[slot(4, a, b)]
    }

    /// Derivative with the index list `idx` (0 = x, 1 = y, 2 = z), of order 3 or 4.
    #[inline(always)]
    fn d(&self, idx: &[usize]) -> f64 {
        let a = idx.iter().filter(|&&i| i == 0).count();
        let b = idx.iter().filter(|&&i| i == 1).count();
        if idx.len() == 3 {
            self.get3(a, b)
        } else {
            self.get4(a, b)
        }
    }
}

/// Third and fourth derivatives of the corner antiderivative $W(X, Y, z)$ of the module table
/// ($\partial^2W/\partial X\partial Y = \Omega = z\ln(R+z) - R$), for $z > 0$:
/// $W_{abc} = \Omega_{a-1,b-1,c}$ for $a, b \ge 1$ and the table entries (and their mirror
/// images) otherwise (Love 1929; Johnson §3.2; derived in the module documentation).
///
/// The result is only meaningful in alternating corner sums
/// $\sum_{i,j}(-1)^{i+j}W(X_i, Y_j, z)$: terms depending on only one of $X$, $Y$ are dropped.
#[inline]
#[must_use]
pub fn corner_derivatives(x: f64, y: f64, z: f64) -> PotentialDerivatives {
    let (x2, y2, z2) = (x * x, y * y, z * z);
    let r = (x2 + y2 + z2).sqrt();
    let rz = r + z;
    let sx2 = x2 + z2;
    let sy2 = y2 + z2;
    let (sx, sy) = (sx2.sqrt(), sy2.sqrt());
    let inv_r = 1.0 / r;
    let inv_rz = 1.0 / rz;
    // Point kernel Omega: first and second derivatives.
    let ox = -x * inv_rz;
    let oy = -y * inv_rz;
    let oz = rz.ln();
    let c2 = inv_r * inv_rz * inv_rz;
    let oxx = -(y2 + z2 + r * z) * c2;
    let oyy = -(x2 + z2 + r * z) * c2;
    let oxy = x * y * c2;
    let oxz = x * inv_r * inv_rz;
    let oyz = y * inv_r * inv_rz;
    let ozz = inv_r;
    // asinh(Y/s_x) and asinh(X/s_y); s > 0 for z > 0.
    let ay = (y / sx).asinh();
    let ax = (x / sy).asinh();
    // R - z = (X^2 + Y^2)/(R + z), without cancellation.
    let rmz = (x2 + y2) * inv_rz;
    // At X = Y = 0 (below a corner) both are 0/0 with limit 0.
    let (w201, w021) = if x2 + y2 == 0.0 {
        (0.0, 0.0)
    } else {
        ((x * y * rmz / (x2 * r + z * y2)).atan(), (x * y * rmz / (y2 * r + z * x2)).atan())
    };
    let w003 = -(x * y / (z * r)).atan();
    let xyr = x * y * inv_r;
    let mut d = PotentialDerivatives::default();
    // Order 3: (a, b, c) with a + b + c = 3.
    d.d3[slot(3, 3, 0)] = y * inv_rz - ay;
    d.d3[slot(3, 2, 1)] = ox;
    d.d3[slot(3, 2, 0)] = w201;
    d.d3[slot(3, 1, 2)] = oy;
    d.d3[slot(3, 1, 1)] = oz;
    d.d3[slot(3, 1, 0)] = ay;
    d.d3[slot(3, 0, 3)] = x * inv_rz - ax;
    d.d3[slot(3, 0, 2)] = w021;
    d.d3[slot(3, 0, 1)] = ax;
    d.d3[slot(3, 0, 0)] = w003;
    // Order 4.
    d.d4[slot(4, 4, 0)] = -oxy + xyr / sx2;
    d.d4[slot(4, 3, 1)] = oxx;
    d.d4[slot(4, 3, 0)] = y * (r * z - x2) * inv_r * inv_rz / sx2;
    d.d4[slot(4, 2, 2)] = oxy;
    d.d4[slot(4, 2, 1)] = oxz;
    d.d4[slot(4, 2, 0)] = -xyr / sx2;
    d.d4[slot(4, 1, 3)] = oyy;
    d.d4[slot(4, 1, 2)] = oyz;
    d.d4[slot(4, 1, 1)] = ozz;
    d.d4[slot(4, 1, 0)] = -z * y * inv_r / sx2;
    d.d4[slot(4, 0, 4)] = -oxy + xyr / sy2;
    d.d4[slot(4, 0, 3)] = x * (r * z - y2) * inv_r * inv_rz / sy2;
    d.d4[slot(4, 0, 2)] = -xyr / sy2;
    d.d4[slot(4, 0, 1)] = -z * x * inv_r / sy2;
    d.d4[slot(4, 0, 0)] = xyr * (1.0 / sx2 + 1.0 / sy2);
    d
}

/// Derivatives of the rectangle potential $\Phi$ at $(x, y, z)$ as the alternating corner
/// sum $\partial^\alpha\Phi = \sum_{i,j}(-1)^{i+j}\,\partial^\alpha W(X_i, Y_j, z)$ of
/// [`corner_derivatives`] (module documentation; Love 1929).
#[inline]
#[must_use]
pub fn potential_derivatives(r: &Rect, x: f64, y: f64, z: f64) -> PotentialDerivatives {
    let (xa, xb) = (x - r.x1, x - r.x2);
    let (ya, yb) = (y - r.y1, y - r.y2);
    let mut s = corner_derivatives(xa, ya, z);
    s = s.add_scaled(&corner_derivatives(xa, yb, z), -1.0);
    s = s.add_scaled(&corner_derivatives(xb, ya, z), -1.0);
    s.add_scaled(&corner_derivatives(xb, yb, z), 1.0)
}

/// Stress at depth $z$ from the potential derivatives `d` (corner sums of
/// [`corner_derivatives`]) for the uniform traction `t` and Poisson ratio $\nu$ (Love 1929;
/// Johnson eqs 3.6–3.7 and Hooke's law):
/// $$\sigma_{ij} = \frac{1}{4\pi}\left(\partial_jU_i + \partial_iU_j\right) +
/// \frac{\nu}{\pi}\,\delta_{ij}\,\partial_z\psi,$$
/// $$\partial_jU_m = 2q_m\Phi_{zzj} - p\Phi_{zmj} + 2\nu\,\partial_{mj}\psi_1 -
/// z\,\partial_{mj}\psi - \delta_{jz}\partial_m\psi\ (m = x, y),\quad
/// \partial_jU_z = p\Phi_{zzj} + (1-2\nu)\partial_j\psi - z\,\partial_{zj}\psi -
/// \delta_{jz}\partial_z\psi,$$
/// $\psi_1 = q_x\Phi_x + q_y\Phi_y + p\Phi_z$, $\psi = \partial_z\psi_1$.
#[inline]
#[must_use]
pub fn stress_from_potential(nu: f64, z: f64, t: &Traction, d: &PotentialDerivatives) -> Stress3 {
    let tr = [t.qx, t.qy, t.p];
    // psi1_{m j} = sum_t t P(t, m, j) (order 3); psi_{m} = psi1_{m z}; psi_{m j} = sum_t
    // t P(t, m, j, z) (order 4).
    let psi1 = |m: usize, j: usize| -> f64 { (0..3).map(|k| tr[k] * d.d(&[k, m, j])).sum() };
    let psi_1 = |m: usize| psi1(m, 2);
    let psi_2 = |m: usize, j: usize| -> f64 { (0..3).map(|k| tr[k] * d.d(&[k, m, j, 2])).sum() };
    // grad U: g[m][j] = d_j U_m.
    let mut g = [[0.0; 3]; 3];
    for (m, row) in g.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            let dz = if j == 2 { 1.0 } else { 0.0 };
            *v = if m < 2 {
                2.0 * tr[m] * d.d(&[2, 2, j]) - t.p * d.d(&[2, m, j]) + 2.0 * nu * psi1(m, j)
                    - z * psi_2(m, j)
                    - dz * psi_1(m)
            } else {
                t.p * d.d(&[2, 2, j]) + (1.0 - 2.0 * nu) * psi_1(j)
                    - z * psi_2(2, j)
                    - dz * psi_1(2)
            };
        }
    }
    let c = 1.0 / (4.0 * PI);
    let iso = nu / PI * psi_1(2);
    Stress3 {
        xx: c * 2.0 * g[0][0] + iso,
        yy: c * 2.0 * g[1][1] + iso,
        zz: c * 2.0 * g[2][2] + iso,
        xy: c * (g[0][1] + g[1][0]),
        xz: c * (g[0][2] + g[2][0]),
        yz: c * (g[1][2] + g[2][1]),
    }
}

/// Gauss–Legendre nodes and weights on $[-1, 1]$ (orders 3, 4, 6), built once.
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

/// Point-force stress of the traction `t` applied as forces `t * 1` at offset $(X, Y)$:
/// Boussinesq for $p$, Cerruti for $q_x$, Cerruti mirrored $x \leftrightarrow y$ for $q_y$.
#[inline]
fn point_stress(nu: f64, t: &Traction, x: f64, y: f64, z: f64) -> Stress3 {
    let mut s = Stress3::default();
    if t.p != 0.0 {
        s = add(s, boussinesq_stress(nu, t.p, x, y, z), 1.0);
    }
    if t.qx != 0.0 {
        s = add(s, cerruti_stress(nu, t.qx, x, y, z), 1.0);
    }
    if t.qy != 0.0 {
        let c = cerruti_stress(nu, t.qy, y, x, z);
        let m = Stress3 { xx: c.yy, yy: c.xx, zz: c.zz, xy: c.xy, xz: c.yz, yz: c.xz };
        s = add(s, m, 1.0);
    }
    s
}

#[inline(always)]
fn add(a: Stress3, b: Stress3, s: f64) -> Stress3 {
    Stress3 {
        xx: a.xx + s * b.xx,
        yy: a.yy + s * b.yy,
        zz: a.zz + s * b.zz,
        xy: a.xy + s * b.xy,
        xz: a.xz + s * b.xz,
        yz: a.yz + s * b.yz,
    }
}

/// Stress at $(x, y, z)$, $z > 0$, below the rectangle `r` carrying the uniform traction `t`,
/// for Poisson ratio $\nu$: the corner-sum closed form of the module documentation
/// ([`potential_derivatives`] then [`stress_from_potential`]; Love 1929 for $p$, Cerruti's
/// field integrated in closed form for $q_x, q_y$), or beyond
/// [`FAR_FIELD`] element sizes the Gauss–Legendre product rule of the point-force stresses
/// $$\sigma \approx \frac{h_xh_y}{4}\sum_{k,l}w_kw_l\,\sigma^{\text{point}}(x-\xi_k,
/// y-\eta_l, z)$$
/// (Johnson eqs 3.21, 3.87). Unchecked: $z \le 0$ or non-finite input gives non-finite or
/// meaningless output (see [`checked_rect_stress`]).
#[inline]
#[must_use]
pub fn rect_stress(nu: f64, r: &Rect, t: &Traction, x: f64, y: f64, z: f64) -> Stress3 {
    let (hx, hy) = (r.x2 - r.x1, r.y2 - r.y1);
    let (cx, cy) = (0.5 * (r.x1 + r.x2), 0.5 * (r.y1 + r.y2));
    let (dx, dy) = (x - cx, y - cy);
    let d = dx.abs().max(dy.abs()).max(z);
    let h = hx.abs().max(hy.abs());
    if d > FAR_FIELD * h {
        let ratio = d / h;
        let n = if ratio > 200.0 {
            3
        } else if ratio > 40.0 {
            4
        } else {
            6
        };
        let (tn, w) = gauss(n);
        // Point stresses are homogeneous of degree -2: sigma(X) = s^2 sigma(s X), s = 1/d.
        let s = 1.0 / d;
        let mut acc = Stress3::default();
        for (ti, wi) in tn.iter().zip(w) {
            let a = (dx - 0.5 * hx * ti) * s;
            for (tj, wj) in tn.iter().zip(w) {
                let b = (dy - 0.5 * hy * tj) * s;
                acc = add(acc, point_stress(nu, t, a, b, z * s), wi * wj);
            }
        }
        let scale = 0.25 * (hx * s) * (hy * s);
        return add(Stress3::default(), acc, scale);
    }
    stress_from_potential(nu, z, t, &potential_derivatives(r, x, y, z))
}

/// [`rect_stress`] with its domain checked.
///
/// # Errors
/// [`Error::OutOfDomain`] for $\nu \notin (-1, 1/2]$, a non-finite traction or coordinate,
/// a depth $z \le 0$, or a coordinate, depth or rectangle edge beyond $10^{100}$ in magnitude
/// (where the squares of the corner sums would overflow).
pub fn checked_rect_stress(
    nu: f64,
    r: &Rect,
    t: &Traction,
    x: f64,
    y: f64,
    z: f64,
) -> Result<Stress3, Error> {
    Material::new(1.0, nu)?;
    finite("p", t.p)?;
    finite("qx", t.qx)?;
    finite("qy", t.qy)?;
    Rect::new(r.x1, r.x2, r.y1, r.y2)?;
    for (name, v) in [("x", x), ("y", y), ("z", z), ("x1", r.x1), ("x2", r.x2), ("y1", r.y1)] {
        finite(name, v)?;
        if v.abs() > 1e100 {
            return Err(Error::OutOfDomain { name, value: v, allowed: "|value| <= 1e100" });
        }
    }
    if r.y2.abs() > 1e100 {
        return Err(Error::OutOfDomain { name: "y2", value: r.y2, allowed: "|value| <= 1e100" });
    }
    if z <= 0.0 {
        return Err(Error::OutOfDomain { name: "z", value: z, allowed: "z > 0 (depth)" });
    }
    Ok(rect_stress(nu, r, t, x, y, z))
}
