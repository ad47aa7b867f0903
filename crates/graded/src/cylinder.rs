//! Rigid cylinder (radius $R$) pressed on the graded half-plane (FORMULAS.md A4; seed 000
//! eqs 15–16, eq 15 corrected) and the slip-zone tangential displacement (FORMULAS.md A5;
//! seed 000 eq 32).

use crate::error::{require, Error};
use crate::load::SurfaceLoad;
use crate::material::GradedMaterial;
use std::f64::consts::{FRAC_PI_2, PI};
use stickslip_special::{gamma, ln_gamma};

/// $\ln B(\tfrac12, \tfrac{3+k}{2})$, so that $P = p_0\,a\,B(\tfrac12,\tfrac{3+k}{2})$.
fn ln_beta_half(k: f64) -> f64 {
    ln_gamma(0.5) + ln_gamma(0.5 * (3.0 + k)) - ln_gamma(2.0 + 0.5 * k)
}

/// The factor $C$ in $a^{2+k} = C\,R P (1-\nu^2)/E_0$ (corrected eq 15, FORMULAS.md A4):
/// $C = \beta\sin(\beta\pi/2)(2+k)\Gamma(\tfrac{3+k+\beta}{2})\Gamma(\tfrac{3+k-\beta}{2})
/// / (2\cos(k\pi/2)\Gamma(\tfrac{3+k}{2})^2)$.
fn half_width_factor(m: &GradedMaterial) -> f64 {
    let (k, b) = (m.k(), m.beta());
    let ln_g = ln_gamma(0.5 * (3.0 + k + b)) + ln_gamma(0.5 * (3.0 + k - b))
        - 2.0 * ln_gamma(0.5 * (3.0 + k));
    b * (b * FRAC_PI_2).sin() * (2.0 + k) * ln_g.exp() / (2.0 * (k * FRAC_PI_2).cos())
}

/// Contact half-width $a$ of a rigid cylinder under load $P$ per unit length (corrected seed
/// 000 eq 15, FORMULAS.md A4):
///
/// $$a^{2+k} = \frac{2RP(1-\nu^2)\,\beta\,(k+2)\sin(\beta\pi/2)\,
///   \Gamma(\tfrac{3+k+\beta}{2})\Gamma(\tfrac{3+k-\beta}{2})\Gamma(\tfrac{3-k}{2})}
///   {\pi E_0 (1-k^2)\,\Gamma(\tfrac{3+k}{2})}.$$
///
/// The seed's eq 15 lacks $\Gamma(\tfrac{3+k-\beta}{2})$. At $k=0$ this is 2D Hertz,
/// $a^2 = 4PR(1-\nu^2)/(\pi E_0)$.
///
/// # Errors
/// [`Error::OutOfDomain`] unless $R > 0$ and $P > 0$ are finite.
pub fn half_width_from_load(m: &GradedMaterial, radius: f64, load: f64) -> Result<f64, Error> {
    require(radius.is_finite() && radius > 0.0, "radius", radius, "0 < R < inf")?;
    require(load.is_finite() && load > 0.0, "load", load, "0 < P < inf")?;
    let c = half_width_factor(m) * radius * (1.0 - m.poisson_ratio() * m.poisson_ratio()) / m.e0();
    Ok(((load.ln() + c.ln()) / (2.0 + m.k())).exp())
}

/// Load per unit length $P$ that produces half-width $a$ (inverse of
/// [`half_width_from_load`], FORMULAS.md A4).
///
/// # Errors
/// [`Error::OutOfDomain`] unless $R > 0$ and $a > 0$ are finite.
pub fn load_from_half_width(m: &GradedMaterial, radius: f64, a: f64) -> Result<f64, Error> {
    require(radius.is_finite() && radius > 0.0, "radius", radius, "0 < R < inf")?;
    require(a.is_finite() && a > 0.0, "a", a, "0 < a < inf")?;
    let c = half_width_factor(m) * radius * (1.0 - m.poisson_ratio() * m.poisson_ratio()) / m.e0();
    Ok(((2.0 + m.k()) * a.ln() - c.ln()).exp())
}

/// A rigid cylinder in frictionless normal contact with the graded half-plane, solved
/// (FORMULAS.md A4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidCylinder {
    mat: GradedMaterial,
    radius: f64,
    a: f64,
    load: f64,
    p0: f64,
}

impl RigidCylinder {
    /// Solve for the contact under load $P$ per unit length: $a$ from the corrected seed 000
    /// eq 15 ([`half_width_from_load`]) and $p_0 = P/(a\,B(\tfrac12,\tfrac{3+k}{2}))$
    /// (FORMULAS.md A4).
    ///
    /// # Errors
    /// As [`half_width_from_load`].
    pub fn from_load(m: &GradedMaterial, radius: f64, load: f64) -> Result<Self, Error> {
        let a = half_width_from_load(m, radius, load)?;
        Ok(Self::build(m, radius, a, load))
    }

    /// Solve for the contact of half-width $a$: $P$ from the corrected seed 000 eq 15
    /// ([`load_from_half_width`]) and $p_0 = P/(a\,B(\tfrac12,\tfrac{3+k}{2}))$
    /// (FORMULAS.md A4).
    ///
    /// # Errors
    /// As [`load_from_half_width`].
    pub fn from_half_width(m: &GradedMaterial, radius: f64, a: f64) -> Result<Self, Error> {
        let load = load_from_half_width(m, radius, a)?;
        Ok(Self::build(m, radius, a, load))
    }

    fn build(m: &GradedMaterial, radius: f64, a: f64, load: f64) -> Self {
        let p0 = load / (a * ln_beta_half(m.k()).exp());
        Self { mat: *m, radius, a, load, p0 }
    }

    /// The material.
    #[must_use]
    pub fn material(&self) -> &GradedMaterial {
        &self.mat
    }
    /// Cylinder radius $R$.
    #[must_use]
    pub fn radius(&self) -> f64 {
        self.radius
    }
    /// Half-width $a$.
    #[must_use]
    pub fn half_width(&self) -> f64 {
        self.a
    }
    /// Load per unit length $P$.
    #[must_use]
    pub fn load(&self) -> f64 {
        self.load
    }

    /// Peak pressure (FORMULAS.md A4):
    /// $p_0 = \dfrac{P\,\Gamma(2+k/2)}{\sqrt\pi\,a\,\Gamma(\tfrac{3+k}{2})}
    ///   = \dfrac{P}{a\,B(\tfrac12,\tfrac{3+k}{2})}$; $k=0$: $2P/(\pi a)$.
    #[must_use]
    pub fn p0(&self) -> f64 {
        self.p0
    }

    /// Pressure $p(x) = p_0(1-x^2/a^2)^{(1+k)/2}$ for $|x| < a$, zero outside
    /// (FORMULAS.md A4).
    #[must_use]
    pub fn pressure(&self, x: f64) -> f64 {
        let t = x / self.a;
        if t.abs() >= 1.0 {
            0.0
        } else {
            self.p0 * ((1.0 - t) * (1.0 + t)).powf(0.5 * (1.0 + self.mat.k()))
        }
    }

    /// The load for [`crate::StressField`] / [`crate::SurfaceDisplacement`]: this pressure
    /// with sliding friction, $p(s) = p_0(1-s^2/a^2)^{(1+k)/2}$, $q = \mu p$ (FORMULAS.md A4,
    /// A5; see [`SurfaceLoad::cylinder`]).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a non-finite friction coefficient $\mu$.
    pub fn surface_load(&self, friction: f64) -> Result<SurfaceLoad, Error> {
        SurfaceLoad::cylinder(self.a, self.p0, self.mat.k(), friction)
    }

    /// Indentation depth below the undisturbed surface at infinity (seed 000 eq 16, exact;
    /// FORMULAS.md A4): $h = a^2/(2Rk)$.
    ///
    /// # Errors
    /// [`Error::NoAbsoluteIndentation`] at $k=0$, where $h$ is infinite; use
    /// [`RigidCylinder::relative_approach`].
    pub fn indentation(&self) -> Result<f64, Error> {
        let k = self.mat.k();
        if k == 0.0 {
            return Err(Error::NoAbsoluteIndentation);
        }
        Ok(self.a * self.a / (2.0 * self.radius * k))
    }

    /// Approach of the cylinder relative to the surface point at distance $L$ from the
    /// centre line, $\delta(L) = h - u_y(L)$, finite for every $k \in [0,1)$.
    ///
    /// Inside the contact ($|L| \le a$) it is $L^2/(2R)$. Outside, with $\ell = |L|/a$, the
    /// pressure integral $\int_{-1}^1 (1-t^2)^{(1+k)/2}(\ell-t)^{-k}dt
    /// = \ell^{-k}B(\tfrac12,\tfrac{3+k}{2})\,{}_2F_1(\tfrac k2,\tfrac{1+k}{2};2+\tfrac k2;\ell^{-2})$
    /// (binomial series of $(\ell-t)^{-k}$ term by term) and $h$ from the spectral relation
    /// (FORMULAS.md A4) give
    ///
    /// $$\delta(L) = \frac{a^2}{2R}\,\frac{1-f}{k},\qquad
    ///   f = \frac{2\cos(k\pi/2)}{\pi(1+k)}B(\tfrac12,\tfrac{3+k}{2})\,\ell^{-k}\,
    ///   {}_2F_1(\tfrac k2,\tfrac{1+k}{2};2+\tfrac k2;\ell^{-2}).$$
    ///
    /// $\ln f$ is assembled from pieces that are each $O(k)$ and computed to relative
    /// accuracy, so $1-f = -\operatorname{expm1}(\ln f)$ keeps its digits as $k\to 0$ (for
    /// $\ell < \sqrt2$ the connection formula of ${}_2F_1$ costs about $\epsilon/k$ relative).
    /// At $k = 0$ the homogeneous (2D Hertz) limit is exact:
    ///
    /// $$\delta_0(L) = \frac{a^2}{2R}\Bigl[\frac{\ell}{\ell+\sqrt{\ell^2-1}} + \operatorname{arccosh}\ell\Bigr] \to \frac{a^2}{2R}\bigl(\ln\tfrac{2L}{a}+\tfrac12\bigr)
    ///   \quad (L\gg a),$$
    ///
    /// from $\int_{-1}^{1}\sqrt{1-t^2}\ln(\ell-t)dt
    /// = \tfrac\pi2[\ell^2-\ell\sqrt{\ell^2-1}+\operatorname{arccosh}\ell-\tfrac12-\ln2]$
    /// (FORMULAS.md A4, B).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for non-finite $L$.
    pub fn relative_approach(&self, datum: f64) -> Result<f64, Error> {
        require(datum.is_finite(), "datum", datum, "finite")?;
        let a = self.a;
        let scale = a * a / (2.0 * self.radius);
        let l = datum.abs() / a;
        if l <= 1.0 {
            return Ok(datum * datum / (2.0 * self.radius));
        }
        let k = self.mat.k();
        if k == 0.0 {
            let s = ((l - 1.0) * (l + 1.0)).sqrt();
            return Ok(scale * (l / (l + s) + (l + s).ln()));
        }
        Ok(scale * one_minus_f(k, l) / k)
    }

    /// Slip-zone tangential displacement from the friction traction $q = \mu p$ alone (seed
    /// 000 eq 32, verified; FORMULAS.md A5):
    ///
    /// $$u_x^{(q)}(x) = \mu\,\frac{(1+k)(1-\nu)}{1-(1+k)\nu}\,h\,\frac{a^2-kx^2}{a^2}
    ///   = \mu\frac{(1+k)^2}{\beta^2}\,h\Bigl(1-\frac{kx^2}{a^2}\Bigr),\quad |x|\le a.$$
    ///
    /// The pressure-induced odd part it omits is [`crate::DisplacementParts::ux_from_p`].
    ///
    /// # Errors
    /// [`Error::NoAbsoluteIndentation`] at $k = 0$ ($h$ infinite);
    /// [`Error::OutOfDomain`] for $|x| > a$ or a non-finite friction coefficient $\mu$.
    pub fn slip_displacement_eq32(&self, x: f64, friction: f64) -> Result<f64, Error> {
        require(friction.is_finite(), "friction", friction, "finite")?;
        require(x.abs() <= self.a, "x", x, "|x| <= a")?;
        let h = self.indentation()?;
        let (k, b) = (self.mat.k(), self.mat.beta());
        Ok(friction * (1.0 + k) * (1.0 + k) / (b * b) * h * (1.0 - k * x * x / (self.a * self.a)))
    }
}

// Digamma and trigamma values used in the small-k expansion of ln Gamma differences.
const PSI_3_2: f64 = 0.036489973978576520559; // psi(3/2) = 2 - gamma - 2 ln 2
const PSI_2: f64 = 0.42278433509846713939; // psi(2) = 1 - gamma
const PSI1_3_2: f64 = 0.93480220054467930942; // psi'(3/2) = pi^2/2 - 4
const PSI1_2: f64 = 0.64493406684822643647; // psi'(2) = pi^2/6 - 1
const PSI2_3_2: f64 = -0.82879664423431999560; // psi''(3/2) = 16 - 14 zeta(3)
const PSI2_2: f64 = -0.40411380631918857080; // psi''(2) = 2 - 2 zeta(3)

/// $\ln\Gamma(\tfrac{3+k}{2}) - \ln\Gamma(\tfrac32) - \ln\Gamma(2+\tfrac k2) + \ln\Gamma(2)$,
/// accurate relative to its size ($O(k)$).
fn ln_gamma_diff(k: f64) -> f64 {
    let e = 0.5 * k;
    if k < 1e-4 {
        e * (PSI_3_2 - PSI_2)
            + e * e / 2.0 * (PSI1_3_2 - PSI1_2)
            + e * e * e / 6.0 * (PSI2_3_2 - PSI2_2)
    } else {
        ln_gamma(1.5 + e) - ln_gamma(1.5) - ln_gamma(2.0 + e)
    }
}

/// Sum of the Gauss series ${}_2F_1(a,b;c;z) - 1$ for $|z| \le 1/2$ (problem-specific helper:
/// geometric convergence, at most a few hundred terms).
fn hyp2f1_minus_one(a: f64, b: f64, c: f64, z: f64) -> f64 {
    let mut term = 1.0;
    let mut sum = 0.0;
    for m in 0..2000 {
        let mf = m as f64;
        term *= (a + mf) * (b + mf) / ((c + mf) * (mf + 1.0)) * z;
        sum += term;
        if term.abs() <= 1e-17 * sum.abs().max(f64::MIN_POSITIVE) {
            break;
        }
    }
    sum
}

/// $\ln F$ with $F = {}_2F_1(\tfrac k2,\tfrac{1+k}{2};2+\tfrac k2;z)$, $0<z<1$.
fn ln_hyp(k: f64, z: f64) -> f64 {
    let (a, b, c) = (0.5 * k, 0.5 * (1.0 + k), 2.0 + 0.5 * k);
    if z <= 0.5 {
        return hyp2f1_minus_one(a, b, c, z).ln_1p();
    }
    // Connection formula z -> 1 - z (c - a - b = (3-k)/2 is not an integer for 0 < k < 1):
    // F = A 2F1(a, b; a+b-c+1; w) + B w^{c-a-b} 2F1(c-a, c-b; c-a-b+1; w), w = 1 - z,
    // with c - a = 2, c - b = 3/2.
    let w = 1.0 - z;
    let cab = 0.5 * (3.0 - k);
    let ln_a = ln_gamma(c) + ln_gamma(cab) - ln_gamma(2.0) - ln_gamma(1.5);
    // Gamma(a+b-c) = Gamma(z0) with z0 = (k-3)/2 in (-3/2, -1): Gamma(z0+2)/(z0 (z0+1)).
    let z0 = 0.5 * (k - 3.0);
    let g_abc = gamma(z0 + 2.0) / (z0 * (z0 + 1.0));
    let bcoef = gamma(c) * g_abc / (gamma(a) * gamma(b));
    let f1 = 1.0 + hyp2f1_minus_one(a, b, a + b - c + 1.0, w);
    let f2 = 1.0 + hyp2f1_minus_one(2.0, 1.5, cab + 1.0, w);
    let acoef_m1 = ln_a.exp_m1();
    // F - 1 = (A - 1) f1 + (f1 - 1) + B w^{cab} f2
    let fm1 = acoef_m1 * f1 + (f1 - 1.0) + bcoef * w.powf(cab) * f2;
    fm1.ln_1p()
}

/// $1 - f(k,\ell)$ of [`RigidCylinder::relative_approach`], $k>0$, $\ell>1$.
fn one_minus_f(k: f64, l: f64) -> f64 {
    // ln f = ln cos(k pi/2) - ln(1+k) + [ln B(1/2,(3+k)/2) - ln(pi/2)] - k ln l + ln F
    let s = (k * PI / 4.0).sin();
    let ln_cos = (-2.0 * s * s).ln_1p();
    let ln_f = ln_cos - k.ln_1p() + ln_gamma_diff(k) - k * l.ln() + ln_hyp(k, 1.0 / (l * l));
    -ln_f.exp_m1()
}
