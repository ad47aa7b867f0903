//! The three shapes of a planner refusal, shared by the checks, the recipe builder, the
//! body resolution and the cost estimate.

use super::Issue;
use stickslip_scene::ErrorKind;

/// A refusal of `kind` on `key`, with its message and hint.
pub(crate) fn issue(
    kind: ErrorKind,
    key: &'static str,
    message: impl Into<String>,
    hint: impl Into<String>,
) -> Issue {
    Issue::new(kind, key, message).hint(hint)
}

pub(crate) fn unsupported(
    key: &'static str,
    message: impl Into<String>,
    hint: impl Into<String>,
) -> Issue {
    issue(ErrorKind::Unsupported, key, message, hint)
}

/// A physics constructor refused a value that passed the scene's range checks.
pub(crate) fn invalid(key: &'static str, e: impl std::fmt::Display) -> Issue {
    issue(ErrorKind::OutOfRange, key, e.to_string(), "see the allowed range in the message")
}
