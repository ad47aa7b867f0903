//! The validated scene: every quantity in SI, every value inside what the physics allows.

// Scene errors are built on the cold path of parsing and carry the file, position, key and
// hint for the user; boxing them would buy nothing measurable.
#![allow(clippy::result_large_err)]

use std::ops::Range;
use std::path::{Path, PathBuf};

use toml::Spanned;

use crate::error::{ErrorKind, SceneError};
use crate::raw::{Qty, RawScene, SQty};
use crate::units::{parse_quantity, Dim};

/// Contact geometry: what touches what.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Geometry {
    /// A cylinder of radius R on a half-plane (2D, plane strain; loads per unit length).
    Cylinder {
        /// Radius R (m).
        radius: f64,
    },
    /// A sphere of radius R on a half-space.
    Sphere {
        /// Radius R (m).
        radius: f64,
    },
    /// An elliptical Hertz contact.
    Ellipsoid(Ellipse),
    /// A flat rigid punch of half-width a (2D).
    Punch {
        /// Half-width (m).
        half_width: f64,
    },
    /// Flat patches with given uniform pressures (3D), e.g. a bolted joint's contact areas.
    Patches(Vec<Patch>),
}

impl Geometry {
    /// True for plane-strain (per unit length) problems.
    pub fn is_2d(&self) -> bool {
        matches!(self, Geometry::Cylinder { .. } | Geometry::Punch { .. })
    }
}

/// How an elliptical contact is given.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Ellipse {
    /// The contact semi-axes a (along x) and b (along y), m.
    SemiAxes {
        /// Semi-axis along x (m).
        a: f64,
        /// Semi-axis along y (m).
        b: f64,
    },
    /// The principal relative radii of curvature (m); the semi-axes follow from Hertz.
    Radii {
        /// Radius in the x-z plane (m).
        rx: f64,
        /// Radius in the y-z plane (m).
        ry: f64,
    },
}

/// A flat contact patch with uniform pressure.
#[derive(Debug, Clone, PartialEq)]
pub struct Patch {
    /// Its outline.
    pub shape: PatchShape,
    /// Centre (m).
    pub centre: [f64; 2],
    /// Uniform pressure (Pa), > 0.
    pub pressure: f64,
}

/// Outline of a patch, centred on its `centre`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum PatchShape {
    /// Axis-aligned square of this side (m).
    Square {
        /// Side (m).
        side: f64,
    },
    /// Axis-aligned rectangle with sides along x and y (m).
    Rectangle {
        /// Sides along x and y (m).
        sides: [f64; 2],
    },
    /// Circle of this radius (m).
    Circle {
        /// Radius (m).
        radius: f64,
    },
}

impl PatchShape {
    /// Area (m^2).
    pub fn area(&self) -> f64 {
        match *self {
            PatchShape::Square { side } => side * side,
            PatchShape::Rectangle { sides } => sides[0] * sides[1],
            PatchShape::Circle { radius } => std::f64::consts::PI * radius * radius,
        }
    }
}

impl Patch {
    /// Normal force carried by the patch (N).
    pub fn force(&self) -> f64 {
        self.pressure * self.shape.area()
    }

    /// True when the two outlines share a region of positive area (touching edges do not
    /// count: a split contact can have patches that abut).
    pub fn overlaps(&self, other: &Patch) -> bool {
        use PatchShape::*;
        let half = |s: &PatchShape| match *s {
            Square { side } => [side / 2.0; 2],
            Rectangle { sides } => [sides[0] / 2.0, sides[1] / 2.0],
            Circle { radius } => [radius; 2],
        };
        let d = [other.centre[0] - self.centre[0], other.centre[1] - self.centre[1]];
        match (self.shape, other.shape) {
            (Circle { radius: r1 }, Circle { radius: r2 }) => d[0].hypot(d[1]) < r1 + r2,
            (Circle { radius }, rect) | (rect, Circle { radius }) => {
                let (c_circle, c_rect) = if matches!(self.shape, Circle { .. }) {
                    (self.centre, other.centre)
                } else {
                    (other.centre, self.centre)
                };
                let h = half(&rect);
                let dx = (c_circle[0] - c_rect[0]).abs() - h[0];
                let dy = (c_circle[1] - c_rect[1]).abs() - h[1];
                let gap = dx.max(0.0).hypot(dy.max(0.0));
                // inside the rectangle (both negative) or closer than the radius
                (dx < 0.0 && dy < 0.0) || gap < radius
            }
            (a, b) => {
                let (ha, hb) = (half(&a), half(&b));
                d[0].abs() < ha[0] + hb[0] && d[1].abs() < ha[1] + hb[1]
            }
        }
    }
}

/// Bounding box of the patches: (lower-left, upper-right).
pub(crate) fn patch_bounds(ps: &[Patch]) -> ([f64; 2], [f64; 2]) {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in ps {
        let h = match p.shape {
            PatchShape::Square { side } => [side / 2.0; 2],
            PatchShape::Rectangle { sides } => [sides[0] / 2.0, sides[1] / 2.0],
            PatchShape::Circle { radius } => [radius; 2],
        };
        for d in 0..2 {
            lo[d] = lo[d].min(p.centre[d] - h[d]);
            hi[d] = hi[d].max(p.centre[d] + h[d]);
        }
    }
    (lo, hi)
}

/// An elastic material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Elastic {
    /// Young's modulus (Pa).
    pub e: f64,
    /// Poisson's ratio, in (-1, 0.5].
    pub nu: f64,
}

/// The body below.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Substrate {
    /// Homogeneous, linear elastic.
    Homogeneous(Elastic),
    /// Power-law graded, E = e0 y^k (Giannakopoulos & Pallot 2000).
    Graded {
        /// E0 in Pa / m^k.
        e0: f64,
        /// Grading exponent, 0 <= k < 1.
        k: f64,
        /// Poisson's ratio, below 1/(1+k).
        nu: f64,
    },
    /// Standard linear solid: eps + alpha eps' = (sigma + beta sigma') / E (Goryacheva 1973).
    Viscoelastic {
        /// Long-time modulus E (Pa) and Poisson's ratio.
        elastic: Elastic,
        /// Retardation time alpha (s).
        alpha: f64,
        /// Relaxation time beta (s), beta <= alpha.
        beta: f64,
    },
}

/// The body above.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Indenter {
    /// Rigid.
    Rigid,
    /// Homogeneous elastic.
    Homogeneous(Elastic),
    /// The same material as the substrate.
    Same,
}

/// How the normal load is prescribed.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum NormalLoad {
    /// The force P (N/m in 2D, N in 3D).
    Force(f64),
    /// The contact half-width a (m); the force follows.
    HalfWidth(f64),
    /// Given by the patches' pressures.
    FromPatches(f64),
}

/// Loads and friction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Load {
    /// Normal load.
    pub normal: NormalLoad,
    /// Tangential load T (N/m in 2D, N in 3D), along `direction_deg`.
    pub tangential: f64,
    /// Direction of T in degrees from +x.
    pub direction_deg: f64,
    /// Coulomb friction coefficient f >= 0.
    pub friction: f64,
    /// Full sliding: q = f p.
    pub sliding: bool,
    /// Twisting moment about the contact normal (N m, 3D).
    pub moment: f64,
}

/// Motion.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Motion {
    /// No motion beyond the applied loads.
    Static,
    /// Steady rolling.
    Rolling {
        /// Speed w (m/s), > 0.
        speed: f64,
        /// Creep delta = (omega R - w) / w.
        creep: f64,
    },
}

/// A subsurface grid, in units of `scale`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldGrid {
    /// x from, to, count.
    pub x: (f64, f64, usize),
    /// depth y from, to, count (y > 0).
    pub y: (f64, f64, usize),
    /// Unit of x and y.
    pub scale: FieldScale,
}

/// Unit of a field grid's coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum FieldScale {
    /// The contact half-width a.
    HalfWidth,
    /// Metres.
    Metres,
}

/// A Mindlin–Deresiewicz loading cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cycle {
    /// Amplitude T*/(fP), in (0, 1].
    pub amplitude: f64,
    /// Points along the loop.
    pub points: usize,
}

/// What to compute beyond the contact solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outputs {
    /// Surface arrays (p, q, displacements, zones).
    pub surface: bool,
    /// Subsurface stresses on a grid.
    pub field: Option<FieldGrid>,
    /// A loading cycle.
    pub cycle: Option<Cycle>,
    /// SVG plots beside the JSON.
    pub plots: bool,
}

/// Which method the user asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Method {
    /// Let the planner choose.
    Auto,
    /// Closed forms only.
    ClosedForm,
    /// Quadrature of the kernels.
    Quadrature,
    /// The modified LP (seed 002).
    Lp,
    /// The fast FFT solver.
    Fast,
}

/// Solver options.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverOptions {
    /// Requested method.
    pub method: Method,
    /// Elements per side for grid solvers.
    pub grid: usize,
    /// Requested relative tolerance.
    pub tolerance: f64,
}

/// A validated scene. Every quantity is SI.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// Title.
    pub title: String,
    /// Where it came from, for messages.
    pub file: Option<PathBuf>,
    /// Geometry.
    pub geometry: Geometry,
    /// The body below.
    pub substrate: Substrate,
    /// The body above.
    pub indenter: Indenter,
    /// Loads.
    pub load: Load,
    /// Motion.
    pub motion: Motion,
    /// Requested outputs.
    pub outputs: Outputs,
    /// Solver options.
    pub solver: SolverOptions,
}

/// The largest grid side the scene format accepts. Whether a grid fits is decided by the
/// planner's memory estimate ([`crate::plan::MEMORY_LIMIT_BYTES`]): a 3D lattice costs
/// about 650 bytes per cell with the fast solver (estimate), so grids of about 5100 per side
/// and more are refused there; this bound only keeps the arithmetic far from overflow.
pub const MAX_GRID: usize = 16384;

/// The built-in default scene: the rigid roller of seed 000, Table 1 (FORMULAS.md A4).
pub const DEFAULT_SCENE: &str = r#"title = "Rigid roller on a power-law graded substrate (seed 000, Table 1)"

[geometry]
kind = "cylinder"
radius = "0.3 m"

[substrate]
model = "graded"
e0 = "1767600 kgf/m^2.1"
k = 0.1
nu = 0.3

[indenter]
model = "rigid"

[load]
half_width = "0.0178 m"
friction = 1.0
sliding = true

[outputs]
surface = true
field = { x = [-1.5, 1.5, 61], y = [0.02, 2.0, 40], scale = "a" }
plots = true
"#;

struct Ctx<'a> {
    src: &'a str,
    file: Option<PathBuf>,
}

impl Ctx<'_> {
    fn err(
        &self,
        kind: ErrorKind,
        key: &str,
        span: Option<Range<usize>>,
        msg: impl Into<String>,
    ) -> SceneError {
        SceneError::new(kind, msg).key(key).at(self.src, span).in_file(self.file.clone())
    }

    fn qty(&self, q: &SQty, key: &str, dim: Dim, name: &'static str) -> Result<f64, SceneError> {
        let v = match q.get_ref() {
            Qty::Num(v) => *v,
            Qty::Text(t) => parse_quantity(t, dim, name).map_err(|e| {
                self.err(ErrorKind::Unit, key, Some(q.span()), e.to_string()).hint(format!(
                    "write a number in SI ({dim}) or a string like \"10 mm\", \"30e6 psi\""
                ))
            })?,
        };
        if !v.is_finite() {
            return Err(self.err(
                ErrorKind::OutOfRange,
                key,
                Some(q.span()),
                "must be a finite number",
            ));
        }
        Ok(v)
    }

    fn positive(
        &self,
        q: &SQty,
        key: &str,
        dim: Dim,
        name: &'static str,
    ) -> Result<f64, SceneError> {
        let v = self.qty(q, key, dim, name)?;
        if v > 0.0 {
            Ok(v)
        } else {
            Err(self
                .err(
                    ErrorKind::OutOfRange,
                    key,
                    Some(q.span()),
                    format!("{name} must be positive, got {v}"),
                )
                .hint(format!("give a {name} > 0")))
        }
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

    fn nu(&self, nu: &Spanned<f64>, key: &str) -> Result<f64, SceneError> {
        let v = *nu.get_ref();
        if v.is_finite() && v > -1.0 && v <= 0.5 {
            Ok(v)
        } else {
            Err(self
                .err(
                    ErrorKind::OutOfRange,
                    key,
                    Some(nu.span()),
                    format!("Poisson's ratio {v} is not allowed"),
                )
                .hint("an isotropic elastic solid has -1 < nu <= 0.5"))
        }
    }

    fn choice<'s>(
        &self,
        s: &'s Spanned<String>,
        key: &str,
        allowed: &[&str],
    ) -> Result<&'s str, SceneError> {
        let v = s.get_ref().as_str();
        if allowed.contains(&v) {
            Ok(v)
        } else {
            Err(self
                .err(ErrorKind::Schema, key, Some(s.span()), format!("unknown value \"{v}\""))
                .hint(format!("one of: {}", allowed.join(", "))))
        }
    }
}

impl Scene {
    /// The built-in default scene (seed 000's Table 1 roller).
    pub fn default_scene() -> Scene {
        // The constant is tested to parse; a failure here is a bug in this crate.
        Scene::from_toml_str(DEFAULT_SCENE, None).expect("the built-in default scene is valid")
    }

    /// Read and validate a scene file.
    pub fn from_file(path: &Path) -> Result<Scene, SceneError> {
        let text = std::fs::read_to_string(path).map_err(|e| {
            SceneError::new(ErrorKind::Io, format!("cannot read the scene file: {e}"))
                .in_file(Some(path.to_path_buf()))
                .hint("check the path; `stickslip run` without a file runs the built-in default scene")
        })?;
        Scene::from_toml_str(&text, Some(path.to_path_buf()))
    }

    /// Parse and validate a scene from TOML text. `file` is used in error messages only.
    pub fn from_toml_str(src: &str, file: Option<PathBuf>) -> Result<Scene, SceneError> {
        let cx = Ctx { src, file };
        let raw: RawScene = toml::from_str(src).map_err(|e| {
            let msg = e.message().trim().to_string();
            let kind = if msg.contains("unknown field")
                || msg.contains("missing field")
                || msg.contains("invalid type")
                || msg.contains("did not match any variant")
            {
                ErrorKind::Schema
            } else {
                ErrorKind::Syntax
            };
            let hint = if kind == ErrorKind::Schema {
                "see docs/SCENES.md for the keys each table takes; units go in strings, e.g. \"10 mm\""
            } else {
                "the file must be valid TOML (https://toml.io)"
            };
            SceneError::new(kind, msg).at(src, e.span()).in_file(cx.file.clone()).hint(hint)
        })?;
        convert(&cx, raw)
    }
}

fn convert(cx: &Ctx<'_>, raw: RawScene) -> Result<Scene, SceneError> {
    let g = raw.geometry.get_ref();
    let gspan = raw.geometry.span();
    let kind = cx.choice(
        &g.kind,
        "geometry.kind",
        &["cylinder", "sphere", "ellipsoid", "punch", "patches"],
    )?;
    let geometry = match kind {
        "cylinder" | "sphere" => {
            let r = cx.required(
                &g.radius,
                "geometry.radius",
                gspan.clone(),
                "the radius R, e.g. radius = \"0.3 m\"",
            )?;
            let radius = cx.positive(r, "geometry.radius", Dim::LENGTH, "radius")?;
            if kind == "cylinder" {
                Geometry::Cylinder { radius }
            } else {
                Geometry::Sphere { radius }
            }
        }
        "punch" => {
            let h = cx.required(
                &g.half_width,
                "geometry.half_width",
                gspan.clone(),
                "the punch half-width",
            )?;
            Geometry::Punch {
                half_width: cx.positive(h, "geometry.half_width", Dim::LENGTH, "half-width")?,
            }
        }
        "ellipsoid" => {
            let pair = |v: &Spanned<Vec<SQty>>, key: &str| -> Result<[f64; 2], SceneError> {
                if v.get_ref().len() != 2 {
                    return Err(cx
                        .err(
                            ErrorKind::Schema,
                            key,
                            Some(v.span()),
                            format!("expected 2 values, got {}", v.get_ref().len()),
                        )
                        .hint("two lengths, e.g. [\"2 mm\", \"1 mm\"]"));
                }
                Ok([
                    cx.positive(&v.get_ref()[0], key, Dim::LENGTH, "length")?,
                    cx.positive(&v.get_ref()[1], key, Dim::LENGTH, "length")?,
                ])
            };
            match (&g.semi_axes, &g.radii) {
                (Some(s), None) => {
                    let [a, b] = pair(s, "geometry.semi_axes")?;
                    Geometry::Ellipsoid(Ellipse::SemiAxes { a, b })
                }
                (None, Some(r)) => {
                    let [rx, ry] = pair(r, "geometry.radii")?;
                    Geometry::Ellipsoid(Ellipse::Radii { rx, ry })
                }
                _ => {
                    return Err(cx
                        .err(ErrorKind::Schema, "geometry", Some(gspan), "an ellipsoid needs exactly one of `semi_axes` and `radii`")
                        .hint("semi_axes = [a, b] for the contact, or radii = [Rx, Ry] for the bodies' relative radii"))
                }
            }
        }
        _ => {
            let list =
                cx.required(&g.patches, "geometry.patches", gspan.clone(), "a list of patches")?;
            if list.get_ref().is_empty() {
                return Err(cx
                    .err(
                        ErrorKind::OutOfRange,
                        "geometry.patches",
                        Some(list.span()),
                        "the patch list is empty",
                    )
                    .hint("give at least one patch"));
            }
            let mut patches: Vec<Patch> = Vec::new();
            for (i, p) in list.get_ref().iter().enumerate() {
                let key = format!("geometry.patches[{i}]");
                let pr = p.get_ref();
                let shape_name = cx.choice(
                    &pr.shape,
                    &format!("{key}.shape"),
                    &["square", "rectangle", "circle"],
                )?;
                let shape = match shape_name {
                    "square" => {
                        let s = cx.required(
                            &pr.side,
                            &format!("{key}.side"),
                            p.span(),
                            "the square's side",
                        )?;
                        PatchShape::Square {
                            side: cx.positive(s, &format!("{key}.side"), Dim::LENGTH, "side")?,
                        }
                    }
                    "rectangle" => {
                        let s = cx.required(
                            &pr.sides,
                            &format!("{key}.sides"),
                            p.span(),
                            "sides = [along x, along y]",
                        )?;
                        if s.get_ref().len() != 2 {
                            return Err(cx
                                .err(
                                    ErrorKind::Schema,
                                    &format!("{key}.sides"),
                                    Some(s.span()),
                                    "expected 2 values",
                                )
                                .hint("sides = [along x, along y]"));
                        }
                        let k = format!("{key}.sides");
                        PatchShape::Rectangle {
                            sides: [
                                cx.positive(&s.get_ref()[0], &k, Dim::LENGTH, "side")?,
                                cx.positive(&s.get_ref()[1], &k, Dim::LENGTH, "side")?,
                            ],
                        }
                    }
                    _ => {
                        let r = cx.required(
                            &pr.radius,
                            &format!("{key}.radius"),
                            p.span(),
                            "the circle's radius",
                        )?;
                        PatchShape::Circle {
                            radius: cx.positive(
                                r,
                                &format!("{key}.radius"),
                                Dim::LENGTH,
                                "radius",
                            )?,
                        }
                    }
                };
                let c = pr.centre.get_ref();
                if c.len() != 2 {
                    return Err(cx
                        .err(
                            ErrorKind::Schema,
                            &format!("{key}.centre"),
                            Some(pr.centre.span()),
                            "expected [x, y]",
                        )
                        .hint("two lengths"));
                }
                let ck = format!("{key}.centre");
                let centre = [
                    cx.qty(&c[0], &ck, Dim::LENGTH, "length")?,
                    cx.qty(&c[1], &ck, Dim::LENGTH, "length")?,
                ];
                let pressure =
                    cx.qty(&pr.pressure, &format!("{key}.pressure"), Dim::STRESS, "pressure")?;
                if pressure <= 0.0 {
                    return Err(cx
                        .err(ErrorKind::OutOfRange, &format!("{key}.pressure"), Some(pr.pressure.span()), format!("a patch with no compressive pressure ({pressure} Pa) carries no load"))
                        .hint("pressure > 0; leave the patch out if it is not in contact"));
                }
                let patch = Patch { shape, centre, pressure };
                if let Some(j) = patches.iter().position(|q| q.overlaps(&patch)) {
                    return Err(cx
                        .err(
                            ErrorKind::Impossible,
                            &key,
                            Some(p.span()),
                            format!("patch {i} overlaps patch {j}"),
                        )
                        .hint("patches must be disjoint (they may touch along an edge)"));
                }
                patches.push(patch);
            }
            Geometry::Patches(patches)
        }
    };

    let s = raw.substrate.get_ref();
    let sspan = raw.substrate.span();
    let model =
        cx.choice(&s.model, "substrate.model", &["homogeneous", "graded", "viscoelastic"])?;
    // For a graded substrate the beta check (more specific) runs before the isotropic range.
    let nu = if model == "graded" { *s.nu.get_ref() } else { cx.nu(&s.nu, "substrate.nu")? };
    let substrate = match model {
        "homogeneous" => {
            let e = cx.required(
                &s.e,
                "substrate.e",
                sspan.clone(),
                "Young's modulus, e.g. e = \"210 GPa\"",
            )?;
            Substrate::Homogeneous(Elastic {
                e: cx.positive(e, "substrate.e", Dim::STRESS, "modulus")?,
                nu,
            })
        }
        "graded" => {
            let k = cx.required(
                &s.k,
                "substrate.k",
                sspan.clone(),
                "the grading exponent k in E = e0 y^k, 0 <= k < 1",
            )?;
            let kv = *k.get_ref();
            if !(kv.is_finite() && (0.0..1.0).contains(&kv)) {
                return Err(cx
                    .err(ErrorKind::OutOfRange, "substrate.k", Some(k.span()), format!("grading exponent k = {kv} is outside [0, 1)"))
                    .hint("0 <= k < 1 (k = 1 is the Gibson soil, where the surface integrals diverge)"));
            }
            // beta^2 = (1+k)(1-(1+k)nu)/(1-nu) must be positive (FORMULAS.md A1).
            if nu >= 1.0 / (1.0 + kv) {
                return Err(cx
                    .err(
                        ErrorKind::OutOfRange,
                        "substrate.nu",
                        Some(s.nu.span()),
                        format!("nu = {nu} with k = {kv} makes beta imaginary"),
                    )
                    .hint(format!(
                        "a graded substrate needs nu < 1/(1+k) = {:.6}, and -1 < nu <= 0.5 as any isotropic solid",
                        1.0 / (1.0 + kv)
                    )));
            }
            let nu = cx.nu(&s.nu, "substrate.nu")?;
            let e0 = cx.required(
                &s.e0,
                "substrate.e0",
                sspan.clone(),
                "E0 of E = e0 y^k, e.g. e0 = \"1767600 kgf/m^2.1\"",
            )?;
            let e0 = cx.positive(
                e0,
                "substrate.e0",
                Dim::graded_modulus(kv),
                "graded modulus (force/length^(2+k))",
            )?;
            Substrate::Graded { e0, k: kv, nu }
        }
        _ => {
            let e = cx.required(&s.e, "substrate.e", sspan.clone(), "the long-time modulus E")?;
            let e = cx.positive(e, "substrate.e", Dim::STRESS, "modulus")?;
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
            let alpha = cx.positive(a, "substrate.alpha", Dim::TIME, "time")?;
            let beta = cx.positive(b, "substrate.beta", Dim::TIME, "time")?;
            if alpha < beta {
                return Err(cx
                    .err(ErrorKind::OutOfRange, "substrate.alpha", Some(a.span()), format!("alpha = {alpha} s is less than beta = {beta} s"))
                    .hint("the standard solid eps + alpha eps' = (sigma + beta sigma')/E dissipates only for alpha > beta; alpha = beta is elastic"));
            }
            Substrate::Viscoelastic { elastic: Elastic { e, nu }, alpha, beta }
        }
    };

    let indenter = match &raw.indenter {
        None => Indenter::Rigid,
        Some(ind) => {
            let i = ind.get_ref();
            match cx.choice(&i.model, "indenter.model", &["rigid", "homogeneous", "same"])? {
                "rigid" => Indenter::Rigid,
                "same" => Indenter::Same,
                _ => {
                    let e = cx.required(
                        &i.e,
                        "indenter.e",
                        ind.span(),
                        "Young's modulus of the indenter",
                    )?;
                    let n = cx.required(
                        &i.nu,
                        "indenter.nu",
                        ind.span(),
                        "Poisson's ratio of the indenter",
                    )?;
                    Indenter::Homogeneous(Elastic {
                        e: cx.positive(e, "indenter.e", Dim::STRESS, "modulus")?,
                        nu: cx.nu(n, "indenter.nu")?,
                    })
                }
            }
        }
    };

    let two_d = geometry.is_2d();
    let (force_dim, force_name) =
        if two_d { (Dim::FORCE_PER_LENGTH, "load per unit length") } else { (Dim::FORCE, "force") };
    let l = raw.load.get_ref();
    let lspan = raw.load.span();
    let normal = match (&geometry, &l.normal, &l.half_width) {
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
        (_, Some(p), None) => {
            NormalLoad::Force(cx.positive(p, "load.normal", force_dim, force_name)?)
        }
        (_, None, Some(a)) => {
            NormalLoad::HalfWidth(cx.positive(a, "load.half_width", Dim::LENGTH, "half-width")?)
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
    let tangential = match &l.tangential {
        Some(t) => cx.qty(t, "load.tangential", force_dim, force_name)?,
        None => 0.0,
    };
    let direction_deg = l.direction_deg.as_ref().map_or(0.0, |d| *d.get_ref());
    let friction = match &l.friction {
        Some(f) => {
            let v = *f.get_ref();
            if !(v.is_finite() && v >= 0.0) {
                return Err(cx
                    .err(
                        ErrorKind::OutOfRange,
                        "load.friction",
                        Some(f.span()),
                        format!("friction coefficient {v} is not allowed"),
                    )
                    .hint("a Coulomb coefficient f >= 0"));
            }
            v
        }
        None => 0.0,
    };
    let moment = match &l.moment {
        Some(m) => {
            let v = cx.qty(m, "load.moment", Dim::MOMENT, "moment")?;
            if v != 0.0 && two_d {
                return Err(cx
                    .err(
                        ErrorKind::Impossible,
                        "load.moment",
                        Some(m.span()),
                        "a twisting moment needs a 3D contact",
                    )
                    .hint("use geometry.kind = sphere, ellipsoid or patches"));
            }
            v
        }
        None => 0.0,
    };
    let sliding = l.sliding.unwrap_or(false);
    if sliding && tangential != 0.0 {
        return Err(cx
            .err(ErrorKind::Impossible, "load.tangential", l.tangential.as_ref().map(|t| t.span()), "with sliding = true the shear is q = f p and the tangential load is f P; do not also give it")
            .hint("remove load.tangential, or set sliding = false for partial slip"));
    }
    if tangential != 0.0 && friction == 0.0 {
        return Err(cx
            .err(
                ErrorKind::Impossible,
                "load.tangential",
                l.tangential.as_ref().map(|t| t.span()),
                "a tangential load on a frictionless contact cannot be carried",
            )
            .hint("give load.friction > 0"));
    }
    if let (NormalLoad::Force(p) | NormalLoad::FromPatches(p), false) = (normal, sliding) {
        if tangential.abs() > friction * p {
            return Err(cx
                .err(ErrorKind::Impossible, "load.tangential", l.tangential.as_ref().map(|t| t.span()), format!("|T| = {} exceeds f P = {} : the contact slides, partial slip is impossible", tangential.abs(), friction * p))
                .hint("reduce T below f P, or set sliding = true"));
        }
    }

    let motion = match &raw.motion {
        None => Motion::Static,
        Some(m) => {
            let mr = m.get_ref();
            match cx.choice(&mr.kind, "motion.kind", &["static", "rolling"])? {
                "static" => Motion::Static,
                _ => {
                    let sp = cx.required(
                        &mr.speed,
                        "motion.speed",
                        m.span(),
                        "the rolling speed w, e.g. speed = \"10 cm/s\"",
                    )?;
                    let speed = cx.positive(sp, "motion.speed", Dim::SPEED, "speed")?;
                    let creep = mr.creep.as_ref().map_or(0.0, |c| *c.get_ref());
                    if !creep.is_finite() {
                        return Err(cx.err(
                            ErrorKind::OutOfRange,
                            "motion.creep",
                            None,
                            "creep must be finite",
                        ));
                    }
                    if !two_d {
                        return Err(cx
                            .err(
                                ErrorKind::Impossible,
                                "motion.kind",
                                Some(mr.kind.span()),
                                "rolling is solved for cylinders (2D)",
                            )
                            .hint("use geometry.kind = \"cylinder\""));
                    }
                    Motion::Rolling { speed, creep }
                }
            }
        }
    };

    let outputs = convert_outputs(cx, raw.outputs.as_ref())?;
    let solver = convert_solver(cx, raw.solver.as_ref())?;

    let scene = Scene {
        title: raw.title.clone().unwrap_or_else(|| "untitled scene".to_string()),
        file: cx.file.clone(),
        geometry,
        substrate,
        indenter,
        load: Load { normal, tangential, direction_deg, friction, sliding, moment },
        motion,
        outputs,
        solver,
    };
    // Combinations no solver handles, and checks that need the contact size, are refused
    // here, located at the key the planner names.
    if let Err(i) = crate::plan::check(&scene) {
        let span = key_span(&raw, i.key);
        return Err(cx.err(i.kind, i.key, span, i.message).hint(i.hint));
    }
    Ok(scene)
}

/// Byte span of a dotted key (or of its table) in the source, for the planner's refusals.
fn key_span(raw: &RawScene, key: &str) -> Option<Range<usize>> {
    let g = raw.geometry.get_ref();
    let s = raw.substrate.get_ref();
    let l = raw.load.get_ref();
    let exact = match key {
        "geometry.kind" => Some(g.kind.span()),
        "substrate.model" => Some(s.model.span()),
        "indenter.model" => raw.indenter.as_ref().map(|i| i.get_ref().model.span()),
        "load.normal" => l.normal.as_ref().map(Spanned::span),
        "load.half_width" => l.half_width.as_ref().map(Spanned::span),
        "load.tangential" => l.tangential.as_ref().map(Spanned::span),
        "load.friction" => l.friction.as_ref().map(Spanned::span),
        "load.moment" => l.moment.as_ref().map(Spanned::span),
        "motion.kind" => raw.motion.as_ref().map(|m| m.get_ref().kind.span()),
        "outputs.field" => raw.outputs.as_ref().and_then(|o| o.field.as_ref()).map(Spanned::span),
        "outputs.cycle" => raw.outputs.as_ref().and_then(|o| o.cycle.as_ref()).map(Spanned::span),
        "solver.method" => raw.solver.as_ref().and_then(|s| s.method.as_ref()).map(Spanned::span),
        "solver.grid" => raw.solver.as_ref().and_then(|s| s.grid.as_ref()).map(Spanned::span),
        _ => None,
    };
    exact.or_else(|| match key.split('.').next() {
        Some("geometry") => Some(raw.geometry.span()),
        Some("substrate") => Some(raw.substrate.span()),
        Some("load") => Some(raw.load.span()),
        Some("indenter") => raw.indenter.as_ref().map(Spanned::span),
        Some("motion") => raw.motion.as_ref().map(Spanned::span),
        _ => None,
    })
}

fn convert_outputs(
    cx: &Ctx<'_>,
    o: Option<&crate::raw::RawOutputs>,
) -> Result<Outputs, SceneError> {
    let Some(o) = o else {
        return Ok(Outputs { surface: true, field: None, cycle: None, plots: false });
    };
    let axis =
        |v: &Spanned<Vec<f64>>, key: &str, depth: bool| -> Result<(f64, f64, usize), SceneError> {
            let a = v.get_ref();
            let bad = |m: String| {
                cx.err(ErrorKind::OutOfRange, key, Some(v.span()), m).hint(
                    "[from, to, count] with from < to and 2 <= count <= 10000 (depth from > 0)",
                )
            };
            if a.len() != 3 {
                return Err(bad(format!("expected [from, to, count], got {} values", a.len())));
            }
            let (lo, hi, n) = (a[0], a[1], a[2]);
            if !(lo.is_finite() && hi.is_finite() && lo < hi) {
                return Err(bad(format!("need from < to, got {lo} .. {hi}")));
            }
            if depth && lo <= 0.0 {
                return Err(bad(format!("depths must be below the surface (> 0), got {lo}")));
            }
            if !(n.fract() == 0.0 && (2.0..=10000.0).contains(&n)) {
                return Err(bad(format!("count {n} is not an integer in 2..=10000")));
            }
            Ok((lo, hi, n as usize))
        };
    let field = match &o.field {
        None => None,
        Some(f) => {
            let fr = f.get_ref();
            let scale = match &fr.scale {
                None => FieldScale::HalfWidth,
                Some(s) => match cx.choice(s, "outputs.field.scale", &["a", "m"])? {
                    "a" => FieldScale::HalfWidth,
                    _ => FieldScale::Metres,
                },
            };
            Some(FieldGrid {
                x: axis(&fr.x, "outputs.field.x", false)?,
                y: axis(&fr.y, "outputs.field.y", true)?,
                scale,
            })
        }
    };
    let cycle = match &o.cycle {
        None => None,
        Some(c) => {
            let cr = c.get_ref();
            let amp = *cr.amplitude.get_ref();
            if !(amp > 0.0 && amp <= 1.0) {
                return Err(cx
                    .err(
                        ErrorKind::OutOfRange,
                        "outputs.cycle.amplitude",
                        Some(cr.amplitude.span()),
                        format!("amplitude T*/(fP) = {amp} is outside (0, 1]"),
                    )
                    .hint("0 < T*/(fP) <= 1"));
            }
            let points = match &cr.points {
                None => 60,
                Some(p) => {
                    let v = *p.get_ref();
                    if !(4..=100_000).contains(&v) {
                        return Err(cx
                            .err(
                                ErrorKind::OutOfRange,
                                "outputs.cycle.points",
                                Some(p.span()),
                                format!("{v} points"),
                            )
                            .hint("4 <= points <= 100000"));
                    }
                    v as usize
                }
            };
            Some(Cycle { amplitude: amp, points })
        }
    };
    Ok(Outputs {
        surface: o.surface.unwrap_or(true),
        field,
        cycle,
        plots: o.plots.unwrap_or(false),
    })
}

fn convert_solver(
    cx: &Ctx<'_>,
    s: Option<&crate::raw::RawSolver>,
) -> Result<SolverOptions, SceneError> {
    let mut out = SolverOptions { method: Method::Auto, grid: 32, tolerance: 1e-10 };
    let Some(s) = s else { return Ok(out) };
    if let Some(m) = &s.method {
        out.method = match cx.choice(
            m,
            "solver.method",
            &["auto", "closed-form", "quadrature", "lp", "fast"],
        )? {
            "auto" => Method::Auto,
            "closed-form" => Method::ClosedForm,
            "quadrature" => Method::Quadrature,
            "lp" => Method::Lp,
            _ => Method::Fast,
        };
    }
    if let Some(g) = &s.grid {
        let v = *g.get_ref();
        if !(4..=MAX_GRID as i64).contains(&v) {
            return Err(cx
                .err(ErrorKind::OutOfRange, "solver.grid", Some(g.span()), format!("grid = {v} elements per side is not allowed"))
                .hint(format!("4 <= grid <= {MAX_GRID}; grids whose working memory would exceed 16 GiB are refused by the planner (about 5100 per side for the fast solver)")));
        }
        out.grid = v as usize;
    }
    if let Some(t) = &s.tolerance {
        let v = *t.get_ref();
        if !(v.is_finite() && v > 0.0 && v < 1.0) {
            return Err(cx
                .err(
                    ErrorKind::OutOfRange,
                    "solver.tolerance",
                    Some(t.span()),
                    format!("tolerance {v} is not allowed"),
                )
                .hint("a relative tolerance in (0, 1), e.g. 1e-10"));
        }
        out.tolerance = v;
    }
    Ok(out)
}
