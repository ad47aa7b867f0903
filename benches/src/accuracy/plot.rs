//! Log-log Pareto plots (error against time), one SVG per method.

use super::MethodReport;
use plotters::prelude::*;
use std::path::Path;

/// Errors of exactly zero are drawn at this floor (below double precision).
const ERROR_FLOOR: f64 = 1e-17;

/// A log range that contains `vals` with a margin (a factor 3 either side; a decade each way
/// for a single value).
fn log_range(vals: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = vals.fold((f64::INFINITY, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if !(lo.is_finite() && hi > 0.0) {
        return (1e-3, 1.0);
    }
    if hi / lo < 10.0 {
        (lo / 10.0, hi * 10.0)
    } else {
        (lo / 3.0, hi * 3.0)
    }
}

/// Draw the Pareto plot of `m` into `path`.
pub(super) fn pareto(m: &MethodReport, path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (720, 460)).into_drawing_area();
    root.fill(&WHITE)?;
    let pts: Vec<(f64, f64)> =
        m.settings.iter().map(|s| (s.seconds.max(1e-9), s.error.max(ERROR_FLOOR))).collect();
    let claims: Vec<(f64, f64)> = m
        .settings
        .iter()
        .filter_map(|s| s.claim.map(|c| (s.seconds.max(1e-9), c.max(ERROR_FLOOR))))
        .collect();
    let (t0, t1) = log_range(pts.iter().map(|p| p.0));
    let (e0, e1) = log_range(pts.iter().chain(&claims).map(|p| p.1));
    let mut chart = ChartBuilder::on(&root)
        .caption(format!("{}: error against time", m.title), ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(70)
        .build_cartesian_2d((t0..t1).log_scale(), (e0..e1).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("time per run [s]")
        .y_desc("error")
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    chart
        .draw_series(LineSeries::new(pts.clone(), BLUE.stroke_width(2)))?
        .label("measured error")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], BLUE.stroke_width(2)));
    chart.draw_series(pts.iter().map(|&p| Circle::new(p, 4, BLUE.filled())))?;
    if !claims.is_empty() {
        chart
            .draw_series(claims.iter().map(|&p| Cross::new(p, 5, RED.stroke_width(2))))?
            .label("claimed accuracy")
            .legend(|(x, y)| Cross::new((x + 8, y), 5, RED.stroke_width(2)));
    }
    chart.draw_series(
        m.settings
            .iter()
            .zip(&pts)
            .map(|(s, &p)| Text::new(format!(" {}", s.label), p, ("sans-serif", 12))),
    )?;
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()?;
    root.present()?;
    Ok(())
}
