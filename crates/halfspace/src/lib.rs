//! Homogeneous, linearly elastic half-plane and half-space solutions for contact mechanics.
//!
//! What is here:
//!
//! - [`adhesion`]: Maugis's solution for a sphere with a Dugdale cohesive zone, between the
//!   JKR and DMT theories (Maugis 1992).
//! - [`material`]: Young's modulus and Poisson ratio, validated; composite modulus
//!   $1/E^* = \sum_i (1-\nu_i^2)/E_i$ and the two-body combinations of FORMULAS.md E and F.
//! - [`flamant`]: the line load on a half-plane (plane strain): stresses and surface
//!   displacements (Johnson, *Contact Mechanics*, eqs 2.15–2.20; FORMULAS.md B).
//! - [`point_load`]: Boussinesq (normal) and Cerruti (tangential) point loads on a half-space:
//!   displacement and stress fields (Johnson ch. 3; FORMULAS.md F).
//! - [`rectangle`]: surface displacement produced by a uniform traction on a rectangle, the
//!   influence coefficients of the traction solvers (Love 1929; FORMULAS.md F).
//! - [`rect_stress`]: the exact subsurface stress tensor below a rectangle carrying a uniform
//!   pressure and uniform shears (Love 1929 for the pressure; Cerruti integrated in closed
//!   form for the shears), the influence coefficients of subsurface stress fields.
//! - [`hertz`]: Hertz contact of cylinders, spheres and general (elliptic) contacts
//!   (Johnson ch. 4; FORMULAS.md B and E).
//! - [`mcewen`]: the subsurface field under a Hertz pressure with proportional shear
//!   (McEwen 1949; Muskhelishvili; FORMULAS.md C).
//! - [`cattaneo2d`]: the 2D Cattaneo–Mindlin partial-slip traction and its field
//!   (FORMULAS.md C).
//!
//! ```
//! use stickslip_halfspace::hertz::HertzLine;
//! use stickslip_halfspace::material::{composite_modulus, Material};
//! // Steel cylinder (R = 20 mm) on steel under P = 100 kN/m.
//! let steel = Material::new(210e9, 0.3).unwrap();
//! let e_star = composite_modulus(&steel, &steel); // E / (2 (1 - nu^2))
//! assert!((e_star - 210e9 / (2.0 * (1.0 - 0.09))).abs() < 1e-3);
//! let h = HertzLine::new(100e3, 0.02, e_star).unwrap();
//! // a^2 = 4 P R / (pi E*), p0 = 2 P / (pi a)
//! let a = (4.0 * 100e3 * 0.02 / (std::f64::consts::PI * e_star)).sqrt();
//! assert!((h.half_width() - a).abs() < 1e-15);
//! assert!((h.max_pressure() - 2.0 * 100e3 / (std::f64::consts::PI * a)).abs() < 1e-6);
//! ```
//!
//! # Conventions (all modules)
//!
//! - Compressive stress is negative. A contact pressure $p \ge 0$ pushes into the body.
//! - **2D** (plane strain): $x$ runs along the surface, $y \ge 0$ is the depth into the body.
//!   A normal line load $P$ pushes into the body (in $+y$); the shear traction $q$ and a
//!   tangential line load $Q$ act on the body in $+x$. At the loaded surface
//!   $\sigma_{yy}(x,0) = -p(x)$ and $\sigma_{xy}(x,0) = -q(x)$ (the surface's outward normal is
//!   $-y$).
//! - **3D**: $x, y$ span the surface, $z \ge 0$ is the depth into the body; normal loads push in
//!   $+z$, tangential loads act on the body in $+x$ (or $+y$). Displacements are positive along
//!   the axes, so $u_z > 0$ means the surface sinks into the body.
//! - Displacements are those of **one body** unless a function says otherwise; for two bodies
//!   add the compliances (see [`material`]).
//!
//! The formulas were checked against the corrected specification `FORMULAS.md` (sections named
//! in each item's documentation); that file is right where a seed paper disagrees.

pub mod adhesion;
pub mod cattaneo2d;
pub mod error;
pub mod flamant;
pub mod hertz;
pub mod material;
pub mod mcewen;
pub mod point_load;
pub mod rect_stress;
pub mod rectangle;

pub use error::Error;
pub use material::Material;

/// A plane (2D) stress state $(\sigma_{xx}, \sigma_{yy}, \sigma_{xy})$, compression negative;
/// $x$ along the surface, $y$ depth.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Stress2 {
    /// Direct stress along the surface, $\sigma_{xx}$.
    pub xx: f64,
    /// Direct stress along the depth, $\sigma_{yy}$.
    pub yy: f64,
    /// Shear stress $\sigma_{xy}$.
    pub xy: f64,
}

impl Stress2 {
    /// Component-wise sum `self + other * scale` (superposition of fields).
    #[must_use]
    pub fn add_scaled(self, other: Self, scale: f64) -> Self {
        Self {
            xx: self.xx + scale * other.xx,
            yy: self.yy + scale * other.yy,
            xy: self.xy + scale * other.xy,
        }
    }
}

/// A 3D stress state, compression negative; $x, y$ along the surface, $z$ depth.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Stress3 {
    /// $\sigma_{xx}$.
    pub xx: f64,
    /// $\sigma_{yy}$.
    pub yy: f64,
    /// $\sigma_{zz}$.
    pub zz: f64,
    /// $\sigma_{xy}$.
    pub xy: f64,
    /// $\sigma_{xz}$.
    pub xz: f64,
    /// $\sigma_{yz}$.
    pub yz: f64,
}

/// A 2D displacement $(u_x, u_y)$; $u_y > 0$ points into the body.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Displacement2 {
    /// Along the surface, $u_x$.
    pub x: f64,
    /// Into the body, $u_y$.
    pub y: f64,
}

/// A 3D displacement $(u_x, u_y, u_z)$; $u_z > 0$ points into the body.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Displacement3 {
    /// $u_x$.
    pub x: f64,
    /// $u_y$.
    pub y: f64,
    /// $u_z$ (into the body).
    pub z: f64,
}
