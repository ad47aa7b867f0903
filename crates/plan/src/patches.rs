//! Pressure patches on a lattice: the scene's patches as the traction crate's grid patches,
//! and how closely a lattice must reproduce their force. The planner refuses a lattice that
//! misses it (`checks.rs`) before `stickslip-run`'s audit would.

use stickslip_lattice::{GridPatch, PatchPressure, Shape};
use stickslip_scene::{Patch, PatchShape};

/// How far the lattice's total normal force may be from the applied one: a lattice of
/// square cells covers a patch's area only approximately.
pub const LATTICE_AREA_TOLERANCE: f64 = 0.02;

/// The scene's patches as the traction crate's grid patches.
pub fn grid_patches(ps: &[Patch]) -> Vec<GridPatch> {
    ps.iter()
        .map(|p| GridPatch {
            shape: match p.shape {
                PatchShape::Square { side } => {
                    Shape::Rectangle { cx: p.centre[0], cy: p.centre[1], wx: side, wy: side }
                }
                PatchShape::Rectangle { sides } => Shape::Rectangle {
                    cx: p.centre[0],
                    cy: p.centre[1],
                    wx: sides[0],
                    wy: sides[1],
                },
                PatchShape::Circle { radius } => {
                    Shape::Circle { cx: p.centre[0], cy: p.centre[1], r: radius }
                }
            },
            pressure: PatchPressure::Uniform(p.pressure),
        })
        .collect()
}
