//! `load.vertical` (issue 29): what carries the vertical wheel load. With "normal" (the
//! default) the vertical components of the patches' normal forces add up to `load.normal`;
//! with "total" the total vertical force of the wheel on the rail, creep forces included
//! (result.json's `wheel_rail.total_on_rail.fz`, summed from the patches' own forces), does,
//! as under CONTACT's force control. The key is refused with a wrong value, outside a wheel
//! on its rail and beside `load.approach`, each naming file:line:column, the key and a hint.

// SceneError carries file, position, key and hint; tests return it as is.
#![allow(clippy::result_large_err)]

mod common;
use common::scenes_dir;
use stickslip_run::{run, Outcome, RunOptions};
use stickslip_scene::{Scene, SceneError};

/// The shipped scene (position 5 unless `lateral` is given) with `edit` applied.
fn text(edit: &dyn Fn(String) -> String) -> (String, std::path::PathBuf) {
    let path = scenes_dir().join("wheel_rail_manchester_a22.toml");
    (edit(std::fs::read_to_string(&path).unwrap()), path)
}

fn parse(edit: &dyn Fn(String) -> String) -> Result<Scene, SceneError> {
    let (t, path) = text(edit);
    Scene::from_toml_str(&t, Some(path))
}

fn solve(vertical: Option<&str>, method: &str, lateral: &str) -> Outcome {
    let s = parse(&|t: String| {
        let t = t
            .replace("lateral = \"2 mm\"", &format!("lateral = \"{lateral}\""))
            .replace("[solver]\n", &format!("[solver]\n{method}"));
        match vertical {
            Some(v) => {
                t.replace("friction = 0.3\n", &format!("friction = 0.3\nvertical = \"{v}\"\n"))
            }
            None => t,
        }
    })
    .unwrap_or_else(|e| panic!("{e}"));
    run(&s, &RunOptions::default()).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn total_makes_the_total_vertical_force_the_load_and_normal_the_normal_forces() {
    let load = 10e3;
    for method in ["method = \"fastsim\"\n", ""] {
        // Position 5 (2 mm, a lateral creep force of about 0.3 f Fn on a tread contact of
        // 13 mrad) and position 21 (10 mm, 24 mrad of yaw, 11 mrad of contact angle).
        for lateral in ["2 mm", "10 mm"] {
            let by_default = solve(None, method, lateral);
            let normal = solve(Some("normal"), method, lateral);
            let total = solve(Some("total"), method, lateral);
            let (d, n, t) = (
                by_default.wheel_rail.as_ref().unwrap(),
                normal.wheel_rail.as_ref().unwrap(),
                total.wheel_rail.as_ref().unwrap(),
            );
            assert_eq!(d, n, "{method} {lateral}: \"normal\" is the default");
            // The normal forces' vertical components, from the patches as reported.
            let vertical = |w: &stickslip_run::WheelRailOut| {
                w.patches.iter().map(|p| p.fn_ * p.contact_angle.cos()).sum::<f64>()
            };
            let fz = |w: &stickslip_run::WheelRailOut| {
                w.patches.iter().map(|p| p.force_on_rail.fz).sum::<f64>()
            };
            let rel = |v: f64| (v - load).abs() / load;
            assert!(rel(vertical(n)) <= 1e-6, "{method} {lateral}: normal {}", vertical(n));
            assert!(
                rel(t.total_on_rail.fz) <= 1e-6,
                "{method} {lateral}: total {}",
                t.total_on_rail.fz
            );
            assert!((fz(t) - t.total_on_rail.fz).abs() <= 1e-9 * load, "{method} {lateral}");
            // The two definitions differ by the creep forces' vertical part, F_s sin(delta),
            // which is not small here: the total force misses the load under "normal", and
            // the normal forces under "total".
            let creep: f64 = n.patches.iter().map(|p| p.fs * p.contact_angle.sin()).sum();
            assert!(creep.abs() > 1e-3 * load, "{method} {lateral}: creep part {creep}");
            assert!(
                (n.total_on_rail.fz - load - creep).abs() <= 1e-6 * load,
                "{method} {lateral}: {} vs {load} + {creep}",
                n.total_on_rail.fz
            );
            assert!(rel(vertical(t)) > 1e-4, "{method} {lateral}: {}", vertical(t));
            assert_eq!(t.vertical_load, Some(load));
        }
    }
}

#[test]
fn a_wrong_value_names_the_key_its_position_and_the_values() {
    let e =
        parse(&|t: String| t.replace("friction = 0.3\n", "friction = 0.3\nvertical = \"net\"\n"))
            .expect_err("refused");
    assert_eq!(e.key.as_deref(), Some("load.vertical"));
    let (src, _) =
        text(&|t: String| t.replace("friction = 0.3\n", "friction = 0.3\nvertical = \"net\"\n"));
    let line = src.lines().position(|l| l.starts_with("vertical")).unwrap() + 1;
    assert_eq!(e.position.map(|p| p.0), Some(line));
    let msg = e.to_string();
    assert!(msg.contains(&format!("wheel_rail_manchester_a22.toml:{line}:")), "{msg}");
    for w in ["net", "\"normal\"", "\"total\""] {
        assert!(msg.contains(w), "{w}: {msg}");
    }
}

#[test]
fn refused_beside_an_approach_and_outside_a_wheel_on_its_rail() {
    let e = parse(&|t: String| {
        t.replace("normal = \"10 kN\"", "approach = \"20 um\"")
            .replace("friction = 0.3\n", "friction = 0.3\nvertical = \"total\"\n")
    })
    .expect_err("refused");
    assert_eq!(e.key.as_deref(), Some("load.vertical"), "{e}");
    assert!(e.position.is_some() && e.hint.is_some(), "{e}");
    assert!(e.to_string().contains("load.approach"), "{e}");

    let src = "[geometry]\nkind = \"sphere\"\nradius = \"10 mm\"\n[substrate]\nmodel = \"homogeneous\"\ne = \"210 GPa\"\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = \"100 N\"\nvertical = \"total\"\n";
    let e = Scene::from_toml_str(src, Some("bad.toml".into())).expect_err("refused");
    assert_eq!(e.key.as_deref(), Some("load.vertical"), "{e}");
    assert_eq!(e.position.map(|p| p.0), Some(12), "{e}");
    assert!(e.to_string().starts_with("bad.toml:12:"), "{e}");
    assert!(e.hint.as_deref().is_some_and(|h| h.contains("wheel-rail")), "{e}");
}
