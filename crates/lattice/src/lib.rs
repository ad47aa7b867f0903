//! Contact lattices and the influence operators of the elastic half-space on them: what
//! every lattice solver of stickslip (normal, tangential, rolling) and the subsurface fields
//! stand on.
//!
//! * [`grid`]: contact grids of uniform rectangular cells with their normal pressure
//!   ([`ContactGrid`]: one patch, several patches, or the contact cells of a lattice);
//! * [`influence`]: tangential influence coefficients of a cell (the exact uniform-rectangle
//!   formula, FORMULAS.md F, or the seed's point-load approximation) and dense matrices of
//!   them (for the modified LP and as the reference of the FFT operators);
//! * [`operator`]: the FFT convolution operators on a lattice, [`Boundary::Free`] (zero-padded)
//!   or [`Boundary::Periodic`]: tangential ([`TensorConvolution`]), normal
//!   ([`NormalOperator`]) and the normal–tangential cross terms of dissimilar bodies
//!   ([`CrossOperator`]); all share one layout, one FFT size rule and one thread pool;
//! * [`field`]: subsurface stresses under any surface traction on a lattice, FFT per depth
//!   layer (beside `stickslip-halfspace`'s closed-form fields of single loads);
//! * [`roughness`]: self-affine random rough surfaces by Fourier synthesis.
//!
//! ```
//! use stickslip_lattice::ContactGrid;
//! // A Hertz circle of radius 1 mm carrying 100 N, 40 cells across.
//! let grid = ContactGrid::hertz_circle(1e-3, 100.0, 40).unwrap();
//! // The cells' normal forces add up to the load.
//! let total: f64 = grid.normal_force().iter().sum();
//! assert!((total - 100.0).abs() < 1.0);
//! ```
//!
//! Units: any consistent set (SI in practice).
#![cfg_attr(docsrs, feature(doc_auto_cfg))]

pub mod error;
pub mod field;
pub mod grid;
pub mod influence;
pub mod operator;
pub mod roughness;

pub use error::{Error, Result};
pub use grid::{ContactGrid, GridPatch, PatchPressure, Shape};
pub use influence::{Compliance, InfluenceModel};
pub use operator::{
    even_quadrant, fast_size, ConvScratch, CrossOperator, NormalOperator, NormalScratch,
    PeriodicLattice, Precision, ScalarConvolution, ScalarScratch, TensorConvolution, TensorKernel,
};
pub use stickslip_quad::Tolerance;

/// Run `f` on a thread of rayon's global pool and return its result (on a pool thread
/// already: run it in place).
///
/// The lattice operators and the solvers built on them split their loops with rayon. Called
/// from a thread outside the pool, each such loop is handed to the pool and waited for
/// (a lock, a wake-up and a sleep every time); on lattices of a few thousand cells, whose
/// loops take microseconds, that hand-over costs more than the loops. A solver's entry
/// point wraps its whole solve in this function, so that its loops are split by work
/// stealing inside the pool instead: one hand-over per solve.
pub fn on_pool<R: Send>(f: impl FnOnce() -> R + Send) -> R {
    if rayon::current_thread_index().is_some() {
        f()
    } else {
        rayon::scope(|_| f())
    }
}

/// Lateral boundary of a lattice, shared by every operator, solver and field on it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Boundary {
    /// The loaded lattice is all there is: an isolated contact on the half-space, traction
    /// free beyond it (zero-padded, aperiodic convolution; no periodic images).
    #[default]
    Free,
    /// The lattice is one period of a periodic surface: tractions and heights repeat with
    /// its period in $x$ and $y$ (Fourier transfers on the period).
    Periodic,
}
