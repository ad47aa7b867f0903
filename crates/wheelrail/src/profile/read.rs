//! The profile file formats: SIMPACK (`.prr`, `.prw`), MiniProf (`.ban`, `.whl`) and plain
//! two-column text or CSV.
//!
//! Each reader turns text into raw points $(y, z)$ in the file's own length unit, each with
//! the line it came from, in the canonical orientation of the format (below), plus what the
//! file says about itself (rail or wheel, its length unit). Units, the caller's mirroring,
//! the checks and the spline follow in [`super::Profile::read`].
//!
//! * **SIMPACK** (`.prr` rail, `.prw` wheel): `header.begin … header.end` with `type`
//!   (0 rail, 1 wheel), then `spline.begin … spline.end` with the processing options and the
//!   `point.begin … point.end` block of `y z [weight]` lines; `!` starts a comment. The
//!   options the points still need are applied as SIMPACK does, in its order: `shift.y`,
//!   `shift.z`; the bounds `bound.y.min/max`, `bound.z.min/max` when min < max; `mirror.y`,
//!   `mirror.z`. `units.len.f` (file units per metre) states the file's length unit.
//!   A non-zero `rotate` is refused (its sense is not stated in the file; give the cant as
//!   `rail_cant` instead). SIMPACK's own `approx.smooth` is not used: the smoothing is ours
//!   ([`super::ProfileOptions::smoothing`]).
//! * **MiniProf** (`.ban` rail, `.whl` wheel): a `.ban` file has `key=value` header lines
//!   (among them `ColumnDef=X,Y,…`, naming the columns) and then lines of numbers; a `.whl`
//!   file has a 7-line header and then lines of numbers. MiniProf's $Y$ points out of the
//!   measured body (up for a rail, down for a wheel), and its $X$ runs from the gauge face
//!   to the field side for a wheel and the other way for a rail, so the canonical
//!   $(y, z)$ is $(-X, -Y)$ for a rail and $(X, Y)$ for a wheel.
//! * **Plain text / CSV** (any other name): two columns $y$, $z$ (further columns ignored)
//!   separated by blanks, commas, semicolons or tabs; lines starting with `#`, `%`, `!` or
//!   `//` are comments; non-numeric lines before the first point (a CSV header) are skipped.
//!   The columns are taken as canonical.
//!
//! The canonical orientation is CONTACT's "right-side profile": $y$ towards the field side
//! (the gauge face of a rail and the flange of a wheel at the small-$y$ end), $z$ pointing
//! down (into the rail; out of the wheel).

use super::Role;
use crate::error::{Error, Result};

/// A profile file format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Format {
    /// SIMPACK `.prr` (rail) / `.prw` (wheel).
    Simpack,
    /// MiniProf `.ban` (rail) / `.whl` (wheel).
    MiniProf,
    /// Plain two-column text or CSV.
    Table,
}

impl Format {
    /// The format a file name's extension implies (case-insensitive): `.prr`, `.prw`
    /// SIMPACK; `.ban`, `.whl` MiniProf; anything else a plain table.
    #[must_use]
    pub fn from_name(name: &str) -> Self {
        match extension(name).as_deref() {
            Some("prr" | "prw") => Format::Simpack,
            Some("ban" | "whl") => Format::MiniProf,
            _ => Format::Table,
        }
    }
}

/// The role a file's extension implies (`.prr`, `.ban` rail; `.prw`, `.whl` wheel).
pub(crate) fn role_of_extension(name: &str) -> Option<Role> {
    match extension(name).as_deref() {
        Some("prr" | "ban") => Some(Role::Rail),
        Some("prw" | "whl") => Some(Role::Wheel),
        _ => None,
    }
}

fn extension(name: &str) -> Option<String> {
    let base = name.rsplit(['/', '\\']).next().unwrap_or(name);
    base.rsplit_once('.').map(|(_, e)| e.to_ascii_lowercase())
}

/// What a reader found.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Raw {
    /// $(y, z, \text{line})$ in the file's unit, canonical orientation of the format.
    pub points: Vec<(f64, f64, usize)>,
    /// The role the file states (SIMPACK `type`), if any.
    pub role: Option<Role>,
    /// File length units per metre the file states (SIMPACK `units.len.f`), if any.
    pub units_per_metre: Option<f64>,
}

fn format_err(name: &str, line: Option<usize>, message: impl Into<String>) -> Error {
    Error::ProfileFormat { name: name.to_string(), line, message: message.into() }
}

/// Parse a number as Rust does (so `NaN` and `inf` are numbers; the checks refuse them with
/// their line).
fn number(tok: &str) -> Option<f64> {
    tok.trim().parse::<f64>().ok()
}

/// The text before a `!` comment.
fn strip_bang(line: &str) -> &str {
    line.split('!').next().unwrap_or("")
}

pub(crate) fn read(text: &str, name: &str, format: Format, role: Role) -> Result<Raw> {
    match format {
        Format::Simpack => simpack(text, name),
        Format::MiniProf => miniprof(text, name, role),
        Format::Table => table(text, name),
    }
}

/// SIMPACK `.prr` / `.prw`.
fn simpack(text: &str, name: &str) -> Result<Raw> {
    let mut role = None;
    let mut units = None;
    let (mut shift_y, mut shift_z, mut rotate) = (0.0, 0.0, 0.0);
    let mut bound = [1.0, 0.0, 1.0, 0.0];
    let (mut mirror_y, mut mirror_z) = (false, false);
    let mut in_points = false;
    let mut seen_points = false;
    let mut points = Vec::new();
    let mut rotate_line = 0;
    // `type` means rail or wheel only in the header block (the spline block has its own).
    let mut in_header = false;
    for (k, line) in text.lines().enumerate() {
        let ln = k + 1;
        let body = strip_bang(line).trim();
        if body.is_empty() {
            continue;
        }
        if in_points {
            if body == "point.end" {
                in_points = false;
                continue;
            }
            let toks: Vec<&str> = body.split_whitespace().collect();
            if toks.len() < 2 {
                return Err(format_err(
                    name,
                    Some(ln),
                    format!("expected `y z` in the point block, found `{body}`"),
                ));
            }
            match (number(toks[0]), number(toks[1])) {
                (Some(y), Some(z)) => points.push((y, z, ln)),
                _ => {
                    return Err(format_err(
                        name,
                        Some(ln),
                        format!("expected two numbers `y z` in the point block, found `{body}`"),
                    ))
                }
            }
            continue;
        }
        if body == "header.begin" || body == "header.end" {
            in_header = body == "header.begin";
            continue;
        }
        if body == "point.begin" {
            in_points = true;
            seen_points = true;
            continue;
        }
        let Some((key, value)) = body.split_once('=') else { continue };
        let (key, value) = (key.trim(), value.trim());
        let num = || {
            number(value).ok_or_else(|| {
                format_err(name, Some(ln), format!("`{key}` needs a number, found `{value}`"))
            })
        };
        match key {
            "type" if in_header => {
                role = match num()? {
                    0.0 => Some(Role::Rail),
                    1.0 => Some(Role::Wheel),
                    v => {
                        return Err(format_err(
                            name,
                            Some(ln),
                            format!("`type` is 0 (rail) or 1 (wheel), found {v}"),
                        ))
                    }
                }
            }
            "units.len.f" => units = Some(num()?),
            "shift.y" => shift_y = num()?,
            "shift.z" => shift_z = num()?,
            "rotate" => {
                rotate = num()?;
                rotate_line = ln;
            }
            "bound.y.min" => bound[0] = num()?,
            "bound.y.max" => bound[1] = num()?,
            "bound.z.min" => bound[2] = num()?,
            "bound.z.max" => bound[3] = num()?,
            "mirror.y" => mirror_y = num()? != 0.0,
            "mirror.z" => mirror_z = num()? != 0.0,
            _ => {}
        }
    }
    if in_points {
        return Err(format_err(name, None, "the point block has no `point.end`"));
    }
    if !seen_points {
        return Err(format_err(
            name,
            None,
            "no `point.begin … point.end` block: not a SIMPACK profile",
        ));
    }
    if rotate != 0.0 {
        return Err(format_err(
            name,
            Some(rotate_line),
            format!("`rotate = {rotate}` is not supported: give the points unrotated and the cant as rail_cant"),
        ));
    }
    if let Some(u) = units {
        if !(u.is_finite() && u > 0.0) {
            return Err(format_err(
                name,
                None,
                format!("`units.len.f` must be positive, found {u}"),
            ));
        }
    }
    let mut out = Vec::with_capacity(points.len());
    for (y, z, ln) in points {
        let (y, z) = (y + shift_y, z + shift_z);
        if bound[0] < bound[1] && !(bound[0]..=bound[1]).contains(&y) {
            continue;
        }
        if bound[2] < bound[3] && !(bound[2]..=bound[3]).contains(&z) {
            continue;
        }
        out.push((if mirror_y { -y } else { y }, if mirror_z { -z } else { z }, ln));
    }
    Ok(Raw { points: out, role, units_per_metre: units })
}

/// MiniProf `.ban` / `.whl`.
fn miniprof(text: &str, name: &str, role: Role) -> Result<Raw> {
    let wheel_file = matches!(extension(name).as_deref(), Some("whl"));
    let (mut xcol, mut ycol) = (0usize, 1usize);
    let mut points = Vec::new();
    let mut started = false;
    for (k, line) in text.lines().enumerate() {
        let ln = k + 1;
        // A .whl file: a 7-line header.
        if wheel_file && ln <= 7 {
            continue;
        }
        let body = line.trim().trim_matches('"');
        if body.is_empty() {
            continue;
        }
        if let Some((key, value)) = body.split_once('=') {
            if started {
                return Err(format_err(
                    name,
                    Some(ln),
                    format!("a header line `{body}` among the points"),
                ));
            }
            if key.trim().eq_ignore_ascii_case("ColumnDef") {
                let cols: Vec<String> =
                    value.split(',').map(|c| c.trim().to_ascii_uppercase()).collect();
                match (cols.iter().position(|c| c == "X"), cols.iter().position(|c| c == "Y")) {
                    (Some(x), Some(y)) => (xcol, ycol) = (x, y),
                    _ => {
                        return Err(format_err(
                            name,
                            Some(ln),
                            format!("`ColumnDef={value}` names no X and Y columns"),
                        ))
                    }
                }
            }
            continue;
        }
        let toks: Vec<&str> = body.split([' ', '\t', ',', ';']).filter(|t| !t.is_empty()).collect();
        let nums: Option<Vec<f64>> = toks.iter().map(|t| number(t)).collect();
        match nums {
            Some(v) if v.len() > xcol.max(ycol) => {
                started = true;
                let (x, y) = (v[xcol], v[ycol]);
                let (py, pz) = match role {
                    Role::Rail => (-x, -y),
                    Role::Wheel => (x, y),
                };
                points.push((py, pz, ln));
            }
            _ if !started && !wheel_file => continue,
            _ => {
                return Err(format_err(
                    name,
                    Some(ln),
                    format!("expected a line of numbers (columns X and Y), found `{body}`"),
                ))
            }
        }
    }
    Ok(Raw { points, role: None, units_per_metre: None })
}

/// Plain two-column text or CSV.
fn table(text: &str, name: &str) -> Result<Raw> {
    let mut points = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let ln = k + 1;
        let body = line.trim();
        if body.is_empty() || ["#", "%", "!", "//"].iter().any(|c| body.starts_with(c)) {
            continue;
        }
        let toks: Vec<&str> = body.split([' ', '\t', ',', ';']).filter(|t| !t.is_empty()).collect();
        let y = toks.first().and_then(|t| number(t));
        let z = toks.get(1).and_then(|t| number(t));
        match (y, z) {
            (Some(y), Some(z)) => points.push((y, z, ln)),
            _ if points.is_empty() => continue, // a header line
            _ => {
                return Err(format_err(
                    name,
                    Some(ln),
                    format!("expected two numbers `y z`, found `{body}`"),
                ))
            }
        }
    }
    Ok(Raw { points, role: None, units_per_metre: None })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_from_names() {
        assert_eq!(Format::from_name("a/b/MBench_UIC60_v3.prr"), Format::Simpack);
        assert_eq!(Format::from_name("wheel.PRW"), Format::Simpack);
        assert_eq!(Format::from_name("rail.ban"), Format::MiniProf);
        assert_eq!(Format::from_name("w.whl"), Format::MiniProf);
        assert_eq!(Format::from_name("rail.csv"), Format::Table);
        assert_eq!(Format::from_name("rail"), Format::Table);
        assert_eq!(role_of_extension("x.prw"), Some(Role::Wheel));
        assert_eq!(role_of_extension("x.ban"), Some(Role::Rail));
    }

    #[test]
    fn simpack_options_and_comments() {
        let text = "header.begin\n type = 1 ! wheel\nheader.end\nspline.begin\n shift.y = 1\n mirror.y = 1\n units.len.f = 1000\n point.begin\n ! comment\n!9 9\n1.0 2.0 1.0\n3.0\t4.0\n point.end\nspline.end\n";
        let r = simpack(text, "w.prw").unwrap();
        assert_eq!(r.role, Some(Role::Wheel));
        assert_eq!(r.units_per_metre, Some(1000.0));
        assert_eq!(r.points, vec![(-2.0, 2.0, 11), (-4.0, 4.0, 12)]);
    }

    #[test]
    fn table_with_header_and_bad_line() {
        let r = table("y,z\n1,2\n3;4\n", "p.csv").unwrap();
        assert_eq!(r.points, vec![(1.0, 2.0, 2), (3.0, 4.0, 3)]);
        let e = table("1 2\n3 x\n", "p.txt").unwrap_err();
        assert!(matches!(e, Error::ProfileFormat { line: Some(2), .. }), "{e}");
    }
}
