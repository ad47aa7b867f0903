//! The crate's error type.

use crate::Estimate;

/// Everything that can go wrong in this crate.
///
/// No integrator ever hides a problem: a non-finite integrand value, a tolerance that was not
/// met, or an input outside the domain of a rule is reported through one of these variants.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// An input lies outside the domain where the rule or integrator is defined.
    #[error("{name} = {value} is out of domain (allowed: {allowed})")]
    OutOfDomain {
        /// Name of the offending input.
        name: &'static str,
        /// Its value.
        value: f64,
        /// Human-readable statement of the allowed range.
        allowed: &'static str,
    },
    /// The integration interval is not usable (a NaN end, or an order that the method does not
    /// accept, e.g. $a \ge b$ for a weighted rule whose weight is defined through $b-x$ and $x-a$).
    #[error("invalid interval [{a}, {b}]: {reason}")]
    InvalidInterval {
        /// Lower end as given.
        a: f64,
        /// Upper end as given.
        b: f64,
        /// Why it was rejected.
        reason: &'static str,
    },
    /// The integrand returned NaN or an infinity at `x` (a physical abscissa).
    #[error("integrand is not finite at x = {x}: f(x) = {value}")]
    NonFinite {
        /// Abscissa (in the caller's variable) where the value was produced.
        x: f64,
        /// The offending value.
        value: f64,
    },
    /// The requested tolerance was not reached within the allowed work. The best estimate is
    /// carried along, with its (honest, too large) error estimate.
    #[error(
        "not converged: value {} with error estimate {:e} > requested {requested:e} after {} evaluations",
        estimate.value, estimate.error, estimate.evals
    )]
    NotConverged {
        /// Best available estimate.
        estimate: Estimate,
        /// Absolute error that would have been accepted, $\max(\text{abs}, \text{rel}\,|I|)$.
        requested: f64,
    },
    /// Constructing a rule failed (Newton's method did not settle on distinct nodes). This is
    /// a bug guard; it is not expected for valid parameters.
    #[error("construction of the {rule} rule with n = {n} failed")]
    RuleConstruction {
        /// Which rule.
        rule: &'static str,
        /// Requested number of nodes.
        n: usize,
    },
}
