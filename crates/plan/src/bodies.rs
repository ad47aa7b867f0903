//! The two bodies of a scene, resolved once ([`resolve`]) at the start of planning: the
//! materials, their composite modulus and Dundurs' $\beta$, which every check, recipe and
//! stage then reads from the [`Bodies`] of the recipe.

use stickslip_graded::GradedMaterial;
use stickslip_halfspace::material::{composite_modulus, dundurs_beta};
use stickslip_halfspace::Material;
use stickslip_scene::{Elastic, Indenter, Scene, Substrate};

use super::recipe::Bodies;
use super::refusal::invalid;
use super::Issue;

/// Resolve the bodies of `scene`.
///
/// # Errors
/// An [`Issue`] naming the key of a material the half-space crate refuses.
pub(crate) fn resolve(scene: &Scene) -> Result<Bodies, Issue> {
    let substrate = substrate_material(&scene.substrate)?;
    let indenter = match scene.indenter {
        Indenter::Rigid => Material::rigid(),
        Indenter::Same => substrate,
        Indenter::Homogeneous(e) => elastic(e, "indenter.e")?,
    };
    Ok(Bodies {
        substrate,
        indenter,
        e_star: composite_modulus(&substrate, &indenter),
        beta: dundurs_beta(&substrate, &indenter),
        identical: identical(scene),
        graded: match scene.substrate {
            Substrate::Graded { e0, k, nu } if k > 0.0 => {
                Some(GradedMaterial::new(e0, k, nu).map_err(|e| invalid("substrate.k", e))?)
            }
            _ => None,
        },
    })
}

/// The substrate as a graded half-plane for the graded quadratures: the graded material
/// itself, or the homogeneous substrate as its limit $k = 0$.
///
/// # Errors
/// An [`Issue`] on `substrate.e` if the graded crate refuses the homogeneous limit.
pub(crate) fn half_plane(bodies: &Bodies) -> Result<GradedMaterial, Issue> {
    match bodies.graded {
        Some(m) => Ok(m),
        None => {
            let s = bodies.substrate;
            GradedMaterial::new(s.youngs_modulus(), 0.0, s.poisson_ratio())
                .map_err(|e| invalid("substrate.e", e))
        }
    }
}

fn elastic(e: Elastic, key: &'static str) -> Result<Material, Issue> {
    Material::new(e.e, e.nu).map_err(|er| invalid(key, er))
}

/// The substrate as a homogeneous material (graded: $E_0$; viscoelastic: the long-time E).
fn substrate_material(s: &Substrate) -> Result<Material, Issue> {
    match *s {
        Substrate::Homogeneous(e) => elastic(e, "substrate.e"),
        Substrate::Graded { e0, nu, .. } => elastic(Elastic { e: e0, nu }, "substrate.e0"),
        Substrate::Viscoelastic { elastic: e, .. } => elastic(e, "substrate.e"),
    }
}

/// Whether the scene's two bodies are of one material, read off the scene alone (the
/// refusals that run before the bodies are resolved need it too).
pub(crate) fn identical(scene: &Scene) -> bool {
    match (scene.indenter, scene.substrate) {
        (Indenter::Same, _) => true,
        (Indenter::Homogeneous(i), Substrate::Homogeneous(s)) => i == s,
        (Indenter::Homogeneous(i), Substrate::Viscoelastic { elastic, .. }) => i == elastic,
        _ => false,
    }
}
