//! The crate's single error type.

/// Everything that can go wrong in `stickslip-lattice`: an input outside its domain, a grid
/// with no cell, overlapping patches, arrays of the wrong length.
///
/// The solver crates above (`stickslip-traction`, `stickslip-normal`, `stickslip-rolling`)
/// convert it into their own error types with the same message.
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
}

/// Shorthand for `Result<T, Error>`.
pub type Result<T> = core::result::Result<T, Error>;

/// `value` if it is finite and strictly positive, else [`Error::OutOfDomain`] naming `name`.
///
/// # Errors
/// As above.
pub fn positive(name: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::OutOfDomain { name, value, allowed: "finite and > 0" })
    }
}

/// `value` if it is finite and non-negative, else [`Error::OutOfDomain`] naming `name`.
///
/// # Errors
/// As above.
pub fn non_negative(name: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::OutOfDomain { name, value, allowed: "finite and >= 0" })
    }
}
