//! A run's `history.csv`, as `write_outputs` writes it, read back as a load path
//! (`[load.history] file = "history.csv"`, `columns = ["tangential", "normal"]`, one step
//! between corners): every step of the first run is a corner of the second, so the second
//! run solves the same path, and its shift and dissipation follow the first's to the
//! solver's tolerance. Before the fast solver's load residual was made continuous at zero
//! load, the step to the first run's zero crossing (a solved force of about 1e-14 N on
//! 480 N of locked-in traction) could not converge.

use stickslip_report::write_outputs;
use stickslip_run::{run, Outcome, RunOptions};
use stickslip_scene::Scene;

/// Seed 002 Example 1's sphere with `history` as its `[load.history]` body.
fn sphere(history: &str) -> String {
    format!(
        r#"[geometry]
kind = "sphere"
radius = "1 in"
[substrate]
model = "homogeneous"
e = "30e6 psi"
nu = 0.3
[indenter]
model = "same"
[load]
normal = "2160 lbf"
friction = 0.1
[load.history]
{history}
[solver]
grid = 48
"#
    )
}

fn solve(text: &str, file: &std::path::Path) -> Outcome {
    let scene =
        Scene::from_toml_str(text, Some(file.to_path_buf())).unwrap_or_else(|e| panic!("{e}"));
    run(&scene, &RunOptions::default()).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn a_runs_history_csv_read_back_reproduces_the_run() {
    let dir = std::env::temp_dir().join(format!("stickslip-history-csv-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let first = solve(
        &sphere("tangential = [\"0 lbf\", \"108 lbf\", \"-108 lbf\", \"108 lbf\"]\nsteps = 8"),
        &dir.join("first.toml"),
    );
    let out = dir.join("first");
    write_outputs(&first, &out, false).unwrap();
    let h = first.history.unwrap();
    let again = solve(
        &sphere("file = \"first/history.csv\"\ncolumns = [\"tangential\", \"normal\"]\nsteps = 1"),
        &dir.join("again.toml"),
    );
    let g = again.history.unwrap();
    // Every row a corner, one step between two: the same steps.
    assert_eq!(g.tangential.len(), h.tangential.len());
    assert_eq!(g.corners, (0..h.tangential.len()).collect::<Vec<_>>());
    let range = h.shift.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let worst = h.shift.iter().zip(&g.shift).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    let (ea, eb) = (h.dissipated.last().unwrap(), g.dissipated.last().unwrap());
    println!(
        "shift: worst difference {worst:e} m of {range:e} m; dissipated {ea:e} J against {eb:e} J"
    );
    assert!(worst <= 1e-6 * range, "shift differs by {worst:e} m of {range:e} m");
    assert!((ea - eb).abs() <= 1e-6 * ea, "dissipated {ea} against {eb}");
    let _ = std::fs::remove_dir_all(&dir);
}
