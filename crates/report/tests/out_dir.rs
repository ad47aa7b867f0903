//! `--out` is all or nothing (`write_outputs`): fault injection on the output directory. An
//! earlier, richer result is replaced whole; a directory of foreign files is refused (and
//! left untouched) unless forced; a read-only parent leaves everything as it was, and the
//! message says so; temporaries of killed runs are cleaned and a previous result a killed
//! run left aside is moved back; concurrent writers end with one complete result.

use std::path::{Path, PathBuf};

use stickslip_report::{write_outputs, write_outputs_with, WriteOptions};
use stickslip_run::{run, Outcome, RunOptions};
use stickslip_scene::{ErrorKind, Scene};

/// A 2D scene with a field and plots: result.json, surface.csv, field.csv and SVGs.
const RICH: &str = r#"title = "rich"
[geometry]
kind = "cylinder"
radius = "20 mm"
[substrate]
model = "homogeneous"
e = "210 GPa"
nu = 0.3
[indenter]
model = "same"
[load]
normal = "100 kN/m"
tangential = "15 kN/m"
friction = 0.3
[outputs]
field = { x = [-2.0, 2.0, 11], y = [0.05, 2.0, 6], scale = "a" }
plots = true
"#;

fn outcome(src: &str) -> Outcome {
    run(&Scene::from_toml_str(src, None).unwrap(), &RunOptions::default()).unwrap()
}

fn poor() -> Outcome {
    outcome(&RICH.replace("title = \"rich\"", "title = \"poor\"").replace(
        "field = { x = [-2.0, 2.0, 11], y = [0.05, 2.0, 6], scale = \"a\" }\nplots = true",
        "plots = false",
    ))
}

fn base(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("stickslip-out-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
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

fn title(dir: &Path) -> String {
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("result.json")).unwrap()).unwrap();
    v["title"].as_str().unwrap().to_string()
}

/// A pid that exists no more (a child that has exited and been reaped).
fn dead_pid() -> u32 {
    let mut c = std::process::Command::new("true").spawn().unwrap();
    let pid = c.id();
    c.wait().unwrap();
    pid
}

#[test]
fn an_earlier_richer_result_is_replaced_whole() {
    let b = base("whole");
    let out = b.join("out");
    write_outputs(&outcome(RICH), &out, true).unwrap();
    let rich = entries(&out);
    println!("{rich:?}");
    assert!(rich.contains(&"field.csv".to_string()) && rich.iter().any(|n| n.ends_with(".svg")));
    let w = write_outputs(&poor(), &out, false).unwrap();
    let now = entries(&out);
    println!("{now:?}");
    assert_eq!(now, vec![".stickslip-result", "report.html", "result.json", "surface.csv"]);
    assert_eq!(title(&out), "poor");
    assert_eq!(w.files.len(), 3);
    assert_eq!(entries(&b), vec!["out"], "temporaries or the lock left beside");
    let _ = std::fs::remove_dir_all(&b);
}

#[test]
fn foreign_files_are_refused_untouched_and_replaced_with_force() {
    let b = base("foreign");
    let out = b.join("thesis");
    std::fs::create_dir(&out).unwrap();
    std::fs::write(out.join("chapter1.tex"), "precious").unwrap();
    let e = write_outputs(&poor(), &out, false).unwrap_err();
    let msg = e.to_string();
    println!("{msg}");
    assert_eq!(e.kind, ErrorKind::Io);
    assert_eq!(e.exit_code(), 1);
    assert!(
        msg.contains("chapter1.tex")
            && msg.contains("--force")
            && msg.contains("nothing was changed")
    );
    assert_eq!(entries(&out), vec!["chapter1.tex"]);
    assert_eq!(std::fs::read_to_string(out.join("chapter1.tex")).unwrap(), "precious");
    assert_eq!(entries(&b), vec!["thesis"]);
    // A result of an earlier version (no marker, result.json and known files) is ours.
    let old = b.join("old");
    std::fs::create_dir(&old).unwrap();
    std::fs::write(
        old.join("result.json"),
        r#"{"title":"x","effects":{},"contact":{},"solver":{}}"#,
    )
    .unwrap();
    std::fs::write(old.join("surface.csv"), "x").unwrap();
    std::fs::write(old.join("pressure.svg"), "x").unwrap();
    write_outputs(&poor(), &old, false).unwrap();
    assert_eq!(
        entries(&old),
        vec![".stickslip-result", "report.html", "result.json", "surface.csv"]
    );
    // --force replaces the foreign directory whole.
    write_outputs_with(&poor(), &out, WriteOptions { plots: false, force: true }).unwrap();
    assert_eq!(
        entries(&out),
        vec![".stickslip-result", "report.html", "result.json", "surface.csv"]
    );
    assert_eq!(entries(&b), vec!["old", "thesis"]);
    let _ = std::fs::remove_dir_all(&b);
}

#[test]
fn paths_that_must_not_be_replaced_are_refused() {
    let b = base("refuse");
    // a file
    std::fs::write(b.join("f"), "x").unwrap();
    let e = write_outputs(&poor(), &b.join("f"), false).unwrap_err();
    assert!(e.to_string().contains("not a directory"), "{e}");
    // the working directory (and its parents), even with force
    let cwd = std::env::current_dir().unwrap();
    for p in [cwd.clone(), cwd.join(".."), PathBuf::from(".")] {
        let e = write_outputs_with(&poor(), &p, WriteOptions { plots: false, force: true })
            .unwrap_err();
        println!("{}: {e}", p.display());
        assert_eq!(e.kind, ErrorKind::Io);
    }
    #[cfg(unix)]
    {
        std::fs::create_dir(b.join("real")).unwrap();
        std::os::unix::fs::symlink(b.join("real"), b.join("link")).unwrap();
        let e = write_outputs(&poor(), &b.join("link"), false).unwrap_err();
        assert!(e.to_string().contains("symbolic link"), "{e}");
    }
    let _ = std::fs::remove_dir_all(&b);
}

#[cfg(unix)]
#[test]
fn a_read_only_parent_leaves_everything_intact_with_an_honest_message() {
    use std::os::unix::fs::PermissionsExt;
    let b = base("ro");
    let ro = b.join("ro");
    std::fs::create_dir(&ro).unwrap();
    let out = ro.join("out");
    write_outputs(&outcome(RICH), &out, true).unwrap();
    let before = entries(&out);
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o555)).unwrap();
    if std::fs::write(ro.join("probe"), "").is_ok() {
        println!(
            "skipped: this user may write read-only directories (root), so permissions do not bite"
        );
        let _ = std::fs::remove_file(ro.join("probe"));
    } else {
        let e = write_outputs(&poor(), &out, false).unwrap_err();
        let msg = e.to_string();
        println!("{msg}");
        assert_eq!(e.kind, ErrorKind::Io);
        assert!(msg.contains("nothing was changed"), "{msg}");
        assert_eq!(entries(&out), before);
        assert_eq!(title(&out), "rich");
        assert_eq!(entries(&ro), vec!["out"]);
    }
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o755)).unwrap();
    let _ = std::fs::remove_dir_all(&b);
}

#[test]
fn temporaries_of_killed_runs_are_cleaned_and_a_result_left_aside_is_moved_back() {
    let b = base("stale");
    let out = b.join("out");
    let dead = dead_pid();
    // A killed run's lock, temporary directory, and (killed between its renames) the
    // previous result moved aside while `out` is missing.
    std::fs::write(b.join(".out.stickslip-lock"), format!("{dead}\n")).unwrap();
    let tmp = b.join(format!(".out.stickslip-tmp-{dead}-1"));
    std::fs::create_dir(&tmp).unwrap();
    std::fs::write(tmp.join("result.json"), "half").unwrap();
    write_outputs(&outcome(RICH), &b.join("keep"), false).unwrap();
    let aside = b.join(format!(".out.stickslip-old-{dead}-2"));
    std::fs::rename(b.join("keep"), &aside).unwrap();
    // A temporary of a live process (pid 1) is not touched.
    let live = b.join(".out.stickslip-tmp-1-3");
    std::fs::create_dir(&live).unwrap();
    // The previous result comes back before it is replaced: the notes say so.
    let w = write_outputs(&poor(), &out, false).unwrap();
    println!("{:#?}", w.notes);
    assert!(w.notes.iter().any(|n| n.contains("moved back")), "{:?}", w.notes);
    assert!(w.notes.iter().any(|n| n.contains("removed")), "{:?}", w.notes);
    assert_eq!(title(&out), "poor");
    assert_eq!(entries(&b), vec![".out.stickslip-tmp-1-3", "out"]);
    let _ = std::fs::remove_dir_all(&b);
}

#[test]
fn concurrent_writers_end_with_one_complete_result() {
    let b = base("threads");
    let out = b.join("out");
    let rich = outcome(RICH);
    let poor = poor();
    std::thread::scope(|s| {
        let hs: Vec<_> = (0..6)
            .map(|i| {
                let (o, plots) = if i % 2 == 0 { (&rich, true) } else { (&poor, false) };
                let out = &out;
                s.spawn(move || write_outputs(o, out, plots).unwrap())
            })
            .collect();
        for h in hs {
            h.join().unwrap();
        }
    });
    let names = entries(&out);
    match title(&out).as_str() {
        "poor" => assert_eq!(
            names,
            vec![".stickslip-result", "report.html", "result.json", "surface.csv"]
        ),
        _ => assert!(
            names.contains(&"field.csv".to_string()) && names.iter().any(|n| n.ends_with(".svg"))
        ),
    }
    assert_eq!(entries(&b), vec!["out"]);
    let _ = std::fs::remove_dir_all(&b);
}
