//! The crate's error type.

/// Everything that can go wrong in this crate.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// An input lies outside the domain where the formula holds.
    #[error("{name} = {value} is out of domain (allowed: {allowed})")]
    OutOfDomain {
        /// Name of the offending input.
        name: &'static str,
        /// Its value.
        value: f64,
        /// Human-readable statement of the allowed range.
        allowed: &'static str,
    },
    /// The field point coincides with the point of application of a concentrated load, where
    /// the solution is singular.
    #[error("{what} is singular at the load point ({x}, {y})")]
    Singular {
        /// Which quantity was asked for.
        what: &'static str,
        /// Field point, first coordinate.
        x: f64,
        /// Field point, second coordinate.
        y: f64,
    },
    /// The tangential load exceeds the limiting friction: the contact slides as a whole.
    #[error("tangential load {q} exceeds the friction limit f P = {limit}")]
    GrossSlip {
        /// Requested tangential load.
        q: f64,
        /// Limiting friction force $fP$.
        limit: f64,
    },
    /// Both bodies are rigid, so no contact compliance exists.
    #[error("both bodies are rigid: the composite modulus is infinite")]
    BothRigid,
    /// A quadrature-based reference did not reach its tolerance.
    #[error("{what}: quadrature failed: {message}")]
    Quadrature {
        /// Which quantity was being integrated.
        what: &'static str,
        /// The integrator's report.
        message: String,
    },
}

/// Returns `Err(OutOfDomain)` unless `value` is finite and strictly positive.
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64, Error> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::OutOfDomain { name, value, allowed: "finite and > 0" })
    }
}

/// Returns `Err(OutOfDomain)` unless `value` is finite.
pub(crate) fn finite(name: &'static str, value: f64) -> Result<f64, Error> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::OutOfDomain { name, value, allowed: "finite" })
    }
}
