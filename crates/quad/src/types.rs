//! Result and tolerance types shared by every integrator.

use crate::Error;

/// The outcome of a quadrature: value, error estimate and cost.
///
/// `error` is meant as a bound: every integrator in this crate documents how it is obtained and
/// the test battery checks that it is never smaller than the true error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// Approximation to the integral.
    pub value: f64,
    /// Estimate of $|I - \text{value}|$ (absolute).
    pub error: f64,
    /// Number of integrand evaluations spent.
    pub evals: usize,
}

impl Estimate {
    /// Sum of two estimates of disjoint pieces: values and errors add, evaluations add.
    #[must_use]
    pub fn combine(self, other: Estimate) -> Estimate {
        Estimate {
            value: self.value + other.value,
            error: self.error + other.error,
            evals: self.evals + other.evals,
        }
    }

    /// Multiply value and error by a constant factor (e.g. a Jacobian or a sign).
    #[must_use]
    pub fn scaled(self, c: f64) -> Estimate {
        Estimate { value: c * self.value, error: c.abs() * self.error, evals: self.evals }
    }
}

/// A requested accuracy: the answer is accepted when
/// $$|I - Q| \le \max(\text{abs},\ \text{rel}\,|Q|).$$
///
/// The one tolerance type of the workspace: every solver that takes an accuracy request takes
/// a `Tolerance` and states the range it supports (e.g.
/// `stickslip_traction::FastConfig::TOLERANCE_RANGE`), refusing a request outside it with a
/// typed error instead of clamping it. The fields are private: a `Tolerance` is always valid
/// ([`Tolerance::new`], [`Tolerance::relative`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    /// Absolute tolerance, $\ge 0$.
    pub(crate) abs: f64,
    /// Relative tolerance, $\ge 0$.
    pub(crate) rel: f64,
}

impl Tolerance {
    /// Smallest relative tolerance accepted when `abs` is zero: about $4.5\varepsilon$; below
    /// that, rounding in the sum of a quadrature rule alone can exceed the request.
    pub const MIN_REL: f64 = 1e-15;

    /// Validated constructor. Both parts must be finite and non-negative, and at least one must
    /// be positive; if `abs == 0`, `rel` must be at least [`Tolerance::MIN_REL`].
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] naming the offending part.
    pub fn new(abs: f64, rel: f64) -> Result<Self, Error> {
        if !(abs.is_finite() && abs >= 0.0) {
            return Err(Error::OutOfDomain { name: "abs", value: abs, allowed: "finite, >= 0" });
        }
        if !(rel.is_finite() && rel >= 0.0) {
            return Err(Error::OutOfDomain { name: "rel", value: rel, allowed: "finite, >= 0" });
        }
        if abs == 0.0 && rel < Self::MIN_REL {
            return Err(Error::OutOfDomain {
                name: "rel",
                value: rel,
                allowed: ">= 1e-15 when abs = 0",
            });
        }
        Ok(Tolerance { abs, rel })
    }

    /// Purely relative tolerance (validated as in [`Tolerance::new`]).
    ///
    /// # Errors
    /// As [`Tolerance::new`].
    pub fn relative(rel: f64) -> Result<Self, Error> {
        Self::new(0.0, rel)
    }

    /// The absolute part, $\ge 0$.
    #[must_use]
    pub fn abs(&self) -> f64 {
        self.abs
    }

    /// The relative part, $\ge 0$.
    #[must_use]
    pub fn rel(&self) -> f64 {
        self.rel
    }

    /// Absolute error accepted for an answer of size `value`: $\max(\text{abs}, \text{rel}|Q|)$.
    #[must_use]
    pub fn target(&self, value: f64) -> f64 {
        self.abs.max(self.rel * value.abs())
    }

    /// Whether `error` meets this tolerance for an answer `value`.
    #[must_use]
    pub fn accepts(&self, value: f64, error: f64) -> bool {
        error <= self.target(value)
    }
}

impl Default for Tolerance {
    /// $10^{-10}$ relative, no absolute floor.
    fn default() -> Self {
        Tolerance { abs: 0.0, rel: 1e-10 }
    }
}

/// Wrap a plain integrand so that a non-finite value becomes [`Error::NonFinite`].
pub(crate) fn checked<F: FnMut(f64) -> f64>(mut f: F) -> impl FnMut(f64) -> Result<f64, Error> {
    move |x| {
        let v = f(x);
        if v.is_finite() {
            Ok(v)
        } else {
            Err(Error::NonFinite { x, value: v })
        }
    }
}

/// Reject NaN ends.
pub(crate) fn check_ends(a: f64, b: f64) -> Result<(), Error> {
    if a.is_nan() || b.is_nan() {
        return Err(Error::InvalidInterval { a, b, reason: "an end is NaN" });
    }
    Ok(())
}

/// Reject infinite or NaN ends, for methods that need a finite interval.
pub(crate) fn check_finite_ends(a: f64, b: f64) -> Result<(), Error> {
    check_ends(a, b)?;
    if !(a.is_finite() && b.is_finite()) {
        return Err(Error::InvalidInterval { a, b, reason: "ends must be finite" });
    }
    Ok(())
}

/// Reject anything but a finite interval with `a < b`.
pub(crate) fn check_ordered(a: f64, b: f64) -> Result<(), Error> {
    check_finite_ends(a, b)?;
    if a >= b {
        return Err(Error::InvalidInterval {
            a,
            b,
            reason: "this method needs a < b (its weight is defined through x - a and b - x)",
        });
    }
    Ok(())
}
