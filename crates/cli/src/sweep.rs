//! `stickslip sweep` and `stickslip merge`: parameter sweeps over a scene, in shards, and
//! the merging of shard tables (the sweep module of the scene crate does the work).

use std::fmt::Write as _;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use stickslip_sweep::{
    journal_path, merge, read_points, write_atomically, Cell, Mode, Shard, Sweep, Table, Vary,
};

use crate::{emit, note, Failure};

/// `stickslip sweep`.
#[derive(Debug, Args)]
pub struct SweepArgs {
    /// Scene file (TOML).
    scene: PathBuf,
    /// A varied key: KEY=START:END:COUNT (COUNT evenly spaced values, ends included, e.g.
    /// load.tangential=0:0.9:10 or load.normal="10 N:50 N:5") or KEY=V1,V2,... (e.g.
    /// load.friction=0.1,0.2). Repeat for more keys; the points are the cartesian product,
    /// the last key varying fastest (with --zip: the lists taken in step).
    #[arg(long, value_name = "KEY=VALUES", required_unless_present = "points", value_parser = vary)]
    vary: Vec<Vary>,
    /// The points as a table (CSV): a header of dotted scene keys, then one row per point
    /// with each key's value (a number, or a quantity with its unit such as `2 mm`); lines
    /// starting with `#` are comments. The columns are zipped (--zip is implied); --vary
    /// adds more keys, of as many values as the table has rows.
    #[arg(long, value_name = "FILE")]
    points: Option<PathBuf>,
    /// Vary the keys together, point by point: point i sets every --vary key to its i-th
    /// value (the lists must be of equal length), e.g. a wheelset's position.lateral,
    /// position.yaw and position.roll in step. Without it the points are the cartesian
    /// product.
    #[arg(long)]
    zip: bool,
    /// Directory for the table: sweep.csv and sweep.parquet, or sweep-IofN.csv and
    /// sweep-IofN.parquet for a shard (so the shards of a job array can share one
    /// directory). Other files in it are left alone.
    #[arg(long, value_name = "DIR")]
    out: PathBuf,
    /// Run shard I of N only: the points whose index is I-1 modulo N. Merge the shard
    /// tables with `stickslip merge`.
    #[arg(long, value_name = "I/N", value_parser = Shard::parse)]
    shard: Option<Shard>,
    /// Refuse a point the planner estimates to take longer than this (seconds); it becomes
    /// a failed row.
    #[arg(long, value_name = "SECONDS", default_value_t = stickslip_run::DEFAULT_TIME_LIMIT_SECONDS, value_parser = crate::positive_seconds)]
    time_limit: f64,
    /// Continue a sweep that was killed: read the rows of the points it finished from its
    /// partial table (sweep.partial.csv, or sweep-IofN.partial.csv, in --out) and run only
    /// the others. Without it a sweep starts from its first point.
    #[arg(long)]
    resume: bool,
    /// Points run at once, each on its own (default: the available cores, or
    /// RAYON_NUM_THREADS when set). 1 runs them
    /// one after the other, each point's solvers using every core; the table is the same
    /// for any number.
    #[arg(short = 'j', long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
    jobs: Option<u32>,
}

/// `stickslip merge`.
#[derive(Debug, Args)]
pub struct MergeArgs {
    /// Shard tables (sweep-IofN.csv files), or directories holding them.
    #[arg(required = true, value_name = "SHARD")]
    shards: Vec<PathBuf>,
    /// Directory for the merged table (sweep.csv and sweep.parquet).
    #[arg(long, value_name = "DIR")]
    out: PathBuf,
}

fn vary(s: &str) -> Result<Vary, String> {
    Vary::parse(s).map_err(|e| format!("{}\n  hint: {}", e.message, e.hint))
}

/// Write `table` as `stem`.csv and `stem`.parquet in `dir`; the paths written.
fn write(table: &Table, dir: &Path, stem: &str) -> Result<[PathBuf; 2], Failure> {
    std::fs::create_dir_all(dir).map_err(|e| {
        Failure::Other(format!("cannot create the directory {}: {e}", dir.display()), 1)
    })?;
    let csv = dir.join(format!("{stem}.csv"));
    let parquet = dir.join(format!("{stem}.parquet"));
    let fail = |e: stickslip_sweep::TableError| Failure::Other(e.to_string(), 1);
    let text = table.to_csv().map_err(fail)?;
    // Each file all or nothing: written beside, flushed, renamed over.
    write_atomically(&csv, text.as_bytes()).map_err(fail)?;
    let tmp = dir.join(format!("{stem}.parquet.tmp"));
    table.write_parquet(&tmp).map_err(fail)?;
    let io =
        |e: std::io::Error| Failure::Other(format!("cannot write {}: {e}", parquet.display()), 1);
    std::fs::File::open(&tmp).and_then(|f| f.sync_all()).map_err(io)?;
    std::fs::rename(&tmp, &parquet).map_err(io)?;
    Ok([csv, parquet])
}

/// Points that ran and points that failed, for the summary.
fn counts(t: &Table) -> (usize, usize) {
    let j = t.column("status");
    let ok =
        t.rows.iter().filter(|r| j.is_some_and(|j| r[j] == Cell::Text(Some("ok".into())))).count();
    (ok, t.rows.len() - ok)
}

fn summary(t: &Table, files: &[PathBuf; 2]) -> String {
    let (ok, failed) = counts(t);
    let mut s = format!(
        "{} points: {ok} ok, {failed} failed (the reason is in the `reason` column)\n",
        t.rows.len()
    );
    for f in files {
        let _ = writeln!(s, "wrote {}", f.display());
    }
    s
}

/// Run a sweep (or one shard of it) and write its table. Failed points are rows of the
/// table, not a failure of the command.
pub fn cmd_sweep(a: &SweepArgs) -> Result<(), Failure> {
    let text = std::fs::read_to_string(&a.scene).map_err(|e| {
        Failure::Other(format!("cannot read the scene file {}: {e}", a.scene.display()), 1)
    })?;
    let mut vary = a.vary.clone();
    if let Some(p) = &a.points {
        let table = std::fs::read_to_string(p).map_err(|e| {
            Failure::Other(format!("cannot read the points file {}: {e}", p.display()), 2)
        })?;
        let mut from_file = read_points(&table, &p.display().to_string())
            .map_err(|e| Failure::Other(e.to_string(), 2))?;
        from_file.append(&mut vary);
        vary = from_file;
    }
    let mode = if a.zip || a.points.is_some() { Mode::Zip } else { Mode::Cartesian };
    let mut sweep = Sweep::with_mode(&text, Some(a.scene.clone()), &vary, mode)?;
    if let Some(j) = a.jobs {
        sweep = sweep.with_jobs(j as usize);
    }
    let shard = a.shard.unwrap_or(Shard::ALL);
    let n = shard.points(sweep.len()).count();
    let bar = std::io::stderr().is_terminal().then(|| {
        let b = ProgressBar::new(n as u64);
        if let Ok(style) = ProgressStyle::with_template(
            "{spinner} point {pos}/{len} [{bar:40}] {elapsed} (eta {eta})",
        ) {
            b.set_style(style.progress_chars("=> "));
        }
        b
    });
    let stem = if shard == Shard::ALL {
        "sweep".to_string()
    } else {
        format!("sweep-{}of{}", shard.index, shard.count)
    };
    // The journal's place is known before anything is created: a refused --resume leaves
    // no directory behind.
    let journal = journal_path(&a.out, &stem);
    if a.resume && !journal.exists() {
        return Err(Failure::Other(
            format!(
                "--resume: no partial table {} to continue from\n  hint: run the sweep without --resume (it starts from its first point)",
                journal.display()
            ),
            2,
        ));
    }
    std::fs::create_dir_all(&a.out).map_err(|e| {
        Failure::Other(format!("cannot create the directory {}: {e}", a.out.display()), 1)
    })?;
    let run = sweep
        .run_journaled(shard, a.time_limit, &journal, a.resume, |_| {
            if let Some(b) = &bar {
                b.inc(1);
            }
        })
        .map_err(|e| {
            let code = if a.resume { 2 } else { 1 };
            Failure::Other(
                format!("{e}\n  hint: run without --resume to start the sweep again"),
                code,
            )
        })?;
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    let table = run.table;
    let files = write(&table, &a.out, &stem)?;
    // The table is whole: the journal has served.
    let _ = std::fs::remove_file(&journal);
    let mut text = summary(&table, &files);
    if a.resume {
        text = format!(
            "resumed: {} points read from the partial table, {} solved now\n{text}",
            run.resumed, run.solved
        );
    }
    emit(&text)
}

/// The shard tables named by `paths`: files as given, directories searched for
/// sweep-IofN.csv.
fn shard_files(paths: &[PathBuf]) -> Result<Vec<PathBuf>, Failure> {
    let mut files = Vec::new();
    for p in paths {
        if p.is_dir() {
            let rd = std::fs::read_dir(p).map_err(|e| {
                Failure::Other(format!("cannot read the directory {}: {e}", p.display()), 1)
            })?;
            let mut found: Vec<PathBuf> = rd
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|f| {
                    f.file_name().and_then(|n| n.to_str()).is_some_and(|n| {
                        n.starts_with("sweep-") && n.ends_with(".csv") && n.contains("of")
                    })
                })
                .collect();
            if found.is_empty() {
                return Err(Failure::Other(
                    format!(
                        "no shard table (sweep-IofN.csv) in {}; give the shard files or their \
                         directories",
                        p.display()
                    ),
                    2,
                ));
            }
            found.sort();
            files.extend(found);
        } else {
            files.push(p.clone());
        }
    }
    Ok(files)
}

/// Merge shard tables into the full table, checking that none is missing.
pub fn cmd_merge(a: &MergeArgs) -> Result<(), Failure> {
    let files = shard_files(&a.shards)?;
    let tables = files
        .iter()
        .map(|f| Table::read_csv(f).map_err(|e| Failure::Other(e.to_string(), 2)))
        .collect::<Result<Vec<_>, _>>()?;
    let names: Vec<String> = files.iter().map(|f| f.display().to_string()).collect();
    let table = merge(tables, &names).map_err(|e| Failure::Other(format!("merge: {e}"), 2))?;
    note(&format!("merged {} shard tables", files.len()));
    let files = write(&table, &a.out, "sweep")?;
    emit(&summary(&table, &files))
}
