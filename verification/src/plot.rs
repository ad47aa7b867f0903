//! Deterministic SVG plots of [`Figure`]s (plotters' SVG backend, our own tick labels).

use crate::fmt::sig;
use crate::record::{Figure, Style};
use crate::Error;
use plotters::prelude::*;

const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
];

fn range(v: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = v
        .filter(|x| x.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| (l.min(x), h.max(x)));
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let span = if hi > lo { hi - lo } else { lo.abs().max(1.0) };
    (lo - 0.05 * span, hi + 0.05 * span)
}

fn err(name: &str, e: impl std::fmt::Display) -> Error {
    Error::Plot { name: name.into(), message: e.to_string() }
}

/// Axis tick label with 4 significant digits; a tick within 1e-9 of the axis span of zero is
/// the zero tick with rounding from the tick arithmetic and prints as 0.
fn tick(v: f64, span: f64) -> String {
    if v.abs() <= 1e-9 * span.abs() {
        "0".to_string()
    } else {
        sig(v, 4)
    }
}

/// The SVG text of a figure: computed curves as lines, computed discrete values as hollow
/// circles, published points as black crosses (a second published series as triangles).
pub(crate) fn svg(fig: &Figure) -> Result<String, Error> {
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, (720, 460)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&fig.name, e))?;
        let pts = || fig.series.iter().flat_map(|s| s.points.iter());
        let (x0, x1) = range(pts().map(|p| p.0));
        let (y0, y1) = range(pts().map(|p| p.1));
        let mut chart = ChartBuilder::on(&root)
            .caption(&fig.caption, ("sans-serif", 14))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(|e| err(&fig.name, e))?;
        chart
            .configure_mesh()
            .x_desc(fig.x_label.as_str())
            .y_desc(fig.y_label.as_str())
            .x_label_formatter(&|v| tick(*v, x1 - x0))
            .y_label_formatter(&|v| tick(*v, y1 - y0))
            .draw()
            .map_err(|e| err(&fig.name, e))?;
        let mut published_seen = 0;
        for (i, s) in fig.series.iter().enumerate() {
            let c = PALETTE[i % PALETTE.len()];
            let data: Vec<(f64, f64)> =
                s.points.iter().copied().filter(|p| p.0.is_finite() && p.1.is_finite()).collect();
            match s.style {
                Style::Line => {
                    chart
                        .draw_series(LineSeries::new(data, c.stroke_width(2)))
                        .map_err(|e| err(&fig.name, e))?
                        .label(s.label.as_str())
                        .legend(move |(x, y)| {
                            PathElement::new(vec![(x, y), (x + 16, y)], c.stroke_width(2))
                        });
                }
                Style::Points => {
                    chart
                        .draw_series(data.into_iter().map(|p| Circle::new(p, 3, c.stroke_width(1))))
                        .map_err(|e| err(&fig.name, e))?
                        .label(s.label.as_str())
                        .legend(move |(x, y)| Circle::new((x + 8, y), 3, c.stroke_width(1)));
                }
                Style::Published if published_seen % 2 == 0 => {
                    published_seen += 1;
                    chart
                        .draw_series(
                            data.into_iter().map(|p| Cross::new(p, 5, BLACK.stroke_width(2))),
                        )
                        .map_err(|e| err(&fig.name, e))?
                        .label(s.label.as_str())
                        .legend(move |(x, y)| Cross::new((x + 8, y), 5, BLACK.stroke_width(2)));
                }
                Style::Published => {
                    // A second published series in the same figure (e.g. Table 2's two rows)
                    // gets a different black marker so the two can be told apart.
                    published_seen += 1;
                    chart
                        .draw_series(
                            data.into_iter()
                                .map(|p| TriangleMarker::new(p, 5, BLACK.stroke_width(1))),
                        )
                        .map_err(|e| err(&fig.name, e))?
                        .label(s.label.as_str())
                        .legend(move |(x, y)| {
                            TriangleMarker::new((x + 8, y), 5, BLACK.stroke_width(1))
                        });
                }
            }
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 11))
            .draw()
            .map_err(|e| err(&fig.name, e))?;
        root.present().map_err(|e| err(&fig.name, e))?;
    }
    Ok(out)
}
