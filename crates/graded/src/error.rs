//! The crate's single error type.

use thiserror::Error as ThisError;

/// Everything that can go wrong in `stickslip-graded`.
///
/// Variants carry the data that explains them, so a message can say what was passed and what
/// would have been accepted.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq, ThisError)]
pub enum Error {
    /// A scalar input lies outside the set the formula is defined on.
    #[error("{name} = {value} is out of domain (allowed: {allowed})")]
    OutOfDomain {
        /// Name of the argument, e.g. `"k"`.
        name: &'static str,
        /// The value that was passed.
        value: f64,
        /// Human-readable description of the admissible set.
        allowed: &'static str,
    },
    /// The Poisson ratio makes $\beta^2 = (1+k)(1-(1+k)\nu)/(1-\nu)$ non-positive, so the
    /// power-law field of FORMULAS.md A1 does not exist.
    #[error("nu = {nu} gives a non-real beta for k = {k} (allowed: -1 < nu < 1/(1+k) = {limit})")]
    BetaNotReal {
        /// Poisson ratio passed.
        nu: f64,
        /// Grading exponent passed.
        k: f64,
        /// The bound $1/(1+k)$ that `nu` must stay below.
        limit: f64,
    },
    /// The absolute indentation $h = a^2/(2Rk)$ has no finite value for the homogeneous
    /// half-plane ($k = 0$): 2D surface displacements are logarithmic. Use the approach
    /// relative to a datum instead (`RigidCylinder::relative_approach`).
    #[error(
        "the absolute indentation h = a^2/(2Rk) is infinite at k = 0; use relative_approach(L) \
         (approach relative to the surface point at distance L)"
    )]
    NoAbsoluteIndentation,
    /// A numerical step from `stickslip-quad` or `stickslip-special` failed.
    #[error("numerical failure in {what}: {detail}")]
    Numerical {
        /// Which computation failed.
        what: &'static str,
        /// The underlying message.
        detail: String,
    },
}

/// Return `Err(OutOfDomain)` unless `ok`.
pub(crate) fn require(
    ok: bool,
    name: &'static str,
    value: f64,
    allowed: &'static str,
) -> Result<(), Error> {
    if ok {
        Ok(())
    } else {
        Err(Error::OutOfDomain { name, value, allowed })
    }
}
