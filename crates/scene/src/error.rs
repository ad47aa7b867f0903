//! The scene crate's error: where (file, line, column, key), what, and a hint.

use std::fmt;
use std::path::PathBuf;

/// What kind of problem a scene has.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The file could not be read or written.
    Io,
    /// The text is not valid TOML.
    Syntax,
    /// A key the format does not have, a missing key, or a value of the wrong type.
    Schema,
    /// A quantity with a unit that is unknown or has the wrong dimension.
    Unit,
    /// A value outside what the physics allows (negative radius, nu > 0.5, ...).
    OutOfRange,
    /// A combination that cannot be solved as asked (T > fP with partial slip, ...).
    Impossible,
    /// A valid scene that no solver in this version handles (a graded sphere, ...).
    Unsupported,
    /// A physics routine failed on a scene that passed validation.
    Solver,
    /// The solution was computed but failed its audit (resultants, Coulomb admissibility,
    /// finiteness) and was not written.
    Audit,
}

impl ErrorKind {
    /// The kind in plain words, as a sweep's table (`error_kind`) and the Python package's
    /// errors name it: "io", "syntax", "schema", "unit", "out of range", "impossible",
    /// "unsupported", "solver", "audit".
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            ErrorKind::Io => "io",
            ErrorKind::Syntax => "syntax",
            ErrorKind::Schema => "schema",
            ErrorKind::Unit => "unit",
            ErrorKind::OutOfRange => "out of range",
            ErrorKind::Impossible => "impossible",
            ErrorKind::Unsupported => "unsupported",
            ErrorKind::Solver => "solver",
            ErrorKind::Audit => "audit",
        }
    }

    /// The exit status of the `stickslip` program for an error of this kind, the one place
    /// the mapping lives:
    ///
    /// | status | meaning | kinds |
    /// |---|---|---|
    /// | 0 | written (and audited) | (no error) |
    /// | 1 | I/O or internal error | [`Io`](Self::Io) |
    /// | 2 | refused before solving | [`Syntax`](Self::Syntax), [`Schema`](Self::Schema), [`Unit`](Self::Unit), [`OutOfRange`](Self::OutOfRange), [`Impossible`](Self::Impossible), [`Unsupported`](Self::Unsupported) |
    /// | 3 | solved but not trustworthy | [`Solver`](Self::Solver), [`Audit`](Self::Audit) |
    ///
    /// Usage errors of the command line (clap) also exit 2; a panic (a bug) exits 1.
    #[must_use]
    pub const fn exit_code(self) -> u8 {
        match self {
            ErrorKind::Io => 1,
            ErrorKind::Syntax
            | ErrorKind::Schema
            | ErrorKind::Unit
            | ErrorKind::OutOfRange
            | ErrorKind::Impossible
            | ErrorKind::Unsupported => 2,
            ErrorKind::Solver | ErrorKind::Audit => 3,
        }
    }
}

/// A problem with a scene, located as precisely as the input allows.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct SceneError {
    /// What kind of problem.
    pub kind: ErrorKind,
    /// The scene file, when the scene came from one.
    pub file: Option<PathBuf>,
    /// 1-based line and column of the offending text, when known.
    pub position: Option<(usize, usize)>,
    /// Dotted key, e.g. `substrate.nu`, when the problem belongs to one.
    pub key: Option<String>,
    /// What is wrong.
    pub message: String,
    /// What is allowed, or how to fix it.
    pub hint: Option<String>,
    /// The checks that failed, for an [`ErrorKind::Audit`] error; empty otherwise.
    pub checks: Vec<Check>,
}

/// One check of the audit: what was measured, the limit, and whether it passed. A run's
/// result lists every check it ran; an [`ErrorKind::Audit`] error carries those that failed.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Check {
    /// What is checked, e.g. "coulomb", "normal resultant".
    pub name: &'static str,
    /// What was measured (relative, or in the unit the description states).
    pub value: f64,
    /// The largest value that passes.
    pub limit: f64,
    /// value <= limit.
    pub pass: bool,
    /// What the value means.
    pub what: String,
}

impl SceneError {
    /// The exit status of the `stickslip` program for this error
    /// ([`ErrorKind::exit_code`]).
    #[must_use]
    pub const fn exit_code(&self) -> u8 {
        self.kind.exit_code()
    }

    /// An error of `kind` saying `message`, not yet located.
    pub fn new(kind: ErrorKind, message: impl Into<String>) -> Self {
        Self {
            kind,
            file: None,
            position: None,
            key: None,
            message: message.into(),
            hint: None,
            checks: Vec::new(),
        }
    }

    /// Name the dotted key the error belongs to.
    pub fn key(mut self, key: impl Into<String>) -> Self {
        self.key = Some(key.into());
        self
    }

    /// Say what is allowed, or how to fix it.
    pub fn hint(mut self, hint: impl Into<String>) -> Self {
        self.hint = Some(hint.into());
        self
    }

    /// Attach a byte span of `source`, converted to line and column.
    pub fn at(mut self, source: &str, span: Option<std::ops::Range<usize>>) -> Self {
        if let Some(span) = span {
            self.position = Some(line_col(source, span.start));
        }
        self
    }

    /// Name the scene file, unless a file is already named.
    pub fn in_file(mut self, file: Option<PathBuf>) -> Self {
        if self.file.is_none() {
            self.file = file;
        }
        self
    }
}

/// 1-based (line, column) of byte offset `at` in `source`; columns count characters.
pub(crate) fn line_col(source: &str, at: usize) -> (usize, usize) {
    let at = at.min(source.len());
    let before = &source[..source.floor_char_boundary_compat(at)];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}

trait FloorCharBoundary {
    fn floor_char_boundary_compat(&self, i: usize) -> usize;
}

impl FloorCharBoundary for str {
    fn floor_char_boundary_compat(&self, mut i: usize) -> usize {
        while i > 0 && !self.is_char_boundary(i) {
            i -= 1;
        }
        i
    }
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let file =
            self.file.as_ref().map_or_else(|| "<scene>".to_string(), |p| p.display().to_string());
        match self.position {
            Some((l, c)) => write!(f, "{file}:{l}:{c}: ")?,
            None => write!(f, "{file}: ")?,
        }
        if let Some(k) = &self.key {
            write!(f, "`{k}`: ")?;
        }
        write!(f, "{}", self.message)?;
        if let Some(h) = &self.hint {
            write!(f, "\n  hint: {h}")?;
        }
        Ok(())
    }
}

impl std::error::Error for SceneError {}

/// A refusal found by validation or the planner, before it is located in a file: the full
/// dotted key to change, what is wrong, and a hint. [`crate::Scene::locate`] makes it a
/// [`SceneError`].
#[derive(Debug, Clone, PartialEq)]
pub struct Issue {
    /// What kind of problem.
    pub kind: ErrorKind,
    /// The full dotted key to change.
    pub key: String,
    /// What is wrong.
    pub message: String,
    /// What is allowed, or how to fix it (empty for none).
    pub hint: String,
}

impl Issue {
    /// A refusal of `kind` at `key`, saying `message`, without a hint.
    pub fn new(kind: ErrorKind, key: &str, message: impl Into<String>) -> Self {
        Issue { kind, key: key.to_string(), message: message.into(), hint: String::new() }
    }

    /// Say what is allowed, or how to fix it.
    pub fn hint(mut self, hint: impl Into<String>) -> Self {
        self.hint = hint.into();
        self
    }
}
