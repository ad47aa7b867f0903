//! Execution: a [`Plan`] run stage by stage.
//!
//! [`execute`] follows the plan's [`Recipe`] and decides nothing again. Each stage is a
//! small module that reads what earlier stages produced:
//!
//! | recipe | stages (files of `exec/`), in order |
//! |---|---|
//! | [`Recipe::Line`] | `normal` (2D) → `friction` (2D traction) → `surface` → `field` |
//! | [`Recipe::Rolling`] | `rolling` (normal and tangential together) |
//! | [`Recipe::WheelRail`] | `wheel_rail` (contact search, normal contact under the wheel load, creep forces per patch: `stickslip-wheelrail`) |
//! | [`Recipe::Contact`] | `normal` (3D, on the `lattice`) → `friction` (closed forms) or `twist` (Lubkin) or `grid` (LP, fast solver) or `roll3d` (3D steady rolling: exact, FASTSIM, Polach) or `transient` (3D rolling in steps from a start state, its steps into `history`) or `history` (a load path, step by step; its final state goes on) → `cycle` → `field` |
//!
//! Every stage increments the evaluation counter of the effects it computes
//! ([`Evaluations`]), so a test can prove that an effect that is off costs nothing. Adding a
//! capability is a plan variant and a stage module, not a branch in a dispatcher.

// Scene errors carry file, position, key and hint; they are built on cold paths.
#![allow(clippy::result_large_err)]

mod adhesion;
mod audit;
mod coupled;
mod cycle;
mod field;
mod friction;
mod grid;
mod history;
mod lattice;
mod normal;
pub(crate) mod outcome;
mod ruiz;
mod transient;

pub use crate::plan::patches::LATTICE_AREA_TOLERANCE;
pub use audit::SAMPLING_TOLERANCE;
mod roll3d;
mod rolling;
mod surface;
mod twist;
mod wheel_rail;

use std::time::Instant;

use crate::plan::{Plan, Recipe};
use outcome::{
    ContactOut, CycleOut, EffectsOut, Evaluations, Field, Forces, Outcome, Progress, RigidOut,
    RollingOut, RunOptions, SolverOut, SurfaceOut, Zones,
};
use stickslip_scene::{ErrorKind, SceneError};

/// A physics routine failed on inputs the planner accepted.
pub(crate) fn solver_err(what: &str, e: impl std::fmt::Display) -> SceneError {
    SceneError::new(ErrorKind::Solver, format!("{what} failed: {e}")).hint(
        "the inputs passed validation, so this is an extreme case the solver cannot handle; \
         please report it with the scene",
    )
}

/// What the stages share: counters, notes, progress, and the solver report.
pub(crate) struct Ctx<'a> {
    pub ev: Evaluations,
    pub notes: Vec<String>,
    opts: RunOptions<'a>,
    pub iterations: usize,
    pub inner_iterations: usize,
    pub residual: f64,
    pub elements: usize,
    pub solve_seconds: f64,
    /// The factor lambda of a closed form shown on the lattice (see
    /// `friction::sample_consistently`); `lambda - 1` is its sampling error.
    pub sampling: Option<f64>,
    /// The coupled normal-tangential solve's record, when it ran.
    pub coupling: Option<outcome::CouplingOut>,
    /// The normal solver of a surface, when it ran.
    pub normal: Option<outcome::NormalSolverOut>,
    /// The sharp punch's check against Boussinesq, when the surface is one.
    pub punch: Option<outcome::PunchOut>,
}

impl Ctx<'_> {
    pub fn progress(&self, stage: &'static str, done: usize, total: usize) {
        if let Some(p) = self.opts.progress {
            p(Progress { stage, done, total });
        }
    }
}

/// The parts of an [`Outcome`] the stages produce.
pub(crate) struct Parts {
    pub contact: ContactOut,
    pub zones: Zones,
    pub forces: Forces,
    pub rigid: RigidOut,
    pub surface: SurfaceOut,
    pub field: Field,
    pub rolling: Option<RollingOut>,
    pub cycle: Option<CycleOut>,
    pub history: Option<outcome::HistoryOut>,
    pub load_curve: Option<outcome::LoadCurve>,
    pub wheel_rail: Option<outcome::WheelRailOut>,
}

/// Points `lo..=hi`, evenly spaced; the midpoint when `n == 1`.
pub(crate) fn linspace(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    if n == 1 {
        return vec![0.5 * (lo + hi)];
    }
    (0..n).map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64).collect()
}

/// The refusal of a result that failed its audit: which checks failed, by how much, and
/// the keys to change.
fn audit_failure(plan: &Plan, out: &Outcome) -> SceneError {
    let failed: Vec<&outcome::Check> = out.audit.checks.iter().filter(|c| !c.pass).collect();
    let list = failed
        .iter()
        .map(|c| format!("{} = {:.3e} (limit {:.1e}: {})", c.name, c.value, c.limit, c.what))
        .collect::<Vec<_>>()
        .join("; ");
    let (key, hint) = match failed.first().map(|c| c.name) {
        Some(
            "normal resultant" | "lattice sampling" | "tangential resultant" | "moment resultant",
        ) => (Some("solver.grid"), "the lattice does not resolve the contact: raise solver.grid"),
        Some("coulomb" | "residual") => {
            (Some("solver.tolerance"), "tighten solver.tolerance (e.g. 1e-10) or raise solver.grid")
        }
        _ => (
            None,
            "the scene is beyond what the solvers handle in f64; please report it with the scene",
        ),
    };
    let mut e = SceneError::new(
        ErrorKind::Audit,
        format!("the result failed its audit and was not written: {list}"),
    )
    .hint(hint);
    e.checks = failed.into_iter().cloned().collect();
    if let Some(k) = key {
        e = e.key(k);
    }
    locate(plan, e)
}

/// A stage's error with the file, and the line and column of its key when the scene came
/// from a file.
fn locate(plan: &Plan, e: SceneError) -> SceneError {
    let e = match (&plan.source, &e.key, e.position) {
        (Some(src), Some(key), None) => {
            let span = src.span(key);
            e.at(src.text(), span)
        }
        _ => e,
    };
    e.in_file(plan.file.clone())
}

/// `plan.execute(&opts)`: a [`Plan`] (made by `stickslip-plan`) run by this crate's stages.
pub trait Execute {
    /// Run this plan, stage by stage ([`execute`]).
    ///
    /// # Errors
    /// See [`execute`].
    fn execute(&self, opts: &RunOptions<'_>) -> Result<Outcome, SceneError>;
}

impl Execute for Plan {
    fn execute(&self, opts: &RunOptions<'_>) -> Result<Outcome, SceneError> {
        execute(self, opts)
    }
}

/// Run `plan`, stage by stage, as planned.
///
/// The result is audited (`exec/audit.rs`: finiteness, sizes, Coulomb admissibility,
/// resultants, residual) before it is returned; `audit` in the result lists the checks.
///
/// # Errors
/// A [`SceneError`] of kind [`ErrorKind::Solver`] (or [`ErrorKind::Impossible`] for a load a
/// grid solver finds beyond the friction capacity) when a physics routine fails, or of kind
/// [`ErrorKind::Audit`] when the result fails a check.
///
/// The run itself goes to a thread of rayon's pool (unless the caller is on one already,
/// as a sweep's points are): the solvers' parallel loops are then split among the pool's
/// threads by work stealing. Called from a thread outside the pool, each of those loops
/// would be handed to the pool and waited for through a lock, a wake-up and a sleep every
/// time: on a 64 x 64 lattice (thousands of short loops a second) a third of the run went
/// into that hand-over.
pub fn execute(plan: &Plan, opts: &RunOptions<'_>) -> Result<Outcome, SceneError> {
    stickslip_lattice::on_pool(|| execute_here(plan, opts))
}

fn execute_here(plan: &Plan, opts: &RunOptions<'_>) -> Result<Outcome, SceneError> {
    let t0 = Instant::now();
    let mut cx = Ctx {
        ev: Evaluations::default(),
        notes: plan
            .notes
            .iter()
            .cloned()
            .chain(plan.grid_solver.as_ref().map(|g| format!("grid solver: {g}")))
            .collect(),
        opts: *opts,
        iterations: 0,
        inner_iterations: 0,
        residual: 0.0,
        elements: 0,
        solve_seconds: 0.0,
        sampling: None,
        coupling: None,
        normal: None,
        punch: None,
    };
    let parts = match &plan.recipe {
        Recipe::Line(r) => line(r, &mut cx),
        Recipe::Rolling(r) => rolling::run(r, &mut cx),
        Recipe::Contact(r) => contact(r, &mut cx),
        Recipe::WheelRail(r) => wheel_rail::run(r, &mut cx),
    }
    .map_err(|e| locate(plan, e))?;
    let mut effects =
        EffectsOut { on: Vec::new(), off: Default::default(), methods: Default::default() };
    let mut methods = Vec::new();
    for e in &plan.effects {
        if e.on {
            effects.on.push(e.effect.name().to_string());
            if let Some(t) = e.technique {
                effects.methods.insert(e.effect.name().to_string(), t.describe().to_string());
                let tag = format!("{t:?}");
                if !methods.contains(&tag) {
                    methods.push(tag);
                }
            }
        } else {
            effects.off.insert(e.effect.name().to_string(), e.reason.clone());
        }
    }
    let mut out = Outcome {
        title: plan.title.clone(),
        effects,
        contact: parts.contact,
        zones: parts.zones,
        forces: parts.forces,
        rigid_displacement: parts.rigid,
        surface: parts.surface,
        field: parts.field,
        solver: SolverOut {
            method: methods.join(" + "),
            iterations: cx.iterations,
            inner_iterations: cx.inner_iterations,
            residual: cx.residual,
            elements: cx.elements,
            solve_seconds: cx.solve_seconds,
            seconds: t0.elapsed().as_secs_f64(),
            coupling: cx.coupling,
            normal: cx.normal,
        },
        rolling: parts.rolling,
        cycle: parts.cycle,
        history: parts.history,
        load_curve: parts.load_curve,
        punch: cx.punch.take(),
        wheel_rail: parts.wheel_rail,
        audit: Default::default(),
        evaluations: cx.ev,
        notes: std::mem::take(&mut cx.notes),
        units: "SI",
    };
    out.audit = audit::audit(plan, &out, &cx);
    if !out.audit.passed {
        return Err(audit_failure(plan, &out));
    }
    Ok(out)
}

/// A static line contact: normal → traction → surface → field.
fn line(r: &crate::plan::recipe::LineRecipe, cx: &mut Ctx<'_>) -> Result<Parts, SceneError> {
    let n = normal::line(&r.normal, r.friction_coefficient, cx)?;
    let t = friction::line(r.friction, &n)?;
    let (surface, rigid) = surface::line(r.surface, &n, &t, cx)?;
    let field = field::line(r.field.as_ref(), &n, &t, cx)?;
    Ok(Parts {
        contact: ContactOut {
            a: n.a,
            b: n.a,
            p0: n.p0,
            indentation: n.indentation,
            normal_load: n.load,
            area: None,
            fraction: None,
            plastic_fraction: None,
            pull_off: None,
            pull_off_reached: None,
        },
        zones: t.zones(n.a, r.friction.is_some(), n.friction_possible),
        forces: Forces {
            normal: n.load,
            tangential: t.tangential,
            moment: 0.0,
            rolling_moment: 0.0,
            fx: None,
            fy: None,
            mz: None,
        },
        rigid: RigidOut { tangential: rigid, rotation: None, per_body: None },
        surface,
        field: Field::Plane(field),
        rolling: None,
        cycle: None,
        history: None,
        load_curve: None,
        wheel_rail: None,
    })
}

/// A static 3D contact: normal on the lattice → the tangential step → the cycle.
fn contact(r: &crate::plan::recipe::ContactRecipe, cx: &mut Ctx<'_>) -> Result<Parts, SceneError> {
    use crate::plan::recipe::Tangential;
    if let Some(beta) = r.coupling {
        let (n, lat, t) = coupled::solve(r, beta, cx)?;
        return contact_parts(r, n, lat, t, cx);
    }
    let n = normal::contact(r, cx)?;
    if let Some(h) = &r.history {
        let (n, lat, t, hist) = history::run(r, h, &n, cx)?;
        let mut parts = contact_parts(r, n, lat, t, cx)?;
        parts.history = Some(hist);
        return Ok(parts);
    }
    let mut lat = n.lattice.clone();
    let t = match r.tangential {
        None => friction::none(&mut lat, r.friction),
        Some(Tangential::Sliding { angle }) => {
            friction::sliding(&mut lat, r.friction, n.load, angle, cx)
        }
        Some(Tangential::Mindlin { force }) => friction::mindlin(&mut lat, r, &n, force, cx)?,
        Some(Tangential::Cattaneo { force, along_x }) => {
            friction::cattaneo(&mut lat, r, &n, force, along_x, cx)?
        }
        Some(Tangential::Lubkin { moment }) => twist::lubkin(&mut lat, r, &n, moment, cx)?,
        Some(Tangential::Grid(g)) => {
            grid::solve(&mut lat, r, &n, g.method, g.force, g.direction, g.moment, g.tolerance, cx)?
        }
        Some(Tangential::Rolling(step)) => match step.transient {
            Some(tr) => {
                let (t, hist) = transient::solve(&mut lat, r, &n, &step, &tr, cx)?;
                let mut parts = contact_parts(r, n, lat, t, cx)?;
                parts.history = Some(hist);
                return Ok(parts);
            }
            None => roll3d::solve(&mut lat, r, &n, &step, cx)?,
        },
    };
    contact_parts(r, n, lat, t, cx)
}

/// The cycle, the field and the result parts of a 3D contact after its tangential step.
fn contact_parts(
    r: &crate::plan::recipe::ContactRecipe,
    n: normal::ContactSolution,
    lat: lattice::Lattice,
    t: friction::TangentialOut,
    cx: &mut Ctx<'_>,
) -> Result<Parts, SceneError> {
    let cycle = match r.cycle {
        Some(c) => Some(cycle::run(c, r, &n, cx)?),
        None => None,
    };
    let field = match &r.field {
        Some(f) => {
            let periodic = matches!(&r.normal, crate::plan::recipe::ContactNormal::Surface { surface, .. }
                if surface.boundary == stickslip_scene::SurfaceBoundary::Periodic);
            Field::Volume(Box::new(field::contact(f, &n, &lat, periodic, cx)?))
        }
        None => Field::default(),
    };
    let load_curve = n.surface.as_ref().and_then(|s| s.curve.clone());
    Ok(Parts {
        contact: ContactOut {
            a: n.ax,
            b: n.ay,
            p0: n.p0,
            indentation: n.indentation,
            normal_load: n.load,
            area: n.surface.as_ref().map(|s| s.area),
            fraction: n.surface.as_ref().map(|s| s.fraction),
            plastic_fraction: n
                .surface
                .as_ref()
                .and_then(|s| s.plastic.as_ref().map(|p| p.fraction)),
            pull_off: n.surface.as_ref().and_then(|s| s.adhesion.map(|a| a.pull_off)),
            pull_off_reached: n.surface.as_ref().and_then(|s| s.adhesion.map(|a| a.reached)),
        },
        zones: t.zones,
        forces: Forces {
            normal: n.load,
            tangential: t.tangential,
            moment: t.moment,
            rolling_moment: 0.0,
            fx: t.creep.map(|c| c[0]),
            fy: t.creep.map(|c| c[1]),
            mz: t.creep.map(|c| c[2]),
        },
        rigid: t.rigid,
        surface: if r.lattice_output {
            match n.surface {
                Some(s) => {
                    let plastic = s.plastic.map(|p| (p.mask, p.displacement));
                    lat.into_surface(Some(s.gap)).with_plastic(plastic)
                }
                None => lat.into_surface(None),
            }
        } else {
            lattice::Lattice::empty().into_surface(None)
        },
        field,
        rolling: None,
        cycle,
        history: None,
        load_curve,
        wheel_rail: None,
    })
}
