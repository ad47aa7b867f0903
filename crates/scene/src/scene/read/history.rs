//! `[load.history]`: a load path's corners, as lists or from a table (`file`), in SI with
//! each corner's span (or its file and line) recorded for refusals.

use toml::Spanned;

use super::Reader;
use crate::error::{ErrorKind, SceneError};
use crate::raw::SQty;
use crate::scene::{History, HistoryControl, PathSource};
use crate::units::{parse_quantity, Dim};

/// `[load.history]`: the corner values with their units, each element's span recorded as
/// `load.history.<key>[i]` so that a refusal points at the corner.
pub(super) fn history(
    cx: &Reader<'_>,
    h: &Spanned<crate::raw::RawHistory>,
    force_dim: Dim,
    force_name: &'static str,
) -> Result<History, SceneError> {
    cx.record("load.history", h.span());
    let r = h.get_ref();
    let list = |v: &Spanned<Vec<SQty>>, key: &str, dim: Dim, name: &'static str| {
        cx.record(key, v.span());
        v.get_ref()
            .iter()
            .enumerate()
            .map(|(i, q)| cx.qty(q, &format!("{key}[{i}]"), dim, name))
            .collect::<Result<Vec<f64>, SceneError>>()
    };
    let (control, tangential, normal, moment, source) = if let Some(file) = &r.file {
        history_file(cx, r, file, force_dim, force_name)?
    } else {
        let (control, tangential) = match (&r.tangential, &r.shift) {
            (Some(t), None) => {
                (HistoryControl::Force, list(t, "load.history.tangential", force_dim, force_name)?)
            }
            (None, Some(d)) => {
                (HistoryControl::Shift, list(d, "load.history.shift", Dim::LENGTH, "shift")?)
            }
            _ => {
                return Err(cx
                    .err(
                        ErrorKind::Schema,
                        "load.history",
                        Some(h.span()),
                        "give exactly one of `tangential` (force control) and `shift` (displacement control), or a `file` of corners",
                    )
                    .hint("e.g. tangential = [\"0 N\", \"20 N\", \"-20 N\", \"20 N\"]"))
            }
        };
        for (key, given) in [("columns", r.columns.is_some()), ("units", r.units.is_some())] {
            if given {
                let span = if key == "columns" {
                    r.columns.as_ref().map(Spanned::span)
                } else {
                    r.units.as_ref().map(Spanned::span)
                };
                return Err(cx
                    .err(
                        ErrorKind::Schema,
                        &format!("load.history.{key}"),
                        span,
                        format!("`{key}` describes a `file` of corners, and none is given"),
                    )
                    .hint("remove it, or give the corners in file = \"path.csv\""));
            }
        }
        let normal = match &r.normal {
            Some(n) => Some(list(n, "load.history.normal", force_dim, force_name)?),
            None => None,
        };
        let moment = match &r.moment {
            Some(m) => Some(list(m, "load.history.moment", Dim::MOMENT, "moment")?),
            None => None,
        };
        (control, tangential, normal, moment, None)
    };
    let steps = match &r.steps {
        Some(s) => {
            cx.record("load.history.steps", s.span());
            let v = *s.get_ref();
            usize::try_from(v).unwrap_or(0)
        }
        None => History::DEFAULT_STEPS,
    };
    Ok(History { control, tangential, normal, moment, steps, source })
}

/// The columns a load path's file may hold, with the dimension of each.
const PATH_COLUMNS: [&str; 4] = ["tangential", "shift", "normal", "moment"];

/// What a load path's file gives: control, tangential (or shift), normal, moment, source.
type PathColumns =
    (HistoryControl, Vec<f64>, Option<Vec<f64>>, Option<Vec<f64>>, Option<PathSource>);

/// `[load.history] file`: the corners from a table (`path_file`), each column in its unit
/// (the header's, or `units.<column>`). Every corner's key (`load.history.tangential[i]`
/// and so on) points at `file` in the scene, and the corner's line is kept for messages.
fn history_file(
    cx: &Reader<'_>,
    r: &crate::raw::RawHistory,
    file: &Spanned<String>,
    force_dim: Dim,
    force_name: &'static str,
) -> Result<PathColumns, SceneError> {
    cx.record("load.history.file", file.span());
    let io = |msg: String| {
        cx.err(ErrorKind::Io, "load.history.file", Some(file.span()), msg).hint(
            "a text table relative to the scene file: a header line such as `tangential [N], normal [N]`, then one row of plain numbers per corner",
        )
    };
    for (key, given) in [
        ("tangential", r.tangential.as_ref().map(Spanned::span)),
        ("shift", r.shift.as_ref().map(Spanned::span)),
        ("normal", r.normal.as_ref().map(Spanned::span)),
        ("moment", r.moment.as_ref().map(Spanned::span)),
    ] {
        if let Some(span) = given {
            return Err(cx
                .err(
                    ErrorKind::Schema,
                    &format!("load.history.{key}"),
                    Some(span),
                    format!("`{key}` given both as a list and by `file`"),
                )
                .hint("give the corners either as lists or in the file, not both"));
        }
    }
    let picked: Option<Vec<String>> = match &r.columns {
        Some(c) => {
            cx.record("load.history.columns", c.span());
            let mut v = Vec::new();
            for name in c.get_ref() {
                if !PATH_COLUMNS.contains(&name.get_ref().as_str()) {
                    return Err(cx
                        .err(
                            ErrorKind::Schema,
                            "load.history.columns",
                            Some(name.span()),
                            format!("`{}` is not a column of a load path", name.get_ref()),
                        )
                        .hint("pick from: tangential or shift, normal, moment"));
                }
                v.push(name.get_ref().clone());
            }
            Some(v)
        }
        None => None,
    };
    let table = crate::scene::path_file::read(file.get_ref(), cx.file.as_deref(), |name| {
        match &picked {
            Some(p) => Ok(p.iter().any(|c| c == name)),
            None if PATH_COLUMNS.contains(&name) => Ok(true),
            None => Err(format!(
                "the column `{name}` is not part of a load path (tangential or shift, normal, moment); to read some columns of a wider table, such as a run's history.csv, name them: columns = [\"tangential\", \"normal\"]"
            )),
        }
    })
    .map_err(io)?;
    if let Some(p) = &picked {
        if let Some(missing) = p.iter().find(|c| table.columns.iter().all(|t| &t.name != *c)) {
            return Err(io(format!(
                "{}:{}: no column `{missing}` in the header",
                table.path.display(),
                table.header_line
            )));
        }
    }
    let units = r.units.as_ref().map(Spanned::get_ref);
    let unit_key = |name: &str| -> Option<&Spanned<String>> {
        let u = units?;
        match name {
            "tangential" => u.tangential.as_ref(),
            "shift" => u.shift.as_ref(),
            "normal" => u.normal.as_ref(),
            _ => u.moment.as_ref(),
        }
    };
    let mut out: [Option<Vec<f64>>; 4] = [None, None, None, None];
    for c in &table.columns {
        let slot = PATH_COLUMNS.iter().position(|n| *n == c.name).unwrap_or(0);
        let (dim, what) = match c.name.as_str() {
            "shift" => (Dim::LENGTH, "shift"),
            "moment" => (Dim::MOMENT, "moment"),
            _ => (force_dim, force_name),
        };
        let factor = match (&c.unit, unit_key(&c.name)) {
            (Some(_), Some(u)) => {
                return Err(cx
                    .err(
                        ErrorKind::Schema,
                        &format!("load.history.units.{}", c.name),
                        Some(u.span()),
                        format!(
                            "the unit of `{}` is given twice: in the header of {} and here",
                            c.name,
                            table.path.display()
                        ),
                    )
                    .hint("keep one of them"))
            }
            (Some(u), None) => parse_quantity(&format!("1 {u}"), dim, what).map_err(|e| {
                io(format!("{}:{}:{}: {e}", table.path.display(), table.header_line, c.at))
            })?,
            (None, Some(u)) => {
                let key = format!("load.history.units.{}", c.name);
                cx.record(&key, u.span());
                parse_quantity(&format!("1 {}", u.get_ref()), dim, what).map_err(|e| {
                    cx.err(ErrorKind::Unit, &key, Some(u.span()), e.to_string())
                        .hint(format!("a unit of {what} ({dim})"))
                })?
            }
            (None, None) => {
                return Err(io(format!(
                    "{}:{}:{}: the column `{}` has no unit",
                    table.path.display(),
                    table.header_line,
                    c.at,
                    c.name
                )))
            }
        };
        let mut v = Vec::with_capacity(c.values.len());
        for (x, line) in c.values.iter().zip(&table.lines) {
            let si = x * factor;
            if !si.is_finite() {
                return Err(io(format!(
                    "{}:{line}: the {} value {x} is not a finite number in SI",
                    table.path.display(),
                    c.name
                )));
            }
            v.push(si);
        }
        for i in 0..v.len() {
            cx.record(&format!("load.history.{}[{i}]", c.name), file.span());
        }
        out[slot] = Some(v);
    }
    let [t, s, n, m] = out;
    let (control, tangential) = match (t, s) {
        (Some(t), None) => (HistoryControl::Force, t),
        (None, Some(s)) => (HistoryControl::Shift, s),
        (t, _) => {
            return Err(io(format!(
                "{}:{}: {}",
                table.path.display(),
                table.header_line,
                if t.is_some() {
                    "both a `tangential` and a `shift` column: a path prescribes one of them (name the one to read in `columns`)"
                } else {
                    "neither a `tangential` nor a `shift` column"
                }
            )))
        }
    };
    Ok((control, tangential, n, m, Some(PathSource { file: table.path, lines: table.lines })))
}
