//! The accuracy-versus-time report.
//!
//! For every method and every setting of its accuracy knob (tolerance, nodes, grid size) the
//! report measures, in the same run, the error against a reference that does not share the
//! method's code (closed forms, mpmath tables, identities such as $\int\sigma_y\,dx = P$) and
//! the median wall time of repeated runs ([`std::time::Instant`]; no criterion here). Each
//! method gets a one-line reading computed from its data and a log-log Pareto plot.
//!
//! [`run`] measures, [`write()`] renders `accuracy.md` and `accuracy/<slug>.svg`, and
//! [`parse_errors`] reads the error column of a rendered report back (the CI test compares the
//! quick run with the committed full report where they share settings).

mod methods;
mod plot;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// How much to measure.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// A subset of settings with few repetitions: runs in CI in well under a minute.
    Quick,
    /// Every setting, more repetitions, the largest grids: for `docs/accuracy.md`.
    Full,
}

impl Mode {
    /// `"quick"` or `"full"`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Mode::Quick => "quick",
            Mode::Full => "full",
        }
    }

    /// Timing repetitions for a measurement of about `cost` seconds (the median is reported).
    fn reps(self, cost: f64) -> usize {
        let base = match self {
            Mode::Quick => 3,
            Mode::Full => 7,
        };
        if cost > 1.0 {
            1
        } else if cost > 0.2 {
            base.min(3)
        } else {
            base
        }
    }
}

/// What the accuracy knob of a method is; decides how the reading is phrased.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Knob {
    /// A requested tolerance (smaller is tighter).
    Tolerance,
    /// Nodes of a fixed rule (larger is tighter).
    Nodes,
    /// Elements across a contact grid (larger is finer; element size $h \propto 1/n$).
    GridSize,
    /// No knob: the method runs to machine precision.
    Fixed,
}

/// One setting of a method's accuracy knob and what it bought.
#[derive(Debug, Clone, PartialEq)]
pub struct Setting {
    /// Short label, unique within the method (e.g. `tol=1e-8`, `n=32`, `N=316`).
    pub label: String,
    /// Numeric value of the knob (tolerance, nodes, elements across; 0 for [`Knob::Fixed`]).
    pub knob: f64,
    /// Measured error against the independent reference (see the method's `error_measure`).
    pub error: f64,
    /// The accuracy the method claims at this setting, if it claims one.
    pub claim: Option<f64>,
    /// Median wall time of one repetition \[s\].
    pub seconds: f64,
    /// The work done in one repetition (evaluations, points, elements).
    pub work: String,
}

impl Setting {
    /// Whether the measured error meets the claim (true when nothing is claimed).
    #[must_use]
    pub fn meets_claim(&self) -> bool {
        self.error.is_finite() && self.claim.is_none_or(|c| self.error <= c)
    }
}

/// The measurements of one method.
#[derive(Debug, Clone, PartialEq)]
pub struct MethodReport {
    /// Identifier: the plot's file stem and the section key of `accuracy.md`.
    pub slug: &'static str,
    /// Title.
    pub title: &'static str,
    /// Kind of accuracy knob.
    pub knob: Knob,
    /// What the error is measured against.
    pub reference: String,
    /// How the error is computed.
    pub error_measure: String,
    /// Where the claim comes from.
    pub claim_source: String,
    /// One row per knob setting, loosest first.
    pub settings: Vec<Setting>,
    /// One-line reading of the trade-off, computed from `settings`.
    pub reading: String,
}

/// The whole report.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// Mode it was measured in.
    pub mode: Mode,
    /// Per-method measurements.
    pub methods: Vec<MethodReport>,
    /// Methods or settings that could not be measured (not in the tree, or the method
    /// returned an error), with the reason.
    pub missing: Vec<String>,
    /// Wall time of the whole run \[s\].
    pub seconds: f64,
}

impl Report {
    /// Every setting whose error does not meet its claim, as `slug/label: error > claim`.
    #[must_use]
    pub fn violations(&self) -> Vec<String> {
        let mut v = Vec::new();
        for m in &self.methods {
            for s in &m.settings {
                if !s.meets_claim() {
                    v.push(format!(
                        "{}/{}: error {:e} > claim {:e}",
                        m.slug,
                        s.label,
                        s.error,
                        s.claim.unwrap_or(f64::NAN)
                    ));
                }
            }
        }
        v
    }
}

/// Median wall time of `reps` runs of `f`, with the result of the first run.
pub(crate) fn timed<T>(reps: usize, mut f: impl FnMut() -> T) -> (T, f64) {
    let mut times = Vec::with_capacity(reps.max(1));
    let mut first = None;
    for _ in 0..reps.max(1) {
        let t0 = Instant::now();
        let v = std::hint::black_box(f());
        times.push(t0.elapsed().as_secs_f64());
        if first.is_none() {
            first = Some(v);
        }
    }
    times.sort_by(f64::total_cmp);
    (first.expect("at least one repetition"), times[times.len() / 2])
}

/// Measure every method.
#[must_use]
pub fn run(mode: Mode) -> Report {
    let t0 = Instant::now();
    let mut missing = Vec::new();
    let mut methods = vec![
        methods::quad_adaptive(mode, methods::QuadKind::Kronrod),
        methods::quad_adaptive(mode, methods::QuadKind::TanhSinh),
        methods::quad_legendre(mode),
        methods::graded_stress(mode),
        methods::rolling_solve(mode),
        methods::rolling_stress(mode),
        methods::lp_mindlin(mode),
        methods::fast_mindlin(mode, &mut missing),
        methods::hertz_ellipse(mode),
        methods::rolling3d_exact(mode),
        methods::rolling3d_approx(mode, false),
        methods::rolling3d_approx(mode, true),
    ];
    for m in &mut methods {
        m.reading = reading(m);
    }
    Report { mode, methods, missing, seconds: t0.elapsed().as_secs_f64() }
}

/// Human-readable duration.
#[must_use]
pub fn fmt_time(s: f64) -> String {
    if s < 1e-6 {
        format!("{:.0} ns", s * 1e9)
    } else if s < 1e-3 {
        format!("{:.1} µs", s * 1e6)
    } else if s < 1.0 {
        format!("{:.2} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

/// Least-squares slope of `ys` against `xs`.
fn slope(xs: &[f64], ys: &[f64]) -> f64 {
    let n = xs.len() as f64;
    let (mx, my) = (xs.iter().sum::<f64>() / n, ys.iter().sum::<f64>() / n);
    let sxy: f64 = xs.iter().zip(ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    sxy / sxx
}

/// The one-line reading of a method, computed from its settings.
fn reading(m: &MethodReport) -> String {
    let s = &m.settings;
    let Some(first) = s.first() else { return "no data".into() };
    let last = s.last().unwrap_or(first);
    match m.knob {
        Knob::Fixed => format!(
            "one setting (runs to machine precision): error {:.1e} in {} ({})",
            first.error,
            fmt_time(first.seconds),
            first.work
        ),
        Knob::Tolerance | Knob::Nodes => {
            // Prefer the example pair (1e-6 vs 1e-10) when both are measured.
            let find = |k: f64| s.iter().find(|x| (x.knob / k - 1.0).abs() < 1e-9);
            let (lo, hi) = match (m.knob, find(1e-6), find(1e-10)) {
                (Knob::Tolerance, Some(a), Some(b)) => (a, b),
                _ => (first, last),
            };
            format!(
                "{} costs {:.1}x what {} costs (error {:.1e} vs {:.1e})",
                hi.label,
                hi.seconds / lo.seconds,
                lo.label,
                hi.error,
                lo.error
            )
        }
        Knob::GridSize => {
            let pts: Vec<&Setting> = s.iter().filter(|x| x.error > 0.0).collect();
            if pts.len() < 2 {
                return "too few grid sizes for a trend".into();
            }
            let lh: Vec<f64> = pts.iter().map(|x| -(x.knob.ln())).collect();
            let le: Vec<f64> = pts.iter().map(|x| x.error.ln()).collect();
            let lt: Vec<f64> = pts.iter().map(|x| x.seconds.ln()).collect();
            let p = slope(&lh, &le);
            let q = -slope(&lh, &lt);
            format!(
                "halving the element size costs {:.1}x and gains {:.1}x (least-squares over {} to \
                 {}; error ~ h^{p:.2}, time ~ h^-{q:.2})",
                2f64.powf(q),
                2f64.powf(p),
                first.label,
                last.label
            )
        }
    }
}

/// Format a number for the tables: 3 significant digits, `-0` normalised.
fn num(v: f64) -> String {
    if v == 0.0 {
        "0".into()
    } else {
        format!("{v:.3e}")
    }
}

/// Render the markdown of a report.
#[must_use]
pub fn markdown(report: &Report) -> String {
    let mut md = String::new();
    let _ = writeln!(md, "# Accuracy versus time\n");
    let _ = writeln!(
        md,
        "Generated by `cargo run --release -p stickslip-benches --bin accuracy` (the same code as \
         `stickslip accuracy`), mode **{}**, total {:.1} s. Errors are measured against \
         references independent of the method (closed forms, mpmath tables, equilibrium); \
         times are the median of repeated runs on the machine that generated the file, so \
         they vary between machines while the errors do not. A setting whose error exceeds \
         its claim is marked **FAIL**.\n",
        report.mode.name(),
        report.seconds
    );
    let _ = writeln!(md, "## Headline trade-offs\n");
    for m in &report.methods {
        let _ = writeln!(md, "- **{}**: {}", m.title, m.reading);
    }
    for miss in &report.missing {
        let _ = writeln!(md, "- not measured: {miss}");
    }
    let _ = writeln!(md);
    for m in &report.methods {
        let _ = writeln!(md, "## {}: {}\n", m.slug, m.title);
        let _ = writeln!(md, "- reference: {}", m.reference);
        let _ = writeln!(md, "- error: {}", m.error_measure);
        let _ = writeln!(md, "- claim: {}", m.claim_source);
        let _ = writeln!(md, "- reading: {}\n", m.reading);
        let _ = writeln!(md, "| setting | error | claim | time | work | status |");
        let _ = writeln!(md, "|---|---|---|---|---|---|");
        for s in &m.settings {
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {} | {} |",
                s.label,
                num(s.error),
                s.claim.map_or("-".to_string(), num),
                fmt_time(s.seconds),
                s.work,
                if s.meets_claim() { "ok" } else { "**FAIL**" }
            );
        }
        let _ = writeln!(md, "\n![{} Pareto plot](accuracy/{}.svg)\n", m.title, m.slug);
    }
    md
}

/// The error column of a rendered report: `(slug, setting label, error)` per table row.
#[must_use]
pub fn parse_errors(markdown: &str) -> Vec<(String, String, f64)> {
    let mut out = Vec::new();
    let mut slug = None;
    for line in markdown.lines() {
        if let Some(h) = line.strip_prefix("## ") {
            slug = h.split_once(':').map(|(s, _)| s.trim().to_string());
            continue;
        }
        let Some(sl) = &slug else { continue };
        if !line.starts_with("| ") || line.starts_with("| setting") {
            continue;
        }
        let cols: Vec<&str> = line.split('|').map(str::trim).collect();
        if cols.len() >= 3 {
            if let Ok(e) = cols[2].parse::<f64>() {
                out.push((sl.clone(), cols[1].to_string(), e));
            }
        }
    }
    out
}

/// Write `accuracy.md` into `out_dir` and one SVG per method into `out_dir/accuracy/`; returns
/// the paths written.
///
/// # Errors
/// Any I/O error, or a plotting error (reported as [`std::io::ErrorKind::Other`]).
pub fn write(report: &Report, out_dir: &Path) -> std::io::Result<Vec<PathBuf>> {
    let plots = out_dir.join("accuracy");
    std::fs::create_dir_all(&plots)?;
    let mut written = Vec::new();
    let md = out_dir.join("accuracy.md");
    std::fs::write(&md, markdown(report))?;
    written.push(md);
    for m in &report.methods {
        let p = plots.join(format!("{}.svg", m.slug));
        plot::pareto(m, &p).map_err(|e| std::io::Error::other(format!("{}: {e}", p.display())))?;
        written.push(p);
    }
    Ok(written)
}
