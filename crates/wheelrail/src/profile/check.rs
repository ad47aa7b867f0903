//! The checks every profile passes before use (refusals name the file and the line).
//!
//! In order, on the points in metres and in the canonical orientation:
//! 1. every coordinate is a finite number;
//! 2. the points are put in the order of increasing $y$ (reversed if the file runs the other
//!    way), and a point closer than [`DUPLICATE_DISTANCE`] to the one kept before it is
//!    dropped (files repeat points, or step by fractions of a micrometre along vertical
//!    faces, which would make the chord-length parameter degenerate);
//! 3. at least [`MIN_POINTS`] points remain;
//! 4. the summed chord length lies in [`LENGTH_RANGE`] (a profile of 5 mm to 500 mm; outside
//!    it the length unit is almost certainly wrong, the rule CONTACT applies too);
//! 5. no two non-adjacent segments cross (a loop);
//! 6. $y$ steps back only on a near-vertical face (segments steeper than
//!    [`BACKSTEP_MIN_SLOPE`]) and by at most [`BACKSTEP_MAX`] in all (a leaning flange back
//!    or gauge face), or by less than [`BACKSTEP_NOISE`] (measurement noise);
//! 7. the shape fits the role: a rail head falls away on both sides of its top (both ends at
//!    least [`RAIL_CROWN_MIN`] below the highest point), and a wheel's field-side end does
//!    not lie more than [`WHEEL_FIELD_DROP_MAX`] below its highest point (a wheel rises
//!    towards its field side; a rail head given as a wheel, or a wheel mirrored so its
//!    flange is on the field side, fails this).

use super::Role;
use crate::error::{Error, Result};

/// Points closer than this to the previous kept point are dropped (m).
pub const DUPLICATE_DISTANCE: f64 = 1e-6;
/// Fewest points of a profile.
pub const MIN_POINTS: usize = 10;
/// Allowed summed chord length of a profile (m).
pub const LENGTH_RANGE: (f64, f64) = (5e-3, 0.5);
/// A backward step in $y$ is allowed on segments at least this steep ($|dz/dy|$, about 70°).
pub const BACKSTEP_MIN_SLOPE: f64 = 2.75;
/// The largest total backward step in $y$ of a near-vertical face (m).
pub const BACKSTEP_MAX: f64 = 1e-3;
/// Backward steps smaller than this are accepted anywhere (measurement noise: MiniProf
/// files give 0.01 mm, and measured rails step back by one digit, m).
pub const BACKSTEP_NOISE: f64 = 2e-5;
/// A rail head's ends lie at least this far below its top (m).
pub const RAIL_CROWN_MIN: f64 = 0.5e-3;
/// A wheel's field-side end lies at most this far below its highest point (m).
pub const WHEEL_FIELD_DROP_MAX: f64 = 5e-3;

fn refuse(name: &str, line: Option<usize>, problem: String, hint: &str) -> Error {
    Error::ProfileCheck { name: name.to_string(), line, problem, hint: hint.to_string() }
}

/// Points that passed the checks: $y$, $z$ (m) and the line of each.
pub(crate) struct Checked {
    pub y: Vec<f64>,
    pub z: Vec<f64>,
    pub line: Vec<usize>,
}

/// Run the checks of the module docs on `points` ($(y, z)$ in m with their lines).
pub(crate) fn check(
    mut points: Vec<(f64, f64, usize)>,
    name: &str,
    role: Role,
    unit: f64,
) -> Result<Checked> {
    // 1. finite
    if let Some(&(y, z, ln)) = points.iter().find(|p| !(p.0.is_finite() && p.1.is_finite())) {
        return Err(refuse(
            name,
            Some(ln),
            format!(
                "the point (y, z) = ({}, {}) is not a pair of finite numbers",
                y / unit,
                z / unit
            ),
            "every profile point needs two finite coordinates; remove or repair the line",
        ));
    }
    if points.len() < 2 {
        return Err(refuse(
            name,
            None,
            format!("{} point(s) found, at least {MIN_POINTS} are needed", points.len()),
            "is this a profile file of the format its name says?",
        ));
    }
    // 2. order and duplicates
    if points[points.len() - 1].0 < points[0].0 {
        points.reverse();
    }
    let mut kept: Vec<(f64, f64, usize)> = Vec::with_capacity(points.len());
    for p in points {
        match kept.last() {
            Some(q) if (p.0 - q.0).hypot(p.1 - q.1) < DUPLICATE_DISTANCE => {}
            _ => kept.push(p),
        }
    }
    // 3. count
    if kept.len() < MIN_POINTS {
        return Err(refuse(
            name,
            None,
            format!("{} distinct point(s), at least {MIN_POINTS} are needed", kept.len()),
            "give the whole running surface of the profile",
        ));
    }
    let y: Vec<f64> = kept.iter().map(|p| p.0).collect();
    let z: Vec<f64> = kept.iter().map(|p| p.1).collect();
    let line: Vec<usize> = kept.iter().map(|p| p.2).collect();
    let n = y.len();
    // 4. size (unit)
    let length: f64 = (1..n).map(|i| (y[i] - y[i - 1]).hypot(z[i] - z[i - 1])).sum();
    let width = y.iter().copied().fold(f64::NEG_INFINITY, f64::max)
        - y.iter().copied().fold(f64::INFINITY, f64::min);
    let height = z.iter().copied().fold(f64::NEG_INFINITY, f64::max)
        - z.iter().copied().fold(f64::INFINITY, f64::min);
    if !(LENGTH_RANGE.0..=LENGTH_RANGE.1).contains(&length) {
        return Err(refuse(
            name,
            None,
            format!(
                "the profile is {length:.4e} m long (summed chord length), {width:.4e} m wide and {height:.4e} m high, read with one file unit = {unit:e} m; a rail or wheel profile is 5 mm to 500 mm long"
            ),
            "check profile_unit (the length unit of the file's numbers)",
        ));
    }
    // 5. loops: non-adjacent segments that cross
    if let Some((i, j)) = first_crossing(&y, &z) {
        return Err(refuse(
            name,
            Some(line[i]),
            format!(
                "the profile crosses itself: the segment of lines {}-{} crosses the segment of lines {}-{}",
                line[i],
                line[i + 1],
                line[j],
                line[j + 1]
            ),
            "remove the loop; a profile must run once across the rail or wheel",
        ));
    }
    // 6. back-steps
    let mut ymax = y[0];
    for i in 1..n {
        let dy = y[i] - y[i - 1];
        let dz = z[i] - z[i - 1];
        let overhang = ymax - y[i];
        if dy < 0.0 && overhang > BACKSTEP_NOISE {
            let steep = dz.abs() >= BACKSTEP_MIN_SLOPE * dy.abs();
            if !steep || overhang > BACKSTEP_MAX {
                return Err(refuse(
                    name,
                    Some(line[i]),
                    format!(
                        "the profile steps back in y by {:.4e} m (to y = {:.6e} m after reaching {:.6e} m){}",
                        overhang,
                        y[i],
                        ymax,
                        if steep { "" } else { " on a face that is not near-vertical" }
                    ),
                    "a profile runs one way across the rail or wheel; only a near-vertical flange back or gauge face may lean back, by at most 1 mm",
                ));
            }
        }
        ymax = ymax.max(y[i]);
    }
    // 7. the shape of the role
    let (imin, zmin) =
        z.iter()
            .copied()
            .enumerate()
            .fold((0, f64::INFINITY), |a, (i, v)| if v < a.1 { (i, v) } else { a });
    match role {
        Role::Rail => {
            let (d0, d1) = (z[0] - zmin, z[n - 1] - zmin);
            if d0 < RAIL_CROWN_MIN || d1 < RAIL_CROWN_MIN {
                return Err(refuse(
                    name,
                    Some(line[imin]),
                    format!(
                        "this does not look like a rail head: its highest point (z = {zmin:.4e} m at y = {:.4e} m) has ends only {d0:.3e} m and {d1:.3e} m below it; a rail head falls away on both sides of its top",
                        y[imin]
                    ),
                    "if this is a wheel profile, give it as the wheel; if z points up in the file, mirror z",
                ));
            }
        }
        Role::Wheel => {
            let drop = z[n - 1] - zmin;
            if drop > WHEEL_FIELD_DROP_MAX {
                return Err(refuse(
                    name,
                    Some(line[n - 1]),
                    format!(
                        "this does not look like a wheel: its field-side end (largest y) lies {drop:.4e} m below its highest point; a wheel rises towards its field side, a rail head falls on both sides"
                    ),
                    "if this is a rail profile, give it as the rail; if the flange is on the field side, mirror y",
                ));
            }
        }
    }
    Ok(Checked { y, z, line })
}

/// The first pair of non-adjacent segments $(i, j)$, $i < j$, that cross (segment $k$ joins
/// points $k$ and $k+1$).
fn first_crossing(y: &[f64], z: &[f64]) -> Option<(usize, usize)> {
    let n = y.len();
    let bbox =
        |k: usize| (y[k].min(y[k + 1]), y[k].max(y[k + 1]), z[k].min(z[k + 1]), z[k].max(z[k + 1]));
    let boxes: Vec<_> = (0..n - 1).map(bbox).collect();
    for i in 0..n - 1 {
        let a = boxes[i];
        for j in i + 2..n - 1 {
            let b = boxes[j];
            if a.1 < b.0 || b.1 < a.0 || a.3 < b.2 || b.3 < a.2 {
                continue;
            }
            if segments_cross(
                [y[i], z[i]],
                [y[i + 1], z[i + 1]],
                [y[j], z[j]],
                [y[j + 1], z[j + 1]],
            ) {
                return Some((i, j));
            }
        }
    }
    None
}

/// Whether the closed segments $pq$ and $rs$ properly cross (orientation test).
fn segments_cross(p: [f64; 2], q: [f64; 2], r: [f64; 2], s: [f64; 2]) -> bool {
    let orient = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    };
    let (d1, d2) = (orient(p, q, r), orient(p, q, s));
    let (d3, d4) = (orient(r, s, p), orient(r, s, q));
    (d1 > 0.0) != (d2 > 0.0)
        && d1 != 0.0
        && d2 != 0.0
        && (d3 > 0.0) != (d4 > 0.0)
        && d3 != 0.0
        && d4 != 0.0
}
