//! The closed forms a plot draws beside a result (the report crate draws them).
//!
//! A reference is drawn only when the planned scene is exactly the closed form's case:
//! Hertz pressure for a homogeneous cylinder, sphere or ellipse (not a surface, patches or a
//! graded substrate); the 2D Cattaneo–Mindlin traction of a Hertz cylinder; Mindlin's (a
//! sphere) or Cattaneo's (an ellipse) traction under a tangential force alone; Carter's
//! elastic rolling; the Mindlin–Deresiewicz loop of a load cycle. The formulas are the
//! library's (stickslip-halfspace, -traction, -rolling); nothing is retyped here.
//!
//! Where the solver evaluated that same closed form (the planned method is the closed form),
//! the reference lies on the result by construction and shows only that the arrays were
//! plotted in the right place; where a numerical solver ran (the grid solvers under a
//! force on a sphere) it is an independent check.

use stickslip_halfspace::cattaneo2d::Cattaneo2d;
use stickslip_halfspace::hertz::{HertzEllipse, HertzLine, HertzSphere};
use stickslip_traction::{closed::Cattaneo, closed::Deresiewicz, closed::Mindlin};

use crate::exec::outcome::Outcome;
use crate::plan::recipe::{
    ContactNormal, ContactRecipe, HistoryRecipe, LineFriction, LineNormal, Recipe, RollingModel,
    Tangential,
};
use crate::plan::Plan;

/// A closed form of a surface quantity at (x, y) (y is ignored in 2D), with its legend label.
pub struct Reference {
    /// The legend label, e.g. "Hertz".
    pub label: &'static str,
    /// The value at (x, y) (m).
    pub at: Box<dyn Fn(f64, f64) -> f64>,
}

/// The references of one scene.
#[derive(Default)]
pub struct References {
    /// The contact pressure p.
    pub pressure: Option<Reference>,
    /// The shear traction: signed q along x in 2D, the magnitude |q| in 3D.
    pub traction: Option<Reference>,
    /// The hysteresis loop (relative displacement, T), densely sampled.
    pub cycle: Option<(Vec<f64>, Vec<f64>)>,
    /// A load path on the Hertz circle at a constant normal load whose tangential force
    /// swings between $-T^*$ and $T^*$: Mindlin's first loading from zero to $T^*$ and the
    /// Mindlin–Deresiewicz loop (relative displacement, T).
    pub history_loop: Option<(Vec<f64>, Vec<f64>)>,
    /// The load curve of a sphere profile on a lattice (a load sweep or an approach path):
    /// its label ("Hertz", or "Maugis" under adhesion) and (approach, force) over the
    /// approaches the curve spans.
    pub load_curve: Option<(&'static str, Vec<f64>, Vec<f64>)>,
}

fn reference(label: &'static str, at: impl Fn(f64, f64) -> f64 + 'static) -> Option<Reference> {
    Some(Reference { label, at: Box::new(at) })
}

/// The references of the planned scene `plan` whose result is `out`.
pub fn of(plan: &Plan, out: &Outcome) -> References {
    match &plan.recipe {
        Recipe::Line(r) => {
            let LineNormal::Hertz { radius, load, bodies } = r.normal else {
                return References::default();
            };
            let es = bodies.e_star;
            let h = match load {
                crate::plan::recipe::LineLoad::HalfWidth(a) => {
                    HertzLine::from_half_width(a, radius, es)
                }
                crate::plan::recipe::LineLoad::Force(p) => HertzLine::new(p, radius, es),
            };
            let Ok(h) = h else { return References::default() };
            let traction = match r.friction {
                Some(LineFriction::Cattaneo { friction, tangential }) => {
                    Cattaneo2d::new(h.half_width(), h.max_pressure(), friction, tangential)
                        .ok()
                        .and_then(|c| reference("Cattaneo-Mindlin", move |x, _| c.traction(x)))
                }
                _ => None,
            };
            References {
                pressure: reference("Hertz", move |x, _| h.pressure(x)),
                traction,
                cycle: None,
                history_loop: None,
                load_curve: None,
            }
        }
        Recipe::Rolling(r) => match r.model {
            RollingModel::Carter(cp) => {
                let s = stickslip_rolling::carter(&cp);
                let s2 = s;
                References {
                    pressure: reference("Hertz", move |x, _| s.pressure(x)),
                    traction: reference("Carter", move |x, _| s2.shear(x)),
                    cycle: None,
                    history_loop: None,
                    load_curve: None,
                }
            }
            RollingModel::Goryacheva { .. } => References::default(),
        },
        Recipe::Contact(r) => contact(r, out),
        Recipe::WheelRail(_) => References::default(),
    }
}

fn contact(r: &ContactRecipe, out: &Outcome) -> References {
    let mut refs = References::default();
    match r.normal {
        ContactNormal::Sphere { radius, force, e_star } => {
            // A load path ends at its last normal load.
            let force = if r.history.is_some() { out.contact.normal_load } else { force };
            let Ok(h) = HertzSphere::new(force, radius, e_star) else { return refs };
            let a = h.contact_radius();
            refs.pressure = reference("Hertz", move |x, y| h.pressure(x.hypot(y)));
            // a tangential force alone (no moment, no rolling) on the Hertz circle
            let q = match r.tangential {
                Some(Tangential::Mindlin { force: q }) => Some(q.magnitude),
                Some(Tangential::Grid(g)) if g.moment.is_none() => g.force.map(|q| q.magnitude),
                _ => None,
            };
            if let Some(q) = q.filter(|q| *q > 0.0 && r.friction > 0.0) {
                if let Ok(m) = Mindlin::new(a, force, r.friction, q) {
                    refs.traction = reference("Mindlin", move |x, y| m.traction(x.hypot(y)).abs());
                }
            }
            if let Some(h) = &r.history {
                refs.history_loop = history_loop(r, h, a, force);
            }
            if let (Some(_), Some(c)) = (r.cycle, &out.cycle) {
                if let Ok(d) = Deresiewicz::new(a, force, r.friction, c.amplitude) {
                    let n = 200;
                    let [sub, ind] = &r.bodies.pair();
                    if let (Ok(l1), Ok(l2)) = (d.hysteresis_loop(sub, n), d.hysteresis_loop(ind, n))
                    {
                        refs.cycle = Some((
                            l1.iter().zip(&l2).map(|(p, q)| p.1 + q.1).collect(),
                            l1.iter().map(|p| p.0).collect(),
                        ));
                    }
                }
            }
        }
        ContactNormal::Ellipse { rx, ry, force, e_star } => {
            let force = if r.history.is_some() { out.contact.normal_load } else { force };
            let Ok(h) = HertzEllipse::new(rx, ry, force, e_star) else { return refs };
            let (ax, ay) = (h.semi_axis_x(), h.semi_axis_y());
            refs.pressure = reference("Hertz", move |x, y| h.pressure(x, y));
            refs.traction = cattaneo(r, ax, ay, force);
        }
        ContactNormal::EllipseGiven { a, b, force } => {
            refs.traction = cattaneo(r, a, b, force);
        }
        ContactNormal::Surface { ref surface, adhesion, .. } => {
            refs.load_curve = sphere_curve(surface, adhesion, r.bodies.e_star, out);
        }
        _ => {}
    }
    refs
}

/// The closed-form load curve of a smooth sphere profile on a free lattice over the
/// approaches of `out.load_curve`: Hertz's force at the contact radius $\sqrt{R\delta}$, or under
/// adhesion Maugis's curve (stickslip-halfspace `adhesion`) from the large contact to the
/// vanishing one.
fn sphere_curve(
    s: &stickslip_scene::Surface,
    adhesion: Option<stickslip_scene::AdhesionKeys>,
    e_star: f64,
    out: &Outcome,
) -> Option<(&'static str, Vec<f64>, Vec<f64>)> {
    let stickslip_scene::Profile::Sphere { radius } = s.profile else { return None };
    if s.roughness.is_some() || s.boundary != stickslip_scene::SurfaceBoundary::Free {
        return None;
    }
    let c = out.load_curve.as_ref()?;
    let lo = c.approach.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = c.approach.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if let Some(a) = adhesion {
        let m = stickslip_halfspace::adhesion::MaugisSphere::new(radius, a.work, a.range, e_star)
            .ok()?;
        let (d, p): (Vec<f64>, Vec<f64>) = m
            .curve(2000)
            .into_iter()
            .filter(|q| q.approach >= lo && q.approach <= hi)
            .map(|q| (q.approach, q.force))
            .unzip();
        return (d.len() > 1).then_some(("Maugis", d, p));
    }
    let lo = lo.max(0.0);
    let n = 200;
    let d: Vec<f64> = (0..=n).map(|i| lo + (hi - lo) * i as f64 / n as f64).collect();
    // Hertz: a = sqrt(R d), and the load of that contact radius.
    let p = d
        .iter()
        .map(|&d| {
            let a = (radius * d).sqrt();
            if a > 0.0 {
                HertzSphere::load_for_contact_radius(a, radius, e_star)
            } else {
                0.0
            }
        })
        .collect();
    (hi > lo).then_some(("Hertz", d, p))
}

/// Cattaneo's traction magnitude on the Hertz ellipse of semi-axes `ax`, `ay` under the
/// normal force `force`, when a tangential force alone acts along one of the axes.
fn cattaneo(r: &ContactRecipe, ax: f64, ay: f64, force: f64) -> Option<Reference> {
    let (q, along_x) = match r.tangential {
        Some(Tangential::Cattaneo { force: q, along_x }) => (q, along_x),
        Some(Tangential::Grid(g)) if g.moment.is_none() => {
            let q = g.force?;
            // along an axis to rounding: the direction is a multiple of pi/2
            let k = q.direction / std::f64::consts::FRAC_PI_2;
            if (k - k.round()).abs() > 1e-12 {
                return None;
            }
            (q, (k.round() as i64) % 2 == 0)
        }
        _ => return None,
    };
    if !(q.magnitude > 0.0 && r.friction > 0.0) {
        return None;
    }
    // the first semi-axis is the one along the load
    let (al, ac) = if along_x { (ax, ay) } else { (ay, ax) };
    let c = Cattaneo::new(al, ac, force, r.friction, q.magnitude).ok()?;
    reference("Cattaneo", move |x, y| {
        let (u, v) = if along_x { (x, y) } else { (y, x) };
        c.traction(u, v).abs()
    })
}

/// Mindlin's first loading and the Mindlin–Deresiewicz loop of a force-controlled path on the
/// Hertz circle of radius `a` under the constant normal load `force`, when its corners swing
/// symmetrically between $-T^*$ and $T^*$ (FORMULAS.md E; relative displacement, both
/// bodies).
fn history_loop(
    r: &ContactRecipe,
    h: &HistoryRecipe,
    a: f64,
    force: f64,
) -> Option<(Vec<f64>, Vec<f64>)> {
    let constant = h.normal.iter().all(|p| (p - force).abs() <= 1e-9 * force);
    let force_control = h.control == stickslip_scene::HistoryControl::Force;
    let hi = h.tangential.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let lo = h.tangential.iter().copied().fold(f64::INFINITY, f64::min);
    if !(constant && force_control && h.moment.is_none() && hi > 0.0 && lo == -hi) {
        return None;
    }
    let d = Deresiewicz::new(a, force, r.friction, hi).ok()?;
    let [sub, ind] = &r.bodies.pair();
    let n = 200;
    let (l1, l2) = (d.hysteresis_loop(sub, n).ok()?, d.hysteresis_loop(ind, n).ok()?);
    let (mut x, mut y) = (Vec::new(), Vec::new());
    for i in 0..=n {
        let t = hi * i as f64 / n as f64;
        let m = Mindlin::new(a, force, r.friction, t).ok()?;
        x.push(m.compliance_relative(sub, ind));
        y.push(t);
    }
    x.extend(l1.iter().zip(&l2).map(|(p, q)| p.1 + q.1));
    y.extend(l1.iter().map(|p| p.0));
    Some((x, y))
}

#[cfg(test)]
mod tests {
    use super::{of, References};
    use crate::{Execute, Outcome, Plan, RunOptions};
    use stickslip_scene::Scene;

    fn run(name: &str) -> (References, Outcome) {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../scenes")
            .join(format!("{name}.toml"));
        let plan = Plan::new(&Scene::from_file(&path).unwrap()).unwrap();
        let out = plan.execute(&RunOptions::default()).unwrap();
        (of(&plan, &out), out)
    }

    fn labels(r: &References) -> (Option<&str>, Option<&str>, bool) {
        (
            r.pressure.as_ref().map(|r| r.label),
            r.traction.as_ref().map(|r| r.label),
            r.cycle.is_some(),
        )
    }

    /// ∫ f over (-a, a) by the midpoint rule in x = a sin θ (the square-root edges of the
    /// contact closed forms become smooth).
    fn line_integral(f: impl Fn(f64) -> f64, a: f64, n: usize) -> f64 {
        let h = std::f64::consts::PI / n as f64;
        (0..n)
            .map(|k| {
                let t = -std::f64::consts::FRAC_PI_2 + (k as f64 + 0.5) * h;
                f(a * t.sin()) * a * t.cos() * h
            })
            .sum()
    }

    /// ∫ 2 π r f(r) dr over (0, a) by the midpoint rule in r = a sin θ, θ in (0, π/2)
    /// (second order: the error is O(n⁻²)).
    fn disc_integral(f: impl Fn(f64) -> f64, a: f64, n: usize) -> f64 {
        let h = std::f64::consts::FRAC_PI_2 / n as f64;
        (0..n)
            .map(|k| {
                let t = (k as f64 + 0.5) * h;
                let r = a * t.sin();
                2.0 * std::f64::consts::PI * r * f(r) * a * t.cos() * h
            })
            .sum()
    }

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs()
    }

    /// A reference is drawn in its own case only, and it carries the scene's load: its
    /// integral over the contact is the normal (or tangential) load of the result, an
    /// equilibrium identity between the closed form and the solver's resultants.
    #[test]
    fn references_only_in_their_cases_and_in_equilibrium() {
        let (r, out) = run("hertz_cylinder_cattaneo");
        assert_eq!(labels(&r), (Some("Hertz"), Some("Cattaneo-Mindlin"), false));
        let a = out.contact.a;
        let p = r.pressure.as_ref().unwrap();
        let q = r.traction.as_ref().unwrap();
        let e = rel(line_integral(|x| (p.at)(x, 0.0), a, 4000), out.contact.normal_load);
        assert!(e < 1e-9, "2D Hertz: integral of p off the load by {e:.2e}");
        let e = rel(line_integral(|x| (q.at)(x, 0.0), a, 4000), out.forces.tangential);
        assert!(e < 1e-5, "2D Cattaneo-Mindlin: integral of q off the load by {e:.2e}");

        let (r, out) = run("carter_steel_rolling");
        assert_eq!(labels(&r), (Some("Hertz"), Some("Carter"), false));
        let a = out.contact.a;
        let q = r.traction.as_ref().unwrap();
        let e = rel(line_integral(|x| (q.at)(x, 0.0), a, 4000), out.forces.tangential);
        assert!(e < 1e-5, "Carter: integral of q off the creep force by {e:.2e}");

        // a numerical grid solver (the LP) under a force on a sphere: Mindlin beside it
        let (r, out) = run("seed002_ex1_lp");
        assert_eq!(labels(&r), (Some("Hertz"), Some("Mindlin"), false));
        let a = out.contact.a;
        let p = r.pressure.as_ref().unwrap();
        let q = r.traction.as_ref().unwrap();
        let e = rel(disc_integral(|x| (p.at)(x, 0.0), a, 100_000), out.contact.normal_load);
        assert!(e < 1e-9, "Hertz sphere: integral of p off the load by {e:.2e}");
        let e = rel(disc_integral(|x| (q.at)(x, 0.0), a, 100_000), out.forces.tangential.abs());
        assert!(e < 1e-5, "Mindlin: integral of q off the tangential load by {e:.2e}");

        let (r, out) = run("sphere_load_cycle");
        assert!(labels(&r).2);
        let (_, t) = r.cycle.as_ref().unwrap();
        let amp = out.cycle.as_ref().unwrap().amplitude;
        let top = t.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(rel(top, amp) < 1e-12, "the loop reaches T* = {amp}, not {top}");

        // not the closed-form case: a surface, a graded substrate, a viscoelastic roller
        for name in ["sphere_as_surface", "graded_roller_partial_slip", "seed001_goryacheva_rubber"]
        {
            let (r, _) = run(name);
            assert_eq!(labels(&r), (None, None, false), "{name}");
        }
    }
}
