//! `--vary` specifications: a dotted scene key and its values, as a range
//! (`key=start:end:count`) or a list (`key=v1,v2,...`).

use std::fmt;

/// One value a varied key takes: a number, or text (a quantity with a unit such as
/// `"10 N"`, or a word such as `"fast"`), or a boolean.
#[derive(Debug, Clone, PartialEq)]
pub enum VaryValue {
    /// An integer written without a decimal point or exponent (`32`); written to the scene
    /// as a TOML integer, so integer keys such as `solver.grid` accept it.
    Integer(i64),
    /// A number (`0.3`, `1e-10`).
    Number(f64),
    /// `true` or `false`.
    Bool(bool),
    /// Anything else, written to the scene as a TOML string (`10 N`, `fast`).
    Text(String),
}

impl VaryValue {
    /// Read one value: an integer, a number, a boolean, or else text (surrounding quotes
    /// removed).
    pub fn parse(s: &str) -> VaryValue {
        let s = s.trim();
        if let Ok(i) = s.parse::<i64>() {
            return VaryValue::Integer(i);
        }
        if let Ok(x) = s.parse::<f64>() {
            if x.is_finite() {
                return VaryValue::Number(x);
            }
        }
        match s {
            "true" => VaryValue::Bool(true),
            "false" => VaryValue::Bool(false),
            _ => {
                let unquoted = s
                    .strip_prefix('"')
                    .and_then(|t| t.strip_suffix('"'))
                    .or_else(|| s.strip_prefix('\'').and_then(|t| t.strip_suffix('\'')))
                    .unwrap_or(s);
                VaryValue::Text(unquoted.to_string())
            }
        }
    }

    /// The value as a number, when it is one.
    pub fn as_number(&self) -> Option<f64> {
        match self {
            VaryValue::Integer(i) => Some(*i as f64),
            VaryValue::Number(x) => Some(*x),
            _ => None,
        }
    }

    /// The TOML value written into the scene.
    pub(crate) fn to_toml(&self) -> toml_edit::Value {
        match self {
            VaryValue::Integer(i) => toml_edit::Value::from(*i),
            VaryValue::Number(x) => toml_edit::Value::from(*x),
            VaryValue::Bool(b) => toml_edit::Value::from(*b),
            VaryValue::Text(t) => toml_edit::Value::from(t.as_str()),
        }
    }
}

impl fmt::Display for VaryValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            VaryValue::Integer(i) => write!(f, "{i}"),
            VaryValue::Number(x) => write!(f, "{}", super::table::format_f64(*x)),
            VaryValue::Bool(b) => write!(f, "{b}"),
            VaryValue::Text(t) => write!(f, "{t}"),
        }
    }
}

/// A varied key and its values, in order.
#[derive(Debug, Clone, PartialEq)]
pub struct Vary {
    /// The dotted scene key, e.g. `load.tangential`.
    pub key: String,
    /// The values, in the order the points take them.
    pub values: Vec<VaryValue>,
    /// The specification as given (after the `=`), kept for the sweep's identity.
    pub spec: String,
}

/// A `--vary` specification that cannot be read.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct VaryError {
    /// The specification as given.
    pub spec: String,
    /// What is wrong.
    pub message: String,
    /// What is allowed.
    pub hint: String,
}

impl fmt::Display for VaryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "--vary `{}`: {}\n  hint: {}", self.spec, self.message, self.hint)
    }
}

impl std::error::Error for VaryError {}

const FORMS: &str = "write KEY=START:END:COUNT (COUNT evenly spaced values, ends included, \
e.g. load.tangential=0:0.9:10 or load.normal=\"10 N:50 N:5\") or KEY=V1,V2,... \
(e.g. load.friction=0.1,0.2 or load.normal=\"10 N\",\"20 N\")";

/// A number with an optional unit after it: `0.5`, `10 N`, `2.5 kN/m`.
fn number_and_unit(s: &str) -> Option<(f64, &str)> {
    let s = s.trim();
    let s = s.strip_prefix('"').and_then(|t| t.strip_suffix('"')).unwrap_or(s);
    let split = s.find(|c: char| c.is_whitespace()).unwrap_or(s.len());
    let (num, unit) = s.split_at(split);
    let x: f64 = num.parse().ok()?;
    x.is_finite().then_some((x, unit.trim()))
}

impl Vary {
    /// Read `KEY=START:END:COUNT` or `KEY=V1,V2,...`.
    ///
    /// # Errors
    /// A [`VaryError`] naming the specification, what is wrong and the forms allowed.
    pub fn parse(spec: &str) -> Result<Vary, VaryError> {
        let err = |message: String, hint: &str| VaryError {
            spec: spec.to_string(),
            message,
            hint: hint.to_string(),
        };
        let Some((key, rhs)) = spec.split_once('=') else {
            return Err(err("no `=` between the key and its values".into(), FORMS));
        };
        let key = key.trim();
        let key_ok = !key.is_empty()
            && key.split('.').all(|part| {
                !part.is_empty()
                    && part.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
            });
        if !key_ok {
            return Err(err(
                format!("`{key}` is not a dotted scene key"),
                "name a key of the scene format (docs/SCENES.md) with its table, e.g. \
                 load.friction or solver.grid",
            ));
        }
        let rhs = rhs.trim();
        if rhs.is_empty() {
            return Err(err(format!("no values for `{key}`"), FORMS));
        }
        let values = if rhs.contains(':') && !rhs.contains(',') {
            Self::range(rhs).map_err(|m| err(m, FORMS))?
        } else {
            let parts: Vec<&str> = rhs.split(',').map(str::trim).collect();
            if parts.iter().any(|p| p.is_empty()) {
                return Err(err("an empty value in the list".into(), FORMS));
            }
            parts.into_iter().map(VaryValue::parse).collect()
        };
        Ok(Vary { key: key.to_string(), values, spec: rhs.to_string() })
    }

    /// `START:END:COUNT`, with the same unit (or none) on both ends.
    fn range(rhs: &str) -> Result<Vec<VaryValue>, String> {
        let rhs = rhs.strip_prefix('"').and_then(|t| t.strip_suffix('"')).unwrap_or(rhs);
        let parts: Vec<&str> = rhs.split(':').collect();
        if parts.len() != 3 {
            return Err(format!(
                "a range has three parts START:END:COUNT; found {} in `{rhs}`",
                parts.len()
            ));
        }
        let count: usize = parts[2].trim().parse().map_err(|_| {
            format!("the count `{}` is not a whole number of points", parts[2].trim())
        })?;
        if count < 2 {
            return Err(format!(
                "the count is {count}; a range needs at least 2 points (give one value as a list)"
            ));
        }
        let (Some((lo, u0)), Some((hi, u1))) =
            (number_and_unit(parts[0]), number_and_unit(parts[1]))
        else {
            return Err(format!(
                "the ends `{}` and `{}` must be numbers, optionally with a unit (`10 N`)",
                parts[0].trim(),
                parts[1].trim()
            ));
        };
        if u0 != u1 {
            return Err(format!(
                "the ends have different units (`{u0}` and `{u1}`); give both in the same unit"
            ));
        }
        Ok((0..count)
            .map(|i| {
                // Ends exact; interior points evenly spaced.
                let x = if i + 1 == count {
                    hi
                } else {
                    lo + (hi - lo) * i as f64 / (count - 1) as f64
                };
                if u0.is_empty() {
                    VaryValue::Number(x)
                } else {
                    let t = super::table::format_f64(x);
                    VaryValue::Text(format!("{} {u0}", t.strip_suffix(".0").unwrap_or(&t)))
                }
            })
            .collect())
    }

    /// True when every value is a number (the table's column is then numeric).
    pub fn numeric(&self) -> bool {
        self.values.iter().all(|v| v.as_number().is_some())
    }

    /// True when every value is a whole number (the table's column is then of integers).
    pub fn integer(&self) -> bool {
        self.values.iter().all(|v| matches!(v, VaryValue::Integer(_)))
    }
}

/// A points table (`stickslip sweep --points`) that cannot be read.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PointsError {
    /// The file's name as given.
    pub file: String,
    /// The line (1-based).
    pub line: usize,
    /// What is wrong.
    pub message: String,
    /// What is allowed.
    pub hint: String,
}

impl fmt::Display for PointsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}\n  hint: {}", self.file, self.line, self.message, self.hint)
    }
}

impl std::error::Error for PointsError {}

/// The varied keys of a points table: a header of dotted scene keys separated by commas,
/// then one row per point with each key's value (a number, or a quantity with its unit such
/// as `2 mm`); blank lines and lines starting with `#` are skipped. The keys are meant to
/// be zipped ([`crate::Sweep::zipped`]): row `i` is point `i`.
///
/// # Errors
/// A [`PointsError`] naming `file` and the line: no header, a row with too few or too many
/// values or an empty one, no rows, a key that is not a dotted scene key.
pub fn read_points(text: &str, file: &str) -> Result<Vec<Vary>, PointsError> {
    let bad = |line: usize, message: String, hint: &str| PointsError {
        file: file.to_string(),
        line,
        message,
        hint: hint.to_string(),
    };
    let per_row = "give every row one value per key of the header";
    let mut rows = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let Some((header_line, header)) = rows.next() else {
        return Err(bad(
            1,
            "no header: the file holds no points".into(),
            "write a header of scene keys (e.g. position.lateral,position.yaw), then one row \
             per point",
        ));
    };
    let keys: Vec<&str> = header.split(',').map(str::trim).collect();
    let mut columns: Vec<Vec<String>> = vec![Vec::new(); keys.len()];
    for (line, l) in rows {
        let cells: Vec<&str> = l.split(',').map(str::trim).collect();
        if cells.len() != keys.len() {
            return Err(bad(
                line,
                format!("{} values for {} keys", cells.len(), keys.len()),
                per_row,
            ));
        }
        if let Some(j) = cells.iter().position(|c| c.is_empty()) {
            return Err(bad(line, format!("no value for `{}`", keys[j]), per_row));
        }
        for (c, v) in columns.iter_mut().zip(cells) {
            c.push(v.to_string());
        }
    }
    if columns.first().is_none_or(Vec::is_empty) {
        return Err(bad(
            header_line,
            "a header but no points".into(),
            "add one row per point below the header",
        ));
    }
    keys.iter()
        .zip(columns)
        .map(|(k, vals)| {
            Vary::parse(&format!("{k}={}", vals.join(",")))
                .map_err(|e| bad(header_line, format!("column `{k}`: {}", e.message), &e.hint))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_lists_and_units() {
        let v = Vary::parse("load.tangential=0:0.9:10").unwrap();
        assert_eq!(v.key, "load.tangential");
        assert_eq!(v.values.len(), 10);
        assert_eq!(v.values[0], VaryValue::Number(0.0));
        assert_eq!(v.values[9], VaryValue::Number(0.9));
        assert_eq!(v.values[3], VaryValue::Number(0.9 * 3.0 / 9.0));
        let v = Vary::parse("load.friction=0.1, 0.2").unwrap();
        assert_eq!(v.values, vec![VaryValue::Number(0.1), VaryValue::Number(0.2)]);
        let v = Vary::parse("load.normal=\"10 N:30 N:3\"").unwrap();
        let t: Vec<String> = v.values.iter().map(ToString::to_string).collect();
        assert_eq!(t, ["10 N", "20 N", "30 N"]);
        let v = Vary::parse("solver.grid=32,64").unwrap();
        assert_eq!(v.values, vec![VaryValue::Integer(32), VaryValue::Integer(64)]);
        assert!(v.numeric() && v.integer());
        assert!(!Vary::parse("load.friction=1,0.5").unwrap().integer());
        let v = Vary::parse("solver.method=fast,lp").unwrap();
        assert_eq!(v.values[1], VaryValue::Text("lp".into()));
        assert!(!v.numeric());
    }

    #[test]
    fn points_tables_read_and_refuse() {
        let t = "# a comment\nposition.lateral, position.yaw\n0 mm, 0 mrad\n\n2 mm,4.8 mrad\n";
        let v = read_points(t, "p.csv").unwrap();
        assert_eq!(v.len(), 2);
        assert_eq!(v[0].key, "position.lateral");
        assert_eq!(
            v[1].values,
            vec![VaryValue::Text("0 mrad".into()), VaryValue::Text("4.8 mrad".into())]
        );
        let cases = [
            ("", 1, "no header"),
            ("# only\n", 1, "no header"),
            ("a.b,c.d\n", 1, "no points"),
            ("a.b,c.d\n1,2\n3\n", 3, "1 values for 2 keys"),
            ("a.b,c.d\n1,\n", 2, "no value for `c.d`"),
            ("a..b,c.d\n1,2\n", 1, "column `a..b`"),
        ];
        for (text, line, want) in cases {
            let e = read_points(text, "p.csv").unwrap_err();
            assert_eq!(e.line, line, "{text:?}");
            assert!(e.message.contains(want), "{text:?}: {}", e.message);
            assert!(e.to_string().starts_with(&format!("p.csv:{line}: ")), "{e}");
        }
    }

    #[test]
    fn bad_specs_say_what_is_wrong() {
        let cases = [
            ("load.friction", "no `=`"),
            ("=1,2", "not a dotted scene key"),
            ("load..friction=1", "not a dotted scene key"),
            ("load.friction=", "no values"),
            ("load.friction=0:1", "three parts"),
            ("load.friction=0:1:x", "not a whole number"),
            ("load.friction=0:1:1", "at least 2 points"),
            ("load.friction=a:1:3", "must be numbers"),
            ("load.normal=1 N:2 kN:3", "different units"),
            ("load.friction=0.1,,0.2", "empty value"),
        ];
        for (spec, want) in cases {
            let e = Vary::parse(spec).unwrap_err();
            assert!(e.message.contains(want), "{spec}: {}", e.message);
            assert!(e.to_string().contains("hint:"), "{spec}");
        }
    }
}
