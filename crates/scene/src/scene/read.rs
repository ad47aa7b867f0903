//! The TOML reader: one way to build a [`Scene`] (the builder is another).
//!
//! It checks only what belongs to the text: TOML syntax, the keys each table takes, value
//! types, names from a fixed list, units and their dimensions. It records the byte span of
//! every value it reads under its dotted key ([`Source`]), so that validation and the
//! planner, which know nothing of TOML, can still point at the line and column of the value
//! they refuse.

use crate::scene::{ApproachPath, NormalSweep};
use std::cell::RefCell;
use std::collections::BTreeMap;
use std::ops::Range;
use std::path::PathBuf;
use std::sync::Arc;

use toml::Spanned;

use super::{
    Cycle, Ellipse, FieldGrid, FieldScale, Geometry, Indenter, Load, Method, NormalLoad, Outputs,
    Patch, PatchShape, Scene, SolverOptions, Source, Substrate,
};
use crate::error::{ErrorKind, SceneError};
use crate::raw::{Qty, RawNormal, RawScene, SQty};
use crate::units::{parse_quantity, Dim};

mod history;
mod material;
mod motion;
pub(crate) mod schema;
mod surface;
mod wheel_rail;

struct Reader<'a> {
    src: &'a str,
    file: Option<PathBuf>,
    spans: RefCell<BTreeMap<String, Range<usize>>>,
    /// The named materials used, by table ("substrate", "indenter").
    materials: RefCell<Vec<(String, crate::materials::Material)>>,
}

impl Reader<'_> {
    fn err(
        &self,
        kind: ErrorKind,
        key: &str,
        span: Option<Range<usize>>,
        msg: impl Into<String>,
    ) -> SceneError {
        SceneError::new(kind, msg).key(key).at(self.src, span).in_file(self.file.clone())
    }

    fn record(&self, key: &str, span: Range<usize>) {
        self.spans.borrow_mut().insert(key.to_string(), span);
    }

    /// A number (SI) or a string with a unit, in SI. Ranges are validation's business.
    fn qty(&self, q: &SQty, key: &str, dim: Dim, name: &'static str) -> Result<f64, SceneError> {
        self.record(key, q.span());
        match q.get_ref() {
            Qty::Num(v) => Ok(*v),
            Qty::Text(t) => parse_quantity(t, dim, name).map_err(|e| {
                let hint = e.suggestion().unwrap_or_else(|| {
                    format!("write a number in SI ({dim}) or a string like \"10 mm\", \"30e6 psi\"")
                });
                self.err(ErrorKind::Unit, key, Some(q.span()), e.to_string()).hint(hint)
            }),
        }
    }

    fn num(&self, v: &Spanned<f64>, key: &str) -> f64 {
        self.record(key, v.span());
        *v.get_ref()
    }

    fn required<'b, T>(
        &self,
        v: &'b Option<T>,
        key: &str,
        table_span: Range<usize>,
        what: &str,
    ) -> Result<&'b T, SceneError> {
        v.as_ref().ok_or_else(|| {
            self.err(ErrorKind::Schema, key, Some(table_span), format!("missing key `{key}`"))
                .hint(what.to_string())
        })
    }

    fn choice<'s>(
        &self,
        s: &'s Spanned<String>,
        key: &str,
        allowed: &[&str],
    ) -> Result<&'s str, SceneError> {
        self.record(key, s.span());
        let v = s.get_ref().as_str();
        if allowed.contains(&v) {
            Ok(v)
        } else {
            Err(self
                .err(ErrorKind::Schema, key, Some(s.span()), format!("unknown value \"{v}\""))
                .hint(format!("one of: {}", allowed.join(", "))))
        }
    }

    /// Exactly two quantities, e.g. `[\"2 mm\", \"1 mm\"]`.
    fn pair(
        &self,
        v: &Spanned<Vec<SQty>>,
        key: &str,
        dim: Dim,
        name: &'static str,
        hint: &str,
    ) -> Result<[f64; 2], SceneError> {
        self.record(key, v.span());
        if v.get_ref().len() != 2 {
            return Err(self
                .err(
                    ErrorKind::Schema,
                    key,
                    Some(v.span()),
                    format!("expected 2 values, got {}", v.get_ref().len()),
                )
                .hint(hint.to_string()));
        }
        let a = self.qty(&v.get_ref()[0], key, dim, name)?;
        let b = self.qty(&v.get_ref()[1], key, dim, name)?;
        self.record(key, v.span());
        Ok([a, b])
    }
}

/// Read `src` (the text of `file`, if any) into a [`Scene`], not yet validated.
pub(crate) fn read(src: &str, file: Option<PathBuf>) -> Result<Scene, SceneError> {
    let cx = Reader {
        src,
        file,
        spans: RefCell::new(BTreeMap::new()),
        materials: RefCell::new(Vec::new()),
    };
    // serde's messages name Rust types, not keys: `schema::explain` says it in plain words.
    let raw: RawScene =
        toml::from_str(src).map_err(|e| schema::explain(src, &e).in_file(cx.file.clone()))?;
    let geometry = geometry(&cx, &raw)?;
    let substrate = substrate(&cx, &raw)?;
    let indenter = indenter(&cx, &raw)?;
    let load = load(&cx, &raw, &geometry)?;
    let wheel = matches!(geometry, Geometry::WheelRail(_));
    if let (false, Some(p)) = (wheel, &raw.position) {
        return Err(cx
            .err(ErrorKind::Schema, "position", Some(p.span()), "`[position]` is given but the geometry is not a wheel on a rail")
            .hint("[position] (lateral, yaw, roll) places a wheelset: use it with geometry.kind = \"wheel-rail\", or remove it"));
    }
    let motion = motion::motion(&cx, &raw, wheel)?;
    let outputs = outputs(&cx, raw.outputs.as_ref())?;
    let solver = solver(&cx, raw.solver.as_ref())?;
    let interface = match &raw.interface {
        Some(i) => super::Interface {
            hardness: match &i.hardness {
                Some(h) => Some(cx.qty(h, "interface.hardness", Dim::STRESS, "hardness")?),
                None => None,
            },
            adhesion: match &i.adhesion {
                Some(a) => Some(adhesion(&cx, a)?),
                None => None,
            },
        },
        None => super::Interface::default(),
    };
    cx.record("geometry", raw.geometry.span());
    cx.record("substrate", raw.substrate.span());
    cx.record("load", raw.load.span());
    if let Some(i) = &raw.indenter {
        cx.record("indenter", i.span());
    }
    if let Some(m) = &raw.motion {
        cx.record("motion", m.span());
    }
    Ok(Scene {
        title: raw.title.clone().unwrap_or_else(|| "untitled scene".to_string()),
        file: cx.file.clone(),
        geometry,
        substrate,
        indenter,
        load,
        motion,
        outputs,
        solver,
        interface,
        source: Some(Arc::new(Source {
            text: Arc::from(src),
            spans: cx.spans.into_inner(),
            materials: cx.materials.into_inner(),
        })),
    })
}

fn geometry(cx: &Reader<'_>, raw: &RawScene) -> Result<Geometry, SceneError> {
    let g = raw.geometry.get_ref();
    let gspan = raw.geometry.span();
    let kind = cx.choice(
        &g.kind,
        "geometry.kind",
        &["cylinder", "sphere", "ellipsoid", "punch", "patches", "surface", "wheel-rail"],
    )?;
    Ok(match kind {
        "cylinder" | "sphere" => {
            let r = cx.required(
                &g.radius,
                "geometry.radius",
                gspan,
                "the radius R, e.g. radius = \"0.3 m\"",
            )?;
            let radius = cx.qty(r, "geometry.radius", Dim::LENGTH, "radius")?;
            if kind == "cylinder" {
                Geometry::Cylinder { radius }
            } else {
                Geometry::Sphere { radius }
            }
        }
        "punch" => {
            let h =
                cx.required(&g.half_width, "geometry.half_width", gspan, "the punch half-width")?;
            Geometry::Punch {
                half_width: cx.qty(h, "geometry.half_width", Dim::LENGTH, "half-width")?,
            }
        }
        "ellipsoid" => {
            let hint = "two lengths, e.g. [\"2 mm\", \"1 mm\"]";
            match (&g.semi_axes, &g.radii) {
                (Some(s), None) => {
                    let [a, b] = cx.pair(s, "geometry.semi_axes", Dim::LENGTH, "length", hint)?;
                    Geometry::Ellipsoid(Ellipse::SemiAxes { a, b })
                }
                (None, Some(r)) => {
                    let [rx, ry] = cx.pair(r, "geometry.radii", Dim::LENGTH, "length", hint)?;
                    Geometry::Ellipsoid(Ellipse::Radii { rx, ry })
                }
                _ => {
                    return Err(cx
                        .err(ErrorKind::Schema, "geometry", Some(gspan), "an ellipsoid needs exactly one of `semi_axes` and `radii`")
                        .hint("semi_axes = [a, b] for the contact, or radii = [Rx, Ry] for the bodies' relative radii"))
                }
            }
        }
        "surface" => Geometry::Surface(surface::surface(cx, g, gspan)?),
        "wheel-rail" => Geometry::WheelRail(wheel_rail::wheel_rail(cx, g, gspan, raw)?),
        _ => {
            let list = cx.required(&g.patches, "geometry.patches", gspan, "a list of patches")?;
            cx.record("geometry.patches", list.span());
            let mut patches: Vec<Patch> = Vec::new();
            for (i, p) in list.get_ref().iter().enumerate() {
                let key = format!("geometry.patches[{i}]");
                cx.record(&key, p.span());
                let pr = p.get_ref();
                let shape_name = cx.choice(
                    &pr.shape,
                    &format!("{key}.shape"),
                    &["square", "rectangle", "circle"],
                )?;
                let shape = match shape_name {
                    "square" => {
                        let k = format!("{key}.side");
                        let s = cx.required(&pr.side, &k, p.span(), "the square's side")?;
                        PatchShape::Square { side: cx.qty(s, &k, Dim::LENGTH, "side")? }
                    }
                    "rectangle" => {
                        let k = format!("{key}.sides");
                        let s =
                            cx.required(&pr.sides, &k, p.span(), "sides = [along x, along y]")?;
                        PatchShape::Rectangle {
                            sides: cx.pair(
                                s,
                                &k,
                                Dim::LENGTH,
                                "side",
                                "sides = [along x, along y]",
                            )?,
                        }
                    }
                    _ => {
                        let k = format!("{key}.radius");
                        let r = cx.required(&pr.radius, &k, p.span(), "the circle's radius")?;
                        PatchShape::Circle { radius: cx.qty(r, &k, Dim::LENGTH, "radius")? }
                    }
                };
                let ck = format!("{key}.centre");
                let centre =
                    cx.pair(&pr.centre, &ck, Dim::LENGTH, "length", "[x, y], two lengths")?;
                let pressure =
                    cx.qty(&pr.pressure, &format!("{key}.pressure"), Dim::STRESS, "pressure")?;
                patches.push(Patch { shape, centre, pressure });
            }
            Geometry::Patches(patches)
        }
    })
}

fn substrate(cx: &Reader<'_>, raw: &RawScene) -> Result<Substrate, SceneError> {
    let s = raw.substrate.get_ref();
    let sspan = raw.substrate.span();
    // Keys that belong to one model only: given with another model they would be ignored
    // silently, so they are refused; given without `model`, they name the model to write.
    let graded_keys: [(&str, Option<Range<usize>>); 2] =
        [("e0", s.e0.as_ref().map(|q| q.span())), ("k", s.k.as_ref().map(|k| k.span()))];
    let visco_keys: [(&str, Option<Range<usize>>); 2] = [
        ("alpha", s.alpha.as_ref().map(|q| q.span())),
        ("beta", s.beta.as_ref().map(|q| q.span())),
    ];
    let model = match &s.model {
        Some(m) => cx.choice(m, "substrate.model", &["homogeneous", "graded", "viscoelastic"])?,
        // The one sensible value when the keys are those of an elastic body.
        None => {
            for (keys, model) in [(&graded_keys, "graded"), (&visco_keys, "viscoelastic")] {
                if let Some((key, Some(span))) = keys.iter().find(|(_, sp)| sp.is_some()) {
                    return Err(cx
                        .err(
                            ErrorKind::Schema,
                            "substrate.model",
                            Some(span.clone()),
                            format!(
                                "missing key `model` in [substrate]: `{key}` belongs to a {model} substrate"
                            ),
                        )
                        .hint(format!(
                            "add model = \"{model}\" (without `model` the substrate is homogeneous: material, or e and nu)"
                        )));
                }
            }
            "homogeneous"
        }
    };
    let foreign = |keys: &[(&str, Option<Range<usize>>)]| -> Result<(), SceneError> {
        match keys.iter().find(|(_, sp)| sp.is_some()) {
            Some((key, Some(span))) => Err(cx
                .err(
                    ErrorKind::Schema,
                    &format!("substrate.{key}"),
                    Some(span.clone()),
                    format!("`{key}` is not a key of a {model} substrate"),
                )
                .hint(match *key {
                    "e0" | "k" => format!("remove `{key}`, or write model = \"graded\""),
                    _ => format!("remove `{key}`, or write model = \"viscoelastic\""),
                })),
            _ => Ok(()),
        }
    };
    match model {
        "homogeneous" => {
            foreign(&graded_keys)?;
            foreign(&visco_keys)?;
        }
        "graded" => foreign(&visco_keys)?,
        _ => foreign(&graded_keys)?,
    }
    let keys = |e_what| material::Keys {
        table: "substrate",
        span: sspan.clone(),
        material: s.material.as_ref(),
        e: s.e.as_ref(),
        nu: s.nu.as_ref(),
        e_what,
    };
    Ok(match model {
        "homogeneous" => Substrate::Homogeneous(material::elastic(
            cx,
            &keys(
                "Young's modulus, e.g. e = \"210 GPa\" (or material = \"steel\" for both e and nu)",
            ),
        )?),
        "graded" => {
            material::refuse(
                cx,
                "substrate",
                s.material.as_ref(),
                "a graded substrate takes e0, k and nu, not a named material",
                "remove `material` and give e0, k and nu",
            )?;
            let nu = cx.required(
                &s.nu,
                "substrate.nu",
                sspan.clone(),
                "Poisson's ratio, e.g. nu = 0.3",
            )?;
            let nu = cx.num(nu, "substrate.nu");
            let k = cx.required(
                &s.k,
                "substrate.k",
                sspan.clone(),
                "the grading exponent k in E = e0 y^k, 0 <= k < 1",
            )?;
            let kv = cx.num(k, "substrate.k");
            let e0 = cx.required(
                &s.e0,
                "substrate.e0",
                sspan,
                "E0 of E = e0 y^k, e.g. e0 = \"1767600 kgf/m^2.1\"",
            )?;
            // The unit of e0 depends on k. With k outside [0, 1) e0 cannot be read; it is
            // left NaN and validation refuses k, which it checks first.
            let e0 = if kv.is_finite() && (0.0..1.0).contains(&kv) {
                cx.qty(
                    e0,
                    "substrate.e0",
                    Dim::graded_modulus(kv),
                    "graded modulus (force/length^(2+k))",
                )?
            } else {
                f64::NAN
            };
            Substrate::Graded { e0, k: kv, nu }
        }
        _ => {
            let elastic = material::elastic(
                cx,
                &keys("the long-time modulus E (or material = \"rubber\" for both e and nu)"),
            )?;
            let a = cx.required(
                &s.alpha,
                "substrate.alpha",
                sspan.clone(),
                "the retardation time alpha (s)",
            )?;
            let b = cx.required(
                &s.beta,
                "substrate.beta",
                sspan.clone(),
                "the relaxation time beta (s)",
            )?;
            let alpha = cx.qty(a, "substrate.alpha", Dim::TIME, "time")?;
            let beta = cx.qty(b, "substrate.beta", Dim::TIME, "time")?;
            Substrate::Viscoelastic { elastic, alpha, beta }
        }
    })
}

fn indenter(cx: &Reader<'_>, raw: &RawScene) -> Result<Indenter, SceneError> {
    let Some(ind) = &raw.indenter else { return Ok(Indenter::Rigid) };
    let i = ind.get_ref();
    let model = match &i.model {
        Some(m) => cx.choice(m, "indenter.model", &["rigid", "homogeneous", "same"])?,
        // Elastic constants say the indenter is elastic; an [indenter] table without them
        // is the rigid indenter, as no table is.
        None if i.material.is_some() || i.e.is_some() || i.nu.is_some() => "homogeneous",
        None => "rigid",
    };
    if model != "homogeneous" {
        material::refuse(
            cx,
            "indenter",
            i.material.as_ref(),
            &format!("a {model} indenter takes no material"),
            "model = \"homogeneous\" with material = \"...\", or remove `material`",
        )?;
        let e = i.e.as_ref().map(|q| ("e", q.span()));
        if let Some((key, span)) = e.or(i.nu.as_ref().map(|n| ("nu", n.span()))) {
            return Err(cx
                .err(
                    ErrorKind::Schema,
                    &format!("indenter.{key}"),
                    Some(span),
                    format!("a {model} indenter takes no `{key}`"),
                )
                .hint("model = \"homogeneous\" (or leave `model` out) for an elastic indenter, or remove `e` and `nu`"));
        }
    }
    Ok(match model {
        "rigid" => Indenter::Rigid,
        "same" => Indenter::Same,
        _ => Indenter::Homogeneous(material::elastic(
            cx,
            &material::Keys {
                table: "indenter",
                span: ind.span(),
                material: i.material.as_ref(),
                e: i.e.as_ref(),
                nu: i.nu.as_ref(),
                e_what:
                    "Young's modulus of the indenter (or material = \"steel\" for both e and nu)",
            },
        )?),
    })
}

/// `interface.adhesion = { work, range }`: both keys, with their units.
fn adhesion(
    cx: &Reader<'_>,
    a: &toml::Spanned<crate::raw::RawAdhesion>,
) -> Result<super::AdhesionKeys, SceneError> {
    cx.record("interface.adhesion", a.span());
    let r = a.get_ref();
    let missing = |key: &'static str, what: &str| {
        cx.err(
            ErrorKind::Schema,
            key,
            Some(a.span()),
            format!("interface.adhesion needs `{}`", key.rsplit('.').next().unwrap_or(key)),
        )
        .hint(format!("adhesion = {{ work = \"50 mJ/m^2\", range = \"10 nm\" }}: {what}"))
    };
    let work = match &r.work {
        Some(w) => {
            cx.qty(w, "interface.adhesion.work", Dim::FORCE_PER_LENGTH, "work of adhesion")?
        }
        None => {
            return Err(missing(
                "interface.adhesion.work",
                "the work of adhesion, energy per area (J/m^2, mJ/m^2)",
            ))
        }
    };
    let range = match &r.range {
        Some(h) => cx.qty(h, "interface.adhesion.range", Dim::LENGTH, "range of adhesion")?,
        None => {
            return Err(missing(
                "interface.adhesion.range",
                "the range of the attraction, a length",
            ))
        }
    };
    Ok(super::AdhesionKeys { work, range })
}

fn load(cx: &Reader<'_>, raw: &RawScene, geometry: &Geometry) -> Result<Load, SceneError> {
    let (force_dim, force_name) = if geometry.is_2d() {
        (Dim::FORCE_PER_LENGTH, "load per unit length")
    } else {
        (Dim::FORCE, "force")
    };
    let l = raw.load.get_ref();
    let lspan = raw.load.span();
    if let (Some(v), false) = (&l.vertical, matches!(geometry, Geometry::WheelRail(_))) {
        return Err(cx
            .err(
                ErrorKind::Schema,
                "load.vertical",
                Some(v.span()),
                "load.vertical says what carries the vertical wheel load of a wheel on its rail; this geometry is not one",
            )
            .hint("remove load.vertical, or set geometry.kind = \"wheel-rail\""));
    }
    if let Some(d) = &l.approach {
        if l.normal.is_some() || l.half_width.is_some() {
            return Err(cx
                .err(
                    ErrorKind::Schema,
                    "load.approach",
                    Some(d.span()),
                    "give exactly one of `normal`, `half_width` and `approach`",
                )
                .hint("normal = P for force control, or approach = d for displacement control"));
        }
        let (last, path) = match d.get_ref() {
            RawNormal::One(q) => (
                cx.qty(&SQty::new(d.span(), q.clone()), "load.approach", Dim::LENGTH, "approach")?,
                None,
            ),
            RawNormal::Sweep(v) => {
                let path = approach_path(cx, v, d.span())?;
                (*path.corners.last().unwrap_or(&0.0), Some(path))
            }
        };
        let mut load = finish_load(cx, l, NormalLoad::Approach(last), force_dim, force_name)?;
        load.approach_path = path;
        return Ok(load);
    }
    // A load sweep `[from, to, steps]`: the scene's load is the last step.
    let mut sweep = None;
    let one: Option<SQty> = match &l.normal {
        None => None,
        Some(n) => match n.get_ref() {
            RawNormal::One(q) => Some(SQty::new(n.span(), q.clone())),
            RawNormal::Sweep(v) => {
                let bad = || {
                    cx.err(ErrorKind::Schema, "load.normal", Some(n.span()), "a load sweep is `[from, to, steps]`")
                        .hint("e.g. normal = [\"1 N\", \"100 N\", 20]: from and to are forces, steps an integer >= 2 (spaced geometrically)")
                };
                let [from, to, steps] = v.as_slice() else { return Err(bad()) };
                let Qty::Num(count) = steps else { return Err(bad()) };
                let count = *count;
                if count.fract() != 0.0 || !(2.0..=1000.0).contains(&count) {
                    return Err(cx
                        .err(
                            ErrorKind::OutOfRange,
                            "load.normal",
                            Some(n.span()),
                            format!("{count} load steps"),
                        )
                        .hint("an integer from 2 to 1000"));
                }
                let from = SQty::new(n.span(), from.clone());
                let f0 = cx.qty(&from, "load.normal", force_dim, force_name)?;
                sweep = Some(NormalSweep { from: f0, steps: count as usize });
                Some(SQty::new(n.span(), to.clone()))
            }
        },
    };
    let normal = match (geometry, &one, &l.half_width) {
        (Geometry::Patches(p), None, None) => {
            NormalLoad::FromPatches(p.iter().map(Patch::force).sum())
        }
        (Geometry::Patches(_), _, _) => {
            return Err(cx
                .err(
                    ErrorKind::Schema,
                    "load.normal",
                    Some(lspan),
                    "patches carry their own pressures; do not give load.normal or load.half_width",
                )
                .hint("remove load.normal / load.half_width"))
        }
        (_, Some(p), None) => NormalLoad::Force(cx.qty(p, "load.normal", force_dim, force_name)?),
        (_, None, Some(a)) => {
            NormalLoad::HalfWidth(cx.qty(a, "load.half_width", Dim::LENGTH, "half-width")?)
        }
        _ => return Err(cx
            .err(
                ErrorKind::Schema,
                "load",
                Some(lspan),
                "give exactly one of `normal` and `half_width`",
            )
            .hint(
                "normal = P (N/m in 2D, N in 3D), or half_width = a to prescribe the contact size",
            )),
    };
    let mut load = finish_load(cx, l, normal, force_dim, force_name)?;
    load.normal_sweep = sweep;
    Ok(load)
}

fn finish_load(
    cx: &Reader<'_>,
    l: &crate::raw::RawLoad,
    normal: NormalLoad,
    force_dim: Dim,
    force_name: &'static str,
) -> Result<Load, SceneError> {
    let tangential = match &l.tangential {
        Some(t) => cx.qty(t, "load.tangential", force_dim, force_name)?,
        None => 0.0,
    };
    let direction_deg = l.direction_deg.as_ref().map_or(0.0, |d| cx.num(d, "load.direction_deg"));
    let friction = l.friction.as_ref().map_or(0.0, |f| cx.num(f, "load.friction"));
    let moment = match &l.moment {
        Some(m) => cx.qty(m, "load.moment", Dim::MOMENT, "moment")?,
        None => 0.0,
    };
    let history = match &l.history {
        Some(h) => Some(history::history(cx, h, force_dim, force_name)?),
        None => None,
    };
    Ok(Load {
        normal,
        tangential,
        direction_deg,
        friction,
        sliding: l.sliding.unwrap_or(false),
        moment,
        normal_sweep: None,
        approach_path: None,
        history,
    })
}

/// `load.approach = [from, to, ..., steps]`: two or more corners (lengths, any sign) and the
/// number of points per leg.
fn approach_path(
    cx: &Reader<'_>,
    v: &[Qty],
    span: std::ops::Range<usize>,
) -> Result<ApproachPath, SceneError> {
    let bad = || {
        cx.err(ErrorKind::Schema, "load.approach", Some(span.clone()), "an approach path is `[from, to, steps]`")
            .hint("e.g. approach = [\"-20 nm\", \"100 nm\", 41]: from and to are lengths (any sign), steps an integer >= 2 (equal steps); more corners before steps turn the path, e.g. [\"-20 nm\", \"100 nm\", \"-20 nm\", 41]")
    };
    let Some((Qty::Num(count), corners)) = v.split_last() else { return Err(bad()) };
    if corners.len() < 2 {
        return Err(bad());
    }
    let count = *count;
    if count.fract() != 0.0 || !(2.0..=ApproachPath::MAX_STEPS as f64).contains(&count) {
        return Err(cx
            .err(ErrorKind::OutOfRange, "load.approach", Some(span), format!("{count} steps"))
            .hint(format!(
                "an integer from 2 to {} (points per leg, both corners included)",
                ApproachPath::MAX_STEPS
            )));
    }
    let points = 1 + (corners.len() - 1) * (count as usize - 1);
    if points > ApproachPath::MAX_POINTS {
        return Err(cx
            .err(
                ErrorKind::OutOfRange,
                "load.approach",
                Some(span),
                format!("{} legs of {count} points: {points} points in all", corners.len() - 1),
            )
            .hint(format!(
                "at most {} points in all: fewer steps or fewer corners",
                ApproachPath::MAX_POINTS
            )));
    }
    let mut c = Vec::with_capacity(corners.len());
    for q in corners {
        c.push(cx.qty(
            &SQty::new(span.clone(), q.clone()),
            "load.approach",
            Dim::LENGTH,
            "approach",
        )?);
    }
    Ok(ApproachPath { corners: c, steps: count as usize })
}

fn outputs(cx: &Reader<'_>, o: Option<&crate::raw::RawOutputs>) -> Result<Outputs, SceneError> {
    let Some(o) = o else {
        return Ok(Outputs { surface: true, field: None, cycle: None, plots: true });
    };
    // from and to: numbers in the scale's unit, or (scale = "m") lengths with units
    let axis = |v: &Spanned<Vec<crate::raw::SQty>>,
                key: &str,
                metres: bool|
     -> Result<(f64, f64, usize), SceneError> {
        cx.record(key, v.span());
        let a = v.get_ref();
        let bad = |m: String| {
            cx.err(ErrorKind::OutOfRange, key, Some(v.span()), m)
                .hint("[from, to, count] with from < to and 2 <= count <= 10000 (depth from > 0)")
        };
        if a.len() != 3 {
            return Err(bad(format!("expected [from, to, count], got {} values", a.len())));
        }
        let end = |q: &crate::raw::SQty| -> Result<f64, SceneError> {
            match q.get_ref() {
                Qty::Num(v) => Ok(*v),
                Qty::Text(t) if !metres => Err(cx
                    .err(
                        ErrorKind::Unit,
                        key,
                        Some(q.span()),
                        format!(
                            "expected a number, found the string \"{t}\" (scale = \"a\" measures in contact semi-axes)"
                        ),
                    )
                    .hint("write plain numbers (multiples of a), or set scale = \"m\" to give lengths like \"1.5 mm\"")),
                Qty::Text(_) => cx.qty(q, key, Dim::LENGTH, "length"),
            }
        };
        let (from, to) = (end(&a[0])?, end(&a[1])?);
        cx.record(key, v.span());
        let n = match a[2].get_ref() {
            Qty::Num(n) => *n,
            Qty::Text(t) => return Err(bad(format!("count \"{t}\" is not a number"))),
        };
        // An integer count; its range is validation's.
        if !(n.fract() == 0.0 && n >= 0.0 && n <= usize::MAX as f64) {
            return Err(bad(format!("count {n} is not an integer in 2..=10000")));
        }
        Ok((from, to, n as usize))
    };
    let field = match &o.field {
        None => None,
        Some(f) => {
            cx.record("outputs.field", f.span());
            let fr = f.get_ref();
            let scale = match &fr.scale {
                None => FieldScale::HalfWidth,
                Some(s) => match cx.choice(s, "outputs.field.scale", &["a", "m"])? {
                    "a" => FieldScale::HalfWidth,
                    _ => FieldScale::Metres,
                },
            };
            let metres = scale == FieldScale::Metres;
            let z = match &fr.z {
                Some(z) => Some(axis(z, "outputs.field.z", metres)?),
                None => None,
            };
            Some(FieldGrid {
                x: axis(&fr.x, "outputs.field.x", metres)?,
                y: axis(&fr.y, "outputs.field.y", metres)?,
                z,
                scale,
            })
        }
    };
    let cycle = match &o.cycle {
        None => None,
        Some(c) => {
            cx.record("outputs.cycle", c.span());
            let cr = c.get_ref();
            let amplitude = cx.num(&cr.amplitude, "outputs.cycle.amplitude");
            let points = match &cr.points {
                None => 60,
                Some(p) => {
                    cx.record("outputs.cycle.points", p.span());
                    let v = *p.get_ref();
                    if v < 0 {
                        return Err(cx
                            .err(
                                ErrorKind::OutOfRange,
                                "outputs.cycle.points",
                                Some(p.span()),
                                format!("{v} points"),
                            )
                            .hint("4 <= points <= 100000"));
                    }
                    usize::try_from(v).unwrap_or(usize::MAX)
                }
            };
            Some(Cycle { amplitude, points })
        }
    };
    Ok(Outputs { surface: o.surface.unwrap_or(true), field, cycle, plots: o.plots.unwrap_or(true) })
}

fn solver(cx: &Reader<'_>, s: Option<&crate::raw::RawSolver>) -> Result<SolverOptions, SceneError> {
    let mut out = SolverOptions::default();
    let Some(s) = s else { return Ok(out) };
    if let Some(m) = &s.method {
        out.method = match cx.choice(
            m,
            "solver.method",
            &["auto", "closed-form", "quadrature", "lp", "fast", "fastsim", "polach"],
        )? {
            "auto" => Method::Auto,
            "closed-form" => Method::ClosedForm,
            "quadrature" => Method::Quadrature,
            "lp" => Method::Lp,
            "fastsim" => Method::Fastsim,
            "polach" => Method::Polach,
            _ => Method::Fast,
        };
    }
    if let Some(g) = &s.grid {
        cx.record("solver.grid", g.span());
        let v = *g.get_ref();
        if v < 0 {
            return Err(cx
                .err(ErrorKind::OutOfRange, "solver.grid", Some(g.span()), format!("grid = {v} elements per side is not allowed"))
                .hint(format!("4 <= grid <= {}; grids whose working memory would exceed 16 GiB are refused by the planner (about 5100 per side for the fast solver)", super::MAX_GRID)));
        }
        out.grid = usize::try_from(v).unwrap_or(usize::MAX);
    }
    if let Some(t) = &s.tolerance {
        out.tolerance = cx.num(t, "solver.tolerance");
    }
    if let Some(c) = &s.cell {
        out.cell = Some(cx.pair(
            c,
            "solver.cell",
            Dim::LENGTH,
            "length",
            "cell = [along x, across the patch], e.g. [\"0.2 mm\", \"0.2 mm\"]",
        )?);
    }
    Ok(out)
}
