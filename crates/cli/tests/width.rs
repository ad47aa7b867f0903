//! Every line `explain` prints for the shipped scenes, and every line of a set of error
//! messages, fits an 80-column terminal. The one exception is a line that a long path (an
//! unbreakable token of more than 40 columns) pushes past column 80.

use std::path::{Path, PathBuf};
use std::process::Command;

const WIDTH: usize = 80;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_stickslip"))
}

fn scenes() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes")
}

/// The lines of `text` wider than 80 columns that are not one unbreakable token past the
/// line's indent.
fn too_wide(text: &str) -> Vec<String> {
    text.lines()
        .filter(|l| l.chars().count() > WIDTH)
        .filter(|l| {
            let indent = l.chars().take_while(|c| *c == ' ').count();
            // allowed: the token that crosses column 80 is a path longer than half the width
            // (moving it to a line of its own would not make that line fit either)
            let mut col = 0;
            let mut crossing = None;
            for (k, w) in l.split(' ').enumerate() {
                let end = col + w.chars().count();
                if end > WIDTH && crossing.is_none() {
                    crossing = Some((k, w));
                }
                col = end + 1;
            }
            match crossing {
                Some((_, w)) => !(w.contains('/') && indent + w.chars().count() > WIDTH / 2),
                None => true,
            }
        })
        .map(str::to_string)
        .collect()
}

#[test]
fn explain_fits_80_columns_for_every_shipped_scene() {
    let mut files: Vec<PathBuf> = std::fs::read_dir(scenes())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    assert!(files.len() >= 20, "only {} shipped scenes found", files.len());
    let mut bad = Vec::new();
    for f in &files {
        let o = bin().arg("explain").arg(f).output().unwrap();
        assert!(o.status.success(), "{}: {}", f.display(), String::from_utf8_lossy(&o.stderr));
        let text = String::from_utf8_lossy(&o.stdout);
        for l in too_wide(&text) {
            bad.push(format!("{}: {l}", f.display()));
        }
    }
    assert!(bad.is_empty(), "{} lines wider than {WIDTH}:\n{}", bad.len(), bad.join("\n"));
}

#[test]
fn error_messages_fit_80_columns() {
    let dir = std::env::temp_dir().join(format!("stickslip-width-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let base = std::fs::read_to_string(scenes().join("hertz_cylinder_cattaneo.toml")).unwrap();
    let cases = [
        ("unknown_key", base.replace("radius = \"20 mm\"", "radiuss = \"20 mm\"")),
        ("bad_unit", base.replace("\"20 mm\"", "\"20 mmm\"")),
        ("wrong_dimension", base.replace("\"210 GPa\"", "\"210 N\"")),
        ("negative_friction", base.replace("friction = 0.3", "friction = -0.3")),
        ("too_much_tangential", base.replace("\"15 kN/m\"", "\"50 kN/m\"")),
        ("bad_poisson", base.replace("nu = 0.3", "nu = 0.7")),
        ("unknown_model", base.replace("\"homogeneous\"", "\"homogenous\"")),
        ("toml_syntax", base.replace("[load]", "[load")),
        ("bad_field", base.replace("[-2.0, 2.0, 41]", "[2.0, -2.0, 0]")),
    ];
    let mut bad = Vec::new();
    for (name, text) in &cases {
        assert_ne!(text, &base, "{name}: the case did not change the scene");
        let f = dir.join(format!("{name}.toml"));
        std::fs::write(&f, text).unwrap();
        for cmd in ["explain", "run"] {
            let mut c = bin();
            c.arg(cmd).arg(&f);
            if cmd == "run" {
                // nothing is written: the scene is refused before the run
                c.arg("--quiet").arg("--out").arg(dir.join(format!("{name}-out")));
            }
            let o = c.output().unwrap();
            assert!(!o.status.success(), "{name}: {cmd} accepted a bad scene");
            let err = String::from_utf8_lossy(&o.stderr);
            assert!(err.contains("error"), "{name}: {err}");
            for l in too_wide(&err) {
                bad.push(format!("{name} ({cmd}): {l}"));
            }
        }
    }
    // a missing file with a long path
    let missing = dir.join("a/directory/that/does/not/exist/with/a/rather/long/name/scene.toml");
    let o = bin().arg("explain").arg(&missing).output().unwrap();
    assert!(!o.status.success());
    for l in too_wide(&String::from_utf8_lossy(&o.stderr)) {
        bad.push(format!("missing file: {l}"));
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(bad.is_empty(), "{} lines wider than {WIDTH}:\n{}", bad.len(), bad.join("\n"));
}
