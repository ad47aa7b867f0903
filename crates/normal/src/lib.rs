//! Normal contact of any surface on a lattice, and its coupling to the tangential contact
//! of dissimilar bodies.
//!
//! * [`solver`]: the pressure, contact area and approach of two elastic half-spaces (or one
//!   against a rigid body) whose initial gap is given cell by cell, free or periodic, under
//!   force or approach control, by constrained conjugate gradients ([`NormalProblem`]);
//!   [`NormalSolution::contact_grid`] hands the contact to the tangential solvers of
//!   `stickslip-traction`;
//! * [`coupled`]: dissimilar bodies, where pressure causes tangential displacement and
//!   shear causes normal displacement (Dundurs' $\beta$): alternating normal and tangential
//!   solves with the cross operators of `stickslip-lattice` ([`CoupledProblem`]).
//!
//! The influence operators themselves ([`NormalOperator`], the cross terms) live in
//! `stickslip-lattice`, shared with the other lattice solvers and the subsurface fields.
//!
//! ```
//! use stickslip_halfspace::Material;
//! use stickslip_normal::{Boundary, NormalLoad, NormalProblem};
//! // A rigid flat square punch (zero gap on a 16 x 16 lattice of 0.1 mm cells) pressed
//! // into steel with 1 kN: the force is carried and every cell is in contact.
//! let gap = vec![0.0; 16 * 16];
//! let steel = Material::new(210e9, 0.3).unwrap();
//! let bodies = [steel, Material::rigid()];
//! let pb = NormalProblem::new(16, 16, (1e-4, 1e-4), &gap, bodies, Boundary::Free).unwrap();
//! let sol = pb.solve(NormalLoad::Force(1e3)).unwrap();
//! assert!((sol.force - 1e3).abs() < 1e-6 * 1e3);
//! assert_eq!(sol.contact_cells, 256);
//! ```
//!
//! Units: SI (m, Pa, N).
#![cfg_attr(docsrs, feature(doc_auto_cfg))]

pub mod coupled;
pub mod error;
pub mod solver;

pub use coupled::{CoupledInfo, CoupledProblem, CoupledSolution};
pub use error::{Error, Result};
pub use solver::{
    Adhesion, AdhesiveSolution, LevelInfo, Nesting, NormalInfo, NormalLoad, NormalProblem,
    NormalSolution, Preconditioner, NEST_MIN_CELLS,
};
pub use stickslip_lattice::{Boundary, CrossOperator, NormalOperator, NormalScratch};
pub use stickslip_quad::Tolerance;
