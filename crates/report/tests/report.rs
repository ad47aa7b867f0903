//! report.html: what it holds for a scene read from a file (write_outputs_report) and for a
//! bare outcome (write_outputs). Its rendering in a browser is tested by the CLI's
//! report_browser test.

use std::path::{Path, PathBuf};

use stickslip_report::{write_outputs, write_outputs_report, ReportContext, WriteOptions};
use stickslip_run::{Execute, Plan, RunOptions};
use stickslip_scene::Scene;

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("stickslip-report-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

#[test]
fn a_3d_rolling_report_holds_the_scene_plan_forces_audit_and_solver() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/wheel_rail_fastsim.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let scene = Scene::from_file(&path).unwrap();
    let plan = Plan::new(&scene).unwrap();
    let out = plan.execute(&RunOptions::default()).unwrap();
    let dir = scratch("rolling");
    write_outputs_report(
        &out,
        &dir,
        WriteOptions { plots: scene.outputs.plots, force: false },
        ReportContext { scene: &scene, plan: &plan },
    )
    .unwrap();
    let html = std::fs::read_to_string(dir.join("report.html")).unwrap();
    // The scene as given, escaped, line by line.
    for line in text.lines().filter(|l| !l.trim().is_empty()) {
        let esc = line.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;");
        let esc = esc.replace('"', "&quot;").replace('\'', "&#39;");
        assert!(html.contains(&esc), "scene line missing: {line}");
    }
    assert!(html.contains("<h3>As resolved</h3>"));
    // Every effect of the plan, on or off, with its reason.
    for e in &plan.effects {
        assert!(
            html.contains(&format!(
                "<td>{}</td><td>{}</td>",
                e.effect.name(),
                if e.on { "on" } else { "off" }
            )),
            "{:?}",
            e.effect
        );
    }
    // The creep forces in kN (Fy of this scene is about -19 kN) and the spin moment.
    let fy = out.forces.fy.unwrap();
    assert!((1e3..1e6).contains(&fy.abs()), "{fy}");
    assert!(html.contains(&format!("creep force Fy</th><td class=\"num\">{:.2} kN", fy / 1e3)));
    assert!(html.contains("spin moment Mz"));
    // One audit row per check, and the solver's iterations.
    let rows = html.matches("<td class=\"pass\">pass</td>").count();
    assert_eq!(rows, out.audit.checks.len());
    assert!(html.contains(&format!("iterations</th><td class=\"num\">{}<", out.solver.iterations)));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_report_from_a_bare_outcome_says_the_scene_is_missing() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/hertz_cylinder_cattaneo.toml");
    let scene = Scene::from_file(&path).unwrap();
    let out = stickslip_run::run(&scene, &RunOptions::default()).unwrap();
    let dir = scratch("bare");
    write_outputs(&out, &dir, false).unwrap();
    let html = std::fs::read_to_string(dir.join("report.html")).unwrap();
    assert!(html.contains("written without its scene"));
    assert!(html.contains("Plots are off"));
    // 2D loads are per unit length, but a bare outcome cannot tell 2D from 3D: both named.
    assert!(html.contains("N (N/m in 2D)"));
    let _ = std::fs::remove_dir_all(&dir);
}
