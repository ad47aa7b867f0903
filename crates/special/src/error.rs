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
    /// The argument is in the domain but the true value's magnitude exceeds `f64::MAX`
    /// (e.g. $\Gamma(x)$ for $x > 171.62$, $I_0(x)$ for $|x| > 713.98$). The plain function
    /// returns $\pm\infty$ there; use the scaled or logarithmic form instead.
    #[error("{name}: the value at {value:e} overflows f64 (use the scaled or logarithmic form)")]
    Overflow {
        /// Name of the function.
        name: &'static str,
        /// The argument.
        value: f64,
    },
}

/// Shorthand used by the `checked_` twins.
pub(crate) fn out_of_domain(name: &'static str, value: f64, allowed: &'static str) -> Error {
    Error::OutOfDomain { name, value, allowed }
}

/// The checked twins' common tail: a finite argument whose value came out infinite overflowed.
pub(crate) fn no_overflow(name: &'static str, x: f64, v: f64) -> Result<f64, Error> {
    if v.is_infinite() && x.is_finite() {
        Err(Error::Overflow { name, value: x })
    } else {
        Ok(v)
    }
}
