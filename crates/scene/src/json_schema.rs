//! The JSON Schema of the scene format, for editors.
//!
//! TOML language servers (Taplo, and the editor extensions built on it) read a
//! `#:schema PATH` comment at the top of a TOML file and then complete keys and enum values,
//! show each key's description and mark what does not fit while typing. The schema is
//! derived from the structs that deserialise the file (`crate::raw`, the format itself, with
//! their doc comments as descriptions); the allowed values of string keys come from the
//! reader's own description of the format (`scene/read/schema.rs`) and the material names
//! from [`crate::materials`]. The repository keeps it at `docs/scene.schema.json` (a test
//! regenerates it and compares).
//!
//! The schema checks the shape of a file (keys, types, enum values); units, dimensions,
//! ranges and combinations are the reader's and the planner's.

use serde_json::{Map, Value};

use crate::raw::RawScene;

/// Where the repository keeps the schema, relative to its root.
pub const SCHEMA_PATH: &str = "docs/scene.schema.json";

/// The schema as a JSON value (draft 7, which the TOML language servers read).
pub fn scene_schema() -> Value {
    let generator = schemars::generate::SchemaSettings::draft07().into_generator();
    let mut v = generator.into_root_schema_for::<RawScene>().to_value();
    no_null(&mut v);
    if let Some(o) = v.as_object_mut() {
        o.insert("title".into(), "stickslip scene".into());
        o.insert(
            "description".into(),
            "A contact problem for stickslip (docs/SCENES.md): geometry, substrate, indenter, \
             load, motion, outputs, solver."
                .into(),
        );
    }
    for (key, choices) in crate::scene::read::schema::keys() {
        let allowed: Vec<Value> = match (key.as_str(), choices) {
            ("substrate.material" | "indenter.material", _) => crate::materials::MATERIALS
                .iter()
                .flat_map(|m| std::iter::once(&m.name).chain(m.aliases))
                .map(|n| Value::from(*n))
                .collect(),
            (_, Some(c)) if !c.is_empty() => c.iter().map(|s| Value::from(*s)).collect(),
            _ => continue,
        };
        if let Some(leaf) = property(&mut v, &key) {
            leaf.insert("enum".into(), Value::Array(allowed));
        }
    }
    v
}

/// The schema as the text of `docs/scene.schema.json` (pretty, with a final newline).
pub fn scene_schema_text() -> String {
    // Serialising a Value cannot fail.
    serde_json::to_string_pretty(&scene_schema()).unwrap_or_default() + "\n"
}

/// TOML has no null: an optional key is absent, never null, so the `null` schemars adds to
/// every `Option` is taken out again; so is the `format` of numbers (`double`, `int64`),
/// which says how Rust stores them and nothing about the file.
fn no_null(v: &mut Value) {
    match v {
        Value::Object(o) => {
            if o.get("format").is_some_and(|f| f == "double" || f == "int64") {
                o.remove("format");
            }
            if let Some(Value::Array(types)) = o.get_mut("type") {
                types.retain(|t| t != "null");
                if types.len() == 1 {
                    let t = types.remove(0);
                    o.insert("type".into(), t);
                }
            }
            if let Some(Value::Array(any)) = o.get_mut("anyOf") {
                any.retain(|s| s.get("type").is_none_or(|t| t != "null"));
                if any.len() == 1 {
                    let only = any.remove(0);
                    o.remove("anyOf");
                    if let Value::Object(inner) = only {
                        for (k, x) in inner {
                            o.entry(k).or_insert(x);
                        }
                    }
                }
            }
            o.values_mut().for_each(no_null);
        }
        Value::Array(a) => a.iter_mut().for_each(no_null),
        _ => {}
    }
}

/// The schema object of a dotted key, following `$ref`s and array items.
fn property<'v>(root: &'v mut Value, key: &str) -> Option<&'v mut Map<String, Value>> {
    let defs = root.get("definitions").cloned().unwrap_or(Value::Null);
    let mut path: Vec<String> = Vec::new();
    let mut cur: &Value = root;
    for seg in key.split('.') {
        let table = resolve(cur, &defs, &mut path)?;
        cur = table.get("properties")?.get(seg)?;
        path.push("properties".into());
        path.push(seg.into());
    }
    // The leaf itself stays where it is (a string key is inline); walk the path mutably.
    let mut m = root;
    for p in &path {
        m = m.get_mut(p)?;
    }
    m.as_object_mut()
}

/// The table schema `v` stands for: itself, its `$ref`, or its array's items; the path
/// followed is appended to `path` (from the root).
fn resolve<'v>(v: &'v Value, defs: &'v Value, path: &mut Vec<String>) -> Option<&'v Value> {
    let v = match (v.get("items"), v.get("allOf").and_then(Value::as_array)) {
        (Some(items), _) => {
            path.push("items".into());
            items
        }
        // A required table: `allOf: [{$ref}]` beside its description.
        (None, Some(all)) if all.len() == 1 => &all[0],
        _ => v,
    };
    match v.get("$ref").and_then(Value::as_str) {
        Some(r) => {
            let name = r.strip_prefix("#/definitions/")?;
            path.clear();
            path.push("definitions".into());
            path.push(name.into());
            defs.get(name)
        }
        None => Some(v),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;

    /// Every key the reader's description knows is in the schema, and no other.
    #[test]
    fn the_schema_has_the_keys_of_the_format() {
        let mut v = scene_schema();
        let ours: BTreeSet<String> =
            crate::scene::read::schema::keys().into_iter().map(|(k, _)| k).collect();
        for k in &ours {
            assert!(property(&mut v, k).is_some(), "{k} is not in the schema");
        }
        // And the other way: walk the schema's properties.
        fn walk(v: &Value, defs: &Value, prefix: &str, out: &mut BTreeSet<String>) {
            let mut path = Vec::new();
            let Some(t) = resolve(v, defs, &mut path) else { return };
            if let Some(props) = t.get("properties").and_then(Value::as_object) {
                for (k, p) in props {
                    let key = if prefix.is_empty() { k.clone() } else { format!("{prefix}.{k}") };
                    out.insert(key.clone());
                    walk(p, defs, &key, out);
                }
            }
        }
        let defs = v.get("definitions").cloned().unwrap_or(Value::Null);
        let mut theirs = BTreeSet::new();
        walk(&v, &defs, "", &mut theirs);
        assert_eq!(ours, theirs);
    }

    #[test]
    fn string_keys_carry_their_values() {
        let mut v = scene_schema();
        let kind = property(&mut v, "geometry.kind").unwrap();
        assert_eq!(
            kind.get("enum").unwrap(),
            &serde_json::json!([
                "cylinder",
                "sphere",
                "ellipsoid",
                "punch",
                "patches",
                "surface",
                "wheel-rail"
            ])
        );
        let shape = property(&mut v, "geometry.patches.shape").unwrap().clone();
        assert_eq!(
            shape.get("enum").unwrap(),
            &serde_json::json!(["square", "rectangle", "circle"])
        );
        let m = property(&mut v, "substrate.material").unwrap().clone();
        assert!(m.get("enum").unwrap().as_array().unwrap().contains(&"steel".into()));
        let fields = v.get("definitions").unwrap().get("RawSubstrate").unwrap();
        assert_eq!(fields.get("additionalProperties"), Some(&Value::Bool(false)));
    }
}
