//! The `stickslip` command-line program.
//!
//! - `stickslip run [SCENE] [--out DIR [--force]] [--json]`: run a scene (the built-in
//!   default scene, seed 000's Table 1 roller, when none is given): plan it (`Plan::new`,
//!   the plan `explain` prints) and execute that plan (`Execute::execute`); write result.json,
//!   CSV, SVG plots and report.html into DIR, replacing it whole (`write_outputs_report`: an existing DIR
//!   that is not a previous result is refused unless `--force`), or print the JSON with
//!   `--json`.
//! - `stickslip explain [SCENE]`: print the plan (effects on and off with reasons, the
//!   technique per effect, the estimated cost) without computing anything.
//! - `stickslip sweep SCENE --vary KEY=VALUES... [--zip] [--points FILE] --out DIR
//!   [--shard I/N]`: a parameter sweep (the cartesian product, or with `--zip` or a points
//!   table the keys in step), every point an independent audited run, into one table (sweep.csv and
//!   sweep.parquet; failed points are rows with their reason); `stickslip merge SHARDS...
//!   --out DIR` merges shard tables, checking that none is missing (`sweep.rs`).
//! - `stickslip reproduce [--out DIR]`: the verification pages (stickslip-verification).
//! - `stickslip accuracy [--quick|--full] [--out DIR]`: the accuracy-versus-time report
//!   (stickslip-benches).
//! - `stickslip new KIND [FILE]`, `stickslip new --list`, `stickslip schema`: a commented
//!   scene to start from, and the JSON Schema editors read (`new.rs`).
//! - `stickslip completions SHELL`, `stickslip man`: shell completions and the manual page
//!   (`completions.rs`).
//!
//! Errors print the scene error (file:line:column, key, message, hint) on stderr; no output
//! file is left behind. Exit status (the mapping is `ErrorKind::exit_code` of the scene
//! crate):
//!
//! | status | meaning |
//! |---|---|
//! | 0 | done: the result was written (and audited); also when the reader of stdout closed it early (`stickslip run --json \| head`), which ends the program quietly |
//! | 1 | I/O or internal error: a scene file or `--out` that cannot be read or written, a full disk, stdout that cannot be written (other than closed), a bug (a panic) |
//! | 2 | refused before solving: TOML syntax, schema, unit, out of range, impossible, unsupported; and command-line usage errors |
//! | 3 | solved but not trustworthy: the solution failed its audit, or a solver failed |

// SceneError carries file, position, key and hint for the user; it is returned once per run.
#![allow(clippy::result_large_err)]

use std::fmt::Write as _;
use std::io::{IsTerminal, Write as _};
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use clap::{CommandFactory, Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
mod sweep;

use stickslip_report::{write_outputs_report, ReportContext, WriteOptions};
use stickslip_run::{Execute, Plan, Progress, RunOptions, SolverOut, Zones};
use stickslip_scene::eng::{eng, eng_scaled};
use stickslip_scene::{Scene, SceneError};

mod completions;
mod new;
mod wrap;

/// The exit statuses, shown by `--help` and `run --help` (a macro so that `concat!` can
/// append them to a subcommand's examples).
macro_rules! exit_codes {
    () => {
        "\
Exit status:
  0  done: the result was written (and audited); also when stdout was closed early
  1  I/O or internal error (unreadable scene, unwritable --out, full disk, a bug)
  2  refused before solving (syntax, schema, unit, out of range, impossible,
     unsupported) or a command-line usage error
  3  solved but not trustworthy (the audit failed, or a solver failed); nothing written"
    };
}

/// The exit statuses.
const EXIT_CODES: &str = exit_codes!();

/// Frictional contact mechanics: run scenes, explain their plan, reproduce the published
/// figures, report accuracy against time.
#[derive(Debug, Parser)]
#[command(name = "stickslip", version, about, after_help = EXIT_CODES)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Run a scene (the built-in default scene when none is given).
    #[command(after_help = concat!(
        "Examples:\n",
        "  stickslip run scenes/hertz_cylinder_cattaneo.toml --out results/hertz\n",
        "      (result.json, CSV, SVG plots and report.html in results/hertz)\n",
        "  stickslip run scenes/sphere_load_cycle.toml --json | head\n\n",
        exit_codes!()
    ))]
    Run {
        /// Scene file (TOML); omit for the seed 000 Table 1 roller.
        scene: Option<PathBuf>,
        /// Write result.json, CSV, SVG plots and report.html into this directory, all or
        /// nothing: the
        /// directory is replaced whole (no stale file of an earlier run stays). An existing
        /// directory that is not a previous stickslip result is refused (see --force).
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// Replace the --out directory even if it holds files that are not a previous
        /// stickslip result (they are deleted).
        #[arg(long, requires = "out")]
        force: bool,
        /// Print result.json to stdout.
        #[arg(long)]
        json: bool,
        /// Refuse a run the planner estimates to take longer than this (seconds). Runs whose
        /// estimated memory exceeds the memory available now are refused too.
        #[arg(long, value_name = "SECONDS", default_value_t = stickslip_run::DEFAULT_TIME_LIMIT_SECONDS, value_parser = positive_seconds)]
        time_limit: f64,
        /// No progress bar and no closing summary on stderr (errors are still printed).
        #[arg(long, short)]
        quiet: bool,
    },
    /// Print the plan of a scene without computing anything.
    #[command(after_help = "Example:\n  stickslip explain scenes/wheel_rail_creepage_spin.toml")]
    Explain {
        /// Scene file (TOML); omit for the built-in default scene.
        scene: Option<PathBuf>,
    },
    /// Run a parameter sweep: the cartesian product of the --vary values (with --zip or
    /// --points: the values taken in step, point by point), each point an independent,
    /// audited run, gathered into one table (CSV and Parquet). A failed point is a row with
    /// its reason; the status is 0 once the table is written.
    #[command(
        after_help = "Example:\n  stickslip sweep scenes/hertz_cylinder_cattaneo.toml --vary load.friction=0.2,0.3,0.4 \\\n      --vary load.tangential=\"0 kN/m:20 kN/m:5\" --out results/sweep\n  stickslip sweep scenes/wheel_rail_manchester_a22.toml \\\n      --points scenes/wheel_rail_manchester_a22_left.csv --out results/a22"
    )]
    Sweep(sweep::SweepArgs),
    /// Merge the tables of a sweep's shards, checking that every point is there once.
    #[command(after_help = "Example:\n  stickslip merge --out results/sweep results/shards")]
    Merge(sweep::MergeArgs),
    /// Regenerate the verification pages (published values against computed ones).
    #[command(after_help = "Example:\n  stickslip reproduce --out /tmp/verification")]
    Reproduce {
        /// Output directory.
        #[arg(long, value_name = "DIR", default_value = "docs/verification")]
        out: PathBuf,
    },
    /// The accuracy-versus-time report.
    #[command(after_help = "Example:\n  stickslip accuracy --quick --out /tmp/accuracy")]
    Accuracy {
        /// The CI subset (well under a minute).
        #[arg(long, conflicts_with = "full")]
        quick: bool,
        /// Every setting, the largest grids (the default).
        #[arg(long)]
        full: bool,
        /// Output directory (accuracy.md and accuracy/*.svg are written into it).
        #[arg(long, value_name = "DIR", default_value = "docs")]
        out: PathBuf,
    },
    /// Write a commented scene to start from (see --list for the kinds).
    #[command(
        after_help = "Examples:\n  stickslip new --list\n  stickslip new sphere my_sphere.toml"
    )]
    New(new::NewArgs),
    /// Print the JSON Schema of the scene format (for editors; see `#:schema`).
    #[command(after_help = "Example:\n  stickslip schema > scene.schema.json")]
    Schema,
    /// Print a shell completion script: stickslip completions bash > ~/.local/share/bash-completion/completions/stickslip
    #[command(
        after_help = "Example:\n  stickslip completions bash > ~/.local/share/bash-completion/completions/stickslip"
    )]
    Completions(completions::CompletionsArgs),
    /// Print the manual page (roff): stickslip man > stickslip.1
    #[command(after_help = "Example:\n  stickslip man > stickslip.1 && man ./stickslip.1")]
    Man,
}

/// Why a command ended without success.
enum Failure {
    /// A scene error (its kind gives the exit status).
    Scene(SceneError),
    /// The reader of stdout closed it: end quietly.
    Closed,
    /// Stdout could not be written (e.g. a full disk).
    Stdout(std::io::Error),
    /// Another failure, with its message and exit status.
    Other(String, u8),
}

impl From<SceneError> for Failure {
    fn from(e: SceneError) -> Self {
        Failure::Scene(e)
    }
}

/// Write `text` to stdout and flush; every write error is handled (never a panic).
fn emit(text: &str) -> Result<(), Failure> {
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes()).and_then(|()| out.flush()).map_err(|e| {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            Failure::Closed
        } else {
            Failure::Stdout(e)
        }
    })
}

/// A line on stderr; a failing stderr is ignored (there is nowhere left to report it).
fn note(text: &str) {
    let _ = writeln!(std::io::stderr(), "{}", wrap::wrap(text, wrap::WIDTH));
}

fn load(scene: Option<&PathBuf>) -> Result<Scene, SceneError> {
    match scene {
        Some(p) => stickslip_run::read_scene_file(p),
        None => Ok(Scene::default_scene()),
    }
}

/// A progress bar that appears only on a terminal and only once a run has lasted a second.
/// Stages that report no intermediate progress (one long solve, e.g. the fast solver) still
/// show: a watcher thread draws the last reported stage once the second has passed, and the
/// bar's spinner keeps ticking.
struct Bar {
    start: Instant,
    bar: Mutex<Option<ProgressBar>>,
    last: Mutex<Option<Progress>>,
    enabled: bool,
}

impl Bar {
    /// A bar that may be drawn (`allowed`: not `--quiet`) when stderr is a terminal.
    fn new(allowed: bool) -> Self {
        Bar {
            start: Instant::now(),
            bar: Mutex::new(None),
            last: Mutex::new(None),
            enabled: allowed && std::io::stderr().is_terminal(),
        }
    }

    fn update(&self, p: Progress) {
        if let Ok(mut l) = self.last.lock() {
            *l = Some(p);
        }
        if !self.enabled || self.start.elapsed() < Duration::from_secs(1) {
            return;
        }
        self.draw(p);
    }

    fn draw(&self, p: Progress) {
        let Ok(mut guard) = self.bar.lock() else { return };
        let bar = guard.get_or_insert_with(|| {
            let b = ProgressBar::new(p.total as u64);
            if let Ok(style) =
                ProgressStyle::with_template("{spinner} {msg:24} [{bar:40}] {pos}/{len} {elapsed}")
            {
                b.set_style(style.progress_chars("=> "));
            }
            b.enable_steady_tick(Duration::from_millis(120));
            b
        });
        bar.set_length(p.total as u64);
        bar.set_position(p.done as u64);
        bar.set_message(p.stage);
    }

    /// Until `done` is set: once a second has passed, draw the last stage reported.
    fn watch(&self, done: &AtomicBool) {
        if !self.enabled {
            return;
        }
        while !done.load(Ordering::Relaxed) {
            std::thread::sleep(Duration::from_millis(50));
            if self.start.elapsed() >= Duration::from_secs(1) {
                let last = self.last.lock().ok().and_then(|l| *l);
                let drawn = self.bar.lock().is_ok_and(|b| b.is_some());
                if !drawn {
                    self.draw(last.unwrap_or(Progress { stage: "running", done: 0, total: 1 }));
                }
                return;
            }
        }
    }

    fn finish(&self) {
        if let Ok(mut g) = self.bar.lock() {
            if let Some(b) = g.take() {
                b.finish_and_clear();
            }
        }
    }
}

/// A time limit: a positive, finite number of seconds.
fn positive_seconds(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        _ => Err(format!("`{s}` is not a positive number of seconds (e.g. 3600)")),
    }
}

fn cmd_run(
    scene: Option<&PathBuf>,
    out: Option<&PathBuf>,
    force: bool,
    json: bool,
    time_limit: f64,
    quiet: bool,
) -> Result<(), Failure> {
    let scene = load(scene)?;
    // The plan `explain` prints; execution follows it and decides nothing again.
    let plan = Plan::new(&scene)?;
    plan.check_machine(&stickslip_run::MachineLimits::detect(time_limit))?;
    let bar = Bar::new(!quiet);
    let cb = |p: Progress| bar.update(p);
    let opts = RunOptions { progress: Some(&cb) };
    let done = AtomicBool::new(false);
    let result = std::thread::scope(|sc| {
        sc.spawn(|| bar.watch(&done));
        let r = plan.execute(&opts);
        done.store(true, Ordering::Relaxed);
        r
    });
    bar.finish();
    let outcome = result?;
    if let Some(dir) = out {
        let w = write_outputs_report(
            &outcome,
            dir,
            WriteOptions { plots: scene.outputs.plots, force },
            ReportContext { scene: &scene, plan: &plan },
        )?;
        for n in &w.notes {
            note(&format!("note: {n}"));
        }
        if !json && !quiet {
            note(&format!(
                "{}: solved in {:.3} s; wrote {} files to {} (open {})",
                outcome.title,
                outcome.solver.seconds,
                w.files.len(),
                w.dir.display(),
                w.dir.join("report.html").display()
            ));
        }
    }
    if json {
        return emit(&(outcome.to_json() + "\n"));
    }
    let mut t = String::new();
    let c = &outcome.contact;
    // 2D (plane strain) loads are per unit length.
    let (fu, mu) = if scene.geometry.is_2d() { ("N/m", "N m/m") } else { ("N", "N m") };
    let _ = writeln!(t, "{}", outcome.title);
    let _ = writeln!(t, "  effects on: {}", outcome.effects.on.join(", "));
    // Engineering units (stickslip_scene::eng); a force or moment below 1e-12 of the run's
    // normal load (times the contact size for moments) is rounding and prints as 0.
    let (fs, ls) = (c.normal_load, c.a.max(c.b));
    let force = |v: f64, u: &str| eng_scaled(v, fs, u);
    let moment = |v: f64, u: &str| eng_scaled(v, fs * ls, u);
    let _ = writeln!(
        t,
        "  contact: a = {}, b = {}, p0 = {}, normal load = {}",
        eng(c.a, "m"),
        eng(c.b, "m"),
        eng(c.p0, "Pa"),
        eng(c.normal_load, fu)
    );
    if let Some(h) = c.indentation {
        let _ = writeln!(t, "  indentation: {}", eng(h, "m"));
    }
    if let Some(a) = c.area {
        let _ = writeln!(t, "  contact area: {}", eng(a, "m²"));
    }
    if let (Some(p), Some(reached)) = (c.pull_off, c.pull_off_reached) {
        if reached {
            let _ = writeln!(t, "  pull-off: {}", eng(p, fu));
        } else {
            let _ = writeln!(t, "  pull-off: not reached (most tensile force {})", eng(p, fu));
        }
    }
    if let Some(lc) = &outcome.load_curve {
        let _ = writeln!(t, "  load curve: {} points (load_curve in result.json)", lc.normal.len());
    }
    let fo = &outcome.forces;
    if let (Some(fx), Some(fy), Some(mz)) = (fo.fx, fo.fy, fo.mz) {
        let _ = writeln!(
            t,
            "  creep forces: Fx = {}, Fy = {}, Mz = {}",
            force(fx, "N"),
            force(fy, "N"),
            moment(mz, "N m")
        );
    } else {
        let _ = writeln!(
            t,
            "  forces: tangential = {}, moment = {}, rolling moment = {}",
            force(fo.tangential, fu),
            moment(fo.moment, mu),
            moment(fo.rolling_moment, mu)
        );
    }
    let _ = writeln!(t, "  {}", zones_line(&outcome.zones, ls));
    let _ = writeln!(t, "  solver: {}", solver_line(&outcome.solver));
    if out.is_none() {
        let _ = writeln!(t, "  (use --out DIR for result.json, CSV and plots, or --json)");
    }
    emit(&t)
}

/// The stick and slip zones in one line: element counts and the stick area fraction for
/// grid solutions, intervals otherwise.
fn zones_line(z: &Zones, scale: f64) -> String {
    match &z.grid {
        Some(g) => format!(
            "stick: {} elements, slip: {} elements, stick area fraction {:.4} (grid of {} contact elements)",
            g.stick,
            g.slip,
            g.stick_area_fraction,
            g.stick + g.slip
        ),
        None => {
            let list = |v: &[[f64; 2]]| -> String {
                if v.is_empty() {
                    "none".to_string()
                } else {
                    v.iter()
                        .map(|i| {
                            let (unit, sc) = if z.coordinate.starts_with("fraction") {
                                ("", 1.0)
                            } else {
                                ("m", scale)
                            };
                            format!("[{}, {}]", eng_scaled(i[0], sc, unit), eng_scaled(i[1], sc, unit))
                        })
                        .collect::<Vec<_>>()
                        .join(" ")
                }
            };
            format!("stick: {}  slip: {} ({})", list(&z.stick), list(&z.slip), z.coordinate)
        }
    }
}

/// The solver in one line: techniques, iterations and residual where a solver iterated, the
/// grid solver's time, and the run's time.
fn solver_line(s: &SolverOut) -> String {
    let mut t = s.method.clone();
    if s.elements > 0 {
        t.push_str(&format!(
            ", {} elements: {} iterations{}, residual {:.2e}, {}",
            s.elements,
            s.iterations,
            if s.inner_iterations > 0 {
                let what = if s.method.contains("SteadyRolling") { "FFT products" } else { "CG" };
                format!(" ({} {what})", s.inner_iterations)
            } else {
                String::new()
            },
            s.residual,
            eng(s.solve_seconds, "s")
        ));
    } else if s.iterations > 0 {
        t.push_str(&format!(", {} iterations, residual {:.2e}", s.iterations, s.residual));
    }
    format!("{t} (run {})", eng(s.seconds, "s"))
}

fn cmd_explain(scene: Option<&PathBuf>) -> Result<(), Failure> {
    let scene = load(scene)?;
    let plan = Plan::new(&scene)?;
    emit(&wrap::wrap(&plan.explain(), wrap::WIDTH))
}

/// `reproduce`: the verification pages of stickslip-verification.
fn cmd_reproduce(out: &std::path::Path) -> Result<(), Failure> {
    let files = stickslip_verification::generate(out)
        .map_err(|e| Failure::Other(format!("reproduce: {e}"), 1))?;
    let mut t = String::new();
    for f in &files {
        let _ = writeln!(t, "wrote {}", f.display());
    }
    emit(&t)
}

/// `accuracy`: the accuracy-versus-time report of stickslip-benches.
fn cmd_accuracy(quick: bool, out: &std::path::Path) -> Result<(), Failure> {
    use stickslip_benches::accuracy::{fmt_time, run as measure, write, Mode};
    let report = measure(if quick { Mode::Quick } else { Mode::Full });
    let mut t = String::new();
    for m in &report.methods {
        let _ = writeln!(t, "{:<16} {}", m.slug, m.reading);
        for s in &m.settings {
            let _ = writeln!(
                t,
                "    {:<12} error {:>10.3e}  {:>10}",
                s.label,
                s.error,
                fmt_time(s.seconds)
            );
        }
    }
    emit(&t)?;
    let files = write(&report, out).map_err(|e| {
        Failure::Other(format!("cannot write the accuracy report to {}: {e}", out.display()), 1)
    })?;
    let mut t = String::new();
    for f in &files {
        let _ = writeln!(t, "wrote {}", f.display());
    }
    emit(&t)
}

fn dispatch(cli: &Cli) -> Result<(), Failure> {
    match &cli.command {
        Command::Run { scene, out, force, json, time_limit, quiet } => {
            cmd_run(scene.as_ref(), out.as_ref(), *force, *json, *time_limit, *quiet)
        }
        Command::Explain { scene } => cmd_explain(scene.as_ref()),
        Command::Sweep(a) => sweep::cmd_sweep(a),
        Command::Merge(a) => sweep::cmd_merge(a),
        Command::Reproduce { out } => cmd_reproduce(out),
        Command::Accuracy { quick, full, out } => cmd_accuracy(*quick && !*full, out),
        Command::New(a) => new::run(a),
        Command::Schema => new::schema(),
        Command::Completions(a) => completions::run(a, Cli::command()),
        Command::Man => completions::man(Cli::command()),
    }
}

fn main() -> ExitCode {
    // Usage errors exit 2 and --help/--version 0 (clap).
    let cli = Cli::parse();
    // A panic is a bug: the default hook prints where; the status is 1 (internal error).
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| dispatch(&cli)));
    match result {
        Ok(Ok(())) => ExitCode::SUCCESS,
        Ok(Err(Failure::Scene(e))) => {
            note(&format!("error: {e}"));
            ExitCode::from(e.exit_code())
        }
        // The reader has what it wanted (`| head`): end quietly, as ripgrep does.
        Ok(Err(Failure::Closed)) => ExitCode::SUCCESS,
        Ok(Err(Failure::Stdout(e))) => {
            note(&format!("error: cannot write to standard output: {e}"));
            ExitCode::from(1)
        }
        Ok(Err(Failure::Other(msg, code))) => {
            note(&format!("error: {msg}"));
            ExitCode::from(code)
        }
        Err(_) => {
            note("error: internal error (a bug in stickslip); please report it with the scene");
            ExitCode::from(1)
        }
    }
}
