//! The load curve of a surface (a load sweep or an approach path): the force and the
//! contact area against the approach, in the order the path was solved (an
//! approach–retraction path draws its hysteresis loop).

use plotters::prelude::RGBColor;
use stickslip_run::{ContactOut, LoadCurve};

use super::{line_chart, Curve};
use stickslip_scene::eng::eng;

/// `load_curve.svg` (force against approach, with the pull-off under adhesion) and
/// `load_curve_area.svg` (contact area, and the cohesive zone's, against approach).
pub(super) fn render(
    c: &LoadCurve,
    reference: Option<&(&'static str, Vec<f64>, Vec<f64>)>,
    contact: &ContactOut,
    st: &str,
    sub: &str,
    files: &mut Vec<(String, String)>,
) -> Result<(), String> {
    let blue = RGBColor(40, 90, 200);
    let red = RGBColor(200, 60, 40);
    let grey = RGBColor(40, 40, 40);
    let pull = match (contact.pull_off, contact.pull_off_reached) {
        (Some(f), Some(true)) => format!(" (pull-off {})", eng(f, "N")),
        (Some(f), _) => {
            format!(" (pull-off not reached; most tensile {})", eng(f, "N"))
        }
        _ => String::new(),
    };
    let mut forces =
        vec![Curve { dashed: false, label: "lattice", x: &c.approach, y: &c.normal, colour: blue }];
    if let Some((label, d, p)) = reference {
        forces.push(Curve { dashed: true, label, x: d, y: p, colour: grey });
    }
    files.push((
        "load_curve.svg".to_string(),
        line_chart(
            (&format!("{st}: normal force against approach{pull}"), sub),
            ("approach", "m"),
            ("normal force", "N"),
            &forces,
            &[],
        )?,
    ));
    let mut curves =
        vec![Curve { dashed: false, label: "contact", x: &c.approach, y: &c.area, colour: blue }];
    if let Some(z) = &c.zone_area {
        curves.push(Curve {
            dashed: true,
            label: "cohesive zone (gap below the range)",
            x: &c.approach,
            y: z,
            colour: red,
        });
    }
    files.push((
        "load_curve_area.svg".to_string(),
        line_chart(
            (&format!("{st}: contact area against approach"), sub),
            ("approach", "m"),
            ("area", "m^2"),
            &curves,
            &[],
        )?,
    ));
    Ok(())
}
