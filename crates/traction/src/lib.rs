//! Tangential traction and microslip of a contact whose pressure is known: stick and slip
//! zones under a tangential force or a twisting moment.
//!
//! * [`closed`]: Mindlin (circle), Cattaneo (ellipse), Mindlin–Deresiewicz (unloading,
//!   hysteresis, energy per cycle) and Lubkin (torsion) closed forms, FORMULAS.md E and G;
//! * [`lp`]: the modified linear program of seed 002, Fig. 3.5;
//! * [`solve`]: tangential force in any direction, or a twisting moment, on a grid, by the
//!   modified LP;
//! * [`fast`]: the fast solver (both traction components free, FFT products, nested start);
//! * [`contract`]: the one grid-solver contract both implement ([`GridSolver`]);
//! * [`history`]: load paths solved step by step from the previous state (fretting loops,
//!   energy per cycle, locked-in traction), on the fast solver.
//!
//! The grids, influence coefficients and FFT operators they work on are those of
//! `stickslip-lattice`; the contact a normal solve finds (`stickslip-normal`) feeds them.
//!
//! ```
//! use stickslip_traction::closed::Mindlin;
//! // Seed 002, Example 1: a = 0.0446 in, P = 2160 lbf, f = 0.1, T = 144 lbf.
//! let m = Mindlin::new(0.0446, 2160.0, 0.1, 144.0).unwrap();
//! // Stick radius a* = a (1 - T/(fP))^(1/3).
//! let want = 0.0446 * (1.0f64 - 144.0 / 216.0).cbrt();
//! assert!((m.stick_radius() - want).abs() < 1e-15);
//! // The traction is zero outside the contact.
//! assert_eq!(m.traction(0.05), 0.0);
//! ```
//!
//! Units: any consistent set (SI, or inch–lbf–psi as in seed 002's examples).
#![cfg_attr(docsrs, feature(doc_auto_cfg))]

pub mod closed;
pub mod contract;
pub mod error;
pub mod fast;
pub mod history;
pub mod lp;
pub mod solve;

pub use contract::{
    FastSolver, GridProblem, GridSolution, GridSolver, Load, LoadKind, ModifiedLp, SolverInfo,
};
pub use error::{Error, Result};
pub use fast::{FastConfig, FastProblem, FastSolution, TractionDirections, WarmStart};
pub use history::{HistoryProblem, LoadHistory, LoadPath, PathControl};
pub use lp::{LpConfig, LpSolution};
pub use solve::{
    DirectionAssumption, ElementState, PatchSummary, Regime, SolveInfo, TractionProblem,
    TractionSolution,
};
pub use stickslip_quad::Tolerance;
