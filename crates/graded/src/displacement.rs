//! Surface displacements of the graded half-plane (FORMULAS.md A3; seed 000 eqs 26–27 read
//! with "σ_xx" as the surface shear traction).

use crate::error::{require, Error};
use crate::load::SurfaceLoad;
use crate::material::GradedMaterial;
use crate::panels::{breakpoints, integrate, Grading, RuleSet};
use crate::stress::Accuracy;
use std::f64::consts::FRAC_PI_2;
pub use stickslip_halfspace::Displacement2;

/// The four surface integrals of FORMULAS.md A3 at one point $x$:
/// $\int p|x-s|^{-k}ds$, $\int p\,\mathrm{sgn}(x-s)|x-s|^{-k}ds$ and the same for $q$.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SurfaceIntegrals {
    /// $\int p(s)\,|x-s|^{-k}\,ds$.
    pub p_even: f64,
    /// $\int p(s)\,\mathrm{sgn}(x-s)\,|x-s|^{-k}\,ds$.
    pub p_odd: f64,
    /// $\int q(s)\,|x-s|^{-k}\,ds$.
    pub q_even: f64,
    /// $\int q(s)\,\mathrm{sgn}(x-s)\,|x-s|^{-k}\,ds$.
    pub q_odd: f64,
}

/// The displacement split by cause (FORMULAS.md A3, A5); $u_y > 0$ into the substrate.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DisplacementParts {
    /// $u_y$ from the pressure (even kernel; infinite at $k=0$).
    pub uy_from_p: f64,
    /// $u_y$ from the shear (odd kernel; finite for all $k$).
    pub uy_from_q: f64,
    /// $u_x$ from the pressure (odd kernel; the part seed eq 32 omits, FORMULAS.md A5).
    pub ux_from_p: f64,
    /// $u_x$ from the shear (even kernel; infinite at $k=0$; eq 32 for $q=\mu p$).
    pub ux_from_q: f64,
}

/// $\cos(\beta\pi/2)/k$, finite as $k\to 0$: $\cos(\beta\pi/2) = -\sin(\pi(\beta-1)/2)$ with
/// $\beta - 1 = k(1-2\nu-k\nu)/((1-\nu)(\beta+1))$ (from $\beta^2$ of FORMULAS.md A1).
pub(crate) fn cos_beta_half_pi_over_k(beta: f64, nu: f64, k: f64) -> f64 {
    let bm1_over_k = (1.0 - 2.0 * nu - k * nu) / ((1.0 - nu) * (beta + 1.0));
    let arg = FRAC_PI_2 * k * bm1_over_k;
    let sinc = if arg == 0.0 { 1.0 } else { arg.sin() / arg };
    -FRAC_PI_2 * bm1_over_k * sinc
}

/// Surface displacements of a [`SurfaceLoad`] on a graded half-plane (FORMULAS.md A3):
///
/// $$u_y(x) = \frac{(1-\nu^2)\beta}{k(1+k)E_0}\Bigl[\frac{\sin(\beta\pi/2)}{2I_k}\int p\,|x-s|^{-k}ds - \frac{\cos(\beta\pi/2)}{2J_k}\int q\,\mathrm{sgn}(x-s)|x-s|^{-k}ds\Bigr],$$
/// $$u_x(x) = \frac{1-\nu^2}{kE_0}\Bigl[\frac{\cos(\beta\pi/2)}{2I_k}\int p\,\mathrm{sgn}(x-s)|x-s|^{-k}ds + \frac{\sin(\beta\pi/2)}{2J_k}\int q\,|x-s|^{-k}ds\Bigr],$$
///
/// measured from the undisturbed surface at infinity ($k>0$: they decay like $|x|^{-k}$).
/// The weak singularity $|x-s|^{-k}$ sits in the Jacobi weight of the two panels that meet at
/// $s=x$, so it is integrated exactly; the patch edge factor likewise.
#[derive(Debug, Clone)]
pub struct SurfaceDisplacement {
    load: SurfaceLoad,
    rules: Vec<RuleSet>,
    mat: GradedMaterial,
    grading: Grading,
}

impl SurfaceDisplacement {
    /// Plan the surface displacement of `load` on `material`.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for an empty load; [`Error::Numerical`] if a rule cannot be built.
    pub fn new(
        material: &GradedMaterial,
        load: SurfaceLoad,
        accuracy: Accuracy,
    ) -> Result<Self, Error> {
        require(!load.patches().is_empty(), "load.patches", 0.0, "at least one patch")?;
        let k = material.k();
        let rules = load
            .patches()
            .iter()
            .map(|p| RuleSet::new(accuracy.nodes(), p.exponent(), -k))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Self { load, rules, mat: *material, grading: Grading::default() })
    }

    /// The four integrals of FORMULAS.md A3 at $x$ (any $x$, inside or outside the load),
    /// $\int p(s)|x-s|^{-k}ds$, $\int p(s)\,\mathrm{sgn}(x-s)|x-s|^{-k}ds$ and the same for $q$
    /// (see [`SurfaceIntegrals`]); per patch of centre $c$ and half-width $b$ they are taken in
    /// $s = c + bt$, which gives the factor $b^{1-k}$.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for non-finite $x$.
    pub fn integrals(&self, x: f64) -> Result<SurfaceIntegrals, Error> {
        require(x.is_finite(), "x", x, "finite")?;
        let k = self.mat.k();
        let mut buf = Vec::with_capacity(96);
        let mut out = SurfaceIntegrals::default();
        for (patch, rules) in self.load.patches().iter().zip(&self.rules) {
            let b = patch.half_width();
            let c = patch.centre();
            let xx = (x - c) / b;
            let d_edge = (xx - 1.0).abs().min((xx + 1.0).abs());
            let h0 = if d_edge > 0.0 { d_edge.min(1.0) } else { 1.0 };
            breakpoints(xx, h0, self.grading, &mut buf);
            let profile = patch.profile();
            let [pe, po, qe, qo] = integrate::<4>(rules, xx, &buf, |t, d| {
                let (ph, qh) = profile.eval(c + b * t);
                let sg = d.signum();
                [ph, ph * sg, qh, qh * sg]
            });
            let scale = b.powf(1.0 - k);
            out.p_even += scale * pe;
            out.p_odd += scale * po;
            out.q_even += scale * qe;
            out.q_odd += scale * qo;
        }
        Ok(out)
    }

    /// The displacement at $x$ split by cause, term by term of FORMULAS.md A3 (seed 000 eqs
    /// 26–27), with $C = (1-\nu^2)/E_0$:
    /// $$u_y^{(p)} = \frac{C\beta\sin(\beta\pi/2)}{2I_k\,k(1+k)}\int p\,|x-s|^{-k}ds,\qquad
    ///   u_y^{(q)} = -\frac{C\beta}{1+k}\,\frac{\cos(\beta\pi/2)}{k}\,\frac{1}{2J_k}
    ///   \int q\,\mathrm{sgn}(x-s)|x-s|^{-k}ds,$$
    /// $$u_x^{(p)} = C\,\frac{\cos(\beta\pi/2)}{k}\,\frac{1}{2I_k}\int p\,\mathrm{sgn}(x-s)
    ///   |x-s|^{-k}ds,\qquad
    ///   u_x^{(q)} = \frac{C\sin(\beta\pi/2)}{2J_k\,k}\int q\,|x-s|^{-k}ds.$$
    /// The two parts that stay finite as $k \to 0$
    /// ([`DisplacementParts::uy_from_q`], [`DisplacementParts::ux_from_p`]) use the stable
    /// form of $\cos(\beta\pi/2)/k$; the other two are infinite at $k = 0$ and are returned as
    /// $\pm\infty$ there.
    ///
    /// # Errors
    /// As [`SurfaceDisplacement::integrals`].
    pub fn parts(&self, x: f64) -> Result<DisplacementParts, Error> {
        let ints = self.integrals(x)?;
        let m = &self.mat;
        let (k, nu, beta) = (m.k(), m.poisson_ratio(), m.beta());
        let c1 = (1.0 - nu * nu) / m.e0();
        let sb = (beta * FRAC_PI_2).sin();
        let cbk = cos_beta_half_pi_over_k(beta, nu, k);
        let (i2, j2) = (2.0 * m.i_k(), 2.0 * m.j_k());
        let uy_coef = c1 * beta / (1.0 + k);
        Ok(DisplacementParts {
            uy_from_p: uy_coef * sb / (i2 * k) * ints.p_even,
            uy_from_q: -uy_coef * cbk / j2 * ints.q_odd,
            ux_from_p: c1 * cbk / i2 * ints.p_odd,
            ux_from_q: c1 * sb / (j2 * k) * ints.q_even,
        })
    }

    /// $(u_x, u_y)$ at $x$, absolute (relative to the surface at infinity), for $k > 0$: the
    /// sums $u_x = u_x^{(p)} + u_x^{(q)}$, $u_y = u_y^{(p)} + u_y^{(q)}$ of
    /// [`SurfaceDisplacement::parts`] (FORMULAS.md A3; seed 000 eqs 26–27).
    ///
    /// # Errors
    /// [`Error::NoAbsoluteIndentation`] at $k = 0$ (2D displacements are logarithmic: use
    /// differences, or `stickslip_halfspace`); otherwise as [`SurfaceDisplacement::integrals`].
    pub fn displacement(&self, x: f64) -> Result<Displacement2, Error> {
        if self.mat.k() == 0.0 {
            return Err(Error::NoAbsoluteIndentation);
        }
        let p = self.parts(x)?;
        Ok(Displacement2 { x: p.ux_from_p + p.ux_from_q, y: p.uy_from_p + p.uy_from_q })
    }
}
