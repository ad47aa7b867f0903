//! Stage 4, rolling: Carter's elastic closed form or Goryacheva's standard-solid rolling,
//! which solve the normal and tangential problems together.

use std::f64::consts::PI;

use stickslip_rolling::Regime as RollRegime;

use super::outcome::{ContactOut, Field, Forces, RigidOut, RollingOut, SurfaceOut, Zones};
use super::{linspace, solver_err, Ctx, Parts};
use crate::plan::recipe::{RollingModel, RollingRecipe};
use stickslip_scene::SceneError;

/// One rolling solve with its surface arrays.
#[allow(clippy::too_many_lines)]
pub(crate) fn run(r: &RollingRecipe, cx: &mut Ctx<'_>) -> Result<Parts, SceneError> {
    let mut xs = Vec::new();
    let (mut ps, mut qs) = (Vec::new(), Vec::new());
    let npts = r.surface_points.map_or(0, |n| n.max(2));
    let (rear, front, stick_start, stick_len, q, m1, mstar, c2, regime, response, p0, load);
    match r.model {
        RollingModel::Goryacheva { params, stress, viscoelastic: visco_on } => {
            let s =
                stickslip_rolling::solve(&params).map_err(|e| solver_err("Goryacheva solve", e))?;
            load = params.load();
            cx.ev.rolling += 1;
            if visco_on {
                cx.ev.viscoelasticity += 1;
            }
            cx.iterations = s.info.length_iterations + s.info.stick_iterations;
            cx.residual = s.info.length_residual.abs().max(s.info.stick_residual.abs());
            rear = s.rear;
            front = s.front;
            stick_start = s.stick_start;
            stick_len = s.stick_length;
            q = s.tangential_force;
            m1 = s.moment_m1;
            mstar = s.rolling_moment;
            c2 = Some(s.c2);
            regime = s.regime;
            response =
                if visco_on { "viscoelastic" } else { "elastic (alpha = beta: solved as Carter)" };
            if !visco_on {
                cx.notes.push("alpha = beta: the standard solid is elastic; Goryacheva's solution reduces to Carter's and is solved as such".to_string());
            }
            let mut pmax: f64 = 0.0;
            if npts > 0 {
                xs = linspace(-rear, front, npts);
                for (i, &x) in xs.iter().enumerate() {
                    let pe =
                        s.pressure(x, &stress).map_err(|e| solver_err("Goryacheva pressure", e))?;
                    let te = s.shear(x, &stress).map_err(|e| solver_err("Goryacheva shear", e))?;
                    cx.ev.normal_contact += 1;
                    cx.ev.rolling += 1;
                    cx.ev.friction += 1;
                    if visco_on {
                        cx.ev.viscoelasticity += (pe.evals + te.evals) as u64;
                    }
                    pmax = pmax.max(pe.value);
                    ps.push(pe.value);
                    qs.push(te.value);
                    if i % 20 == 0 {
                        cx.progress("rolling stresses", i, npts);
                    }
                }
            }
            p0 = if pmax > 0.0 { pmax } else { 2.0 * load / (PI * 0.5 * (rear + front)) };
        }
        RollingModel::Carter(cp) => {
            let s = stickslip_rolling::carter(&cp);
            load = cp.load();
            cx.ev.rolling += 1;
            rear = s.half_width;
            front = s.half_width;
            stick_start = s.stick_start;
            stick_len = s.stick_length;
            q = s.tangential_force;
            m1 = 0.0;
            mstar = s.rolling_moment;
            c2 = None;
            regime = s.regime;
            response = "elastic (Carter)";
            p0 = s.peak_pressure;
            if npts > 0 {
                xs = linspace(-rear, front, npts);
                for &x in &xs {
                    ps.push(s.pressure(x));
                    qs.push(s.shear(x));
                    cx.ev.normal_contact += 1;
                    cx.ev.rolling += 1;
                    cx.ev.friction += 1;
                }
            }
        }
    }
    let regime_s = match regime {
        RollRegime::StickSlip => "stick-slip",
        RollRegime::FullSlip => "full slip",
        RollRegime::FullStick => "full stick",
    };
    let zones = match regime {
        RollRegime::StickSlip => Zones {
            stick: vec![[stick_start, front]],
            slip: vec![[-rear, stick_start]],
            coordinate: "x",
            grid: None,
        },
        RollRegime::FullSlip => {
            Zones { stick: vec![], slip: vec![[-rear, front]], coordinate: "x", grid: None }
        }
        RollRegime::FullStick => {
            Zones { stick: vec![[-rear, front]], slip: vec![], coordinate: "x", grid: None }
        }
    };
    cx.notes.push("rolling: the cylinder moves in +x, the contact is (-a, b) with the trailing edge at -a; q is Goryacheva's tau_xy on the base (FORMULAS.md D); surface displacements are not computed for rolling".to_string());
    let l = rear + front;
    Ok(Parts {
        contact: ContactOut {
            a: rear,
            b: front,
            p0,
            indentation: None,
            normal_load: load,
            area: None,
            fraction: None,
            plastic_fraction: None,
            pull_off: None,
            pull_off_reached: None,
        },
        zones,
        forces: Forces {
            normal: load,
            tangential: q,
            moment: 0.0,
            rolling_moment: mstar,
            fx: None,
            fy: None,
            mz: None,
        },
        rigid: RigidOut { tangential: None, rotation: None, per_body: None },
        surface: SurfaceOut::Line {
            x: xs,
            p: ps,
            q: qs,
            ux: vec![],
            uy: vec![],
            datum: "not computed for rolling".to_string(),
        },
        field: Field::default(),
        rolling: Some(RollingOut {
            l,
            d: 0.5 * (front - rear),
            m: stick_len,
            c: stick_start,
            C2: c2,
            Q: q,
            M1: m1,
            Mstar: mstar,
            regime: regime_s,
            response,
        }),
        cycle: None,
        history: None,
        load_curve: None,
        wheel_rail: None,
    })
}
