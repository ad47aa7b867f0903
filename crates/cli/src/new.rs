//! `stickslip new KIND [FILE]`: a commented scene to start from, one per kind of problem
//! (the templates of `stickslip_scene::templates`); `stickslip new --list` lists them;
//! `stickslip schema` prints the JSON Schema editors read.
//!
//! The first line of a written scene is a `#:schema PATH` directive for TOML language
//! servers. Inside a stickslip checkout (a parent directory holds `docs/scene.schema.json`)
//! it points at that file by a relative path; elsewhere `new` writes `scene.schema.json`
//! beside the scene and points at it, so completion works offline and matches the program
//! that wrote it. To standard output the line points at `./scene.schema.json`, which
//! `stickslip schema > scene.schema.json` writes.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use clap::builder::{PossibleValue, PossibleValuesParser};
use clap::Args;
use stickslip_scene::json_schema::{scene_schema_text, SCHEMA_PATH};
use stickslip_scene::templates::{self, TEMPLATES};

use crate::{emit, note, Failure};

/// The name of the schema written beside a scene outside a checkout.
const BESIDE: &str = "scene.schema.json";

/// The arguments of `new`.
#[derive(Debug, Args)]
pub struct NewArgs {
    /// The kind of problem (see --list).
    #[arg(value_parser = kind_parser(), required_unless_present = "list")]
    kind: Option<String>,
    /// Write the scene here (and the editor schema beside it when needed); standard output
    /// when omitted.
    file: Option<PathBuf>,
    /// List the kinds with what each solves.
    #[arg(long, conflicts_with_all = ["kind", "file"])]
    list: bool,
    /// Replace FILE if it exists.
    #[arg(long, requires = "file")]
    force: bool,
}

/// The kinds as clap's possible values, so that `--help`, errors and shell completions
/// name them.
fn kind_parser() -> PossibleValuesParser {
    PossibleValuesParser::new(TEMPLATES.iter().map(|t| PossibleValue::new(t.kind).help(t.about)))
}

/// `new`.
pub fn run(a: &NewArgs) -> Result<(), Failure> {
    if a.list {
        let mut t = String::new();
        for tpl in &TEMPLATES {
            let _ = writeln!(t, "{:<22} {}", tpl.kind, tpl.about);
        }
        return emit(&t);
    }
    let kind = a.kind.as_deref().unwrap_or_default();
    let tpl = templates::find(kind).ok_or_else(|| {
        Failure::Other(format!("unknown kind `{kind}`; one of: {}", templates::kinds()), 2)
    })?;
    let Some(file) = &a.file else {
        note("note: the #:schema line expects scene.schema.json beside the scene: `stickslip schema > scene.schema.json` writes it");
        return emit(&templates::with_schema(tpl.text, &format!("./{BESIDE}")));
    };
    if file.exists() && !a.force {
        return Err(Failure::Other(
            format!("{} exists; use --force to replace it", file.display()),
            2,
        ));
    }
    let dir = match file.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let io = |what: &Path, e: std::io::Error| {
        Failure::Other(format!("cannot write {}: {e}", what.display()), 1)
    };
    let (directive, schema_file) = match checkout_schema(&dir) {
        Some(rel) => (rel, None),
        None => (format!("./{BESIDE}"), Some(dir.join(BESIDE))),
    };
    std::fs::write(file, templates::with_schema(tpl.text, &directive)).map_err(|e| io(file, e))?;
    note(&format!("wrote {} (run it: stickslip run {})", file.display(), file.display()));
    if let Some(s) = schema_file {
        let ours = std::fs::read_to_string(&s).map_or(true, |t| is_stickslip_schema(&t));
        if ours {
            std::fs::write(&s, scene_schema_text()).map_err(|e| io(&s, e))?;
            note(&format!(
                "wrote {} (the schema its #:schema line names, for editors)",
                s.display()
            ));
        } else {
            note(&format!(
                "note: {} exists and is not a stickslip schema; left as is (`stickslip schema` prints ours)",
                s.display()
            ));
        }
    }
    Ok(())
}

/// `schema`: the JSON Schema of the scene format on standard output.
pub fn schema() -> Result<(), Failure> {
    emit(&scene_schema_text())
}

fn is_stickslip_schema(text: &str) -> bool {
    text.contains("\"title\": \"stickslip scene\"")
}

/// The relative path from `dir` to the `docs/scene.schema.json` of a stickslip checkout
/// that contains `dir`, if any.
fn checkout_schema(dir: &Path) -> Option<String> {
    let abs = std::fs::canonicalize(dir).ok()?;
    for (up, a) in abs.ancestors().enumerate() {
        let candidate = a.join(SCHEMA_PATH);
        if std::fs::read_to_string(&candidate).is_ok_and(|t| is_stickslip_schema(&t)) {
            return Some(if up == 0 {
                format!("./{SCHEMA_PATH}")
            } else {
                format!("{}{SCHEMA_PATH}", "../".repeat(up))
            });
        }
    }
    None
}
