//! The crate's error type.

/// Everything that can go wrong in this crate.
///
/// Physical regimes (full slip, full stick, the elastic limit) are *results*, never errors:
/// only inputs outside the model's domain, parameter combinations whose derived scales are not
/// representable in `f64`, and failed stress quadratures are reported here.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// An input lies outside the domain of the model.
    #[error("{name} = {value} is out of domain (allowed: {allowed})")]
    OutOfDomain {
        /// Name of the offending input.
        name: &'static str,
        /// Its value.
        value: f64,
        /// Human-readable statement of the allowed range.
        allowed: &'static str,
    },
    /// A derived quantity (a length scale, a Bessel argument, a result) is not a finite,
    /// normal `f64` for this combination of otherwise valid inputs.
    #[error("{quantity} = {value} is not representable for these parameters")]
    NonFinite {
        /// Which derived quantity.
        quantity: &'static str,
        /// Its value (infinite, NaN, zero or subnormal).
        value: f64,
    },
    /// A stress quadrature (eq 12 or 13) did not reach the requested tolerance.
    #[error("quadrature of the {quantity} at x = {x} failed: {source}")]
    Quadrature {
        /// `"pressure"` or `"shear"`.
        quantity: &'static str,
        /// Abscissa in the contact \[m\].
        x: f64,
        /// The integrator's report (carries the best estimate when not converged).
        source: stickslip_quad::Error,
    },
    /// The contact grid of a 3D rolling problem has no element.
    #[error("the contact grid is empty: {reason}")]
    EmptyGrid {
        /// Why no element was produced.
        reason: &'static str,
    },
    /// An iterative solver of the 3D theory reached its budget before its residual met the
    /// tolerance.
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
    /// An error of the contact lattice (grid, influence operator), with its own message.
    #[error(transparent)]
    Lattice(#[from] stickslip_lattice::Error),
    /// An error of the tangential solver of a transient rolling step (fast partial-slip
    /// solver), with its own message.
    #[error(transparent)]
    Tangential(#[from] stickslip_traction::Error),
}

/// Shorthand for `Result<T, Error>`.
pub type Result<T, E = Error> = core::result::Result<T, E>;

/// Check that `value` is finite and strictly positive.
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64, Error> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::OutOfDomain { name, value, allowed: "finite, > 0" })
    }
}

/// Check that a derived quantity is a finite normal positive number.
pub(crate) fn normal(quantity: &'static str, value: f64) -> Result<f64, Error> {
    if value.is_finite() && value >= f64::MIN_POSITIVE {
        Ok(value)
    } else {
        Err(Error::NonFinite { quantity, value })
    }
}

/// Check that a result is finite.
pub(crate) fn finite(quantity: &'static str, value: f64) -> Result<f64, Error> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NonFinite { quantity, value })
    }
}
