//! `[geometry]` of kind "surface": the lattice, the boundary, the profile and the roughness
//! (a height file or generated), read and checked with their keys' positions.

use super::Reader;
use crate::error::{ErrorKind, SceneError};
use crate::scene::{Profile, Surface, SurfaceBoundary};
use crate::units::{parse_quantity, Dim};

/// `[geometry]` of kind "surface": the lattice, the profile and the roughness.
pub(super) fn surface(
    cx: &Reader<'_>,
    g: &crate::raw::RawGeometry,
    gspan: std::ops::Range<usize>,
) -> Result<Surface, SceneError> {
    let boundary = match &g.boundary {
        None => SurfaceBoundary::Free,
        Some(b) => match cx.choice(b, "geometry.boundary", &["free", "periodic"])? {
            "free" => SurfaceBoundary::Free,
            _ => SurfaceBoundary::Periodic,
        },
    };
    let size = cx.required(
        &g.size,
        "geometry.size",
        gspan.clone(),
        "size = [\"4 mm\", \"4 mm\"], the lattice extent in x and y",
    )?;
    let size = cx.pair(
        size,
        "geometry.size",
        Dim::LENGTH,
        "length",
        "two lengths, e.g. [\"4 mm\", \"4 mm\"]",
    )?;
    let cells = cx.required(
        &g.cells,
        "geometry.cells",
        gspan.clone(),
        "cells = [256, 256], the cells along x and y",
    )?;
    cx.record("geometry.cells", cells.span());
    let c = cells.get_ref();
    let whole = |v: f64| v.fract() == 0.0 && (1.0..=1e6).contains(&v);
    if c.len() != 2 || !c.iter().all(|v| whole(*v)) {
        return Err(cx
            .err(
                ErrorKind::Schema,
                "geometry.cells",
                Some(cells.span()),
                "expected two whole numbers of cells",
            )
            .hint("cells = [256, 256]"));
    }
    let cells = [c[0] as usize, c[1] as usize];
    let p = cx.required(&g.profile, "geometry.profile", gspan, "[geometry.profile] with shape = \"sphere\", radius = \"10 mm\" (or ellipsoid, punch, wavy, flat)")?;
    cx.record("geometry.profile", p.span());
    let pr = p.get_ref();
    let pspan = p.span();
    fn need<'v>(
        cx: &Reader<'_>,
        v: &'v Option<crate::raw::SQty>,
        key: &str,
        span: std::ops::Range<usize>,
        what: &str,
    ) -> Result<&'v crate::raw::SQty, SceneError> {
        cx.required(v, key, span, what)
    }
    let profile = match cx.choice(
        &pr.shape,
        "geometry.profile.shape",
        &["sphere", "ellipsoid", "cylinder", "punch", "wavy", "flat"],
    )? {
        "sphere" => Profile::Sphere {
            radius: cx.qty(
                need(cx, &pr.radius, "geometry.profile.radius", pspan.clone(), "the radius")?,
                "geometry.profile.radius",
                Dim::LENGTH,
                "radius",
            )?,
        },
        "ellipsoid" => {
            let r =
                cx.required(&pr.radii, "geometry.profile.radii", p.span(), "radii = [Rx, Ry]")?;
            Profile::Ellipsoid {
                radii: cx.pair(
                    r,
                    "geometry.profile.radii",
                    Dim::LENGTH,
                    "radius",
                    "two radii, e.g. [\"20 mm\", \"10 mm\"]",
                )?,
            }
        }
        "punch" => Profile::Punch {
            radius: cx.qty(
                need(
                    cx,
                    &pr.radius,
                    "geometry.profile.radius",
                    pspan.clone(),
                    "the radius of the flat face",
                )?,
                "geometry.profile.radius",
                Dim::LENGTH,
                "radius",
            )?,
            // Left out (or 0): the sharp-edged flat punch.
            edge_radius: match &pr.edge_radius {
                None => 0.0,
                Some(q) => cx.qty(q, "geometry.profile.edge_radius", Dim::LENGTH, "radius")?,
            },
        },
        "wavy" => Profile::Wavy {
            wavelength: cx.qty(
                need(
                    cx,
                    &pr.wavelength,
                    "geometry.profile.wavelength",
                    pspan.clone(),
                    "the wavelength",
                )?,
                "geometry.profile.wavelength",
                Dim::LENGTH,
                "length",
            )?,
            amplitude: cx.qty(
                need(
                    cx,
                    &pr.amplitude,
                    "geometry.profile.amplitude",
                    pspan.clone(),
                    "the amplitude",
                )?,
                "geometry.profile.amplitude",
                Dim::LENGTH,
                "length",
            )?,
            along_xy: match &pr.along {
                None => false,
                Some(a) => cx.choice(a, "geometry.profile.along", &["x", "xy"])? == "xy",
            },
        },
        "cylinder" => {
            let crown = match &pr.crown {
                None => 0.0,
                Some(c) => cx.qty(c, "geometry.profile.crown", Dim::LENGTH, "length")?,
            };
            let end_radius = match (&pr.end_radius, crown > 0.0) {
                (Some(r), _) => cx.qty(r, "geometry.profile.end_radius", Dim::LENGTH, "radius")?,
                (None, false) => 0.0,
                (None, true) => cx.qty(
                    need(
                        cx,
                        &pr.end_radius,
                        "geometry.profile.end_radius",
                        pspan.clone(),
                        "the end radius of the crown",
                    )?,
                    "geometry.profile.end_radius",
                    Dim::LENGTH,
                    "radius",
                )?,
            };
            Profile::Cylinder {
                radius: cx.qty(
                    need(
                        cx,
                        &pr.radius,
                        "geometry.profile.radius",
                        pspan.clone(),
                        "the roller radius",
                    )?,
                    "geometry.profile.radius",
                    Dim::LENGTH,
                    "radius",
                )?,
                length: cx.qty(
                    need(
                        cx,
                        &pr.length,
                        "geometry.profile.length",
                        pspan.clone(),
                        "the roller length (along y)",
                    )?,
                    "geometry.profile.length",
                    Dim::LENGTH,
                    "length",
                )?,
                crown,
                end_radius,
            }
        }
        // "flat": `cx.choice` admits only the listed shapes
        _ => Profile::Flat,
    };
    let roughness = match &g.roughness {
        None => None,
        Some(r) => {
            cx.record("geometry.roughness", r.span());
            let rr = r.get_ref();
            let Some(file) = &rr.file else {
                let heights = generated(cx, rr, r.span(), cells, size)?;
                return Ok(Surface { boundary, size, cells, profile, roughness: Some(heights) });
            };
            cx.record("geometry.roughness.file", file.span());
            let unit = match &rr.unit {
                None => 1.0,
                Some(u) => {
                    cx.record("geometry.roughness.unit", u.span());
                    parse_quantity(&format!("1 {}", u.get_ref()), Dim::LENGTH, "height unit")
                        .map_err(|e| {
                            cx.err(
                                ErrorKind::Unit,
                                "geometry.roughness.unit",
                                Some(u.span()),
                                e.to_string(),
                            )
                            .hint(e.suggestion().unwrap_or_else(
                                || "a length unit, e.g. \"um\", \"nm\", \"m\"".to_string(),
                            ))
                        })?
                }
            };
            let heights = crate::scene::heights::read(file.get_ref(), cx.file.as_deref()).map_err(|m| {
                cx.err(ErrorKind::Io, "geometry.roughness.file", Some(file.span()), m)
                    .hint("a .npy file of float64 (shape (ny, nx)) or a .csv with one row per y, relative to the scene file")
            })?;
            Some(heights.into_iter().map(|h| h * unit).collect())
        }
    };
    Ok(Surface { boundary, size, cells, profile, roughness })
}

/// Generated roughness: a self-affine random surface (lattice::roughness) of the lattice.
fn generated(
    cx: &Reader<'_>,
    rr: &crate::raw::RawRoughness,
    span: std::ops::Range<usize>,
    cells: [usize; 2],
    size: [f64; 2],
) -> Result<Vec<f64>, SceneError> {
    use stickslip_lattice::{roughness::Rms, roughness::SelfAffine};
    let hurst = cx.num(
        cx.required(
            &rr.hurst,
            "geometry.roughness.hurst",
            span.clone(),
            "hurst = 0.8 (0 < H <= 1), or file = \"heights.npy\"",
        )?,
        "geometry.roughness.hurst",
    );
    let rms = match (&rr.rms_height, &rr.rms_slope) {
        (Some(h), None) => {
            Rms::Height(cx.qty(h, "geometry.roughness.rms_height", Dim::LENGTH, "rms height")?)
        }
        (None, Some(s)) => Rms::Slope(cx.num(s, "geometry.roughness.rms_slope")),
        _ => {
            return Err(cx
                .err(
                    ErrorKind::Schema,
                    "geometry.roughness",
                    Some(span),
                    "give exactly one of `rms_height` and `rms_slope`",
                )
                .hint("rms_height = \"1 um\", or rms_slope = 0.05"))
        }
    };
    let nyquist = (cells[0] as f64 / 2.0).min(cells[1] as f64 * size[0] / (2.0 * size[1]));
    let k_low = rr.k_low.as_ref().map_or(1.0, |k| cx.num(k, "geometry.roughness.k_low"));
    let k_rolloff =
        rr.k_rolloff.as_ref().map_or(k_low, |k| cx.num(k, "geometry.roughness.k_rolloff"));
    let k_high = rr.k_high.as_ref().map_or(nyquist, |k| cx.num(k, "geometry.roughness.k_high"));
    let seed = match &rr.seed {
        None => 0,
        Some(s) => {
            cx.record("geometry.roughness.seed", s.span());
            u64::try_from(*s.get_ref()).map_err(|_| {
                cx.err(
                    ErrorKind::OutOfRange,
                    "geometry.roughness.seed",
                    Some(s.span()),
                    "a negative seed",
                )
                .hint("a whole number >= 0")
            })?
        }
    };
    let spec = SelfAffine { hurst, k_low, k_rolloff, k_high, rms, seed };
    spec.heights(cells[0], cells[1], size).map_err(|e| {
        let key = match &e {
            stickslip_lattice::Error::OutOfDomain { name, .. } => match *name {
                "hurst" => "geometry.roughness.hurst",
                "k_low" => "geometry.roughness.k_low",
                "k_high" => "geometry.roughness.k_high",
                "rms" => match rms {
                    Rms::Height(_) => "geometry.roughness.rms_height",
                    Rms::Slope(_) => "geometry.roughness.rms_slope",
                },
                _ => "geometry.roughness",
            },
            _ => "geometry.roughness",
        };
        let span = cx.spans.borrow().get(key).cloned();
        cx.err(ErrorKind::OutOfRange, key, span, e.to_string()).hint(format!(
            "0 < hurst <= 1, 1 <= k_low <= k_rolloff <= k_high <= {nyquist} (cycles per lattice length along x), rms > 0"
        ))
    })
}
