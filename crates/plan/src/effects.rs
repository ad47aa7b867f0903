//! The effects of a recipe: which effect each stage computes, by which technique, and why
//! the others are off (what `stickslip explain` prints and the run's counters check).

use super::build::{graded_k, visco};
use super::recipe::{
    Bodies, ContactFieldMethod, ContactNormal, ContactRecipe, GridMethod, GridStep,
    LineFieldMethod, LineFriction, LineNormal, LineRecipe, Recipe, RollingMethod, RollingModel,
    Tangential,
};
use super::{Effect, EffectPlan, Technique};
use stickslip_scene::eng::eng;
use stickslip_scene::{Method, Motion, Scene, Substrate};

impl Recipe {
    /// The technique of the normal-contact stage.
    pub fn normal_technique(&self) -> Technique {
        match self {
            Recipe::Line(r) => match r.normal {
                LineNormal::Hertz { .. } => Technique::HertzLine,
                LineNormal::Graded { .. } => Technique::GradedCylinder,
                LineNormal::Punch { .. } => Technique::FlatPunch,
            },
            Recipe::Rolling(r) => r.model.technique(),
            Recipe::WheelRail(_) => Technique::SurfaceContact,
            Recipe::Contact(r) => match r.normal {
                ContactNormal::Sphere { .. } => Technique::HertzSphere,
                ContactNormal::Ellipse { .. } => Technique::HertzEllipse,
                ContactNormal::EllipseGiven { .. } => Technique::EllipseGiven,
                ContactNormal::Patches(_) => Technique::PatchPressure,
                ContactNormal::Surface { adhesion: Some(_), .. } => Technique::AdhesiveSurface,
                ContactNormal::Surface { .. } => Technique::SurfaceContact,
            },
        }
    }

    /// The technique of the friction stage, when there is one.
    pub fn friction_technique(&self) -> Option<Technique> {
        match self {
            Recipe::Line(r) => r.friction.map(|f| match f {
                LineFriction::Sliding { .. } => Technique::Sliding,
                LineFriction::Cattaneo { .. } => Technique::Cattaneo2d,
                LineFriction::GradedPartialSlip { .. } => Technique::GradedPartialSlip,
            }),
            Recipe::Rolling(r) => Some(r.model.technique()),
            Recipe::WheelRail(r) => match r.tangential {
                stickslip_wheelrail::Tangential::Fastsim => Some(Technique::Fastsim),
                stickslip_wheelrail::Tangential::None => None,
                _ => Some(Technique::SteadyRolling),
            },
            Recipe::Contact(r) => match (&r.history, r.tangential) {
                (Some(_), _) => Some(Technique::LoadHistory),
                (None, t) => t.map(|t| t.technique()),
            },
        }
    }
}

impl RollingModel {
    /// Carter or Goryacheva.
    pub fn technique(&self) -> Technique {
        match self {
            RollingModel::Carter(_) => Technique::Carter,
            RollingModel::Goryacheva { viscoelastic: true, .. } => Technique::Goryacheva,
            // alpha = beta is solved by Goryacheva's equations, reported as Carter's case
            RollingModel::Goryacheva { viscoelastic: false, .. } => Technique::Carter,
        }
    }
}

impl Tangential {
    /// The technique of this step.
    pub fn technique(&self) -> Technique {
        match self {
            Tangential::Sliding { .. } => Technique::Sliding,
            Tangential::Mindlin { .. } => Technique::Mindlin,
            Tangential::Cattaneo { .. } => Technique::Cattaneo,
            Tangential::Lubkin { .. } => Technique::Lubkin,
            Tangential::Rolling(r) => match r.method {
                RollingMethod::Fastsim => Technique::Fastsim,
                RollingMethod::Polach => Technique::Polach,
                RollingMethod::Transient => Technique::TransientRolling,
                _ => Technique::SteadyRolling,
            },
            Tangential::Grid(GridStep { method: GridMethod::Fast, .. }) => Technique::Fast,
            Tangential::Grid(GridStep { method: GridMethod::Lp, force: None, .. }) => {
                Technique::LpMoment
            }
            Tangential::Grid(GridStep { method: GridMethod::Lp, .. }) => Technique::LpForce,
        }
    }
}

pub(super) fn effects(
    scene: &Scene,
    bodies: &Bodies,
    recipe: &Recipe,
    notes: &mut Vec<String>,
) -> Vec<EffectPlan> {
    use Effect as E;
    let l = &scene.load;
    let on = |effect, reason: String, t: Technique| EffectPlan {
        effect,
        on: true,
        reason,
        technique: Some(t),
    };
    let off = |effect, reason: String| EffectPlan { effect, on: false, reason, technique: None };
    let mut effects: Vec<EffectPlan> = Vec::with_capacity(8);
    effects.push(on(E::NormalContact, "always".to_string(), recipe.normal_technique()));

    let rolling = matches!(
        scene.motion,
        Motion::Rolling { .. } | Motion::RollingCreepage { .. } | Motion::Wheelset { .. }
    );
    let f = l.friction;
    let friction_cause = if l.history.is_some() {
        Some("a load path ([load.history])")
    } else if l.tangential != 0.0 {
        Some("a tangential load")
    } else if l.sliding {
        Some("sliding = true")
    } else if l.moment != 0.0 {
        Some("a twisting moment")
    } else if rolling {
        Some("rolling")
    } else {
        None
    };
    match (recipe.friction_technique(), friction_cause) {
        (Some(t), Some(cause)) => {
            if t == Technique::Cattaneo2d && !bodies.identical {
                notes.push("2D Cattaneo-Mindlin neglects the coupling of normal and tangential tractions; exact for identical materials only (Dundurs beta = 0)".to_string());
            }
            if t == Technique::GradedPartialSlip {
                notes.push("graded partial slip: the stick zone is where the q-induced u_x is uniform; the pressure-induced odd part of u_x (FORMULAS.md A5) is neglected, as in Cattaneo-Mindlin".to_string());
            }
            if matches!(t, Technique::Mindlin | Technique::Cattaneo | Technique::Lubkin)
                && !bodies.identical
            {
                notes.push("Mindlin/Cattaneo/Lubkin neglect normal-tangential coupling (exact for identical materials)".to_string());
            }
            let mut reason = format!("f = {f} > 0 with {cause}");
            if let Recipe::Contact(c) = recipe {
                let surface = matches!(c.normal, ContactNormal::Surface { .. });
                let grid = matches!(c.tangential, Some(Tangential::Grid(_)));
                if grid && c.coupling.is_none() && !c.bodies.identical {
                    let beta = c.bodies.beta;
                    if beta != 0.0 {
                        notes.push(if surface {
                            format!("the modified LP neglects the normal-tangential coupling (Dundurs beta = {beta:.4}); solver.method = \"fast\" or \"auto\" solves it")
                        } else {
                            format!("the grid solver on a closed-form pressure neglects the normal-tangential coupling (Dundurs beta = {beta:.4}; exact for beta = 0); geometry.kind = \"surface\" solves it coupled")
                        });
                    }
                }
                if surface && l.sliding && !c.bodies.identical {
                    let beta = c.bodies.beta;
                    if beta != 0.0 {
                        notes.push(format!("sliding q = f p on the surface's uncoupled pressure: the normal displacement of the shear (Dundurs beta = {beta:.4}) is neglected"));
                    }
                }
                if let Some(beta) = c.coupling {
                    reason.push_str(&format!("; coupled with the normal contact through Dundurs beta = {beta:.4} (dissimilar bodies): alternating normal and tangential solves until both fields settle"));
                }
            }
            effects.push(on(E::Friction, reason, t));
        }
        _ if f > 0.0 => effects.push(off(
            E::Friction,
            format!("f = {f} but no tangential load, sliding, moment or rolling: nothing for friction to carry"),
        )),
        _ => effects.push(off(E::Friction, "friction coefficient is 0".to_string())),
    }

    match graded_k(scene) {
        Some(k) if k > 0.0 => effects.push(on(
            E::Grading,
            format!("graded substrate with k = {k}"),
            Technique::GradedKernels,
        )),
        Some(_) => effects.push(off(
            E::Grading,
            "graded substrate with k = 0 is homogeneous: solved as a homogeneous half-plane"
                .to_string(),
        )),
        None => effects.push(off(E::Grading, "substrate is not graded".to_string())),
    }

    match (visco(scene), scene.substrate) {
        (Some(true), Substrate::Viscoelastic { alpha, beta, .. }) => effects.push(on(
            E::Viscoelasticity,
            format!("standard solid with alpha = {} > beta = {}", eng(alpha, "s"), eng(beta, "s")),
            Technique::Goryacheva,
        )),
        (Some(false), _) => effects.push(off(
            E::Viscoelasticity,
            "alpha = beta: the standard solid is elastic; solved as elastic (Carter)".to_string(),
        )),
        _ => effects.push(off(E::Viscoelasticity, "no viscoelastic material".to_string())),
    }

    match (recipe, scene.motion) {
        (Recipe::WheelRail(r), Motion::Wheelset { speed, .. }) => {
            let omega = r.motion.map_or(0.0, |m| m.pitch_rate);
            let (method, t) = match r.tangential {
                stickslip_wheelrail::Tangential::Fastsim => {
                    ("FASTSIM (solver.method = \"fastsim\")".to_string(), Technique::Fastsim)
                }
                stickslip_wheelrail::Tangential::Exact { tolerance } => (
                    format!("the exact steady-rolling theory at relative tolerance {tolerance:e}"),
                    Technique::SteadyRolling,
                ),
                _ => ("none".to_string(), Technique::SteadyRolling),
            };
            if !matches!(r.tangential, stickslip_wheelrail::Tangential::None) {
                let why = match r.motion.and_then(|m| m.creepage) {
                    Some(c) => format!("a wheel rolling at V = {} with the creepages given (motion.creepage: longitudinal {:e}, lateral {:e}, spin {}) on its single patch; creep forces by {method}", eng(speed, "m/s"), c.longitudinal, c.lateral, eng(c.spin, "1/m")),
                    None => format!("a wheelset rolling at V = {} with pitch rate {}: each patch's creepages (longitudinal, lateral, spin) from the motion, the position and the patch's contact angle and rolling radius; creep forces by {method}", eng(speed, "m/s"), eng(omega, "rad/s")),
                };
                effects.push(on(E::Rolling, why, t));
            } else {
                effects.push(off(
                    E::Rolling,
                    "friction coefficient is 0: normal contact only".to_string(),
                ));
            }
            if !bodies.identical {
                notes.push("wheel-rail patches are solved as quasi-identical bodies: the normal-tangential coupling (Dundurs beta) is neglected".to_string());
            }
        }
        (Recipe::Rolling(r), Motion::Rolling { speed, creep }) => effects.push(on(
            E::Rolling,
            format!("rolling at w = {}, creep {}", eng(speed, "m/s"), eng(creep, "")),
            r.model.technique(),
        )),
        (
            Recipe::Contact(ContactRecipe { tangential: Some(t @ Tangential::Rolling(r)), .. }),
            Motion::RollingCreepage { speed, longitudinal, lateral, spin, transient: None },
        ) => {
            let why = match (scene.solver.method, r.method) {
                (Method::Auto, RollingMethod::Exact) => format!("the exact theory: solver.tolerance = {:e} is below FASTSIM's force error (0.1 fN)", scene.solver.tolerance),
                (Method::Auto, RollingMethod::Fastsim) => format!("FASTSIM: solver.tolerance = {} admits its force error (up to 0.1 fN)", scene.solver.tolerance),
                (Method::Auto, _) => format!("Polach's law: solver.tolerance = {} admits its force error (up to 0.15 fN) and there is no spin", scene.solver.tolerance),
                _ => format!("solver.method = {:?}", r.method),
            };
            effects.push(on(
                E::Rolling,
                format!(
                    "3D steady rolling at V = {}, creepages xi = {}, eta = {}, spin = {} 1/m; {why}",
                    eng(speed, "m/s"),
                    eng(longitudinal, ""),
                    eng(lateral, ""),
                    eng(spin, "")
                ),
                t.technique(),
            ));
            if !bodies.identical {
                notes.push("3D rolling treats the bodies as quasi-identical: the normal-tangential coupling (Dundurs beta) is neglected".to_string());
            }
        }
        (
            Recipe::Contact(ContactRecipe { tangential: Some(t @ Tangential::Rolling(r)), .. }),
            Motion::RollingCreepage { speed, spin, transient: Some(tr), .. },
        ) => {
            let force = r.transient.map_or((0.0, 0.0), |x| x.force);
            effects.push(on(
                E::Rolling,
                format!(
                    "transient rolling at V = {} from {} under the creep force ({}, {}) on the indenter, spin = {} 1/m, over {} in steps of one element length; the creepages follow from the force",
                    eng(speed, "m/s"),
                    match tr.start {
                        stickslip_scene::TransientStart::Shift => "a Cattaneo shift at rest",
                        stickslip_scene::TransientStart::Rest => "rest",
                    },
                    eng(force.0, "N"),
                    eng(force.1, "N"),
                    eng(spin, ""),
                    tr.distance.map_or("two contact lengths".to_string(), |d| eng(d, "m")),
                ),
                t.technique(),
            ));
            if !bodies.identical {
                notes.push("transient rolling treats the bodies as quasi-identical: the normal-tangential coupling (Dundurs beta) is neglected".to_string());
            }
        }
        _ => effects.push(off(E::Rolling, "motion is static".to_string())),
    }

    let path_moment = l.history.as_ref().and_then(|h| h.moment.as_ref());
    match (recipe, l.moment != 0.0, path_moment) {
        (Recipe::Contact(ContactRecipe { tangential: Some(t), .. }), true, _) => effects.push(on(
            E::Twist,
            format!("moment M = {}", eng(l.moment, "N m")),
            t.technique(),
        )),
        (Recipe::Contact(_), _, Some(m)) => effects.push(on(
            E::Twist,
            format!("a moment along the load path ({} corner values)", m.len()),
            Technique::LoadHistory,
        )),
        _ => effects.push(off(E::Twist, "no twisting moment".to_string())),
    }

    match (&l.history, scene.outputs.cycle) {
        (Some(h), cycle) => {
            let what = match h.control {
                stickslip_scene::HistoryControl::Force => "tangential force",
                stickslip_scene::HistoryControl::Shift => "shift",
            };
            let mut reason = format!(
                "[load.history]: {} corners of the {what}{}{}, {} steps between corners; each step solved from the one before",
                h.tangential.len(),
                if h.normal.is_some() { " and the normal load" } else { "" },
                if h.moment.is_some() { " and the moment" } else { "" },
                h.steps
            );
            if let Some(c) = cycle {
                reason.push_str(&format!(
                    "; outputs.cycle with T*/(fP) = {} beside it (Mindlin-Deresiewicz closed form)",
                    c.amplitude
                ));
            }
            if let Recipe::Contact(c) = recipe {
                if c.bodies.beta != 0.0 {
                    let given = matches!(
                        c.normal,
                        ContactNormal::EllipseGiven { .. } | ContactNormal::Patches(_)
                    );
                    reason.push_str(&if given {
                        format!("; dissimilar bodies (Dundurs beta = {:.4}): the tangential displacement of each step's pressure change enters its slip (the prescribed pressure does not respond to the traction)", c.bodies.beta)
                    } else {
                        format!("; coupled with the normal contact through Dundurs beta = {:.4} (dissimilar bodies): each step alternates normal and tangential solves until the traction settles", c.bodies.beta)
                    });
                }
            }
            effects.push(on(E::Hysteresis, reason, Technique::LoadHistory));
        }
        (None, Some(c)) => effects.push(on(
            E::Hysteresis,
            format!("outputs.cycle with T*/(fP) = {}", c.amplitude),
            Technique::Deresiewicz,
        )),
        (None, None) => effects.push(off(E::Hysteresis, "no outputs.cycle".to_string())),
    }

    match recipe {
        Recipe::Contact(ContactRecipe { field: Some(field), .. }) => effects.push(on(
            E::SubsurfaceField,
            format!(
                "outputs.field with {} x {} x {} points",
                field.grid.x.2,
                field.grid.y.2,
                field.grid.z.map_or(1, |z| z.2)
            ),
            match field.method {
                ContactFieldMethod::HertzSphere => Technique::HertzSphereField,
                ContactFieldMethod::HertzSliding { .. } => Technique::HamiltonSlidingField,
                ContactFieldMethod::HertzEllipse => Technique::HertzEllipseField,
                ContactFieldMethod::Lattice => Technique::LatticeField,
            },
        )),
        Recipe::Line(LineRecipe { field: Some(field), .. }) => effects.push(on(
            E::SubsurfaceField,
            format!("outputs.field with {} x {} points", field.grid.x.2, field.grid.y.2),
            match field.method {
                LineFieldMethod::McEwen => Technique::McEwen,
                LineFieldMethod::Quadrature { .. } => Technique::StressQuadrature,
            },
        )),
        _ => effects.push(off(E::SubsurfaceField, "no outputs.field".to_string())),
    }
    effects
}
