//! The key parameters of a scene in a plot's subtitle (radius, load, friction, ...).

use stickslip_run::plan::recipe::{ContactNormal, LineFriction, LineNormal, Recipe, RollingModel};
use stickslip_run::{Outcome, Plan};

use crate::report::eng;

/// The scene's key parameters for a plot's subtitle: radius, load, friction, tangential
/// load and moment where the scene has them.
pub(crate) fn key_parameters(plan: Option<&Plan>, out: &Outcome) -> String {
    let mut parts = Vec::new();
    let two_d = matches!(plan.map(|p| &p.recipe), Some(Recipe::Line(_) | Recipe::Rolling(_)));
    let (force, moment) = if two_d { ("N/m", "N m/m") } else { ("N", "N m") };
    let mut friction = None;
    match plan.map(|p| &p.recipe) {
        Some(Recipe::Line(r)) => {
            if let LineNormal::Hertz { radius, .. } | LineNormal::Graded { radius, .. } = r.normal {
                parts.push(format!("R = {}", eng(radius, "m")));
            }
            friction = r.friction.map(|f| match f {
                LineFriction::Sliding { friction }
                | LineFriction::Cattaneo { friction, .. }
                | LineFriction::GradedPartialSlip { friction, .. } => friction,
            });
        }
        Some(Recipe::Rolling(r)) => {
            if let RollingModel::Carter(cp) = r.model {
                parts.push(format!("R = {}", eng(cp.radius(), "m")));
                friction = Some(cp.friction());
            }
        }
        Some(Recipe::Contact(r)) => {
            match r.normal {
                ContactNormal::Sphere { radius, .. } => {
                    parts.push(format!("R = {}", eng(radius, "m")));
                }
                ContactNormal::Ellipse { rx, ry, .. } => {
                    parts.push(format!("Rx = {}, Ry = {}", eng(rx, "m"), eng(ry, "m")));
                }
                ContactNormal::EllipseGiven { a, b, .. } => {
                    parts.push(format!("a = {}, b = {}", eng(a, "m"), eng(b, "m")));
                }
                ContactNormal::Surface { ref surface, adhesion, hardness, .. } => {
                    if let stickslip_scene::Profile::Sphere { radius } = surface.profile {
                        parts.push(format!("R = {}", eng(radius, "m")));
                    }
                    if let Some(a) = adhesion {
                        parts.push(format!(
                            "w = {}, h0 = {}",
                            eng(a.work, "J/m^2"),
                            eng(a.range, "m")
                        ));
                    }
                    if let Some(h) = hardness {
                        parts.push(format!("H = {}", eng(h, "Pa")));
                    }
                }
                _ => {}
            }
            friction = (r.friction > 0.0).then_some(r.friction);
        }
        _ => {}
    }
    parts.push(format!("P = {}", eng(out.contact.normal_load, force)));
    if let Some(f) = friction {
        parts.push(format!("f = {f}"));
    }
    let fo = &out.forces;
    if fo.tangential != 0.0 {
        parts.push(format!("Q = {}", eng(fo.tangential, force)));
    }
    if fo.moment != 0.0 {
        parts.push(format!("M = {}", eng(fo.moment, moment)));
    }
    parts.join(", ")
}
