//! The sweep table: typed columns, written as CSV (the `csv` crate) and Parquet (the
//! `parquet` crate, its low-level writer without Arrow), and read back from CSV to merge
//! shards.

use std::fmt;
use std::path::Path;
use std::sync::Arc;

/// The type of a column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A whole number, never missing (the point index, the exit status).
    Int,
    /// A number, missing (empty in CSV, null in Parquet) where it does not apply.
    Float,
    /// Text, missing where it does not apply.
    Text,
}

/// One cell of the table.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// A whole number.
    Int(i64),
    /// A number or nothing.
    Float(Option<f64>),
    /// Text or nothing.
    Text(Option<String>),
}

impl Cell {
    /// The cell as CSV text (empty when missing).
    pub fn to_text(&self) -> String {
        match self {
            Cell::Int(i) => i.to_string(),
            Cell::Float(Some(x)) => format_f64(*x),
            Cell::Text(Some(t)) => t.clone(),
            Cell::Float(None) | Cell::Text(None) => String::new(),
        }
    }
}

/// A number in the shortest form that reads back to the same `f64` (ryu), e.g. `0.3`,
/// `1e-10`, `210000000000.0`.
pub fn format_f64(x: f64) -> String {
    ryu::Buffer::new().format(x).to_string()
}

/// A table problem: an unreadable or unwritable file, or shards that do not fit together.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TableError(pub String);

impl fmt::Display for TableError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for TableError {}

/// Columns and rows; every row has one cell per column, of the column's kind.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Column names and kinds, in order.
    pub columns: Vec<(String, Kind)>,
    /// Rows, in order.
    pub rows: Vec<Vec<Cell>>,
}

impl Table {
    /// The index of the column `name`.
    pub fn column(&self, name: &str) -> Option<usize> {
        self.columns.iter().position(|(n, _)| n == name)
    }

    /// The CSV text: a header line, then one line per row (RFC 4180 quoting).
    ///
    /// # Errors
    /// Never in practice (writing to memory); a [`TableError`] otherwise.
    pub fn to_csv(&self) -> Result<String, TableError> {
        let mut w = csv::Writer::from_writer(Vec::new());
        let e = |e: csv::Error| TableError(format!("cannot write the CSV table: {e}"));
        w.write_record(self.columns.iter().map(|(n, _)| n.as_str())).map_err(e)?;
        for row in &self.rows {
            w.write_record(row.iter().map(Cell::to_text)).map_err(e)?;
        }
        let bytes = w.into_inner().map_err(|e| TableError(format!("cannot write CSV: {e}")))?;
        String::from_utf8(bytes).map_err(|e| TableError(format!("CSV is not UTF-8: {e}")))
    }

    /// Read a table written by [`Table::to_csv`]. The kinds of the fixed columns are known
    /// ([`super::FIXED_HEAD`], [`super::FIXED_TAIL`]); a varied column is of integers when
    /// every cell reads as one, numeric when every cell reads as a number, text otherwise.
    ///
    /// # Errors
    /// A [`TableError`] naming the file for a missing file, bad CSV, a missing fixed column
    /// or a cell that does not read as its column's kind.
    pub fn read_csv(path: &Path) -> Result<Table, TableError> {
        let name = path.display();
        let mut r = csv::Reader::from_path(path)
            .map_err(|e| TableError(format!("cannot read the sweep table {name}: {e}")))?;
        let header: Vec<String> = r
            .headers()
            .map_err(|e| TableError(format!("{name}: bad CSV header: {e}")))?
            .iter()
            .map(str::to_string)
            .collect();
        let mut text_rows: Vec<Vec<String>> = Vec::new();
        for rec in r.records() {
            let rec = rec.map_err(|e| TableError(format!("{name}: bad CSV: {e}")))?;
            text_rows.push(rec.iter().map(str::to_string).collect());
        }
        let fixed = |n: &str| {
            super::FIXED_HEAD.iter().chain(super::FIXED_TAIL).find(|(c, _)| *c == n).map(|c| c.1)
        };
        for (n, _) in super::FIXED_HEAD.iter().chain(super::FIXED_TAIL) {
            if !header.iter().any(|h| h == n) {
                return Err(TableError(format!(
                    "{name}: no `{n}` column; is this a table written by `stickslip sweep`?"
                )));
            }
        }
        let columns: Vec<(String, Kind)> = header
            .iter()
            .enumerate()
            .map(|(j, h)| {
                let kind = fixed(h).unwrap_or_else(|| {
                    let all = |ok: fn(&str) -> bool| {
                        text_rows.iter().all(|r| r.get(j).is_some_and(|c| ok(c)))
                    };
                    // Whole numbers are written without a point, other numbers with one
                    // (`format_f64`), so the kind written is the kind read.
                    if all(|c| c.parse::<i64>().is_ok()) {
                        Kind::Int
                    } else if all(|c| c.is_empty() || c.parse::<f64>().is_ok()) {
                        Kind::Float
                    } else {
                        Kind::Text
                    }
                });
                (h.clone(), kind)
            })
            .collect();
        let mut rows = Vec::with_capacity(text_rows.len());
        for (i, tr) in text_rows.iter().enumerate() {
            let mut row = Vec::with_capacity(columns.len());
            for ((col, kind), t) in columns.iter().zip(tr) {
                let bad = || {
                    TableError(format!(
                        "{name}: row {}: column `{col}`: `{t}` is not a {}",
                        i + 2,
                        if *kind == Kind::Int { "whole number" } else { "number" }
                    ))
                };
                row.push(match kind {
                    Kind::Int => Cell::Int(t.parse().map_err(|_| bad())?),
                    Kind::Float if t.is_empty() => Cell::Float(None),
                    Kind::Float => Cell::Float(Some(t.parse().map_err(|_| bad())?)),
                    Kind::Text if t.is_empty() => Cell::Text(None),
                    Kind::Text => Cell::Text(Some(t.clone())),
                });
            }
            rows.push(row);
        }
        Ok(Table { columns, rows })
    }

    /// Make column `j` text (a varied column numeric in one shard and text in another).
    pub(crate) fn make_text(&mut self, j: usize) {
        self.columns[j].1 = Kind::Text;
        for row in &mut self.rows {
            let t = row[j].to_text();
            row[j] = Cell::Text((!t.is_empty()).then_some(t));
        }
    }

    /// The Parquet file: one row group; whole numbers INT64 (required), numbers DOUBLE and
    /// text UTF-8 BYTE_ARRAY (optional: missing cells are nulls); uncompressed.
    ///
    /// # Errors
    /// A [`TableError`] when the file cannot be written.
    pub fn write_parquet(&self, path: &Path) -> Result<(), TableError> {
        self.parquet(path).map_err(|e| {
            TableError(format!("cannot write the Parquet table {}: {e}", path.display()))
        })
    }

    fn parquet(&self, path: &Path) -> Result<(), Box<dyn std::error::Error>> {
        use parquet::basic::{LogicalType, Repetition, Type as Physical};
        use parquet::data_type::{ByteArray, ByteArrayType, DoubleType, Int64Type};
        use parquet::file::properties::WriterProperties;
        use parquet::file::writer::SerializedFileWriter;
        use parquet::schema::types::Type;

        let mut fields = Vec::with_capacity(self.columns.len());
        for (name, kind) in &self.columns {
            let t = match kind {
                Kind::Int => Type::primitive_type_builder(name, Physical::INT64)
                    .with_repetition(Repetition::REQUIRED),
                Kind::Float => Type::primitive_type_builder(name, Physical::DOUBLE)
                    .with_repetition(Repetition::OPTIONAL),
                Kind::Text => Type::primitive_type_builder(name, Physical::BYTE_ARRAY)
                    .with_repetition(Repetition::OPTIONAL)
                    .with_logical_type(Some(LogicalType::String)),
            };
            fields.push(Arc::new(t.build()?));
        }
        let schema = Arc::new(Type::group_type_builder("sweep").with_fields(fields).build()?);
        let props = Arc::new(WriterProperties::builder().build());
        let file = std::fs::File::create(path)?;
        let mut writer = SerializedFileWriter::new(file, schema, props)?;
        let mut group = writer.next_row_group()?;
        for (j, (_, kind)) in self.columns.iter().enumerate() {
            let Some(mut col) = group.next_column()? else { break };
            let cells = self.rows.iter().map(|r| &r[j]);
            match kind {
                Kind::Int => {
                    let v: Vec<i64> =
                        cells.map(|c| if let Cell::Int(i) = c { *i } else { 0 }).collect();
                    col.typed::<Int64Type>().write_batch(&v, None, None)?;
                }
                Kind::Float => {
                    let opt: Vec<Option<f64>> =
                        cells.map(|c| if let Cell::Float(x) = c { *x } else { None }).collect();
                    let def: Vec<i16> = opt.iter().map(|x| i16::from(x.is_some())).collect();
                    let v: Vec<f64> = opt.into_iter().flatten().collect();
                    col.typed::<DoubleType>().write_batch(&v, Some(&def), None)?;
                }
                Kind::Text => {
                    let opt: Vec<Option<&str>> = cells
                        .map(|c| if let Cell::Text(t) = c { t.as_deref() } else { None })
                        .collect();
                    let def: Vec<i16> = opt.iter().map(|x| i16::from(x.is_some())).collect();
                    let v: Vec<ByteArray> =
                        opt.into_iter().flatten().map(ByteArray::from).collect();
                    col.typed::<ByteArrayType>().write_batch(&v, Some(&def), None)?;
                }
            }
            col.close()?;
        }
        group.close()?;
        writer.close()?;
        Ok(())
    }
}
