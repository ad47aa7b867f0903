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

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::report::ReportContext;
use stickslip_run::{Outcome, SurfaceOut};
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

/// The files of `out` as (name, contents), rendered in memory.
///
/// # Errors
/// A [`SceneError`] (kind [`ErrorKind::Io`]) if a plot cannot be drawn.
pub(crate) fn render(
    out: &Outcome,
    plots: bool,
    ctx: Option<ReportContext<'_>>,
) -> Result<Vec<(String, Vec<u8>)>, SceneError> {
    let mut files: Vec<(String, String)> = vec![("result.json".to_string(), out.to_json() + "\n")];
    let mut binary: Vec<(String, Vec<u8>)> = Vec::new();
    let mut s = String::new();
    match &out.surface {
        SurfaceOut::Line { x, p, q, ux, uy, .. } if !x.is_empty() => {
            let disp = !ux.is_empty();
            s.push_str(if disp { "x_m,p_Pa,q_Pa,ux_m,uy_m\n" } else { "x_m,p_Pa,q_Pa\n" });
            for i in 0..x.len() {
                let _ = write!(s, "{},{},{}", x[i], p[i], q[i]);
                if disp {
                    let _ = write!(s, ",{},{}", ux[i], uy[i]);
                }
                s.push('\n');
            }
            files.push(("surface.csv".to_string(), std::mem::take(&mut s)));
        }
        SurfaceOut::Grid {
            x,
            y,
            p,
            qx,
            qy,
            stick,
            gap,
            slip_x,
            slip_y,
            dissipation,
            slip_amplitude,
            ruiz,
            plastic,
            plastic_displacement,
        } if !x.is_empty() => {
            // A surface's, a 3D rolling contact's and a load path's maps also as (ny, nx)
            // arrays: pressure, tractions, gap, micro-slip or dissipation and slip range,
            // contact.
            if gap.is_some() || slip_x.is_some() || dissipation.is_some() {
                let (nx, ny) = (x.len(), y.len());
                let rows = |m: &Vec<Vec<f64>>| -> Vec<f64> {
                    (0..ny).flat_map(|j| (0..nx).map(move |i| m[i][j])).collect()
                };
                let mut maps = vec![("p", p), ("qx", qx), ("qy", qy)];
                for (name, m) in [
                    ("gap", gap),
                    ("slip_x", slip_x),
                    ("slip_y", slip_y),
                    ("dissipation", dissipation),
                    ("slip_amplitude", slip_amplitude),
                    ("ruiz", ruiz),
                    ("plastic", plastic),
                    ("plastic_displacement", plastic_displacement),
                ] {
                    if let Some(m) = m {
                        maps.push((name, m));
                    }
                }
                for (name, m) in maps {
                    binary.push((format!("surface_{name}.npy"), npy(&rows(m), &[ny, nx])));
                }
                let stick_f: Vec<f64> =
                    (0..ny).flat_map(|j| (0..nx).map(move |i| f64::from(stick[i][j]))).collect();
                binary.push(("surface_stick.npy".to_string(), npy(&stick_f, &[ny, nx])));
                binary.push(("surface_x.npy".to_string(), npy(x, &[nx])));
                binary.push(("surface_y.npy".to_string(), npy(y, &[ny])));
            }
            s.push_str("x_m,y_m,p_Pa,qx_Pa,qy_Pa,stick");
            if slip_x.is_some() {
                s.push_str(",slip_x_m_per_s,slip_y_m_per_s");
            }
            if dissipation.is_some() {
                s.push_str(",dissipation_J_per_m2,slip_amplitude_m");
            }
            s.push('\n');
            for (i, xi) in x.iter().enumerate() {
                for (j, yj) in y.iter().enumerate() {
                    // A load path's cells that dissipated but left the contact are listed
                    // too (their pressure is zero now).
                    let dissipated = dissipation.as_ref().is_some_and(|d| d[i][j] != 0.0);
                    if stick[i][j] >= 0 || dissipated {
                        let _ = write!(
                            s,
                            "{xi},{yj},{},{},{},{}",
                            p[i][j], qx[i][j], qy[i][j], stick[i][j]
                        );
                        if let (Some(sx), Some(sy)) = (slip_x, slip_y) {
                            let _ = write!(s, ",{},{}", sx[i][j], sy[i][j]);
                        }
                        if let (Some(d), Some(a)) = (dissipation, slip_amplitude) {
                            let _ = write!(s, ",{},{}", d[i][j], a[i][j]);
                        }
                        s.push('\n');
                    }
                }
            }
            files.push(("surface.csv".to_string(), std::mem::take(&mut s)));
        }
        _ => {}
    }
    let f = out.field.plane();
    if !f.x.is_empty() {
        s.push_str("x_m,y_m,sxx_Pa,syy_Pa,sxy_Pa\n");
        for (j, y) in f.y.iter().enumerate() {
            for (i, x) in f.x.iter().enumerate() {
                let _ = writeln!(s, "{x},{y},{},{},{}", f.sxx[j][i], f.syy[j][i], f.sxy[j][i]);
            }
        }
        files.push(("field.csv".to_string(), std::mem::take(&mut s)));
    }
    if let Some(v) = out.field.volume() {
        s.push_str("x,y,z,sxx,syy,szz,sxy,syz,sxz,von_mises,tresca,max_principal\n");
        let a = &v.arrays;
        let (nx, ny) = (v.x.len(), v.y.len());
        for (k, z) in v.z.iter().enumerate() {
            for (j, y) in v.y.iter().enumerate() {
                for (i, x) in v.x.iter().enumerate() {
                    let m = (k * ny + j) * nx + i;
                    let _ = writeln!(
                        s,
                        "{x},{y},{z},{},{},{},{},{},{},{},{},{}",
                        a.sxx[m],
                        a.syy[m],
                        a.szz[m],
                        a.sxy[m],
                        a.syz[m],
                        a.sxz[m],
                        a.von_mises[m],
                        a.tresca[m],
                        a.max_principal[m]
                    );
                }
            }
        }
        files.push(("field.csv".to_string(), std::mem::take(&mut s)));
        if v.values.is_none() {
            for (name, data) in [
                ("sxx", &a.sxx),
                ("syy", &a.syy),
                ("szz", &a.szz),
                ("sxy", &a.sxy),
                ("syz", &a.syz),
                ("sxz", &a.sxz),
                ("von_mises", &a.von_mises),
                ("tresca", &a.tresca),
                ("max_principal", &a.max_principal),
            ] {
                binary.push((format!("field_{name}.npy"), npy(data, &v.shape)));
            }
            for (name, data) in [("x", &v.x), ("y", &v.y), ("z", &v.z)] {
                binary.push((format!("field_{name}.npy"), npy(data, &[data.len()])));
            }
        }
    }
    if let Some(c) = &out.cycle {
        s.push_str("T_N,delta_m\n");
        for (t, d) in c.t.iter().zip(&c.delta) {
            let _ = writeln!(s, "{t},{d}");
        }
        files.push(("cycle.csv".to_string(), std::mem::take(&mut s)));
    }
    if let Some(h) = out.history.as_ref().filter(|h| !h.distance.is_empty()) {
        // Transient rolling: the creep forces and creepages along the distance rolled.
        s.push_str("step,distance_m,fx_N,fy_N,mz_N_m,creepage_longitudinal,creepage_lateral,shift_m,stick_fraction,dissipated_J,work_J,elastic_energy_J\n");
        for i in 0..h.distance.len() {
            let _ = writeln!(
                s,
                "{i},{},{},{},{},{},{},{},{},{},{},{}",
                h.distance[i],
                h.fx[i],
                h.fy[i],
                h.mz[i],
                h.creepage_longitudinal[i],
                h.creepage_lateral[i],
                h.shift[i],
                h.stick_fraction[i],
                h.dissipated[i],
                h.work[i],
                h.elastic_energy[i]
            );
        }
        files.push(("history.csv".to_string(), std::mem::take(&mut s)));
    } else if let Some(h) = &out.history {
        s.push_str("step,corner,tangential_N,normal_N,moment_N_m,shift_m,rotation_rad,stick_fraction,dissipated_J,work_J,elastic_energy_J,gross_slip\n");
        for i in 0..h.tangential.len() {
            let corner =
                h.corners.iter().position(|c| *c == i).map_or(String::new(), |c| c.to_string());
            let _ = writeln!(
                s,
                "{i},{corner},{},{},{},{},{},{},{},{},{},{}",
                h.tangential[i],
                h.normal[i],
                h.moment[i],
                h.shift[i],
                h.rotation[i],
                h.stick_fraction[i],
                h.dissipated[i],
                h.work[i],
                h.elastic_energy[i],
                u8::from(h.gross_slip[i])
            );
        }
        files.push(("history.csv".to_string(), std::mem::take(&mut s)));
    }
    if let Some(c) = &out.load_curve {
        s.push_str("normal_N,approach_m,area_m2,fraction,p0_Pa,iterations\n");
        for i in 0..c.normal.len() {
            let _ = writeln!(
                s,
                "{},{},{},{},{},{}",
                c.normal[i], c.approach[i], c.area[i], c.fraction[i], c.p0[i], c.iterations[i]
            );
        }
        files.push(("load_curve.csv".to_string(), std::mem::take(&mut s)));
    }
    if let Some(w) = &out.wheel_rail {
        // Each patch's maps, (ns, nx) as a surface's are (ny, nx).
        for (k, p) in w.patches.iter().enumerate() {
            let m = &p.maps;
            let shape = [m.s.len(), m.x.len()];
            if m.pressure.len() != shape[0] * shape[1] {
                continue;
            }
            binary.push((format!("patch{k}_x.npy"), npy(&m.x, &[shape[1]])));
            binary.push((format!("patch{k}_s.npy"), npy(&m.s, &[shape[0]])));
            binary.push((format!("patch{k}_pressure.npy"), npy(&m.pressure, &shape)));
            binary.push((format!("patch{k}_gap.npy"), npy(&m.gap, &shape)));
            if let (Some(qx), Some(qs)) = (&m.qx, &m.qs) {
                binary.push((format!("patch{k}_qx.npy"), npy(qx, &shape)));
                binary.push((format!("patch{k}_qs.npy"), npy(qs, &shape)));
                let st: Vec<f64> = m.stick.iter().map(|&v| f64::from(v)).collect();
                binary.push((format!("patch{k}_stick.npy"), npy(&st, &shape)));
            }
        }
    }
    let svgs = if plots {
        crate::plots::render(out, ctx.map(|c| c.plan)).map_err(|e| {
            SceneError::new(ErrorKind::Io, format!("cannot draw the plots: {e}"))
                .hint("run without outputs.plots; nothing was written or changed")
        })?
    } else {
        Vec::new()
    };
    files.push(("report.html".to_string(), crate::report::render(out, ctx, &svgs, plots)));
    files.extend(svgs);
    let mut all: Vec<(String, Vec<u8>)> =
        files.into_iter().map(|(n, t)| (n, t.into_bytes())).collect();
    all.extend(binary);
    Ok(all)
}

/// A little-endian float64 array in the `.npy` format (version 1.0): the magic string, the
/// header length, a Python-literal header (`descr`, `fortran_order`, `shape`) padded with
/// spaces to a multiple of 64 bytes and ending in a newline, then the data in C order.
pub(crate) fn npy(data: &[f64], shape: &[usize]) -> Vec<u8> {
    let dims = match shape {
        [n] => format!("({n},)"),
        _ => format!("({})", shape.iter().map(usize::to_string).collect::<Vec<_>>().join(", ")),
    };
    let mut header = format!("{{'descr': '<f8', 'fortran_order': False, 'shape': {dims}, }}");
    // magic (6) + version (2) + length (2) + header + '\n', a multiple of 64
    while (10 + header.len() + 1) % 64 != 0 {
        header.push(' ');
    }
    header.push('\n');
    let mut out = Vec::with_capacity(10 + header.len() + 8 * data.len());
    out.extend_from_slice(b"\x93NUMPY\x01\x00");
    out.extend_from_slice(&(header.len() as u16).to_le_bytes());
    out.extend_from_slice(header.as_bytes());
    for v in data {
        out.extend_from_slice(&v.to_le_bytes());
    }
    out
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
