//! Rail and wheel profiles: reading ([`read`]), checking ([`check`]) and the smoothing
//! spline ([`crate::spline`]).
//!
//! A [`Profile`] is a checked plane curve in the canonical orientation (CONTACT's right-side
//! profile: $y$ towards the field side, $z$ down, metres), ordered by increasing $y$, with the
//! parametric cubic smoothing spline through its points. The physics reads no file: the
//! caller hands over the text and a name for messages ([`Profile::read`]), or the points
//! ([`Profile::from_points`]).

pub mod check;
pub mod read;

pub use read::Format;

use crate::error::{Error, Result};
use crate::spline::{alpha_for_length, CurvePoint, ParametricSpline};

/// Which body a profile describes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    /// A rail (the lower body, body 1 of the contact).
    Rail,
    /// A wheel (the upper body, body 2).
    Wheel,
}

impl Role {
    fn name(self) -> &'static str {
        match self {
            Role::Rail => "rail",
            Role::Wheel => "wheel",
        }
    }
}

/// How a profile file is read.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfileOptions {
    /// Length of one file unit in metres (`profile_unit`; default $10^{-3}$, mm).
    pub unit: f64,
    /// Mirror $y$ after the format's own conversion (module [`read`]).
    pub mirror_y: bool,
    /// Mirror $z$ after the format's own conversion.
    pub mirror_z: bool,
    /// The smoothing length $L_c$ of the spline (m; 0 interpolates; [`crate::spline`]).
    pub smoothing: f64,
}

impl Default for ProfileOptions {
    /// Millimetres, no mirroring, the interpolating spline.
    fn default() -> Self {
        Self { unit: 1e-3, mirror_y: false, mirror_z: false, smoothing: 0.0 }
    }
}

/// A checked profile with its spline (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    name: String,
    role: Role,
    y: Vec<f64>,
    z: Vec<f64>,
    line: Vec<usize>,
    spline: ParametricSpline,
    smoothing: f64,
    /// Dense samples $(t, y, z)$ of the spline, spacing at most [`SAMPLE_STEP`].
    samples: Vec<[f64; 3]>,
}

/// Largest parameter step of [`Profile::samples`] (m): the contact search's resolution along
/// the profiles (between samples the curve is taken as straight: an error of
/// $h^2/(8R)$, 0.03 µm for a flange radius of 10 mm, and the smallest gap is refined on the
/// exact curves).
pub const SAMPLE_STEP: f64 = 5e-5;

impl Profile {
    /// Read a profile from `text` (the contents of the file called `name`, which error
    /// messages name) in the format `format` (e.g. [`Format::from_name`]) as `role`.
    ///
    /// Lengths are the file's numbers times `options.unit` (a SIMPACK file that states its
    /// own unit, `units.len.f`, must agree). Then the caller's mirroring, the checks of
    /// [`check`] and the spline of smoothing length `options.smoothing`.
    ///
    /// # Errors
    /// [`Error::ProfileFormat`] for text the format cannot read; [`Error::ProfileCheck`] for
    /// a failed check, a unit disagreeing with the file's, or a file that states the other
    /// role (SIMPACK `type`, or the extensions `.prr`/`.ban` rail, `.prw`/`.whl` wheel);
    /// [`Error::OutOfDomain`] for a non-positive unit or a negative smoothing length.
    pub fn read(
        text: &str,
        name: &str,
        format: Format,
        role: Role,
        options: &ProfileOptions,
    ) -> Result<Self> {
        validate_options(options)?;
        let raw = read::read(text, name, format, role)?;
        let stated = raw
            .role
            .map(|r| (r, "SIMPACK type"))
            .or_else(|| read::role_of_extension(name).map(|r| (r, "file extension")));
        if let Some((r, how)) = stated {
            if r != role {
                return Err(Error::ProfileCheck {
                    name: name.to_string(),
                    line: None,
                    problem: format!(
                        "the file is a {} profile (its {how} says so) but is given as the {}",
                        r.name(),
                        role.name()
                    ),
                    hint: format!("give a {} profile here", role.name()),
                });
            }
        }
        if let Some(per_metre) = raw.units_per_metre {
            let stated_unit = 1.0 / per_metre;
            if ((stated_unit - options.unit) / options.unit).abs() > 1e-9 {
                return Err(Error::ProfileCheck {
                    name: name.to_string(),
                    line: None,
                    problem: format!(
                        "the file states its lengths in units of {stated_unit:e} m (units.len.f = {per_metre}) but profile_unit is {:e} m",
                        options.unit
                    ),
                    hint: "set profile_unit to the file's unit".to_string(),
                });
            }
        }
        let points = raw
            .points
            .into_iter()
            .map(|(y, z, ln)| {
                let (y, z) = (y * options.unit, z * options.unit);
                (if options.mirror_y { -y } else { y }, if options.mirror_z { -z } else { z }, ln)
            })
            .collect();
        Self::build(name, role, points, options)
    }

    /// A profile from points $(y, z)$ in metres, canonical orientation (module docs); line
    /// numbers in messages are the 1-based point indices. `options.unit` only labels
    /// messages here.
    ///
    /// # Errors
    /// As [`Profile::read`] for the checks.
    pub fn from_points(
        name: &str,
        role: Role,
        points: &[(f64, f64)],
        options: &ProfileOptions,
    ) -> Result<Self> {
        validate_options(options)?;
        let pts = points.iter().enumerate().map(|(i, &(y, z))| (y, z, i + 1)).collect();
        Self::build(name, role, pts, options)
    }

    fn build(
        name: &str,
        role: Role,
        points: Vec<(f64, f64, usize)>,
        options: &ProfileOptions,
    ) -> Result<Self> {
        let c = check::check(points, name, role, options.unit)?;
        let n = c.y.len();
        let length: f64 = (1..n).map(|i| (c.y[i] - c.y[i - 1]).hypot(c.z[i] - c.z[i - 1])).sum();
        let alpha = alpha_for_length(options.smoothing, length / (n - 1) as f64);
        let spline = ParametricSpline::new(&c.y, &c.z, alpha);
        let (t0, t1) = spline.range();
        let knots = spline.knots().to_vec();
        let mut samples = Vec::with_capacity(((t1 - t0) / SAMPLE_STEP) as usize + n);
        for i in 0..n - 1 {
            let (a, b) = (knots[i], knots[i + 1]);
            let k = ((b - a) / SAMPLE_STEP).ceil().max(1.0) as usize;
            for m in 0..k {
                let t = a + (b - a) * m as f64 / k as f64;
                let p = spline.eval_in(i, t);
                samples.push([t, p.p[0], p.p[1]]);
            }
        }
        let p = spline.eval_in(n - 2, t1);
        samples.push([t1, p.p[0], p.p[1]]);
        Ok(Self {
            name: name.to_string(),
            role,
            y: c.y,
            z: c.z,
            line: c.line,
            spline,
            smoothing: options.smoothing,
            samples,
        })
    }

    /// The name given with the text.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Rail or wheel.
    #[must_use]
    pub fn role(&self) -> Role {
        self.role
    }

    /// The checked points $(y, z)$ (m, canonical, increasing $y$ overall).
    #[must_use]
    pub fn points(&self) -> (&[f64], &[f64]) {
        (&self.y, &self.z)
    }

    /// The file line of each checked point.
    #[must_use]
    pub fn lines(&self) -> &[usize] {
        &self.line
    }

    /// The smoothing length used (m).
    #[must_use]
    pub fn smoothing(&self) -> f64 {
        self.smoothing
    }

    /// The spline.
    #[must_use]
    pub fn spline(&self) -> &ParametricSpline {
        &self.spline
    }

    /// The curve at parameter $t$ (chord length, m).
    #[must_use]
    pub fn eval(&self, t: f64) -> CurvePoint {
        self.spline.eval(t)
    }

    /// Dense samples $[t, y, z]$ of the spline (step at most [`SAMPLE_STEP`]).
    #[must_use]
    pub fn samples(&self) -> &[[f64; 3]] {
        &self.samples
    }
}

fn validate_options(o: &ProfileOptions) -> Result<()> {
    if !(o.unit.is_finite() && o.unit > 0.0) {
        return Err(Error::OutOfDomain {
            name: "profile_unit",
            value: o.unit,
            allowed: "finite and > 0 (metres per file unit)",
        });
    }
    if !(o.smoothing.is_finite() && o.smoothing >= 0.0) {
        return Err(Error::OutOfDomain {
            name: "profile smoothing length",
            value: o.smoothing,
            allowed: "finite and >= 0 (m; 0 interpolates)",
        });
    }
    Ok(())
}
