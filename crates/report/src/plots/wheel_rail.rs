//! A wheel on its rail: the two profiles at the contact with the patches marked, and each
//! patch's pressure and stick/slip maps (the map code of [`super::maps`]).

use plotters::prelude::*;
use stickslip_run::WheelRailOut;

use super::maps::{heat_map, stick_map, stick_outline, Map};
use super::{err, titled, PlotResult};

const RAIL: RGBColor = RGBColor(40, 40, 40);
const WHEEL: RGBColor = RGBColor(40, 90, 200);
const PATCH: RGBColor = RGBColor(210, 60, 40);

/// The plots of a wheel on its rail, appended to `files`.
pub(super) fn render(
    w: &WheelRailOut,
    st: &str,
    sub: &str,
    files: &mut Vec<(String, String)>,
) -> Result<(), String> {
    files.push(("wheel_rail_profiles.svg".to_string(), profiles(w, st, sub)?));
    for (k, p) in w.patches.iter().enumerate() {
        let m = &p.maps;
        let (nx, ns) = (m.x.len(), m.s.len());
        if nx == 0 || ns == 0 || m.pressure.len() != nx * ns || m.stick.len() != nx * ns {
            continue;
        }
        // The maps' rows are along s; the stick map and outline take [i][j].
        let rows: Vec<Vec<f64>> =
            (0..ns).map(|j| m.pressure[j * nx..(j + 1) * nx].to_vec()).collect();
        let stick: Vec<Vec<i8>> =
            (0..nx).map(|i| (0..ns).map(|j| m.stick[j * nx + i]).collect()).collect();
        let outline = if m.qx.is_some() { stick_outline(&m.x, &m.s, &stick) } else { Vec::new() };
        let what = if m.qx.is_some() { " (white: stick zone outline)" } else { "" };
        files.push((
            format!("patch{k}_pressure.svg"),
            heat_map(&Map {
                title: format!(
                    "{st}: patch {k}, pressure p, contact angle {:.4} rad{what}",
                    p.contact_angle
                ),
                sub,
                name: "p",
                base: "Pa",
                x: &m.x,
                y: &m.s,
                v: &rows,
                yflip: false,
                yname: "s",
                outline: &outline,
            })?,
        ));
        if m.qx.is_some() {
            files.push((
                format!("patch{k}_stick_slip.svg"),
                stick_map((&format!("{st}: patch {k}"), sub), &m.x, &m.s, &stick)?,
            ));
        }
    }
    Ok(())
}

/// The ends of patch `k`'s contact across the patch, in track (y, z), m: the reference point
/// moved along the patch's s axis, $(\cos\delta, \sin\delta)$, to the first and last
/// contact rows.
pub(crate) fn patch_ends(w: &WheelRailOut, k: usize) -> Option<[[f64; 2]; 2]> {
    let p = w.patches.get(k)?;
    let m = &p.maps;
    let nx = m.x.len();
    let rows: Vec<usize> = (0..m.s.len())
        .filter(|&j| m.stick.get(j * nx..(j + 1) * nx).is_some_and(|r| r.iter().any(|&v| v >= 0)))
        .collect();
    let (j0, j1) = (*rows.first()?, *rows.last()?);
    let h = 0.5 * p.lattice.hs;
    let (c, s) = (p.contact_angle.cos(), p.contact_angle.sin());
    let at = |d: f64| [p.reference[1] + d * c, p.reference[2] + d * s];
    Some([at(m.s[j0] - h), at(m.s[j1] + h)])
}

/// Rail and wheel profiles in the track's y–z plane near the contact, equal scales, z down
/// drawn downwards; each patch's contact width drawn along its plane, its reference point
/// marked.
fn profiles(w: &WheelRailOut, st: &str, sub: &str) -> PlotResult {
    let [rail, wheel] = &w.profiles;
    let mm = |p: &[f64; 2]| (p[0] * 1e3, -p[1] * 1e3);
    // The window: 80 mm across, centred on the patches (or the rail's top).
    let (yc, hc) = if w.patches.is_empty() {
        rail.iter().map(mm).fold((0.0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a })
    } else {
        let n = w.patches.len() as f64;
        let y = w.patches.iter().map(|p| p.reference[1]).sum::<f64>() / n;
        let z = w.patches.iter().map(|p| p.reference[2]).sum::<f64>() / n;
        (y * 1e3, -z * 1e3)
    };
    let (width, height) = (720u32, 470u32);
    let (half_w, half_h) = (40.0, 40.0 * 0.62);
    let (y0, y1, h0, h1) = (yc - half_w, yc + half_w, hc - half_h, hc + half_h);
    let inside = |q: &(f64, f64)| q.0 >= y0 && q.0 <= y1 && q.1 >= h0 && q.1 <= h1;
    let mut s = String::new();
    {
        let root = SVGBackend::with_string(&mut s, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let root = titled(
            &root,
            &format!(
                "{st}: profiles at the contact (rail black, wheel blue, patches red), z = {:.4} mm",
                w.z_wheelset * 1e3
            ),
            sub,
        )?;
        let mut chart = ChartBuilder::on(&root)
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(y0..y1, h0..h1)
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc("y (mm, track, to the right)")
            .y_desc("-z (mm, up)")
            .draw()
            .map_err(err)?;
        for (curve, colour, label) in [(rail, RAIL, "rail"), (wheel, WHEEL, "wheel")] {
            // The parts inside the window, as separate runs.
            let pts: Vec<(f64, f64)> = curve.iter().map(mm).collect();
            let mut runs: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
            for q in pts {
                if inside(&q) {
                    if let Some(r) = runs.last_mut() {
                        r.push(q);
                    }
                } else if runs.last().is_some_and(|r| !r.is_empty()) {
                    runs.push(Vec::new());
                }
            }
            for (i, r) in runs.into_iter().filter(|r| r.len() > 1).enumerate() {
                let series =
                    chart.draw_series(LineSeries::new(r, colour.stroke_width(2))).map_err(err)?;
                if i == 0 {
                    series.label(label).legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 18, y)], colour.stroke_width(2))
                    });
                }
            }
        }
        for (k, p) in w.patches.iter().enumerate() {
            if let Some([a, b]) = patch_ends(w, k) {
                chart
                    .draw_series(std::iter::once(PathElement::new(
                        vec![mm(&a), mm(&b)],
                        PATCH.stroke_width(5),
                    )))
                    .map_err(err)?;
            }
            let c = (p.reference[1] * 1e3, -p.reference[2] * 1e3);
            chart.draw_series(std::iter::once(Circle::new(c, 4, PATCH.filled()))).map_err(err)?;
            chart
                .draw_series(std::iter::once(Text::new(
                    format!("patch {k}: Fn {:.4} kN, δ {:.4} rad", p.fn_ / 1e3, p.contact_angle),
                    (c.0 + 1.0, c.1 + 3.0 + 2.5 * k as f64),
                    ("sans-serif", 13),
                )))
                .map_err(err)?;
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

#[cfg(test)]
mod tests {
    use super::*;
    use stickslip_run::{run, RunOptions};
    use stickslip_scene::Scene;

    /// The distance from `q` to the polyline `line` (m).
    fn distance(q: [f64; 2], line: &[[f64; 2]]) -> f64 {
        line.windows(2)
            .map(|w| {
                let (a, b) = (w[0], w[1]);
                let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                let t = (((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / (dx * dx + dy * dy))
                    .clamp(0.0, 1.0);
                (q[0] - a[0] - t * dx).hypot(q[1] - a[1] - t * dy)
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// The patches drawn on the profiles lie on the placed rail: the ends of each patch's
    /// contact width, laid along (cos d, sin d) from its reference point, are on the rail
    /// polyline within 0.05 mm, on the tread (left wheel, A-2.2 position 5) and on the flange
    /// (right wheel, position 14, contact angle about -1.16 rad).
    #[test]
    fn patches_are_drawn_on_the_rail() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let file = root.join("scenes/wheel_rail_manchester_a22.toml");
        let base = std::fs::read_to_string(&file).unwrap();
        let flange = base
            .replace("side = \"left\"", "side = \"right\"")
            .replace("lateral = \"2 mm\"", "lateral = \"6.5 mm\"")
            .replace("yaw = \"4.8 mrad\"", "yaw = \"15.6 mrad\"")
            .replace("roll = \"-0.1128 mrad\"", "roll = \"-4.376 mrad\"")
            .replace("-4.3459197 rad/s", "-4.2748834 rad/s");
        assert_ne!(flange, base);
        let mut angles = Vec::new();
        for text in [&base, &flange] {
            let out = run(
                &Scene::from_toml_str(text, Some(file.clone())).unwrap(),
                &RunOptions::default(),
            )
            .unwrap();
            let w = out.wheel_rail.as_ref().unwrap();
            for (k, p) in w.patches.iter().enumerate() {
                angles.push(p.contact_angle);
                let [a, b] = patch_ends(w, k).unwrap();
                let width = (a[0] - b[0]).hypot(a[1] - b[1]);
                assert!(width >= p.lattice.hs * (1.0 - 1e-9), "patch {k}: width {width}");
                for e in [a, b] {
                    let d = distance(e, &w.profiles[0]);
                    assert!(
                        d < 5e-5,
                        "patch {k} (angle {}): an end {d} m off the rail",
                        p.contact_angle
                    );
                }
            }
            let svg = profiles(w, "t", "").unwrap();
            assert!(svg.contains("patch 0: Fn"));
        }
        assert!(angles.iter().any(|a| a.abs() > 1.0), "a flange contact was drawn: {angles:?}");
    }
}
