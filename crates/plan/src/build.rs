//! The planner's decisions: the recipe (which method serves each stage), the effects with
//! their reasons, the notes. Refusals come first ([`super::checks`]), the cost estimate
//! last ([`super::cost`]).

use std::f64::consts::PI;

use stickslip_graded::Accuracy;
use stickslip_halfspace::hertz::HertzSphere;
use stickslip_normal::NormalProblem;
use stickslip_rolling::{CarterParams, GoryachevaParams, StressConfig};
use stickslip_traction::{FastConfig, ModifiedLp};

use super::bodies;
use super::checks::{self, along_axis, tolerance_for};
use super::cost::{self, lattice_elements};
use super::recipe::{
    Bodies, ContactField, ContactFieldMethod, ContactNormal, ContactRecipe, Creepage, CycleRecipe,
    Force, GridMethod, GridStep, HistoryRecipe, LineDisplacements, LineField, LineFieldMethod,
    LineFriction, LineLoad, LineNormal, LineRecipe, LineSurface, Recipe, RollingMethod,
    RollingModel, RollingRecipe, RollingStep, SurfaceLoad, Tangential, TransientRecipe,
};
use super::refusal::{invalid, unsupported};
use super::{Issue, Plan, SURFACE_POINTS};
use stickslip_scene::ErrorKind;
use stickslip_scene::{
    Ellipse, Geometry, Method, Motion, NormalLoad, Patch, Scene, Substrate, Surface,
    SurfaceBoundary,
};

/// Plan `scene`: refuse what no solver handles, choose the method of every stage, explain
/// each effect, estimate the cost.
pub(crate) fn build(scene: &Scene) -> Result<Plan, Issue> {
    checks::refuse(scene)?;
    let bodies = bodies::resolve(scene)?;
    checks::magnitudes(scene, &bodies)?;
    let mut notes = Vec::new();
    let visco = visco(scene);
    let rolling = matches!(scene.motion, Motion::Rolling { .. });
    if visco == Some(false) && !rolling {
        notes.push("alpha = beta: the standard solid is elastic with modulus E; solved as a homogeneous elastic body".to_string());
    }
    let (recipe, grid_reason) = match (&scene.geometry, scene.motion) {
        (Geometry::Cylinder { radius }, Motion::Rolling { speed, creep }) => {
            (Recipe::Rolling(rolling_recipe(scene, *radius, speed, creep)?), None)
        }
        (Geometry::Cylinder { radius }, Motion::Static) => {
            (Recipe::Line(line_recipe(scene, &bodies, LineBody::Cylinder(*radius))?), None)
        }
        (Geometry::Punch { half_width }, Motion::Static) => {
            (Recipe::Line(line_recipe(scene, &bodies, LineBody::Punch(*half_width))?), None)
        }
        (Geometry::WheelRail(w), Motion::Static | Motion::Wheelset { .. }) => {
            (Recipe::WheelRail(Box::new(wheel_rail_recipe(scene, &bodies, w)?)), None)
        }
        (_, Motion::Wheelset { .. }) => {
            return Err(unsupported(
                "motion.pitch_rate",
                "a wheelset's motion needs a wheel on a rail",
                "use geometry.kind = \"wheel-rail\"",
            ))
        }
        (Geometry::WheelRail(_), _) => {
            return Err(unsupported(
                "motion.kind",
                "a wheel on a rail rolls with motion.speed and motion.pitch_rate",
                "[motion] kind = \"rolling\", speed = \"2 m/s\", pitch_rate = \"-4.35 rad/s\"",
            ))
        }
        (_, Motion::Rolling { .. }) => {
            return Err(unsupported(
                "geometry.kind",
                "rolling needs a cylinder",
                "use geometry.kind = \"cylinder\"",
            ))
        }
        (Geometry::Sphere { radius }, Motion::Static | Motion::RollingCreepage { .. }) => {
            let (r, reason) = contact_recipe(scene, &bodies, ContactBody::Sphere(*radius))?;
            (Recipe::Contact(r), Some(reason))
        }
        (Geometry::Ellipsoid(e), Motion::Static | Motion::RollingCreepage { .. }) => {
            let (r, reason) = contact_recipe(scene, &bodies, ContactBody::Ellipsoid(*e))?;
            (Recipe::Contact(r), Some(reason))
        }
        (Geometry::Patches(ps), Motion::Static) => {
            let (r, reason) = contact_recipe(scene, &bodies, ContactBody::Patches(ps))?;
            (Recipe::Contact(r), Some(reason))
        }
        (Geometry::Surface(s), Motion::Static | Motion::RollingCreepage { .. }) => {
            let (r, reason) = contact_recipe(scene, &bodies, ContactBody::Surface(s))?;
            (Recipe::Contact(r), Some(reason))
        }
        (_, Motion::RollingCreepage { .. }) => {
            return Err(unsupported(
                "geometry.kind",
                "3D rolling with creepage needs a sphere, an ellipsoid or a surface (a cylinder rolls in 2D: use motion.creep)",
                "use geometry.kind = \"ellipsoid\" (radii), \"sphere\" or \"surface\"",
            ))
        }
    };
    let effects = super::effects::effects(scene, &bodies, &recipe, &mut notes);
    let grid_solver = match &recipe {
        Recipe::Contact(ContactRecipe { history: Some(_), .. }) => Some(
            "a load path: the fast solver, one warm solve per step from the step before"
                .to_string(),
        ),
        Recipe::Contact(ContactRecipe { tangential: Some(Tangential::Grid(_)), .. }) => grid_reason,
        _ => None,
    };
    let (surface_points, grid_elements, cost) = cost::estimate(scene, &effects)?;
    checks::capacity(scene, &bodies)?;
    checks::lattice(scene)?;
    checks::spin(scene, &bodies)?;
    Ok(Plan {
        title: scene.title.clone(),
        file: scene.file.clone(),
        source: scene.source.clone(),
        effects,
        surface_points,
        grid_elements,
        grid_solver,
        cost,
        notes,
        recipe,
    })
}

/// A wheel on its rail: the profiles read and checked, the track and wheelset placed, the
/// load, the motion and the tangential method resolved.
fn wheel_rail_recipe(
    scene: &Scene,
    bodies: &Bodies,
    w: &stickslip_scene::WheelRail,
) -> Result<crate::recipe::WheelRailRecipe, Issue> {
    use stickslip_wheelrail as wr;
    let wr_err = |key: &str, e: wr::Error, hint: &str| {
        Issue::new(ErrorKind::OutOfRange, key, e.to_string()).hint(hint.to_string())
    };
    if !matches!(scene.substrate, Substrate::Homogeneous(_)) {
        return Err(unsupported(
            "substrate.model",
            "a wheel on a rail is solved for homogeneous elastic bodies",
            "substrate.model = \"homogeneous\" (the rail), e.g. e = \"210 GPa\", nu = 0.28",
        ));
    }
    let l = &scene.load;
    if l.tangential != 0.0 || l.moment != 0.0 || l.sliding || l.history.is_some() {
        return Err(unsupported(
            "load",
            "a wheel on a rail takes no tangential load, moment, sliding or load path: its creep forces follow from the motion",
            "remove load.tangential, load.moment, load.sliding and [load.history]; set [motion] speed and pitch_rate",
        ));
    }
    let options = wr::ProfileOptions { unit: w.profile_unit, ..wr::ProfileOptions::default() };
    let read = |f: &stickslip_scene::ProfileFile, role, key: &str| {
        read_profile(f, role, &options).map_err(|e| {
            Issue::new(ErrorKind::OutOfRange, key, format!("the profile is refused: {e}"))
                .hint("check the file named in the message at its line; geometry.profile_unit gives the file's length unit (default mm); a rail profile (.prr, .ban) goes in rail_profile, a wheel profile (.prw, .whl) in wheel_profile")
        })
    };
    let rail = read(&w.rail_profile, wr::Role::Rail, "geometry.rail_profile")?;
    let wheel = read(&w.wheel_profile, wr::Role::Wheel, "geometry.wheel_profile")?;
    let track = wr::Track::new(rail, w.gauge, w.gauge_height, w.rail_cant).map_err(|e| {
        wr_err("geometry.gauge_height", e, "the rail's gauge face must reach gauge_height below its top (14 mm for standard track); check gauge, gauge_height and rail_cant")
    })?;
    let wheelset = wr::Wheelset::new(wheel, w.flange_back_distance, w.flange_back_position, w.wheel_radius)
        .map_err(|e| wr_err("geometry.flange_back_position", e, "flange_back_position is the flange back's y in the wheel profile's own coordinates (e.g. -70 mm for S1002); check flange_back_distance and wheel_radius"))?;
    let side = match w.side {
        stickslip_scene::RailSide::Left => wr::Side::Left,
        stickslip_scene::RailSide::Right => wr::Side::Right,
    };
    let cell = scene.solver.cell.map_or((2e-4, 2e-4), |[a, b]| (a, b));
    let load = match l.normal {
        NormalLoad::Force(p) => match w.vertical {
            stickslip_scene::WheelLoadDefinition::Normal => wr::VerticalLoad::Force(p),
            stickslip_scene::WheelLoadDefinition::Total => wr::VerticalLoad::TotalForce(p),
        },
        NormalLoad::Approach(d) => wr::VerticalLoad::Approach(d),
        _ => {
            return Err(unsupported(
                "load.normal",
                "a wheel on a rail takes the vertical wheel load or the approach",
                "load.normal = \"10 kN\" or load.approach = \"50 um\"",
            ))
        }
    };
    let motion = match scene.motion {
        Motion::Wheelset { speed, creepage: Some([longitudinal, lateral, spin]), .. } => {
            Some(wr::Motion::with_creepage(speed, Creepage { longitudinal, lateral, spin }))
        }
        Motion::Wheelset { speed, pitch_rate, creepage: None } => Some(match pitch_rate {
            Some(omega) => wr::Motion::rolling(speed, omega),
            None => wr::Motion::free_rolling(speed, w.wheel_radius),
        }),
        _ => None,
    };
    let tangential = match (motion, l.friction > 0.0, scene.solver.method) {
        (None, _, _) | (_, false, _) => wr::Tangential::None,
        (Some(_), true, Method::Fastsim) => wr::Tangential::Fastsim,
        (Some(_), true, Method::Auto | Method::Fast) => {
            wr::Tangential::Exact { tolerance: scene.solver.tolerance.clamp(1e-10, 1e-2) }
        }
        (Some(_), true, m) => {
            return Err(unsupported(
                "solver.method",
                format!("solver.method = {m:?} does not solve a wheel on a rail"),
                "solver.method = \"auto\" (the exact steady-rolling theory) or \"fastsim\"",
            ))
        }
    };
    // The problem is built once here so that its refusals (cell, friction, materials, the
    // rail's placement) come before any solving.
    wr::WheelRail::new(
        side,
        track.clone(),
        wheelset.clone(),
        bodies.substrate,
        bodies.indenter,
        l.friction,
        cell,
    )
    .map_err(|e| {
        wr_err(
            "solver.cell",
            e,
            "cell = [along x, across], two lengths > 0; friction >= 0; at most one rigid body",
        )
    })?;
    Ok(crate::recipe::WheelRailRecipe {
        side,
        track,
        wheelset,
        bodies: *bodies,
        friction: l.friction,
        cell,
        position: wr::Position {
            lateral: w.position.lateral,
            yaw: w.position.yaw,
            roll: w.position.roll,
        },
        motion,
        load,
        tangential,
    })
}

/// A profile file read, checked and splined, once per process for each name, text, role
/// and options: the points of a sweep read the same files (issue 29 item 9). The key holds
/// the whole text, so a file changed between two runs is read again; at most 16 profiles are
/// kept.
fn read_profile(
    f: &stickslip_scene::ProfileFile,
    role: stickslip_wheelrail::Role,
    options: &stickslip_wheelrail::ProfileOptions,
) -> Result<stickslip_wheelrail::Profile, stickslip_wheelrail::Error> {
    use std::sync::{Arc, Mutex};
    use stickslip_wheelrail as wr;
    type Key = (String, Arc<str>, String);
    static PROFILES: Mutex<Vec<(Key, wr::Profile)>> = Mutex::new(Vec::new());
    // The role and the options by their exact (Debug) text: f64 prints to the last bit.
    let key: Key = (f.name.clone(), f.text.clone(), format!("{role:?} {options:?}"));
    let same =
        |k: &Key| k.0 == key.0 && k.2 == key.2 && (Arc::ptr_eq(&k.1, &key.1) || k.1 == key.1);
    if let Some(p) = PROFILES
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .iter()
        .find(|(k, _)| same(k))
    {
        return Ok(p.1.clone());
    }
    let p = wr::Profile::read(&f.text, &f.name, wr::Format::from_name(&f.name), role, options)?;
    let mut cache = PROFILES.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    if cache.len() >= 16 {
        cache.remove(0);
    }
    cache.push((key, p.clone()));
    Ok(p)
}

/// Whether the substrate is viscoelastic: `Some(true)` when alpha != beta, `Some(false)`
/// when the standard solid is elastic (alpha = beta), `None` for other substrates.
pub(super) fn visco(scene: &Scene) -> Option<bool> {
    match scene.substrate {
        Substrate::Viscoelastic { alpha, beta, .. } => Some(alpha != beta),
        _ => None,
    }
}

pub(super) fn graded_k(scene: &Scene) -> Option<f64> {
    match scene.substrate {
        Substrate::Graded { k, .. } => Some(k),
        _ => None,
    }
}

fn approach_refused() -> Issue {
    Issue::new(
        ErrorKind::Schema,
        "load.approach",
        "the approach (displacement control) is for geometry.kind = \"surface\"",
    )
    .hint("give load.normal = P")
}

fn half_width_refused() -> Issue {
    Issue::new(
        ErrorKind::Schema,
        "load.half_width",
        "this geometry takes the normal load, not a half-width",
    )
    .hint("give load.normal = P")
}

// ---------------------------------------------------------------------------------------
// 2D static

/// The body of a line contact.
#[derive(Clone, Copy)]
enum LineBody {
    /// A cylinder of this radius (m).
    Cylinder(f64),
    /// A flat punch of this half-width (m).
    Punch(f64),
}

fn line_recipe(scene: &Scene, bodies: &Bodies, body: LineBody) -> Result<LineRecipe, Issue> {
    let l = &scene.load;
    let k = graded_k(scene);
    let grading = k.is_some_and(|k| k > 0.0);
    let line_load = match l.normal {
        NormalLoad::HalfWidth(a) => LineLoad::HalfWidth(a),
        NormalLoad::Force(p) | NormalLoad::FromPatches(p) => LineLoad::Force(p),
        NormalLoad::Approach(_) => return Err(approach_refused()),
    };
    let graded_material = bodies.graded;
    let normal = match (body, graded_material) {
        (LineBody::Punch(half_width), _) => match line_load {
            LineLoad::Force(force) => LineNormal::Punch { half_width, force },
            LineLoad::HalfWidth(_) => return Err(half_width_refused()),
        },
        (LineBody::Cylinder(radius), Some(material)) => {
            LineNormal::Graded { radius, load: line_load, material }
        }
        (LineBody::Cylinder(radius), None) => {
            LineNormal::Hertz { radius, load: line_load, bodies: *bodies }
        }
    };
    let f = l.friction;
    let friction = if f > 0.0 && (l.tangential != 0.0 || l.sliding) {
        Some(if l.sliding {
            LineFriction::Sliding { friction: f }
        } else if grading {
            LineFriction::GradedPartialSlip { friction: f, tangential: l.tangential }
        } else {
            LineFriction::Cattaneo { friction: f, tangential: l.tangential }
        })
    } else {
        None
    };
    let field = match scene.outputs.field {
        Some(grid) => {
            let punch = matches!(normal, LineNormal::Punch { .. });
            let method = if grading || punch || scene.solver.method == Method::Quadrature {
                let material = bodies::half_plane(bodies)?;
                LineFieldMethod::Quadrature { material, accuracy: graded_accuracy(scene)? }
            } else {
                LineFieldMethod::McEwen
            };
            Some(LineField { grid, method })
        }
        None => None,
    };
    let surface = if scene.outputs.surface {
        let displacements = match normal {
            LineNormal::Hertz { bodies, .. } => {
                LineDisplacements::Homogeneous { substrate: bodies.substrate }
            }
            LineNormal::Graded { material, .. } => {
                LineDisplacements::Graded { material, accuracy: graded_accuracy(scene)? }
            }
            LineNormal::Punch { .. } => LineDisplacements::None,
        };
        Some(LineSurface { points: SURFACE_POINTS, displacements })
    } else {
        None
    };
    Ok(LineRecipe { normal, friction_coefficient: f, friction, surface, field })
}

fn graded_accuracy(scene: &Scene) -> Result<Accuracy, Issue> {
    let t = tolerance_for(scene, "the graded-kernel quadrature", Accuracy::TOLERANCE_RANGE)?;
    let t = stickslip_graded::Tolerance::relative(t).map_err(|e| invalid("solver.tolerance", e))?;
    Accuracy::new(t).map_err(|e| invalid("solver.tolerance", e))
}

// ---------------------------------------------------------------------------------------
// rolling

fn rolling_recipe(
    scene: &Scene,
    radius: f64,
    speed: f64,
    creep: f64,
) -> Result<RollingRecipe, Issue> {
    let NormalLoad::Force(load) = scene.load.normal else {
        return Err(unsupported(
            "load.half_width",
            "rolling takes the normal load; the contact length follows from it",
            "give load.normal = P (N/m)",
        ));
    };
    let friction = scene.load.friction;
    let model = match scene.substrate {
        Substrate::Viscoelastic { elastic: el, alpha, beta } => {
            let tol = tolerance_for(
                scene,
                "the rolling stress quadrature",
                StressConfig::TOLERANCE_RANGE,
            )?;
            let params = GoryachevaParams::new(
                el.e, el.nu, radius, load, friction, creep, alpha, beta, speed,
            )
            .map_err(|e| invalid("substrate", e))?;
            RollingModel::Goryacheva {
                params,
                stress: StressConfig {
                    tol: stickslip_rolling::Tolerance::relative(tol)
                        .map_err(|e| invalid("solver.tolerance", e))?,
                    max_subdivisions: 200,
                },
                viscoelastic: alpha != beta,
            }
        }
        Substrate::Homogeneous(el) => RollingModel::Carter(
            CarterParams::new(el.e, el.nu, radius, load, friction, creep)
                .map_err(|e| invalid("substrate", e))?,
        ),
        Substrate::Graded { .. } => {
            return Err(unsupported(
                "motion.kind",
                "rolling is solved for homogeneous (Carter) and viscoelastic (Goryacheva) bodies, not graded ones",
                "use motion.kind = \"static\", or a homogeneous / viscoelastic substrate",
            ))
        }
    };
    Ok(RollingRecipe { model, surface_points: scene.outputs.surface.then_some(SURFACE_POINTS) })
}

// ---------------------------------------------------------------------------------------
// 3D static

/// The grid solver for 3D partial slip without a closed form, and why: what
/// `solver.method` asks for, or under `"auto"` the modified LP up to
/// [`super::MAX_LP_ELEMENTS`] contact elements (exact for its discretisation, seed 002) and
/// the fast solver beyond it or when a force and a moment act together (the LP takes one
/// load mode). True for the fast solver.
fn grid_solver(method: Method, elements: usize, both: bool) -> (bool, String) {
    use super::MAX_LP_ELEMENTS;
    match method {
        Method::Lp => (false, "solver.method = \"lp\"".to_string()),
        Method::Fast => (true, "solver.method = \"fast\"".to_string()),
        _ if both => (
            true,
            "a tangential force and a twisting moment act together; the LP takes one load mode: the fast solver".to_string(),
        ),
        _ if elements > MAX_LP_ELEMENTS => (
            true,
            format!("about {elements} contact elements > {MAX_LP_ELEMENTS}, the dense LP's limit: the fast solver"),
        ),
        _ => (
            false,
            format!("about {elements} contact elements <= {MAX_LP_ELEMENTS}: the modified LP (exact for its discretisation, seed 002)"),
        ),
    }
}

/// The 3D steady-rolling step: the theory from `solver.method`, or under `"auto"` from the
/// tolerance (the accuracy knob): Polach's law when the tolerance admits its measured force
/// error and there is no spin, FASTSIM when it admits FASTSIM's, else the exact theory.
fn rolling_step(
    scene: &Scene,
    body: ContactBody<'_>,
    speed: f64,
    creepage: Creepage,
) -> Result<Tangential, Issue> {
    use stickslip_rolling::{
        steady3d::FASTSIM_FORCE_ERROR, steady3d::POLACH_FORCE_ERROR, steady3d::TOLERANCE_RANGE,
    };
    let l = &scene.load;
    if l.friction <= 0.0 {
        return Err(unsupported(
            "load.friction",
            "rolling with creepage needs a friction coefficient: without friction no creep force arises",
            "give load.friction, e.g. friction = 0.3",
        ));
    }
    if l.tangential != 0.0 || l.moment != 0.0 || l.sliding {
        return Err(unsupported(
            "load.tangential",
            "in steady rolling the creep forces and spin moment follow from the creepages; a tangential load, a moment or sliding cannot also be prescribed",
            "remove load.tangential, load.moment and load.sliding; set motion.creepage instead",
        ));
    }
    let ellipse = matches!(body, ContactBody::Sphere(_) | ContactBody::Ellipsoid(_));
    let needs_ellipse = |name: &str| {
        unsupported(
            "solver.method",
            format!("{name} needs a Hertz ellipse (its parameters come from Kalker's coefficients of an elliptical contact)"),
            "use method = \"auto\" or \"fast\" (the exact theory), which rolls any surface",
        )
    };
    let tol = scene.solver.tolerance;
    let method = match scene.solver.method {
        Method::Fastsim if !ellipse => return Err(needs_ellipse("FASTSIM")),
        Method::Fastsim => RollingMethod::Fastsim,
        Method::Polach if !ellipse => return Err(needs_ellipse("Polach's law")),
        Method::Polach if creepage.spin != 0.0 => {
            return Err(unsupported(
                "motion.creepage.spin",
                "Polach's creep-force law has no spin",
                "use method = \"fastsim\" or \"auto\", or remove the spin",
            ))
        }
        Method::Polach => RollingMethod::Polach,
        Method::Fast => RollingMethod::Exact,
        Method::Auto if ellipse && creepage.spin == 0.0 && tol >= POLACH_FORCE_ERROR => {
            RollingMethod::Polach
        }
        Method::Auto if ellipse && tol >= FASTSIM_FORCE_ERROR => RollingMethod::Fastsim,
        Method::Auto => RollingMethod::Exact,
        _ => {
            return Err(unsupported(
                "solver.method",
                "3D rolling is solved by the exact theory (\"fast\"), FASTSIM (\"fastsim\") or Polach's law (\"polach\")",
                "use method = \"auto\"",
            ))
        }
    };
    if method == RollingMethod::Polach && scene.outputs.field.is_some() {
        return Err(unsupported(
            "outputs.field",
            "Polach's law gives forces only, no traction distribution to compute stresses from",
            "use method = \"fastsim\" or \"fast\" for subsurface stresses under rolling",
        ));
    }
    let tolerance = if method == RollingMethod::Exact {
        tolerance_for(scene, "the exact steady-rolling solver", TOLERANCE_RANGE)?
    } else {
        tol
    };
    Ok(Tangential::Rolling(RollingStep { method, creepage, speed, tolerance, transient: None }))
}

/// Transient 3D rolling (`[motion.transient]`): the creep force `load.tangential` along
/// `load.direction` or, when a longitudinal or lateral creepage is given, those creepages
/// (the force then only acts in the shift at rest); the spin creepage; steps of one element
/// length by the fast solver.
fn transient_step(
    scene: &Scene,
    speed: f64,
    (longitudinal, lateral, spin): (f64, f64, f64),
    t: stickslip_scene::Transient,
) -> Result<Tangential, Issue> {
    if !matches!(scene.solver.method, Method::Auto | Method::Fast) {
        return Err(unsupported(
            "solver.method",
            "transient rolling is solved by the exact theory's transient form (each step a fast solve); FASTSIM, Polach and the LP have no transient form here",
            "use method = \"auto\" or \"fast\"",
        ));
    }
    let l = &scene.load;
    let d = l.direction_deg.to_radians();
    let tolerance = tolerance_for(scene, "the fast solver", FastConfig::TOLERANCE_RANGE)?;
    Ok(Tangential::Rolling(RollingStep {
        method: RollingMethod::Transient,
        creepage: Creepage { longitudinal: 0.0, lateral: 0.0, spin },
        speed,
        tolerance,
        transient: Some(TransientRecipe {
            force: (l.tangential * d.cos(), l.tangential * d.sin()),
            direction_deg: l.direction_deg,
            shift_first: t.start == stickslip_scene::TransientStart::Shift,
            distance: t.distance,
            creepage: t.creepage_control.then_some((longitudinal, lateral)),
        }),
    }))
}

/// The body of a 3D contact.
#[derive(Clone, Copy)]
enum ContactBody<'a> {
    Sphere(f64),
    Ellipsoid(Ellipse),
    Patches(&'a [Patch]),
    Surface(&'a Surface),
}

fn contact_recipe(
    scene: &Scene,
    bodies: &Bodies,
    body: ContactBody<'_>,
) -> Result<(ContactRecipe, String), Issue> {
    let l = &scene.load;
    let (sub, e_star) = (bodies.substrate, bodies.e_star);
    let force_of = || match l.normal {
        NormalLoad::Force(p) | NormalLoad::FromPatches(p) => Ok(p),
        NormalLoad::HalfWidth(_) => Err(half_width_refused()),
        NormalLoad::Approach(_) => Err(approach_refused()),
    };
    let normal = match body {
        ContactBody::Sphere(radius) => {
            let force = match l.normal {
                NormalLoad::Force(p) | NormalLoad::FromPatches(p) => p,
                NormalLoad::HalfWidth(a) => HertzSphere::load_for_contact_radius(a, radius, e_star),
                NormalLoad::Approach(_) => return Err(approach_refused()),
            };
            ContactNormal::Sphere { radius, force, e_star }
        }
        ContactBody::Ellipsoid(Ellipse::Radii { rx, ry }) => {
            ContactNormal::Ellipse { rx, ry, force: force_of()?, e_star }
        }
        ContactBody::Ellipsoid(Ellipse::SemiAxes { a, b }) => {
            ContactNormal::EllipseGiven { a, b, force: force_of()? }
        }
        ContactBody::Patches(ps) => ContactNormal::Patches(ps.to_vec()),
        ContactBody::Surface(s) => {
            let load = match l.normal {
                NormalLoad::Approach(d) => SurfaceLoad::Approach(d),
                NormalLoad::HalfWidth(_) => return Err(half_width_refused()),
                NormalLoad::Force(p) | NormalLoad::FromPatches(p) => SurfaceLoad::Force(p),
            };
            checks::periodic_surface(scene)?;
            checks::adhesion(scene, s, e_star)?;
            let tolerance =
                tolerance_for(scene, "the normal-contact solver", NormalProblem::TOLERANCE_RANGE)?;
            ContactNormal::Surface {
                surface: Box::new(s.clone()),
                load,
                tolerance,
                sweep: l.normal_sweep,
                hardness: scene.interface.hardness,
                approaches: l.approach_path.as_ref().map(stickslip_scene::ApproachPath::approaches),
                adhesion: scene.interface.adhesion,
            }
        }
    };
    let method = scene.solver.method;
    let both = l.tangential != 0.0 && l.moment != 0.0;
    let elements = lattice_elements(scene);
    // Dissimilar bodies on a surface with friction carrying a force or moment: the normal
    // and tangential problems are solved together (Dundurs coupling), with the fast solver.
    let beta = bodies.beta;
    let periodic = matches!(&normal, ContactNormal::Surface { surface, .. } if surface.boundary == SurfaceBoundary::Periodic);
    let couple = matches!(normal, ContactNormal::Surface { .. })
        && beta != 0.0
        && l.friction > 0.0
        && !l.sliding
        && (l.tangential != 0.0 || l.moment != 0.0)
        && !matches!(scene.motion, Motion::RollingCreepage { .. } | Motion::Rolling { .. })
        && method != Method::Lp;
    if couple && scene.interface.hardness.is_some() {
        return Err(unsupported(
            "interface.hardness",
            format!("a hardness cap between dissimilar bodies (Dundurs beta = {beta:.4}) with a tangential load is not solved in this version (the coupled normal-tangential solve has no cap)"),
            "remove interface.hardness, or the tangential load, or use bodies of one material",
        ));
    }
    if couple && scene.interface.adhesion.is_some() {
        return Err(unsupported(
            "interface.adhesion",
            format!("adhesion between dissimilar bodies (Dundurs beta = {beta:.4}) with a tangential load is not solved in this version (the coupled normal-tangential solve has no cohesive zone)"),
            "remove the tangential load (the adhesive normal contact of dissimilar bodies is solved), or use bodies of one material",
        ));
    }
    if couple && l.normal_sweep.is_some() {
        return Err(unsupported(
            "load.normal",
            format!("a load sweep between dissimilar bodies (Dundurs beta = {beta:.4}) with a tangential load is not solved in this version (the coupled solve runs at one load)"),
            "give one normal load, or remove the tangential load for the sweep",
        ));
    }
    let (fast, grid_reason) = if couple && method != Method::Fast {
        (
            true,
            format!("dissimilar bodies on a surface (Dundurs beta = {beta:.4}): the coupled normal-tangential solve uses the fast solver"),
        )
    } else if periodic {
        (true, "a periodic surface: the fast solver with its periodic operator".to_string())
    } else {
        grid_solver(method, elements, both)
    };
    let closed_ok = !matches!(method, Method::Lp | Method::Fast);
    let force = {
        let angle = l.direction_deg.to_radians();
        let (direction, magnitude) =
            if l.tangential < 0.0 { (angle + PI, -l.tangential) } else { (angle, l.tangential) };
        Force { signed: l.tangential, magnitude, direction }
    };
    let f = l.friction;
    let direction = force.direction;
    let grid_step = |method,
                     force: Option<Force>,
                     moment: Option<f64>|
     -> Result<Tangential, Issue> {
        let tolerance = match method {
            GridMethod::Fast => {
                tolerance_for(scene, "the fast solver", FastConfig::TOLERANCE_RANGE)?
            }
            GridMethod::Lp => tolerance_for(scene, "the modified LP", ModifiedLp::TOLERANCE_RANGE)?,
        };
        Ok(Tangential::Grid(GridStep { method, force, direction, moment, tolerance }))
    };
    let rolling = match scene.motion {
        Motion::RollingCreepage { speed, longitudinal, lateral, spin, transient: None } => {
            Some(rolling_step(scene, body, speed, Creepage { longitudinal, lateral, spin })?)
        }
        Motion::RollingCreepage { speed, longitudinal, lateral, spin, transient: Some(t) } => {
            Some(transient_step(scene, speed, (longitudinal, lateral, spin), t)?)
        }
        _ => None,
    };
    let tangential = if rolling.is_some() {
        rolling
    } else if f > 0.0 && (l.tangential != 0.0 || l.sliding || l.moment != 0.0) {
        Some(if l.sliding {
            Tangential::Sliding { angle: l.direction_deg.to_radians() }
        } else if l.tangential == 0.0 {
            // a moment alone
            match body {
                ContactBody::Sphere(_) if closed_ok => Tangential::Lubkin { moment: l.moment },
                _ if fast => grid_step(GridMethod::Fast, None, Some(l.moment))?,
                _ => grid_step(GridMethod::Lp, None, Some(l.moment))?,
            }
        } else {
            match body {
                ContactBody::Sphere(_) if closed_ok && !both => Tangential::Mindlin { force },
                ContactBody::Ellipsoid(_) if closed_ok && !both && along_axis(l.direction_deg) => {
                    // along x when the direction is within 45 degrees of the x axis
                    let d = l.direction_deg.rem_euclid(180.0);
                    Tangential::Cattaneo { force, along_x: d.min(180.0 - d) < 45.0 }
                }
                _ if fast => {
                    grid_step(GridMethod::Fast, Some(force), (l.moment != 0.0).then_some(l.moment))?
                }
                _ => grid_step(GridMethod::Lp, Some(force), None)?,
            }
        })
    } else {
        None
    };
    let history = match &l.history {
        Some(h) => Some(history_recipe(scene, h, &normal)?),
        None => None,
    };
    let lattice_output = scene.outputs.surface
        || matches!(tangential, Some(Tangential::Grid(_) | Tangential::Rolling(_)))
        || history.is_some()
        || scene.outputs.field.is_some();
    let cycle =
        scene.outputs.cycle.map(|c| CycleRecipe { amplitude: c.amplitude, points: c.points });
    let field = match scene.outputs.field {
        Some(grid) => {
            let frictionless = tangential.is_none();
            let sliding = match tangential {
                Some(Tangential::Sliding { angle }) => Some(angle),
                _ => None,
            };
            let method = match (&normal, frictionless, sliding) {
                _ if scene.solver.method == Method::Fast || history.is_some() => {
                    ContactFieldMethod::Lattice
                }
                (ContactNormal::Sphere { .. }, true, _) => ContactFieldMethod::HertzSphere,
                (
                    ContactNormal::Sphere { .. }
                    | ContactNormal::Ellipse { .. }
                    | ContactNormal::EllipseGiven { .. },
                    false,
                    Some(angle),
                ) => ContactFieldMethod::HertzSliding { friction: f, angle },
                (ContactNormal::Ellipse { .. } | ContactNormal::EllipseGiven { .. }, true, _) => {
                    ContactFieldMethod::HertzEllipse
                }
                _ => ContactFieldMethod::Lattice,
            };
            checks::field_box(bodies, &normal, grid)?;
            Some(ContactField { grid, method, nu: sub.poisson_ratio() })
        }
        None => None,
    };
    Ok((
        ContactRecipe {
            normal,
            bodies: *bodies,
            grid: scene.solver.grid,
            friction: f,
            tangential,
            cycle,
            history,
            lattice_output,
            field,
            coupling: (couple
                && matches!(
                    tangential,
                    Some(Tangential::Grid(GridStep { method: GridMethod::Fast, .. }))
                ))
            .then_some(beta),
        },
        grid_reason,
    ))
}

/// The recipe of a load path: the fast solver (no other solver takes a path), a free
/// boundary (the history has no periodic operator), the normal load per corner.
fn history_recipe(
    scene: &Scene,
    h: &stickslip_scene::History,
    normal: &ContactNormal,
) -> Result<HistoryRecipe, Issue> {
    if !matches!(scene.solver.method, Method::Auto | Method::Fast) {
        return Err(unsupported(
            "solver.method",
            "a load path is solved by the fast solver, step by step",
            "use method = \"auto\" or \"fast\"",
        ));
    }
    if let ContactNormal::Surface { surface, .. } = normal {
        if surface.boundary == SurfaceBoundary::Periodic && h.moment.is_some() {
            return Err(unsupported(
                "load.history.moment",
                "a moment on a periodic surface is not solved (a rotation is not periodic)",
                "remove load.history.moment, or use geometry.boundary = \"free\"",
            ));
        }
    }
    let constant = match scene.load.normal {
        NormalLoad::Force(p) | NormalLoad::FromPatches(p) => p,
        // validation refuses a path under anything but a normal force
        _ => return Err(half_width_refused()),
    };
    Ok(HistoryRecipe {
        control: h.control,
        direction: scene.load.direction_deg.to_radians(),
        tangential: h.tangential.clone(),
        normal: (0..h.tangential.len()).map(|i| h.normal_at(i, constant)).collect(),
        moment: h.moment.clone(),
        steps: h.steps,
        source: h.source.clone(),
        tolerance: tolerance_for(scene, "the fast solver", FastConfig::TOLERANCE_RANGE)?,
    })
}
