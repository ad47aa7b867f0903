//! Refusals before anything is computed: the combinations no solver handles
//! ([`refuse`]), the tolerance each solver supports ([`tolerance_for`]) and the capacity
//! checks that need the contact size ([`capacity`]).

use stickslip_halfspace::hertz::{HertzLine, HertzSphere};
use stickslip_traction::closed::Lubkin;

use super::bodies;
use super::recipe::{Bodies, ContactNormal};
use super::refusal::{invalid, issue, unsupported};
use super::Issue;
use stickslip_scene::eng::eng;
use stickslip_scene::{ErrorKind, FieldGrid, FieldScale};
use stickslip_scene::{
    Geometry, Indenter, Method, Motion, NormalLoad, Scene, Substrate, SurfaceBoundary,
};

/// `solver.tolerance` if `what` supports it, else a refusal naming the supported range
/// (tolerances are never clamped).
pub(crate) fn tolerance_for(scene: &Scene, what: &str, range: (f64, f64)) -> Result<f64, Issue> {
    let t = scene.solver.tolerance;
    if t >= range.0 && t <= range.1 {
        Ok(t)
    } else {
        Err(issue(
            ErrorKind::OutOfRange,
            "solver.tolerance",
            format!("tolerance {t:e} is outside what {what} supports"),
            format!("use a tolerance in [{:e}, {:e}], e.g. 1e-10", range.0, range.1),
        ))
    }
}

/// The lattice of a patch scene must resolve every patch: each patch holds element
/// centres, no element belongs to two patches, and the lattice's normal force (pressure
/// times the cells whose centres lie in a patch) is within
/// [`crate::patches::LATTICE_AREA_TOLERANCE`] of the patches' force. Otherwise the refusal
/// names the smallest grid found that does.
pub(crate) fn lattice(scene: &Scene) -> Result<(), Issue> {
    use crate::patches::LATTICE_AREA_TOLERANCE as TOL;
    let Geometry::Patches(ps) = &scene.geometry else { return Ok(()) };
    let patches = crate::patches::grid_patches(ps);
    let (lo, hi) = stickslip_scene::patch_bounds(ps);
    let force: f64 = ps.iter().map(stickslip_scene::Patch::force).sum();
    // Relative error of the lattice force at `n` elements across the largest extent, or
    // None when the lattice cannot hold the patches (empty or overlapping cells).
    let error = |n: usize| -> Option<f64> {
        let h = (hi[0] - lo[0]).max(hi[1] - lo[1]) / n as f64;
        let grid =
            stickslip_lattice::ContactGrid::from_patches(h, h, (lo[0], lo[1]), &patches).ok()?;
        Some((grid.total_normal_force() - force).abs() / force)
    };
    let n = scene.solver.grid;
    let err = error(n);
    if err.is_some_and(|e| e <= TOL) {
        return Ok(());
    }
    // The error of a lattice falls roughly as 1/n: start from that estimate, then double.
    let mut m = match err {
        Some(e) => ((n as f64 * e / TOL).ceil() as usize).max(n + 1),
        None => 2 * n,
    };
    let mut found = None;
    while m <= 4096 {
        if error(m).is_some_and(|e| e <= TOL) {
            found = Some(m);
            break;
        }
        m = m + m / 2 + 1;
    }
    let what = match err {
        Some(e) => format!(
            "grid = {n} covers the patches with a lattice whose normal force is {:.1} % off the patches' force (allowed {:.0} %)",
            100.0 * e,
            100.0 * TOL
        ),
        None => format!("grid = {n} is too coarse for the patches: a patch holds no element centre, or two patches share one"),
    };
    Err(issue(
        ErrorKind::OutOfRange,
        "solver.grid",
        what,
        match found {
            Some(m) => format!("use solver.grid >= {m}"),
            None => "the patches are too small for any lattice up to 4096 elements per side; enlarge them or split the scene".to_string(),
        },
    ))
}

/// A twisting moment on an ellipse or patches against the contact's full-slip moment about
/// the centre of pressure on the lattice (`ContactGrid::spin_capacity`, an upper bound of
/// the torsional capacity): above it the contact spins and no solver can carry the moment.
pub(crate) fn spin(scene: &Scene, bodies: &Bodies) -> Result<(), Issue> {
    use stickslip_lattice::ContactGrid;
    let l = &scene.load;
    if l.moment == 0.0 || l.friction <= 0.0 {
        return Ok(());
    }
    let n = scene.solver.grid;
    let grid = match &scene.geometry {
        Geometry::Ellipsoid(e) => {
            let NormalLoad::Force(p) = l.normal else { return Ok(()) };
            let (a, b) = match *e {
                stickslip_scene::Ellipse::SemiAxes { a, b } => (a, b),
                stickslip_scene::Ellipse::Radii { rx, ry } => {
                    let Ok(h) =
                        stickslip_halfspace::hertz::HertzEllipse::new(rx, ry, p, bodies.e_star)
                    else {
                        return Ok(());
                    };
                    (h.semi_axis_x(), h.semi_axis_y())
                }
            };
            ContactGrid::hertz_ellipse(a, b, p, n, n)
        }
        Geometry::Sphere { radius } if l.tangential != 0.0 => {
            let NormalLoad::Force(p) = l.normal else { return Ok(()) };
            let Ok(h) = HertzSphere::new(p, *radius, bodies.e_star) else {
                return Ok(());
            };
            ContactGrid::hertz_circle(h.contact_radius(), p, n)
        }
        Geometry::Patches(ps) => {
            let (lo, hi) = stickslip_scene::patch_bounds(ps);
            let h = (hi[0] - lo[0]).max(hi[1] - lo[1]) / n as f64;
            ContactGrid::from_patches(h, h, (lo[0], lo[1]), &crate::patches::grid_patches(ps))
        }
        _ => return Ok(()),
    };
    let Ok(grid) = grid else { return Ok(()) };
    let cap = grid.spin_capacity(l.friction);
    if l.moment.abs() > cap {
        return Err(issue(
            ErrorKind::Impossible,
            "load.moment",
            format!(
                "|M| = {} exceeds the full-slip moment of the contact about its centre of pressure, {}: the contact spins",
                eng(l.moment.abs(), "N m"),
                eng(cap, "N m")
            ),
            format!("reduce the moment below {} (less when a tangential force acts too)", eng(cap, "N m")),
        ));
    }
    if l.tangential != 0.0 && !l.sliding {
        // Together a force and a moment are carried only inside the limit surface of the
        // contact's friction; beyond it the solver would run out of stick mid-way.
        let d = l.direction_deg.to_radians();
        let t = (l.tangential * d.cos(), l.tangential * d.sin());
        let lambda = grid.load_capacity_factor(l.friction, t, l.moment);
        if lambda < 1.0 {
            return Err(issue(
                ErrorKind::Impossible,
                "load.moment",
                format!(
                    "the tangential force {} and the moment {} together exceed what friction carries on this contact: at most {lambda:.4} times this combination can be carried before the contact slides (gross slip, found on the lattice of solver.grid = {n})",
                    eng(l.tangential, "N"), eng(l.moment, "N m")
                ),
                format!("scale load.tangential and load.moment by less than {lambda:.4}, or reduce one of them"),
            ));
        }
    }
    Ok(())
}

/// Normal load implied by a prescribed contact size, where the geometry fixes it.
fn implied_load(scene: &Scene, bodies: &Bodies) -> Option<f64> {
    let a = match scene.load.normal {
        NormalLoad::HalfWidth(a) => a,
        NormalLoad::Force(p) | NormalLoad::FromPatches(p) => return Some(p),
        NormalLoad::Approach(_) => return None,
    };
    match (&scene.geometry, scene.substrate) {
        (Geometry::Cylinder { radius }, Substrate::Graded { k, .. }) if k > 0.0 => {
            let m = bodies.graded?;
            stickslip_graded::load_from_half_width(&m, *radius, a).ok()
        }
        (Geometry::Cylinder { radius }, _) => {
            HertzLine::from_half_width(a, *radius, bodies.e_star).ok().map(|h| h.load())
        }
        (Geometry::Sphere { radius }, _) => {
            Some(HertzSphere::load_for_contact_radius(a, *radius, bodies.e_star))
        }
        _ => None,
    }
}

/// Checks that need the contact solved in closed form: T > fP when the load is given as a
/// half-width, Lubkin's gross-slip moment.
pub(crate) fn capacity(scene: &Scene, bodies: &Bodies) -> Result<(), Issue> {
    let l = &scene.load;
    let Some(p) = implied_load(scene, bodies) else { return Ok(()) };
    if let NormalLoad::HalfWidth(_) = l.normal {
        if !l.sliding && l.tangential.abs() > l.friction * p {
            return Err(issue(
                ErrorKind::Impossible,
                "load.tangential",
                format!(
                    "|T| = {} exceeds f P = {} (P = {} implied by the half-width): the contact slides, partial slip is impossible",
                    eng(l.tangential.abs(), "N/m"),
                    eng(l.friction * p, "N/m"),
                    eng(p, "N/m")
                ),
                "reduce T below f P, or set sliding = true",
            ));
        }
    }
    if let (Geometry::Sphere { radius }, true) = (&scene.geometry, l.moment != 0.0) {
        let Ok(h) = HertzSphere::new(p, *radius, bodies.e_star) else {
            return Ok(());
        };
        let mmax = Lubkin::gross_slip_moment_of(h.contact_radius(), p, l.friction);
        if l.moment.abs() > mmax {
            return Err(issue(
                ErrorKind::Impossible,
                "load.moment",
                format!(
                    "|M| = {} exceeds the gross-slip moment 3 pi f P a / 16 = {}: the contact spins",
                    eng(l.moment.abs(), "N m"),
                    eng(mmax, "N m")
                ),
                "reduce the moment below 3 pi f P a / 16 (Lubkin)",
            ));
        }
    }
    Ok(())
}

/// The combinations no solver handles, refused with the key to change and a hint.
#[allow(clippy::too_many_lines)]
pub(crate) fn refuse(scene: &Scene) -> Result<(), Issue> {
    let g = &scene.geometry;
    let l = &scene.load;
    let method = scene.solver.method;
    let two_d = g.is_2d();
    let rolling = matches!(scene.motion, Motion::Rolling { .. });
    let graded_k = match scene.substrate {
        Substrate::Graded { k, .. } => Some(k),
        _ => None,
    };
    let grading = graded_k.is_some_and(|k| k > 0.0);
    let visco = match scene.substrate {
        Substrate::Viscoelastic { alpha, beta, .. } => Some(alpha != beta),
        _ => None,
    };

    // ---- combinations no solver handles -------------------------------------------------
    if method == Method::Fast && (two_d || rolling) {
        return Err(unsupported(
            "solver.method",
            "the fast solver works on 3D contact grids (sphere, ellipsoid, patches); 2D and rolling contacts use closed forms or quadrature",
            "use method = \"auto\", \"closed-form\" or \"quadrature\"",
        ));
    }
    if visco == Some(true) && !rolling {
        return Err(unsupported(
            "substrate.model",
            "a viscoelastic substrate is solved in steady rolling (Goryacheva 1973); static viscoelastic indentation is not",
            "add [motion] kind = \"rolling\" with a speed, or use model = \"homogeneous\" with the relaxed modulus",
        ));
    }
    if graded_k.is_some() && !matches!(g, Geometry::Cylinder { .. }) {
        return Err(unsupported(
            "geometry.kind",
            "the graded substrate is solved for a rigid cylinder (seed 000, G&P 2000)",
            "use geometry.kind = \"cylinder\", or a homogeneous substrate",
        ));
    }
    if graded_k.is_some() && scene.indenter != Indenter::Rigid {
        return Err(unsupported(
            "indenter.model",
            "the graded-substrate solution (FORMULAS.md A4) is for a rigid cylinder",
            "use [indenter] model = \"rigid\"",
        ));
    }
    if rolling {
        if graded_k.is_some() {
            return Err(unsupported(
                "motion.kind",
                "rolling is solved for homogeneous (Carter) and viscoelastic (Goryacheva) bodies, not graded ones",
                "use motion.kind = \"static\", or a homogeneous / viscoelastic substrate",
            ));
        }
        if !matches!(g, Geometry::Cylinder { .. }) {
            return Err(unsupported(
                "geometry.kind",
                "rolling needs a cylinder",
                "use geometry.kind = \"cylinder\"",
            ));
        }
        if !bodies::identical(scene) {
            return Err(unsupported(
                "indenter.model",
                "Carter and Goryacheva solve a cylinder rolling on a base of the same material",
                "use [indenter] model = \"same\"",
            ));
        }
        if !matches!(l.normal, NormalLoad::Force(_)) {
            return Err(unsupported(
                "load.half_width",
                "rolling takes the normal load; the contact length follows from it",
                "give load.normal = P (N/m)",
            ));
        }
        if l.tangential != 0.0 || l.sliding {
            return Err(issue(
                ErrorKind::Impossible,
                "load.tangential",
                "in steady rolling the tangential force follows from the creep; it cannot also be prescribed",
                "remove load.tangential / load.sliding and set motion.creep",
            ));
        }
        if l.friction <= 0.0 {
            return Err(issue(
                ErrorKind::Impossible,
                "load.friction",
                "rolling with stick and slip needs a friction coefficient",
                "give load.friction > 0",
            ));
        }
        if scene.outputs.field.is_some() {
            return Err(unsupported(
                "outputs.field",
                "subsurface fields are not computed for rolling contacts in this version",
                "remove outputs.field",
            ));
        }
        if matches!(method, Method::Lp) {
            return Err(unsupported(
                "solver.method",
                "the LP is a 3D grid solver; rolling uses Carter or Goryacheva",
                "use method = \"auto\"",
            ));
        }
        if method == Method::ClosedForm && visco == Some(true) {
            return Err(unsupported(
                "solver.method",
                "viscoelastic rolling has no closed form (Goryacheva's eqs 19 and 24 are solved numerically)",
                "use method = \"auto\" or \"quadrature\"",
            ));
        }
    }
    if scene.outputs.cycle.is_some() {
        if !matches!(g, Geometry::Sphere { .. }) {
            return Err(unsupported(
                "outputs.cycle",
                "the Mindlin-Deresiewicz cycle is solved for a sphere (Hertz circle)",
                "use geometry.kind = \"sphere\", or remove outputs.cycle",
            ));
        }
        if l.friction <= 0.0 {
            return Err(issue(
                ErrorKind::Impossible,
                "load.friction",
                "a loading cycle needs friction",
                "give load.friction > 0",
            ));
        }
        if l.sliding {
            return Err(issue(
                ErrorKind::Impossible,
                "load.sliding",
                "a loading cycle below gross slip cannot be combined with full sliding",
                "set sliding = false",
            ));
        }
    }
    if two_d {
        if matches!(method, Method::Lp) {
            return Err(unsupported(
                "solver.method",
                "the LP is a 3D grid solver; 2D contacts use closed forms or quadrature",
                "use method = \"auto\", \"closed-form\" or \"quadrature\"",
            ));
        }
        if matches!(g, Geometry::Punch { .. }) && l.tangential != 0.0 {
            return Err(unsupported(
                "load.tangential",
                "partial slip under a flat punch is not solved in this version",
                "use sliding = true (q = f p), or a cylinder",
            ));
        }
    } else {
        if l.tangential != 0.0
            && l.moment != 0.0
            && matches!(method, Method::Lp | Method::ClosedForm)
        {
            return Err(unsupported(
                "load.moment",
                "a tangential force and a twisting moment together have no closed form, and the LP takes one load mode",
                "use method = \"fast\" (or \"auto\"), or give either load.tangential or load.moment",
            ));
        }
        if l.sliding && l.moment != 0.0 {
            return Err(issue(ErrorKind::Impossible, "load.moment", "with sliding = true the traction is q = f p along the sliding direction; a moment cannot also be prescribed", "remove load.moment or sliding"));
        }
        if l.moment != 0.0 && l.friction <= 0.0 {
            return Err(issue(
                ErrorKind::Impossible,
                "load.moment",
                "a twisting moment on a frictionless contact cannot be carried",
                "give load.friction > 0",
            ));
        }
        if method == Method::Quadrature && (l.tangential != 0.0 || l.moment != 0.0) {
            return Err(unsupported(
                "solver.method",
                "3D partial slip is solved by closed forms or grid solvers (LP, fast), not by quadrature",
                "use method = \"auto\", \"closed-form\", \"lp\" or \"fast\"",
            ));
        }
    }
    if method == Method::ClosedForm {
        if grading {
            return Err(unsupported(
                "solver.method",
                "a graded substrate's displacements and stresses have no closed form; they are integrated numerically",
                "use method = \"auto\" or \"quadrature\"",
            ));
        }
        if matches!(g, Geometry::Patches(_)) && (l.tangential != 0.0 || l.moment != 0.0) {
            return Err(unsupported(
                "solver.method",
                "patches under a tangential load have no closed form",
                "use method = \"auto\", \"lp\" or \"fast\"",
            ));
        }
        if matches!(g, Geometry::Ellipsoid(_)) && l.moment != 0.0 {
            return Err(unsupported(
                "solver.method",
                "twisting an ellipse has no closed form",
                "use method = \"auto\", \"lp\" or \"fast\"",
            ));
        }
        if matches!(g, Geometry::Ellipsoid(_))
            && l.tangential != 0.0
            && !along_axis(l.direction_deg)
        {
            return Err(unsupported(
                "solver.method",
                "Cattaneo's closed form needs the load along an axis of the ellipse",
                "use direction_deg = 0 or 90, or method = \"auto\"",
            ));
        }
        if matches!(g, Geometry::Punch { .. }) && scene.outputs.field.is_some() {
            return Err(unsupported(
                "solver.method",
                "the flat-punch field is integrated numerically here",
                "use method = \"auto\"",
            ));
        }
    }
    Ok(())
}

/// What a periodic surface cannot carry: a tangential force goes through the fast solver's
/// periodic operator; a moment (a rotation is not periodic), sliding, rolling and the modified
/// LP (no periodic images) are refused.
pub(crate) fn periodic_surface(scene: &Scene) -> Result<(), Issue> {
    let periodic =
        matches!(&scene.geometry, Geometry::Surface(s) if s.boundary == SurfaceBoundary::Periodic);
    let l = &scene.load;
    if periodic && l.friction > 0.0 {
        if l.moment != 0.0 {
            return Err(unsupported(
                "load.moment",
                "a twisting moment on a periodic surface has no meaning (a rigid rotation is not periodic)",
                "use boundary = \"free\" for an isolated contact under a moment, or remove load.moment",
            ));
        }
        if l.sliding
            || matches!(scene.motion, Motion::RollingCreepage { .. } | Motion::Rolling { .. })
        {
            return Err(unsupported(
                "geometry.boundary",
                "sliding and rolling on a periodic surface are not solved in this version",
                "use boundary = \"free\", or a tangential force below the friction limit",
            ));
        }
        if l.tangential != 0.0 && scene.solver.method == Method::Lp {
            return Err(unsupported(
                "solver.method",
                "the modified LP solves isolated contacts only (no periodic images)",
                "use solver.method = \"fast\" or \"auto\" on a periodic surface",
            ));
        }
    }
    Ok(())
}

/// How far from the contact a field box may reach, in contact semi-axes.
pub const MAX_FIELD_REACH: f64 = 10.0;

/// A 3D field box must stay within [`MAX_FIELD_REACH`] contact semi-axes of the contact
/// (in plane and in depth): beyond, the stresses are the far field of a point load and a
/// lattice over the box would be mostly empty.
pub(crate) fn field_box(
    bodies: &Bodies,
    normal: &ContactNormal,
    grid: FieldGrid,
) -> Result<(), Issue> {
    let e_star = bodies.e_star;
    let (ax, ay) = match normal {
        ContactNormal::Sphere { radius, force, e_star } => {
            let a = HertzSphere::new(*force, *radius, *e_star)
                .map_err(|e| invalid("load.normal", e))?
                .contact_radius();
            (a, a)
        }
        ContactNormal::Ellipse { rx, ry, force, .. } => {
            let h = stickslip_halfspace::hertz::HertzEllipse::new(*rx, *ry, *force, e_star)
                .map_err(|e| invalid("load.normal", e))?;
            (h.semi_axis_x(), h.semi_axis_y())
        }
        ContactNormal::EllipseGiven { a, b, .. } => (*a, *b),
        ContactNormal::Patches(ps) => {
            let (lo, hi) = stickslip_scene::patch_bounds(ps);
            (0.5 * (hi[0] - lo[0]), 0.5 * (hi[1] - lo[1]))
        }
        ContactNormal::Surface { surface, .. } => (0.5 * surface.size[0], 0.5 * surface.size[1]),
    };
    let unit = match grid.scale {
        FieldScale::HalfWidth => ax,
        FieldScale::Metres => 1.0,
    };
    let reach = MAX_FIELD_REACH * ax.max(ay);
    let far = |v: f64| (v * unit).abs() > reach;
    let z = grid.z.unwrap_or((0.0, 0.0, 1));
    for (key, (lo, hi, _)) in
        [("outputs.field.x", grid.x), ("outputs.field.y", grid.y), ("outputs.field.z", z)]
    {
        if far(lo) || far(hi) {
            return Err(issue(
                ErrorKind::OutOfRange,
                key,
                format!(
                    "the box reaches {} from the contact centre; the contact's largest semi-axis is {}",
                    eng((lo * unit).abs().max((hi * unit).abs()), "m"),
                    eng(ax.max(ay), "m")
                ),
                format!("keep the box within {MAX_FIELD_REACH} semi-axes of the contact (scale = \"a\" measures in the semi-axis a along x)"),
            ));
        }
    }
    Ok(())
}

/// Whether an ellipse load direction lies along one of the axes (the Cattaneo closed form).
pub(crate) fn along_axis(deg: f64) -> bool {
    let r = deg.rem_euclid(90.0);
    r.min(90.0 - r) < 1e-9
}

/// The dimensionless size of the contact, refused outside the range where a half-space
/// contact in f64 is meaningful (`stickslip_scene::ranges`): the Hertz contact size over
/// the radius of curvature, $a/R$, for curved bodies, and the mean pressure over the
/// composite modulus, $\bar p/E^*$, for flat ones. Each scale is the closed form of the
/// geometry (for a surface, that of its smooth profile), so it is known before solving.
pub(crate) fn magnitudes(scene: &Scene, bodies: &Bodies) -> Result<(), Issue> {
    use stickslip_scene::ranges::{CONTACT_OVER_RADIUS, PRESSURE_OVER_MODULUS};
    use stickslip_scene::{Ellipse, Profile};
    let es = bodies.e_star;
    let load_key = match scene.load.normal {
        _ if matches!(scene.geometry, Geometry::Patches(_)) => "geometry.patches",
        NormalLoad::HalfWidth(_) => "load.half_width",
        NormalLoad::Approach(_) => "load.approach",
        _ => "load.normal",
    };
    let sphere_a = |p: f64, r: f64| (3.0 * p * r / (4.0 * es)).cbrt();
    let line_a = |p: f64, r: f64| (4.0 * p * r / (std::f64::consts::PI * es)).sqrt();
    // (a/R, R) or (p/E*, the length it is the pressure of): None when neither applies.
    enum Measure {
        Curved { ratio: f64, what: String },
        Flat { ratio: f64, what: String },
    }
    // An approach path is measured at its deepest corner; one that never presses (an
    // adhesive contact held apart) has no contact size to check.
    let normal = match &scene.load.approach_path {
        Some(p) => NormalLoad::Approach(p.deepest()),
        None => scene.load.normal,
    };
    if matches!(normal, NormalLoad::Approach(d) if d <= 0.0) {
        return Ok(());
    }
    let m = match (&scene.geometry, normal) {
        (Geometry::Cylinder { radius }, NormalLoad::HalfWidth(a)) => Some(Measure::Curved {
            ratio: a / radius,
            what: format!("a/R with R = {}", eng(radius.abs(), "m")),
        }),
        (Geometry::Cylinder { radius }, NormalLoad::Force(p)) => {
            let a = match bodies.graded {
                Some(g) => stickslip_graded::half_width_from_load(&g, *radius, p)
                    .map_err(|e| invalid("load.normal", e))?,
                None => line_a(p, *radius),
            };
            Some(Measure::Curved {
                ratio: a / radius,
                what: format!("a/R with R = {}", eng(radius.abs(), "m")),
            })
        }
        (Geometry::Sphere { radius }, NormalLoad::HalfWidth(a)) => Some(Measure::Curved {
            ratio: a / radius,
            what: format!("a/R with R = {}", eng(radius.abs(), "m")),
        }),
        (Geometry::Sphere { radius }, NormalLoad::Force(p)) => Some(Measure::Curved {
            ratio: sphere_a(p, *radius) / radius,
            what: format!("a/R with R = {}", eng(radius.abs(), "m")),
        }),
        (Geometry::Ellipsoid(Ellipse::Radii { rx, ry }), NormalLoad::Force(p)) => {
            let re = (rx * ry).sqrt();
            Some(Measure::Curved {
                ratio: sphere_a(p, re) / rx.min(*ry),
                what: format!(
                    "a/R with a the equivalent sphere's and R = min(Rx, Ry) = {}",
                    eng(rx.min(*ry), "m")
                ),
            })
        }
        (Geometry::Ellipsoid(Ellipse::SemiAxes { a, b }), NormalLoad::Force(p)) => {
            Some(Measure::Flat {
                ratio: p / (std::f64::consts::PI * a * b) / es,
                what: "P/(pi a b E*)".to_string(),
            })
        }
        (Geometry::Punch { half_width }, NormalLoad::Force(p)) => Some(Measure::Flat {
            ratio: p / (2.0 * half_width) / es,
            what: "P/(2 b E*)".to_string(),
        }),
        (Geometry::Patches(ps), _) => {
            let p = ps.iter().map(|q| q.pressure).fold(0.0, f64::max);
            Some(Measure::Flat {
                ratio: p / es,
                what: "the largest patch pressure over E*".to_string(),
            })
        }
        (Geometry::Surface(s), n) => {
            let area = s.size[0] * s.size[1];
            let side = s.size[0].min(s.size[1]);
            match (s.profile, n) {
                (Profile::Sphere { radius }, NormalLoad::Force(p)) => Some(Measure::Curved {
                    ratio: sphere_a(p, radius) / radius,
                    what: format!("a/R with R = {}", eng(radius.abs(), "m")),
                }),
                (Profile::Sphere { radius }, NormalLoad::Approach(d)) => Some(Measure::Curved {
                    ratio: (radius * d).sqrt() / radius,
                    what: format!("a/R = sqrt(d/R) with R = {}", eng(radius.abs(), "m")),
                }),
                (Profile::Ellipsoid { radii }, NormalLoad::Force(p)) => {
                    let r = radii[0].min(radii[1]);
                    Some(Measure::Curved {
                        ratio: sphere_a(p, (radii[0] * radii[1]).sqrt()) / r,
                        what: format!("a/R with R = min(radii) = {}", eng(r, "m")),
                    })
                }
                (Profile::Ellipsoid { radii }, NormalLoad::Approach(d)) => {
                    let r = radii[0].min(radii[1]);
                    Some(Measure::Curved {
                        ratio: (d / r).sqrt(),
                        what: format!("a/R = sqrt(d/R) with R = min(radii) = {}", eng(r, "m")),
                    })
                }
                (Profile::Cylinder { radius, length, .. }, NormalLoad::Force(p)) => {
                    Some(Measure::Curved {
                        ratio: line_a(p / length, radius) / radius,
                        what: format!(
                            "a/R with R = {} (load per roller length)",
                            eng(radius.abs(), "m")
                        ),
                    })
                }
                (Profile::Punch { radius, .. }, NormalLoad::Force(p)) => Some(Measure::Flat {
                    ratio: p / (std::f64::consts::PI * radius * radius) / es,
                    what: "P/(pi a^2 E*)".to_string(),
                }),
                // Boussinesq: the mean pressure of a punch pressed by d is 2 E* d/(pi a).
                (Profile::Punch { radius, .. }, NormalLoad::Approach(d)) => Some(Measure::Flat {
                    ratio: 2.0 * d / (std::f64::consts::PI * radius),
                    what: "2 d/(pi a), the mean pressure over E* (Boussinesq)".to_string(),
                }),
                (_, NormalLoad::Force(p)) => Some(Measure::Flat {
                    ratio: p / area / es,
                    what: "the load over the lattice area over E*".to_string(),
                }),
                (_, NormalLoad::Approach(d)) => Some(Measure::Flat {
                    ratio: d / side,
                    what: "the approach over the lattice side".to_string(),
                }),
                _ => None,
            }
        }
        _ => None,
    };
    let (ratio, what, (lo, hi), why) = match m {
        None => return Ok(()),
        Some(Measure::Curved { ratio, what }) => (
            ratio,
            what,
            CONTACT_OVER_RADIUS,
            "above 0.3 the contact is not a small-strain Hertz contact (the parabolic gap errs by over 2 % at its edge); below 1e-6 the indentation is under 1e-12 of the radius, beyond the digits of double precision",
        ),
        Some(Measure::Flat { ratio, what }) => (
            ratio,
            what,
            PRESSURE_OVER_MODULUS,
            "above 0.1 the strains are beyond linear elasticity; below 1e-12 the surface displacements are beyond the digits of double precision relative to the contact size",
        ),
    };
    if ratio.is_finite() && (lo..=hi).contains(&ratio) {
        return Ok(());
    }
    Err(issue(
        ErrorKind::OutOfRange,
        load_key,
        format!(
            "the contact's dimensionless size {what} is {ratio:.3e}, outside the range verified in double precision, {lo:e} to {hi:e} (E* = {})",
            eng(es, "Pa")
        ),
        format!("change the load, the radius or the moduli to bring it inside: {why}"),
    ))
}

/// Adhesion on a surface (`interface.adhesion`): the adhesive stress $w/h_0$ within linear
/// elasticity (at most 0.1 E*, as a contact pressure); the range resolved by the lattice
/// (no step of the initial gap between neighbouring cells within reach of the range larger
/// than the range: a zone narrower than a cell does not let go, and the pull-off would be
/// the lattice's); friction stages are not posed on an adhesive contact in this version.
pub(crate) fn adhesion(
    scene: &Scene,
    s: &stickslip_scene::Surface,
    e_star: f64,
) -> Result<(), Issue> {
    let Some(a) = scene.interface.adhesion else { return Ok(()) };
    let s0 = a.work / a.range;
    let hi = stickslip_scene::ranges::PRESSURE_OVER_MODULUS.1;
    if s0 > hi * e_star {
        return Err(issue(
            ErrorKind::OutOfRange,
            "interface.adhesion",
            format!(
                "the adhesive stress w/h0 = {} is {:.3} E* (E* = {}), above the {hi} of linear elasticity",
                eng(s0, "Pa"),
                s0 / e_star,
                eng(e_star, "Pa")
            ),
            format!("a longer range or a smaller work: w/h0 at most {}", eng(hi * e_star, "Pa")),
        ));
    }
    let l = &scene.load;
    if l.sliding
        || !matches!(scene.motion, Motion::Static)
        || scene.outputs.cycle.is_some()
        || scene.outputs.field.is_some()
    {
        return Err(unsupported(
            "interface.adhesion",
            "sliding, rolling or a Mindlin cycle on an adhesive contact, and the subsurface field under it, are not posed by scenes in this version (a static tangential load or moment is: it acts at the last point of the approach path)",
            "remove sliding, motion, outputs.cycle and outputs.field, or pose a static load.tangential or load.moment instead",
        ));
    }
    let deepest = match (&l.approach_path, l.normal) {
        (Some(p), _) => p.deepest(),
        (None, NormalLoad::Approach(d)) => d,
        _ => return Ok(()),
    };
    let [nx, ny] = s.cells;
    let gap = s.initial_gap();
    let step = stickslip_scene::HeightStep::of(
        &gap,
        nx,
        ny,
        s.boundary == SurfaceBoundary::Periodic,
        deepest,
        a.range,
    );
    if step.step > a.range {
        let f = step.step / a.range;
        let need = |n: usize| ((n as f64 * f).ceil() as usize).next_power_of_two();
        return Err(issue(
            ErrorKind::OutOfRange,
            "interface.adhesion.range",
            format!(
                "the range {} is shorter than the step of the initial gap between neighbouring cells where the surfaces come within range ({} at cell ({}, {}), {} cells within reach at the deepest approach {}): the cohesive zone would be narrower than a cell, and the contact would not let go where the continuum lets go",
                eng(a.range, "m"),
                eng(step.step, "m"),
                step.cell.0,
                step.cell.1,
                step.cells_in_reach,
                eng(deepest, "m")
            ),
            format!(
                "a lattice of at least {} x {} cells over the same size (geometry.cells; for a smooth profile the step falls with the cell), a smaller geometry.size, or a longer range",
                need(nx),
                need(ny)
            ),
        ));
    }
    Ok(())
}
