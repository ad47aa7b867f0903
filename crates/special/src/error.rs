//! The crate's error type.

/// Why a `checked_` function refused its input.
#[non_exhaustive]
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum Error {
    /// The argument lies outside the function's domain (this includes NaN and poles).
    #[error("{name}: argument {value:e} is out of domain (allowed: {allowed})")]
    OutOfDomain {
        /// Name of the function that refused the argument.
        name: &'static str,
        /// The offending argument.
        value: f64,
        /// Human-readable description of the allowed set.
        allowed: &'static str,
    },
}

/// Shorthand used by the `checked_` twins.
pub(crate) fn out_of_domain(name: &'static str, value: f64, allowed: &'static str) -> Error {
    Error::OutOfDomain { name, value, allowed }
}
