//! `docs/scene.schema.json` is the JSON Schema of the scene format generated from the reader's
//! types (`stickslip_scene::json_schema`) and must be current: this test regenerates it and
//! compares (`STICKSLIP_UPDATE_DOCS=1` writes it instead). Every scene in `scenes/` and
//! every template of `stickslip new` is valid against it and starts with the `#:schema`
//! directive editors read.

mod common;
use common::scenes_dir;
use std::path::PathBuf;
use stickslip_scene::json_schema::{scene_schema, scene_schema_text, SCHEMA_PATH};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

#[test]
fn docs_scene_schema_json_is_current() {
    let text = scene_schema_text();
    assert_eq!(text, scene_schema_text(), "the schema is not deterministic");
    let path = root().join(SCHEMA_PATH);
    if std::env::var("STICKSLIP_UPDATE_DOCS").is_ok_and(|v| v == "1") {
        std::fs::write(&path, &text).unwrap();
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == text,
        "{SCHEMA_PATH} is not current: run STICKSLIP_UPDATE_DOCS=1 cargo test --release -p stickslip-scene --test schema"
    );
}

/// The scene as the JSON the schema describes (TOML tables as objects).
fn as_json(text: &str) -> serde_json::Value {
    let v: toml::Value = toml::from_str(text).unwrap();
    serde_json::to_value(v).unwrap()
}

#[test]
fn every_scene_and_template_fits_the_schema_and_names_it() {
    let schema = scene_schema();
    let validator = jsonschema::draft7::new(&schema).unwrap();
    let mut files: Vec<(String, String)> = Vec::new();
    for e in std::fs::read_dir(scenes_dir()).unwrap().filter_map(Result::ok) {
        let p = e.path();
        if p.extension().is_some_and(|x| x == "toml") {
            let text = std::fs::read_to_string(&p).unwrap();
            let first = text.lines().next().unwrap_or("");
            assert_eq!(first, "#:schema ../docs/scene.schema.json", "{}", p.display());
            files.push((p.display().to_string(), text));
        }
    }
    assert!(files.len() >= 20, "{} scenes", files.len());
    for t in stickslip_scene::templates::TEMPLATES {
        files.push((format!("template {}", t.kind), t.text.to_string()));
    }
    for (name, text) in &files {
        let errors: Vec<String> = validator
            .iter_errors(&as_json(text))
            .map(|e| format!("{e} at {}", e.instance_path()))
            .collect();
        assert!(errors.is_empty(), "{name}: {errors:?}");
    }
}

/// What the schema refuses, an editor marks while typing: a misspelt key, a value outside
/// a list, a string where a number goes, a quantity that is not one.
#[test]
fn the_schema_refuses_what_the_reader_refuses() {
    let schema = scene_schema();
    let validator = jsonschema::draft7::new(&schema).unwrap();
    let good = stickslip_scene::templates::find("sphere").unwrap().text;
    assert!(validator.is_valid(&as_json(good)));
    for (from, to) in [
        ("friction = 0.3", "frictoin = 0.3"),
        ("kind = \"sphere\"", "kind = \"sphear\""),
        ("friction = 0.3", "friction = \"0.3 N\""),
        ("normal = \"50 N\"", "normal = \"fifty N\""),
        ("material = \"steel\"", "material = \"unobtainium\""),
        ("[load]", "[lode]"),
    ] {
        assert!(good.contains(from), "{from}");
        let bad = good.replacen(from, to, 1);
        assert!(!validator.is_valid(&as_json(&bad)), "{to} passes the schema");
        assert!(
            stickslip_scene::Scene::from_toml_str(&bad, None).is_err(),
            "{to} passes the reader"
        );
    }
}
