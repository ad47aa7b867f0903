//! The built `stickslip` binary: the default run (under 10 s, real results), explain, JSON
//! on stdout, and bad input (a file that does not exist, a malformed scene, an impossible
//! scene, a directory that cannot be written): non-zero exit, the error names file, line,
//! column and key, and no output file is left behind.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::Instant;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_stickslip"))
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("stickslip-cli-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn text(o: &Output) -> (String, String) {
    (
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

fn entries(d: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(d)
        .map(|r| {
            r.filter_map(|e| e.ok()).map(|e| e.file_name().to_string_lossy().into_owned()).collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

#[test]
fn default_run_writes_real_results_in_under_ten_seconds() {
    let d = tmp("default");
    let out = d.join("out");
    let t0 = Instant::now();
    let o = bin().args(["run", "--out"]).arg(&out).output().unwrap();
    let secs = t0.elapsed().as_secs_f64();
    let (so, se) = text(&o);
    println!("{so}{se}default run: {secs:.3} s");
    assert!(o.status.success());
    let files = entries(&out);
    println!("{files:?}");
    for f in [
        "result.json",
        "surface.csv",
        "field.csv",
        "pressure.svg",
        "traction.svg",
        "stick_slip.svg",
        "displacement.svg",
        "field_sxx.svg",
    ] {
        assert!(files.contains(&f.to_string()), "{f} missing");
    }
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("result.json")).unwrap()).unwrap();
    let p = v["contact"]["normal_load"].as_f64().unwrap();
    assert!((p / (986.39 * 9.80665) - 1.0).abs() < 1e-5, "{p}");
    assert_eq!(v["field"]["sxx"].as_array().unwrap().len(), 40);
    assert!(entries(&d).iter().all(|n| !n.contains("tmp")));
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn json_goes_to_stdout_and_explain_computes_nothing() {
    let o = bin().args(["run", "--json"]).output().unwrap();
    assert!(o.status.success());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    for k in [
        "title",
        "effects",
        "contact",
        "zones",
        "forces",
        "rigid_displacement",
        "surface",
        "field",
        "solver",
    ] {
        assert!(v.get(k).is_some(), "{k}");
    }
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/seed002_ex1_lp.toml");
    let o = bin().arg("explain").arg(&scene).output().unwrap();
    let (so, _) = text(&o);
    println!("{so}");
    assert!(o.status.success());
    assert!(
        so.contains("effects off") && so.contains("modified LP") && so.contains("estimated cost")
    );
}

#[test]
fn bad_input_exits_non_zero_with_location_and_leaves_nothing() {
    let d = tmp("bad");
    let out = d.join("out");
    // a file that does not exist
    let o = bin().args(["run", "/nonexistent/scene.toml", "--out"]).arg(&out).output().unwrap();
    let (_, se) = text(&o);
    println!("{se}");
    assert!(!o.status.success());
    assert!(se.contains("/nonexistent/scene.toml"));
    // a malformed scene: nu > 0.5 on line 7
    let bad = d.join("bad.toml");
    std::fs::write(&bad, "[geometry]\nkind = \"sphere\"\nradius = 0.01\n[substrate]\nmodel = \"homogeneous\"\ne = 1e9\nnu = 0.6\n[load]\nnormal = 10.0\n").unwrap();
    let o = bin().arg("run").arg(&bad).arg("--out").arg(&out).output().unwrap();
    let (_, se) = text(&o);
    println!("{se}");
    assert!(!o.status.success());
    assert!(se.contains("bad.toml:7:6"), "{se}");
    assert!(se.contains("substrate.nu") && se.contains("hint"));
    // an impossible scene: T > f P with the load given as a half-width
    let imp = d.join("impossible.toml");
    std::fs::write(&imp, "[geometry]\nkind = \"cylinder\"\nradius = 0.3\n[substrate]\nmodel = \"graded\"\ne0 = \"1767600 kgf/m^2.1\"\nk = 0.1\nnu = 0.3\n[load]\nhalf_width = 0.0178\nfriction = 0.5\ntangential = 5000.0\n").unwrap();
    let o = bin().arg("run").arg(&imp).arg("--out").arg(&out).output().unwrap();
    let (_, se) = text(&o);
    println!("{se}");
    assert!(!o.status.success());
    assert!(se.contains("impossible.toml:12:") && se.contains("load.tangential"), "{se}");
    // a directory that cannot be written (its parent is a regular file)
    let o = bin().arg("run").arg("--out").arg(bad.join("out")).output().unwrap();
    let (_, se) = text(&o);
    println!("{se}");
    assert!(!o.status.success());
    assert!(se.contains("cannot write"));
    // nothing was left behind
    assert_eq!(entries(&d), vec!["bad.toml".to_string(), "impossible.toml".to_string()]);
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn grid_runs_print_element_counts_and_the_solver_and_explain_names_the_grid_solver() {
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes");
    for (name, tag, choice) in [
        ("seed002_ex4_square.toml", "LpForce", "modified LP"),
        ("fast_two_patch_joint_fine.toml", "Fast", "fast solver"),
    ] {
        let o = bin().arg("run").arg(scenes.join(name)).output().unwrap();
        let (so, se) = text(&o);
        println!("{so}{se}");
        assert!(o.status.success());
        assert!(!so.contains("stick: []"), "{so}");
        let line = so.lines().find(|l| l.trim_start().starts_with("stick:")).unwrap();
        assert!(
            line.contains(" elements, slip: ") && line.contains("stick area fraction"),
            "{line}"
        );
        let solver = so.lines().find(|l| l.trim_start().starts_with("solver:")).unwrap();
        assert!(solver.contains(tag) && solver.contains("iterations"), "{solver}");
        let o = bin().arg("explain").arg(scenes.join(name)).output().unwrap();
        let (so, _) = text(&o);
        assert!(o.status.success());
        // the line and its continuation lines (wrapped to 80 columns under the value)
        let g: Vec<&str> = so
            .lines()
            .skip_while(|l| !l.starts_with("grid solver:"))
            .enumerate()
            .take_while(|(k, l)| *k == 0 || l.starts_with("             "))
            .map(|(_, l)| l.trim())
            .collect();
        let g = g.join(" ");
        println!("{g}");
        assert!(g.contains(choice), "{g}");
    }
}

#[test]
fn a_run_ends_with_a_one_line_summary_unless_quiet() {
    let d = tmp("summary");
    let out = d.join("out");
    let o = bin().args(["run", "--out"]).arg(&out).output().unwrap();
    let (_, se) = text(&o);
    assert!(o.status.success(), "{se}");
    // stderr is not a terminal here: no progress bar, only the summary: one line, wrapped
    // to 80 columns (its continuation lines indented).
    let lines: Vec<&str> = se.lines().collect();
    assert!(!lines[0].starts_with(' ') && lines[1..].iter().all(|l| l.starts_with("  ")), "{se}");
    assert!(lines.iter().all(|l| l.chars().count() <= 80 || l.contains('/')), "{se}");
    let summary = lines.iter().map(|l| l.trim()).collect::<Vec<_>>().join(" ");
    let report = out.join("report.html").display().to_string();
    assert!(summary.contains("solved in") && summary.contains(&report), "{se}");
    assert!(out.join("report.html").exists());
    let o = bin().args(["run", "--quiet", "--out"]).arg(&out).output().unwrap();
    let (_, se) = text(&o);
    assert!(o.status.success() && se.is_empty(), "{se}");
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn every_subcommand_help_has_an_example() {
    for sub in [
        "run",
        "explain",
        "sweep",
        "merge",
        "reproduce",
        "accuracy",
        "new",
        "schema",
        "completions",
        "man",
    ] {
        let o = bin().args([sub, "--help"]).output().unwrap();
        let (so, _) = text(&o);
        assert!(o.status.success(), "{sub}");
        let at = so.find("Example").unwrap_or_else(|| panic!("{sub} --help has no example:\n{so}"));
        assert!(so[at..].contains(&format!("stickslip {sub}")), "{sub}: {so}");
    }
}
