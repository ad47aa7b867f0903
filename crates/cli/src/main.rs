//! The `stickslip` command-line program.
//!
//! - `stickslip run [SCENE] [--out DIR] [--json]`: run a scene (the built-in default scene,
//!   seed 000's Table 1 roller, when none is given) through `stickslip_scene::run`, the one
//!   code path the library offers; write result.json, CSV and SVG plots into DIR, or print the
//!   JSON with `--json`.
//! - `stickslip explain [SCENE]`: print the plan (effects on and off with reasons, the
//!   technique per effect, the estimated cost) without computing anything.
//! - `stickslip reproduce [--out DIR]`: the verification pages (stickslip-verification).
//! - `stickslip accuracy [--quick|--full] [--out DIR]`: the accuracy-versus-time report
//!   (stickslip-benches).
//!
//! Errors print the scene error (file:line:column, key, message, hint) and exit with status 1
//! (2 for usage errors, from clap); no output file is left behind.

// SceneError carries file, position, key and hint for the user; it is returned once per run.
#![allow(clippy::result_large_err)]

use std::io::IsTerminal;
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Mutex;
use std::time::{Duration, Instant};

use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
use stickslip_scene::{run, write_outputs, Plan, Progress, RunOptions, Scene, SceneError};

/// Frictional contact mechanics: run scenes, explain their plan, reproduce the published
/// figures, report accuracy against time.
#[derive(Debug, Parser)]
#[command(name = "stickslip", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Run a scene (the built-in default scene when none is given).
    Run {
        /// Scene file (TOML); omit for the seed 000 Table 1 roller.
        scene: Option<PathBuf>,
        /// Write result.json, CSV and SVG plots into this directory (all or nothing).
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// Print result.json to stdout.
        #[arg(long)]
        json: bool,
    },
    /// Print the plan of a scene without computing anything.
    Explain {
        /// Scene file (TOML); omit for the built-in default scene.
        scene: Option<PathBuf>,
    },
    /// Regenerate the verification pages (published values against computed ones).
    Reproduce {
        /// Output directory.
        #[arg(long, value_name = "DIR", default_value = "docs/verification")]
        out: PathBuf,
    },
    /// The accuracy-versus-time report.
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
}

fn load(scene: Option<&PathBuf>) -> Result<Scene, SceneError> {
    match scene {
        Some(p) => Scene::from_file(p),
        None => Ok(Scene::default_scene()),
    }
}

/// A progress bar that appears only on a terminal and only once a run has lasted a second.
struct Bar {
    start: Instant,
    bar: Mutex<Option<ProgressBar>>,
    enabled: bool,
}

impl Bar {
    fn new() -> Self {
        Bar {
            start: Instant::now(),
            bar: Mutex::new(None),
            enabled: std::io::stderr().is_terminal(),
        }
    }

    fn update(&self, p: Progress) {
        if !self.enabled || self.start.elapsed() < Duration::from_secs(1) {
            return;
        }
        let Ok(mut guard) = self.bar.lock() else { return };
        let bar = guard.get_or_insert_with(|| {
            let b = ProgressBar::new(p.total as u64);
            if let Ok(style) =
                ProgressStyle::with_template("{spinner} {msg:24} [{bar:40}] {pos}/{len} {elapsed}")
            {
                b.set_style(style.progress_chars("=> "));
            }
            b
        });
        bar.set_length(p.total as u64);
        bar.set_position(p.done as u64);
        bar.set_message(p.stage);
    }

    fn finish(&self) {
        if let Ok(mut g) = self.bar.lock() {
            if let Some(b) = g.take() {
                b.finish_and_clear();
            }
        }
    }
}

fn cmd_run(scene: Option<&PathBuf>, out: Option<&PathBuf>, json: bool) -> Result<(), SceneError> {
    let scene = load(scene)?;
    let bar = Bar::new();
    let cb = |p: Progress| bar.update(p);
    let opts = RunOptions { progress: Some(&cb) };
    let result = run(&scene, &opts);
    bar.finish();
    let outcome = result?;
    if let Some(dir) = out {
        let w = write_outputs(&outcome, dir, scene.outputs.plots)?;
        if !json {
            eprintln!("wrote {} files to {}", w.files.len(), w.dir.display());
        }
    }
    if json {
        println!("{}", outcome.to_json());
    } else {
        let c = &outcome.contact;
        // 2D (plane strain) loads are per unit length.
        let (fu, mu) = if scene.geometry.is_2d() { ("N/m", "N m/m") } else { ("N", "N m") };
        println!("{}", outcome.title);
        println!("  effects on: {}", outcome.effects.on.join(", "));
        println!(
            "  contact: a = {:.6e} m, b = {:.6e} m, p0 = {:.6e} Pa, normal load = {:.6e} {fu}",
            c.a, c.b, c.p0, c.normal_load
        );
        if let Some(h) = c.indentation {
            println!("  indentation: {h:.6e} m");
        }
        println!(
            "  forces: tangential = {:.6e} {fu}, moment = {:.6e} {mu}, rolling moment = {:.6e} {mu}",
            outcome.forces.tangential, outcome.forces.moment, outcome.forces.rolling_moment
        );
        println!(
            "  stick: {:?}  slip: {:?} ({})",
            outcome.zones.stick, outcome.zones.slip, outcome.zones.coordinate
        );
        println!("  solver: {} ({:.3} s)", outcome.solver.method, outcome.solver.seconds);
        if out.is_none() {
            println!("  (use --out DIR for result.json, CSV and plots, or --json)");
        }
    }
    Ok(())
}

fn cmd_explain(scene: Option<&PathBuf>) -> Result<(), SceneError> {
    let scene = load(scene)?;
    let plan = Plan::new(&scene)?;
    print!("{}", plan.explain(&scene));
    Ok(())
}

/// `reproduce`: the verification pages of stickslip-verification.
fn cmd_reproduce(out: &std::path::Path) -> ExitCode {
    match stickslip_verification::generate(out) {
        Ok(files) => {
            for f in &files {
                println!("wrote {}", f.display());
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: reproduce: {e}");
            ExitCode::from(1)
        }
    }
}

/// `accuracy`: the accuracy-versus-time report of stickslip-benches.
fn cmd_accuracy(quick: bool, out: &std::path::Path) -> ExitCode {
    use stickslip_benches::accuracy::{fmt_time, run as measure, write, Mode};
    let report = measure(if quick { Mode::Quick } else { Mode::Full });
    for m in &report.methods {
        println!("{:<16} {}", m.slug, m.reading);
        for s in &m.settings {
            println!("    {:<12} error {:>10.3e}  {:>10}", s.label, s.error, fmt_time(s.seconds));
        }
    }
    match write(&report, out) {
        Ok(files) => {
            for f in &files {
                println!("wrote {}", f.display());
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: cannot write the accuracy report to {}: {e}", out.display());
            ExitCode::from(1)
        }
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::Run { scene, out, json } => cmd_run(scene.as_ref(), out.as_ref(), *json),
        Command::Explain { scene } => cmd_explain(scene.as_ref()),
        Command::Reproduce { out } => return cmd_reproduce(out),
        Command::Accuracy { quick, full, out } => return cmd_accuracy(*quick && !*full, out),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(1)
        }
    }
}
