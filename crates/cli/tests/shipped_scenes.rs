//! Regression guard: every scene we ship, run by the real `stickslip` program, against a
//! stored copy of what it wrote.
//!
//! The cases are every `scenes/*.toml` of the repository (stored as `<stem>.json`), every
//! template of `stickslip new` (the kinds `stickslip new --list` prints, written by
//! `stickslip new KIND FILE` into a temporary directory; stored as `template-<kind>.json`)
//! and the built-in default scene (`stickslip run --out DIR` without a scene; stored as
//! `default.json`). Each is run as `stickslip run SCENE --out DIR` with `RAYON_NUM_THREADS=2`
//! (see [`THREADS`]). The stored copies live in `tests/shipped/` beside this file: the
//! run's `result.json`, plus under the key [`META`] the exit status and the sorted names of
//! the files the run wrote into DIR.
//!
//! This test uses only the binary and files, never the library API, so it does not change
//! when the crates are renamed or reorganised. It reads and writes JSON with its own small
//! reader and writer ([`Json`]) that keep each number's text as the program wrote it
//! (serde_json's default float parsing is not correctly rounded and moves some numbers by an
//! ulp), so a stored copy is the program's result.json byte for byte, apart from the
//! placeholders of [`EXCLUDED`] and [`MASKED`] and the added key [`META`].
//!
//! Comparison ([`compare`]): the same keys everywhere (a missing or added key fails with its
//! dotted path), the same array lengths, strings, booleans and nulls equal, integers equal,
//! other numbers within 1e-12 relative ([`RELATIVE`], no absolute floor). The values that
//! change from run to run (wall times) are listed in [`EXCLUDED`] and [`MASKED`], each with
//! its reason; nothing else is skipped.
//!
//! After an intended change of results, regenerate the stored copies and review the diff:
//!
//! ```sh
//! STICKSLIP_UPDATE_SHIPPED=1 cargo test --release -p stickslip --test shipped_scenes
//! ```
//!
//! That also deletes stored copies whose scene is gone. Without that variable the test never
//! writes: a missing stored copy is a failure (as in CI, `CI=true`).

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;

/// The variable that makes the test write the stored copies instead of comparing.
const UPDATE_VAR: &str = "STICKSLIP_UPDATE_SHIPPED";

/// The command that regenerates the stored copies (printed on failure).
const UPDATE_HOW: &str =
    "STICKSLIP_UPDATE_SHIPPED=1 cargo test --release -p stickslip --test shipped_scenes";

/// The key of a stored copy that holds what this test records beside result.json: the exit
/// status and the sorted file names of the out directory.
const META: &str = "shipped_scenes_test";

/// The thread count of every run: more than one, so that the parallel paths are the ones
/// checked. Every solver sums in fixed blocks added in order, so its bits do not depend on
/// the thread count (checked with 1, 2 and 3 threads when this was set); a solver that sums
/// in the order rayon's work stealing happens to take fails this test at once (the normal
/// solver of surfaces did: pressures moved by up to 3e-9 relative between two runs).
const THREADS: &str = "2";

/// Largest relative difference |a - b| <= RELATIVE * max(|a|, |b|) accepted between two
/// non-integer numbers. There is no absolute floor. Every number repeats bit for bit, the numerical zeros too: `surface.gap` in contact cells (below
/// 3e-16 m, against 7e-11 m to 1e-2 m outside) or FASTSIM's Fx of -4e-14 N beside Fy of
/// 2e4 N in `wheel_rail_fastsim`. A floor would have to be set per key from its neighbours'
/// scale, and would let such a zero grow by orders of magnitude unseen. A change that
/// reorders a sum moves these zeros first (and on the lattice solvers the pressures too, see
/// [`THREADS`]); if it is intended, regenerate the stored copies.
const RELATIVE: f64 = 1e-12;

/// Keys whose values are not compared (dotted paths, `[]` for any array index), each with
/// the reason. The key must still be present in both; the stored copy holds a placeholder.
const EXCLUDED: &[(&str, &str)] = &[
    ("solver.seconds", "wall time of the whole run"),
    ("solver.solve_seconds", "wall time of the lattice solvers"),
    ("solver.normal.setup_seconds", "wall time of the normal solver's set-up"),
    ("solver.normal.solve_seconds", "wall time of the normal solver"),
];

/// Wall times inside strings: at the path, the number that follows the text and is followed
/// by " s" is replaced by [`MASK`] before comparing; the rest of the string is compared.
const MASKED: &[(&str, &str, &str)] = &[
    ("notes[]", "set-up ", "the fast solver's note: wall time of its set-up"),
    ("notes[]", "iteration ", "the fast solver's note: wall time of its iterations"),
    ("notes[]", "the steps took ", "the load path's note: wall time of its steps"),
];

/// What a masked number becomes.
const MASK: &str = "<wall time>";

/// About this many differences are printed in all (every failing case gets its heading and
/// at least [`MIN_LINES`] of its differences).
const MAX_LINES: usize = 50;

/// The differences printed for each failing case even when [`MAX_LINES`] is used up.
const MIN_LINES: usize = 3;

/// One difference: its message line, and for two numbers their relative difference.
struct Diff {
    line: String,
    relative: Option<f64>,
}

/// One run: its stored name and its scene file (`None`: the built-in default scene).
struct Case {
    name: String,
    scene: Option<PathBuf>,
}

/// The repository root: the nearest ancestor of this crate that holds `scenes/*.toml`.
fn repository() -> PathBuf {
    let here = Path::new(env!("CARGO_MANIFEST_DIR"));
    here.ancestors()
        .find(|d| toml_files(&d.join("scenes")).next().is_some())
        .unwrap_or_else(|| panic!("no ancestor of {} holds scenes/*.toml", here.display()))
        .to_path_buf()
}

/// The `*.toml` files of a directory (none if it does not exist).
fn toml_files(dir: &Path) -> impl Iterator<Item = PathBuf> {
    std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
}

/// Where the stored copies are.
fn shipped_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests").join("shipped")
}

fn bin() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_stickslip"));
    c.env("RAYON_NUM_THREADS", THREADS);
    c
}

/// The sorted names of the entries of a directory (empty if it does not exist).
fn entries(d: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(d)
        .into_iter()
        .flatten()
        .filter_map(Result::ok)
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// Every case: the repository's scenes, the templates written by `stickslip new` into
/// `work`, and the default scene.
fn cases(work: &Path) -> Vec<Case> {
    let mut scenes: Vec<PathBuf> = toml_files(&repository().join("scenes")).collect();
    scenes.sort();
    let mut v: Vec<Case> = scenes
        .into_iter()
        .map(|p| Case {
            name: p.file_stem().unwrap().to_string_lossy().into_owned(),
            scene: Some(p),
        })
        .collect();
    let o = bin().args(["new", "--list"]).output().unwrap();
    assert!(o.status.success(), "stickslip new --list: {}", String::from_utf8_lossy(&o.stderr));
    let list = String::from_utf8(o.stdout).unwrap();
    let kinds: Vec<&str> = list.lines().filter_map(|l| l.split_whitespace().next()).collect();
    assert!(!kinds.is_empty(), "stickslip new --list printed no kinds");
    let dir = work.join("templates");
    std::fs::create_dir_all(&dir).unwrap();
    for kind in kinds {
        let file = dir.join(format!("{kind}.toml"));
        let o = bin().arg("new").arg(kind).arg(&file).current_dir(work).output().unwrap();
        assert!(
            o.status.success() && file.is_file(),
            "stickslip new {kind} {}: {}",
            file.display(),
            String::from_utf8_lossy(&o.stderr)
        );
        v.push(Case { name: format!("template-{kind}"), scene: Some(file) });
    }
    v.push(Case { name: "default".into(), scene: None });
    v
}

/// A JSON value as the program wrote it: numbers keep their text, objects their key order.
#[derive(Clone, Debug, PartialEq)]
enum Json {
    Null,
    Bool(bool),
    /// The number's text (an integer if it has no `.`, `e` or `E`).
    Num(String),
    Str(String),
    Arr(Vec<Json>),
    Obj(Vec<(String, Json)>),
}

impl Json {
    /// Parses a JSON text; the error names the byte offset.
    fn parse(text: &str) -> Result<Json, String> {
        let mut r = Reader { b: text.as_bytes(), i: 0 };
        let v = r.value()?;
        r.space();
        if r.i != r.b.len() {
            return Err(r.err("trailing characters"));
        }
        Ok(v)
    }

    /// The value of `key` in an object.
    fn get(&self, key: &str) -> Option<&Json> {
        match self {
            Json::Obj(m) => m.iter().find(|(k, _)| k == key).map(|(_, v)| v),
            _ => None,
        }
    }

    /// Pretty text in serde_json's layout (two-space indent), as result.json is written.
    fn pretty(&self) -> String {
        let mut s = String::new();
        self.write(&mut s, 0);
        s.push('\n');
        s
    }

    fn write(&self, s: &mut String, level: usize) {
        let pad = |s: &mut String, n: usize| s.extend(std::iter::repeat_n("  ", n));
        match self {
            Json::Null => s.push_str("null"),
            Json::Bool(b) => s.push_str(if *b { "true" } else { "false" }),
            Json::Num(t) => s.push_str(t),
            Json::Str(t) => quote(s, t),
            Json::Arr(a) if a.is_empty() => s.push_str("[]"),
            Json::Obj(m) if m.is_empty() => s.push_str("{}"),
            Json::Arr(a) => {
                s.push_str("[\n");
                for (i, v) in a.iter().enumerate() {
                    pad(s, level + 1);
                    v.write(s, level + 1);
                    s.push_str(if i + 1 < a.len() { ",\n" } else { "\n" });
                }
                pad(s, level);
                s.push(']');
            }
            Json::Obj(m) => {
                s.push_str("{\n");
                for (i, (k, v)) in m.iter().enumerate() {
                    pad(s, level + 1);
                    quote(s, k);
                    s.push_str(": ");
                    v.write(s, level + 1);
                    s.push_str(if i + 1 < m.len() { ",\n" } else { "\n" });
                }
                pad(s, level);
                s.push('}');
            }
        }
    }

    /// Compact text, for messages.
    fn compact(&self) -> String {
        match self {
            Json::Arr(a) => {
                format!("[{}]", a.iter().map(Json::compact).collect::<Vec<_>>().join(","))
            }
            Json::Obj(m) => {
                let items: Vec<String> = m
                    .iter()
                    .map(|(k, v)| {
                        let mut s = String::new();
                        quote(&mut s, k);
                        format!("{s}:{}", v.compact())
                    })
                    .collect();
                format!("{{{}}}", items.join(","))
            }
            other => {
                let mut s = String::new();
                other.write(&mut s, 0);
                s
            }
        }
    }
}

/// `t` as a JSON string, escaped as serde_json escapes (quote, backslash, control
/// characters; everything else as is).
fn quote(s: &mut String, t: &str) {
    s.push('"');
    for c in t.chars() {
        match c {
            '"' => s.push_str("\\\""),
            '\\' => s.push_str("\\\\"),
            '\n' => s.push_str("\\n"),
            '\r' => s.push_str("\\r"),
            '\t' => s.push_str("\\t"),
            '\u{8}' => s.push_str("\\b"),
            '\u{c}' => s.push_str("\\f"),
            c if (c as u32) < 0x20 => s.push_str(&format!("\\u{:04x}", c as u32)),
            c => s.push(c),
        }
    }
    s.push('"');
}

/// The reader of [`Json::parse`].
struct Reader<'a> {
    b: &'a [u8],
    i: usize,
}

impl Reader<'_> {
    fn err(&self, what: &str) -> String {
        format!("{what} at byte {}", self.i)
    }

    fn space(&mut self) {
        while self.b.get(self.i).is_some_and(|c| c.is_ascii_whitespace()) {
            self.i += 1;
        }
    }

    fn eat(&mut self, c: u8) -> Result<(), String> {
        self.space();
        if self.b.get(self.i) == Some(&c) {
            self.i += 1;
            Ok(())
        } else {
            Err(self.err(&format!("expected `{}`", c as char)))
        }
    }

    fn value(&mut self) -> Result<Json, String> {
        self.space();
        let rest = &self.b[self.i..];
        for (word, v) in
            [("null", Json::Null), ("true", Json::Bool(true)), ("false", Json::Bool(false))]
        {
            if rest.starts_with(word.as_bytes()) {
                self.i += word.len();
                return Ok(v);
            }
        }
        match rest.first() {
            Some(b'"') => self.string().map(Json::Str),
            Some(b'[') => {
                self.i += 1;
                let mut a = Vec::new();
                self.space();
                if self.b.get(self.i) == Some(&b']') {
                    self.i += 1;
                    return Ok(Json::Arr(a));
                }
                loop {
                    a.push(self.value()?);
                    self.space();
                    match self.b.get(self.i) {
                        Some(b',') => self.i += 1,
                        Some(b']') => {
                            self.i += 1;
                            return Ok(Json::Arr(a));
                        }
                        _ => return Err(self.err("expected `,` or `]`")),
                    }
                }
            }
            Some(b'{') => {
                self.i += 1;
                let mut m = Vec::new();
                self.space();
                if self.b.get(self.i) == Some(&b'}') {
                    self.i += 1;
                    return Ok(Json::Obj(m));
                }
                loop {
                    self.space();
                    let k = self.string()?;
                    self.eat(b':')?;
                    m.push((k, self.value()?));
                    self.space();
                    match self.b.get(self.i) {
                        Some(b',') => self.i += 1,
                        Some(b'}') => {
                            self.i += 1;
                            return Ok(Json::Obj(m));
                        }
                        _ => return Err(self.err("expected `,` or `}`")),
                    }
                }
            }
            Some(c) if *c == b'-' || c.is_ascii_digit() => {
                let n = rest
                    .iter()
                    .position(|c| !(c.is_ascii_digit() || b"+-.eE".contains(c)))
                    .unwrap_or(rest.len());
                let t = std::str::from_utf8(&rest[..n]).unwrap().to_string();
                if t.parse::<f64>().is_err() {
                    return Err(self.err("bad number"));
                }
                self.i += n;
                Ok(Json::Num(t))
            }
            _ => Err(self.err("expected a value")),
        }
    }

    fn string(&mut self) -> Result<String, String> {
        self.eat(b'"')?;
        let mut bytes = Vec::new();
        loop {
            let Some(&c) = self.b.get(self.i) else { return Err(self.err("unclosed string")) };
            self.i += 1;
            match c {
                b'"' => break,
                b'\\' => {
                    let Some(&e) = self.b.get(self.i) else { return Err(self.err("bad escape")) };
                    self.i += 1;
                    let ch = match e {
                        b'"' => '"',
                        b'\\' => '\\',
                        b'/' => '/',
                        b'b' => '\u{8}',
                        b'f' => '\u{c}',
                        b'n' => '\n',
                        b'r' => '\r',
                        b't' => '\t',
                        b'u' => {
                            let hi = self.hex4()?;
                            let code = if (0xD800..0xDC00).contains(&hi) {
                                if !self.b[self.i..].starts_with(b"\\u") {
                                    return Err(self.err("lone surrogate"));
                                }
                                self.i += 2;
                                let lo = self.hex4()?;
                                0x10000 + ((hi - 0xD800) << 10) + (lo.wrapping_sub(0xDC00) & 0x3FF)
                            } else {
                                hi
                            };
                            char::from_u32(code).ok_or_else(|| self.err("bad \\u escape"))?
                        }
                        _ => return Err(self.err("bad escape")),
                    };
                    bytes.extend_from_slice(ch.encode_utf8(&mut [0; 4]).as_bytes());
                }
                c => bytes.push(c),
            }
        }
        String::from_utf8(bytes).map_err(|_| self.err("string is not UTF-8"))
    }

    fn hex4(&mut self) -> Result<u32, String> {
        let t = self.b.get(self.i..self.i + 4).ok_or_else(|| self.err("short \\u escape"))?;
        let v = std::str::from_utf8(t)
            .ok()
            .and_then(|t| u32::from_str_radix(t, 16).ok())
            .ok_or_else(|| self.err("bad \\u escape"))?;
        self.i += 4;
        Ok(v)
    }
}

/// Runs a case; what this test stores for it: result.json (if written) with [`META`]
/// appended, normalised by [`normalise`].
fn run(case: &Case, work: &Path) -> Json {
    let out = work.join("out").join(&case.name);
    let mut c = bin();
    c.arg("run");
    if let Some(s) = &case.scene {
        c.arg(s);
    }
    let o = c.arg("--out").arg(&out).current_dir(work).output().unwrap();
    let result = out.join("result.json");
    let mut v = if result.is_file() {
        let text = std::fs::read_to_string(&result).unwrap();
        Json::parse(&text).unwrap_or_else(|e| panic!("{}: {e}", result.display()))
    } else {
        Json::Obj(Vec::new())
    };
    let Json::Obj(map) = &mut v else { panic!("{}: not a JSON object", result.display()) };
    assert!(
        map.iter().all(|(k, _)| k != META),
        "result.json has a key `{META}`: rename this test's key"
    );
    if !o.status.success() {
        // Shown with the failure; the status itself is compared through META.
        eprintln!("{}: exit {:?}: {}", case.name, o.status, String::from_utf8_lossy(&o.stderr));
    }
    let status = o.status.code().map_or(Json::Null, |c| Json::Num(c.to_string()));
    let files = Json::Arr(entries(&out).into_iter().map(Json::Str).collect());
    map.push((
        META.into(),
        Json::Obj(vec![("exit_status".into(), status), ("files".into(), files)]),
    ));
    let _ = std::fs::remove_dir_all(&out);
    normalise(&mut v, "");
    v
}

/// `path` with every array index written `[]`.
fn pattern(path: &str) -> String {
    let mut s = String::with_capacity(path.len());
    let mut in_index = false;
    for ch in path.chars() {
        match ch {
            '[' => {
                in_index = true;
                s.push_str("[]");
            }
            ']' => in_index = false,
            _ if in_index => {}
            _ => s.push(ch),
        }
    }
    s
}

/// Replaces the values of [`EXCLUDED`] by a placeholder naming the reason, and the numbers
/// of [`MASKED`] by [`MASK`].
fn normalise(v: &mut Json, path: &str) {
    let pat = pattern(path);
    if let Some((_, why)) = EXCLUDED.iter().find(|(p, _)| *p == pat) {
        *v = Json::Str(format!("not compared: {why}"));
        return;
    }
    match v {
        Json::Obj(m) => {
            for (k, x) in m.iter_mut() {
                let p = if path.is_empty() { k.clone() } else { format!("{path}.{k}") };
                normalise(x, &p);
            }
        }
        Json::Arr(a) => {
            for (i, x) in a.iter_mut().enumerate() {
                normalise(x, &format!("{path}[{i}]"));
            }
        }
        Json::Str(s) => {
            for (_, before, _) in MASKED.iter().filter(|(p, _, _)| *p == pat) {
                *s = mask(s, before);
            }
        }
        _ => {}
    }
}

/// `s` with each number that follows `before` and is followed by " s" replaced by [`MASK`].
fn mask(s: &str, before: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut rest = s;
    while let Some(i) = rest.find(before) {
        let (head, tail) = rest.split_at(i + before.len());
        out.push_str(head);
        let n = tail
            .find(|c: char| !(c.is_ascii_digit() || matches!(c, '.' | 'e' | 'E' | '-' | '+')))
            .unwrap_or(tail.len());
        if n > 0 && tail[n..].starts_with(" s") {
            out.push_str(MASK);
            rest = &tail[n..];
        } else {
            rest = tail;
        }
    }
    out.push_str(rest);
    out
}

/// A value for a message, shortened.
fn show(v: &Json) -> String {
    let s = v.compact();
    if s.chars().count() > 160 {
        format!("{}...", s.chars().take(160).collect::<String>())
    } else {
        s
    }
}

/// Whether a number's text is an integer (no fraction, no exponent).
fn is_integer(t: &str) -> bool {
    !t.contains(['.', 'e', 'E'])
}

/// Every difference between the stored copy `a` and this run's `b`.
fn compare(a: &Json, b: &Json, path: &str, out: &mut Vec<Diff>) {
    let at = if path.is_empty() { "(top level)" } else { path };
    let plain = |line: String| Diff { line, relative: None };
    match (a, b) {
        (Json::Obj(x), Json::Obj(y)) => {
            let mut keys: Vec<&String> = x.iter().map(|(k, _)| k).collect();
            keys.extend(y.iter().map(|(k, _)| k).filter(|k| a.get(k).is_none()));
            for k in keys {
                let p = if path.is_empty() { k.clone() } else { format!("{path}.{k}") };
                match (a.get(k), b.get(k)) {
                    (Some(u), Some(v)) => compare(u, v, &p, out),
                    (Some(u), None) => {
                        out.push(plain(format!("{p}: missing now (stored {})", show(u))))
                    }
                    (None, Some(v)) => {
                        out.push(plain(format!("{p}: added now ({}), not stored", show(v))))
                    }
                    (None, None) => unreachable!(),
                }
            }
        }
        (Json::Arr(x), Json::Arr(y)) => {
            if x.len() != y.len() {
                out.push(plain(format!(
                    "{at}: stored {} elements, now {} (stored {}, now {})",
                    x.len(),
                    y.len(),
                    show(a),
                    show(b)
                )));
            } else {
                for (i, (u, v)) in x.iter().zip(y).enumerate() {
                    compare(u, v, &format!("{path}[{i}]"), out);
                }
            }
        }
        (Json::Num(x), Json::Num(y)) if is_integer(x) || is_integer(y) => {
            // Counts: equal, and of the same kind (an integer turned float is a change of
            // result.json's format).
            if x != y {
                out.push(plain(format!("{at}: stored {x}, now {y}")));
            }
        }
        (Json::Num(x), Json::Num(y)) => {
            // Rust's parse is correctly rounded: the values the program wrote.
            let (u, v): (f64, f64) = (x.parse().unwrap(), y.parse().unwrap());
            let d = (u - v).abs();
            let scale = u.abs().max(v.abs());
            if d > RELATIVE * scale {
                let r = d / scale;
                out.push(Diff {
                    line: format!("{at}: stored {x}, now {y} (relative difference {r:.2e})"),
                    relative: Some(r),
                });
            }
        }
        _ => {
            if a != b {
                out.push(plain(format!("{at}: stored {}, now {}", show(a), show(b))));
            }
        }
    }
}

#[test]
fn shipped_scenes_match_their_stored_results() {
    let t0 = Instant::now();
    let update = std::env::var(UPDATE_VAR).is_ok_and(|v| v == "1");
    let work = std::env::temp_dir().join(format!("stickslip-shipped-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&work);
    std::fs::create_dir_all(&work).unwrap();
    let cases = cases(&work);
    let stored_dir = shipped_dir();

    // Run in a few threads (each run is one process with one rayon thread).
    let workers = std::thread::available_parallelism().map_or(2, |n| n.get()).clamp(1, 4);
    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<Option<Json>>> = Mutex::new(vec![None; cases.len()]);
    std::thread::scope(|s| {
        for _ in 0..workers {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(case) = cases.get(i) else { break };
                let v = run(case, &work);
                results.lock().unwrap()[i] = Some(v);
            });
        }
    });
    let results: Vec<Json> =
        results.into_inner().unwrap().into_iter().map(|v| v.expect("every case ran")).collect();
    let _ = std::fs::remove_dir_all(&work);

    let names: BTreeSet<String> = cases.iter().map(|c| format!("{}.json", c.name)).collect();
    assert_eq!(names.len(), cases.len(), "two cases share a stored name");
    let stale: Vec<String> = entries(&stored_dir)
        .into_iter()
        .filter(|n| n.ends_with(".json") && !names.contains(n))
        .collect();

    if update {
        std::fs::create_dir_all(&stored_dir).unwrap();
        for (case, v) in cases.iter().zip(&results) {
            std::fs::write(stored_dir.join(format!("{}.json", case.name)), v.pretty()).unwrap();
        }
        for n in &stale {
            std::fs::remove_file(stored_dir.join(n)).unwrap();
            println!("deleted {n} (no such scene now)");
        }
        println!(
            "wrote {} stored copies to {} in {:.1} s",
            cases.len(),
            stored_dir.display(),
            t0.elapsed().as_secs_f64()
        );
        return;
    }

    let mut report = String::new();
    let mut failed = 0;
    let mut budget = MAX_LINES;
    for (case, v) in cases.iter().zip(&results) {
        let file = stored_dir.join(format!("{}.json", case.name));
        let source = case
            .scene
            .as_ref()
            .map_or("the built-in default scene".into(), |p| p.display().to_string());
        let Ok(text) = std::fs::read_to_string(&file) else {
            failed += 1;
            report.push_str(&format!(
                "\n{}: no stored copy {} (scene {source})\n",
                case.name,
                file.display()
            ));
            continue;
        };
        let stored =
            Json::parse(&text).unwrap_or_else(|e| panic!("{}: not JSON: {e}", file.display()));
        let mut diffs = Vec::new();
        compare(&stored, v, "", &mut diffs);
        if diffs.is_empty() {
            continue;
        }
        failed += 1;
        let largest = diffs
            .iter()
            .filter_map(|d| d.relative.map(|r| (r, d)))
            .max_by(|x, y| x.0.total_cmp(&y.0))
            .map_or(String::new(), |(_, d)| format!("; the largest relative: {}", d.line));
        report.push_str(&format!(
            "\n{}: {} difference{} from {} (scene {source}){largest}\n",
            case.name,
            diffs.len(),
            if diffs.len() == 1 { "" } else { "s" },
            file.display()
        ));
        let shown = diffs.len().min(budget.max(MIN_LINES));
        budget = budget.saturating_sub(shown);
        for d in &diffs[..shown] {
            report.push_str(&format!("  {}\n", d.line));
        }
        if diffs.len() > shown {
            report.push_str(&format!("  ... and {} more\n", diffs.len() - shown));
        }
    }
    for n in &stale {
        report.push_str(&format!("\n{n}: stored, but no scene of that name runs now\n"));
    }
    println!("{} cases in {:.1} s", cases.len(), t0.elapsed().as_secs_f64());
    assert!(
        failed == 0 && stale.is_empty(),
        "{failed} of {} shipped scenes differ from (or lack) their stored copies, {} stored copies have \
         no scene:\n{report}\n\
         If the change is intended, regenerate the stored copies and review the diff:\n  {UPDATE_HOW}\n",
        cases.len(),
        stale.len()
    );
}
