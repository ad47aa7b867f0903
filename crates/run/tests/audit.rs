//! Every result is audited before it is written (issue: never a silent wrong answer):
//! shipped scenes pass every check with the limits stated, no number in result.json is
//! `null`, closed forms shown on a lattice obey Coulomb's law and equilibrium on the
//! lattice, and a result that fails a check is refused with the key to change.

use std::path::Path;

use stickslip_run::{run, Outcome, RunOptions};
use stickslip_scene::{ErrorKind, Scene};

fn scenes() -> Vec<std::path::PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes");
    let mut v: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    v.sort();
    v
}

fn has_null(v: &serde_json::Value) -> bool {
    match v {
        serde_json::Value::Null => true,
        serde_json::Value::Array(a) => a.iter().any(has_null),
        serde_json::Value::Object(o) => o.values().any(has_null),
        _ => false,
    }
}

#[test]
fn every_shipped_scene_passes_its_audit_and_writes_no_null() {
    for path in scenes() {
        let name = path.display().to_string();
        let out = run(&Scene::from_file(&path).unwrap(), &RunOptions::default()).unwrap();
        assert!(out.audit.passed, "{name}");
        let names: Vec<&str> = out.audit.checks.iter().map(|c| c.name).collect();
        // An adhesive contact may pull and let go: its sizes are checked non-negative.
        let sizes = if out.contact.pull_off.is_some() { "sizes" } else { "positive sizes" };
        // The traction checks read the written surface (absent with outputs.surface = false).
        let written = match &out.surface {
            stickslip_run::SurfaceOut::Line { x, .. }
            | stickslip_run::SurfaceOut::Grid { x, .. } => !x.is_empty(),
        };
        let required: &[&str] =
            if written { &["finite", sizes, "coulomb"] } else { &["finite", sizes] };
        for required in required {
            assert!(names.contains(required), "{name}: no {required} check in {names:?}");
        }
        for c in &out.audit.checks {
            assert!(c.pass && c.value.is_finite() && c.limit.is_finite(), "{name}: {c:?}");
        }
        let json: serde_json::Value = serde_json::from_str(&out.to_json()).unwrap();
        assert!(!has_null(&json), "{name}: a null in result.json");
        assert!(json["audit"]["passed"].as_bool().unwrap(), "{name}");
    }
}

#[allow(clippy::result_large_err)]
fn mindlin(grid: usize) -> Result<Outcome, stickslip_scene::SceneError> {
    let src = format!(
        "[geometry]\nkind = \"sphere\"\nradius = \"1 in\"\n[substrate]\nmodel = \"homogeneous\"\ne = \"30e6 psi\"\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = \"2160 lbf\"\ntangential = \"144 lbf\"\nfriction = 0.1\n[solver]\ngrid = {grid}\n"
    );
    run(&Scene::from_toml_str(&src, Some("m.toml".into()))?, &RunOptions::default())
}

/// Independent of the audit's own arithmetic: sum the written lattice directly.
#[test]
fn a_closed_form_on_a_lattice_obeys_coulomb_and_carries_the_load_at_every_grid() {
    for grid in [4, 6, 10, 20, 32, 64] {
        let out = mindlin(grid).unwrap();
        let stickslip_run::SurfaceOut::Grid { x, y, p, qx, qy, .. } = &out.surface else {
            panic!("a lattice")
        };
        let area = (x[1] - x[0]) * (y[1] - y[0]);
        let f = 0.1;
        let (mut tx, mut ty, mut worst) = (0.0, 0.0, 0.0f64);
        for i in 0..x.len() {
            for j in 0..y.len() {
                let q = qx[i][j].hypot(qy[i][j]);
                worst = worst.max(q / (f * p[i][j]).max(f64::MIN_POSITIVE));
                tx += qx[i][j] * area;
                ty += qy[i][j] * area;
            }
        }
        let t = out.forces.tangential;
        assert!(worst <= 1.0 + 1e-12, "grid {grid}: |q|/(f p) up to {worst}");
        assert!((tx - t).abs() <= 1e-12 * t && ty.abs() <= 1e-12 * t, "grid {grid}: {tx} vs {t}");
    }
}

#[test]
fn a_lattice_too_coarse_for_the_stick_zone_is_refused_with_the_grid_key() {
    let src = "[geometry]\nkind = \"sphere\"\nradius = 0.01\n[substrate]\nmodel = \"homogeneous\"\ne = 2e11\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = 100.0\nmoment = 0.002\nfriction = 0.3\n[solver]\ngrid = 4\n";
    let e = run(&Scene::from_toml_str(src, Some("t.toml".into())).unwrap(), &RunOptions::default())
        .unwrap_err();
    assert_eq!(e.kind, ErrorKind::Audit, "{e}");
    assert_eq!(e.key.as_deref(), Some("solver.grid"), "{e}");
    assert_eq!(e.position.map(|p| p.0), Some(15), "{e}");
    assert!(e.message.contains("lattice sampling"), "{e}");
    // The failed checks travel with the error (the Python package's AuditError.checks).
    assert!(!e.checks.is_empty() && e.checks.iter().all(|c| !c.pass), "{:?}", e.checks);
    assert_eq!(e.checks[0].name, "lattice sampling");
}
