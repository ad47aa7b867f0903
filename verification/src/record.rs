//! The records a check produces: rows (published or closed-form reference beside the computed
//! value), qualitative claims, free tables and figures; and their text rendering, which is
//! what the snapshots hold.

use crate::fmt::{num, num_scaled, rel};
use std::fmt::Write as _;

/// Where a published value or claim comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Source {
    /// Seed file prefix: `"000"`, `"001"` or `"002"`.
    pub seed: &'static str,
    /// Figure, table, example or equation.
    pub place: &'static str,
    /// The words (or printed numbers) it came from, quoted from the OCR text.
    pub words: &'static str,
}

/// How precisely a published number is known.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Resolution {
    /// Printed in the text: known to half a unit of its last printed digit.
    Printed,
    /// Read off a figure or a digitised table: known to this absolute amount.
    Digitised(f64),
}

/// A published value: typed once, with its source.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Published {
    /// The number as printed (e.g. `"0.66196e-4"`).
    pub text: &'static str,
    /// Its value.
    pub value: f64,
    /// How precisely it is known.
    pub resolution: Resolution,
    /// Where it comes from.
    pub source: Source,
}

impl Published {
    /// Absolute half-width of the interval the published number stands for: half a unit of
    /// the last printed digit of [`Published::text`], or the digitising error.
    #[must_use]
    pub fn half_width(&self) -> f64 {
        match self.resolution {
            Resolution::Digitised(d) => d,
            Resolution::Printed => {
                let t = self.text.trim_start_matches(['-', '+']);
                let (mant, exp) = match t.split_once(['e', 'E']) {
                    Some((m, e)) => (m, e.parse::<i32>().unwrap_or(0)),
                    None => (t, 0),
                };
                let decimals = mant.split_once('.').map_or(0, |(_, f)| f.len()) as i32;
                0.5 * 10f64.powi(exp - decimals)
            }
        }
    }
}

/// Why a published value and ours differ (FORMULAS.md, "Errata summary").
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum Cause {
    /// A misprint in the seed (the detail says which).
    Misprint(&'static str),
    /// The seed set every $\Gamma(\cdot)$ to 1 (seed 000 Table 1).
    GammaSetToOne,
    /// Per-body displacement on one side, relative (two-body) on the other.
    PerBodyVsRelative,
    /// Discretisation: a finite grid or a different influence model.
    Discretisation(&'static str),
    /// Truncation of a series (the seed's two-term integration by parts).
    Truncation,
    /// Reading a published figure or contour label.
    Digitisation,
    /// Not reproducible, and why.
    NotReproducible(&'static str),
}

impl Cause {
    /// The one-line attribution.
    #[must_use]
    pub fn line(&self) -> String {
        match self {
            Cause::Misprint(d) => format!("misprint: {d}"),
            Cause::GammaSetToOne => {
                "Gamma set to 1 (the seed took the Gamma function for a constant)".into()
            }
            Cause::PerBodyVsRelative => "per-body vs relative (two-body) displacement".into(),
            Cause::Discretisation(d) => format!("discretisation: {d}"),
            Cause::Truncation => "truncation (first two terms of an integration by parts)".into(),
            Cause::Digitisation => "digitisation (values read off a figure)".into(),
            Cause::NotReproducible(d) => format!("not reproducible: {d}"),
        }
    }
}

/// What a computed value is compared with.
#[derive(Debug, Clone, PartialEq)]
pub enum Reference {
    /// A published number.
    Published(Published),
    /// An independent closed form or identity, with the relative tolerance that counts as
    /// agreement.
    Closed {
        /// Name of the closed form.
        name: String,
        /// Its value.
        value: f64,
        /// Relative tolerance for "agrees".
        tol: f64,
    },
    /// Nothing: a computed value recorded for the reader.
    None,
}

/// One line of a check: a quantity, its reference, our value.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// What is compared.
    pub quantity: String,
    /// The reference.
    pub reference: Reference,
    /// Our value.
    pub computed: f64,
    /// Why they differ, when they do.
    pub cause: Option<Cause>,
    /// Scale below $10^{-12}$ of which the computed value is shown as `0` (rounding or
    /// quadrature residue of a quantity that vanishes exactly); 0 for none.
    pub zero_scale: f64,
}

/// Whether a row agrees with its reference.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// Within the published precision or the stated tolerance.
    Agrees,
    /// Outside it.
    Diverges,
    /// No reference.
    Recorded,
}

impl Row {
    /// A row against a published value.
    #[must_use]
    pub fn published(quantity: impl Into<String>, p: Published, computed: f64) -> Self {
        Self {
            quantity: quantity.into(),
            reference: Reference::Published(p),
            computed,
            cause: None,
            zero_scale: 0.0,
        }
    }
    /// A row against a closed form with relative tolerance `tol`.
    #[must_use]
    pub fn closed(
        quantity: impl Into<String>,
        name: impl Into<String>,
        value: f64,
        computed: f64,
        tol: f64,
    ) -> Self {
        Self {
            quantity: quantity.into(),
            reference: Reference::Closed { name: name.into(), value, tol },
            computed,
            cause: None,
            zero_scale: 0.0,
        }
    }
    /// A computed value without reference.
    #[must_use]
    pub fn value(quantity: impl Into<String>, computed: f64) -> Self {
        Self {
            quantity: quantity.into(),
            reference: Reference::None,
            computed,
            cause: None,
            zero_scale: 0.0,
        }
    }
    /// Attach the cause of a divergence.
    #[must_use]
    pub fn because(mut self, cause: Cause) -> Self {
        self.cause = Some(cause);
        self
    }
    /// Show the computed value as `0` when it is below $10^{-12}$ `scale`.
    #[must_use]
    pub fn zero_below(mut self, scale: f64) -> Self {
        self.zero_scale = scale;
        self
    }
    /// The reference value, if any.
    #[must_use]
    pub fn reference_value(&self) -> Option<f64> {
        match &self.reference {
            Reference::Published(p) => Some(p.value),
            Reference::Closed { value, .. } => Some(*value),
            Reference::None => None,
        }
    }
    /// Relative difference computed/reference − 1 (NaN without reference or for a zero
    /// reference).
    #[must_use]
    pub fn relative(&self) -> f64 {
        match self.reference_value() {
            Some(v) if v != 0.0 => self.computed / v - 1.0,
            _ => f64::NAN,
        }
    }
    /// Agreement status.
    #[must_use]
    pub fn status(&self) -> Status {
        match &self.reference {
            Reference::Published(p) => {
                let ok = (self.computed - p.value).abs() <= p.half_width() * (1.0 + 1e-9);
                if ok {
                    Status::Agrees
                } else {
                    Status::Diverges
                }
            }
            Reference::Closed { value, tol, .. } => {
                let d = (self.computed - value).abs();
                if d <= tol * value.abs() || (*value == 0.0 && d <= *tol) {
                    Status::Agrees
                } else {
                    Status::Diverges
                }
            }
            Reference::None => Status::Recorded,
        }
    }
}

/// A qualitative claim of a seed, decided by numbers.
#[derive(Debug, Clone, PartialEq)]
pub struct Claim {
    /// The claim, in our words.
    pub claim: String,
    /// Where the seed makes it.
    pub source: Source,
    /// Whether it holds in our computation.
    pub holds: bool,
    /// The numbers that decide it.
    pub deciding: String,
    /// What FORMULAS.md says is true, where it says something (asserted by the tests).
    pub expected: Option<bool>,
}

/// A free-form table (header and rows of already formatted cells).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Table {
    /// Caption.
    pub caption: String,
    /// Column names.
    pub header: Vec<String>,
    /// Rows of cells.
    pub rows: Vec<Vec<String>>,
}

/// Drawing style of a series.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// A computed curve.
    Line,
    /// Computed discrete values (grid elements, LP solutions).
    Points,
    /// Published points, overlaid.
    Published,
}

/// One series of a figure.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend label.
    pub label: String,
    /// Drawing style.
    pub style: Style,
    /// The points $(x, y)$.
    pub points: Vec<(f64, f64)>,
}

/// A figure: reproduced as computed curves with published points overlaid.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// File stem, e.g. `"seed000_F4_y0.25a"`.
    pub name: String,
    /// Caption.
    pub caption: String,
    /// Axis labels.
    pub x_label: String,
    /// Axis labels.
    pub y_label: String,
    /// The series.
    pub series: Vec<Series>,
}

/// Everything one VERIFICATION.md id produces.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Check {
    /// The VERIFICATION.md id.
    pub id: &'static str,
    /// Seed prefix.
    pub seed: &'static str,
    /// Title.
    pub title: String,
    /// What was computed and the choices made.
    pub how: Vec<String>,
    /// Rows.
    pub rows: Vec<Row>,
    /// Claims.
    pub claims: Vec<Claim>,
    /// Extra tables.
    pub tables: Vec<Table>,
    /// Figures.
    pub figures: Vec<Figure>,
}

impl Check {
    /// The snapshot text: rows, claims and tables with our number formatting; figures as a
    /// list of their series (the data themselves are in the generated pages).
    #[must_use]
    pub fn render(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "{} (seed {}): {}", self.id, self.seed, self.title);
        for h in &self.how {
            let _ = writeln!(s, "  how: {h}");
        }
        if !self.rows.is_empty() {
            let _ = writeln!(s, "rows: quantity | reference | computed | rel. diff | status");
            for r in &self.rows {
                let _ = writeln!(s, "  {}", row_cells(r).join(" | "));
            }
        }
        for c in &self.claims {
            let _ = writeln!(
                s,
                "claim [{}]{}: {} (seed {} {}) -- {}",
                if c.holds { "holds" } else { "does not hold" },
                match c.expected {
                    Some(true) => ", FORMULAS.md: holds",
                    Some(false) => ", FORMULAS.md: does not hold",
                    None => "",
                },
                c.claim,
                c.source.seed,
                c.source.place,
                c.deciding
            );
        }
        for t in &self.tables {
            let _ = writeln!(s, "table: {}", t.caption);
            let _ = writeln!(s, "  {}", t.header.join(" | "));
            for r in &t.rows {
                let _ = writeln!(s, "  {}", r.join(" | "));
            }
        }
        for f in &self.figures {
            let _ = writeln!(s, "figure {}: {}", f.name, f.caption);
            for se in &f.series {
                let _ = writeln!(s, "  {:?} {} ({} points)", se.style, se.label, se.points.len());
            }
        }
        s
    }
}

/// The formatted cells of a row: quantity, reference, computed, relative difference,
/// status with cause.
#[must_use]
pub fn row_cells(r: &Row) -> Vec<String> {
    let reference = match &r.reference {
        Reference::Published(p) => {
            format!(
                "{} (seed {} {}: \"{}\")",
                p.text, p.source.seed, p.source.place, p.source.words
            )
        }
        Reference::Closed { name, value, .. } => format!("{} ({name})", num(*value)),
        Reference::None => "-".into(),
    };
    let status = match (r.status(), &r.cause) {
        (Status::Agrees, _) => "agrees".to_string(),
        (Status::Recorded, _) => "recorded".to_string(),
        (Status::Diverges, Some(c)) => format!("diverges: {}", c.line()),
        (Status::Diverges, None) => "diverges: UNATTRIBUTED".to_string(),
    };
    let computed =
        if r.zero_scale > 0.0 { num_scaled(r.computed, r.zero_scale) } else { num(r.computed) };
    let relative = if r.zero_scale > 0.0 && r.computed.abs() <= 1e-12 * r.zero_scale {
        rel(f64::NAN)
    } else {
        rel(r.relative())
    };
    vec![r.quantity.clone(), reference, computed, relative, status]
}

/// A divergence between a published value (or a published formula, evaluated) and ours,
/// with its cause.
#[derive(Debug, Clone, PartialEq)]
pub struct Divergence {
    /// VERIFICATION.md id.
    pub id: &'static str,
    /// Quantity.
    pub quantity: String,
    /// The published number as printed with its source, or the published formula's name.
    pub reference: String,
    /// The published value.
    pub published: f64,
    /// Ours.
    pub computed: f64,
    /// The attribution (`None` is a bug the tests catch).
    pub cause: Option<Cause>,
}

/// The divergences of one check: rows that do not agree with their reference.
#[must_use]
pub fn divergences(check: &Check) -> Vec<Divergence> {
    check
        .rows
        .iter()
        .filter(|r| r.status() == Status::Diverges)
        .filter_map(|r| {
            let reference = match &r.reference {
                Reference::Published(p) => {
                    format!("{} (seed {} {})", p.text, p.source.seed, p.source.place)
                }
                Reference::Closed { name, .. } => name.clone(),
                Reference::None => return None,
            };
            Some(Divergence {
                id: check.id,
                quantity: r.quantity.clone(),
                reference,
                published: r.reference_value()?,
                computed: r.computed,
                cause: r.cause.clone(),
            })
        })
        .collect()
}
