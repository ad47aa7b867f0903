//! Power-law graded half-plane, $E(y) = E_0\,y^k$ ($0 \le k < 1$, constant $\nu$, plane
//! strain), after Giannakopoulos & Pallot (2000) and the rigid-roller paper of seed 000,
//! with every formula in the corrected form of `FORMULAS.md` sections A and B.
//!
//! - [`material`]: $\beta$, $I_k$, $J_k$ (eqs 12–14, A1) and [`GradedMaterial`].
//! - [`load`]: surface tractions $p(s)$, $q(s)$ as patches with known edge behaviour, or any
//!   closure.
//! - [`stress`]: subsurface stresses by full integration of the line-load field (A2), with an
//!   accuracy knob, in parallel over points.
//! - [`displacement`]: surface displacements with the weak singularity $|x-s|^{-k}$ in the
//!   quadrature weight (A3), split into the pressure and shear parts (A5).
//! - [`cylinder`]: the rigid cylinder (corrected eq 15, eq 16, A4), the approach relative to a
//!   datum (finite for every $k$, exact homogeneous limit at $k=0$, B), eq 32 (A5).
//!
//! ```
//! use stickslip_graded::{half_width_from_load, load_from_half_width, GradedMaterial};
//! // Seed 000, Table 1: E0 = 1767600 kgf/m^2.1, k = 0.1, nu = 0.3, R = 0.3 m.
//! let m = GradedMaterial::new(1767600.0 * 9.80665, 0.1, 0.3).unwrap();
//! let p = load_from_half_width(&m, 0.3, 0.0178).unwrap();
//! // The two directions of eq 15 invert each other.
//! let a = half_width_from_load(&m, 0.3, p).unwrap();
//! assert!((a - 0.0178).abs() < 1e-15);
//! // P grows as a^(2 + k): doubling a multiplies P by 2^2.1.
//! let p2 = load_from_half_width(&m, 0.3, 2.0 * 0.0178).unwrap();
//! assert!((p2 / p - 2f64.powf(2.1)).abs() < 1e-12);
//! ```
//!
//! # Conventions
//! $x$ along the surface, $y > 0$ depth into the substrate; compression negative; $p>0$
//! pushes into the substrate, $q>0$ acts on it in $+x$; $u_y > 0$ into the substrate. At the
//! surface $\sigma_{yy} = -p$ and $\sigma_{xy} = -q$ (outward normal $-y$). $E_0$ carries units
//! of stress/length$^k$. These are the conventions of `stickslip-halfspace`, whose
//! [`Stress2`] and [`Displacement2`] types are reused.
//!
//! # The homogeneous limit
//! Everything is continuous as $k \to 0$ except the absolute indentation $h = a^2/(2Rk)$ and
//! the even-kernel displacement parts, which diverge physically (2D displacements are
//! logarithmic). Those return [`Error::NoAbsoluteIndentation`] at $k = 0$; use
//! [`RigidCylinder::relative_approach`] instead.

pub mod cylinder;
pub mod displacement;
mod error;
pub mod load;
pub mod material;
mod panels;
pub mod partial_slip;
mod rules;
pub mod stress;

pub use cylinder::{half_width_from_load, load_from_half_width, RigidCylinder};
pub use displacement::{DisplacementParts, SurfaceDisplacement, SurfaceIntegrals};
pub use error::Error;
pub use load::{LoadPatch, Profile, SurfaceLoad, TractionFn};
pub use material::{beta, checked_beta, checked_i_k, checked_j_k, i_k, j_k, GradedMaterial};
pub use stickslip_halfspace::{Displacement2, Stress2};
pub use stickslip_quad::Tolerance;
pub use stress::{Accuracy, StressField, MIN_RELATIVE_DEPTH};
