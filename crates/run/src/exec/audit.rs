//! The audit: checks every result passes before it is written.
//!
//! A result is either right within its stated accuracy or not given. The checks are
//! independent of how the result was computed: they read the written arrays and totals.
//!
//! | check | what | limit |
//! |---|---|---|
//! | finite | every number finite | none non-finite |
//! | positive sizes | contact length (2D: a + b), semi-axis b, peak pressure, normal load | > 0 |
//! | coulomb | $\max_k (\lvert\mathbf q_k\rvert - f p_k)/(f p_0)$ over the written points | grid solvers (and exact or transient 3D rolling) $\max(10^{-9}, \mathrm{tol})$; rolling $\max(10^{-9}, 100\,\mathrm{tol})$; closed forms $10^{-12}$ |
//! | stick inside contact | stick cells without pressure; stick intervals outside the contact | none |
//! | normal resultant | $\lvert h_xh_y\sum p_k - P\rvert / P$ on a 3D lattice | [`LATTICE_AREA_TOLERANCE`] |
//! | tangential resultant | $\lvert h_xh_y\sum \mathbf q_k - \mathbf T\rvert / (fP)$ | as coulomb, plus the normal resultant's |
//! | moment resultant | moment of the lattice traction about the centre of pressure against M, over the spin scale $f P \bar r$ | as tangential |
//! | residual | the iterative solver's residual against the requested tolerance | tol |
//! | load balance | wheel on rail: $\lvert\sum_p F_{n,p}\cos\delta_p - F_z\rvert / F_z$ | [`WHEEL_LOAD_TOLERANCE`] |
//! | patches | wheel on rail: every patch with $F_n > 0$, area $> 0$, $\lvert\delta\rvert < 90°$ | none fails |
//! | lattice sampling | $\lvert\lambda - 1\rvert$ of a closed form shown on the lattice | [`SAMPLING_TOLERANCE`] |

use super::outcome::{Audit, Check, Outcome, SurfaceOut};
use super::Ctx;
use crate::plan::patches::LATTICE_AREA_TOLERANCE;
use crate::plan::recipe::{
    ContactRecipe, GridStep, Recipe, RollingMethod, RollingModel, RollingStep, Tangential,
};
use crate::plan::Plan;

/// How far the stick correction of a closed form shown on a lattice may be scaled to make the
/// lattice resultant exact (`exec/friction.rs`, `sample_consistently`): $|\lambda - 1|$ is the
/// lattice's discretisation error of that correction, the same kind of error a grid solver
/// on that lattice makes (seed 002's 80-element circle: a few per cent). Beyond a quarter the
/// lattice no longer resolves the stick zone (a 4 x 4 lattice under Lubkin's torsion: 0.85)
/// and the run is refused with `solver.grid`. Coulomb's law holds on the lattice for any
/// $0 \le \lambda \le 2$ whatever this limit.
pub const SAMPLING_TOLERANCE: f64 = 0.25;

/// How far the sum of a wheel's patches' vertical normal-force components may be from the
/// given vertical wheel load (relative): ten times the wheel-rail solver's load tolerance
/// ($10^{-7}$).
pub const WHEEL_LOAD_TOLERANCE: f64 = 1e-6;

struct Builder(Vec<Check>);

impl Builder {
    fn at_most(&mut self, name: &'static str, value: f64, limit: f64, what: impl Into<String>) {
        let pass = value <= limit;
        self.0.push(Check { name, value, limit, pass, what: what.into() });
    }

    fn above(&mut self, name: &'static str, value: f64, limit: f64, what: impl Into<String>) {
        let pass = value > limit;
        self.0.push(Check { name, value, limit, pass, what: what.into() });
    }
}

/// The Coulomb limit, resultant limit and residual limit of the plan's method.
fn limits(plan: &Plan) -> (f64, Option<f64>) {
    match &plan.recipe {
        Recipe::Contact(ContactRecipe { history: Some(h), .. }) => {
            (h.tolerance.max(1e-9), Some(h.tolerance))
        }
        Recipe::Contact(ContactRecipe {
            tangential: Some(Tangential::Grid(GridStep { tolerance, .. })),
            ..
        }) => (tolerance.max(1e-9), Some(*tolerance)),
        Recipe::Contact(ContactRecipe {
            tangential:
                Some(Tangential::Rolling(RollingStep {
                    method: RollingMethod::Exact | RollingMethod::Transient,
                    tolerance,
                    ..
                })),
            ..
        }) => (tolerance.max(1e-9), Some(*tolerance)),
        Recipe::WheelRail(r) => match r.tangential {
            stickslip_wheelrail::Tangential::Exact { tolerance } => {
                (tolerance.max(1e-9), Some(tolerance))
            }
            _ => (1e-9, None),
        },
        Recipe::Rolling(r) => match r.model {
            RollingModel::Goryacheva { stress, .. } => ((100.0 * stress.tol.rel()).max(1e-9), None),
            RollingModel::Carter(_) => (1e-12, None),
        },
        _ => (1e-12, None),
    }
}

fn friction_of(plan: &Plan) -> f64 {
    match &plan.recipe {
        Recipe::Line(r) => r.friction_coefficient,
        Recipe::Rolling(r) => match r.model {
            RollingModel::Carter(p) => p.friction(),
            RollingModel::Goryacheva { params, .. } => params.friction(),
        },
        Recipe::Contact(r) => r.friction,
        Recipe::WheelRail(r) => r.friction,
    }
}

/// Run every check of `out`.
#[allow(clippy::too_many_lines)]
pub(crate) fn audit(plan: &Plan, out: &Outcome, cx: &Ctx<'_>) -> Audit {
    let mut b = Builder(Vec::new());
    let bad = out.first_non_finite();
    b.at_most(
        "finite",
        f64::from(u8::from(bad.is_some())),
        0.0,
        match &bad {
            Some(path) => format!("the first non-finite number is at {path}"),
            None => "every number is finite".to_string(),
        },
    );
    let c = &out.contact;
    let two_d = matches!(plan.recipe, Recipe::Line(_) | Recipe::Rolling(_));
    let length = if two_d { c.a + c.b } else { c.a.min(c.b) };
    // An adhesive contact may pull (a negative load) and may have let go (no contact).
    let adhesive = matches!(
        &plan.recipe,
        Recipe::Contact(ContactRecipe {
            normal: crate::plan::recipe::ContactNormal::Surface { adhesion: Some(_), .. },
            ..
        })
    );
    if adhesive {
        b.at_most(
            "sizes",
            -c.a.min(c.b),
            0.0,
            "the extents of the contact are not negative (an adhesive contact may pull, and may have let go)",
        );
    } else {
        b.above(
            "positive sizes",
            length.min(c.b).min(c.p0).min(c.normal_load),
            0.0,
            if two_d {
                "the smallest of the contact length a + b, b, p0 and the normal load (a may be negative in rolling: the trailing edge ahead of the axis)"
            } else {
                "the smallest of the semi-axes, p0 and the normal load"
            },
        );
    }
    let f = friction_of(plan);
    let (coulomb_limit, residual_limit) = limits(plan);
    let scale = if f > 0.0 { f * c.p0 } else { c.p0 };
    // An adhesive contact that has let go has no compressive peak.
    let scale = if adhesive { scale.abs().max(f64::MIN_POSITIVE) } else { scale };
    if let Recipe::Contact(ContactRecipe {
        normal: crate::plan::recipe::ContactNormal::Surface { hardness: Some(h), .. },
        ..
    }) = &plan.recipe
    {
        b.at_most(
            "hardness",
            c.p0 / h - 1.0,
            0.0,
            "the peak pressure over the hardness, less 1 (the cap holds)",
        );
    }
    match &out.surface {
        SurfaceOut::Line { x, p, q, .. } if !x.is_empty() => {
            let worst = p
                .iter()
                .zip(q)
                .map(|(p, q)| (q.abs() - f * p) / scale)
                .fold(f64::NEG_INFINITY, f64::max);
            b.at_most(
                "coulomb",
                worst,
                coulomb_limit,
                "max over the surface points of (|q| - f p)/(f p0)",
            );
        }
        SurfaceOut::Grid { x, y, p, qx, qy, stick, .. } if !x.is_empty() => {
            let (mut worst, mut stick_outside) = (f64::NEG_INFINITY, 0usize);
            let (mut sp, mut sx, mut sy, mut spx, mut spy) = (0.0, 0.0, 0.0, 0.0, 0.0);
            let mut sabs = 0.0;
            for i in 0..x.len() {
                for j in 0..y.len() {
                    let q = qx[i][j].hypot(qy[i][j]);
                    // Tension (adhesion) carries no friction.
                    worst = worst.max((q - f * p[i][j].max(0.0)) / scale);
                    if stick[i][j] == 1 && p[i][j] <= 0.0 {
                        stick_outside += 1;
                    }
                    sp += p[i][j];
                    sabs += p[i][j].abs();
                    spx += p[i][j] * x[i];
                    spy += p[i][j] * y[j];
                    sx += qx[i][j];
                    sy += qy[i][j];
                }
            }
            let hx = if x.len() > 1 { x[1] - x[0] } else { 0.0 };
            let hy = if y.len() > 1 { y[1] - y[0] } else { 0.0 };
            let area = hx * hy;
            b.at_most(
                "coulomb",
                worst,
                coulomb_limit,
                "max over the lattice cells of (|q| - f p)/(f p0)",
            );
            b.at_most(
                "stick inside contact",
                stick_outside as f64,
                0.0,
                "stick cells without pressure",
            );
            let normal_error = if adhesive {
                // (0 when the bodies have let go entirely: no pressure, no load)
                let d = c.normal_load.abs().max(sabs * area);
                if d > 0.0 {
                    (sp * area - c.normal_load).abs() / d
                } else {
                    (sp * area - c.normal_load).abs()
                }
            } else {
                (sp * area - c.normal_load).abs() / c.normal_load
            };
            b.at_most(
                "normal resultant",
                normal_error,
                LATTICE_AREA_TOLERANCE,
                if adhesive {
                    "|lattice normal force - P| / max(|P|, lattice sum of |p| dA)"
                } else {
                    "|lattice normal force - P| / P"
                },
            );
            let distribution = !matches!(
                plan.recipe,
                Recipe::Contact(ContactRecipe {
                    tangential: Some(Tangential::Rolling(RollingStep {
                        method: RollingMethod::Polach,
                        ..
                    })),
                    ..
                })
            );
            if distribution
                && f > 0.0
                && (out.forces.tangential != 0.0 || out.forces.moment != 0.0 || sx != 0.0)
            {
                let cap = f * c.normal_load;
                let t = out.forces.tangential;
                let (ex, ey) = grid_direction(plan);
                // 3D rolling reports the creep force on the indenter as (fx, fy), and the
                // lattice carries the traction on the substrate: -(fx, fy); otherwise T along
                // its direction.
                let (tx, ty) = match (out.forces.fx, out.forces.fy) {
                    (Some(fx), Some(fy)) => (-fx, -fy),
                    _ => (t * ex, t * ey),
                };
                let err = (sx * area - tx).hypot(sy * area - ty) / cap;
                b.at_most(
                    "tangential resultant",
                    err,
                    coulomb_limit + f64::max(normal_error, 1e-12),
                    "|lattice traction resultant - T| / (f P)",
                );
                let (cx0, cy0) = if sp > 0.0 { (spx / sp, spy / sp) } else { (0.0, 0.0) };
                let mut mz = 0.0;
                let mut rbar = 0.0;
                for i in 0..x.len() {
                    for j in 0..y.len() {
                        let (dx, dy) = (x[i] - cx0, y[j] - cy0);
                        mz += dx * qy[i][j] - dy * qx[i][j];
                        rbar += p[i][j] * dx.hypot(dy);
                    }
                }
                let spin = if sp > 0.0 { f * c.normal_load * rbar / sp } else { 1.0 };
                // With a force alone the moment is not prescribed (no rotation is imposed);
                // 3D rolling reports its spin moment mz.
                let moment = out.forces.mz.map_or(out.forces.moment, |mz| -mz);
                if moment != 0.0 {
                    b.at_most(
                        "moment resultant",
                        (mz * area - moment).abs() / spin,
                        coulomb_limit + f64::max(normal_error, 1e-12),
                        "|lattice moment about the centre of pressure - M| / (f P r_mean)",
                    );
                }
            }
        }
        _ => {}
    }
    if let Some(w) = &out.wheel_rail {
        if f > 0.0 {
            if let Some(worst) = w.patches.iter().filter_map(|p| p.coulomb).reduce(f64::max) {
                b.at_most(
                    "coulomb",
                    worst,
                    coulomb_limit,
                    "max over the patches' contact cells of (|q| - f p)/(f pmax)",
                );
            }
        }
        match (w.vertical_load, w.vertical) {
            (Some(load), Some("total")) => b.at_most(
                "load balance",
                (w.total_on_rail.fz - load).abs() / load,
                WHEEL_LOAD_TOLERANCE,
                "|the total vertical force of the wheel on the rail (creep forces included) - the vertical wheel load| / the load",
            ),
            (Some(load), _) => b.at_most(
                "load balance",
                (w.normal_vertical - load).abs() / load,
                WHEEL_LOAD_TOLERANCE,
                "|sum over the patches of Fn cos(delta) - the vertical wheel load| / the load",
            ),
            _ => {}
        }
        let contact_angles_ok = w.patches.iter().all(|p| {
            p.contact_angle.abs() < std::f64::consts::FRAC_PI_2 && p.fn_ > 0.0 && p.area > 0.0
        });
        b.at_most(
            "patches",
            f64::from(u8::from(!contact_angles_ok)),
            0.0,
            "every patch presses the rail (Fn > 0, area > 0) with |contact angle| < 90 deg",
        );
    }
    let inside = |iv: &[[f64; 2]]| {
        iv.iter().all(|s| {
            s[0] >= -c.a * (1.0 + 1e-12) - 1e-300 && s[1] <= c.b.max(c.a) * (1.0 + 1e-12) + 1e-300
        })
    };
    if out.zones.coordinate == "x" {
        b.at_most(
            "stick inside contact",
            f64::from(u8::from(!inside(&out.zones.stick))),
            0.0,
            "stick intervals outside the contact (-a, b)",
        );
    }
    if let Some(tol) = residual_limit {
        b.at_most(
            "residual",
            out.solver.residual,
            tol,
            "the grid solver's residual against the requested tolerance",
        );
    }
    if let Some(lambda) = cx.sampling {
        b.at_most(
            "lattice sampling",
            (lambda - 1.0).abs(),
            SAMPLING_TOLERANCE,
            "|lambda - 1| of the closed form shown on the lattice (its discretisation error)",
        );
    }
    let passed = b.0.iter().all(|c| c.pass);
    Audit { passed, checks: b.0 }
}

/// The unit direction of the tangential force of a 3D recipe.
fn grid_direction(plan: &Plan) -> (f64, f64) {
    let d = match &plan.recipe {
        Recipe::Contact(ContactRecipe { history: Some(h), .. }) => h.direction,
        Recipe::Contact(r) => match r.tangential {
            Some(Tangential::Mindlin { force } | Tangential::Cattaneo { force, .. }) => {
                force.direction - if force.signed < 0.0 { std::f64::consts::PI } else { 0.0 }
            }
            Some(Tangential::Grid(g)) => match g.force {
                Some(force) => {
                    force.direction - if force.signed < 0.0 { std::f64::consts::PI } else { 0.0 }
                }
                None => g.direction,
            },
            Some(Tangential::Sliding { angle }) => angle,
            _ => 0.0,
        },
        _ => 0.0,
    };
    (d.cos(), d.sin())
}
