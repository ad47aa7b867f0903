//! A load path read from a table (`[load.history] file = "path.csv"`): the same path as the
//! lists gives the same history, and every flaw of the table is refused with the file, line
//! and column. (A run's own `history.csv` read back: `stickslip-report`'s
//! `tests/history_csv.rs`.)

// SceneError carries file, position, key and hint; tests return it as is.
#![allow(clippy::result_large_err)]

mod common;

use std::path::{Path, PathBuf};

use stickslip_run::{run, Outcome, RunOptions};
use stickslip_scene::{ErrorKind, Scene, SceneError};

/// Seed 002 Example 1's sphere with `history` as its `[load.history]` body.
fn sphere(history: &str) -> String {
    format!("{}[load.history]\n{history}\n[solver]\ngrid = 48\n", common::SEED002_SPHERE)
}

/// A fresh directory for one test's scene and tables.
fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("stickslip-path-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Read the scene `text` as if it were `dir/scene.toml`, with the tables `files` beside it.
fn read(dir: &Path, text: &str, files: &[(&str, &str)]) -> Result<Scene, SceneError> {
    for (name, body) in files {
        std::fs::write(dir.join(name), body).unwrap();
    }
    Scene::from_toml_str(text, Some(dir.join("scene.toml")))
}

fn solve(scene: &Scene) -> Outcome {
    run(scene, &RunOptions::default()).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn a_table_is_the_same_path_as_the_lists() {
    let d = dir("same");
    let lists = sphere(
        "tangential = [\"0 lbf\", \"100 lbf\", \"-100 lbf\", \"100 lbf\"]\nnormal = [\"2160 lbf\", \"2160 lbf\", \"1800 lbf\", \"2160 lbf\"]\nsteps = 6",
    );
    let table = "# the same path in pound-force\ntangential [lbf], normal (lbf)\n0, 2160\n100, 2160\n-100, 1800\n100, 2160\n";
    let a = solve(&read(&d, &lists, &[]).unwrap());
    let b = solve(
        &read(&d, &sphere("file = \"path.csv\"\nsteps = 6"), &[("path.csv", table)]).unwrap(),
    );
    let (ha, hb) = (a.history.unwrap(), b.history.unwrap());
    assert_eq!(ha.corners, hb.corners);
    for (name, x, y) in [
        ("tangential", &ha.tangential, &hb.tangential),
        ("normal", &ha.normal, &hb.normal),
        ("shift", &ha.shift, &hb.shift),
        ("dissipated", &ha.dissipated, &hb.dissipated),
    ] {
        let scale = x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (i, (p, q)) in x.iter().zip(y).enumerate() {
            assert!((p - q).abs() <= 1e-12 * scale, "{name}[{i}]: {p} against {q}");
        }
    }
    // Units from the `units` table instead of the header.
    let c = read(
        &d,
        &sphere("file = \"bare.csv\"\nunits = { tangential = \"lbf\", normal = \"kN\" }"),
        &[("bare.csv", "tangential, normal\n0, 9.6\n10, 9.6\n")],
    )
    .unwrap();
    let h = c.load.history.unwrap();
    assert_eq!(h.tangential, vec![0.0, 10.0 * 4.4482216152605]);
    assert_eq!(h.normal, Some(vec![9600.0, 9600.0]));
    assert_eq!(h.source.unwrap().lines, vec![2, 3]);
}

/// The refusal of a scene: from reading, validation or the run.
fn refusal(d: &Path, history: &str, files: &[(&str, &str)]) -> SceneError {
    match read(d, &sphere(history), files) {
        Err(e) => e,
        Ok(s) => run(&s, &RunOptions::default()).expect_err("the scene was solved"),
    }
}

#[test]
fn flaws_of_the_table_are_refused_with_their_place() {
    let d = dir("flaws");
    let at = |name: &str, rest: &str| format!("{}{rest}", d.join(name).display());
    let cases: [(&str, &str, &str, ErrorKind, &str, String); 9] = [
        (
            "no unit",
            "file = \"a.csv\"",
            "tangential, normal [N]\n0, 1\n",
            ErrorKind::Io,
            "load.history.file",
            at("a.csv", ":1:1: the column `tangential` has no unit"),
        ),
        (
            "not a number",
            "file = \"a.csv\"",
            "tangential [N]\n0\n1e\n",
            ErrorKind::Io,
            "load.history.file",
            at("a.csv", ":3:1: `1e` in column `tangential` is not a number"),
        ),
        (
            "a unit of the wrong kind",
            "file = \"a.csv\"",
            "tangential [um]\n0\n",
            ErrorKind::Io,
            "load.history.file",
            at("a.csv", ":1:1: "),
        ),
        (
            "a column of another table",
            "file = \"a.csv\"",
            "tangential [N], stick_fraction\n0, 1\n",
            ErrorKind::Io,
            "load.history.file",
            at("a.csv", ":1:17: the column `stick_fraction` is not part of a load path"),
        ),
        (
            "both controls",
            "file = \"a.csv\"",
            "tangential [N], shift [um]\n0, 0\n",
            ErrorKind::Io,
            "load.history.file",
            "both a `tangential` and a `shift` column".into(),
        ),
        (
            "a missing file",
            "file = \"none.csv\"",
            "",
            ErrorKind::Io,
            "load.history.file",
            "cannot read".into(),
        ),
        (
            "a list beside the file",
            "file = \"a.csv\"\nnormal = [\"1 N\"]",
            "tangential [N]\n0\n",
            ErrorKind::Schema,
            "load.history.normal",
            "given both as a list and by `file`".into(),
        ),
        (
            "units twice",
            "file = \"a.csv\"\nunits = { tangential = \"N\" }",
            "tangential [N]\n0\n",
            ErrorKind::Schema,
            "load.history.units.tangential",
            "given twice".into(),
        ),
        (
            "a separating corner",
            "file = \"a.csv\"",
            "tangential [N], normal [N]\n0, 100\n\n# unloads\n0, -1\n",
            ErrorKind::Impossible,
            "load.history.normal[1]",
            at("a.csv", ":5)"),
        ),
    ];
    for (name, history, table, kind, key, says) in cases {
        let files: &[(&str, &str)] = if table.is_empty() { &[] } else { &[("a.csv", table)] };
        let e = refusal(&d, history, files);
        println!("{name}: {e}");
        assert_eq!((e.kind, e.key.as_deref()), (kind, Some(key)), "{name}: {e}");
        assert!(e.to_string().contains(&says), "{name}: `{says}` not in: {e}");
        assert!(e.position.is_some(), "{name}: no position in the scene");
    }
    // `columns` and `units` describe a file; without one they are refused.
    let e = refusal(&d, "tangential = [\"0 N\"]\ncolumns = [\"tangential\"]", &[]);
    assert_eq!(e.key.as_deref(), Some("load.history.columns"));
    let e =
        refusal(&d, "file = \"a.csv\"\ncolumns = [\"stick\"]", &[("a.csv", "tangential [N]\n0\n")]);
    assert_eq!(e.key.as_deref(), Some("load.history.columns"));
}
