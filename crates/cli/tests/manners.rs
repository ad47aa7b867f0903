//! The binary's manners: exit codes (0 written, 1 I/O, 2 refused or usage, 3 not
//! trustworthy), a closed or full stdout (no panic), and `--out` under concurrent runs and
//! a kill (SIGKILL) during the write.

use std::io::Read as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_stickslip"))
}

fn scene(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes").join(name)
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("stickslip-manners-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn entries(d: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(d)
        .map(|r| {
            r.filter_map(Result::ok).map(|e| e.file_name().to_string_lossy().into_owned()).collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

/// A complete result directory: the marker, and a result.json that parses; its title.
fn complete(dir: &Path) -> Result<String, String> {
    let names = entries(dir);
    if !names.contains(&".stickslip-result".to_string()) {
        return Err(format!("no marker in {names:?}"));
    }
    let text = std::fs::read_to_string(dir.join("result.json")).map_err(|e| e.to_string())?;
    let v: serde_json::Value = serde_json::from_str(&text).map_err(|e| e.to_string())?;
    Ok(v["title"].as_str().unwrap_or_default().to_string())
}

#[test]
fn exit_codes_zero_one_and_two() {
    let d = tmp("codes");
    let code = |o: &Output| o.status.code();
    // 0: written
    let o = bin()
        .arg("run")
        .arg(scene("hertz_cylinder_cattaneo.toml"))
        .arg("--out")
        .arg(d.join("ok"))
        .output()
        .unwrap();
    assert_eq!(code(&o), Some(0), "{}", stderr(&o));
    // 1: I/O (a scene file that does not exist; an --out whose parent is a file)
    let o = bin().args(["run", "/nonexistent/scene.toml"]).output().unwrap();
    assert_eq!(code(&o), Some(1), "{}", stderr(&o));
    std::fs::write(d.join("file"), "x").unwrap();
    let o = bin()
        .arg("run")
        .arg(scene("hertz_cylinder_cattaneo.toml"))
        .arg("--out")
        .arg(d.join("file/out"))
        .output()
        .unwrap();
    assert_eq!(code(&o), Some(1), "{}", stderr(&o));
    // 2: refused before solving (syntax, schema, range) and usage errors
    for (name, text) in [
        ("syntax.toml", "[geometry\n"),
        ("schema.toml", "[geometry]\nkind = \"sphere\"\nradius = true\n[substrate]\nmodel = \"homogeneous\"\ne = 1e9\nnu = 0.3\n[load]\nnormal = 1.0\n"),
        ("range.toml", "[geometry]\nkind = \"sphere\"\nradius = 0.01\n[substrate]\nmodel = \"homogeneous\"\ne = 1e9\nnu = 0.6\n[load]\nnormal = 10.0\n"),
    ] {
        let p = d.join(name);
        std::fs::write(&p, text).unwrap();
        for cmd in ["run", "explain"] {
            let o = bin().arg(cmd).arg(&p).output().unwrap();
            let se = stderr(&o);
            println!("{name} {cmd}: {se}");
            assert_eq!(code(&o), Some(2), "{name} {cmd}: {se}");
            assert!(se.contains(name) && se.contains("hint") && !se.contains("panicked"), "{se}");
        }
    }
    for args in [&["run", "--bogus"][..], &["run", "--force"], &["frobnicate"]] {
        let o = bin().args(args).output().unwrap();
        assert_eq!(code(&o), Some(2), "{args:?}: {}", stderr(&o));
    }
    // --help names the exit codes
    for args in [&["--help"][..], &["run", "--help"]] {
        let o = bin().args(args).output().unwrap();
        let so = String::from_utf8_lossy(&o.stdout);
        assert!(so.contains("Exit status") && so.contains("3  solved but not trustworthy"), "{so}");
    }
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn a_stdout_closed_early_ends_the_program_quietly() {
    // result.json of this scene is about 100 kB, more than a pipe holds.
    let mut child = bin()
        .arg("run")
        .arg(scene("hertz_cylinder_cattaneo.toml"))
        .arg("--json")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut out = child.stdout.take().unwrap();
    let mut first = [0u8; 100];
    out.read_exact(&mut first).unwrap();
    drop(out);
    let o = child.wait_with_output().unwrap();
    let se = stderr(&o);
    println!("status {:?}, stderr {se:?}", o.status);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(se.is_empty(), "{se}");
    assert!(String::from_utf8_lossy(&first).starts_with('{'));
}

#[test]
fn a_full_stdout_is_an_error_with_status_one() {
    let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") else {
        println!("no /dev/full here: skipped");
        return;
    };
    for args in [&["--json"][..], &[]] {
        let o = bin()
            .arg("run")
            .arg(scene("hertz_cylinder_cattaneo.toml"))
            .args(args)
            .stdout(full.try_clone().unwrap())
            .output()
            .unwrap();
        let se = stderr(&o);
        println!("{args:?}: status {:?}, stderr {se:?}", o.status);
        assert_eq!(o.status.code(), Some(1), "{se}");
        assert!(se.contains("cannot write to standard output") && !se.contains("panicked"), "{se}");
    }
}

#[test]
fn concurrent_runs_into_one_out_end_with_one_complete_result() {
    let d = tmp("concurrent");
    let out = d.join("out");
    let runs: Vec<_> =
        ["hertz_cylinder_cattaneo.toml", "seed002_ex4_square.toml", "sphere_load_cycle.toml"]
            .iter()
            .map(|s| {
                bin()
                    .arg("run")
                    .arg(scene(s))
                    .arg("--out")
                    .arg(&out)
                    .stdout(Stdio::null())
                    .stderr(Stdio::piped())
                    .spawn()
                    .unwrap()
            })
            .collect();
    for c in runs {
        let o = c.wait_with_output().unwrap();
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let title = complete(&out).unwrap();
    // The files are those of the run whose title result.json carries, never a mix.
    let names = entries(&out);
    println!("{title}: {names:?}");
    let expect: &[&str] = if title.contains("cylinder") {
        &["field.csv", "field_sxx.svg", "pressure.svg", "surface.csv"]
    } else if title.contains("cycle") {
        &["cycle.csv", "cycle.svg"]
    } else {
        &["pressure.svg", "surface.csv"]
    };
    for f in expect {
        assert!(names.contains(&f.to_string()), "{f} missing from {names:?} ({title})");
    }
    if !title.contains("cylinder") {
        assert!(!names.contains(&"field.csv".to_string()), "{names:?}");
    }
    if !title.contains("cycle") {
        assert!(!names.contains(&"cycle.csv".to_string()), "{names:?}");
    }
    assert_eq!(entries(&d), vec!["out".to_string()], "temporaries or the lock left beside --out");
    let _ = std::fs::remove_dir_all(&d);
}

#[cfg(unix)]
#[test]
fn a_run_killed_while_writing_leaves_a_complete_result_and_the_next_run_cleans_up() {
    let d = tmp("kill");
    let out = d.join("out");
    let o = bin()
        .arg("run")
        .arg(scene("hertz_cylinder_cattaneo.toml"))
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let before = std::fs::read(out.join("result.json")).unwrap();
    // A large result (about 15 MB): kill the run as soon as its temporary directory appears.
    let mut child = bin()
        .arg("run")
        .arg(scene("fast_mindlin_sphere_256.toml"))
        .arg("--out")
        .arg(&out)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let t0 = Instant::now();
    let mut seen = false;
    while t0.elapsed() < Duration::from_secs(120) {
        if entries(&d).iter().any(|n| n.contains("stickslip-tmp")) {
            seen = true;
            break;
        }
        if child.try_wait().unwrap().is_some() {
            break;
        }
        std::thread::sleep(Duration::from_micros(200));
    }
    let killed = Command::new("kill").args(["-KILL", &child.id().to_string()]).status().unwrap();
    let status = child.wait().unwrap();
    println!(
        "temporary seen: {seen}; kill: {killed}; status {status:?}; beside: {:?}",
        entries(&d)
    );
    // Either the previous result, intact, or the new one, complete: never a mix.
    let title = complete(&out).unwrap();
    let now = std::fs::read(out.join("result.json")).unwrap();
    if title.contains("256") {
        assert!(entries(&out).contains(&"surface.csv".to_string()));
        assert!(!entries(&out).contains(&"field.csv".to_string()), "a stale file stayed");
    } else {
        assert_eq!(now, before, "the previous result changed");
        assert!(entries(&out).contains(&"field.csv".to_string()));
    }
    // The next run removes what the killed one left (temporaries, its lock).
    let o = bin()
        .arg("run")
        .arg(scene("hertz_cylinder_cattaneo.toml"))
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    println!("{}", stderr(&o));
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(entries(&d), vec!["out".to_string()]);
    complete(&out).unwrap();
    let _ = std::fs::remove_dir_all(&d);
}
