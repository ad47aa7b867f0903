//! `[interface]` and the approach path: what the scene alone decides (the resolution of an
//! adhesive range by the lattice needs the gap and is the planner's).

use super::{at_most, positive, within};
use crate::error::{ErrorKind, Issue};
use crate::scene::ranges;
use crate::scene::{Geometry, NormalLoad, Scene};

/// `[interface]`: a positive hardness or adhesion, on a surface lattice, without a load
/// history; adhesion under an approach, not with a hardness.
pub(super) fn interface(scene: &Scene) -> Result<(), Issue> {
    if let Some(h) = scene.interface.hardness {
        positive("interface.hardness", h, "hardness")?;
        on_surface(scene, "interface.hardness", "a hardness cap")?;
    }
    let Some(a) = scene.interface.adhesion else { return Ok(()) };
    positive("interface.adhesion.work", a.work, "work of adhesion")?;
    within("interface.adhesion.range", a.range, &ranges::SMALL_LENGTH)?;
    on_surface(scene, "interface.adhesion", "adhesion")?;
    if scene.interface.hardness.is_some() {
        return Err(Issue::new(
            ErrorKind::Unsupported,
            "interface.adhesion",
            "adhesion together with a hardness cap is not solved in this version",
        )
        .hint("remove interface.hardness or interface.adhesion"));
    }
    if !matches!(scene.load.normal, NormalLoad::Approach(_)) {
        return Err(Issue::new(
            ErrorKind::Unsupported,
            "load.normal",
            "an adhesive contact is solved under a prescribed approach: on its unstable branch the force does not determine the state (it jumps in and out)",
        )
        .hint("give load.approach = \"50 nm\", or a path load.approach = [\"-20 nm\", \"100 nm\", 41] (the force along it is in load_curve)"));
    }
    Ok(())
}

/// A closed-form geometry, or a load history, refused for `what` at `key`.
fn on_surface(scene: &Scene, key: &str, what: &str) -> Result<(), Issue> {
    if !matches!(scene.geometry, Geometry::Surface(_)) {
        return Err(Issue::new(
            ErrorKind::Unsupported,
            key,
            format!("{what} is solved on a surface lattice only; this geometry is a closed form"),
        )
        .hint(format!("give geometry.kind = \"surface\" with the same profile (e.g. [geometry.profile] shape = \"sphere\") to solve it on a lattice, or remove {key}")));
    }
    if scene.load.history.is_some() {
        return Err(Issue::new(
            ErrorKind::Unsupported,
            key,
            format!("{what} under a load history is not solved in this version"),
        )
        .hint(format!("remove [load.history] (one load, a normal-load sweep or an approach path) or remove {key}")));
    }
    Ok(())
}

/// The corners of `load.approach = [from, to, ..., steps]` (or the one approach of an
/// adhesive contact): each at most the length range in magnitude, any sign; consecutive
/// corners apart.
pub(super) fn approach_path(scene: &Scene) -> Result<(), Issue> {
    let Some(p) = &scene.load.approach_path else { return Ok(()) };
    for (i, &c) in p.corners.iter().enumerate() {
        at_most("load.approach", c, &ranges::SMALL_LENGTH).map_err(|e| {
            let n = i + 1;
            Issue { message: format!("corner {n}: {}", e.message), ..e }
        })?;
    }
    if let Some(i) = p.corners.windows(2).position(|w| w[0] == w[1]) {
        return Err(Issue::new(
            ErrorKind::Impossible,
            "load.approach",
            format!(
                "corners {} and {} are equal: the leg between them has no length",
                i + 1,
                i + 2
            ),
        )
        .hint("consecutive corners must differ (e.g. [\"-20 nm\", \"100 nm\", 41])"));
    }
    if scene.interface.hardness.is_some() && p.corners.windows(2).any(|w| w[1] < w[0]) {
        return Err(Issue::new(
            ErrorKind::Unsupported,
            "load.approach",
            "an approach path that retracts under a hardness cap is not solved: the cap has no memory of plastic flow, so unloading would retrace the loading instead of keeping the permanent plastic displacement",
        )
        .hint("give an approach path that only presses further (increasing corners), or remove interface.hardness"));
    }
    if scene.interface.adhesion.is_none() && p.corners.last().is_some_and(|&c| c <= 0.0) {
        return Err(Issue::new(
            ErrorKind::Impossible,
            "load.approach",
            "the approach path ends at an approach <= 0: without adhesion the surfaces are apart there, and the last point is the state the later stages and the arrays take",
        )
        .hint("end the path at a positive approach (the force along it is in load_curve), or add interface.adhesion"));
    }
    Ok(())
}
