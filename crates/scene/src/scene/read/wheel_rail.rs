//! `[geometry]` of kind "wheel-rail" and `[position]`: the profile files (read here, parsed
//! and checked by the planner with `stickslip-wheelrail`), the track and wheelset
//! dimensions, and the wheelset's position.

use std::ops::Range;
use std::path::Path;

use super::Reader;
use crate::error::{ErrorKind, SceneError};
use crate::raw::{Qty, RawGeometry, RawScene, SQty};
use crate::scene::{ProfileFile, RailSide, WheelLoadDefinition, WheelRail, WheelsetPosition};
use crate::units::{parse_quantity, Dim};

/// An angle: a number (rad) or a string with rad, mrad, urad or deg.
pub(super) fn angle(cx: &Reader<'_>, q: &SQty, key: &str) -> Result<f64, SceneError> {
    cx.record(key, q.span());
    let bad = |found: &str| {
        cx.err(ErrorKind::Unit, key, Some(q.span()), format!("\"{found}\" is not an angle"))
            .hint("an angle is a number in rad or a string with its unit: \"4.8 mrad\", \"0.0025 rad\", \"1.5 deg\"")
    };
    match q.get_ref() {
        Qty::Num(v) => Ok(*v),
        Qty::Text(t) => {
            let s = t.trim();
            let split = s
                .find(|c: char| c.is_alphabetic() || c == 'µ' || c == 'μ')
                .ok_or_else(|| bad(t))?;
            let (num, unit) = (s[..split].trim(), s[split..].trim());
            let v: f64 = num.parse().map_err(|_| bad(t))?;
            let f = match unit {
                "rad" => 1.0,
                "mrad" => 1e-3,
                "urad" | "µrad" | "μrad" => 1e-6,
                "deg" | "°" => std::f64::consts::PI / 180.0,
                _ => return Err(bad(t)),
            };
            Ok(v * f)
        }
    }
}

fn length(
    cx: &Reader<'_>,
    v: &Option<SQty>,
    key: &str,
    gspan: &Range<usize>,
    what: &str,
) -> Result<f64, SceneError> {
    let q = cx.required(v, key, gspan.clone(), what)?;
    cx.qty(q, key, Dim::LENGTH, "length")
}

fn profile_file(
    cx: &Reader<'_>,
    v: &Option<toml::Spanned<String>>,
    key: &str,
    gspan: &Range<usize>,
    what: &str,
) -> Result<ProfileFile, SceneError> {
    let f = cx.required(v, key, gspan.clone(), what)?;
    cx.record(key, f.span());
    let name = f.get_ref().clone();
    let path = match cx.file.as_deref().and_then(Path::parent) {
        Some(dir) if Path::new(&name).is_relative() => dir.join(&name),
        _ => Path::new(&name).to_path_buf(),
    };
    let text = std::fs::read_to_string(&path).map_err(|e| {
        cx.err(
            ErrorKind::Io,
            key,
            Some(f.span()),
            format!("cannot read the profile file {}: {e}", path.display()),
        )
        .hint("the path is relative to the scene file; SIMPACK (.prr, .prw), MiniProf (.ban, .whl) or two columns y z")
    })?;
    Ok(ProfileFile { name, path, text: std::sync::Arc::from(text) })
}

/// `[geometry]` of kind "wheel-rail" with `[position]`.
pub(super) fn wheel_rail(
    cx: &Reader<'_>,
    g: &RawGeometry,
    gspan: Range<usize>,
    raw: &RawScene,
) -> Result<WheelRail, SceneError> {
    let side = match &g.side {
        None => {
            return Err(cx
                .err(ErrorKind::Schema, "geometry.side", Some(gspan), "missing key `geometry.side`")
                .hint("side = \"left\" or \"right\" (the rail the wheel runs on)"))
        }
        Some(s) => match cx.choice(s, "geometry.side", &["left", "right"])? {
            "left" => RailSide::Left,
            _ => RailSide::Right,
        },
    };
    let rail_profile = profile_file(
        cx,
        &g.rail_profile,
        "geometry.rail_profile",
        &gspan,
        "the rail profile file, e.g. rail_profile = \"MBench_UIC60_v3.prr\"",
    )?;
    let wheel_profile = profile_file(
        cx,
        &g.wheel_profile,
        "geometry.wheel_profile",
        &gspan,
        "the wheel profile file, e.g. wheel_profile = \"MBench_S1002_v3.prw\"",
    )?;
    let profile_unit = match &g.profile_unit {
        None => 1e-3,
        Some(u) => {
            cx.record("geometry.profile_unit", u.span());
            parse_quantity(&format!("1 {}", u.get_ref()), Dim::LENGTH, "length").map_err(|e| {
                cx.err(ErrorKind::Unit, "geometry.profile_unit", Some(u.span()), e.to_string())
                    .hint("a length unit: \"mm\" (the default), \"m\", \"in\"")
            })?
        }
    };
    let gauge = length(
        cx,
        &g.gauge,
        "geometry.gauge",
        &gspan,
        "the track gauge, e.g. gauge = \"1435 mm\"",
    )?;
    let gauge_height = length(
        cx,
        &g.gauge_height,
        "geometry.gauge_height",
        &gspan,
        "the depth of the gauge point below the track plane, e.g. gauge_height = \"14 mm\"",
    )?;
    let rail_cant = match &g.rail_cant {
        None => 0.0,
        Some(q) => angle(cx, q, "geometry.rail_cant")?,
    };
    let flange_back_distance = length(
        cx,
        &g.flange_back_distance,
        "geometry.flange_back_distance",
        &gspan,
        "the wheelset's flange back distance, e.g. flange_back_distance = \"1360 mm\"",
    )?;
    let flange_back_position = length(
        cx,
        &g.flange_back_position,
        "geometry.flange_back_position",
        &gspan,
        "the flange back in the wheel profile's own y, e.g. flange_back_position = \"-70 mm\"",
    )?;
    let wheel_radius = length(
        cx,
        &g.wheel_radius,
        "geometry.wheel_radius",
        &gspan,
        "the nominal wheel radius, e.g. wheel_radius = \"460 mm\"",
    )?;
    let mut position = WheelsetPosition::default();
    if let Some(p) = &raw.position {
        cx.record("position", p.span());
        let pr = p.get_ref();
        if let Some(q) = &pr.lateral {
            position.lateral = cx.qty(q, "position.lateral", Dim::LENGTH, "length")?;
        }
        if let Some(q) = &pr.yaw {
            position.yaw = angle(cx, q, "position.yaw")?;
        }
        if let Some(q) = &pr.roll {
            position.roll = angle(cx, q, "position.roll")?;
        }
    }
    // What carries the vertical load: refused beside load.approach (no load to carry).
    let l = raw.load.get_ref();
    let vertical = match &l.vertical {
        None => WheelLoadDefinition::Normal,
        Some(v) => {
            let hint = "vertical = \"normal\" (the default: the normal forces' vertical components carry load.normal) or \"total\" (the total vertical force, creep forces included, as CONTACT)";
            let value =
                cx.choice(v, "load.vertical", &["normal", "total"]).map_err(|e| e.hint(hint))?;
            if l.approach.is_some() {
                return Err(cx
                    .err(
                        ErrorKind::Schema,
                        "load.vertical",
                        Some(v.span()),
                        "load.vertical says what carries the vertical wheel load load.normal; under load.approach there is no load to carry",
                    )
                    .hint("remove load.vertical, or give load.normal = \"10 kN\" instead of load.approach"));
            }
            if value == "total" {
                WheelLoadDefinition::Total
            } else {
                WheelLoadDefinition::Normal
            }
        }
    };
    Ok(WheelRail {
        vertical,
        side,
        rail_profile,
        wheel_profile,
        profile_unit,
        gauge,
        gauge_height,
        rail_cant,
        flange_back_distance,
        flange_back_position,
        wheel_radius,
        position,
    })
}
