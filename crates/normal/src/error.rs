//! The crate's single error type.

/// Everything that can go wrong in `stickslip-normal`.
///
/// Errors of the lattice below (a bad grid) and of the tangential solver (inside the
/// Dundurs coupling) are carried whole, with their own message.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// A scalar input lies outside its allowed domain.
    #[error("{name} = {value:e} is out of domain: allowed {allowed}")]
    OutOfDomain {
        /// Name of the input.
        name: &'static str,
        /// The value that was given.
        value: f64,
        /// Human-readable description of the allowed domain.
        allowed: &'static str,
    },
    /// The lattice has no cell.
    #[error("the contact grid is empty: {reason}")]
    EmptyGrid {
        /// Why.
        reason: &'static str,
    },
    /// Two arrays that must have the same length do not.
    #[error("length mismatch for {name}: expected {expected}, got {got}")]
    LengthMismatch {
        /// Name of the array.
        name: &'static str,
        /// Expected length.
        expected: usize,
        /// Actual length.
        got: usize,
    },
    /// The iteration reached its budget before its residual met the tolerance.
    #[error("{solver} did not converge: relative residual {residual:e} > tolerance {tolerance:e} after {iterations} iterations (raise max_iterations or the tolerance)")]
    NotConverged {
        /// Which solver.
        solver: &'static str,
        /// Iterations performed.
        iterations: usize,
        /// Residual reached.
        residual: f64,
        /// Requested tolerance.
        tolerance: f64,
    },
    /// A tolerance outside the range the solver supports (its `TOLERANCE_RANGE`); never
    /// clamped.
    #[error("{solver}: tolerance (abs {abs:e}, rel {rel:e}) outside the supported range: rel in [{}, {}], abs = 0", range.0, range.1)]
    ToleranceOutOfRange {
        /// Which solver.
        solver: &'static str,
        /// Absolute part requested.
        abs: f64,
        /// Relative part requested.
        rel: f64,
        /// Supported relative tolerances, inclusive.
        range: (f64, f64),
    },
    /// The computed contact covers fewer lattice cells than the solver accepts as resolved
    /// ([`crate::NormalProblem::with_min_contact_cells`]): refine the lattice (or raise the
    /// load).
    #[error("the contact covers {cells} lattice cells, fewer than the {minimum} needed to resolve it: refine the lattice (smaller cells) or raise the load")]
    UnresolvedContact {
        /// Contact cells found.
        cells: usize,
        /// The minimum accepted.
        minimum: usize,
    },
    /// The solve would need more memory than allowed
    /// ([`crate::NormalProblem::with_memory_limit`]); refused before anything is planned.
    #[error("a lattice of {cells} cells needs about {needed} bytes to solve, more than the limit of {limit} bytes: use fewer cells (about {fits} fit) or allow more memory")]
    MemoryExceeded {
        /// Cells of the lattice.
        cells: usize,
        /// Bytes the solve would need ([`crate::NormalProblem::memory_bytes`]).
        needed: u64,
        /// The limit given.
        limit: u64,
        /// About how many cells fit in the limit (at the same boundary).
        fits: usize,
    },
    /// Under a hardness cap the lattice carries at most the hardness times its area (every
    /// cell plastic); a force at or above that has no solution.
    #[error("a normal force of {force:e} N cannot be carried under the hardness {hardness:e} Pa: the lattice of {area:e} m^2 carries less than {capacity:e} N even fully plastic (enlarge the lattice, raise the hardness or lower the force)")]
    AboveCapacity {
        /// The force asked for (N).
        force: f64,
        /// The hardness (Pa).
        hardness: f64,
        /// The lattice area (m²).
        area: f64,
        /// hardness x area (N).
        capacity: f64,
    },
    /// An error of the lattice (grid construction, operators).
    #[error(transparent)]
    Lattice(#[from] stickslip_lattice::Error),
    /// An error of the tangential solver inside the Dundurs coupling.
    #[error(transparent)]
    Tangential(#[from] stickslip_traction::Error),
}

/// Shorthand for `Result<T, Error>`.
pub type Result<T> = core::result::Result<T, Error>;

/// `value` if it is finite and strictly positive, else [`Error::OutOfDomain`].
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64> {
    match value.is_finite() && value > 0.0 {
        true => Ok(value),
        false => Err(Error::OutOfDomain { name, value, allowed: "finite and > 0" }),
    }
}

/// Check a tolerance against a solver's supported range of relative tolerances (purely
/// relative: `abs() == 0`).
pub(crate) fn tolerance_in(
    solver: &'static str,
    tolerance: stickslip_quad::Tolerance,
    range: (f64, f64),
) -> Result<f64> {
    let rel = tolerance.rel();
    if tolerance.abs() == 0.0 && (range.0..=range.1).contains(&rel) {
        Ok(rel)
    } else {
        Err(Error::ToleranceOutOfRange { solver, abs: tolerance.abs(), rel, range })
    }
}
