//! Reading a load path from a table (`[load.history] file = "path.csv"`).
//!
//! The file is text: lines starting with `#` and blank lines are skipped, the first other
//! line is the header, and every line after it is one corner of the path. Cells are
//! separated by commas (spaces around them are ignored). A header cell is a column name,
//! optionally with its unit: `tangential [N]`, `tangential (kN)` or, as in the `history.csv`
//! a run writes, `tangential_N`, `moment_N_m` (the underscores after the name read as
//! spaces). The values are plain numbers in that unit.
//!
//! This module only reads the table: which columns a path needs, their units and the checks
//! of the values belong to the scene reader. Errors are messages that start with
//! `file:line:column`.

use std::path::{Path, PathBuf};

/// One column of the table: its name, the unit the header gives (if any), its values.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Column {
    /// The name without its unit, e.g. `tangential`.
    pub name: String,
    /// The unit written in the header, e.g. `kN`; `None` when the header gives none.
    pub unit: Option<String>,
    /// 1-based column (in characters) of the header cell, for messages.
    pub at: usize,
    /// One value per data row.
    pub values: Vec<f64>,
}

/// A table read from a file.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Table {
    /// The file as opened (relative names resolved against the scene's directory).
    pub path: PathBuf,
    /// The 1-based line of the header.
    pub header_line: usize,
    /// The 1-based line of each data row.
    pub lines: Vec<usize>,
    /// The columns, in file order.
    pub columns: Vec<Column>,
}

/// The names a header cell may carry a unit after (`name_unit`), longest first so that
/// `elastic_energy_J` is not read as `elastic` with unit `energy J`.
const NAMES: [&str; 12] = [
    "elastic_energy",
    "stick_fraction",
    "gross_slip",
    "tangential",
    "dissipated",
    "rotation",
    "normal",
    "moment",
    "corner",
    "shift",
    "step",
    "work",
];

/// Split a header cell into its name and unit.
fn header_cell(cell: &str) -> (String, Option<String>) {
    let cell = cell.trim();
    for (open, close) in [('[', ']'), ('(', ')')] {
        if let (Some(i), true) = (cell.find(open), cell.ends_with(close)) {
            let unit = cell[i + 1..cell.len() - 1].trim();
            let name = cell[..i].trim().to_string();
            return (name, (!unit.is_empty()).then(|| unit.to_string()));
        }
    }
    for n in NAMES {
        if let Some(rest) = cell.strip_prefix(n).and_then(|r| r.strip_prefix('_')) {
            if !rest.is_empty() {
                return (n.to_string(), Some(rest.replace('_', " ")));
            }
        }
    }
    (cell.to_string(), None)
}

/// The cells of one line with the 1-based character column where each starts.
fn cells(line: &str) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut start = 0;
    for (i, c) in line.char_indices().chain(std::iter::once((line.len(), ','))) {
        if c == ',' {
            let cell = &line[start..i];
            let lead = cell.len() - cell.trim_start().len();
            out.push((line[..start + lead].chars().count() + 1, cell.trim()));
            start = i + 1;
        }
    }
    out
}

/// Read the table `name` (relative to the directory of `scene_file` when given), keeping
/// only the columns `wanted` accepts; a column it refuses is an error naming the column.
/// Only the kept columns must hold numbers.
pub(crate) fn read(
    name: &str,
    scene_file: Option<&Path>,
    wanted: impl Fn(&str) -> Result<bool, String>,
) -> Result<Table, String> {
    let path = match scene_file.and_then(Path::parent) {
        Some(dir) if Path::new(name).is_relative() => dir.join(name),
        _ => Path::new(name).to_path_buf(),
    };
    let text = std::fs::read_to_string(&path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    parse(&text, path, wanted)
}

fn parse(
    text: &str,
    path: PathBuf,
    wanted: impl Fn(&str) -> Result<bool, String>,
) -> Result<Table, String> {
    let at = |line: usize, col: usize| format!("{}:{line}:{col}", path.display());
    let mut rows = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l))
        .filter(|(_, l)| !l.trim().is_empty() && !l.trim_start().starts_with('#'));
    let Some((header_line, header)) = rows.next() else {
        return Err(format!("{}: no header line (the file holds no table)", path.display()));
    };
    // Every header cell, and the index of each kept one.
    let mut names: Vec<String> = Vec::new();
    let mut columns: Vec<(usize, Column)> = Vec::new();
    for (k, (col, cell)) in cells(header).into_iter().enumerate() {
        let (name, unit) = header_cell(cell);
        if name.is_empty() {
            return Err(format!("{}: an empty column name in the header", at(header_line, col)));
        }
        if names.contains(&name) {
            return Err(format!("{}: the column `{name}` appears twice", at(header_line, col)));
        }
        if wanted(&name).map_err(|m| format!("{}: {m}", at(header_line, col)))? {
            columns.push((k, Column { name: name.clone(), unit, at: col, values: Vec::new() }));
        }
        names.push(name);
    }
    let mut lines = Vec::new();
    for (line, text) in rows {
        let row = cells(text);
        if row.len() != names.len() {
            return Err(format!(
                "{}: {} cells where the header has {} columns",
                at(line, 1),
                row.len(),
                names.len()
            ));
        }
        for (k, c) in &mut columns {
            let (col, cell) = row[*k];
            c.values.push(cell.parse::<f64>().map_err(|_| {
                format!("{}: `{cell}` in column `{}` is not a number", at(line, col), c.name)
            })?);
        }
        lines.push(line);
    }
    if lines.is_empty() {
        return Err(format!("{}: a header but no rows", at(header_line, 1)));
    }
    Ok(Table { path, header_line, lines, columns: columns.into_iter().map(|(_, c)| c).collect() })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(text: &str) -> Result<Table, String> {
        parse(text, PathBuf::from("p.csv"), |_| Ok(true))
    }

    #[test]
    fn header_units_in_brackets_parentheses_and_underscores() {
        assert_eq!(header_cell(" tangential [kN] "), ("tangential".into(), Some("kN".into())));
        assert_eq!(header_cell("normal (lbf)"), ("normal".into(), Some("lbf".into())));
        assert_eq!(header_cell("moment_N_m"), ("moment".into(), Some("N m".into())));
        assert_eq!(header_cell("elastic_energy_J"), ("elastic_energy".into(), Some("J".into())));
        assert_eq!(header_cell("stick_fraction"), ("stick_fraction".into(), None));
        assert_eq!(header_cell("shift"), ("shift".into(), None));
    }

    #[test]
    fn rows_comments_and_positions() {
        let t =
            table("# a path\n\ntangential [N], normal [N]\n0, 100\n 20 ,100\n-20, 80\n").unwrap();
        assert_eq!(t.header_line, 3);
        assert_eq!(t.lines, vec![4, 5, 6]);
        assert_eq!(t.columns[0].values, vec![0.0, 20.0, -20.0]);
        assert_eq!(t.columns[1].values, vec![100.0, 100.0, 80.0]);
        assert_eq!(t.columns[1].at, 17);
        let e = table("tangential [N], normal [N]\n0, 100\n20, x1\n").unwrap_err();
        assert!(e.starts_with("p.csv:3:5: `x1` in column `normal`"), "{e}");
        let e = table("tangential [N], normal [N]\n0, 100, 3\n").unwrap_err();
        assert!(e.starts_with("p.csv:2:1: 3 cells"), "{e}");
        let e = table("tangential [N], tangential [kN]\n0, 1\n").unwrap_err();
        assert!(e.contains("appears twice"), "{e}");
        assert!(table("# only a comment\n").unwrap_err().contains("no header"));
        assert!(table("tangential [N]\n").unwrap_err().contains("no rows"));
        // Columns left out need not hold numbers; a refused one is named at its place.
        let t = parse("gross_slip, tangential_N\nfalse, 2\n", PathBuf::from("p.csv"), |n| {
            Ok(n == "tangential")
        })
        .unwrap();
        assert_eq!((t.columns.len(), t.columns[0].values[0]), (1, 2.0));
        let e = parse("a, b\n1, 2\n", PathBuf::from("p.csv"), |n| {
            if n == "b" {
                Err("no b".into())
            } else {
                Ok(true)
            }
        })
        .unwrap_err();
        assert_eq!(e, "p.csv:1:4: no b");
    }
}
