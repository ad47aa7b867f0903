//! `[interface]` (issue 32): a hardness cap on a surface scene, its outputs (the plastic
//! share, mask and displacement, the audit of the cap), the friction stage on the capped
//! pressure, and the refusals with file:line:column and the key.

use std::f64::consts::PI;

use stickslip_run::{run, RunOptions, SurfaceOut};
use stickslip_scene::{ErrorKind, Scene};

const SCENE: &str = "[geometry]
kind = \"surface\"
size = [\"2 mm\", \"2 mm\"]
cells = [128, 128]
[geometry.profile]
shape = \"sphere\"
radius = \"10 mm\"
[substrate]
model = \"homogeneous\"
e = \"210 GPa\"
nu = 0.3
[indenter]
model = \"same\"
[load]
normal = \"LOAD\"
tangential = \"TANGENTIAL\"
friction = 0.3
[interface]
hardness = \"HARDNESS\"
";

fn scene(load: &str, tangential: &str, hardness: &str) -> String {
    SCENE.replace("LOAD", load).replace("TANGENTIAL", tangential).replace("HARDNESS", hardness)
}

#[allow(clippy::result_large_err)]
fn go(src: &str) -> Result<stickslip_run::Outcome, stickslip_scene::SceneError> {
    let file = std::env::temp_dir().join("interface.toml");
    run(&Scene::from_toml_str(src, Some(file))?, &RunOptions::default())
}

/// A steel sphere on steel (R = 10 mm, H = 2 GPa): the Hertz onset of plasticity is at
/// F_Y = pi^3 R^2 H^3 / (6 E*^2) = 310 N. At 3 F_Y the pressure is capped, the plastic share
/// and maps are given and agree with each other, the audit holds the cap, and the partial
/// slip stage runs on the capped pressure (Coulomb audit passed, |q| <= f H).
#[test]
fn capped_sphere_scene() {
    let es = 210e9 / (2.0 * (1.0 - 0.3 * 0.3));
    let (r, h) = (0.01, 2e9f64);
    let f_y = PI.powi(3) * r * r * h.powi(3) / (6.0 * es * es);
    let f = 3.0 * f_y;
    let out = go(&scene(&format!("{f} N"), &format!("{} N", 0.15 * f), "2 GPa")).unwrap();
    let c = &out.contact;
    println!(
        "3 F_Y = {f:.2} N: p0 {:.4e}, plastic fraction {:?}, area {:?}",
        c.p0, c.plastic_fraction, c.area
    );
    assert!(c.p0 <= h);
    assert!((c.p0 - h).abs() <= 1e-12 * h, "the peak is at the cap");
    let share = c.plastic_fraction.unwrap();
    assert!(share > 0.2 && share < 0.8, "{share}");
    assert!((out.forces.normal - f).abs() <= 1e-8 * f);
    assert!(out.audit.passed);
    assert!(out.audit.checks.iter().any(|k| k.name == "hardness" && k.pass));
    let SurfaceOut::Grid { p, qx, qy, plastic: Some(m), plastic_displacement: Some(w), .. } =
        &out.surface
    else {
        panic!("no plastic maps")
    };
    let (mut cells, mut plastic, mut qmax) = (0usize, 0usize, 0.0f64);
    for i in 0..p.len() {
        for j in 0..p[i].len() {
            cells += usize::from(p[i][j] > 0.0);
            let pl = m[i][j] == 1.0;
            plastic += usize::from(pl);
            assert_eq!(pl, p[i][j] >= h, "mask against the pressure");
            assert!(w[i][j] >= 0.0 && (pl || w[i][j] == 0.0));
            qmax = qmax.max(qx[i][j].hypot(qy[i][j]));
        }
    }
    assert!((share - plastic as f64 / cells as f64).abs() < 1e-15);
    assert!(qmax <= 0.3 * h * (1.0 + 1e-9), "a cell at the hardness slips under f H at most");
    assert!(out.notes.iter().any(|n| n.contains("hardness cap")), "{:?}", out.notes);
}

/// Below the onset (0.9 F_Y, p0 = 0.965 H) the cap changes nothing: the elastic result.
#[test]
fn a_cap_above_the_peak_is_elastic() {
    let es = 210e9 / (2.0 * (1.0 - 0.3 * 0.3));
    let (r, h) = (0.01, 2e9f64);
    let f = 0.9 * PI.powi(3) * r * r * h.powi(3) / (6.0 * es * es);
    let capped = go(&scene(&format!("{f} N"), "0 N", "2 GPa")).unwrap();
    let elastic = go(&scene(&format!("{f} N"), "0 N", "2 GPa")
        .replace("[interface]\nhardness = \"2 GPa\"\n", ""))
    .unwrap();
    assert_eq!(capped.contact.plastic_fraction, Some(0.0));
    assert_eq!(elastic.contact.plastic_fraction, None);
    let e = (capped.contact.p0 - elastic.contact.p0).abs() / elastic.contact.p0;
    println!("0.9 F_Y: capped p0 against elastic {e:.1e}");
    assert!(e < 1e-8);
}

/// Refusals: the file, line and column, the key, the kind.
#[test]
fn refusals_name_the_key_and_place() {
    let cases: Vec<(String, &str, ErrorKind, usize)> = vec![
        (scene("10 N", "0 N", "-2 GPa"), "interface.hardness", ErrorKind::OutOfRange, 19),
        (scene("10 N", "0 N", "0 Pa"), "interface.hardness", ErrorKind::OutOfRange, 19),
        (scene("10 N", "0 N", "2 GN"), "interface.hardness", ErrorKind::Unit, 19),
        (
            "[geometry]\nkind = \"sphere\"\nradius = \"10 mm\"\n[substrate]\nmodel = \"homogeneous\"\ne = \"210 GPa\"\nnu = 0.3\n[load]\nnormal = \"10 N\"\n[interface]\nhardness = \"2 GPa\"\n".to_string(),
            "interface.hardness",
            ErrorKind::Unsupported,
            11,
        ),
        (
            scene("10 N", "1 N", "2 GPa").replace("[indenter]\nmodel = \"same\"\n", ""),
            "interface.hardness",
            ErrorKind::Unsupported,
            17,
        ),
        (
            scene("10 N", "0 N", "2 GPa").replace("hardness", "hardnes"),
            "interface",
            ErrorKind::Schema,
            0,
        ),
    ];
    for (src, key, kind, line) in cases {
        let e = match go(&src) {
            Err(e) => e,
            Ok(_) => panic!("{key}: accepted"),
        };
        println!("{e}");
        assert_eq!(e.kind, kind, "{e}");
        assert!(e.to_string().contains("interface.toml:"), "{e}");
        if line > 0 {
            assert_eq!(e.key.as_deref(), Some(key), "{e}");
            assert_eq!(e.position.map(|p| p.0), Some(line), "{e}");
        }
        assert!(e.hint.is_some() || kind == ErrorKind::Schema, "{e}");
    }
    // The force beyond what the lattice carries fully plastic.
    let e = go(&scene("10000 N", "0 N", "2 GPa")).unwrap_err();
    println!("{e}");
    assert!(e.to_string().contains("hardness"), "{e}");
}
