//! Checks on the repository itself (issue 14): the physics crates stay below the upper
//! layers, the dependency picture in ARCHITECTURE.md is the one Cargo declares, and nothing
//! in the repository links or refers to files outside it.
//!
//! These tests read the workspace (its `Cargo.toml` files through `cargo metadata`, and its
//! files through `git ls-files`); they compute nothing of the physics.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Component, Path, PathBuf};
use std::process::Command;

/// The workspace root: the parent of this package's directory (`verification/`).
fn workspace_root() -> PathBuf {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    manifest.parent().expect("verification/ lies inside the workspace").to_path_buf()
}

/// Dependency kinds as `cargo metadata` spells them (`null` is a normal dependency).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Kind {
    Normal,
    Dev,
    Build,
}

impl Kind {
    fn name(self) -> &'static str {
        match self {
            Kind::Normal => "normal",
            Kind::Dev => "dev",
            Kind::Build => "build",
        }
    }
}

/// Every dependency between packages of the workspace: (dependent, dependency) -> kinds.
type Edges = BTreeMap<(String, String), BTreeSet<Kind>>;

/// The workspace's packages and the edges between them, from
/// `cargo metadata --format-version 1 --no-deps --offline`.
fn workspace_graph() -> (BTreeSet<String>, Edges) {
    let root = workspace_root();
    let out = Command::new(env!("CARGO"))
        .args(["metadata", "--format-version", "1", "--no-deps", "--offline"])
        .current_dir(&root)
        .output()
        .expect("cannot run `cargo metadata`");
    assert!(
        out.status.success(),
        "`cargo metadata --no-deps --offline` failed in {}:\n{}",
        root.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    let meta: serde_json::Value =
        serde_json::from_slice(&out.stdout).expect("`cargo metadata` printed valid JSON");
    let packages = meta["packages"].as_array().expect("metadata has a `packages` array");
    let names: BTreeSet<String> = packages
        .iter()
        .map(|p| p["name"].as_str().expect("every package has a name").to_string())
        .collect();
    let mut edges = Edges::new();
    for p in packages {
        let from = p["name"].as_str().expect("package name");
        for d in p["dependencies"].as_array().expect("package has `dependencies`") {
            // `name` is the package depended on (a `rename` would be in `rename`).
            let to = d["name"].as_str().expect("dependency name");
            if !names.contains(to) {
                continue;
            }
            let kind = match d["kind"].as_str() {
                None => Kind::Normal,
                Some("dev") => Kind::Dev,
                Some("build") => Kind::Build,
                Some(other) => panic!("unknown dependency kind {other:?} of {from} -> {to}"),
            };
            edges.entry((from.to_string(), to.to_string())).or_default().insert(kind);
        }
    }
    (names, edges)
}

fn kinds(k: &BTreeSet<Kind>) -> String {
    k.iter().map(|k| k.name()).collect::<Vec<_>>().join("+")
}

/// The physics crates: libraries that must not know about scenes, the CLI, the
/// verification or the benches.
const PHYSICS: [&str; 9] = [
    "stickslip-special",
    "stickslip-quad",
    "stickslip-halfspace",
    "stickslip-graded",
    "stickslip-lattice",
    "stickslip-traction",
    "stickslip-normal",
    "stickslip-rolling",
    "stickslip-wheelrail",
];

/// The layers above the physics crates.
const UPPER: [&str; 8] = [
    "stickslip-scene",
    "stickslip-plan",
    "stickslip-run",
    "stickslip-report",
    "stickslip-sweep",
    "stickslip",
    "stickslip-verification",
    "stickslip-benches",
];

/// The path of a run, each part with the parts it must not depend on (not even for tests):
/// the scene format knows nothing of planning or running, the planner nothing of how a
/// recipe is executed, the run nothing of its files or of sweeps, and the report and the
/// sweeps sit beside each other on the run.
const RUN_PATH: [(&str, &[&str]); 5] = [
    (
        "stickslip-scene",
        &["stickslip-plan", "stickslip-run", "stickslip-report", "stickslip-sweep"],
    ),
    ("stickslip-plan", &["stickslip-run", "stickslip-report", "stickslip-sweep"]),
    ("stickslip-run", &["stickslip-report", "stickslip-sweep"]),
    ("stickslip-report", &["stickslip-sweep"]),
    ("stickslip-sweep", &["stickslip-report"]),
];

/// What `special` and `quad` must not use: anything about contact mechanics.
const CONTACT: [&str; 9] = [
    "stickslip-halfspace",
    "stickslip-graded",
    "stickslip-rolling",
    "stickslip-traction",
    "stickslip-scene",
    "stickslip-plan",
    "stickslip-run",
    "stickslip-report",
    "stickslip-sweep",
];

/// The package a short name of the ARCHITECTURE.md picture stands for: `cli` is `stickslip`,
/// every other name drops the `stickslip-` prefix.
fn package_of(short: &str) -> String {
    if short == "cli" {
        "stickslip".to_string()
    } else {
        format!("stickslip-{short}")
    }
}

/// The dependency picture of ARCHITECTURE.md, parsed.
///
/// Format: the first fenced block whose info string is `deps`. Each non-empty line that does
/// not start with `#` reads `package -> dep, dep (dev), ...`: the package on the left (short
/// name, see [`package_of`]) depends on each package on the right; a right-hand name
/// followed by `(dev)` is a dev-dependency only, a bare name has a normal (or build)
/// dependency. A package with no dependency of ours is written `package ->`.
///
/// Returns the packages named on the left and the edges (dependent, dependency, dev only).
fn architecture_picture() -> (BTreeSet<String>, BTreeSet<(String, String, bool)>) {
    let path = workspace_root().join("ARCHITECTURE.md");
    let text = std::fs::read_to_string(&path).expect("ARCHITECTURE.md is readable");
    let mut lines = text.lines().enumerate();
    lines
        .by_ref()
        .find(|(_, l)| l.trim() == "```deps")
        .expect("ARCHITECTURE.md has no ```deps block: the dependency picture is missing");
    let mut left = BTreeSet::new();
    let mut edges = BTreeSet::new();
    let mut closed = false;
    for (i, line) in lines {
        let line = line.trim();
        if line.starts_with("```") {
            closed = true;
            break;
        }
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let (from, deps) = line.split_once("->").unwrap_or_else(|| {
            panic!("ARCHITECTURE.md:{}: {line:?} is not of the form `package -> deps`", i + 1)
        });
        let from = package_of(from.trim());
        assert!(
            left.insert(from.clone()),
            "ARCHITECTURE.md:{}: {from} has two lines in the dependency picture",
            i + 1
        );
        for dep in deps.split(',').map(str::trim).filter(|d| !d.is_empty()) {
            let (name, dev) = match dep.strip_suffix("(dev)") {
                Some(n) => (n.trim(), true),
                None => (dep, false),
            };
            assert!(
                !name.contains(char::is_whitespace),
                "ARCHITECTURE.md:{}: {dep:?} is not a package name (optionally followed by `(dev)`)",
                i + 1
            );
            edges.insert((from.clone(), package_of(name), dev));
        }
    }
    assert!(closed, "ARCHITECTURE.md: the ```deps block is not closed");
    (left, edges)
}

#[test]
fn physics_crates_do_not_depend_on_upper_layers() {
    let (names, edges) = workspace_graph();
    for p in PHYSICS.iter().chain(&UPPER) {
        assert!(
            names.contains(*p),
            "package {p} is not in the workspace any more: update this test and ARCHITECTURE.md"
        );
    }
    let mut wrong = Vec::new();
    for ((from, to), k) in &edges {
        let (from, to) = (from.as_str(), to.as_str());
        if PHYSICS.contains(&from) && UPPER.contains(&to) {
            wrong.push(format!(
                "{from} -> {to} ({}): a physics crate must not depend on an upper layer; move what it needs from {to} down, or the code that needs it up",
                kinds(k)
            ));
        }
        if (from == "stickslip-special" || from == "stickslip-quad") && CONTACT.contains(&to) {
            wrong.push(format!(
                "{from} -> {to} ({}): special and quad know nothing about contact mechanics",
                kinds(k)
            ));
        }
        if RUN_PATH.iter().any(|(p, not)| *p == from && not.contains(&to)) {
            wrong.push(format!(
                "{from} -> {to} ({}): the parts of a run depend on earlier parts only (scene, plan, run, then report or sweep)",
                kinds(k)
            ));
        }
        if from == "stickslip-report" && PHYSICS.contains(&to) {
            wrong.push(format!(
                "{from} -> {to} ({}): the report writes what the run computed; what it needs from a physics crate belongs in the run's outcome",
                kinds(k)
            ));
        }
        if from == "stickslip-special" {
            wrong.push(format!(
                "{from} -> {to} ({}): special must depend on no crate of ours",
                kinds(k)
            ));
        }
        if from == "stickslip-quad" && to != "stickslip-special" {
            wrong.push(format!("{from} -> {to} ({}): quad may depend only on special", kinds(k)));
        }
    }
    wrong.sort();
    wrong.dedup();
    assert!(
        wrong.is_empty(),
        "dependency rules of ARCHITECTURE.md broken:\n  {}",
        wrong.join("\n  ")
    );

    // The picture in ARCHITECTURE.md and Cargo agree, edge for edge.
    let (left, picture) = architecture_picture();
    let cargo: BTreeSet<(String, String, bool)> = edges
        .iter()
        .map(|((f, t), k)| (f.clone(), t.clone(), k.iter().all(|k| *k == Kind::Dev)))
        .collect();
    let show = |(f, t, dev): &(String, String, bool)| {
        format!("{f} -> {t}{}", if *dev { " (dev)" } else { "" })
    };
    let missing: Vec<String> = cargo.difference(&picture).map(show).collect();
    let extra: Vec<String> = picture.difference(&cargo).map(show).collect();
    let unlisted: Vec<&String> = names.difference(&left).collect();
    let unknown: Vec<&String> = left.difference(&names).collect();
    assert!(
        missing.is_empty() && extra.is_empty() && unlisted.is_empty() && unknown.is_empty(),
        "the ```deps picture in ARCHITECTURE.md does not match `cargo metadata`; make the picture say what the Cargo.toml files say.\n\
         in Cargo but not in the picture: {missing:?}\n\
         in the picture but not in Cargo: {extra:?}\n\
         packages without a line in the picture: {unlisted:?}\n\
         names in the picture that are not packages: {unknown:?}"
    );
    println!(
        "{} packages, {} edges between them, all in ARCHITECTURE.md",
        names.len(),
        edges.len()
    );
}

/// Files this test reads: every file git tracks or would track (untracked files not
/// ignored count too, so a new page is checked before it is committed), with one of these
/// extensions.
const CHECKED: [&str; 5] = ["md", "rs", "toml", "py", "txt"];

fn repository_files(root: &Path) -> Vec<PathBuf> {
    let out = Command::new("git")
        .args(["ls-files", "-z", "--cached", "--others", "--exclude-standard"])
        .current_dir(root)
        .output()
        .expect("cannot run `git ls-files` (the test needs git and a checkout)");
    assert!(
        out.status.success(),
        "`git ls-files` failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut files: Vec<PathBuf> = String::from_utf8_lossy(&out.stdout)
        .split('\0')
        .filter(|f| !f.is_empty())
        .map(PathBuf::from)
        .filter(|f| f.extension().and_then(|e| e.to_str()).is_some_and(|e| CHECKED.contains(&e)))
        // a tracked file deleted in the working tree is not there to check
        .filter(|f| root.join(f).is_file())
        .collect();
    files.sort();
    files.dedup();
    files
}

/// `path` relative to the directory `base` (both relative to the root), normalised
/// lexically; `None` when it climbs above the repository root.
fn resolve(base: &Path, path: &str) -> Option<PathBuf> {
    let mut out = PathBuf::new();
    for c in base.join(path).components() {
        match c {
            Component::Normal(s) => out.push(s),
            Component::CurDir => {}
            Component::ParentDir => {
                if !out.pop() {
                    return None;
                }
            }
            Component::RootDir | Component::Prefix(_) => return None,
        }
    }
    Some(out)
}

/// The targets of the markdown links `[text](target)` on a line.
fn link_targets(line: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(i) = rest.find("](") {
        let after = &rest[i + 2..];
        let end = after.find([')', ' ', '\t']).unwrap_or(after.len());
        out.push(&after[..end]);
        rest = &after[end..];
    }
    out
}

/// Whether a link target names a file: not a web or mail address, not an anchor on the
/// same page. In Rust and other non-Markdown files only doc comments hold links, and a
/// target without `/` or a file extension (or with `::`) is a rustdoc intra-doc link.
fn is_file_link(target: &str, markdown: bool) -> bool {
    if target.is_empty()
        || target.starts_with('#')
        || ["http://", "https://", "mailto:"].iter().any(|s| target.starts_with(s))
    {
        return false;
    }
    markdown || (!target.contains("::") && (target.contains('/') || target.contains('.')))
}

#[test]
fn nothing_links_outside_the_repository() {
    let root = workspace_root();
    // Spelt in two pieces so that this file does not match itself.
    let outside = [concat!("..", "/shared"), concat!("/work", "/shared")];
    let files = repository_files(&root);
    assert!(files.len() > 50, "only {} files found: is this the stickslip checkout?", files.len());
    let mut wrong = Vec::new();
    let mut links = 0usize;
    for file in &files {
        let name = file.to_string_lossy().replace('\\', "/");
        let Ok(text) = std::fs::read_to_string(root.join(file)) else {
            continue; // not UTF-8: not a document
        };
        let markdown = name.ends_with(".md");
        let dir = file.parent().unwrap_or(Path::new(""));
        let mut fenced = false;
        for (i, line) in text.lines().enumerate() {
            let at = format!("{name}:{}", i + 1);
            for o in outside {
                if line.contains(o) {
                    wrong.push(format!(
                        "{at}: refers to `{o}`, outside the repository; point to the in-repo page (docs/FORMULAS.md, docs/SCENES.md, docs/VERIFICATION.md) instead"
                    ));
                }
            }
            if markdown && line.trim_start().starts_with("```") {
                fenced = !fenced;
                continue;
            }
            let is_doc = if markdown {
                !fenced
            } else {
                let t = line.trim_start();
                t.starts_with("//") || t.starts_with('#')
            };
            if !is_doc {
                continue;
            }
            for target in link_targets(line) {
                if !is_file_link(target, markdown) {
                    continue;
                }
                links += 1;
                let path = target.split(['#', '?']).next().unwrap_or("");
                if path.is_empty() {
                    continue;
                }
                match resolve(dir, path) {
                    None => wrong.push(format!(
                        "{at}: link ({target}) leads outside the repository; link to a file in the repository or to a public web address"
                    )),
                    Some(p) if !root.join(&p).exists() => wrong.push(format!(
                        "{at}: link ({target}) points to {}, which does not exist; fix the path (it is relative to {})",
                        p.display(),
                        if dir.as_os_str().is_empty() { "the repository root".to_string() } else { dir.display().to_string() }
                    )),
                    Some(_) => {}
                }
            }
        }
    }
    assert!(wrong.is_empty(), "{} problem(s):\n  {}", wrong.len(), wrong.join("\n  "));
    println!("{} files, {links} links to files, all inside the repository", files.len());
}

/// Issue 28: the bodies of a scene are resolved once. Within the planner and the run only
/// `crates/plan/src/bodies.rs` derives the composite modulus, Dundurs' beta or a homogeneous material
/// from the scene; every check, recipe and stage reads them from the recipe's `Bodies`.
#[test]
fn the_run_resolves_the_bodies_in_one_place() {
    let root = workspace_root();
    let home = Path::new("crates/plan/src/bodies.rs");
    let derivations =
        ["composite_modulus(", "dundurs_beta(", "Material::new(", "GradedMaterial::new("];
    let mut found = Vec::new();
    for f in repository_files(&root) {
        if !(f.starts_with("crates/run/src") || f.starts_with("crates/plan/src")) || f == home {
            continue;
        }
        let text = std::fs::read_to_string(root.join(&f)).expect("a tracked file is readable");
        for (n, line) in text.lines().enumerate() {
            let code = line.split("//").next().unwrap_or("");
            for d in derivations {
                if code.contains(d) {
                    found.push(format!("{}:{}: {}", f.display(), n + 1, line.trim()));
                }
            }
        }
    }
    assert!(
        found.is_empty(),
        "the bodies are resolved in {} only; read them from the recipe's `Bodies` instead of deriving them again:\n{}",
        home.display(),
        found.join("\n")
    );
    let text = std::fs::read_to_string(root.join(home)).expect("crates/plan/src/bodies.rs exists");
    assert!(
        derivations[..2].iter().all(|d| text.contains(d)),
        "crates/plan/src/bodies.rs resolves E* and beta"
    );
}
