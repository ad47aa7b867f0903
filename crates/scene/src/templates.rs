//! Commented starting scenes, one per kind of problem the program solves: the text
//! `stickslip new KIND` writes. Each runs as written (a test plans and executes every one)
//! and starts with a `#:schema` line for editors (see [`crate::json_schema`]).
//!
//! The files are `crates/scene/templates/KIND.toml`; their `#:schema` line points at
//! `docs/scene.schema.json` from there, and [`with_schema`] replaces it by a line that works
//! where the scene is written.

/// One template.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Template {
    /// The name `stickslip new` takes (`sphere`, `viscoelastic-rolling` ...).
    pub kind: &'static str,
    /// One line on what it solves.
    pub about: &'static str,
    /// The scene.
    pub text: &'static str,
}

/// Every template, in the order `stickslip new --list` shows them.
pub const TEMPLATES: [Template; 10] = [
    Template {
        kind: "sphere",
        about: "ball on a flat: Hertz contact, Mindlin partial slip (3D)",
        text: include_str!("../templates/sphere.toml"),
    },
    Template {
        kind: "cylinder",
        about: "roller on a flat: line contact, Cattaneo partial slip, stresses below (2D)",
        text: include_str!("../templates/cylinder.toml"),
    },
    Template {
        kind: "ellipsoid",
        about: "elliptical Hertz contact with partial slip (3D)",
        text: include_str!("../templates/ellipsoid.toml"),
    },
    Template {
        kind: "patches",
        about: "flat patches with given pressures (a joint) under a tangential load (3D)",
        text: include_str!("../templates/patches.toml"),
    },
    Template {
        kind: "rolling",
        about: "elastic wheel rolling with creep: Carter (2D)",
        text: include_str!("../templates/rolling.toml"),
    },
    Template {
        kind: "rolling-3d",
        about: "wheel on rail in 3D: creepage and spin, creep forces, stick and slip areas",
        text: include_str!("../templates/rolling-3d.toml"),
    },
    Template {
        kind: "graded",
        about: "rigid roller on a substrate graded with depth, E = e0 y^k (2D)",
        text: include_str!("../templates/graded.toml"),
    },
    Template {
        kind: "viscoelastic-rolling",
        about: "viscoelastic cylinder rolling: rolling resistance (2D)",
        text: include_str!("../templates/viscoelastic-rolling.toml"),
    },
    Template {
        kind: "surface",
        about: "any surface on a lattice: profile plus roughness, then partial slip (3D)",
        text: include_str!("../templates/surface.toml"),
    },
    Template {
        kind: "subsurface",
        about: "stresses below a ball contact under a tangential load (3D field)",
        text: include_str!("../templates/subsurface.toml"),
    },
];

/// The template of `kind`.
pub fn find(kind: &str) -> Option<&'static Template> {
    TEMPLATES.iter().find(|t| t.kind == kind)
}

/// The kinds, for messages.
pub fn kinds() -> String {
    TEMPLATES.iter().map(|t| t.kind).collect::<Vec<_>>().join(", ")
}

/// `text` with its first line, the `#:schema` directive, pointing at `schema` (a path
/// relative to where the scene is written, or absolute).
pub fn with_schema(text: &str, schema: &str) -> String {
    let rest = match text.split_once('\n') {
        Some((first, rest)) if first.starts_with("#:schema") => rest,
        _ => text,
    };
    format!("#:schema {schema}\n{rest}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_template_points_at_the_schema_from_its_directory() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("templates");
        for t in TEMPLATES {
            let first = t.text.lines().next().unwrap();
            let target = first.strip_prefix("#:schema ").unwrap();
            assert!(dir.join(target).is_file(), "{}: {first}", t.kind);
            assert_eq!(find(t.kind), Some(&t));
            let moved = with_schema(t.text, "./scene.schema.json");
            assert!(moved.starts_with("#:schema ./scene.schema.json\n# "), "{}", t.kind);
            assert_eq!(moved.lines().count(), t.text.lines().count());
        }
        let n = std::fs::read_dir(&dir).unwrap().count();
        assert_eq!(n, TEMPLATES.len(), "a file in templates/ is not listed");
    }
}
