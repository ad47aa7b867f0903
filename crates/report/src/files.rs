//! A run's files rendered in memory, before `output.rs` writes them all or nothing:
//! result.json, the CSV tables, the `.npy` arrays, the SVG plots and report.html.

use std::fmt::Write as _;

use crate::report::ReportContext;
use stickslip_run::{Outcome, SurfaceOut};
use stickslip_scene::{ErrorKind, SceneError};

/// The files of `out` as (name, contents), rendered in memory.
///
/// # Errors
/// A [`SceneError`] (kind [`ErrorKind::Io`]) if a plot cannot be drawn.
pub(crate) fn render(
    out: &Outcome,
    plots: bool,
    ctx: Option<ReportContext<'_>>,
) -> Result<Vec<(String, Vec<u8>)>, SceneError> {
    let mut files: Vec<(String, String)> = vec![("result.json".to_string(), out.to_json() + "\n")];
    let mut binary: Vec<(String, Vec<u8>)> = Vec::new();
    let mut s = String::new();
    match &out.surface {
        SurfaceOut::Line { x, p, q, ux, uy, .. } if !x.is_empty() => {
            let disp = !ux.is_empty();
            s.push_str(if disp { "x_m,p_Pa,q_Pa,ux_m,uy_m\n" } else { "x_m,p_Pa,q_Pa\n" });
            for i in 0..x.len() {
                let _ = write!(s, "{},{},{}", x[i], p[i], q[i]);
                if disp {
                    let _ = write!(s, ",{},{}", ux[i], uy[i]);
                }
                s.push('\n');
            }
            files.push(("surface.csv".to_string(), std::mem::take(&mut s)));
        }
        SurfaceOut::Grid {
            x,
            y,
            p,
            qx,
            qy,
            stick,
            gap,
            slip_x,
            slip_y,
            dissipation,
            slip_amplitude,
            ruiz,
            plastic,
            plastic_displacement,
        } if !x.is_empty() => {
            // A surface's, a 3D rolling contact's and a load path's maps also as (ny, nx)
            // arrays: pressure, tractions, gap, micro-slip or dissipation and slip range,
            // contact.
            if gap.is_some() || slip_x.is_some() || dissipation.is_some() {
                let (nx, ny) = (x.len(), y.len());
                let rows = |m: &Vec<Vec<f64>>| -> Vec<f64> {
                    (0..ny).flat_map(|j| (0..nx).map(move |i| m[i][j])).collect()
                };
                let mut maps = vec![("p", p), ("qx", qx), ("qy", qy)];
                for (name, m) in [
                    ("gap", gap),
                    ("slip_x", slip_x),
                    ("slip_y", slip_y),
                    ("dissipation", dissipation),
                    ("slip_amplitude", slip_amplitude),
                    ("ruiz", ruiz),
                    ("plastic", plastic),
                    ("plastic_displacement", plastic_displacement),
                ] {
                    if let Some(m) = m {
                        maps.push((name, m));
                    }
                }
                for (name, m) in maps {
                    binary.push((format!("surface_{name}.npy"), npy(&rows(m), &[ny, nx])));
                }
                let stick_f: Vec<f64> =
                    (0..ny).flat_map(|j| (0..nx).map(move |i| f64::from(stick[i][j]))).collect();
                binary.push(("surface_stick.npy".to_string(), npy(&stick_f, &[ny, nx])));
                binary.push(("surface_x.npy".to_string(), npy(x, &[nx])));
                binary.push(("surface_y.npy".to_string(), npy(y, &[ny])));
            }
            s.push_str("x_m,y_m,p_Pa,qx_Pa,qy_Pa,stick");
            if slip_x.is_some() {
                s.push_str(",slip_x_m_per_s,slip_y_m_per_s");
            }
            if dissipation.is_some() {
                s.push_str(",dissipation_J_per_m2,slip_amplitude_m");
            }
            s.push('\n');
            for (i, xi) in x.iter().enumerate() {
                for (j, yj) in y.iter().enumerate() {
                    // A load path's cells that dissipated but left the contact are listed
                    // too (their pressure is zero now).
                    let dissipated = dissipation.as_ref().is_some_and(|d| d[i][j] != 0.0);
                    if stick[i][j] >= 0 || dissipated {
                        let _ = write!(
                            s,
                            "{xi},{yj},{},{},{},{}",
                            p[i][j], qx[i][j], qy[i][j], stick[i][j]
                        );
                        if let (Some(sx), Some(sy)) = (slip_x, slip_y) {
                            let _ = write!(s, ",{},{}", sx[i][j], sy[i][j]);
                        }
                        if let (Some(d), Some(a)) = (dissipation, slip_amplitude) {
                            let _ = write!(s, ",{},{}", d[i][j], a[i][j]);
                        }
                        s.push('\n');
                    }
                }
            }
            files.push(("surface.csv".to_string(), std::mem::take(&mut s)));
        }
        _ => {}
    }
    let f = out.field.plane();
    if !f.x.is_empty() {
        s.push_str("x_m,y_m,sxx_Pa,syy_Pa,sxy_Pa\n");
        for (j, y) in f.y.iter().enumerate() {
            for (i, x) in f.x.iter().enumerate() {
                let _ = writeln!(s, "{x},{y},{},{},{}", f.sxx[j][i], f.syy[j][i], f.sxy[j][i]);
            }
        }
        files.push(("field.csv".to_string(), std::mem::take(&mut s)));
    }
    if let Some(v) = out.field.volume() {
        s.push_str("x,y,z,sxx,syy,szz,sxy,syz,sxz,von_mises,tresca,max_principal\n");
        let a = &v.arrays;
        let (nx, ny) = (v.x.len(), v.y.len());
        for (k, z) in v.z.iter().enumerate() {
            for (j, y) in v.y.iter().enumerate() {
                for (i, x) in v.x.iter().enumerate() {
                    let m = (k * ny + j) * nx + i;
                    let _ = writeln!(
                        s,
                        "{x},{y},{z},{},{},{},{},{},{},{},{},{}",
                        a.sxx[m],
                        a.syy[m],
                        a.szz[m],
                        a.sxy[m],
                        a.syz[m],
                        a.sxz[m],
                        a.von_mises[m],
                        a.tresca[m],
                        a.max_principal[m]
                    );
                }
            }
        }
        files.push(("field.csv".to_string(), std::mem::take(&mut s)));
        if v.values.is_none() {
            for (name, data) in [
                ("sxx", &a.sxx),
                ("syy", &a.syy),
                ("szz", &a.szz),
                ("sxy", &a.sxy),
                ("syz", &a.syz),
                ("sxz", &a.sxz),
                ("von_mises", &a.von_mises),
                ("tresca", &a.tresca),
                ("max_principal", &a.max_principal),
            ] {
                binary.push((format!("field_{name}.npy"), npy(data, &v.shape)));
            }
            for (name, data) in [("x", &v.x), ("y", &v.y), ("z", &v.z)] {
                binary.push((format!("field_{name}.npy"), npy(data, &[data.len()])));
            }
        }
    }
    if let Some(c) = &out.cycle {
        s.push_str("T_N,delta_m\n");
        for (t, d) in c.t.iter().zip(&c.delta) {
            let _ = writeln!(s, "{t},{d}");
        }
        files.push(("cycle.csv".to_string(), std::mem::take(&mut s)));
    }
    if let Some(h) = out.history.as_ref().filter(|h| !h.distance.is_empty()) {
        // Transient rolling: the creep forces and creepages along the distance rolled.
        s.push_str("step,distance_m,fx_N,fy_N,mz_N_m,creepage_longitudinal,creepage_lateral,shift_m,stick_fraction,dissipated_J,work_J,elastic_energy_J\n");
        for i in 0..h.distance.len() {
            let _ = writeln!(
                s,
                "{i},{},{},{},{},{},{},{},{},{},{},{}",
                h.distance[i],
                h.fx[i],
                h.fy[i],
                h.mz[i],
                h.creepage_longitudinal[i],
                h.creepage_lateral[i],
                h.shift[i],
                h.stick_fraction[i],
                h.dissipated[i],
                h.work[i],
                h.elastic_energy[i]
            );
        }
        files.push(("history.csv".to_string(), std::mem::take(&mut s)));
    } else if let Some(h) = &out.history {
        s.push_str("step,corner,tangential_N,normal_N,moment_N_m,shift_m,rotation_rad,stick_fraction,dissipated_J,work_J,elastic_energy_J,gross_slip\n");
        for i in 0..h.tangential.len() {
            let corner =
                h.corners.iter().position(|c| *c == i).map_or(String::new(), |c| c.to_string());
            let _ = writeln!(
                s,
                "{i},{corner},{},{},{},{},{},{},{},{},{},{}",
                h.tangential[i],
                h.normal[i],
                h.moment[i],
                h.shift[i],
                h.rotation[i],
                h.stick_fraction[i],
                h.dissipated[i],
                h.work[i],
                h.elastic_energy[i],
                u8::from(h.gross_slip[i])
            );
        }
        files.push(("history.csv".to_string(), std::mem::take(&mut s)));
    }
    if let Some(c) = &out.load_curve {
        s.push_str("normal_N,approach_m,area_m2,fraction,p0_Pa,iterations");
        s.push_str(if c.zone_area.is_some() { ",zone_area_m2\n" } else { "\n" });
        for i in 0..c.normal.len() {
            let _ = write!(
                s,
                "{},{},{},{},{},{}",
                c.normal[i], c.approach[i], c.area[i], c.fraction[i], c.p0[i], c.iterations[i]
            );
            let _ = match &c.zone_area {
                Some(z) => writeln!(s, ",{}", z[i]),
                None => writeln!(s),
            };
        }
        files.push(("load_curve.csv".to_string(), std::mem::take(&mut s)));
    }
    if let Some(w) = &out.wheel_rail {
        // Each patch's maps, (ns, nx) as a surface's are (ny, nx).
        for (k, p) in w.patches.iter().enumerate() {
            let m = &p.maps;
            let shape = [m.s.len(), m.x.len()];
            if m.pressure.len() != shape[0] * shape[1] {
                continue;
            }
            binary.push((format!("patch{k}_x.npy"), npy(&m.x, &[shape[1]])));
            binary.push((format!("patch{k}_s.npy"), npy(&m.s, &[shape[0]])));
            binary.push((format!("patch{k}_pressure.npy"), npy(&m.pressure, &shape)));
            binary.push((format!("patch{k}_gap.npy"), npy(&m.gap, &shape)));
            if let (Some(qx), Some(qs)) = (&m.qx, &m.qs) {
                binary.push((format!("patch{k}_qx.npy"), npy(qx, &shape)));
                binary.push((format!("patch{k}_qs.npy"), npy(qs, &shape)));
                let st: Vec<f64> = m.stick.iter().map(|&v| f64::from(v)).collect();
                binary.push((format!("patch{k}_stick.npy"), npy(&st, &shape)));
            }
        }
    }
    let svgs = if plots {
        crate::plots::render(out, ctx.map(|c| c.plan)).map_err(|e| {
            SceneError::new(ErrorKind::Io, format!("cannot draw the plots: {e}"))
                .hint("run without outputs.plots; nothing was written or changed")
        })?
    } else {
        Vec::new()
    };
    files.push(("report.html".to_string(), crate::report::render(out, ctx, &svgs, plots)));
    files.extend(svgs);
    let mut all: Vec<(String, Vec<u8>)> =
        files.into_iter().map(|(n, t)| (n, t.into_bytes())).collect();
    all.extend(binary);
    Ok(all)
}

/// A little-endian float64 array in the `.npy` format (version 1.0): the magic string, the
/// header length, a Python-literal header (`descr`, `fortran_order`, `shape`) padded with
/// spaces to a multiple of 64 bytes and ending in a newline, then the data in C order.
pub(crate) fn npy(data: &[f64], shape: &[usize]) -> Vec<u8> {
    let dims = match shape {
        [n] => format!("({n},)"),
        _ => format!("({})", shape.iter().map(usize::to_string).collect::<Vec<_>>().join(", ")),
    };
    let mut header = format!("{{'descr': '<f8', 'fortran_order': False, 'shape': {dims}, }}");
    // magic (6) + version (2) + length (2) + header + '\n', a multiple of 64
    while (10 + header.len() + 1) % 64 != 0 {
        header.push(' ');
    }
    header.push('\n');
    let mut out = Vec::with_capacity(10 + header.len() + 8 * data.len());
    out.extend_from_slice(b"\x93NUMPY\x01\x00");
    out.extend_from_slice(&(header.len() as u16).to_le_bytes());
    out.extend_from_slice(header.as_bytes());
    for v in data {
        out.extend_from_slice(&v.to_le_bytes());
    }
    out
}
