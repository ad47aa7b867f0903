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
    /// Phase 1 ended with artificial variables still positive and no admissible entering
    /// column: the restricted-entry simplex found no complementary solution.
    #[error("modified LP found no complementary feasible solution (phase-1 objective {objective:e} after {iterations} pivots)")]
    Infeasible {
        /// Pivots performed.
        iterations: usize,
        /// Remaining sum of artificial variables (scaled).
        objective: f64,
    },
    /// An iterative solver reached its iteration budget before its residual met the
    /// tolerance: the fast solver's Newton iteration, or the modified LP's pivot budget
    /// (residual: the phase-1 objective relative to the right-hand side, tolerance: the LP's
    /// feasibility tolerance).
    #[error("{solver} did not converge: relative residual {residual:e} > tolerance {tolerance:e} after {iterations} iterations (raise max_iterations or the tolerance)")]
    NotConverged {
        /// Which solver.
        solver: &'static str,
        /// Iterations performed (Newton steps, or LP pivots).
        iterations: usize,
        /// Residual reached (the fast solver: the larger of the complementarity and load
        /// residuals).
        residual: f64,
        /// Requested tolerance.
        tolerance: f64,
    },
    /// The load is beyond what friction can carry: the bodies slide (gross slip) and there is
    /// no equilibrium. `requested` is the load in the direction that failed, `capacity` what
    /// the contact carries in that direction alone (a force: $\sum_k fP_k$ per component; a
    /// moment: the spin capacity $\sum_k fP_k|\mathbf x_k - \mathbf c|$, or
    /// $\sum_k fP_k\max(g_k, 0)$ under the LP's fixed directions).
    #[error("{load} {requested:e} exceeds the friction capacity {capacity:e}: the bodies slide (gross slip)")]
    CapacityExceeded {
        /// Which load: the force, the moment, or the two together.
        load: crate::contract::LoadKind,
        /// The load asked for (force magnitude or component, or |moment|).
        requested: f64,
        /// The largest load of that kind the contact can carry.
        capacity: f64,
    },
    /// The active set left no stick component to carry the load constraints: the load is at
    /// or just below gross slip (under a force and a moment together, gross slip comes before
    /// either capacity is reached alone), where no partial-slip equilibrium was found.
    #[error("{solver}: no stick component left to carry the {load} at Newton step {iteration} ({free_components} free components): the load is at or near gross slip")]
    NoStickLeft {
        /// Which solver.
        solver: &'static str,
        /// Which load was applied.
        load: crate::contract::LoadKind,
        /// Newton step at which it happened (1-based).
        iteration: usize,
        /// Free traction components left in the Newton system.
        free_components: usize,
    },
    /// A solver was given a tolerance outside the range it supports (stated by each solver as
    /// a `TOLERANCE_RANGE` constant); tolerances are never clamped.
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
    /// The solver does not handle this kind of load (the modified LP: a force and a moment
    /// together).
    #[error("{solver} does not solve a {load} load")]
    UnsupportedLoad {
        /// Which solver.
        solver: &'static str,
        /// The load kind given.
        load: crate::contract::LoadKind,
    },
    /// A corner of a load path cannot be solved (checked before any step): its normal
    /// load is not positive, or its tangential load exceeds what friction carries.
    #[error("load path corner {corner} (0-based): {name} = {value:e}: allowed {allowed}")]
    PathCorner {
        /// The corner (0-based).
        corner: usize,
        /// What was checked.
        name: &'static str,
        /// The value found.
        value: f64,
        /// What is allowed.
        allowed: &'static str,
    },
    /// A step of a load path failed; `source` says why.
    #[error("load path step {step} (0-based): {source}")]
    HistoryStep {
        /// The step (0-based; step 0 is the first corner).
        step: usize,
        /// The step's error.
        source: Box<Error>,
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
    /// An error of the lattice below (grid construction, influence operators), with its own
    /// message.
    #[error(transparent)]
    Lattice(#[from] stickslip_lattice::Error),
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
