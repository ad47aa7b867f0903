//! Stage 6, subsurface field of a line contact: the McEwen / Muskhelishvili closed form, or
//! full integration of the line-load kernels (graded, or Flamant's at k = 0).

use stickslip_graded::StressField;
use stickslip_halfspace::mcewen::HertzTraction;
use stickslip_halfspace::Stress2;

use super::friction::LineTraction;
use super::normal::LineContact;
use super::outcome::FieldOut;
use super::{linspace, solver_err, Ctx};
use crate::error::SceneError;
use crate::plan::recipe::{LineField, LineFieldMethod, LineFriction};
use crate::scene::FieldScale;

/// The stresses on the field grid (empty arrays when not asked for).
pub(crate) fn line(
    field: Option<&LineField>,
    n: &LineContact,
    t: &LineTraction,
    cx: &mut Ctx<'_>,
) -> Result<FieldOut, SceneError> {
    let mut out = FieldOut::default();
    let Some(field) = field else { return Ok(out) };
    let fg = field.grid;
    let a = n.a;
    let scale = match fg.scale {
        FieldScale::HalfWidth => a,
        FieldScale::Metres => 1.0,
    };
    out.x = linspace(fg.x.0 * scale, fg.x.1 * scale, fg.x.2);
    out.y = linspace(fg.y.0 * scale, fg.y.1 * scale, fg.y.2);
    let ny = out.y.len();
    let quad = match field.method {
        LineFieldMethod::Quadrature { material, accuracy } => Some(
            StressField::new(&material, t.surface_load(n)?, accuracy)
                .map_err(|e| solver_err("stress field", e))?,
        ),
        LineFieldMethod::McEwen => None,
    };
    let sliding = match t.kind {
        Some(LineFriction::Sliding { friction }) => friction * n.p0,
        _ => 0.0,
    };
    let mcewen = HertzTraction::new(a, n.p0, sliding).map_err(|e| solver_err("McEwen field", e))?;
    let graded = n.graded.is_some();
    for (j, &y) in out.y.iter().enumerate() {
        let row: Vec<Stress2> = match &quad {
            Some(sf) => sf.grid(&out.x, &[y]).map_err(|e| solver_err("stress field", e))?,
            None => out
                .x
                .iter()
                .map(|&x| match &t.cattaneo {
                    Some(c) => c.stress(x, y),
                    None => mcewen.stress(x, y),
                })
                .collect::<Result<_, _>>()
                .map_err(|e| solver_err("McEwen field", e))?,
        };
        cx.ev.subsurface_field += row.len() as u64;
        if graded {
            cx.ev.grading += row.len() as u64;
        }
        out.sxx.push(row.iter().map(|s| s.xx).collect());
        out.syy.push(row.iter().map(|s| s.yy).collect());
        out.sxy.push(row.iter().map(|s| s.xy).collect());
        cx.progress("subsurface field", j + 1, ny);
    }
    Ok(out)
}
