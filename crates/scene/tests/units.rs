//! Units in scenes as a newcomer writes them: the micro-contact units (mN, uN, µN, nN, nm)
//! read, and a unit in the wrong letter case is refused at its key and position with the
//! intended unit as the hint.

// SceneError carries file, position, key and hint; tests return it as is.
#![allow(clippy::result_large_err)]

use stickslip_scene::{ErrorKind, Geometry, NormalLoad, Scene};

fn ball(radius: &str, normal: &str) -> String {
    format!(
        "[geometry]\nkind = \"sphere\"\nradius = \"{radius}\"\n[substrate]\nmodel = \"homogeneous\"\nmaterial = \"silicon\"\n[indenter]\nmodel = \"homogeneous\"\nmaterial = \"diamond\"\n[load]\nnormal = \"{normal}\"\n"
    )
}

#[test]
fn micro_contact_units_read() {
    let cases: [(&str, &str, f64, f64); 5] = [
        ("0.5 mm", "1 mN", 0.5e-3, 1e-3),
        ("20 um", "50 uN", 20e-6, 50e-6),
        ("20 µm", "50 µN", 20e-6, 50e-6),
        ("200 nm", "300 nN", 200e-9, 300e-9),
        ("2e4 nm", "5e-2 mN", 20e-6, 50e-6),
    ];
    for (r, p, rv, pv) in cases {
        let s = Scene::from_toml_str(&ball(r, p), None).unwrap_or_else(|e| panic!("{r} {p}: {e}"));
        let Geometry::Sphere { radius } = s.geometry else { panic!() };
        assert!((radius / rv - 1.0).abs() < 1e-15, "{r}: {radius}");
        let NormalLoad::Force(f) = s.load.normal else { panic!() };
        assert!((f / pv - 1.0).abs() < 1e-15, "{p}: {f}");
    }
}

#[test]
fn a_wrong_case_names_the_intended_unit() {
    let cases: [(String, &str, &str); 3] = [
        (ball("0.5 mm", "1 Mn"), "load.normal", "did you mean 'mN' or 'MN'?"),
        (ball("0.5 MM", "1 mN"), "geometry.radius", "did you mean 'mm' or 'Mm'?"),
        (ball("0.5 mm", "1 KN"), "load.normal", "did you mean 'kN'?"),
    ];
    for (src, key, hint) in cases {
        let e = Scene::from_toml_str(&src, Some("u.toml".into())).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Unit, "{e}");
        assert_eq!(e.key.as_deref(), Some(key), "{e}");
        assert_eq!(e.hint.as_deref(), Some(hint), "{e}");
        let line = if key == "load.normal" { 11 } else { 3 };
        assert_eq!(e.position, Some((line, 10)), "{e}");
        assert!(e.to_string().starts_with(&format!("u.toml:{line}:10: `{key}`")), "{e}");
    }
}
