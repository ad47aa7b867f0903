//! The scenes overview page (`docs/scenes.md`): for every scene of a directory, the effects
//! on and off and the technique the planner chose for each, as `stickslip explain` prints
//! them, computed by the planner alone (nothing is run).

use std::fmt::Write as _;
use std::path::Path;

use crate::{Effect, Plan, Technique};
use stickslip_scene::{ErrorKind, Scene, SceneError};

/// The Markdown page for the `*.toml` scenes of `dir`, sorted by file name. `link_prefix` is
/// the path from the page to `dir` (e.g. `../scenes`). The output depends only on the
/// scene files (no times, no absolute paths).
///
/// # Errors
/// A [`SceneError`] if the directory cannot be read or a scene is refused.
#[allow(clippy::result_large_err)]
pub fn scenes_page(dir: &Path, link_prefix: &str) -> Result<String, SceneError> {
    let io = |e: std::io::Error| {
        SceneError::new(ErrorKind::Io, format!("cannot read {}: {e}", dir.display()))
    };
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .map_err(io)?
        .filter_map(Result::ok)
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".toml"))
        .collect();
    names.sort();
    let mut rows = Vec::new();
    for name in &names {
        let text = std::fs::read_to_string(dir.join(name)).map_err(io)?;
        // The scene's own path, so that files it names (roughness, a load path) resolve.
        let scene = Scene::from_toml_str(&text, Some(dir.join(name)))?;
        let plan = Plan::new(&scene)?;
        rows.push((name.clone(), scene, plan));
    }

    let mut s = String::new();
    let w = &mut s;
    // Writing to a String cannot fail.
    let _ = writeln!(w, "# Scenes and their plans\n");
    let _ = writeln!(
        w,
        "Generated from `scenes/*.toml` by the effect planner of `stickslip-run` (what \
         `stickslip explain SCENE` prints, nothing is computed); do not edit. Regenerate with\n\n\
         ```sh\nSTICKSLIP_UPDATE_DOCS=1 cargo test --release -p stickslip-run --test scenes_page\n```\n\n\
         A test checks that this page is current.\n"
    );
    let _ = writeln!(w, "## Effects and the technique chosen for each\n");
    let _ = writeln!(
        w,
        "Each cell is the technique that computes the effect (see the legend below), or `off`. \
         Closed forms are in plain text, numerical methods in *italics*.\n"
    );
    let mut head = "| scene |".to_string();
    let mut rule = "|---|".to_string();
    for e in Effect::ALL {
        let _ = write!(head, " {} |", e.name());
        rule.push_str("---|");
    }
    head.push_str(" 3D lattice elements (estimate) |");
    rule.push_str("---:|");
    let _ = writeln!(w, "{head}\n{rule}");
    for (name, _, plan) in &rows {
        let stem = name.trim_end_matches(".toml");
        let _ = write!(w, "| [`{stem}`]({link_prefix}/{name}) |");
        for e in Effect::ALL {
            let cell = match plan.technique(e) {
                Some(t) if t.is_closed_form() => format!("{t:?}"),
                Some(t) => format!("*{t:?}*"),
                None => "off".to_string(),
            };
            let _ = write!(w, " {cell} |");
        }
        let el =
            if plan.grid_elements > 0 { format!("{}", plan.grid_elements) } else { "".to_string() };
        let _ = writeln!(w, " {el} |");
    }

    let _ = writeln!(w, "\n## Titles and grid solver choices\n");
    let _ = writeln!(w, "| scene | title | grid solver |\n|---|---|---|");
    for (name, scene, plan) in &rows {
        let stem = name.trim_end_matches(".toml");
        let g = plan.grid_solver.as_deref().unwrap_or("none (closed forms or quadrature)");
        let _ = writeln!(w, "| `{stem}` | {} | {} |", escape(&scene.title), escape(g));
    }

    let _ = writeln!(w, "\n## Why effects are off\n");
    let _ = writeln!(w, "| scene | effects off, with the planner's reason |\n|---|---|");
    for (name, _, plan) in &rows {
        let stem = name.trim_end_matches(".toml");
        let off: Vec<String> = plan
            .effects
            .iter()
            .filter(|e| !e.on)
            .map(|e| format!("**{}**: {}", e.effect.name(), escape(&e.reason)))
            .collect();
        let _ = writeln!(w, "| `{stem}` | {} |", off.join("; "));
    }

    let _ = writeln!(w, "\n## Legend\n");
    let _ = writeln!(w, "| technique | kind | what it is |\n|---|---|---|");
    for t in Technique::ALL {
        let kind = if t.is_closed_form() { "closed form" } else { "numerical" };
        let _ = writeln!(w, "| {t:?} | {kind} | {} |", escape(t.describe()));
    }
    Ok(s)
}

/// Escape the characters that break a Markdown table cell.
fn escape(s: &str) -> String {
    s.replace('|', "\\|").replace('*', "\\*")
}
