//! Line-contact surface arrays: pressure, shear traction and the substrate's surface
//! displacements along x (closed forms for a homogeneous substrate, the graded kernels by
//! quadrature for a graded one).

use stickslip_graded::SurfaceDisplacement;
use stickslip_halfspace::hertz::strip::{self, Strip};

use super::friction::LineTraction;
use super::normal::LineContact;
use super::outcome::SurfaceOut;
use super::{linspace, solver_err, Ctx};
use crate::plan::recipe::{LineDisplacements, LineSurface};
use stickslip_scene::SceneError;

/// The surface arrays (empty when not asked for) and, on a graded substrate under a
/// tangential load, the absolute u_x of the stick zone (at x = 0).
pub(crate) fn line(
    s: Option<LineSurface>,
    n: &LineContact,
    t: &LineTraction,
    cx: &mut Ctx<'_>,
) -> Result<(SurfaceOut, Option<f64>), SceneError> {
    let Some(s) = s else {
        let empty = SurfaceOut::Line {
            x: vec![],
            p: vec![],
            q: vec![],
            ux: vec![],
            uy: vec![],
            datum: String::new(),
        };
        return Ok((empty, None));
    };
    let a = n.a;
    let friction = t.kind.is_some();
    let xs = linspace(-1.5 * a, 1.5 * a, s.points);
    let (mut ps, mut qs) = (Vec::with_capacity(xs.len()), Vec::with_capacity(xs.len()));
    for &x in &xs {
        ps.push(n.pressure(x));
        cx.ev.normal_contact += 1;
        if friction {
            qs.push(t.q(x, n));
            cx.ev.friction += 1;
        } else {
            qs.push(0.0);
        }
    }
    let (mut uxs, mut uys) = (Vec::new(), Vec::new());
    let mut rigid = None;
    let datum = match s.displacements {
        LineDisplacements::Graded { material, accuracy } => {
            let sd = SurfaceDisplacement::new(&material, t.surface_load(n)?, accuracy)
                .map_err(|e| solver_err("graded surface displacement", e))?;
            for (i, &x) in xs.iter().enumerate() {
                let d =
                    sd.displacement(x).map_err(|e| solver_err("graded surface displacement", e))?;
                uxs.push(d.x);
                uys.push(d.y);
                cx.ev.grading += 1;
                if i % 20 == 0 {
                    cx.progress("surface displacements", i, xs.len());
                }
            }
            if friction {
                let d = sd
                    .displacement(0.0)
                    .map_err(|e| solver_err("graded surface displacement", e))?;
                cx.ev.grading += 1;
                rigid = Some(d.x);
            }
            "absolute: measured from the undisturbed surface at infinity (graded, k > 0; FORMULAS.md A3)".to_string()
        }
        LineDisplacements::Homogeneous { substrate } => {
            let pressure = Strip { half_width: a, peak: n.p0 };
            for &x in &xs {
                let (ux, uy) = strip::surface_displacement(x, pressure, &t.shear, &substrate);
                uxs.push(ux);
                uys.push(uy);
            }
            "substrate only; logarithmic parts relative to the surface point x = 0, odd (step) parts absolute (2D half-plane displacements are defined up to a constant; FORMULAS.md B)".to_string()
        }
        LineDisplacements::None => "not computed for the flat punch".to_string(),
    };
    Ok((SurfaceOut::Line { x: xs, p: ps, q: qs, ux: uxs, uy: uys, datum }, rigid))
}
