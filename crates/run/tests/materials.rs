//! Named materials in a run: the run of a scene with named materials matches Hertz with
//! the table's moduli, and `explain` prints the moduli it used.

// SceneError carries file, position, key and hint; tests return it as is.
#![allow(clippy::result_large_err)]

use stickslip_run::{run, Plan, RunOptions};
use stickslip_scene::{Scene, SceneError};

/// The issue's newcomer: a 1 mN load on a 0.5 mm ball, named materials.
const BALL: &str = r#"title = "silicon nitride ball on glass"
[geometry]
kind = "sphere"
radius = "0.5 mm"
[substrate]
model = "homogeneous"
material = "glass"
[indenter]
model = "homogeneous"
material = "silicon nitride"
[load]
normal = "1 mN"
tangential = "100 uN"
friction = 0.3
"#;

fn read(src: &str) -> Result<Scene, SceneError> {
    Scene::from_toml_str(src, Some("m.toml".into()))
}

/// The contact radius of the run against Hertz, a = (3 P R / (4 E*))^(1/3), computed here.
#[test]
fn the_one_millinewton_ball_runs_and_matches_hertz() {
    let s = read(BALL).unwrap();
    let out = run(&s, &RunOptions::default()).unwrap();
    let e_star = 1.0 / ((1.0 - 0.22f64.powi(2)) / 70e9 + (1.0 - 0.27f64.powi(2)) / 310e9);
    let a = (3.0 * 1e-3 * 0.5e-3 / (4.0 * e_star)).cbrt();
    assert!((out.contact.a / a - 1.0).abs() < 1e-12, "{} against {a}", out.contact.a);
    assert!((out.contact.normal_load - 1e-3).abs() < 1e-15);
}

#[test]
fn explain_prints_the_moduli_used() {
    let text = Plan::new(&read(BALL).unwrap()).unwrap().explain();
    assert!(text.contains("materials (typical values of one grade"), "{text}");
    assert!(
        text.contains("substrate  glass: E = 70 GPa, nu = 0.22 (soda-lime float glass"),
        "{text}"
    );
    assert!(text.contains("indenter   silicon nitride: E = 310 GPa, nu = 0.27"), "{text}");
    // A scene without names prints no such section.
    let plain = BALL
        .replace("material = \"glass\"", "e = \"70 GPa\"\nnu = 0.22")
        .replace("material = \"silicon nitride\"", "e = \"310 GPa\"\nnu = 0.27");
    assert!(!Plan::new(&read(&plain).unwrap()).unwrap().explain().contains("materials ("));
}
