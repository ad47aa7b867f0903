//! The crate's single error type.

/// Everything that can go wrong in `stickslip-traction`.
///
/// Each variant carries the data that explains it, so a caller can print a message that
/// names the offending input and what would have been accepted.
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
    /// A grid would contain no element.
    #[error("the contact grid is empty: {reason}")]
    EmptyGrid {
        /// Why no element was produced.
        reason: &'static str,
    },
    /// Two patches of a multi-patch grid cover the same element.
    #[error("patches {first} and {second} overlap at element centre ({x:e}, {y:e})")]
    OverlappingPatches {
        /// Index of the first patch.
        first: usize,
        /// Index of the second patch.
        second: usize,
        /// x of an element centre covered by both.
        x: f64,
        /// y of an element centre covered by both.
        y: f64,
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
    /// The simplex did not finish within its iteration budget.
    #[error("modified LP stopped after {iterations} pivots without reaching a feasible point (phase-1 objective {objective:e})")]
    IterationLimit {
        /// Pivots performed.
        iterations: usize,
        /// Remaining sum of artificial variables (scaled).
        objective: f64,
    },
    /// Phase 1 ended with artificial variables still positive and no admissible entering
    /// column: the restricted-entry simplex found no complementary solution.
    #[error("modified LP found no complementary feasible solution (phase-1 objective {objective:e} after {iterations} pivots)")]
    Infeasible {
        /// Pivots performed.
        iterations: usize,
        /// Remaining sum of artificial variables (scaled).
        objective: f64,
    },
    /// An iterative solver (the fast solver's Newton iteration) reached its iteration limit
    /// before its residual met the tolerance.
    #[error("{solver} did not converge: relative residual {residual:e} > tolerance {tolerance:e} after {iterations} iterations (raise max_iterations or the tolerance)")]
    NotConverged {
        /// Which solver.
        solver: &'static str,
        /// Iterations performed.
        iterations: usize,
        /// Residual reached (the larger of the complementarity and load residuals).
        residual: f64,
        /// Requested tolerance.
        tolerance: f64,
    },
    /// A dense linear system (the full-stick twist preprocessor) was singular.
    #[error("the full-stick system is not positive definite (pivot {index})")]
    NotPositiveDefinite {
        /// Index of the failing pivot.
        index: usize,
    },
    /// An error from the half-space crate (influence coefficients, Hertz).
    #[error("half-space: {0}")]
    Halfspace(String),
    /// An error from the special-function crate.
    #[error("special function: {0}")]
    Special(String),
    /// An error from the quadrature crate.
    #[error("quadrature: {0}")]
    Quad(String),
}

/// Shorthand for `Result<T, Error>`.
pub type Result<T> = core::result::Result<T, Error>;

/// Check that `value` is finite and strictly positive.
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::OutOfDomain { name, value, allowed: "finite and > 0" })
    }
}

/// Check that `value` is finite and non-negative.
pub(crate) fn non_negative(name: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::OutOfDomain { name, value, allowed: "finite and >= 0" })
    }
}
