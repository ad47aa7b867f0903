//! Validation of a typed [`Scene`]: every range and every combination a scene must satisfy
//! before planning, in one place, whichever way the scene was built (TOML or the builder).
//!
//! Each refusal is an [`Issue`] naming the full dotted key (`geometry.patches[2].side`),
//! what was found, what is allowed and a hint; [`Scene::locate`] turns it into a
//! [`SceneError`](crate::SceneError) with the file, line and column when the scene came
//! from a file. The checks run in the order of the scene format (geometry, substrate,
//! indenter, load, motion, outputs, solver), so the first problem of a file is reported.

use super::ranges::{self, Range};
use super::{
    Cycle, Elastic, Ellipse, FieldGrid, Geometry, History, HistoryControl, Indenter, Motion,
    NormalLoad, Outputs, Patch, PatchShape, Scene, SolverOptions, Substrate, MAX_GRID,
};
use crate::eng::{eng, eng_beside};
use crate::error::{ErrorKind, Issue};

mod interface;

/// Every check of `scene`; the first refusal.
pub(crate) fn validate(scene: &Scene) -> Result<(), Issue> {
    geometry(&scene.geometry)?;
    substrate(&scene.substrate)?;
    indenter(&scene.indenter)?;
    load(scene)?;
    if scene.solver.cell.is_some() && !matches!(scene.geometry, Geometry::WheelRail(_)) {
        return Err(Issue::new(
            ErrorKind::Schema,
            "solver.cell",
            "`solver.cell` sizes the patches of a wheel on a rail; this geometry takes solver.grid",
        )
        .hint("remove solver.cell, or use solver.grid = elements per side"));
    }
    history(scene)?;
    motion(scene)?;
    outputs(&scene.outputs, scene.geometry.is_2d())?;
    solver(&scene.solver)?;
    interface::interface(scene)
}

/// `v` finite and not subnormal (0 or at least 2.2e-308 in magnitude).
fn finite(key: &str, v: f64) -> Result<f64, Issue> {
    if !v.is_finite() {
        Err(Issue::new(ErrorKind::OutOfRange, key, "must be a finite number")
            .hint("a finite number (a string with a unit, e.g. \"10 mm\", or SI)"))
    } else if !ranges::is_normal_or_zero(v) {
        Err(Issue::new(ErrorKind::OutOfRange, key, format!("{v:e} is a subnormal number")).hint(
            "double precision keeps fewer than 16 digits below 2.2e-308; write 0 or a value of sensible size",
        ))
    } else {
        Ok(v)
    }
}

/// The message and hint of a magnitude outside `r`, in engineering units
/// ([`crate::eng`]); a value that rounds to a bound's four digits is written in full.
fn outside(key: &str, v: f64, r: &Range) -> Issue {
    let (lo, hi) = (eng(r.lo, r.unit), eng(r.hi, r.unit));
    let found = eng_beside(v, &[r.lo, r.hi], r.unit);
    Issue::new(
        ErrorKind::OutOfRange,
        key,
        format!(
            "{} {found} is outside the range verified in double precision, {lo} to {hi}",
            r.name
        ),
    )
    .hint(r.why)
}

/// `v` positive and within `r`.
fn within(key: &str, v: f64, r: &Range) -> Result<f64, Issue> {
    positive(key, v, r.name)?;
    if v < r.lo || v > r.hi {
        return Err(outside(key, v, r));
    }
    Ok(v)
}

/// `v` zero, or its magnitude within `r`.
fn zero_or_within(key: &str, v: f64, r: &Range) -> Result<f64, Issue> {
    finite(key, v)?;
    if v != 0.0 && (v.abs() < r.lo || v.abs() > r.hi) {
        return Err(outside(key, v, r));
    }
    Ok(v)
}

/// `v` finite, zero or normal, and `|v|` at most the range's upper end (signed values
/// that may pass through zero, such as a load path's corners).
fn at_most(key: &str, v: f64, r: &Range) -> Result<f64, Issue> {
    finite(key, v)?;
    if v.abs() > r.hi {
        return Err(outside(key, v, r));
    }
    Ok(v)
}

/// `v` finite and > 0; `name` says what it is ("radius", "modulus", ...).
fn positive(key: &str, v: f64, name: &str) -> Result<f64, Issue> {
    finite(key, v)?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err(Issue::new(ErrorKind::OutOfRange, key, format!("{name} must be positive, got {v}"))
            .hint(format!("give a {name} > 0")))
    }
}

fn poisson(key: &str, nu: f64) -> Result<f64, Issue> {
    if nu.is_finite() && nu > -1.0 && nu <= 0.5 {
        Ok(nu)
    } else {
        Err(Issue::new(ErrorKind::OutOfRange, key, format!("Poisson's ratio {nu} is not allowed"))
            .hint("an isotropic elastic solid has -1 < nu <= 0.5"))
    }
}

fn geometry(g: &Geometry) -> Result<(), Issue> {
    match g {
        Geometry::Cylinder { radius } | Geometry::Sphere { radius } => {
            within("geometry.radius", *radius, &ranges::LENGTH)?;
        }
        Geometry::Punch { half_width } => {
            within("geometry.half_width", *half_width, &ranges::LENGTH)?;
        }
        Geometry::Ellipsoid(Ellipse::SemiAxes { a, b }) => {
            within("geometry.semi_axes", *a, &ranges::LENGTH)?;
            within("geometry.semi_axes", *b, &ranges::LENGTH)?;
        }
        Geometry::Ellipsoid(Ellipse::Radii { rx, ry }) => {
            within("geometry.radii", *rx, &ranges::LENGTH)?;
            within("geometry.radii", *ry, &ranges::LENGTH)?;
        }
        Geometry::Patches(ps) => patches(ps)?,
        Geometry::Surface(s) => surface(s)?,
        Geometry::WheelRail(w) => wheel_rail(w)?,
    }
    Ok(())
}

fn wheel_rail(w: &super::WheelRail) -> Result<(), Issue> {
    positive("geometry.profile_unit", w.profile_unit, "length unit")?;
    positive("geometry.gauge", w.gauge, "gauge")?;
    finite("geometry.gauge_height", w.gauge_height)?;
    positive("geometry.flange_back_distance", w.flange_back_distance, "flange back distance")?;
    finite("geometry.flange_back_position", w.flange_back_position)?;
    positive("geometry.wheel_radius", w.wheel_radius, "wheel radius")?;
    finite("position.lateral", w.position.lateral)?;
    let quarter = std::f64::consts::FRAC_PI_4;
    for (key, v) in [
        ("geometry.rail_cant", w.rail_cant),
        ("position.yaw", w.position.yaw),
        ("position.roll", w.position.roll),
    ] {
        if !(v.is_finite() && v.abs() < quarter) {
            return Err(Issue::new(ErrorKind::OutOfRange, key, format!("angle {} is not allowed", eng(v, "rad")))
                .hint("a finite angle below 45 deg in size; write it with its unit, e.g. \"4.8 mrad\" (rail cants are about 1:40, 25 mrad; yaw and roll a few mrad)"));
        }
    }
    Ok(())
}

/// The largest lattice side of a surface.
pub const MAX_SURFACE_CELLS: usize = 4096;

fn surface(s: &super::Surface) -> Result<(), Issue> {
    use super::Profile;
    within("geometry.size", s.size[0], &ranges::LENGTH)?;
    within("geometry.size", s.size[1], &ranges::LENGTH)?;
    for c in s.cells {
        if !(8..=MAX_SURFACE_CELLS).contains(&c) {
            return Err(Issue::new(
                ErrorKind::OutOfRange,
                "geometry.cells",
                format!("{c} cells along a side"),
            )
            .hint(format!("8 <= cells <= {MAX_SURFACE_CELLS} along each side")));
        }
    }
    match s.profile {
        Profile::Sphere { radius } => {
            within("geometry.profile.radius", radius, &ranges::LENGTH)?;
        }
        Profile::Ellipsoid { radii } => {
            within("geometry.profile.radii", radii[0], &ranges::LENGTH)?;
            within("geometry.profile.radii", radii[1], &ranges::LENGTH)?;
        }
        Profile::Punch { radius, edge_radius } => {
            within("geometry.profile.radius", radius, &ranges::LENGTH)?;
            // 0: the sharp-edged punch.
            if edge_radius != 0.0 {
                within("geometry.profile.edge_radius", edge_radius, &ranges::LENGTH)?;
            }
        }
        Profile::Wavy { wavelength, amplitude, .. } => {
            within("geometry.profile.wavelength", wavelength, &ranges::LENGTH)?;
            within("geometry.profile.amplitude", amplitude, &ranges::SMALL_LENGTH)?;
        }
        Profile::Cylinder { radius, length, crown, end_radius } => {
            within("geometry.profile.radius", radius, &ranges::LENGTH)?;
            within("geometry.profile.length", length, &ranges::LENGTH)?;
            if !(crown.is_finite() && crown >= 0.0)
                || zero_or_within("geometry.profile.crown", crown, &ranges::SMALL_LENGTH).is_err()
            {
                return Err(Issue::new(
                    ErrorKind::OutOfRange,
                    "geometry.profile.crown",
                    format!("crown {}", eng(crown, "m")),
                )
                .hint("the crown drop at the roller ends is a length >= 0 (0: no crown)"));
            }
            if crown > 0.0 {
                within("geometry.profile.end_radius", end_radius, &ranges::LENGTH)?;
                let end = (2.0 * end_radius * crown).sqrt();
                if end > 0.5 * length {
                    return Err(Issue::new(
                        ErrorKind::OutOfRange,
                        "geometry.profile.crown",
                        format!(
                            "a crown of {} with end radius {} needs rounded ends {} long, more than half the length {}",
                            eng(crown, "m"), eng(end_radius, "m"), eng(end, "m"), eng(length, "m")
                        ),
                    )
                    .hint(format!("at most crown = length^2/(8 end_radius) = {}, or a smaller end_radius", eng(length * length / (8.0 * end_radius), "m"))));
                }
            }
            if s.size[1] < length {
                return Err(Issue::new(
                    ErrorKind::OutOfRange,
                    "geometry.size",
                    format!("the lattice is {} long in y but the roller is {} long", eng(s.size[1], "m"), eng(length, "m")),
                )
                .hint(format!("make size[1] at least the roller length {} (a little more shows its ends), or shorten the roller", eng(length, "m"))));
            }
        }
        Profile::Flat => {}
    }
    if let Some(h) = &s.roughness {
        let n = s.cells[0] * s.cells[1];
        if h.len() != n {
            return Err(Issue::new(
                ErrorKind::OutOfRange,
                "geometry.roughness.file",
                format!("{} heights for {} x {} cells", h.len(), s.cells[0], s.cells[1]),
            )
            .hint("one row per y with one height per x cell, as `cells` says"));
        }
        if let Some(k) = h.iter().position(|v| !v.is_finite() || !ranges::is_normal_or_zero(*v)) {
            return Err(Issue::new(
                ErrorKind::OutOfRange,
                "geometry.roughness.file",
                format!(
                    "height {k} (row {}, column {}) is not finite, or is a subnormal number",
                    k / s.cells[0],
                    k % s.cells[0]
                ),
            )
            .hint("every height must be a number, 0 or at least 2.2e-308 in magnitude; fill missing points before reading"));
        }
    }
    Ok(())
}

fn patches(ps: &[Patch]) -> Result<(), Issue> {
    if ps.is_empty() {
        return Err(Issue::new(
            ErrorKind::OutOfRange,
            "geometry.patches",
            "the patch list is empty",
        )
        .hint("give at least one patch"));
    }
    for (i, p) in ps.iter().enumerate() {
        let key = format!("geometry.patches[{i}]");
        match p.shape {
            PatchShape::Square { side } => {
                within(&format!("{key}.side"), side, &ranges::LENGTH)?;
            }
            PatchShape::Rectangle { sides } => {
                within(&format!("{key}.sides"), sides[0], &ranges::LENGTH)?;
                within(&format!("{key}.sides"), sides[1], &ranges::LENGTH)?;
            }
            PatchShape::Circle { radius } => {
                within(&format!("{key}.radius"), radius, &ranges::LENGTH)?;
            }
        }
        finite(&format!("{key}.centre"), p.centre[0])?;
        finite(&format!("{key}.centre"), p.centre[1])?;
        let pk = format!("{key}.pressure");
        finite(&pk, p.pressure)?;
        if p.pressure > 0.0 {
            within(&pk, p.pressure, &ranges::PRESSURE)?;
        }
        if p.pressure <= 0.0 {
            return Err(Issue::new(
                ErrorKind::OutOfRange,
                &pk,
                format!(
                    "a patch with no compressive pressure ({}) carries no load",
                    eng(p.pressure, "Pa")
                ),
            )
            .hint("pressure > 0; leave the patch out if it is not in contact"));
        }
        if let Some(j) = ps[..i].iter().position(|q| q.overlaps(p)) {
            return Err(Issue::new(
                ErrorKind::Impossible,
                &key,
                format!("patch {i} overlaps patch {j}"),
            )
            .hint("patches must be disjoint (they may touch along an edge)"));
        }
    }
    Ok(())
}

/// The largest grading exponent accepted: the graded kernels are integrated with
/// Gauss–Jacobi rules of weight exponent $-k$, whose construction fails in f64 within
/// about $10^{-14}$ of $k = 1$ (measured: $1 - 10^{-12}$ runs, $1 - 10^{-14}$ fails); this
/// limit keeps three decades from that edge.
pub const MAX_GRADING_EXPONENT: f64 = 1.0 - 1e-9;

fn substrate(s: &Substrate) -> Result<(), Issue> {
    match *s {
        Substrate::Homogeneous(Elastic { e, nu }) => {
            poisson("substrate.nu", nu)?;
            within("substrate.e", e, &ranges::MODULUS)?;
        }
        Substrate::Graded { e0, k, nu } => {
            if !(k.is_finite() && (0.0..1.0).contains(&k)) {
                return Err(Issue::new(
                    ErrorKind::OutOfRange,
                    "substrate.k",
                    format!("grading exponent k = {k} is outside [0, 1)"),
                )
                .hint(
                    "0 <= k < 1 (k = 1 is the Gibson soil, where the surface integrals diverge)",
                ));
            }
            if k > MAX_GRADING_EXPONENT {
                return Err(Issue::new(
                    ErrorKind::OutOfRange,
                    "substrate.k",
                    format!("grading exponent k = {k} is too close to 1 for the kernel quadrature"),
                )
                .hint(format!("use k <= {MAX_GRADING_EXPONENT} (the Gauss-Jacobi weight (1-t)^-k cannot be built in f64 closer to 1)")));
            }
            // beta^2 = (1+k)(1-(1+k)nu)/(1-nu) must be positive (FORMULAS.md A1); this more
            // specific check comes before the isotropic range.
            if nu >= 1.0 / (1.0 + k) {
                return Err(Issue::new(
                    ErrorKind::OutOfRange,
                    "substrate.nu",
                    format!("nu = {nu} with k = {k} makes beta imaginary"),
                )
                .hint(format!(
                    "a graded substrate needs nu < 1/(1+k) = {:.6}, and -1 < nu <= 0.5 as any isotropic solid",
                    1.0 / (1.0 + k)
                )));
            }
            poisson("substrate.nu", nu)?;
            within("substrate.e0", e0, &ranges::MODULUS)?;
        }
        Substrate::Viscoelastic { elastic: Elastic { e, nu }, alpha, beta } => {
            poisson("substrate.nu", nu)?;
            within("substrate.e", e, &ranges::MODULUS)?;
            within("substrate.alpha", alpha, &ranges::TIME)?;
            within("substrate.beta", beta, &ranges::TIME)?;
            if alpha < beta {
                return Err(Issue::new(
                    ErrorKind::OutOfRange,
                    "substrate.alpha",
                    format!("alpha = {} is less than beta = {}", eng(alpha, "s"), eng(beta, "s")),
                )
                .hint("the standard solid eps + alpha eps' = (sigma + beta sigma')/E dissipates only for alpha > beta; alpha = beta is elastic"));
            }
        }
    }
    Ok(())
}

fn indenter(i: &Indenter) -> Result<(), Issue> {
    if let Indenter::Homogeneous(Elastic { e, nu }) = *i {
        within("indenter.e", e, &ranges::MODULUS)?;
        poisson("indenter.nu", nu)?;
    }
    Ok(())
}

fn load(scene: &Scene) -> Result<(), Issue> {
    let l = &scene.load;
    let two_d = scene.geometry.is_2d();
    let force_range = if two_d { ranges::FORCE_PER_LENGTH } else { ranges::FORCE };
    match (&scene.geometry, l.normal) {
        (Geometry::Patches(_), NormalLoad::FromPatches(_)) => {}
        (Geometry::Patches(_), _) => {
            return Err(Issue::new(
                ErrorKind::Schema,
                "load.normal",
                "patches carry their own pressures; do not give load.normal or load.half_width",
            )
            .hint("remove load.normal / load.half_width"))
        }
        (_, NormalLoad::FromPatches(_)) => {
            return Err(Issue::new(
                ErrorKind::Schema,
                "load.normal",
                "only patches carry their own pressures; this geometry needs load.normal or load.half_width",
            )
            .hint("normal = P (N/m in 2D, N in 3D), or half_width = a"))
        }
        (_, NormalLoad::Force(p)) => {
            within("load.normal", p, &force_range)?;
            if let Some(sw) = scene.load.normal_sweep {
                if !matches!(scene.geometry, Geometry::Surface(_)) {
                    return Err(Issue::new(
                        ErrorKind::Unsupported,
                        "load.normal",
                        "a load sweep is solved for surfaces (geometry.kind = \"surface\"); closed forms give the area-load curve directly",
                    )
                    .hint("give one force, e.g. normal = \"10 N\""));
                }
                within("load.normal", sw.from, &force_range)?;
                if sw.from >= p {
                    return Err(Issue::new(
                        ErrorKind::OutOfRange,
                        "load.normal",
                        format!(
                            "the sweep starts at {}, not below its end {}",
                            eng(sw.from, force_range.unit),
                            eng(p, force_range.unit)
                        ),
                    )
                    .hint("write [from, to, steps] with 0 < from < to, e.g. [\"1 N\", \"100 N\", 20]"));
                }
            }
        }
        (Geometry::Surface(_), NormalLoad::HalfWidth(_)) => {
            return Err(Issue::new(
                ErrorKind::Schema,
                "load.half_width",
                "a surface takes the normal force or the approach, not a half-width",
            )
            .hint("normal = \"10 N\" (force control) or approach = \"2 um\" (displacement control)"))
        }
        (Geometry::WheelRail(_), NormalLoad::HalfWidth(_)) => {
            return Err(Issue::new(
                ErrorKind::Schema,
                "load.half_width",
                "a wheel on a rail takes the vertical wheel load or the approach, not a half-width",
            )
            .hint("normal = \"10 kN\" (the vertical wheel load) or approach = \"50 um\""))
        }
        (Geometry::Surface(_), NormalLoad::Approach(d))
            if scene.load.approach_path.is_some() || scene.interface.adhesion.is_some() =>
        {
            // Signed: a path and an adhesive contact may hold the surfaces apart.
            at_most("load.approach", d, &ranges::SMALL_LENGTH)?;
            interface::approach_path(scene)?;
        }
        (Geometry::Surface(_) | Geometry::WheelRail(_), NormalLoad::Approach(d)) => {
            if scene.load.approach_path.is_some() {
                return Err(Issue::new(
                    ErrorKind::Unsupported,
                    "load.approach",
                    "an approach path is solved for surfaces (geometry.kind = \"surface\")",
                )
                .hint("give one approach, e.g. approach = \"50 um\""));
            }
            within("load.approach", d, &ranges::SMALL_LENGTH)?;
        }
        (_, NormalLoad::Approach(_)) => {
            return Err(Issue::new(
                ErrorKind::Schema,
                "load.approach",
                "the approach (displacement control) is for geometry.kind = \"surface\"",
            )
            .hint("give load.normal = P"))
        }
        (_, NormalLoad::HalfWidth(a)) => {
            within("load.half_width", a, &ranges::LENGTH)?;
        }
    }
    // |T| <= f P bounds the tangential load; it needs no range of its own.
    finite("load.tangential", l.tangential)?;
    if !l.direction_deg.is_finite() || !ranges::is_normal_or_zero(l.direction_deg) {
        return Err(Issue::new(
            ErrorKind::OutOfRange,
            "load.direction_deg",
            format!("direction {} degrees is not a finite angle", l.direction_deg),
        )
        .hint("an angle in degrees from +x, e.g. direction_deg = 90"));
    }
    if !(l.friction.is_finite() && l.friction >= 0.0) {
        return Err(Issue::new(
            ErrorKind::OutOfRange,
            "load.friction",
            format!("friction coefficient {} is not allowed", l.friction),
        )
        .hint("a Coulomb coefficient f >= 0"));
    }
    zero_or_within("load.friction", l.friction, &ranges::FRICTION)?;
    zero_or_within("load.moment", l.moment, &ranges::MOMENT)?;
    if l.moment != 0.0 && two_d {
        return Err(Issue::new(
            ErrorKind::Impossible,
            "load.moment",
            "a twisting moment needs a 3D contact",
        )
        .hint("use geometry.kind = sphere, ellipsoid or patches"));
    }
    if l.sliding && l.tangential != 0.0 {
        return Err(Issue::new(ErrorKind::Impossible, "load.tangential", "with sliding = true the shear is q = f p and the tangential load is f P; do not also give it")
            .hint("remove load.tangential, or set sliding = false for partial slip"));
    }
    if l.tangential != 0.0 && l.friction == 0.0 {
        return Err(Issue::new(
            ErrorKind::Impossible,
            "load.tangential",
            "a tangential load on a frictionless contact cannot be carried",
        )
        .hint("give load.friction > 0"));
    }
    if let (NormalLoad::Force(p) | NormalLoad::FromPatches(p), false) = (l.normal, l.sliding) {
        if l.tangential.abs() > l.friction * p {
            return Err(Issue::new(
                ErrorKind::Impossible,
                "load.tangential",
                format!(
                    "|T| = {} exceeds f P = {}: the contact slides, partial slip is impossible",
                    eng(l.tangential.abs(), force_range.unit),
                    eng(l.friction * p, force_range.unit)
                ),
            )
            .hint("reduce T below f P, or set sliding = true"));
        }
    }
    Ok(())
}

/// `[load.history]`: a load path on a static 3D contact with friction, under a normal
/// force; corner lists of one length; positive normal loads; under force control no corner
/// beyond the friction capacity f P (the bodies would slide and accelerate).
#[allow(clippy::too_many_lines)]
fn history(scene: &Scene) -> Result<(), Issue> {
    let l = &scene.load;
    let Some(h) = &l.history else { return Ok(()) };
    let key = |k: &str, i: usize| format!("load.history.{k}[{i}]");
    let (list, what) = match h.control {
        HistoryControl::Force => ("tangential", "force"),
        HistoryControl::Shift => ("shift", "shift"),
    };
    if scene.geometry.is_2d() {
        return Err(Issue::new(
            ErrorKind::Unsupported,
            "load.history",
            "a load path is solved on 3D contacts",
        )
        .hint("use geometry.kind = sphere, ellipsoid, patches or surface"));
    }
    if scene.motion != Motion::Static {
        return Err(Issue::new(
            ErrorKind::Unsupported,
            "load.history",
            "a load path is solved for a static contact",
        )
        .hint("remove [motion], or remove [load.history]"));
    }
    if l.sliding {
        return Err(Issue::new(
            ErrorKind::Impossible,
            "load.sliding",
            "a load path finds sliding where it happens; full sliding is not prescribed with it",
        )
        .hint("remove sliding = true (a shift path slides beyond its onset)"));
    }
    for (k, v) in [("load.tangential", l.tangential), ("load.moment", l.moment)] {
        if v != 0.0 {
            return Err(Issue::new(
                ErrorKind::Impossible,
                k,
                format!(
                    "{k} = {v} is given beside a load path, which prescribes the tangential load"
                ),
            )
            .hint(format!("remove {k}; give its values along the path in [load.history]")));
        }
    }
    if l.friction <= 0.0 || l.friction.is_nan() {
        return Err(Issue::new(
            ErrorKind::Impossible,
            "load.friction",
            "a load path on a frictionless contact carries no tangential load",
        )
        .hint("give load.friction > 0"));
    }
    let constant = match l.normal {
        NormalLoad::Force(p) | NormalLoad::FromPatches(p) if l.normal_sweep.is_none() => p,
        _ => {
            return Err(Issue::new(
                ErrorKind::Unsupported,
                "load.normal",
                "a load path is solved under a normal force (one value), not a half-width, an approach or a sweep",
            )
            .hint("give load.normal = P (the path's normal load where [load.history] has no normal)"))
        }
    };
    if !(1..=History::MAX_STEPS).contains(&h.steps) {
        return Err(Issue::new(
            ErrorKind::OutOfRange,
            "load.history.steps",
            format!("{} steps between corners", h.steps),
        )
        .hint(format!("an integer from 1 to {}", History::MAX_STEPS)));
    }
    let n = h.tangential.len();
    if !(1..=History::MAX_CORNERS).contains(&n) {
        return Err(Issue::new(
            ErrorKind::OutOfRange,
            &format!("load.history.{list}"),
            format!("{n} corners"),
        )
        .hint(format!("from 1 to {} corner values", History::MAX_CORNERS)));
    }
    // Corner values along a path are signed and pass through zero: a value far below the
    // range (a run's solved force of 1e-14 N at a zero crossing, read back from its
    // history.csv) is a numerical zero of that path, not a magnitude of its own; the path's
    // scale is its normal load's. So only the upper end (and subnormals) are refused here.
    for (i, v) in h.tangential.iter().enumerate() {
        match h.control {
            HistoryControl::Force => at_most(&key(list, i), *v, &ranges::FORCE)?,
            HistoryControl::Shift => at_most(&key(list, i), *v, &ranges::SMALL_LENGTH)?,
        };
    }
    for (k, other) in [("normal", &h.normal), ("moment", &h.moment)] {
        if let Some(v) = other {
            if v.len() != n {
                return Err(Issue::new(
                    ErrorKind::Schema,
                    &format!("load.history.{k}"),
                    format!("{} values for {n} corners of load.history.{list}", v.len()),
                )
                .hint(format!("give one {k} value per corner ({n})")));
            }
            for (i, x) in v.iter().enumerate() {
                match k {
                    "normal" if *x > 0.0 => within(&key(k, i), *x, &ranges::FORCE)?,
                    "normal" => finite(&key(k, i), *x)?,
                    _ => at_most(&key(k, i), *x, &ranges::MOMENT)?,
                };
            }
        }
    }
    if let Some(v) = &h.normal {
        if let Some((i, p)) = v.iter().enumerate().find(|(_, p)| **p <= 0.0) {
            return Err(Issue::new(
                ErrorKind::Impossible,
                &key("normal", i),
                format!(
                    "the normal load reaches {} at corner {i}{}: the bodies separate",
                    eng(*p, "N"),
                    h.corner_origin(i)
                ),
            )
            .hint("keep the normal load > 0 at every corner (a path that separates the bodies is not solved)"));
        }
    }
    if h.moment.is_some() && h.control == HistoryControl::Shift {
        return Err(Issue::new(
            ErrorKind::Unsupported,
            "load.history.moment",
            "a moment on a shift-controlled path is not solved",
        )
        .hint("prescribe the tangential force (tangential = [...]) with the moment"));
    }
    if h.control == HistoryControl::Force {
        for (i, t) in h.tangential.iter().enumerate() {
            let cap = l.friction * h.normal_at(i, constant);
            if t.abs() > cap * (1.0 + 1e-12) {
                return Err(Issue::new(
                    ErrorKind::Impossible,
                    &key(list, i),
                    format!(
                        "at corner {i}{} the tangential {what} |T| = {} exceeds f P = {}: no equilibrium, the bodies slide",
                        h.corner_origin(i),
                        eng(t.abs(), "N"),
                        eng(cap, "N")
                    ),
                )
                .hint("keep |T| <= f P at every corner, or prescribe the shift (shift = [...]) to let the contact slide"));
            }
        }
    }
    Ok(())
}

/// Creepages given directly: each 0, or within the creep range in magnitude.
fn creepages(c: [f64; 3]) -> Result<(), Issue> {
    for (key, v) in [
        ("motion.creepage.longitudinal", c[0]),
        ("motion.creepage.lateral", c[1]),
        ("motion.creepage.spin", c[2]),
    ] {
        if !v.is_finite() || zero_or_within(key, v, &ranges::CREEP).is_err() {
            return Err(Issue::new(ErrorKind::OutOfRange, key, format!("creepage {v:e} is outside the range verified in double precision: 0, or 1e-12 to 1e6 in magnitude"))
                .hint("creepages are small numbers (1e-4 to 1e-2 in wheel-rail contact; spin in 1/m); larger ones mean full slip and are still solved, up to 1e6"));
        }
    }
    Ok(())
}

fn motion(scene: &Scene) -> Result<(), Issue> {
    if let Motion::Wheelset { speed, pitch_rate, creepage } = scene.motion {
        positive("motion.speed", speed, "speed")?;
        if let Some(w) = pitch_rate {
            finite("motion.pitch_rate", w)?;
        }
        if let Some(c) = creepage {
            creepages(c)?;
        }
    }
    if matches!(scene.geometry, Geometry::WheelRail(_))
        && !matches!(scene.motion, Motion::Wheelset { .. } | Motion::Static)
    {
        return Err(Issue::new(ErrorKind::Schema, "motion.kind", "a wheel on a rail takes motion.kind = \"rolling\" with speed and pitch_rate")
            .hint("[motion] kind = \"rolling\", speed = \"2 m/s\", pitch_rate = \"-4.35 rad/s\" (or leave [motion] out for normal contact only)"));
    }
    if let Motion::RollingCreepage { speed, longitudinal, lateral, spin, transient } = scene.motion
    {
        within("motion.speed", speed, &ranges::SPEED)?;
        if let Some(t) = transient {
            if let Some(d) = t.distance {
                within("motion.transient.distance", d, &ranges::LENGTH)?;
            }
            if t.creepage_control
                && scene.load.tangential != 0.0
                && t.start == crate::TransientStart::Rest
            {
                return Err(Issue::new(ErrorKind::Schema, "load.tangential", "both a creep force (load.tangential) and creepages (motion.creepage) are prescribed for rolling from rest")
                    .hint("give either the creep force (the creepages follow) or the longitudinal and lateral creepages (the force follows); with start = \"shift\" the force acts in the shift at rest and the creepages in the rolling"));
            }
            if scene.load.history.is_some() || scene.load.sliding || scene.load.moment != 0.0 {
                return Err(Issue::new(ErrorKind::Unsupported, "motion.transient", "transient rolling takes a constant creep force (load.tangential, load.direction) and the spin; a load path, sliding or a moment are not solved with it in this version")
                    .hint("remove [load.history], load.sliding and load.moment"));
            }
            if scene.load.friction <= 0.0 {
                return Err(Issue::new(
                    ErrorKind::Impossible,
                    "load.friction",
                    "transient rolling needs friction: without it no creep force is carried",
                )
                .hint("give load.friction, e.g. friction = 0.3"));
            }
        }
        creepages([longitudinal, lateral, spin])?;
    }
    if let Motion::Rolling { speed, creep } = scene.motion {
        within("motion.speed", speed, &ranges::SPEED)?;
        if !creep.is_finite() {
            return Err(Issue::new(ErrorKind::OutOfRange, "motion.creep", "creep must be finite")
                .hint("a finite creep ratio (omega R - w)/w, e.g. creep = 1e-3"));
        }
        zero_or_within("motion.creep", creep, &ranges::CREEP)?;
        if !scene.geometry.is_2d() {
            return Err(Issue::new(
                ErrorKind::Impossible,
                "motion.kind",
                "rolling is solved for cylinders (2D)",
            )
            .hint("use geometry.kind = \"cylinder\""));
        }
    }
    Ok(())
}

/// The largest number of points along one axis of a field grid.
pub const MAX_FIELD_POINTS: usize = 10_000;

fn axis(key: &str, a: (f64, f64, usize), depth: bool) -> Result<(), Issue> {
    let bad = |m: String| {
        Issue::new(ErrorKind::OutOfRange, key, m)
            .hint("[from, to, count] with from < to and 2 <= count <= 10000 (depth from > 0)")
    };
    let (lo, hi, n) = a;
    if !(lo.is_finite() && hi.is_finite() && lo < hi) {
        return Err(bad(format!("need from < to, got {lo} .. {hi}")));
    }
    if depth && lo <= 0.0 {
        return Err(bad(format!("depths must be below the surface (> 0), got {lo}")));
    }
    if !(2..=MAX_FIELD_POINTS).contains(&n) {
        return Err(bad(format!("count {n} is not an integer in 2..=10000")));
    }
    Ok(())
}

/// An axis of a 3D box: `from <= to`, at least one point, one point when `from == to`.
fn box_axis(key: &str, a: (f64, f64, usize), depth: bool) -> Result<(), Issue> {
    let bad = |m: String| {
        Issue::new(ErrorKind::OutOfRange, key, m).hint(
            "[from, to, count] with from <= to and 1 <= count <= 10000 (one point when from = to; depths > 0)",
        )
    };
    let (lo, hi, n) = a;
    if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
        return Err(bad(format!("need from <= to, got {lo} .. {hi}")));
    }
    if depth && lo <= 0.0 {
        return Err(bad(format!("depths must be below the surface (> 0), got {lo}")));
    }
    if !(1..=MAX_FIELD_POINTS).contains(&n) || (lo < hi && n < 2) {
        return Err(bad(format!("count {n} is not allowed for {lo} .. {hi}")));
    }
    Ok(())
}

fn outputs(o: &Outputs, two_d: bool) -> Result<(), Issue> {
    if let Some(FieldGrid { x, y, z, .. }) = o.field {
        match (two_d, z) {
            (true, None) => {
                axis("outputs.field.x", x, false)?;
                axis("outputs.field.y", y, true)?;
            }
            (true, Some(_)) => {
                return Err(Issue::new(
                    ErrorKind::Schema,
                    "outputs.field.z",
                    "z is the depth axis of a 3D contact; in 2D the depth is y",
                )
                .hint("remove z; give y = [from, to, count] as the depth"))
            }
            (false, Some(z)) => {
                box_axis("outputs.field.x", x, false)?;
                box_axis("outputs.field.y", y, false)?;
                box_axis("outputs.field.z", z, true)?;
            }
            (false, None) => {
                return Err(Issue::new(
                    ErrorKind::Schema,
                    "outputs.field",
                    "a 3D field needs the depth axis z",
                )
                .hint("field = { x = [-1.5, 1.5, 61], y = [0, 0, 1], z = [0.02, 2.0, 40], scale = \"a\" }"))
            }
        }
    }
    if let Some(Cycle { amplitude, points }) = o.cycle {
        if !(amplitude > 0.0 && amplitude <= 1.0) {
            return Err(Issue::new(
                ErrorKind::OutOfRange,
                "outputs.cycle.amplitude",
                format!("amplitude T*/(fP) = {amplitude} is outside (0, 1]"),
            )
            .hint("0 < T*/(fP) <= 1"));
        }
        if !(4..=100_000).contains(&points) {
            return Err(Issue::new(
                ErrorKind::OutOfRange,
                "outputs.cycle.points",
                format!("{points} points"),
            )
            .hint("4 <= points <= 100000"));
        }
    }
    Ok(())
}

fn solver(s: &SolverOptions) -> Result<(), Issue> {
    if !(4..=MAX_GRID).contains(&s.grid) {
        return Err(Issue::new(ErrorKind::OutOfRange, "solver.grid", format!("grid = {} elements per side is not allowed", s.grid))
            .hint(format!("4 <= grid <= {MAX_GRID}; grids whose working memory would exceed 16 GiB are refused by the planner (about 5100 per side for the fast solver)")));
    }
    let t = s.tolerance;
    if !(t.is_finite() && t > 0.0 && t < 1.0) {
        return Err(Issue::new(
            ErrorKind::OutOfRange,
            "solver.tolerance",
            format!("tolerance {t} is not allowed"),
        )
        .hint("a relative tolerance in (0, 1), e.g. 1e-10"));
    }
    if let Some([hx, hs]) = s.cell {
        for v in [hx, hs] {
            if !(v.is_finite() && v > 0.0 && v <= 0.1) {
                return Err(Issue::new(ErrorKind::OutOfRange, "solver.cell", format!("element size {} is not allowed", eng(v, "m")))
                    .hint("two lengths > 0, about a tenth of the patch's semi-axes, e.g. cell = [\"0.2 mm\", \"0.2 mm\"]"));
            }
        }
    }
    Ok(())
}
