//! Named materials in scenes: `material = "steel"` reads as the table's E and nu, a name
//! together with `e` or `nu` is refused at the extra key, and docs/materials.md prints the
//! table of the code. (A run with named materials and `explain`: the run's
//! `tests/materials.rs`.)

// SceneError carries file, position, key and hint; tests return it as is.
#![allow(clippy::result_large_err)]

use std::path::PathBuf;

use stickslip_scene::materials::{lookup, table_markdown};
use stickslip_scene::{Elastic, ErrorKind, Indenter, Scene, SceneError, Substrate};

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

#[test]
fn a_named_material_is_its_e_and_nu() {
    let s = read(BALL).unwrap();
    assert_eq!(s.substrate, Substrate::Homogeneous(Elastic { e: 70e9, nu: 0.22 }));
    assert_eq!(s.indenter, Indenter::Homogeneous(Elastic { e: 310e9, nu: 0.27 }));
    // The same scene with the numbers written out reads the same.
    let written = BALL
        .replace("material = \"glass\"", "e = \"70 GPa\"\nnu = 0.22")
        .replace("material = \"silicon nitride\"", "e = \"310 GPa\"\nnu = 0.27");
    let w = read(&written).unwrap();
    assert_eq!((w.substrate, w.indenter), (s.substrate, s.indenter));
    // Viscoelastic substrates take a name for their long-time E and nu.
    let visco = std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../../scenes/seed001_goryacheva_rubber.toml"),
    )
    .unwrap()
    .replace("e = 5000000.0\nnu = 0.49", "material = \"rubber\"");
    let v = read(&visco).unwrap();
    let Substrate::Viscoelastic { elastic, .. } = v.substrate else { panic!("{v:?}") };
    assert_eq!(elastic, lookup("rubber").unwrap().elastic());
}

#[test]
fn refusals_name_the_key_and_where() {
    let cases: [(&str, String, &str, usize, &str, &str); 6] = [
        (
            "material and e",
            BALL.replace("material = \"glass\"", "material = \"glass\"\ne = \"70 GPa\""),
            "substrate.e",
            8,
            "`e` given together with material = \"glass\"",
            "remove `e` and `nu` to use glass (E = 70 GPa, nu = 0.22)",
        ),
        (
            "material and nu",
            BALL.replace(
                "material = \"silicon nitride\"",
                "nu = 0.3\nmaterial = \"silicon nitride\"",
            ),
            "indenter.nu",
            10,
            "`nu` given together with material",
            "or remove `material`",
        ),
        (
            "unknown material",
            BALL.replace("\"glass\"", "\"unobtainium\""),
            "substrate.material",
            7,
            "unknown material \"unobtainium\"",
            "steel, stainless steel",
        ),
        (
            "graded",
            BALL.replace(
                "model = \"homogeneous\"\nmaterial = \"glass\"",
                "model = \"graded\"\nmaterial = \"glass\"",
            ),
            "substrate.material",
            7,
            "a graded substrate takes e0, k and nu",
            "remove `material`",
        ),
        (
            "rigid indenter",
            BALL.replace(
                "model = \"homogeneous\"\nmaterial = \"silicon nitride\"",
                "model = \"rigid\"\nmaterial = \"steel\"",
            ),
            "indenter.material",
            10,
            "a rigid indenter takes no material",
            "model = \"homogeneous\"",
        ),
        (
            "neither",
            BALL.replace("material = \"glass\"\n", ""),
            "substrate.e",
            5,
            "missing key `substrate.e`",
            "material = \"steel\"",
        ),
    ];
    for (name, src, key, line, msg, hint) in cases {
        let e = read(&src).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Schema, "{name}: {e}");
        assert_eq!(e.key.as_deref(), Some(key), "{name}: {e}");
        assert_eq!(e.position.map(|p| p.0), Some(line), "{name}: {e}");
        assert!(e.message.contains(msg), "{name}: {e}");
        assert!(e.hint.as_deref().unwrap_or("").contains(hint), "{name}: {e}");
        assert_eq!(e.file.as_deref(), Some(std::path::Path::new("m.toml")), "{name}");
    }
}

/// docs/materials.md prints the table of `materials.rs` between its markers.
#[test]
fn docs_materials_md_is_current() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../docs/materials.md");
    let page = std::fs::read_to_string(&path).unwrap();
    let start = "<!-- table: generated from crates/scene/src/materials.rs -->\n";
    let end = "<!-- end of table -->";
    let (head, rest) = page.split_once(start).expect("the start marker");
    let (_, tail) = rest.split_once(end).expect("the end marker");
    let want = format!("{head}{start}{}{end}{tail}", table_markdown());
    if std::env::var("STICKSLIP_UPDATE_DOCS").is_ok_and(|v| v == "1") {
        std::fs::write(&path, &want).unwrap();
        return;
    }
    assert!(
        page == want,
        "docs/materials.md is not current: run STICKSLIP_UPDATE_DOCS=1 cargo test --release -p stickslip-scene --test materials"
    );
}

#[test]
fn a_material_that_is_not_a_string_is_refused_in_plain_words() {
    let e = read(&BALL.replace("material = \"glass\"", "material = 7")).unwrap_err();
    assert_eq!(e.key.as_deref(), Some("substrate.material"), "{e}");
    assert!(e.message.contains("expected a string, found the number 7"), "{e}");
    assert!(e.hint.as_deref().unwrap_or("").contains("material = \"steel\""), "{e}");
}
