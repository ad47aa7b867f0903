//! Plots are on by default (issue 33, item 1), and a report of a big lattice stays small:
//! the maps of a 1024 x 1024 surface are drawn as images of 160 x 160 block means, while the
//! `.npy` arrays keep every cell.

use std::path::{Path, PathBuf};
use std::process::Command;

fn tmp(name: &str) -> PathBuf {
    let d =
        std::env::temp_dir().join(format!("stickslip-big-report-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

const SCENE: &str = "[geometry]\nkind = \"surface\"\nsize = [\"0.6 mm\", \"0.6 mm\"]\ncells = [1024, 1024]\n[geometry.profile]\nshape = \"sphere\"\nradius = \"10 mm\"\n[geometry.roughness]\nhurst = 0.8\nrms_height = \"50 nm\"\nk_low = 2.0\nseed = 1\n[substrate]\nmodel = \"homogeneous\"\nmaterial = \"steel\"\n[indenter]\nmodel = \"same\"\n[load]\nnormal = \"5 N\"\ntangential = \"0.5 N\"\nfriction = 0.2\nOUTPUTS";

fn run(dir: &Path, outputs: &str) -> PathBuf {
    let scene = dir.join("big.toml");
    std::fs::write(&scene, SCENE.replace("OUTPUTS", outputs)).unwrap();
    let out = dir.join("out");
    let o = Command::new(env!("CARGO_BIN_EXE_stickslip"))
        .args(["run", scene.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    out
}

#[test]
fn a_1024_squared_surface_has_its_plots_in_a_report_under_2_mb() {
    let dir = tmp("on");
    let out = run(&dir, "");
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    let size = html.len();
    println!("report.html of a 1024^2 surface: {size} bytes");
    assert!(size < 2_000_000, "report.html is {size} bytes");
    // Plots by default: the maps and the stick map, each in the page.
    for svg in ["pressure.svg", "traction.svg", "stick_slip.svg"] {
        assert!(out.join(svg).exists(), "{svg} missing");
        assert!(html.contains(&format!("(also {svg})")), "{svg} not in report.html");
    }
    assert!(html.contains("data:image/png;base64,"), "the maps are not images");
    assert!(html.contains("7 x 7 cell blocks"), "the block size is not in the titles");
    assert!(html.contains("surface_p.npy"), "the report does not say where the full data are");
    // The arrays stay whole: 1024 x 1024 f64 and a 128-byte npy header.
    let npy = std::fs::metadata(out.join("surface_p.npy")).unwrap().len();
    assert_eq!(npy, 1024 * 1024 * 8 + 128);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn plots_false_turns_them_off() {
    let dir = tmp("off");
    let out = run(&dir, "[outputs]\nplots = false\n");
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(html.contains("Plots are off for this scene"));
    assert!(!out.join("pressure.svg").exists());
    assert!(!html.contains("<figure class=\"plot\""));
    let _ = std::fs::remove_dir_all(&dir);
}
