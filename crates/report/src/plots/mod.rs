//! SVG plots of an outcome (plotters, SVG backend), rendered to strings so that nothing is
//! written before every plot has been drawn.

use plotters::prelude::*;

mod contour;
mod load_curve;
mod maps;
mod parameters;
mod raster;
mod wheel_rail;

use stickslip_run::reference;
use stickslip_run::{Outcome, Plan, SurfaceOut};

use crate::report::eng_near;
use maps::*;

type PlotResult = Result<String, String>;

/// A named curve.
struct Curve<'a> {
    label: &'a str,
    x: &'a [f64],
    y: &'a [f64],
    colour: RGBColor,
    /// A closed-form reference, drawn dashed.
    dashed: bool,
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

/// An axis or colour scale in engineering units: values are divided by `div` and labelled
/// with `unit` (an SI prefix on the base unit, e.g. µm, MPa).
#[derive(Debug, Clone)]
struct Units {
    div: f64,
    unit: String,
}

impl Units {
    /// The prefix that puts the largest magnitude `maxabs` in [1, 1000) (no prefix for an
    /// empty base unit, i.e. a ratio): the terminal's and the report's prefix rules
    /// (`stickslip_scene::eng::common_prefix`).
    fn for_max(maxabs: f64, base: &str) -> Units {
        let (div, unit) = stickslip_scene::eng::common_prefix(maxabs, base);
        Units { div, unit }
    }

    fn of(v: impl Iterator<Item = f64>, base: &str) -> Units {
        Units::for_max(v.filter(|x| x.is_finite()).fold(0.0f64, |m, x| m.max(x.abs())), base)
    }

    /// An axis description: "name (unit)", or the name alone for a ratio.
    fn desc(&self, name: &str) -> String {
        if self.unit.is_empty() {
            name.to_string()
        } else {
            format!("{name} ({})", self.unit)
        }
    }

    fn scale(&self, v: &[f64]) -> Vec<f64> {
        v.iter().map(|x| x / self.div).collect()
    }
}

/// A round tick label: as many decimals as the tick spacing of an axis spanning `span` needs
/// (plotters puts about ten ticks on an axis), no exponent.
fn tick(v: f64, span: f64) -> String {
    let step = (span.abs() / 10.0).max(1e-300);
    let decimals = (-step.log10().floor()).clamp(0.0, 9.0) as usize;
    let s = format!("{v:.decimals$}");
    // "-0" and "-0.00" from rounding are zero.
    if s.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

/// `area` below a title line and, when `sub` is not empty, a smaller line of key parameters.
fn titled<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    title: &str,
    sub: &str,
) -> Result<DrawingArea<DB, plotters::coord::Shift>, String> {
    let area = area.titled(title, ("sans-serif", 16)).map_err(err)?;
    if sub.is_empty() {
        Ok(area)
    } else {
        area.titled(sub, ("sans-serif", 13)).map_err(err)
    }
}

fn line_chart(
    (title, sub): (&str, &str),
    (xname, xbase): (&str, &str),
    (yname, ybase): (&str, &str),
    curves: &[Curve<'_>],
    bands: &[(f64, f64, RGBColor)],
) -> PlotResult {
    let xu = Units::of(curves.iter().flat_map(|c| c.x.iter().copied()), xbase);
    let yu = Units::of(curves.iter().flat_map(|c| c.y.iter().copied()), ybase);
    let scaled: Vec<(Vec<f64>, Vec<f64>)> =
        curves.iter().map(|c| (xu.scale(c.x), yu.scale(c.y))).collect();
    let mut s = String::new();
    {
        let root = SVGBackend::with_string(&mut s, (720, 460)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let root = titled(&root, title, sub)?;
        let (x0, x1) = range(scaled.iter().flat_map(|c| c.0.iter().copied()));
        let (y0, y1) = range(scaled.iter().flat_map(|c| c.1.iter().copied()));
        let mut chart = ChartBuilder::on(&root)
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc(xu.desc(xname))
            .y_desc(yu.desc(yname))
            .x_label_formatter(&|v| tick(*v, x1 - x0))
            .y_label_formatter(&|v| tick(*v, y1 - y0))
            .draw()
            .map_err(err)?;
        for &(a, b, col) in bands {
            chart
                .draw_series(std::iter::once(Rectangle::new(
                    [(a / xu.div, y0), (b / xu.div, y1)],
                    col.mix(0.15).filled(),
                )))
                .map_err(err)?;
        }
        for (c, (x, y)) in curves.iter().zip(&scaled) {
            let col = c.colour;
            let pts = x.iter().copied().zip(y.iter().copied());
            if c.dashed {
                chart
                    .draw_series(DashedLineSeries::new(pts, 7, 4, col.stroke_width(2)))
                    .map_err(err)?
                    .label(c.label)
                    .legend(move |(x, y)| {
                        plotters::element::DashedPathElement::new(
                            vec![(x, y), (x + 18, y)],
                            5,
                            3,
                            col.stroke_width(2),
                        )
                    });
            } else {
                chart
                    .draw_series(LineSeries::new(pts, col.stroke_width(2)))
                    .map_err(err)?
                    .label(c.label)
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 18, y)], col.stroke_width(2))
                    });
            }
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

/// `n` points from `a` to `b`.
fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n).map(|k| a + (b - a) * k as f64 / (n - 1) as f64).collect()
}

/// A closed form sampled densely along x at the fixed y `y0`, as a dashed curve's data.
fn sample(r: &reference::Reference, x0: f64, x1: f64, y0: f64) -> (Vec<f64>, Vec<f64>) {
    let xs = linspace(x0, x1, 401);
    let ys = xs.iter().map(|&x| (r.at)(x, y0)).collect();
    (xs, ys)
}

/// Every plot of `out` as (file name, SVG text). Titles start with the scene's title, with
/// the key parameters on a second line; the closed-form references of the planned scene
/// (when `plan` is given) are drawn dashed.
pub(crate) fn render(out: &Outcome, plan: Option<&Plan>) -> Result<Vec<(String, String)>, String> {
    let mut files = Vec::new();
    let blue = RGBColor(40, 90, 200);
    let red = RGBColor(200, 60, 40);
    let grey = RGBColor(40, 40, 40);
    let st = &out.title;
    let sub = parameters::key_parameters(plan, out);
    let sub = sub.as_str();
    let refs = plan.map(|p| reference::of(p, out)).unwrap_or_default();
    let x_m = ("x", "m");
    match &out.surface {
        SurfaceOut::Line { x, p, q, ux, uy, .. } if !x.is_empty() => {
            let (x0, x1) = (x[0], x[x.len() - 1]);
            let pref = refs.pressure.as_ref().map(|r| (r.label, sample(r, x0, x1, 0.0)));
            let qref = refs.traction.as_ref().map(|r| (r.label, sample(r, x0, x1, 0.0)));
            let mut curves = vec![Curve { dashed: false, label: "p", x, y: p, colour: blue }];
            if let Some((label, (rx, ry))) = &pref {
                curves.push(Curve { dashed: true, label, x: rx, y: ry, colour: grey });
            }
            files.push((
                "pressure.svg".to_string(),
                line_chart(
                    (&format!("{st}: contact pressure"), sub),
                    x_m,
                    ("p", "Pa"),
                    &curves,
                    &[],
                )?,
            ));
            let mut bands: Vec<(f64, f64, RGBColor)> =
                out.zones.stick.iter().map(|z| (z[0], z[1], blue)).collect();
            bands.extend(out.zones.slip.iter().map(|z| (z[0], z[1], red)));
            let mut curves = vec![
                Curve { dashed: false, label: "q", x, y: q, colour: red },
                Curve { dashed: false, label: "p", x, y: p, colour: blue },
            ];
            if let Some((label, (rx, ry))) = &qref {
                curves.push(Curve { dashed: true, label, x: rx, y: ry, colour: grey });
            }
            files.push((
                "traction.svg".to_string(),
                line_chart(
                    (&format!("{st}: shear traction q (bands: stick blue, slip red)"), sub),
                    x_m,
                    ("p, q", "Pa"),
                    &curves,
                    &bands,
                )?,
            ));
            files.push((
                "stick_slip.svg".to_string(),
                line_chart(
                    (&format!("{st}: stick (blue) and slip (red) zones, |q|/p"), sub),
                    x_m,
                    ("|q| / p", ""),
                    &[Curve {
                        dashed: false,
                        label: "|q|/p",
                        x,
                        y: &p
                            .iter()
                            .zip(q)
                            .map(|(p, q)| if *p > 0.0 { q.abs() / p } else { 0.0 })
                            .collect::<Vec<_>>(),
                        colour: grey,
                    }],
                    &bands,
                )?,
            ));
            if !ux.is_empty() {
                files.push((
                    "displacement.svg".to_string(),
                    line_chart(
                        (&format!("{st}: surface displacement of the substrate"), sub),
                        x_m,
                        ("u", "m"),
                        &[
                            Curve { dashed: false, label: "ux", x, y: ux, colour: red },
                            Curve { dashed: false, label: "uy", x, y: uy, colour: blue },
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
            let outline = stick_outline(x, y, stick);
            let map = |title: String, name, v| Map {
                title,
                sub,
                name,
                base: "Pa",
                x,
                y,
                v,
                yflip: false,
                yname: "y",
                outline: &outline,
            };
            let pt = tr(p);
            files.push((
                "pressure.svg".to_string(),
                heat_map(&map(format!("{st}: pressure p (white: stick zone outline)"), "p", &pt))?,
            ));
            let qmag: Vec<Vec<f64>> = (0..x.len())
                .map(|i| (0..y.len()).map(|j| qx[i][j].hypot(qy[i][j])).collect())
                .collect();
            let qt = tr(&qmag);
            files.push((
                "traction.svg".to_string(),
                heat_map(&map(
                    format!("{st}: traction |q| (white: stick zone outline)"),
                    "|q|",
                    &qt,
                ))?,
            ));
            files.push(("stick_slip.svg".to_string(), stick_map((st, sub), x, y, stick)?));
            // Sections along x through the row nearest the centre, beside the closed forms
            // evaluated on that same row.
            let j0 = (0..y.len()).min_by(|&a, &b| y[a].abs().total_cmp(&y[b].abs())).unwrap_or(0);
            let (x0, x1, y0) = (x[0], x[x.len() - 1], y[j0]);
            let at = format!("section y = {}", eng_near(y0, x1.abs().max(x0.abs()), 1e-10, "m"));
            for (file, name, row, r) in [
                ("pressure_section.svg", "p", &pt[j0], refs.pressure.as_ref()),
                ("traction_section.svg", "|q|", &qt[j0], refs.traction.as_ref()),
            ] {
                if name == "|q|" && row.iter().all(|v| *v == 0.0) {
                    continue;
                }
                let reference = r.map(|r| (r.label, sample(r, x0, x1, y0)));
                let mut curves =
                    vec![Curve { dashed: false, label: name, x, y: row, colour: blue }];
                if let Some((label, (rx, ry))) = &reference {
                    curves.push(Curve { dashed: true, label, x: rx, y: ry, colour: grey });
                }
                files.push((
                    file.to_string(),
                    line_chart(
                        (&format!("{st}: {name}, {at}"), sub),
                        x_m,
                        (name, "Pa"),
                        &curves,
                        &[],
                    )?,
                ));
            }
        }
        _ => {}
    }
    let f = out.field.plane();
    if !f.x.is_empty() && !f.y.is_empty() {
        for (name, v) in [("sxx", &f.sxx), ("syy", &f.syy), ("sxy", &f.sxy)] {
            files.push((
                format!("field_{name}.svg"),
                heat_map(&Map {
                    title: format!("{st}: subsurface {name}"),
                    sub,
                    name,
                    base: "Pa",
                    x: &f.x,
                    y: &f.y,
                    v,
                    yflip: true,
                    yname: "depth y",
                    outline: &[],
                })?,
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
                    heat_map(&Map {
                        title: format!(
                            "{st}: {name}, section y = {}",
                            eng_near(v.y[j0], v.x[0].abs().max(v.x[nx - 1].abs()), 1e-10, "m")
                        ),
                        sub,
                        name,
                        base: "Pa",
                        x: &v.x,
                        y: &v.z,
                        v: &rows,
                        yflip: true,
                        yname: "depth z",
                        outline: &[],
                    })?,
                ));
            }
            if ny > 1 && nz > 1 {
                let rows: Vec<Vec<f64>> = (0..nz)
                    .map(|k| (0..ny).map(|j| data[(k * ny + j) * nx + i0]).collect())
                    .collect();
                files.push((
                    format!("field_{name}_yz.svg"),
                    heat_map(&Map {
                        title: format!(
                            "{st}: {name}, section x = {}",
                            eng_near(v.x[i0], v.y[0].abs().max(v.y[ny - 1].abs()), 1e-10, "m")
                        ),
                        sub,
                        name,
                        base: "Pa",
                        x: &v.y,
                        y: &v.z,
                        v: &rows,
                        yflip: true,
                        yname: "depth z",
                        outline: &[],
                    })?,
                ));
            }
        }
    }
    if let SurfaceOut::Grid {
        x,
        y,
        stick,
        dissipation: Some(d),
        slip_amplitude: Some(sa),
        ruiz,
        ..
    } = &out.surface
    {
        if !x.is_empty() && !y.is_empty() {
            let tr = |m: &Vec<Vec<f64>>| -> Vec<Vec<f64>> {
                (0..y.len()).map(|j| (0..x.len()).map(|i| m[i][j]).collect()).collect()
            };
            let outline = stick_outline(x, y, stick);
            for (file, title, name, base, m) in [
                (
                    "dissipation.svg",
                    "energy dissipated per area over the load path",
                    "D",
                    "J/m^2",
                    d,
                ),
                (
                    "slip_amplitude.svg",
                    "largest slip range over the load path (peak to peak)",
                    "slip range",
                    "m",
                    sa,
                ),
            ]
            .into_iter()
            .chain(ruiz.as_ref().map(|r| {
                (
                    "ruiz.svg",
                    "Ruiz parameter, largest tension times shear at the turning points times slip range",
                    "F2",
                    "Pa J/m^2",
                    r,
                )
            })) {
                let v = tr(m);
                files.push((
                    file.to_string(),
                    heat_map(&Map {
                        title: format!("{st}: {title} (white: final stick zone outline)"),
                        sub,
                        name,
                        base,
                        x,
                        y,
                        v: &v,
                        yflip: false,
                        yname: "y",
                        outline: &outline,
                    })?,
                ));
            }
        }
    }
    if let Some(h) = out.history.as_ref().filter(|h| !h.distance.is_empty()) {
        // Transient rolling: the creepage that carries the creep force, and the stick area,
        // against the distance rolled.
        files.push((
            "history_creepage.svg".to_string(),
            line_chart(
                (&format!("{st}: creepages along the distance rolled"), sub),
                ("distance rolled", "m"),
                ("creepage", ""),
                &[
                    Curve {
                        dashed: false,
                        label: "longitudinal",
                        x: &h.distance,
                        y: &h.creepage_longitudinal,
                        colour: blue,
                    },
                    Curve {
                        dashed: true,
                        label: "lateral",
                        x: &h.distance,
                        y: &h.creepage_lateral,
                        colour: red,
                    },
                ],
                &[],
            )?,
        ));
        files.push((
            "history_stick.svg".to_string(),
            line_chart(
                (&format!("{st}: stick fraction along the distance rolled"), sub),
                ("distance rolled", "m"),
                ("stick fraction", ""),
                &[Curve {
                    dashed: false,
                    label: "stick fraction",
                    x: &h.distance,
                    y: &h.stick_fraction,
                    colour: blue,
                }],
                &[],
            )?,
        ));
    } else if let Some(h) = &out.history {
        let mut curves = vec![Curve {
            dashed: false,
            label: "load path",
            x: &h.shift,
            y: &h.tangential,
            colour: blue,
        }];
        if let Some((rx, ry)) = &refs.history_loop {
            curves.push(Curve {
                dashed: true,
                label: "Mindlin-Deresiewicz",
                x: rx,
                y: ry,
                colour: grey,
            });
        }
        files.push((
            "history_loop.svg".to_string(),
            line_chart(
                (&format!("{st}: tangential force against rigid shift along the path"), sub),
                ("rigid shift", "m"),
                ("T", "N"),
                &curves,
                &[],
            )?,
        ));
        let step: Vec<f64> = (0..h.tangential.len()).map(|i| i as f64).collect();
        files.push((
            "history_stick.svg".to_string(),
            line_chart(
                (
                    &format!(
                        "{st}: stick fraction along the path (cells not slipping in the step)"
                    ),
                    sub,
                ),
                ("step", ""),
                ("stick fraction", ""),
                &[Curve {
                    dashed: false,
                    label: "stick fraction",
                    x: &step,
                    y: &h.stick_fraction,
                    colour: blue,
                }],
                &[],
            )?,
        ));
        files.push((
            "history_energy.svg".to_string(),
            line_chart(
                (&format!("{st}: energy along the path"), sub),
                ("step", ""),
                ("energy", "J"),
                &[
                    Curve {
                        dashed: false,
                        label: "dissipated",
                        x: &step,
                        y: &h.dissipated,
                        colour: red,
                    },
                    Curve {
                        dashed: true,
                        label: "stored (elastic)",
                        x: &step,
                        y: &h.elastic_energy,
                        colour: blue,
                    },
                ],
                &[],
            )?,
        ));
    }
    if let Some(c) = &out.cycle {
        let mut curves =
            vec![Curve { dashed: false, label: "result", x: &c.delta, y: &c.t, colour: blue }];
        if let Some((rx, ry)) = &refs.cycle {
            curves.push(Curve {
                dashed: true,
                label: "Mindlin-Deresiewicz",
                x: rx,
                y: ry,
                colour: grey,
            });
        }
        files.push((
            "cycle.svg".to_string(),
            line_chart(
                (&format!("{st}: hysteresis loop"), sub),
                ("relative displacement", "m"),
                ("T", "N"),
                &curves,
                &[],
            )?,
        ));
    }
    if let Some(c) = &out.load_curve {
        load_curve::render(c, refs.load_curve.as_ref(), &out.contact, st, sub, &mut files)?;
    }
    if let Some(w) = &out.wheel_rail {
        wheel_rail::render(w, st, sub, &mut files)?;
    }
    Ok(files)
}
