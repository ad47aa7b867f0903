//! Bad wheel-on-rail input through a scene and the program (issue 29 item 10): profiles
//! that never come close, a lateral shift past flange climb, a profile with a NaN, a profile
//! in the wrong unit, a wheel profile given as the rail. Each is refused before any contact
//! is solved: exit status 2, the key (and for a file its name and line), a hint, and no
//! output directory.

use std::path::{Path, PathBuf};
use std::process::Command;

fn data(file: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../wheelrail/data").join(file)
}

/// The shipped scene with the profile paths made absolute, then `edit` applied.
fn scene(edit: impl Fn(String) -> String) -> String {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/wheel_rail_manchester_a22.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let text = text
        .replace(
            "../crates/wheelrail/data/MBench_UIC60_v3.prr",
            &data("MBench_UIC60_v3.prr").display().to_string(),
        )
        .replace(
            "../crates/wheelrail/data/MBench_S1002_v3.prw",
            &data("MBench_S1002_v3.prw").display().to_string(),
        );
    edit(text)
}

/// Run `text` (written as scene.toml in a fresh directory beside `files`); the stderr of a
/// refusal with exit status 2 that wrote nothing.
fn refused(name: &str, text: &str, files: &[(&str, String)]) -> String {
    let dir =
        std::env::temp_dir().join(format!("stickslip-wr-refusal-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for (f, t) in files {
        std::fs::write(dir.join(f), t).unwrap();
    }
    let scene = dir.join("scene.toml");
    std::fs::write(&scene, text).unwrap();
    let out = dir.join("out");
    let o = Command::new(env!("CARGO_BIN_EXE_stickslip"))
        .arg("run")
        .arg(&scene)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert_eq!(o.status.code(), Some(2), "{name}: {err}");
    assert!(!out.exists(), "{name}: the output directory was created");
    assert!(err.contains("hint"), "{name}: no hint in {err}");
    let _ = std::fs::remove_dir_all(&dir);
    err
}

#[test]
fn profiles_that_never_come_close_give_the_smallest_gap_and_where() {
    // The wheels 320 mm further apart than the rails' gauge allows.
    let text = scene(|t| {
        t.replace("flange_back_distance = \"1360 mm\"", "flange_back_distance = \"2000 mm\"")
    });
    let err = refused("apart", &text, &[]);
    assert!(err.contains("position.lateral"), "{err}");
    assert!(err.contains("gap"), "{err}");
}

#[test]
fn a_lateral_shift_past_flange_climb_is_refused() {
    // The left wheel's flange is on the track-centre side: a shift to the left (negative y)
    // of 20 mm climbs it (the right wheel's library test shifts +20 mm).
    let text = scene(|t| t.replace("lateral = \"2 mm\"", "lateral = \"-20 mm\""));
    let err = refused("climb", &text, &[]);
    assert!(err.contains("position.lateral") && err.contains("flange"), "{err}");
}

#[test]
fn a_profile_with_a_nan_names_the_file_and_line() {
    let rail = std::fs::read_to_string(data("MBench_UIC60_v3.prr")).unwrap();
    let mut lines: Vec<String> = rail.lines().map(String::from).collect();
    // The first point after the point block's comment lines.
    let first = lines.iter().position(|l| l.trim() == "point.begin").unwrap() + 4;
    let y = lines[first].split_whitespace().next().unwrap().to_string();
    lines[first] = format!("    {y}  nan");
    let text = scene(|t| t.replace(&data("MBench_UIC60_v3.prr").display().to_string(), "rail.prr"));
    let err = refused("nan", &text, &[("rail.prr", lines.join("\n"))]);
    assert!(err.contains("geometry.rail_profile"), "{err}");
    assert!(err.contains(&format!("rail.prr:{}", first + 1)), "line {}: {err}", first + 1);
}

#[test]
fn a_profile_in_the_wrong_unit_is_refused() {
    // Millimetre numbers read as metres: a rail 170 m high.
    let text = scene(|t| t.replace("profile_unit = \"mm\"", "profile_unit = \"m\""));
    let err = refused("unit", &text, &[]);
    assert!(err.contains("geometry."), "{err}");
    assert!(err.contains("unit"), "{err}");
}

#[test]
fn a_plain_profile_in_the_wrong_unit_is_refused() {
    // The rail's points as a plain y,z table in millimetres (no header stating the unit),
    // read in metres: a rail 170 m high.
    let rail = std::fs::read_to_string(data("MBench_UIC60_v3.prr")).unwrap();
    let start = rail.lines().position(|l| l.trim() == "point.begin").unwrap();
    let csv: Vec<String> = rail
        .lines()
        .skip(start + 1)
        .take_while(|l| l.trim() != "point.end")
        .filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('!'))
        .map(|l| l.split_whitespace().take(2).collect::<Vec<_>>().join(","))
        .collect();
    assert!(csv.len() > 10);
    let text = scene(|t| {
        t.replace(&data("MBench_UIC60_v3.prr").display().to_string(), "rail.csv")
            .replace("profile_unit = \"mm\"", "profile_unit = \"m\"")
    });
    let err = refused("plain-unit", &text, &[("rail.csv", csv.join("\n"))]);
    assert!(err.contains("geometry.rail_profile") && err.contains("rail.csv"), "{err}");
    assert!(err.contains("unit"), "{err}");
}

#[test]
fn a_wheel_profile_given_as_the_rail_is_refused() {
    let text = scene(|t| {
        t.replace(
            &data("MBench_UIC60_v3.prr").display().to_string(),
            &data("MBench_S1002_v3.prw").display().to_string(),
        )
    });
    let err = refused("role", &text, &[]);
    assert!(err.contains("geometry.rail_profile") && err.contains("wheel"), "{err}");
}
