//! Verification of the three source texts: every published figure, table and numerical claim
//! listed in `docs/VERIFICATION.md`, recomputed with the physics crates, set beside
//! the published value, and attributed where the two differ.
//!
//! - [`published`]: the published values, typed once, each with its source.
//! - [`as_published`]: the seeds' formulas as printed, **wrong on purpose**, used only to
//!   measure how far they are from the corrected forms (FORMULAS.md).
//! - [`seed000`], [`seed001`], [`seed002`]: one builder per VERIFICATION.md id, returning a
//!   [`Check`] (rows, claims, tables, figures).
//! - [`record`]: the data model and its text rendering (what the insta snapshots hold), and
//!   the [`Divergence`] list.
//! - [`report`]: [`generate`] writes `docs/verification/` (one Markdown page per seed, one SVG
//!   per figure, `divergences.md`); `src/bin/reproduce.rs` and `stickslip reproduce` call it.
//! - [`fmt`]: our number formatting (10 significant digits, `-0` normalised), so that
//!   snapshots and pages are the same on every machine.
//!
//! Each check is computed once per process and cached ([`check`]), so the snapshot tests and
//! the page generator share the work.

pub mod as_published;
pub mod fmt;
mod plot;
pub mod published;
pub mod record;
pub mod report;
pub mod seed000;
pub mod seed001;
pub mod seed002;

pub use record::{Cause, Check, Claim, Divergence, Figure, Published, Reference, Row, Status};
pub use report::generate;

use std::sync::OnceLock;

/// Errors of the verification crate.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// From the graded-substrate crate.
    #[error("graded: {0}")]
    Graded(#[from] stickslip_graded::Error),
    /// From the traction crate.
    #[error("traction: {0}")]
    Traction(#[from] stickslip_traction::Error),
    /// From `stickslip-lattice` (contact grids).
    #[error(transparent)]
    Lattice(#[from] stickslip_lattice::Error),
    /// From the rolling crate.
    #[error("rolling: {0}")]
    Rolling(#[from] stickslip_rolling::Error),
    /// From the homogeneous half-space crate.
    #[error("halfspace: {0}")]
    Halfspace(#[from] stickslip_halfspace::Error),
    /// A quadrature failed.
    #[error("quadrature: {0}")]
    Quadrature(String),
    /// Writing a page failed.
    #[error("cannot write {path}: {message}")]
    Io {
        /// The file.
        path: String,
        /// The system's message.
        message: String,
    },
    /// Drawing a figure failed.
    #[error("plot {name}: {message}")]
    Plot {
        /// The figure.
        name: String,
        /// The backend's message.
        message: String,
    },
    /// No check has this id.
    #[error("unknown VERIFICATION.md id {id:?}")]
    UnknownId {
        /// The id asked for.
        id: String,
    },
}

/// A check builder.
pub type Builder = fn() -> Result<Check, Error>;

/// Every VERIFICATION.md id with its builder, in the order of VERIFICATION.md.
pub const IDS: [(&str, Builder); 21] = [
    ("T1", seed000::t1),
    ("F4", seed000::f4),
    ("F5", seed000::f5),
    ("F6", seed000::f6),
    ("F7/T2", seed000::f7_t2),
    ("F8", seed000::f8),
    ("F9", seed000::f9),
    ("F10/F11/T3", seed000::f10_f11_t3),
    ("TT", seed000::two_term),
    ("G-W", seed001::g_w),
    ("G-E", seed001::g_e),
    ("G-L", seed001::g_l),
    ("G-S", seed001::g_s),
    ("F3.2", seed002::f3_2),
    ("F3.3/F3.4/Eq3.5", seed002::f3_3_f3_4_eq3_5),
    ("Ex1/F3.6", seed002::ex1),
    ("Ex2/F3.7", seed002::ex2),
    ("Ex3/T3.1/F3.8-F3.11", seed002::ex3),
    ("Ex4/F3.12-F3.15", seed002::ex4),
    ("Ex5/F3.16-F3.21", seed002::ex5),
    ("Tw", seed002::twist),
];

static CACHE: [OnceLock<Result<Check, Error>>; 21] = [const { OnceLock::new() }; 21];

/// The check of a VERIFICATION.md id, computed on first use and cached for the process.
///
/// # Errors
/// [`Error::UnknownId`] for an id not in [`IDS`]; otherwise the error of its builder.
pub fn check(id: &str) -> Result<&'static Check, Error> {
    let i =
        IDS.iter().position(|(k, _)| *k == id).ok_or_else(|| Error::UnknownId { id: id.into() })?;
    CACHE[i].get_or_init(IDS[i].1).as_ref().map_err(Clone::clone)
}

/// All checks, in [`IDS`] order.
///
/// # Errors
/// The first builder error.
pub fn all_checks() -> Result<Vec<&'static Check>, Error> {
    IDS.iter().map(|(id, _)| check(id)).collect()
}

/// The divergence list of all checks.
///
/// # Errors
/// As [`all_checks`].
pub fn all_divergences() -> Result<Vec<Divergence>, Error> {
    Ok(all_checks()?.into_iter().flat_map(record::divergences).collect())
}
