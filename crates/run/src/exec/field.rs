//! Stage 6, subsurface field: of a line contact, the McEwen / Muskhelishvili closed form or
//! full integration of the line-load kernels (graded, or Flamant's at k = 0); of a 3D
//! contact, the Hertz sphere's closed form or the lattice traction by FFT per depth layer.

use stickslip_graded::StressField;
use stickslip_halfspace::mcewen::HertzTraction;
use stickslip_halfspace::Stress2;

use stickslip_halfspace::hertz::ellipse_field::HertzLoadField;
use stickslip_halfspace::hertz::sphere_field::hertz_sphere_stress;
use stickslip_halfspace::Stress3;
use stickslip_lattice::{
    field::invariants, field::subsurface_field, field::Boundary as FieldBoundary,
    field::FieldConfig, field::Lattice as FieldLattice, field::StressLayer, field::SurfaceTraction,
};

use super::friction::LineTraction;
use super::lattice::Lattice;
use super::normal::{ContactSolution, LineContact};
use super::outcome::{
    FieldArrays, FieldMax, FieldOut, FieldPeak, VolumeField, INLINE_FIELD_POINTS,
};
use super::{linspace, solver_err, Ctx};
use crate::plan::recipe::{
    ContactField, ContactFieldMethod, LineField, LineFieldMethod, LineFriction,
};
use stickslip_scene::eng::eng;
use stickslip_scene::{FieldScale, SceneError};

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

// ---------------------------------------------------------------------------------------
// 3D

/// The stresses of a 3D contact on the box of `f`: the Hertz sphere's closed form, or the
/// lattice's pressure and traction (on the substrate) by FFT per depth layer
/// (`stickslip_lattice::field`) on a lattice of the contact's cell size extended over the
/// box, interpolated bilinearly between cell centres to the box points.
pub(crate) fn contact(
    f: &ContactField,
    n: &ContactSolution,
    lat: &Lattice,
    periodic: bool,
    cx: &mut Ctx<'_>,
) -> Result<VolumeField, SceneError> {
    let g = f.grid;
    let unit = match g.scale {
        FieldScale::HalfWidth => n.ax,
        FieldScale::Metres => 1.0,
    };
    let zg = g.z.unwrap_or((0.0, 0.0, 1));
    let xs = linspace(g.x.0 * unit, g.x.1 * unit, g.x.2);
    let ys = linspace(g.y.0 * unit, g.y.1 * unit, g.y.2);
    let zs = linspace(zg.0 * unit, zg.1 * unit, zg.2);
    let (nx, ny, nz) = (xs.len(), ys.len(), zs.len());
    let total = nx * ny * nz;
    let mut stresses: Vec<Stress3> = Vec::with_capacity(total);
    let method = match f.method {
        ContactFieldMethod::HertzSphere => {
            for (k, &z) in zs.iter().enumerate() {
                for &y in &ys {
                    for &x in &xs {
                        stresses.push(hertz_sphere_stress(n.ax, n.p0, f.nu, x, y, z));
                    }
                }
                cx.progress("subsurface field", k + 1, nz);
            }
            "Hertz sphere field in closed form".to_string()
        }
        ContactFieldMethod::HertzSliding { friction, angle } => {
            let err = |e| solver_err("sliding Hertz field", e);
            let (c, s) = (angle.cos(), angle.sin());
            let circle = n.ax == n.ay;
            // A circle: Hamilton's field (shear along +x) in axes turned by `angle`. An
            // ellipse: the pressure with the shear f p cos(angle) along x, plus the shear
            // f p sin(angle) along y as the x-shear of the ellipse with its axes swapped,
            // in axes turned by 90 degrees.
            let along = if circle {
                HertzLoadField::new(n.ax, n.ax, n.p0, friction, f.nu).map_err(err)?
            } else {
                HertzLoadField::new(n.ax, n.ay, n.p0, friction * c, f.nu).map_err(err)?
            };
            let across = if circle || s == 0.0 {
                None
            } else {
                Some(
                    HertzLoadField::new(n.ay, n.ax, n.p0, friction * s, f.nu)
                        .map_err(err)?
                        .without_pressure(),
                )
            };
            for (k, &z) in zs.iter().enumerate() {
                for &y in &ys {
                    for &x in &xs {
                        let st = if circle {
                            let local =
                                along.stress(c * x + s * y, -s * x + c * y, z).map_err(err)?;
                            rotate_xy(&local.stress, c, s)
                        } else {
                            let mut st = along.stress(x, y, z).map_err(err)?.stress;
                            if let Some(across) = &across {
                                let l = across.stress(y, -x, z).map_err(err)?.stress;
                                let t = rotate_xy(&l, 0.0, 1.0);
                                st = Stress3 {
                                    xx: st.xx + t.xx,
                                    yy: st.yy + t.yy,
                                    zz: st.zz + t.zz,
                                    xy: st.xy + t.xy,
                                    xz: st.xz + t.xz,
                                    yz: st.yz + t.yz,
                                };
                            }
                            st
                        };
                        stresses.push(st);
                    }
                }
                cx.progress("subsurface field", k + 1, nz);
            }
            format!(
                "sliding Hertz {} (f = {friction}, shear at {:.1} deg) by Hamilton's field as one integral per point and shear direction",
                if circle { "sphere" } else { "ellipse" },
                angle.to_degrees()
            )
        }
        ContactFieldMethod::HertzEllipse => {
            let load = HertzLoadField::new(n.ax, n.ay, n.p0, 0.0, f.nu)
                .map_err(|e| solver_err("Hertz ellipse field", e))?;
            for (k, &z) in zs.iter().enumerate() {
                for &y in &ys {
                    for &x in &xs {
                        let st = load
                            .stress(x, y, z)
                            .map_err(|e| solver_err("Hertz ellipse field", e))?;
                        stresses.push(st.stress);
                    }
                }
                cx.progress("subsurface field", k + 1, nz);
            }
            "Hertz ellipse field as one integral per point (Love's potential)".to_string()
        }
        ContactFieldMethod::Lattice => {
            // A periodic surface: the periodic traction on the surface's own lattice (one
            // period), points taken modulo the period. Otherwise the contact's lattice
            // extended with unloaded cells over the box.
            let (fl, p, qx, qy) =
                if periodic { period_lattice(lat)? } else { extended_lattice(lat, &xs, &ys)? };
            let boundary = if periodic { FieldBoundary::Periodic } else { FieldBoundary::Free };
            let t = SurfaceTraction { p: &p, qx: &qx, qy: &qy };
            cx.progress("subsurface field", 0, nz);
            let config = FieldConfig { boundary, ..FieldConfig::default() };
            let field = subsurface_field(fl, f.nu, &t, &zs, config)
                .map_err(|e| solver_err("subsurface field", e))?;
            cx.progress("subsurface field", nz, nz);
            for layer in &field.layers {
                for &y in &ys {
                    for &x in &xs {
                        stresses.push(interpolate(&fl, layer, x, y, periodic));
                    }
                }
            }
            if periodic {
                format!(
                    "periodic lattice of {} x {} cells of {} x {} (one period of the surface), FFT per depth layer with the periodic half-space transfer, bilinear between cell centres across the period; the mean traction's in-plane stresses (sxx, syy, sxy of the zero frequency) are not determined by a periodic half-space and are left out",
                    fl.nx, fl.ny, eng(fl.hx, "m"), eng(fl.hy, "m")
                )
            } else {
                format!(
                    "lattice of {} x {} cells of {} x {} (the contact's), FFT per depth layer, bilinear between cell centres",
                    fl.nx, fl.ny, eng(fl.hx, "m"), eng(fl.hy, "m")
                )
            }
        }
    };
    cx.ev.subsurface_field += total as u64;
    let mut a = FieldArrays::default();
    let mut peaks: [Option<FieldPeak>; 3] = [None; 3];
    for (idx, s) in stresses.iter().enumerate() {
        let inv = invariants(s);
        a.sxx.push(s.xx);
        a.syy.push(s.yy);
        a.szz.push(s.zz);
        a.sxy.push(s.xy);
        a.syz.push(s.yz);
        a.sxz.push(s.xz);
        a.von_mises.push(inv.von_mises);
        a.tresca.push(inv.tresca);
        let max_principal = inv.principal[0].max(inv.principal[1]).max(inv.principal[2]);
        a.max_principal.push(max_principal);
        let (i, j, k) = (idx % nx, (idx / nx) % ny, idx / (nx * ny));
        let at = |value: f64| FieldPeak { value, x: xs[i], y: ys[j], z: zs[k] };
        let vals = [inv.von_mises, inv.tresca, max_principal];
        for (peak, v) in peaks.iter_mut().zip(vals) {
            if peak.is_none_or(|p| v > p.value) {
                *peak = Some(at(v));
            }
        }
    }
    let none = FieldPeak { value: f64::NAN, x: f64::NAN, y: f64::NAN, z: f64::NAN };
    let max = FieldMax {
        von_mises: peaks[0].unwrap_or(none),
        tresca: peaks[1].unwrap_or(none),
        max_principal: peaks[2].unwrap_or(none),
    };
    Ok(VolumeField {
        x: xs,
        y: ys,
        z: zs,
        shape: [nz, ny, nx],
        method,
        max,
        values: (total <= INLINE_FIELD_POINTS).then(|| a.clone()),
        arrays: a,
    })
}

/// A stress given in axes turned by the angle of cosine `c` and sine `s` about z, in the
/// scene's axes: $\sigma = R\sigma'R^T$ with the columns of $R$ the turned axes.
fn rotate_xy(l: &Stress3, c: f64, s: f64) -> Stress3 {
    Stress3 {
        xx: c * c * l.xx - 2.0 * c * s * l.xy + s * s * l.yy,
        yy: s * s * l.xx + 2.0 * c * s * l.xy + c * c * l.yy,
        xy: c * s * (l.xx - l.yy) + (c * c - s * s) * l.xy,
        zz: l.zz,
        xz: c * l.xz - s * l.yz,
        yz: s * l.xz + c * l.yz,
    }
}

/// The contact lattice extended with unloaded cells of the same size so that every box
/// point lies between cell centres; p, qx, qy per cell (index `j * nx + i`).
#[allow(clippy::type_complexity)]
fn extended_lattice(
    lat: &Lattice,
    xs: &[f64],
    ys: &[f64],
) -> Result<(FieldLattice, Vec<f64>, Vec<f64>, Vec<f64>), SceneError> {
    let step = |v: &[f64]| if v.len() > 1 { v[1] - v[0] } else { 0.0 };
    let (hx, hy) = (step(&lat.x), step(&lat.y));
    if !(hx > 0.0 && hy > 0.0) {
        return Err(solver_err("subsurface field", "the contact lattice has a single cell"));
    }
    let lo = |v: &[f64]| v.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = |v: &[f64]| v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    // cells added before the first contact cell and after the last, one beyond the box
    let before = |c0: f64, b0: f64, h: f64| (((c0 - b0) / h).ceil().max(0.0) as usize) + 1;
    let after = |c1: f64, b1: f64, h: f64| (((b1 - c1) / h).ceil().max(0.0) as usize) + 1;
    let (bx, ax_) = (before(lat.x[0], lo(xs), hx), after(hi(&lat.x), hi(xs), hx));
    let (by, ay_) = (before(lat.y[0], lo(ys), hy), after(hi(&lat.y), hi(ys), hy));
    let (nx, ny) = (lat.x.len() + bx + ax_, lat.y.len() + by + ay_);
    let x0 = lat.x[0] - bx as f64 * hx;
    let y0 = lat.y[0] - by as f64 * hy;
    let fl = FieldLattice::new(nx, ny, hx, hy, x0, y0)
        .map_err(|e| solver_err("subsurface field lattice", e))?;
    let (mut p, mut qx, mut qy) = (vec![0.0; nx * ny], vec![0.0; nx * ny], vec![0.0; nx * ny]);
    for i in 0..lat.x.len() {
        for j in 0..lat.y.len() {
            if lat.stick[i][j] >= 0 {
                let k = (j + by) * nx + (i + bx);
                p[k] = lat.p[i][j];
                qx[k] = lat.qx[i][j];
                qy[k] = lat.qy[i][j];
            }
        }
    }
    Ok((fl, p, qx, qy))
}

/// The stress at (x, y) of `layer`, bilinear between the four surrounding cell centres.
/// One period of a periodic surface's lattice with its tractions (row-major `j * nx + i`).
#[allow(clippy::type_complexity)]
fn period_lattice(
    lat: &Lattice,
) -> Result<(FieldLattice, Vec<f64>, Vec<f64>, Vec<f64>), SceneError> {
    let (nx, ny) = (lat.x.len(), lat.y.len());
    if nx < 2 || ny < 2 {
        return Err(solver_err("subsurface field", "the surface lattice has a single row"));
    }
    let (hx, hy) = (lat.x[1] - lat.x[0], lat.y[1] - lat.y[0]);
    let fl = FieldLattice::new(nx, ny, hx, hy, lat.x[0], lat.y[0])
        .map_err(|e| solver_err("subsurface field lattice", e))?;
    let (mut p, mut qx, mut qy) = (vec![0.0; nx * ny], vec![0.0; nx * ny], vec![0.0; nx * ny]);
    for i in 0..nx {
        for j in 0..ny {
            if lat.stick[i][j] >= 0 {
                let k = j * nx + i;
                p[k] = lat.p[i][j];
                qx[k] = lat.qx[i][j];
                qy[k] = lat.qy[i][j];
            }
        }
    }
    Ok((fl, p, qx, qy))
}

/// Bilinear interpolation between cell centres. On a periodic lattice the point is taken
/// modulo the period and the cells beyond the last centre are the first ones; otherwise it is
/// clamped to the lattice.
fn interpolate(fl: &FieldLattice, layer: &StressLayer, x: f64, y: f64, periodic: bool) -> Stress3 {
    // Lower and upper cell and the weight of the upper one along one axis.
    let axis = |u: f64, n: usize| -> (usize, usize, f64) {
        if periodic {
            let u = u.rem_euclid(n as f64);
            let i0 = (u.floor() as usize).min(n - 1);
            (i0, (i0 + 1) % n, u - i0 as f64)
        } else {
            let u = u.clamp(0.0, (n - 1) as f64);
            let i0 = (u.floor() as usize).min(n - 2);
            (i0, i0 + 1, u - i0 as f64)
        }
    };
    let (i0, i1, s) = axis((x - fl.x0) / fl.hx, fl.nx);
    let (j0, j1, t) = axis((y - fl.y0) / fl.hy, fl.ny);
    let w = [(1.0 - s) * (1.0 - t), s * (1.0 - t), (1.0 - s) * t, s * t];
    let ks = [j0 * fl.nx + i0, j0 * fl.nx + i1, j1 * fl.nx + i0, j1 * fl.nx + i1];
    let mut out = Stress3::default();
    for (wk, &k) in w.iter().zip(&ks) {
        let c = layer.stress(k);
        out.xx += wk * c.xx;
        out.yy += wk * c.yy;
        out.zz += wk * c.zz;
        out.xy += wk * c.xy;
        out.xz += wk * c.xz;
        out.yz += wk * c.yz;
    }
    out
}
