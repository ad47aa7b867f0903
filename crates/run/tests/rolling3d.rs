//! 3D rolling with creepage and spin through the scene: bad input refused with key and
//! position, full slip solved and said, the accuracy knob choosing the theory, and the
//! outputs (creep forces, micro-slip maps) consistent with the traction written.

use stickslip_run::{read_scene, run, Plan, RunOptions, SurfaceOut, Technique};
use stickslip_scene::{ErrorKind, Scene, SceneError};

fn wheel(creepage: &str, extra: &str) -> String {
    format!(
        r#"[geometry]
kind = "ellipsoid"
radii = ["460 mm", "300 mm"]
[substrate]
model = "homogeneous"
e = "210 GPa"
nu = 0.28
[indenter]
model = "same"
[load]
normal = "100 kN"
friction = 0.3
[motion]
kind = "rolling"
speed = "20 m/s"
creepage = {creepage}
{extra}"#
    )
}

fn refused(text: &str) -> SceneError {
    read_scene(text, Some("wheel.toml".into())).unwrap_err()
}

fn assert_refusal(e: &SceneError, kind: ErrorKind, key: &str, line: usize) {
    assert_eq!(e.kind, kind, "{e}");
    assert_eq!(e.key.as_deref(), Some(key), "{e}");
    assert_eq!(e.position.map(|p| p.0), Some(line), "{e}");
    assert!(e.hint.is_some(), "{e}");
}

#[test]
fn bad_rolling_input_is_refused_with_key_and_position() {
    // Spin without a reciprocal-length unit, or with a length.
    let e = refused(&wheel("{ longitudinal = 1e-3, spin = 0.1 }", ""));
    assert_refusal(&e, ErrorKind::Unit, "motion.creepage.spin", 16);
    assert!(e.hint.as_deref().unwrap().contains("1/m"), "{e}");
    let e = refused(&wheel("{ spin = \"0.1 m\" }", ""));
    assert_refusal(&e, ErrorKind::Unit, "motion.creepage.spin", 16);
    // A non-positive speed.
    for speed in ["0 m/s", "-3 m/s"] {
        let e = refused(&wheel("{ longitudinal = 1e-3 }", "").replace("20 m/s", speed));
        assert_refusal(&e, ErrorKind::OutOfRange, "motion.speed", 15);
    }
    // creep and creepage together; a cylinder; no friction; a prescribed tangential load.
    let e = refused(&wheel("{ longitudinal = 1e-3 }\ncreep = 1e-3", ""));
    assert_eq!(e.key.as_deref(), Some("motion.creep"), "{e}");
    let e = refused(
        &wheel("{ longitudinal = 1e-3 }", "")
            .replace(
                "kind = \"ellipsoid\"\nradii = [\"460 mm\", \"300 mm\"]",
                "kind = \"cylinder\"\nradius = \"460 mm\"",
            )
            .replace("normal = \"100 kN\"", "normal = \"100 kN/m\""),
    );
    assert_eq!((e.kind, e.key.as_deref()), (ErrorKind::Unsupported, Some("geometry.kind")), "{e}");
    let e =
        refused(&wheel("{ longitudinal = 1e-3 }", "").replace("friction = 0.3", "friction = 0.0"));
    assert_eq!(e.key.as_deref(), Some("load.friction"), "{e}");
    let e = refused(
        &wheel("{ longitudinal = 1e-3 }", "")
            .replace("friction = 0.3", "friction = 0.3\ntangential = \"1 kN\""),
    );
    assert_eq!(e.key.as_deref(), Some("load.tangential"), "{e}");
    // Polach has no spin.
    let e = refused(&wheel("{ spin = \"0.1 1/m\" }", "[solver]\nmethod = \"polach\""));
    assert_eq!(e.key.as_deref(), Some("motion.creepage.spin"), "{e}");
}

/// Creepage far beyond saturation: every element slides, |F| = fN, and the run says so.
#[test]
fn full_slip_is_a_result() {
    let scene = Scene::from_toml_str(&wheel("{ longitudinal = 0.5 }", "[solver]\ngrid = 24"), None)
        .unwrap();
    let out = run(&scene, &RunOptions::default()).unwrap();
    assert_eq!(out.zones.grid.unwrap().stick, 0);
    let fx = out.forces.fx.unwrap();
    assert!((fx / (-0.3 * 1e5) - 1.0).abs() < 1e-6, "{fx}");
    assert!(out.notes.iter().any(|n| n.contains("full slip")), "{:?}", out.notes);
    assert!(out.audit.passed);
}

/// solver.tolerance chooses the theory under "auto": the exact one by default, FASTSIM from
/// its measured error (0.1 fN), Polach from 0.15 fN without spin.
#[test]
fn the_tolerance_is_the_accuracy_knob() {
    let technique = |creepage: &str, tol: &str| {
        let s =
            Scene::from_toml_str(&wheel(creepage, &format!("[solver]\ntolerance = {tol}")), None)
                .unwrap();
        let plan = Plan::new(&s).unwrap();
        plan.effects.iter().find(|e| e.effect.name() == "rolling").unwrap().technique.unwrap()
    };
    assert_eq!(technique("{ longitudinal = 1e-3 }", "1e-10"), Technique::SteadyRolling);
    assert_eq!(technique("{ longitudinal = 1e-3 }", "0.12"), Technique::Fastsim);
    assert_eq!(technique("{ longitudinal = 1e-3 }", "0.2"), Technique::Polach);
    assert_eq!(technique("{ longitudinal = 1e-3, spin = \"0.1 1/m\" }", "0.2"), Technique::Fastsim);
}

/// The written arrays: the lattice traction (on the substrate) sums to minus the creep force
/// on the indenter; the micro-slip of the indenter is zero where the surface sticks (to the
/// residual) and, where it slips, along the substrate's traction (friction drags the
/// substrate the way the indenter slides), whose magnitude is f p.
#[test]
fn outputs_are_consistent() {
    let scene = Scene::from_toml_str(
        &wheel(
            "{ longitudinal = 1e-3, lateral = 5e-4, spin = \"0.3 1/m\" }",
            "[solver]\ngrid = 40",
        ),
        None,
    )
    .unwrap();
    let out = run(&scene, &RunOptions::default()).unwrap();
    let SurfaceOut::Grid { x, y, p, qx, qy, stick, slip_x: Some(sx), slip_y: Some(sy), .. } =
        &out.surface
    else {
        panic!("3D rolling writes its micro-slip maps")
    };
    let area = (x[1] - x[0]) * (y[1] - y[0]);
    let (mut fx, mut fy) = (0.0, 0.0);
    let (mut stick_n, mut slip_n) = (0, 0);
    for i in 0..x.len() {
        for j in 0..y.len() {
            fx += qx[i][j] * area;
            fy += qy[i][j] * area;
            let s = sx[i][j].hypot(sy[i][j]);
            match stick[i][j] {
                1 => {
                    stick_n += 1;
                    // Zero to the solver's residual: V times 1e-9 of the creepage.
                    assert!(s <= 20.0 * 1e-3 * 1e-9, "stick cell ({i}, {j}) slips {s} m/s");
                }
                0 => {
                    slip_n += 1;
                    let q = qx[i][j].hypot(qy[i][j]);
                    if s > 0.0 && q > 0.0 {
                        let cos = (qx[i][j] * sx[i][j] + qy[i][j] * sy[i][j]) / (q * s);
                        assert!(cos > 1.0 - 1e-6, "cell ({i}, {j}): {cos}");
                        assert!((q - 0.3 * p[i][j]).abs() <= 1e-8 * 0.3 * out.contact.p0);
                    }
                }
                _ => assert_eq!((qx[i][j], qy[i][j], s), (0.0, 0.0, 0.0)),
            }
        }
    }
    assert!(stick_n > 0 && slip_n > 0);
    let (rfx, rfy) = (out.forces.fx.unwrap(), out.forces.fy.unwrap());
    assert!((fx + rfx).abs() < 1e-9 * rfx.abs() && (fy + rfy).abs() < 1e-9 * rfy.abs().max(1.0));
    assert!(out.forces.mz.unwrap().is_finite());
}

/// Any surface rolls by the exact theory on the contact the normal solver found: a sphere
/// given as a surface profile (128 x 128 lattice over 0.8 mm, about 28 cells across the
/// contact) against the same sphere as a Hertz contact (the sphere's grid of 28 cells across):
/// the creep forces agree within 3 % of fN (both grids resolve the contact to a few per cent;
/// their element sizes differ by a quarter), and the audit passes on both.
#[test]
fn a_surface_rolls_like_its_hertz_contact() {
    let common = r#"[substrate]
model = "homogeneous"
e = "210 GPa"
nu = 0.3
[indenter]
model = "same"
[load]
normal = "10 N"
friction = 0.2
[motion]
kind = "rolling"
speed = "1 m/s"
creepage = { longitudinal = 5e-4, spin = "1 1/m" }
"#;
    let surface = format!(
        "[geometry]\nkind = \"surface\"\nboundary = \"free\"\nsize = [\"0.8 mm\", \"0.8 mm\"]\ncells = [128, 128]\n[geometry.profile]\nshape = \"sphere\"\nradius = \"10 mm\"\n{common}"
    );
    let sphere =
        format!("[geometry]\nkind = \"sphere\"\nradius = \"10 mm\"\n{common}[solver]\ngrid = 28\n");
    let a = run(&Scene::from_toml_str(&surface, None).unwrap(), &RunOptions::default()).unwrap();
    let b = run(&Scene::from_toml_str(&sphere, None).unwrap(), &RunOptions::default()).unwrap();
    let fnorm = 0.2 * 10.0;
    let d = (a.forces.fx.unwrap() - b.forces.fx.unwrap())
        .hypot(a.forces.fy.unwrap() - b.forces.fy.unwrap())
        / fnorm;
    println!(
        "surface F = ({:.5}, {:.5}) N, Hertz F = ({:.5}, {:.5}) N: {d:.4} fN",
        a.forces.fx.unwrap(),
        a.forces.fy.unwrap(),
        b.forces.fx.unwrap(),
        b.forces.fy.unwrap()
    );
    assert!(d < 0.03, "{d}");
    assert!(a.audit.passed && b.audit.passed);
}

/// A load sweep on a surface: the sphere given as a profile, 8 forces from 1 N to 20 N. At
/// every step the area and the approach follow Hertz (a^3 = 3PR/(4E*), approach a^2/R:
/// an independent closed form) to the lattice's resolution (a within one cell, approach
/// 2 %), and the last step is the scene's result.
#[test]
fn a_surface_load_sweep_follows_hertz() {
    let scene = r#"[geometry]
kind = "surface"
boundary = "free"
size = ["0.8 mm", "0.8 mm"]
cells = [128, 128]
[geometry.profile]
shape = "sphere"
radius = "10 mm"
[substrate]
model = "homogeneous"
e = "210 GPa"
nu = 0.3
[indenter]
model = "same"
[load]
normal = ["1 N", "20 N", 8]
"#;
    let out = run(&Scene::from_toml_str(scene, None).unwrap(), &RunOptions::default()).unwrap();
    let c = out.load_curve.as_ref().expect("load_curve");
    assert_eq!(c.normal.len(), 8);
    let (r, e_star) = (0.01, 210e9 / (2.0 * (1.0 - 0.09)));
    let h = 0.8e-3 / 128.0;
    for i in 0..8 {
        let want_p = 20f64.powf(i as f64 / 7.0);
        assert!((c.normal[i] / want_p - 1.0).abs() < 1e-6, "step {i}: {}", c.normal[i]);
        let a = (3.0 * c.normal[i] * r / (4.0 * e_star)).cbrt();
        let a_lattice = (c.area[i] / std::f64::consts::PI).sqrt();
        assert!((a_lattice - a).abs() < h, "step {i}: a {a_lattice} vs Hertz {a}");
        assert!(
            (c.approach[i] / (a * a / r) - 1.0).abs() < 0.02,
            "step {i}: approach {}",
            c.approach[i]
        );
        if i > 0 {
            assert!(c.area[i] > c.area[i - 1]);
        }
    }
    assert!((out.contact.normal_load - 20.0).abs() < 1e-9 * 20.0);
    assert!(out.audit.passed);
    println!("iterations per step: {:?}", c.iterations);
}
