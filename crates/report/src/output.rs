//! Writing a run's results: result.json, CSV of the arrays, SVG plots, report.html. All or
//! nothing.
//!
//! The target directory `DIR` is replaced whole, never merged into:
//!
//! 1. every file is rendered in memory;
//! 2. a lock file `.NAME.stickslip-lock` beside `DIR` (created with `create_new`, holding
//!    the writer's pid) serialises runs into one `DIR`: a second run waits for it (up to
//!    [`LOCK_WAIT`]) and then refuses, naming the pid; a lock whose pid no longer exists
//!    (a killed run) is taken over;
//! 3. temporaries of earlier runs that were killed (`.NAME.stickslip-tmp-PID-*`,
//!    `.NAME.stickslip-old-PID-*` whose PID no longer exists) are removed; if a run was
//!    killed between its two renames, so that `DIR` is missing and its previous result sits
//!    aside, that result is moved back first;
//! 4. an existing `DIR` must be empty or a previous stickslip result (it holds the marker
//!    file `.stickslip-result`, or, from versions before the marker, result.json and only
//!    files a run writes); anything else is refused unless `force`;
//! 5. the files and the marker are written into a fresh sibling `.NAME.stickslip-tmp-PID-*`;
//! 6. `DIR` (if it exists) is renamed aside to `.NAME.stickslip-old-PID-*`, the new
//!    directory is renamed to `DIR`, and the old one is removed. If the second rename
//!    fails, the old directory is renamed back.
//!
//! After any failure the error says what state `DIR` is in (as it was, in almost every
//! case). A kill (SIGKILL) at any moment leaves either the previous result or the new one
//! in `DIR`, except between the two renames of step 6, when `DIR` is briefly missing and
//! the previous result is aside; the next run into `DIR` puts it back (step 3).

#![allow(clippy::result_large_err)]

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::files::render;
use crate::report::ReportContext;
use stickslip_run::Outcome;
use stickslip_scene::{ErrorKind, SceneError};

/// What [`write_outputs`] wrote.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Written {
    /// The output directory.
    pub dir: PathBuf,
    /// The files, in the order written (the marker `.stickslip-result` is not listed).
    pub files: Vec<PathBuf>,
    /// What else was done or could not be done, for the user (temporaries of killed runs
    /// removed, a previous result restored, an old directory that could not be removed).
    pub notes: Vec<String>,
}

/// How [`write_outputs_with`] writes.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct WriteOptions {
    /// Draw the SVG plots.
    pub plots: bool,
    /// Replace an existing directory even if it holds files that are not a previous
    /// stickslip result (they are deleted).
    pub force: bool,
}

/// The marker file every result directory holds; it tells a later run that the directory
/// may be replaced.
pub const MARKER: &str = ".stickslip-result";

/// How long a run waits for another run writing into the same directory.
pub const LOCK_WAIT: Duration = Duration::from_secs(30);

fn io_err(dir: &Path, what: &str, e: impl std::fmt::Display) -> SceneError {
    SceneError::new(
        ErrorKind::Io,
        format!("cannot write the results to {}: {what}: {e}", dir.display()),
    )
    .hint(format!(
        "choose a directory you can write (--out DIR); nothing was changed: {} is as it was",
        dir.display()
    ))
}

fn refuse(dir: &Path, what: impl std::fmt::Display, hint: impl Into<String>) -> SceneError {
    SceneError::new(ErrorKind::Io, format!("cannot write the results to {}: {what}", dir.display()))
        .hint(hint)
}

/// Write result.json, the CSV files, report.html and (when `plots`) the SVG plots of `out`
/// into `dir`,
/// all or nothing, replacing `dir` whole (see the module documentation). An existing `dir`
/// that holds anything but a previous stickslip result is refused; see
/// [`write_outputs_with`] to force.
///
/// # Errors
/// A [`SceneError`] of kind [`ErrorKind::Io`] naming the directory and saying what state it
/// is in (as it was, after almost every failure).
pub fn write_outputs(out: &Outcome, dir: &Path, plots: bool) -> Result<Written, SceneError> {
    write_outputs_with(out, dir, WriteOptions { plots, force: false })
}

/// [`write_outputs`] with options: plots, and `force` to replace a directory that is not a
/// previous result.
///
/// # Errors
/// As [`write_outputs`].
pub fn write_outputs_with(
    out: &Outcome,
    dir: &Path,
    opts: WriteOptions,
) -> Result<Written, SceneError> {
    let files = render(out, opts.plots, None)?;
    write_files(&files, dir, opts.force)
}

/// [`write_outputs_with`], with the scene and its plan in report.html (the scene's text as
/// given, the scene as resolved, the plan's effects, methods and estimate).
///
/// # Errors
/// As [`write_outputs`].
pub fn write_outputs_report(
    out: &Outcome,
    dir: &Path,
    opts: WriteOptions,
    ctx: ReportContext<'_>,
) -> Result<Written, SceneError> {
    let files = render(out, opts.plots, Some(ctx))?;
    write_files(&files, dir, opts.force)
}

/// The paths a run works with: the target, its parent and name, and the lock.
struct Target {
    dir: PathBuf,
    parent: PathBuf,
    name: String,
}

impl Target {
    fn resolve(dir: &Path) -> Result<Target, SceneError> {
        let meta = std::fs::symlink_metadata(dir);
        if let Ok(m) = &meta {
            if m.file_type().is_symlink() {
                return Err(refuse(
                    dir,
                    "it is a symbolic link",
                    "give the directory itself (a run replaces the whole directory); nothing was changed",
                ));
            }
            if !m.is_dir() {
                return Err(refuse(
                    dir,
                    "it exists and is not a directory",
                    "choose another --out; nothing was changed (a file is never replaced)",
                ));
            }
        }
        let name = match dir.file_name() {
            Some(n)
                if dir
                    .components()
                    .next_back()
                    .is_some_and(|c| matches!(c, std::path::Component::Normal(_))) =>
            {
                n.to_string_lossy().into_owned()
            }
            _ => {
                return Err(refuse(
                    dir,
                    "it does not name a directory that can be replaced",
                    "give a directory by name, e.g. --out results/run1; nothing was changed",
                ))
            }
        };
        let parent = match dir.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        std::fs::create_dir_all(&parent).map_err(|e| io_err(dir, "cannot create its parent", e))?;
        let parent = std::fs::canonicalize(&parent)
            .map_err(|e| io_err(dir, "cannot resolve its parent", e))?;
        let full = parent.join(&name);
        // Never replace the working directory, one of its ancestors or the home directory.
        let cwd = std::env::current_dir().ok();
        let home = std::env::var_os("HOME").map(PathBuf::from);
        if cwd.as_deref().is_some_and(|c| c.starts_with(&full))
            || home.as_deref().is_some_and(|h| h == full)
        {
            return Err(refuse(
                dir,
                "it is the working directory, one of its parents or the home directory",
                "a run replaces its --out directory whole; give a directory of its own, e.g. --out results/run1; nothing was changed",
            ));
        }
        Ok(Target { dir: full, parent, name })
    }

    fn sibling(&self, what: &str, pid: u32) -> PathBuf {
        let stamp = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos());
        self.parent.join(format!(".{}.stickslip-{what}-{pid}-{stamp}", self.name))
    }

    fn lock_path(&self) -> PathBuf {
        self.parent.join(format!(".{}.stickslip-lock", self.name))
    }
}

/// Whether process `pid` exists (conservatively true when this cannot be told).
fn pid_alive(pid: u32) -> bool {
    if pid == std::process::id() {
        return true;
    }
    if cfg!(target_os = "linux") {
        return Path::new("/proc").join(pid.to_string()).exists();
    }
    if cfg!(unix) {
        return std::process::Command::new("kill")
            .args(["-0", &pid.to_string()])
            .stderr(std::process::Stdio::null())
            .status()
            .map_or(true, |s| s.success());
    }
    true
}

/// The lock file, removed when dropped.
struct Lock(PathBuf);

impl Drop for Lock {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

fn lock(t: &Target, user_dir: &Path, wait: Duration) -> Result<Lock, SceneError> {
    let path = t.lock_path();
    let start = Instant::now();
    loop {
        match std::fs::OpenOptions::new().write(true).create_new(true).open(&path) {
            Ok(mut f) => {
                let _ = writeln!(f, "{}", std::process::id());
                return Ok(Lock(path));
            }
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {
                let held = std::fs::read_to_string(&path).unwrap_or_default();
                let pid = held.trim().parse::<u32>().ok();
                match pid {
                    Some(p) if !pid_alive(p) => {
                        // A killed run's lock: take it over if it is still that one.
                        if std::fs::read_to_string(&path).unwrap_or_default() == held {
                            if let Err(e) = std::fs::remove_file(&path) {
                                return Err(io_err(
                                    user_dir,
                                    &format!(
                                        "cannot remove the lock {} of a stopped run (pid {p})",
                                        path.display()
                                    ),
                                    e,
                                ));
                            }
                        }
                        continue;
                    }
                    // A lock being written this very moment (empty) or held by a live run.
                    _ => {}
                }
                if start.elapsed() >= wait {
                    let who = pid.map_or_else(
                        || "another run".to_string(),
                        |p| format!("another stickslip run (pid {p})"),
                    );
                    return Err(refuse(
                        user_dir,
                        format!("{who} is writing into it (lock {})", path.display()),
                        format!(
                            "wait for that run to finish and try again, or choose another --out; if no such process exists, remove {}; nothing was changed",
                            path.display()
                        ),
                    ));
                }
                std::thread::sleep(Duration::from_millis(50));
            }
            Err(e) => return Err(io_err(user_dir, "cannot create a lock file beside it", e)),
        }
    }
}

/// The pid in the name of a temporary `.NAME.stickslip-{tmp,old}-PID-STAMP`.
fn temp_pid(file: &str, prefix: &str) -> Option<u32> {
    file.strip_prefix(prefix)?.split('-').next()?.parse().ok()
}

/// Remove the temporaries of killed runs into `t`; if `t.dir` is missing and a killed run
/// left the previous result aside, move it back first. Returns notes for the user.
fn clean_stale(t: &Target) -> Vec<String> {
    let mut notes = Vec::new();
    let tmp_prefix = format!(".{}.stickslip-tmp-", t.name);
    let old_prefix = format!(".{}.stickslip-old-", t.name);
    let Ok(entries) = std::fs::read_dir(&t.parent) else { return notes };
    let mut tmps = Vec::new();
    let mut olds = Vec::new();
    for e in entries.filter_map(Result::ok) {
        let n = e.file_name().to_string_lossy().into_owned();
        if let Some(p) = temp_pid(&n, &tmp_prefix) {
            if !pid_alive(p) {
                tmps.push(e.path());
            }
        } else if let Some(p) = temp_pid(&n, &old_prefix) {
            if !pid_alive(p) {
                olds.push(e.path());
            }
        }
    }
    // The newest aside directory (names sort by stamp only within one pid; use mtime).
    olds.sort_by_key(|p| std::fs::metadata(p).and_then(|m| m.modified()).ok());
    if !t.dir.exists() {
        if let Some(last) = olds.pop() {
            match std::fs::rename(&last, &t.dir) {
                Ok(()) => notes.push(format!(
                    "an earlier run was stopped while replacing {}; its previous result was moved back from {}",
                    t.dir.display(),
                    last.display()
                )),
                Err(e) => notes.push(format!(
                    "an earlier run left a previous result at {}; it could not be moved back ({e})",
                    last.display()
                )),
            }
        }
    }
    for p in tmps.iter().chain(&olds) {
        match std::fs::remove_dir_all(p) {
            Ok(()) => {
                notes.push(format!("removed {}, left by a run that was stopped", p.display()))
            }
            Err(e) => {
                notes.push(format!("could not remove {}, left by a stopped run: {e}", p.display()))
            }
        }
    }
    notes
}

/// Whether the existing directory `dir` may be replaced without `force`: empty, marked, or
/// holding result.json and only files a run writes. On refusal, up to five foreign names.
fn foreign_files(dir: &Path) -> Result<Vec<String>, std::io::Error> {
    let mut names = Vec::new();
    for e in std::fs::read_dir(dir)? {
        names.push(e?.file_name().to_string_lossy().into_owned());
    }
    if names.is_empty() || names.iter().any(|n| n == MARKER) {
        return Ok(Vec::new());
    }
    let ours = |n: &str| {
        matches!(
            n,
            "result.json"
                | "surface.csv"
                | "field.csv"
                | "cycle.csv"
                | "history.csv"
                | "load_curve.csv"
                | "report.html"
        ) || ((n.ends_with(".svg") || n.ends_with(".npy")) && !n.starts_with('.'))
    };
    let json_ok = std::fs::read_to_string(dir.join("result.json"))
        .ok()
        .and_then(|t| serde_json::from_str::<serde_json::Value>(&t).ok())
        .is_some_and(|v| {
            ["title", "effects", "contact", "solver"].iter().all(|k| v.get(k).is_some())
        });
    let mut foreign: Vec<String> =
        if json_ok { names.into_iter().filter(|n| !ours(n)).collect() } else { names };
    foreign.sort();
    foreign.truncate(5);
    Ok(foreign)
}

/// Write `files` (name, contents) into `dir` as described in the module documentation.
pub(crate) fn write_files(
    files: &[(String, Vec<u8>)],
    dir: &Path,
    force: bool,
) -> Result<Written, SceneError> {
    let t = Target::resolve(dir)?;
    let _lock = lock(&t, dir, LOCK_WAIT)?;
    let mut notes = clean_stale(&t);
    let exists = match std::fs::symlink_metadata(&t.dir) {
        Ok(m) if m.is_dir() => true,
        Ok(_) => {
            return Err(refuse(
                dir,
                "it exists and is not a directory",
                "choose another --out; nothing was changed (a file is never replaced)",
            ))
        }
        Err(_) => false,
    };
    if exists && !force {
        let foreign = foreign_files(&t.dir).map_err(|e| io_err(dir, "cannot list it", e))?;
        if !foreign.is_empty() {
            return Err(refuse(
                dir,
                format!(
                    "it holds files that are not a previous stickslip result ({})",
                    foreign.join(", ")
                ),
                "a run replaces its --out directory whole; choose another directory, or pass --force to replace it (its files are deleted); nothing was changed",
            ));
        }
    }
    let pid = std::process::id();
    let tmp = t.sibling("tmp", pid);
    std::fs::create_dir(&tmp)
        .map_err(|e| io_err(dir, "cannot create a temporary directory beside it", e))?;
    let cleanup = |e: SceneError| -> SceneError {
        let _ = std::fs::remove_dir_all(&tmp);
        e
    };
    let marker = format!("stickslip {} result\n", env!("CARGO_PKG_VERSION"));
    for (n, text) in
        files.iter().map(|(n, t)| (n.as_str(), t.as_slice())).chain([(MARKER, marker.as_bytes())])
    {
        std::fs::write(tmp.join(n), text).map_err(|e| cleanup(io_err(dir, n, e)))?;
    }
    let aside = t.sibling("old", pid);
    if let Some(note) = replace(&t.dir, &tmp, &aside, exists, &mut |a, b| std::fs::rename(a, b))
        .map_err(|e| e.into_error(dir))?
    {
        notes.push(note);
    }
    Ok(Written {
        dir: dir.to_path_buf(),
        files: files.iter().map(|(n, _)| dir.join(n)).collect(),
        notes,
    })
}

/// How [`replace`] failed, and so what state the target is in.
#[derive(Debug)]
enum ReplaceError {
    /// Nothing changed: the target is as it was; the new files are removed.
    Unchanged(&'static str, std::io::Error),
    /// The target is missing: its previous result is at `aside` and the new one at `tmp`.
    Split { aside: PathBuf, tmp: PathBuf, first: std::io::Error, back: std::io::Error },
}

impl ReplaceError {
    fn into_error(self, dir: &Path) -> SceneError {
        match self {
            ReplaceError::Unchanged(what, e) => io_err(dir, what, e),
            ReplaceError::Split { aside, tmp, first, back } => SceneError::new(
                ErrorKind::Io,
                format!(
                    "cannot write the results to {}: the new result could not be moved into place ({first}) and the previous one could not be moved back ({back})",
                    dir.display()
                ),
            )
            .hint(format!(
                "{} does not exist now: the previous result is at {} and the new one at {}; rename one of them to {} by hand (the next run into it moves the previous one back)",
                dir.display(),
                aside.display(),
                tmp.display(),
                dir.display()
            )),
        }
    }
}

/// Put the complete directory `tmp` in place of `dir` (which exists when `exists`):
/// rename `dir` to `aside`, `tmp` to `dir`, remove `aside`. `rename` is `std::fs::rename`
/// (a parameter so that tests can make any step fail). On success, a note if `aside`
/// could not be removed.
fn replace(
    dir: &Path,
    tmp: &Path,
    aside: &Path,
    exists: bool,
    rename: &mut dyn FnMut(&Path, &Path) -> std::io::Result<()>,
) -> Result<Option<String>, ReplaceError> {
    if !exists {
        return match rename(tmp, dir) {
            Ok(()) => Ok(None),
            Err(e) => {
                let _ = std::fs::remove_dir_all(tmp);
                Err(ReplaceError::Unchanged("cannot move the results into place", e))
            }
        };
    }
    if let Err(e) = rename(dir, aside) {
        let _ = std::fs::remove_dir_all(tmp);
        return Err(ReplaceError::Unchanged("cannot move the previous result aside", e));
    }
    if let Err(first) = rename(tmp, dir) {
        return match rename(aside, dir) {
            Ok(()) => {
                let _ = std::fs::remove_dir_all(tmp);
                Err(ReplaceError::Unchanged("cannot move the results into place", first))
            }
            Err(back) => Err(ReplaceError::Split {
                aside: aside.to_path_buf(),
                tmp: tmp.to_path_buf(),
                first,
                back,
            }),
        };
    }
    Ok(std::fs::remove_dir_all(aside).err().map(|e| {
        format!(
            "the previous result, moved aside to {}, could not be removed ({e}); the next run into {} removes it",
            aside.display(),
            dir.display()
        )
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let d =
            std::env::temp_dir().join(format!("stickslip-replace-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    fn setup(name: &str) -> (PathBuf, PathBuf, PathBuf, PathBuf) {
        let base = scratch(name);
        let (dir, tmp, aside) = (base.join("out"), base.join(".tmp"), base.join(".old"));
        std::fs::create_dir(&dir).unwrap();
        std::fs::write(dir.join("result.json"), "old").unwrap();
        std::fs::create_dir(&tmp).unwrap();
        std::fs::write(tmp.join("result.json"), "new").unwrap();
        (base, dir, tmp, aside)
    }

    fn fail_at(n: usize) -> impl FnMut(&Path, &Path) -> std::io::Result<()> {
        let mut i = 0;
        move |a, b| {
            i += 1;
            if i == n {
                Err(std::io::Error::other(format!("injected failure of rename {n}")))
            } else {
                std::fs::rename(a, b)
            }
        }
    }

    #[test]
    fn replace_succeeds_and_removes_the_old_directory() {
        let (base, dir, tmp, aside) = setup("ok");
        assert!(replace(&dir, &tmp, &aside, true, &mut fail_at(0)).unwrap().is_none());
        assert_eq!(std::fs::read_to_string(dir.join("result.json")).unwrap(), "new");
        assert!(!tmp.exists() && !aside.exists());
        let _ = std::fs::remove_dir_all(base);
    }

    #[test]
    fn first_rename_failing_leaves_the_target_as_it_was() {
        let (base, dir, tmp, aside) = setup("first");
        let e = replace(&dir, &tmp, &aside, true, &mut fail_at(1)).unwrap_err();
        assert!(matches!(e, ReplaceError::Unchanged(..)));
        let msg = e.into_error(&dir).to_string();
        assert!(msg.contains("nothing was changed"), "{msg}");
        assert_eq!(std::fs::read_to_string(dir.join("result.json")).unwrap(), "old");
        assert!(!tmp.exists() && !aside.exists());
        let _ = std::fs::remove_dir_all(base);
    }

    #[test]
    fn second_rename_failing_moves_the_previous_result_back() {
        let (base, dir, tmp, aside) = setup("second");
        let e = replace(&dir, &tmp, &aside, true, &mut fail_at(2)).unwrap_err();
        assert!(matches!(e, ReplaceError::Unchanged(..)), "{e:?}");
        assert_eq!(std::fs::read_to_string(dir.join("result.json")).unwrap(), "old");
        assert!(!tmp.exists() && !aside.exists());
        let _ = std::fs::remove_dir_all(base);
    }

    #[test]
    fn second_and_restoring_rename_failing_say_where_both_results_are() {
        let (base, dir, tmp, aside) = setup("split");
        let mut i = 0;
        let mut rename = |a: &Path, b: &Path| {
            i += 1;
            if i >= 2 {
                Err(std::io::Error::other("injected"))
            } else {
                std::fs::rename(a, b)
            }
        };
        let e = replace(&dir, &tmp, &aside, true, &mut rename).unwrap_err();
        let msg = e.into_error(&dir).to_string();
        println!("{msg}");
        assert!(!msg.contains("nothing was"), "{msg}");
        assert!(
            msg.contains(&aside.display().to_string()) && msg.contains(&tmp.display().to_string())
        );
        assert_eq!(std::fs::read_to_string(aside.join("result.json")).unwrap(), "old");
        assert_eq!(std::fs::read_to_string(tmp.join("result.json")).unwrap(), "new");
        let _ = std::fs::remove_dir_all(base);
    }

    #[test]
    fn a_dead_runs_lock_is_taken_over_and_a_live_one_refused() {
        let base = scratch("lock");
        let t = Target::resolve(&base.join("out")).unwrap();
        // A process that has exited: its pid is (almost surely) free.
        let mut child = std::process::Command::new("true").spawn().unwrap();
        let dead = child.id();
        child.wait().unwrap();
        std::fs::write(t.lock_path(), format!("{dead}\n")).unwrap();
        let l = lock(&t, &t.dir, Duration::ZERO).unwrap();
        assert_eq!(
            std::fs::read_to_string(t.lock_path()).unwrap().trim(),
            std::process::id().to_string()
        );
        // Held by a live process (this one): refused after the wait.
        let e = match lock(&t, &t.dir, Duration::from_millis(100)) {
            Err(e) => e,
            Ok(_) => panic!("a held lock was taken"),
        };
        assert!(e.to_string().contains("is writing into it"), "{e}");
        drop(l);
        assert!(!t.lock_path().exists());
        let _ = std::fs::remove_dir_all(base);
    }
}
