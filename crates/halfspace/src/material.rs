//! Isotropic linear-elastic material constants and the two-body combinations.
//!
//! Sources: Johnson, *Contact Mechanics* (1985) eq. 4.22 (composite modulus) and §7.2
//! (tangential compliance); Dundurs (1969) for the coupling parameter; FORMULAS.md sections E
//! (composite modulus, Mindlin compliance) and F (two-body influence coefficients).

use crate::error::{positive, Error};

/// An isotropic linear-elastic material: Young's modulus $E$ and Poisson ratio $\nu$, or a
/// rigid body.
///
/// The shear modulus is $G = E / (2(1+\nu))$. A rigid body has $E = G = \infty$ and contributes
/// nothing to any compliance; its Poisson ratio never enters a formula (it is stored as 0.5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    e: f64,
    nu: f64,
    g: f64,
}

impl Material {
    /// A deformable material with Young's modulus `e` $> 0$ (finite) and Poisson ratio `nu`
    /// in $(-1, 1/2]$ (the range where the strain energy is positive definite).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if `e` is not finite and positive or `nu` is outside
    /// $(-1, 1/2]$.
    pub fn new(e: f64, nu: f64) -> Result<Self, Error> {
        positive("e", e)?;
        if !(nu > -1.0 && nu <= 0.5) {
            return Err(Error::OutOfDomain { name: "nu", value: nu, allowed: "-1 < nu <= 0.5" });
        }
        Ok(Self { e, nu, g: e / (2.0 * (1.0 + nu)) })
    }

    /// A rigid body ($E = G = \infty$).
    #[must_use]
    pub fn rigid() -> Self {
        Self { e: f64::INFINITY, nu: 0.5, g: f64::INFINITY }
    }

    /// Young's modulus $E$ (infinite for a rigid body).
    #[must_use]
    pub fn youngs_modulus(&self) -> f64 {
        self.e
    }

    /// Poisson ratio $\nu$.
    #[must_use]
    pub fn poisson_ratio(&self) -> f64 {
        self.nu
    }

    /// Shear modulus $G = E/(2(1+\nu))$.
    #[must_use]
    pub fn shear_modulus(&self) -> f64 {
        self.g
    }

    /// Whether the body is rigid.
    #[must_use]
    pub fn is_rigid(&self) -> bool {
        self.e.is_infinite()
    }

    /// Normal (plane-strain) compliance of this body, $(1-\nu^2)/E$ (0 when rigid): one term
    /// of $1/E^* = \sum_i(1-\nu_i^2)/E_i$ (Johnson eq. 4.22; FORMULAS.md E).
    #[must_use]
    pub fn normal_compliance(&self) -> f64 {
        if self.is_rigid() {
            0.0
        } else {
            (1.0 - self.nu * self.nu) / self.e
        }
    }

    /// Plane-strain modulus $E/(1-\nu^2)$ of this body alone (the $E^*$ against a rigid
    /// counterpart; Johnson eq. 4.22, FORMULAS.md E). $+\infty$ for a rigid body.
    #[must_use]
    pub fn plane_strain_modulus(&self) -> f64 {
        1.0 / self.normal_compliance()
    }

    /// The per-body constants $(1-\nu)/G$, $\nu/G$, $(1-2\nu)/G$ that multiply the
    /// Boussinesq/Cerruti kernels (all zero when rigid); see [`Compliance`] for the surface
    /// displacements they enter (Johnson eqs 3.22, 3.86; FORMULAS.md F).
    #[must_use]
    pub fn compliance(&self) -> Compliance {
        if self.is_rigid() {
            Compliance { one_minus_nu: 0.0, nu: 0.0, one_minus_two_nu: 0.0 }
        } else {
            Compliance {
                one_minus_nu: (1.0 - self.nu) / self.g,
                nu: self.nu / self.g,
                one_minus_two_nu: (1.0 - 2.0 * self.nu) / self.g,
            }
        }
    }
}

/// Elastic constants in the form the surface Green's functions use:
/// $c_1 = (1-\nu)/G$, $c_2 = \nu/G$, $c_3 = (1-2\nu)/G$.
///
/// For one body (FORMULAS.md F), the surface displacement at offset $(x, y)$, $r=\sqrt{x^2+y^2}$,
/// due to a unit normal force is $u_z = c_1/(2\pi r)$, $u_x = -c_3 x/(4\pi r^2)$, and due to a unit
/// tangential force along $x$ it is $u_x = [c_1/r + c_2 x^2/r^3]/(2\pi)$,
/// $u_y = c_2 x y/(2\pi r^3)$, $u_z = c_3 x/(4\pi r^2)$.
///
/// For the *relative* displacement of two bodies pressed together, [`Compliance::pair`] adds
/// $c_1$ and $c_2$ of both bodies (the two surfaces move apart under the same traction) and
/// *subtracts* $c_3$ (the coupling terms of the two bodies oppose each other; it vanishes for
/// identical materials, Dundurs $\beta = 0$).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Compliance {
    /// $(1-\nu)/G$.
    pub one_minus_nu: f64,
    /// $\nu/G$.
    pub nu: f64,
    /// $(1-2\nu)/G$ (the normal–tangential coupling).
    pub one_minus_two_nu: f64,
}

impl Compliance {
    /// Relative (two-body) constants: $c_1 = \sum_i (1-\nu_i)/G_i$, $c_2 = \sum_i \nu_i/G_i$,
    /// $c_3 = (1-2\nu_1)/G_1 - (1-2\nu_2)/G_2$ (FORMULAS.md F: $A_{kj} = A^{(1)}_{kj} +
    /// A^{(2)}_{kj}$; the coupling is the difference, the numerator of Dundurs' $\beta$, see
    /// [`dundurs_beta`]).
    #[must_use]
    pub fn pair(m1: &Material, m2: &Material) -> Self {
        let (a, b) = (m1.compliance(), m2.compliance());
        Self {
            one_minus_nu: a.one_minus_nu + b.one_minus_nu,
            nu: a.nu + b.nu,
            one_minus_two_nu: a.one_minus_two_nu - b.one_minus_two_nu,
        }
    }
}

/// Composite (contact) modulus $E^*$ of two bodies,
/// $$\frac{1}{E^*} = \frac{1-\nu_1^2}{E_1} + \frac{1-\nu_2^2}{E_2}$$
/// (Johnson eq. 4.22; FORMULAS.md E). A rigid partner contributes zero; two rigid bodies give
/// $+\infty$ (see [`checked_composite_modulus`]).
#[must_use]
pub fn composite_modulus(m1: &Material, m2: &Material) -> f64 {
    1.0 / (m1.normal_compliance() + m2.normal_compliance())
}

/// [`composite_modulus`] that refuses two rigid bodies.
///
/// # Errors
/// [`Error::BothRigid`] if both materials are rigid.
pub fn checked_composite_modulus(m1: &Material, m2: &Material) -> Result<f64, Error> {
    if m1.is_rigid() && m2.is_rigid() {
        Err(Error::BothRigid)
    } else {
        Ok(composite_modulus(m1, m2))
    }
}

/// Two-body tangential compliance factor of Mindlin's problem,
/// $$\sum_i \frac{2-\nu_i}{G_i},$$
/// so that the relative tangential displacement of two spheres in full stick is
/// $\delta = \frac{3 f P}{16 a}\sum_i\frac{2-\nu_i}{G_i}\left[1-(1-T/fP)^{2/3}\right]$
/// (Mindlin 1949; Johnson eq. 7.45 per body; FORMULAS.md E).
#[must_use]
pub fn composite_shear_compliance(m1: &Material, m2: &Material) -> f64 {
    let one = |m: &Material| if m.is_rigid() { 0.0 } else { (2.0 - m.nu) / m.g };
    one(m1) + one(m2)
}

/// Dundurs' second parameter
/// $$\beta = \frac{(1-2\nu_1)/G_1 - (1-2\nu_2)/G_2}{2\left[(1-\nu_1)/G_1 + (1-\nu_2)/G_2\right]},$$
/// which measures the normal–tangential coupling neglected by the uncoupled traction solvers
/// (Dundurs 1969; Johnson §5.1, with body 1 first; FORMULAS.md E, F: the coupling vanishes when
/// $(1-2\nu_1)/G_1 = (1-2\nu_2)/G_2$). Returns NaN for two rigid bodies.
#[must_use]
pub fn dundurs_beta(m1: &Material, m2: &Material) -> f64 {
    let c = Compliance::pair(m1, m2);
    c.one_minus_two_nu / (2.0 * c.one_minus_nu)
}
