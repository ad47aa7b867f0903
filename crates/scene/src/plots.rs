//! SVG plots of an outcome (plotters, SVG backend), rendered to strings so that nothing is
//! written before every plot has been drawn.

use plotters::prelude::*;

use crate::exec::outcome::{Outcome, SurfaceOut};

type PlotResult = Result<String, String>;

/// A named curve.
struct Curve<'a> {
    label: &'a str,
    x: &'a [f64],
    y: &'a [f64],
    colour: RGBColor,
}

fn range(v: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for x in v.filter(|x| x.is_finite()) {
        lo = lo.min(x);
        hi = hi.max(x);
    }
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    if hi - lo <= 1e-300 + 1e-12 * hi.abs().max(lo.abs()) {
        let d = if hi == 0.0 { 1.0 } else { 0.1 * hi.abs() };
        return (lo - d, hi + d);
    }
    let pad = 0.05 * (hi - lo);
    (lo - pad, hi + pad)
}

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

fn line_chart(
    title: &str,
    xlabel: &str,
    ylabel: &str,
    curves: &[Curve<'_>],
    bands: &[(f64, f64, RGBColor)],
) -> PlotResult {
    let mut s = String::new();
    {
        let root = SVGBackend::with_string(&mut s, (720, 440)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let (x0, x1) = range(curves.iter().flat_map(|c| c.x.iter().copied()));
        let (y0, y1) = range(curves.iter().flat_map(|c| c.y.iter().copied()));
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(80)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc(xlabel)
            .y_desc(ylabel)
            .x_label_formatter(&|v| tick(*v, x1 - x0))
            .y_label_formatter(&|v| tick(*v, y1 - y0))
            .draw()
            .map_err(err)?;
        for &(a, b, col) in bands {
            chart
                .draw_series(std::iter::once(Rectangle::new(
                    [(a, y0), (b, y1)],
                    col.mix(0.15).filled(),
                )))
                .map_err(err)?;
        }
        for c in curves {
            let col = c.colour;
            chart
                .draw_series(LineSeries::new(
                    c.x.iter().copied().zip(c.y.iter().copied()),
                    col.stroke_width(2),
                ))
                .map_err(err)?
                .label(c.label)
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 18, y)], col.stroke_width(2))
                });
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    Ok(s)
}

/// Blue (negative) - white - red (positive) colour scale, symmetric about zero.
fn diverging(v: f64, vmax: f64) -> RGBColor {
    let t = if vmax > 0.0 { (v / vmax).clamp(-1.0, 1.0) } else { 0.0 };
    let w = |a: f64| (255.0 * (1.0 - a.abs())) as u8;
    if t >= 0.0 {
        RGBColor(255, w(t), w(t))
    } else {
        RGBColor(w(t), w(t), 255)
    }
}

/// Most cells drawn along a side of a map: beyond it, square blocks of cells are merged so
/// that an SVG of a fine grid stays a few MB (one rectangle per drawn cell).
const MAX_CELLS_PER_SIDE: usize = 160;

/// Cells merged per block along an axis of `n` cells.
fn block(n: usize) -> usize {
    n.div_ceil(MAX_CELLS_PER_SIDE).max(1)
}

/// Block centres of an axis: the mean of each run of `b` coordinates.
fn coarse_axis(x: &[f64], b: usize) -> Vec<f64> {
    x.chunks(b).map(|c| c.iter().sum::<f64>() / c.len() as f64).collect()
}

/// Block means of `v[j][i]` (rows along y, columns along x).
fn coarse_rows(v: &[Vec<f64>], by: usize, bx: usize) -> Vec<Vec<f64>> {
    v.chunks(by)
        .map(|rows| {
            let nx = rows[0].len();
            (0..nx.div_ceil(bx))
                .map(|ib| {
                    let cols = ib * bx..((ib + 1) * bx).min(nx);
                    let cnt = (rows.len() * cols.len()) as f64;
                    rows.iter().map(|r| r[cols.clone()].iter().sum::<f64>()).sum::<f64>() / cnt
                })
                .collect()
        })
        .collect()
}

fn heat_map(
    title: &str,
    x: &[f64],
    y: &[f64],
    v: &[Vec<f64>],
    yflip: bool,
    ylabel: &str,
) -> PlotResult {
    let (bx, by) = (block(x.len()), block(y.len()));
    if bx > 1 || by > 1 {
        let title = format!("{title}, {bx} x {by} cell blocks");
        return heat_map(
            &title,
            &coarse_axis(x, bx),
            &coarse_axis(y, by),
            &coarse_rows(v, by, bx),
            yflip,
            ylabel,
        );
    }
    let mut s = String::new();
    {
        let root = SVGBackend::with_string(&mut s, (720, 480)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let hx = if x.len() > 1 { x[1] - x[0] } else { 1.0 };
        let hy = if y.len() > 1 { y[1] - y[0] } else { 1.0 };
        let (xa, xb) = (x[0] - 0.5 * hx, x[x.len() - 1] + 0.5 * hx);
        let (ya, yb) = (y[0] - 0.5 * hy, y[y.len() - 1] + 0.5 * hy);
        let vmax = v.iter().flatten().fold(0.0f64, |m, z| m.max(z.abs()));
        let caption = format!("{title} (colour: -{vmax:.3e} blue .. +{vmax:.3e} red)");
        let mut chart = ChartBuilder::on(&root)
            .caption(caption, ("sans-serif", 16))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(80)
            .build_cartesian_2d(xa..xb, if yflip { yb..ya } else { ya..yb })
            .map_err(err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("x (m)")
            .y_desc(ylabel)
            .x_label_formatter(&|v| tick(*v, xb - xa))
            .y_label_formatter(&|v| tick(*v, yb - ya))
            .draw()
            .map_err(err)?;
        // v is indexed [row j along y][column i along x] for fields.
        let cells = y
            .iter()
            .enumerate()
            .flat_map(|(j, &yy)| x.iter().enumerate().map(move |(i, &xx)| (i, j, xx, yy)));
        chart
            .draw_series(cells.map(|(i, j, xx, yy)| {
                let c = diverging(v[j][i], vmax);
                Rectangle::new(
                    [(xx - 0.5 * hx, yy - 0.5 * hy), (xx + 0.5 * hx, yy + 0.5 * hy)],
                    c.filled(),
                )
            }))
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    Ok(s)
}

fn stick_map(x: &[f64], y: &[f64], stick: &[Vec<i8>]) -> PlotResult {
    let (bx, by) = (block(x.len()), block(y.len()));
    if bx > 1 || by > 1 {
        // A block sticks if most of its contact elements stick; outside if it has none.
        let merged: Vec<Vec<i8>> = stick
            .chunks(bx)
            .map(|cols| {
                (0..y.len().div_ceil(by))
                    .map(|jb| {
                        let rows = jb * by..((jb + 1) * by).min(y.len());
                        let (mut st, mut sl) = (0usize, 0usize);
                        for c in cols {
                            for v in &c[rows.clone()] {
                                match v {
                                    1 => st += 1,
                                    0 => sl += 1,
                                    _ => {}
                                }
                            }
                        }
                        if st + sl == 0 {
                            -1
                        } else {
                            i8::from(st >= sl)
                        }
                    })
                    .collect()
            })
            .collect();
        return stick_map(&coarse_axis(x, bx), &coarse_axis(y, by), &merged);
    }
    let mut s = String::new();
    {
        let root = SVGBackend::with_string(&mut s, (600, 600)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let hx = if x.len() > 1 { x[1] - x[0] } else { 1.0 };
        let hy = if y.len() > 1 { y[1] - y[0] } else { 1.0 };
        let (xa, xb) = (x[0] - 0.5 * hx, x[x.len() - 1] + 0.5 * hx);
        let (ya, yb) = (y[0] - 0.5 * hy, y[y.len() - 1] + 0.5 * hy);
        let mut chart = ChartBuilder::on(&root)
            .caption("stick (blue) and slip (red) elements", ("sans-serif", 16))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(80)
            .build_cartesian_2d(xa..xb, ya..yb)
            .map_err(err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("x (m)")
            .y_desc("y (m)")
            .x_label_formatter(&|v| tick(*v, xb - xa))
            .y_label_formatter(&|v| tick(*v, yb - ya))
            .draw()
            .map_err(err)?;
        let cells = x.iter().enumerate().flat_map(|(i, &xx)| {
            y.iter().enumerate().filter_map(move |(j, &yy)| {
                let st = stick[i][j];
                (st >= 0).then_some((xx, yy, st))
            })
        });
        // Coarse grids show each element with a thin gap; fine ones edge to edge.
        let half = if x.len().max(y.len()) > 40 { 0.5 } else { 0.45 };
        chart
            .draw_series(cells.map(|(xx, yy, st)| {
                let c = if st == 1 { RGBColor(70, 110, 220) } else { RGBColor(220, 80, 60) };
                Rectangle::new(
                    [(xx - half * hx, yy - half * hy), (xx + half * hx, yy + half * hy)],
                    c.filled(),
                )
            }))
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    Ok(s)
}

/// Every plot of `out` as (file name, SVG text).
pub(crate) fn render(out: &Outcome) -> Result<Vec<(String, String)>, String> {
    let mut files = Vec::new();
    let blue = RGBColor(40, 90, 200);
    let red = RGBColor(200, 60, 40);
    match &out.surface {
        SurfaceOut::Line { x, p, q, ux, uy, .. } if !x.is_empty() => {
            files.push((
                "pressure.svg".to_string(),
                line_chart(
                    "contact pressure",
                    "x (m)",
                    "p (Pa)",
                    &[Curve { label: "p", x, y: p, colour: blue }],
                    &[],
                )?,
            ));
            let mut bands: Vec<(f64, f64, RGBColor)> =
                out.zones.stick.iter().map(|z| (z[0], z[1], blue)).collect();
            bands.extend(out.zones.slip.iter().map(|z| (z[0], z[1], red)));
            files.push((
                "traction.svg".to_string(),
                line_chart(
                    "shear traction q (bands: stick blue, slip red)",
                    "x (m)",
                    "q (Pa)",
                    &[
                        Curve { label: "q", x, y: q, colour: red },
                        Curve { label: "p", x, y: p, colour: blue },
                    ],
                    &bands,
                )?,
            ));
            files.push((
                "stick_slip.svg".to_string(),
                line_chart(
                    "stick (blue) and slip (red) zones with the traction ratio |q|/p",
                    "x (m)",
                    "|q| / p",
                    &[Curve {
                        label: "|q|/p",
                        x,
                        y: &p
                            .iter()
                            .zip(q)
                            .map(|(p, q)| if *p > 0.0 { q.abs() / p } else { 0.0 })
                            .collect::<Vec<_>>(),
                        colour: RGBColor(40, 40, 40),
                    }],
                    &bands,
                )?,
            ));
            if !ux.is_empty() {
                files.push((
                    "displacement.svg".to_string(),
                    line_chart(
                        "surface displacement of the substrate",
                        "x (m)",
                        "u (m)",
                        &[
                            Curve { label: "ux", x, y: ux, colour: red },
                            Curve { label: "uy", x, y: uy, colour: blue },
                        ],
                        &[],
                    )?,
                ));
            }
        }
        SurfaceOut::Grid { x, y, p, qx, qy, stick, .. } if !x.is_empty() && !y.is_empty() => {
            // fields are [j][i]; the grid is [i][j]: transpose for the heat map
            let tr = |m: &Vec<Vec<f64>>| -> Vec<Vec<f64>> {
                (0..y.len()).map(|j| (0..x.len()).map(|i| m[i][j]).collect()).collect()
            };
            files.push((
                "pressure.svg".to_string(),
                heat_map("pressure p (Pa)", x, y, &tr(p), false, "y (m)")?,
            ));
            let qmag: Vec<Vec<f64>> = (0..x.len())
                .map(|i| (0..y.len()).map(|j| qx[i][j].hypot(qy[i][j])).collect())
                .collect();
            files.push((
                "traction.svg".to_string(),
                heat_map("traction magnitude |q| (Pa)", x, y, &tr(&qmag), false, "y (m)")?,
            ));
            files.push(("stick_slip.svg".to_string(), stick_map(x, y, stick)?));
        }
        _ => {}
    }
    let f = out.field.plane();
    if !f.x.is_empty() && !f.y.is_empty() {
        for (name, v) in [("sxx", &f.sxx), ("syy", &f.syy), ("sxy", &f.sxy)] {
            files.push((
                format!("field_{name}.svg"),
                heat_map(&format!("subsurface {name} (Pa)"), &f.x, &f.y, v, true, "depth y (m)")?,
            ));
        }
    }
    if let Some(v) = out.field.volume() {
        let a = &v.arrays;
        let (nx, ny, nz) = (v.x.len(), v.y.len(), v.z.len());
        let (i0, j0) = (nx / 2, ny / 2);
        for (name, data) in [
            ("von_mises", &a.von_mises),
            ("tresca", &a.tresca),
            ("max_principal", &a.max_principal),
            ("szz", &a.szz),
        ] {
            if nx > 1 && nz > 1 {
                let rows: Vec<Vec<f64>> = (0..nz)
                    .map(|k| (0..nx).map(|i| data[(k * ny + j0) * nx + i]).collect())
                    .collect();
                files.push((
                    format!("field_{name}_xz.svg"),
                    heat_map(
                        &format!("{name} (Pa), section y = {:.3e} m", v.y[j0]),
                        &v.x,
                        &v.z,
                        &rows,
                        true,
                        "depth z (m)",
                    )?,
                ));
            }
            if ny > 1 && nz > 1 {
                let rows: Vec<Vec<f64>> = (0..nz)
                    .map(|k| (0..ny).map(|j| data[(k * ny + j) * nx + i0]).collect())
                    .collect();
                files.push((
                    format!("field_{name}_yz.svg"),
                    heat_map(
                        &format!("{name} (Pa), section x = {:.3e} m", v.x[i0]),
                        &v.y,
                        &v.z,
                        &rows,
                        true,
                        "depth z (m)",
                    )?,
                ));
            }
        }
    }
    if let Some(c) = &out.cycle {
        files.push((
            "cycle.svg".to_string(),
            line_chart(
                "Mindlin-Deresiewicz loop",
                "relative displacement (m)",
                "T (N)",
                &[Curve { label: "loop", x: &c.delta, y: &c.t, colour: blue }],
                &[],
            )?,
        ));
    }
    Ok(files)
}

/// Axis tick label: three significant digits in exponent form. A tick within 1e-9 of the axis
/// span of zero is the zero tick with rounding from the tick arithmetic (plotters gives e.g.
/// 3.5e-18 on an axis spanning 5e-2) and prints as 0.
fn tick(v: f64, span: f64) -> String {
    if v.abs() <= 1e-9 * span.abs() {
        "0".to_string()
    } else {
        format!("{v:.3e}")
    }
}
