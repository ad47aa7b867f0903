//! The crate's single error type.

/// Everything that can go wrong in `stickslip-wheelrail`.
///
/// Profile problems name the file (the name the caller gave with the text) and, where one
/// line is at fault, its line number (1-based). Errors of the solvers below are carried
/// whole, with their own message.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// A profile file cannot be read as its format says.
    #[error("{name}{}: {message}", line_suffix(*line))]
    ProfileFormat {
        /// The file's name (as given by the caller).
        name: String,
        /// The line at fault (1-based), if one is.
        line: Option<usize>,
        /// What is wrong.
        message: String,
    },
    /// A profile was read but fails a check (finite values, enough points, no loops, no
    /// back-steps beyond a near-vertical face, plausible size, the shape of its role).
    #[error("{name}{}: {problem} ({hint})", line_suffix(*line))]
    ProfileCheck {
        /// The file's name.
        name: String,
        /// The line at fault (1-based), if one is.
        line: Option<usize>,
        /// What is wrong, with the numbers found.
        problem: String,
        /// What to do about it.
        hint: String,
    },
    /// A scalar input lies outside its allowed domain.
    #[error("{name} = {value:e} is out of domain: allowed {allowed}")]
    OutOfDomain {
        /// Name of the input (as in the API and the scene keys).
        name: &'static str,
        /// The value that was given.
        value: f64,
        /// Human-readable description of the allowed domain.
        allowed: &'static str,
    },
    /// The track or wheelset cannot be placed as asked (e.g. no gauge face at the gauge
    /// height).
    #[error("{what} ({hint})")]
    Placement {
        /// What is wrong, with the numbers found.
        what: String,
        /// What to do about it.
        hint: String,
    },
    /// The wheel and the rail never come close: over their common lateral range the
    /// smallest vertical gap is `min_gap` at lateral position `y` (track coordinates, m).
    #[error("the wheel and the rail never come close: {}", if *overlap { format!("the smallest vertical gap is {min_gap:e} m at y = {y:e} m (track coordinates)") } else { "the profiles do not even overlap laterally (no vertical gap to measure)".to_string() })]
    NoContact {
        /// The smallest vertical gap over the common lateral range (m); infinite when the
        /// profiles do not overlap laterally.
        min_gap: f64,
        /// Where (track $y$, m).
        y: f64,
        /// Whether the two profiles overlap laterally at all.
        overlap: bool,
    },
    /// The contact lies where the profiles cannot carry it: on or beyond the wheel's flange
    /// tip (the wheel has climbed the rail), or at an end of a profile's data.
    #[error("{what}: no wheel-rail contact can be solved there (a lateral shift past flange climb, or profiles cut too short; reduce the lateral shift or give longer profiles)")]
    FlangeClimb {
        /// What was found, with the numbers.
        what: String,
    },
    /// The vertical-load iteration did not reach the load.
    #[error("the wheelset height did not converge to the vertical load: relative residual {residual:e} after {iterations} iterations")]
    NotConverged {
        /// Iterations performed.
        iterations: usize,
        /// Relative force residual reached.
        residual: f64,
    },
    /// An error of the closed-form Hertz contact (the load estimate).
    #[error(transparent)]
    Hertz(#[from] stickslip_halfspace::Error),
    /// An error of the lattice (grids).
    #[error(transparent)]
    Lattice(#[from] stickslip_lattice::Error),
    /// An error of the normal solver.
    #[error(transparent)]
    Normal(#[from] stickslip_normal::Error),
    /// An error of the rolling solvers.
    #[error(transparent)]
    Rolling(#[from] stickslip_rolling::Error),
}

fn line_suffix(line: Option<usize>) -> String {
    line.map_or(String::new(), |l| format!(":{l}"))
}

/// Shorthand for `Result<T, Error>`.
pub type Result<T> = core::result::Result<T, Error>;

/// `value` if it is finite and strictly positive, else [`Error::OutOfDomain`].
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::OutOfDomain { name, value, allowed: "finite and > 0" })
    }
}

/// `value` if it is finite, else [`Error::OutOfDomain`].
pub(crate) fn finite(name: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::OutOfDomain { name, value, allowed: "finite" })
    }
}
