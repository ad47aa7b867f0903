//! Writing a run's results: result.json, CSV of the arrays, SVG plots. All or nothing.
//!
//! Every file is rendered in memory first; then they are written into a fresh temporary
//! directory beside the target and moved into place by `rename` (same filesystem). On any
//! error the temporary directory is removed and the target is left as it was.

#![allow(clippy::result_large_err)]

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use crate::error::{ErrorKind, SceneError};
use crate::exec::outcome::{Outcome, SurfaceOut};

/// What [`write_outputs`] wrote.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Written {
    /// The output directory.
    pub dir: PathBuf,
    /// The files, in the order written.
    pub files: Vec<PathBuf>,
}

fn io_err(dir: &Path, what: &str, e: impl std::fmt::Display) -> SceneError {
    SceneError::new(
        ErrorKind::Io,
        format!("cannot write the results to {}: {what}: {e}", dir.display()),
    )
    .hint("choose a directory you can write (--out DIR); nothing was written")
}

/// The files of `out` as (name, contents), rendered in memory.
///
/// # Errors
/// A [`SceneError`] (kind [`ErrorKind::Io`]) if a plot cannot be drawn.
pub(crate) fn render(out: &Outcome, plots: bool) -> Result<Vec<(String, String)>, SceneError> {
    let mut files = vec![("result.json".to_string(), out.to_json() + "\n")];
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
        SurfaceOut::Grid { x, y, p, qx, qy, stick } if !x.is_empty() => {
            s.push_str("x_m,y_m,p_Pa,qx_Pa,qy_Pa,stick\n");
            for (i, xi) in x.iter().enumerate() {
                for (j, yj) in y.iter().enumerate() {
                    if stick[i][j] >= 0 {
                        let _ = writeln!(
                            s,
                            "{xi},{yj},{},{},{},{}",
                            p[i][j], qx[i][j], qy[i][j], stick[i][j]
                        );
                    }
                }
            }
            files.push(("surface.csv".to_string(), std::mem::take(&mut s)));
        }
        _ => {}
    }
    let f = &out.field;
    if !f.x.is_empty() {
        s.push_str("x_m,y_m,sxx_Pa,syy_Pa,sxy_Pa\n");
        for (j, y) in f.y.iter().enumerate() {
            for (i, x) in f.x.iter().enumerate() {
                let _ = writeln!(s, "{x},{y},{},{},{}", f.sxx[j][i], f.syy[j][i], f.sxy[j][i]);
            }
        }
        files.push(("field.csv".to_string(), std::mem::take(&mut s)));
    }
    if let Some(c) = &out.cycle {
        s.push_str("T_N,delta_m\n");
        for (t, d) in c.t.iter().zip(&c.delta) {
            let _ = writeln!(s, "{t},{d}");
        }
        files.push(("cycle.csv".to_string(), std::mem::take(&mut s)));
    }
    if plots {
        let svgs = crate::plots::render(out).map_err(|e| {
            SceneError::new(ErrorKind::Io, format!("cannot draw the plots: {e}"))
                .hint("run without outputs.plots; nothing was written")
        })?;
        files.extend(svgs);
    }
    Ok(files)
}

/// Write result.json, the CSV files and (when `plots`) the SVG plots of `out` into `dir`,
/// all or nothing (see the module documentation). `dir` is created if it does not exist;
/// files of the same names in an existing `dir` are replaced.
///
/// # Errors
/// A [`SceneError`] of kind [`ErrorKind::Io`] naming the directory; no file is left behind.
pub fn write_outputs(out: &Outcome, dir: &Path, plots: bool) -> Result<Written, SceneError> {
    let files = render(out, plots)?;
    if dir.exists() && !dir.is_dir() {
        return Err(io_err(dir, "it exists and is not a directory", "refusing to replace a file"));
    }
    let parent = match dir.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    std::fs::create_dir_all(&parent).map_err(|e| io_err(dir, "cannot create its parent", e))?;
    let stamp = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos());
    let name = dir.file_name().map_or_else(|| "out".into(), |n| n.to_string_lossy().into_owned());
    let tmp = parent.join(format!(".{name}.stickslip-tmp-{}-{stamp}", std::process::id()));
    std::fs::create_dir(&tmp)
        .map_err(|e| io_err(dir, "cannot create a temporary directory beside it", e))?;
    let cleanup = |e: SceneError| -> SceneError {
        let _ = std::fs::remove_dir_all(&tmp);
        e
    };
    for (n, text) in &files {
        std::fs::write(tmp.join(n), text).map_err(|e| cleanup(io_err(dir, n, e)))?;
    }
    let mut written = Vec::with_capacity(files.len());
    if dir.exists() {
        // Probe that the target accepts new entries before moving anything into it.
        let probe = dir.join(format!(".stickslip-probe-{}-{stamp}", std::process::id()));
        std::fs::write(&probe, b"")
            .map_err(|e| cleanup(io_err(dir, "the directory is not writable", e)))?;
        let _ = std::fs::remove_file(&probe);
        for (n, _) in &files {
            std::fs::rename(tmp.join(n), dir.join(n)).map_err(|e| cleanup(io_err(dir, n, e)))?;
            written.push(dir.join(n));
        }
        let _ = std::fs::remove_dir_all(&tmp);
    } else {
        std::fs::rename(&tmp, dir)
            .map_err(|e| cleanup(io_err(dir, "cannot move the results into place", e)))?;
        written.extend(files.iter().map(|(n, _)| dir.join(n)));
    }
    Ok(Written { dir: dir.to_path_buf(), files: written })
}
