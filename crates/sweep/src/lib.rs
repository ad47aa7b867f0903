//! Parameter sweeps: one scene, some of its keys varied over lists or ranges, every point of
//! the cartesian product (or, zipped, of the lists taken in step) an independent, audited
//! run, gathered into one table.
//!
//! - [`Vary`]: a `--vary` specification (`key=start:end:count` or `key=v1,v2,...`; values
//!   are numbers, or text such as quantities with units, `"10 N"`);
//! - [`Sweep`]: the scene text and the varied keys; point `i` of [`Sweep::len`] sets each
//!   varied key in the TOML document (`toml_edit`, so the rest of the file is untouched) and
//!   reads the result with the ordinary reader, so each point gets the same validation and
//!   file:line:column errors as a scene file; points are numbered in cartesian order, the
//!   last varied key fastest; [`Sweep::zipped`] instead takes the keys' lists in step
//!   (point `i` sets every key to its `i`-th value; the lists are of equal length), as
//!   vehicle dynamics sweeps a wheelset's lateral shift, yaw and roll together;
//! - [`Shard`]: `i/N`, the points whose index is `i - 1` modulo `N` (for job arrays);
//! - [`Sweep::run_point`]: plan, check against the machine, execute and audit one point, into
//!   one row of the [`Table`]: the point index, the sweep's identity, the varied values, the
//!   status and (for a failed point) the reason and exit status, and the key results;
//! - [`merge`]: shard tables into the full table, checking that they belong to the same sweep
//!   and that every point is there exactly once.
//!
//! ```
//! use stickslip_sweep::{Shard, Sweep, Vary};
//! let vary = [Vary::parse("load.friction=0.2,0.4").unwrap()];
//! let sweep = Sweep::new(stickslip_scene::DEFAULT_SCENE, None, &vary).unwrap();
//! assert_eq!(sweep.len(), 2);
//! let table = sweep.run(Shard::ALL, 600.0, |_| {});
//! assert_eq!(table.rows.len(), 2);
//! let mu = table.column("load.friction").unwrap();
//! assert_eq!(table.rows[1][mu], stickslip_sweep::Cell::Float(Some(0.4)));
//! ```

// SceneError carries file, position, key and hint for the user; one per point.
#![allow(clippy::result_large_err)]

mod budget;
mod journal;
mod table;
mod vary;

use std::fmt;
use std::hash::Hasher as _;
use std::path::PathBuf;

use rayon::prelude::*;

pub use journal::{journal_path, write_atomically, Journaled, SYNC_INTERVAL};
pub use table::{format_f64, Cell, Kind, Table, TableError};
pub use vary::{read_points, PointsError, Vary, VaryError, VaryValue};

use stickslip_run::{read_scene, Execute, MachineLimits, Outcome, Plan, RunOptions};
use stickslip_scene::{ErrorKind, SceneError};

/// The columns before the varied keys: the point index, the sweep's identity (a hash of the
/// scene text and the `--vary` specifications) and the number of points of the whole sweep.
pub const FIXED_HEAD: &[(&str, Kind)] =
    &[("point", Kind::Int), ("sweep", Kind::Text), ("points", Kind::Int)];

/// The columns after the varied keys: status, failure, and the key results (SI; 2D loads
/// per unit length). A result that does not apply, or a failed point, leaves the cell empty.
pub const FIXED_TAIL: &[(&str, Kind)] = &[
    ("status", Kind::Text),
    ("exit_code", Kind::Int),
    ("error_kind", Kind::Text),
    ("reason", Kind::Text),
    ("normal_load", Kind::Float),
    ("tangential", Kind::Float),
    ("moment", Kind::Float),
    ("rolling_moment", Kind::Float),
    ("fx", Kind::Float),
    ("fy", Kind::Float),
    ("mz", Kind::Float),
    ("a", Kind::Float),
    ("b", Kind::Float),
    ("p0", Kind::Float),
    ("indentation", Kind::Float),
    ("area", Kind::Float),
    ("contact_fraction", Kind::Float),
    ("stick_fraction", Kind::Float),
    ("rigid_tangential", Kind::Float),
    ("iterations", Kind::Float),
    ("residual", Kind::Float),
    ("elements", Kind::Float),
    ("audit_checks", Kind::Float),
    ("method", Kind::Text),
];

/// A deterministic subset of the points: shard `index` of `count` (1-based) holds the points
/// whose index is `index - 1` modulo `count`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// 1-based shard number.
    pub index: usize,
    /// Number of shards.
    pub count: usize,
}

impl Shard {
    /// Every point.
    pub const ALL: Shard = Shard { index: 1, count: 1 };

    /// Read `i/N` with 1 <= i <= N.
    ///
    /// # Errors
    /// A message saying what was found and what is allowed.
    pub fn parse(s: &str) -> Result<Shard, String> {
        let bad = || {
            format!(
                "`{s}` is not a shard: write I/N with 1 <= I <= N, e.g. 3/8 (with Slurm: \
                 $((SLURM_ARRAY_TASK_ID + 1))/$SLURM_ARRAY_TASK_COUNT)"
            )
        };
        let (i, n) = s.split_once('/').ok_or_else(bad)?;
        let (i, n): (usize, usize) =
            (i.trim().parse().map_err(|_| bad())?, n.trim().parse().map_err(|_| bad())?);
        if i == 0 || n == 0 || i > n {
            return Err(bad());
        }
        Ok(Shard { index: i, count: n })
    }

    /// The points of this shard among `points`.
    pub fn points(self, points: usize) -> impl Iterator<Item = usize> {
        (self.index - 1..points).step_by(self.count)
    }
}

/// How the varied keys' values combine into points.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Every combination: the cartesian product, the last key fastest.
    Cartesian,
    /// The lists in step: point `i` takes the `i`-th value of every key (lists of equal
    /// length).
    Zip,
}

/// The number of patches of a wheel on its rail that get their own columns in the table
/// (`patch0_...` to `patch2_...`): tread, flange and one more.
pub const WHEEL_RAIL_PATCH_COLUMNS: usize = 3;

/// The columns of a wheel-rail sweep after [`FIXED_TAIL`]: the wheelset's height, the
/// force of the wheel on the rail in track coordinates, the number of patches.
pub const WHEEL_RAIL_TAIL: &[&str] = &["z_wheelset", "fx_rail", "fy_rail", "fz_rail", "patches"];

/// The columns of each patch `k` of a wheel-rail sweep, named `patch{k}_{name}` (SI, the
/// keys of result.json's `wheel_rail.patches`).
pub const WHEEL_RAIL_PATCH: &[&str] = &[
    "y_rail",
    "z_rail",
    "y_wheel",
    "contact_angle",
    "rolling_radius",
    "creepage_longitudinal",
    "creepage_lateral",
    "creepage_spin",
    "fn",
    "fx",
    "fs",
    "mn",
    "pmax",
    "area",
    "stick_fraction",
];

/// A sweep: the scene text, where it came from, the varied keys and how they combine.
#[derive(Debug, Clone)]
pub struct Sweep {
    text: String,
    file: Option<PathBuf>,
    vary: Vec<Vary>,
    mode: Mode,
    wheel_rail: bool,
    id: String,
    jobs: Option<usize>,
}

/// A scene given as text that is not TOML, or a varied key that cannot be set in it.
fn sweep_error(file: Option<&PathBuf>, key: &str, message: String, hint: &str) -> SceneError {
    SceneError::new(ErrorKind::Schema, message)
        .key(key.to_string())
        .hint(hint.to_string())
        .in_file(file.cloned())
}

impl Sweep {
    /// A sweep of the scene `text` (read from `file`, for messages) over `vary`.
    ///
    /// The scene itself need not be valid (a sweep may supply a missing key, or replace a
    /// value the checks refuse); each point is read and checked on its own.
    ///
    /// # Errors
    /// A [`SceneError`]: the reader's syntax error when `text` is not TOML; a key varied
    /// twice; a varied key whose place in the document is not a table; a reading error
    /// (syntax, schema, unit) of the first point, which would fail every point alike: a
    /// key the format does not have, a value of the wrong type, a unit that does not read.
    pub fn new(text: &str, file: Option<PathBuf>, vary: &[Vary]) -> Result<Sweep, SceneError> {
        Self::with_mode(text, file, vary, Mode::Cartesian)
    }

    /// A sweep of the scene `text` over `vary` taken in step ([`Mode::Zip`]): point `i` sets
    /// every varied key to its `i`-th value.
    ///
    /// # Errors
    /// Those of [`Sweep::new`], and a [`SceneError`] on the first key whose number of
    /// values differs from the first key's.
    pub fn zipped(text: &str, file: Option<PathBuf>, vary: &[Vary]) -> Result<Sweep, SceneError> {
        Self::with_mode(text, file, vary, Mode::Zip)
    }

    /// A sweep of `text` over `vary` combined by `mode` ([`Sweep::new`], [`Sweep::zipped`]).
    ///
    /// # Errors
    /// As [`Sweep::new`] and [`Sweep::zipped`].
    pub fn with_mode(
        text: &str,
        file: Option<PathBuf>,
        vary: &[Vary],
        mode: Mode,
    ) -> Result<Sweep, SceneError> {
        if let Err(e) = text.parse::<toml_edit::DocumentMut>() {
            // The scene reader locates the error (file:line:column).
            return Err(match read_scene(text, file.clone()) {
                Err(se) => se,
                Ok(_) => SceneError::new(ErrorKind::Syntax, format!("the scene is not TOML: {e}"))
                    .in_file(file),
            });
        }
        for (i, v) in vary.iter().enumerate() {
            if vary[..i].iter().any(|w| w.key == v.key) {
                return Err(sweep_error(
                    file.as_ref(),
                    &v.key,
                    format!("`{}` is varied twice", v.key),
                    "give each key one --vary; list all its values there",
                ));
            }
        }
        if mode == Mode::Zip {
            if let Some(first) = vary.first() {
                let n = first.values.len();
                if let Some(v) = vary.iter().find(|v| v.values.len() != n) {
                    return Err(sweep_error(
                        file.as_ref(),
                        &v.key,
                        format!(
                            "--zip: `{}` has {} values but `{}` has {n}; zipped keys take one \
                             value each per point",
                            v.key,
                            v.values.len(),
                            first.key
                        ),
                        "give every --vary the same number of values, or drop --zip for the \
                         cartesian product",
                    ));
                }
            }
        }
        let mut h = fnv::FnvHasher::default();
        h.write(text.as_bytes());
        if mode == Mode::Zip {
            // Cartesian sweeps keep the identity they had before zipped sweeps existed.
            h.write(b"\0zip");
        }
        for v in vary {
            h.write(&[0]);
            h.write(v.key.as_bytes());
            h.write(&[0]);
            for x in &v.values {
                h.write(x.to_string().as_bytes());
                h.write(&[1]);
            }
        }
        let mut s = Sweep {
            text: text.to_string(),
            file,
            vary: vary.to_vec(),
            mode,
            wheel_rail: false,
            id: format!("{:016x}", h.finish()),
            jobs: None,
        };
        // Setting the keys can fail only for the document's structure, the same at every
        // point: check it once with the first point.
        // A reading error (a misspelt key, a missing table) fails every point the same way:
        // refuse it at once. Range and combination refusals may depend on the point.
        if !s.is_empty() {
            let first = s.point_text(0)?;
            if let Err(e) = read_scene(&first, s.file.clone()) {
                if matches!(e.kind, ErrorKind::Syntax | ErrorKind::Schema | ErrorKind::Unit) {
                    return Err(e);
                }
            }
            // A wheel on its rail gets the columns of its wheelset and patches.
            s.wheel_rail = first
                .parse::<toml_edit::DocumentMut>()
                .ok()
                .and_then(|d| d.get("geometry")?.get("kind")?.as_str().map(|k| k == "wheel-rail"))
                .unwrap_or(false);
        }
        Ok(s)
    }

    /// The sweep's identity: a hash (FNV-1a, 64 bits) of the scene text and the varied keys
    /// and values, stored in every row so that [`merge`] can tell shards of different sweeps
    /// apart.
    pub fn id(&self) -> &str {
        &self.id
    }

    /// Run at most `jobs` points at once (`stickslip sweep --jobs`): 1 runs them one after
    /// the other on the calling thread (each point's solvers still use the threads of the
    /// global pool, as [`Sweep::run_serial`]); more runs them on a pool of that many
    /// threads, which the points' own solvers share (nested work stays in the pool, so the
    /// machine is not oversubscribed). Without it, as many as the global pool has threads
    /// (all cores by default). The memory available may lower the number further. The
    /// table does not depend on it.
    #[must_use]
    pub fn with_jobs(mut self, jobs: usize) -> Sweep {
        self.jobs = Some(jobs.max(1));
        self
    }

    /// The largest number of points run at once, when set by [`Sweep::with_jobs`].
    pub fn jobs(&self) -> Option<usize> {
        self.jobs
    }

    /// The varied keys.
    pub fn vary(&self) -> &[Vary] {
        &self.vary
    }

    /// How the varied keys combine.
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// The number of points (the product of the numbers of values; zipped, the length of
    /// the lists).
    pub fn len(&self) -> usize {
        match self.mode {
            Mode::Cartesian => self.vary.iter().map(|v| v.values.len()).product(),
            Mode::Zip => self.vary.first().map_or(1, |v| v.values.len()),
        }
    }

    /// True when some varied key has no values.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The value of each varied key at point `i` (cartesian order, the last key fastest;
    /// zipped, the `i`-th value of each).
    pub fn values(&self, i: usize) -> Vec<&VaryValue> {
        if self.mode == Mode::Zip {
            return self.vary.iter().map(|v| &v.values[i]).collect();
        }
        let mut rest = i;
        let mut out: Vec<&VaryValue> = self
            .vary
            .iter()
            .rev()
            .map(|v| {
                let n = v.values.len();
                let x = &v.values[rest % n];
                rest /= n;
                x
            })
            .collect();
        out.reverse();
        out
    }

    /// The scene text of point `i`: the varied keys set in the document, the rest as written.
    ///
    /// # Errors
    /// A [`SceneError`] when the text is not TOML or a varied key's parent is not a table.
    pub fn point_text(&self, i: usize) -> Result<String, SceneError> {
        // `new` parsed the text already; toml_edit keeps its layout.
        let mut doc: toml_edit::DocumentMut = self.text.parse().map_err(|e| {
            SceneError::new(ErrorKind::Syntax, format!("the scene is not TOML: {e}"))
                .in_file(self.file.clone())
        })?;
        for (v, x) in self.vary.iter().zip(self.values(i)) {
            let keys: Vec<&str> = v.key.split('.').collect();
            set(doc.as_table_mut(), &keys, x.to_toml(), false).map_err(|m| {
                sweep_error(
                    self.file.as_ref(),
                    &v.key,
                    m,
                    "vary a key of a table (docs/SCENES.md), e.g. load.friction",
                )
            })?;
        }
        Ok(doc.to_string())
    }

    /// The table's columns: [`FIXED_HEAD`], one per varied key (integers when all its
    /// values are whole numbers, numbers when all are numbers, else text), [`FIXED_TAIL`];
    /// for a wheel on its rail then [`WHEEL_RAIL_TAIL`] and, for each of the first
    /// [`WHEEL_RAIL_PATCH_COLUMNS`] patches, [`WHEEL_RAIL_PATCH`] as `patch{k}_{name}`.
    pub fn columns(&self) -> Vec<(String, Kind)> {
        let head = FIXED_HEAD.iter().map(|(n, k)| (n.to_string(), *k));
        let varied = self.vary.iter().map(|v| {
            let kind = if v.integer() {
                Kind::Int
            } else if v.numeric() {
                Kind::Float
            } else {
                Kind::Text
            };
            (v.key.clone(), kind)
        });
        let tail = FIXED_TAIL.iter().map(|(n, k)| (n.to_string(), *k));
        let mut all: Vec<(String, Kind)> = head.chain(varied).chain(tail).collect();
        if self.wheel_rail {
            all.extend(WHEEL_RAIL_TAIL.iter().map(|n| (n.to_string(), Kind::Float)));
            for k in 0..WHEEL_RAIL_PATCH_COLUMNS {
                all.extend(WHEEL_RAIL_PATCH.iter().map(|n| (format!("patch{k}_{n}"), Kind::Float)));
            }
        }
        all
    }

    /// Run point `i` on its own: read, plan, check against the machine (`time_limit`
    /// seconds and the memory available), execute and audit; the row of the table.
    pub fn run_point(&self, i: usize, time_limit: f64) -> Vec<Cell> {
        self.run_point_in(i, time_limit, None)
    }

    /// [`Sweep::run_point`], its planned memory reserved from `budget` while it executes.
    fn run_point_in(
        &self,
        i: usize,
        time_limit: f64,
        budget: Option<&budget::Budget>,
    ) -> Vec<Cell> {
        let result = self.point_text(i).and_then(|text| {
            let scene = read_scene(&text, self.file.clone())?;
            let plan = Plan::new(&scene)?;
            plan.check_machine(&MachineLimits::detect(time_limit))?;
            let _held = budget.map(|b| b.reserve(plan.cost.memory_bytes));
            plan.execute(&RunOptions::default())
        });
        self.row(i, &result)
    }

    /// The row of point `i` from its result.
    pub fn row(&self, i: usize, result: &Result<Outcome, SceneError>) -> Vec<Cell> {
        let mut row = vec![
            Cell::Int(i as i64),
            Cell::Text(Some(self.id.clone())),
            Cell::Int(self.len() as i64),
        ];
        for (v, x) in self.vary.iter().zip(self.values(i)) {
            row.push(match x {
                VaryValue::Integer(n) if v.integer() => Cell::Int(*n),
                _ if v.numeric() => Cell::Float(x.as_number()),
                _ => Cell::Text(Some(x.to_string())),
            });
        }
        match result {
            Ok(out) => {
                row.extend([
                    Cell::Text(Some("ok".into())),
                    Cell::Int(0),
                    Cell::Text(None),
                    Cell::Text(None),
                ]);
                row.extend(results(out));
            }
            Err(e) => {
                row.extend([
                    Cell::Text(Some("failed".into())),
                    Cell::Int(i64::from(e.exit_code())),
                    Cell::Text(Some(e.kind.name().into())),
                    Cell::Text(Some(e.to_string())),
                ]);
                let n = FIXED_TAIL.len() - 4;
                row.extend((0..n).map(|j| match FIXED_TAIL[4 + j].1 {
                    Kind::Text => Cell::Text(None),
                    _ => Cell::Float(None),
                }));
            }
        }
        if self.wheel_rail {
            row.extend(wheel_rail_results(result.as_ref().ok()));
        }
        row
    }

    /// Run the points of `shard` in parallel, as many at a time as there are threads (all
    /// cores by default, or [`Sweep::with_jobs`]) and as the memory available holds (each
    /// point reserves its planned memory from what the machine had free when the sweep
    /// started, and waits while the points running hold too much; `budget.rs`); `done` is called after each
    /// point (for a progress bar), from the thread that ran it. Each point is still one
    /// independent, audited run, and every solver gives the same bits for any number of
    /// threads, so the table is [`Sweep::run_serial`]'s, in the same order.
    pub fn run(&self, shard: Shard, time_limit: f64, done: impl Fn(usize) + Sync) -> Table {
        let points: Vec<usize> = shard.points(self.len()).collect();
        let rows = self.run_points(&points, time_limit, |i, _| done(i));
        Table { columns: self.columns(), rows }
    }

    /// Run `points` as [`Sweep::run`] does (in parallel, as the threads and the memory
    /// allow); their rows in the order of `points`. `done` gets each point's row as it
    /// finishes, from the thread that ran it.
    pub(crate) fn run_points(
        &self,
        points: &[usize],
        time_limit: f64,
        done: impl Fn(usize, &[Cell]) + Sync,
    ) -> Vec<Vec<Cell>> {
        let at_once = self.jobs.unwrap_or_else(rayon::current_num_threads).min(points.len());
        // The memory available when the sweep starts, shared by the points running at once.
        let budget = (at_once > 1)
            .then(|| MachineLimits::detect(f64::INFINITY).memory_bytes.map(budget::Budget::new))
            .flatten();
        let one = |i: usize| {
            let r = self.run_point_in(i, time_limit, budget.as_ref());
            done(i, &r);
            r
        };
        let serial = || points.iter().map(|&i| one(i)).collect();
        let run = || -> Vec<Vec<Cell>> { points.par_iter().map(|&i| one(i)).collect() };
        // The current pool runs min(points, its threads) at once: use it when that is the
        // number asked (its idle threads then help the points' own solvers).
        if at_once <= 1 {
            serial()
        } else if at_once == rayon::current_num_threads().min(points.len()) {
            run()
        } else {
            match rayon::ThreadPoolBuilder::new().num_threads(at_once).build() {
                Ok(pool) => pool.install(run),
                Err(_) => serial(),
            }
        }
    }

    /// Run the points of `shard` one after the other; `done` is called after each point.
    pub fn run_serial(&self, shard: Shard, time_limit: f64, done: impl Fn(usize)) -> Table {
        let rows = shard
            .points(self.len())
            .map(|i| {
                let r = self.run_point(i, time_limit);
                done(i);
                r
            })
            .collect();
        Table { columns: self.columns(), rows }
    }
}

/// Set `keys` (a dotted path) to `v` below `t`, creating missing tables.
fn set(
    t: &mut dyn toml_edit::TableLike,
    keys: &[&str],
    v: toml_edit::Value,
    inline: bool,
) -> Result<(), String> {
    let (first, rest) = keys.split_first().ok_or("an empty key")?;
    if rest.is_empty() {
        if t.get(first).is_some_and(|i| i.is_table() || i.is_array_of_tables()) {
            return Err(format!("`{first}` is a table in the scene, not a value"));
        }
        t.insert(first, toml_edit::Item::Value(v));
        return Ok(());
    }
    if t.get(first).is_none() {
        let item = if inline {
            toml_edit::Item::Value(toml_edit::Value::InlineTable(toml_edit::InlineTable::new()))
        } else {
            let mut n = toml_edit::Table::new();
            n.set_implicit(true);
            toml_edit::Item::Table(n)
        };
        t.insert(first, item);
    }
    let item = t.get_mut(first).ok_or("a missing table")?;
    let inline = item.is_inline_table();
    let child = item
        .as_table_like_mut()
        .ok_or_else(|| format!("`{first}` holds a value in the scene, not a table"))?;
    set(child, rest, v, inline)
}

/// The key results of an outcome, in the order of [`FIXED_TAIL`] after its first four.
fn results(o: &Outcome) -> Vec<Cell> {
    let f = |x: f64| Cell::Float(Some(x));
    let c = &o.contact;
    vec![
        f(c.normal_load),
        f(o.forces.tangential),
        f(o.forces.moment),
        f(o.forces.rolling_moment),
        Cell::Float(o.forces.fx),
        Cell::Float(o.forces.fy),
        Cell::Float(o.forces.mz),
        f(c.a),
        f(c.b),
        f(c.p0),
        Cell::Float(c.indentation),
        Cell::Float(c.area),
        Cell::Float(c.fraction),
        Cell::Float(stick_fraction(o)),
        Cell::Float(o.rigid_displacement.tangential),
        f(o.solver.iterations as f64),
        f(o.solver.residual),
        f(o.solver.elements as f64),
        f(o.audit.checks.len() as f64),
        Cell::Text(Some(o.solver.method.clone())),
    ]
}

/// The wheel-rail cells of a row ([`WHEEL_RAIL_TAIL`], then [`WHEEL_RAIL_PATCH`] per
/// patch); empty cells for a failed point, a patch that did not form, or a result that does
/// not apply (no stick fraction without creep forces).
fn wheel_rail_results(o: Option<&Outcome>) -> Vec<Cell> {
    let n = WHEEL_RAIL_TAIL.len() + WHEEL_RAIL_PATCH_COLUMNS * WHEEL_RAIL_PATCH.len();
    let Some(w) = o.and_then(|o| o.wheel_rail.as_ref()) else {
        return vec![Cell::Float(None); n];
    };
    let f = |x: f64| Cell::Float(Some(x));
    let t = &w.total_on_rail;
    let mut row = vec![f(w.z_wheelset), f(t.fx), f(t.fy), f(t.fz), f(w.patches.len() as f64)];
    for k in 0..WHEEL_RAIL_PATCH_COLUMNS {
        match w.patches.get(k) {
            Some(p) => row.extend([
                f(p.y_rail),
                f(p.z_rail),
                f(p.y_wheel),
                f(p.contact_angle),
                f(p.rolling_radius),
                f(p.creepage.longitudinal),
                f(p.creepage.lateral),
                f(p.creepage.spin),
                f(p.fn_),
                f(p.fx),
                f(p.fs),
                f(p.mn),
                f(p.pmax),
                f(p.area),
                Cell::Float(p.stick_fraction),
            ]),
            None => row.extend(std::iter::repeat_n(Cell::Float(None), WHEEL_RAIL_PATCH.len())),
        }
    }
    row
}

/// The stick share of the contact: a grid solution's stick area fraction; for intervals
/// along x, the stick length over the contact length; for radii (axisymmetric contacts), the
/// stick area over the contact area.
fn stick_fraction(o: &Outcome) -> Option<f64> {
    let z = &o.zones;
    if let Some(g) = &z.grid {
        return Some(g.stick_area_fraction);
    }
    let measure: fn(&[f64; 2]) -> f64 = if z.coordinate == "radius" {
        |i| (i[1] * i[1] - i[0] * i[0]).abs()
    } else {
        |i| (i[1] - i[0]).abs()
    };
    // fold from +0.0: an empty `sum` of f64 is -0.0.
    let stick = z.stick.iter().map(measure).fold(0.0, |s, x| s + x);
    let total = z.slip.iter().map(measure).fold(stick, |s, x| s + x);
    (total > 0.0).then(|| stick / total)
}

/// Why shard tables cannot be merged.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MergeError(pub String);

impl fmt::Display for MergeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for MergeError {}

/// Merge shard tables into the full sweep: the same columns and the same sweep identity in
/// every table, every point `0..points` exactly once; rows sorted by point.
///
/// # Errors
/// A [`MergeError`] naming the tables (by `names`) that differ, the points missing or the
/// points found twice.
pub fn merge(tables: Vec<Table>, names: &[String]) -> Result<Table, MergeError> {
    let header = |t: &Table| t.columns.iter().map(|c| c.0.clone()).collect::<Vec<_>>();
    if names.len() != tables.len() {
        return Err(MergeError(format!("{} tables but {} names", tables.len(), names.len())));
    }
    let first = tables.first().ok_or_else(|| MergeError("no tables to merge".into()))?;
    let (first_header, first_name) = (header(first), &names[0]);
    // The sweep and its size, from the first row, with the table it came from.
    let mut identity: Option<(String, String, &String)> = None;
    for (t, name) in tables.iter().zip(names) {
        if header(t) != first_header {
            return Err(MergeError(format!(
                "{name} has the columns [{}], {first_name} has [{}]: they are not shards of \
                 one sweep",
                header(t).join(", "),
                first_header.join(", ")
            )));
        }
        let (Some(js), Some(jn)) = (t.column("sweep"), t.column("points")) else {
            return Err(MergeError(format!("{name} has no `sweep` or `points` column")));
        };
        for row in &t.rows {
            let (id, n) = (row[js].to_text(), row[jn].to_text());
            match &identity {
                None => identity = Some((id, n, name)),
                Some((id0, n0, name0)) if (&id, &n) != (id0, n0) => {
                    return Err(MergeError(format!(
                        "{name} holds sweep {id} ({n} points), {name0} sweep {id0} ({n0} \
                         points): the scene or the --vary differ"
                    )))
                }
                Some(_) => {}
            }
        }
    }
    let Some((_, points, _)) = identity else {
        return Err(MergeError("the tables hold no rows".into()));
    };
    let points: i64 = points.parse().map_err(|_| MergeError(format!("`{points}` points")))?;
    // Tables without rows add nothing (and their inferred kinds mean nothing).
    let mut tables = tables.into_iter().filter(|t| !t.rows.is_empty());
    let mut all = tables.next().ok_or_else(|| MergeError("the tables hold no rows".into()))?;
    for mut t in tables {
        for j in 0..all.columns.len() {
            if all.columns[j].1 != t.columns[j].1 {
                all.make_text(j);
                t.make_text(j);
            }
        }
        all.rows.extend(t.rows);
    }
    let p = all.column("point").ok_or_else(|| MergeError("no point column".into()))?;
    let idx = |r: &Vec<Cell>| if let Cell::Int(i) = r[p] { i } else { -1 };
    all.rows.sort_by_key(idx);
    let mut seen = vec![0usize; points.max(0) as usize];
    for r in &all.rows {
        match usize::try_from(idx(r)).ok().and_then(|i| seen.get_mut(i)) {
            Some(s) => *s += 1,
            None => {
                return Err(MergeError(format!(
                    "point {} is outside the sweep's 0..{points}",
                    idx(r)
                )))
            }
        }
    }
    // The points where `want` holds, the first 20 listed.
    let list = |want: fn(usize) -> bool| {
        let v: Vec<usize> =
            seen.iter().enumerate().filter(|(_, n)| want(**n)).map(|(i, _)| i).collect();
        let shown: Vec<String> = v.iter().take(20).map(ToString::to_string).collect();
        let more = if v.len() > 20 { format!(", ... ({} in all)", v.len()) } else { String::new() };
        (!v.is_empty()).then(|| shown.join(", ") + &more)
    };
    if let Some(twice) = list(|n| n > 1) {
        return Err(MergeError(format!("points found more than once: {twice}")));
    }
    if let Some(missing) = list(|n| n == 0) {
        return Err(MergeError(format!(
            "points missing: {missing} (of 0..{}); run the missing shards and merge again",
            points - 1
        )));
    }
    Ok(all)
}
