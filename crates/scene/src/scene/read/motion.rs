//! `[motion]`: static, 2D rolling with a creep ratio, 3D rolling with creepages (steady or
//! transient, `[motion.transient]`), or a wheelset's speed and pitch rate.

use super::Reader;
use crate::error::{ErrorKind, SceneError};
use crate::raw::{Qty, RawScene};
use crate::scene::{Motion, Transient, TransientStart};
use crate::units::Dim;

pub(super) fn motion(cx: &Reader<'_>, raw: &RawScene, wheel: bool) -> Result<Motion, SceneError> {
    let Some(m) = &raw.motion else { return Ok(Motion::Static) };
    let mr = m.get_ref();
    if let (false, Some(p)) = (wheel, &mr.pitch_rate) {
        return Err(cx
            .err(ErrorKind::Schema, "motion.pitch_rate", Some(p.span()), "`pitch_rate` is given but the geometry is not a wheel on a rail")
            .hint("pitch_rate is a wheelset's angular velocity about its axle (geometry.kind = \"wheel-rail\"); 3D rolling of other bodies takes motion.creepage"));
    }
    let rolling_key = mr
        .speed
        .as_ref()
        .map(|q| ("speed", q.span()))
        .or(mr.creep.as_ref().map(|c| ("creep", c.span())))
        .or(mr.creepage.as_ref().map(|c| ("creepage", c.span())))
        .or(mr.transient.as_ref().map(|c| ("transient", c.span())));
    let kind = match &mr.kind {
        Some(k) => cx.choice(k, "motion.kind", &["static", "rolling"])?,
        // A speed or a creep says the bodies roll; nothing else can be meant.
        None if rolling_key.is_some() => "rolling",
        None => "static",
    };
    Ok(match kind {
        "static" => {
            if let Some((key, span)) = rolling_key {
                return Err(cx
                    .err(
                        ErrorKind::Schema,
                        &format!("motion.{key}"),
                        Some(span),
                        format!("a static contact takes no `{key}`"),
                    )
                    .hint("kind = \"rolling\" (or leave `kind` out) to roll, or remove the rolling keys"));
            }
            Motion::Static
        }
        _ => {
            let sp = cx.required(
                &mr.speed,
                "motion.speed",
                m.span(),
                "the rolling speed w, e.g. speed = \"10 cm/s\"",
            )?;
            let speed = cx.qty(sp, "motion.speed", Dim::SPEED, "speed")?;
            if wheel {
                if let Some(c) = &mr.creep {
                    return Err(cx
                        .err(ErrorKind::Schema, "motion.creep", Some(c.span()), "`creep` is the 2D creep ratio of a rolling cylinder, not a wheel on a rail")
                        .hint("give the wheelset's motion.pitch_rate, or for a single patch its creepages motion.creepage = { longitudinal, lateral, spin }"));
                }
                if let (Some(c), Some(_)) = (&mr.creepage, &mr.pitch_rate) {
                    return Err(cx
                        .err(ErrorKind::Schema, "motion.creepage", Some(c.span()), "both `creepage` and `pitch_rate` are given")
                        .hint("the creepages follow from the pitch rate, or are given directly for a single patch: give one"));
                }
                if let Some(t) = &mr.transient {
                    return Err(cx
                        .err(ErrorKind::Unsupported, "motion.transient", Some(t.span()), "transient rolling of a wheel on a rail is not solved in this version")
                        .hint("remove [motion.transient]; transient rolling is solved for a sphere, an ellipsoid or a surface"));
                }
                let pitch_rate = match &mr.pitch_rate {
                    None => None,
                    Some(p) => {
                        Some(cx.qty(p, "motion.pitch_rate", Dim::PER_TIME, "angular velocity")?)
                    }
                };
                let creepage = match &mr.creepage {
                    Some(cr) => Some(creepages(cx, cr)?),
                    None => None,
                };
                return Ok(Motion::Wheelset { speed, pitch_rate, creepage });
            }
            let transient = match &mr.transient {
                None => None,
                Some(t) => {
                    cx.record("motion.transient", t.span());
                    let tr = t.get_ref();
                    let start = match &tr.start {
                        None => TransientStart::Shift,
                        Some(s) => {
                            match cx.choice(s, "motion.transient.start", &["shift", "rest"])? {
                                "rest" => TransientStart::Rest,
                                _ => TransientStart::Shift,
                            }
                        }
                    };
                    let distance = match &tr.distance {
                        None => None,
                        Some(d) => {
                            Some(cx.qty(d, "motion.transient.distance", Dim::LENGTH, "length")?)
                        }
                    };
                    if let Some(c) = &mr.creep {
                        return Err(cx
                            .err(ErrorKind::Schema, "motion.creep", Some(c.span()), "`creep` is given with [motion.transient]")
                            .hint("transient rolling is 3D: its creep force is load.tangential, its spin motion.creepage.spin; remove `creep`"));
                    }
                    Some(Transient { start, distance, creepage_control: false })
                }
            };
            if transient.is_some() && mr.creepage.is_none() {
                return Ok(Motion::RollingCreepage {
                    speed,
                    longitudinal: 0.0,
                    lateral: 0.0,
                    spin: 0.0,
                    transient,
                });
            }
            if let Some(cr) = &mr.creepage {
                if let Some(c) = &mr.creep {
                    return Err(cx
                        .err(
                            ErrorKind::Schema,
                            "motion.creep",
                            Some(c.span()),
                            "both `creep` and `creepage` are given",
                        )
                        .hint("`creep` is the 2D creep ratio of a rolling cylinder; `creepage = { longitudinal, lateral, spin }` is for 3D rolling: give one"));
                }
                let [longitudinal, lateral, spin] = creepages(cx, cr)?;
                let c = cr.get_ref();
                // Transient rolling at prescribed creepages when either is given (zero
                // included: free rolling with spin); otherwise under the creep force.
                let transient = transient.map(|t| Transient {
                    creepage_control: c.longitudinal.is_some() || c.lateral.is_some(),
                    ..t
                });
                return Ok(Motion::RollingCreepage {
                    speed,
                    longitudinal,
                    lateral,
                    spin,
                    transient,
                });
            }
            let creep = mr.creep.as_ref().map_or(0.0, |c| cx.num(c, "motion.creep"));
            Motion::Rolling { speed, creep }
        }
    })
}

/// `motion.creepage = { longitudinal, lateral, spin }`: the two ratios, and the spin with
/// its reciprocal-length unit.
fn creepages(
    cx: &Reader<'_>,
    cr: &toml::Spanned<crate::raw::RawCreepage>,
) -> Result<[f64; 3], SceneError> {
    cx.record("motion.creepage", cr.span());
    let c = cr.get_ref();
    let longitudinal =
        c.longitudinal.as_ref().map_or(0.0, |v| cx.num(v, "motion.creepage.longitudinal"));
    let lateral = c.lateral.as_ref().map_or(0.0, |v| cx.num(v, "motion.creepage.lateral"));
    let spin = match &c.spin {
        None => 0.0,
        Some(s) => {
            if let Qty::Num(v) = s.get_ref() {
                if *v != 0.0 {
                    return Err(cx
                        .err(
                            ErrorKind::Unit,
                            "motion.creepage.spin",
                            Some(s.span()),
                            format!("the spin creepage {v} has no unit"),
                        )
                        .hint("spin is a reciprocal length: write it with its unit, e.g. spin = \"0.1 1/m\" or \"0.1 rad/m\""));
                }
            }
            cx.qty(s, "motion.creepage.spin", Dim::PER_LENGTH, "reciprocal length")?
        }
    };
    Ok([longitudinal, lateral, spin])
}
