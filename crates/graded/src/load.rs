//! Surface tractions on a strip: pressure $p(s)$ and shear $q(s)$, as a sum of patches
//! with known algebraic edge behaviour (so the integrators can put the edge singularity in a
//! Gauss–Jacobi weight).

use crate::error::{require, Error};
use std::fmt;
use std::sync::Arc;

/// Signature of a user traction: `s -> (p_hat(s), q_hat(s))`, the smooth factors of a
/// [`LoadPatch`].
pub type TractionFn = dyn Fn(f64) -> (f64, f64) + Send + Sync;

/// The smooth factor $(\hat p(s), \hat q(s))$ of a patch.
#[derive(Clone)]
pub enum Profile {
    /// Constant factors: $\hat p = $ `p`, $\hat q = $ `q` (Hertz-type shapes).
    Uniform {
        /// Pressure amplitude (positive pushes into the substrate).
        p: f64,
        /// Shear amplitude (positive acts on the substrate in $+x$).
        q: f64,
    },
    /// Any closure $s \mapsto (\hat p(s), \hat q(s))$, $s$ in the same length unit as the
    /// patch; it should be smooth on the patch for the quadrature rules to converge fast.
    Custom(Arc<TractionFn>),
}

impl fmt::Debug for Profile {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Uniform { p, q } => write!(f, "Uniform {{ p: {p}, q: {q} }}"),
            Self::Custom(_) => write!(f, "Custom(..)"),
        }
    }
}

impl Profile {
    #[inline]
    pub(crate) fn eval(&self, s: f64) -> (f64, f64) {
        match self {
            Self::Uniform { p, q } => (*p, *q),
            Self::Custom(f) => f(s),
        }
    }
}

/// One patch of surface traction on $[c-b,\,c+b]$:
///
/// $$p(s) = \Bigl(1-\tfrac{(s-c)^2}{b^2}\Bigr)^{\gamma}\,\hat p(s), \qquad
///   q(s) = \Bigl(1-\tfrac{(s-c)^2}{b^2}\Bigr)^{\gamma}\,\hat q(s),$$
///
/// zero outside. $\gamma = (1+k)/2$ is the rigid-cylinder pressure on the graded half-plane
/// (FORMULAS.md A4), $\gamma = 1/2$ Hertz, $\gamma = 0$ a plain bounded traction.
#[derive(Debug, Clone)]
pub struct LoadPatch {
    pub(crate) centre: f64,
    pub(crate) half_width: f64,
    pub(crate) exponent: f64,
    pub(crate) profile: Profile,
}

impl LoadPatch {
    /// Validate and build a patch with centre `centre`, half-width `half_width > 0` and edge
    /// exponent `exponent` $> -1$ (integrable).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a non-finite centre, a non-positive half-width or an
    /// exponent $\le -1$ (or above 50, where the shape is no longer meaningful).
    pub fn new(
        centre: f64,
        half_width: f64,
        exponent: f64,
        profile: Profile,
    ) -> Result<Self, Error> {
        require(centre.is_finite(), "centre", centre, "finite")?;
        require(
            half_width.is_finite() && half_width > 0.0,
            "half_width",
            half_width,
            "0 < half_width < inf",
        )?;
        require(exponent > -1.0 && exponent <= 50.0, "exponent", exponent, "-1 < exponent <= 50")?;
        Ok(Self { centre, half_width, exponent, profile })
    }

    /// $(p(s), q(s))$ at a point $s$ (zero outside the patch).
    #[must_use]
    pub fn traction(&self, s: f64) -> (f64, f64) {
        let t = (s - self.centre) / self.half_width;
        if t.abs() >= 1.0 {
            if t.abs() == 1.0 && self.exponent == 0.0 {
                return self.profile.eval(s);
            }
            return (0.0, 0.0);
        }
        let w = ((1.0 - t) * (1.0 + t)).powf(self.exponent);
        let (p, q) = self.profile.eval(s);
        (w * p, w * q)
    }

    /// Centre $c$.
    #[must_use]
    pub fn centre(&self) -> f64 {
        self.centre
    }
    /// Half-width $b$.
    #[must_use]
    pub fn half_width(&self) -> f64 {
        self.half_width
    }
    /// Edge exponent $\gamma$.
    #[must_use]
    pub fn exponent(&self) -> f64 {
        self.exponent
    }
    /// The smooth factor.
    #[must_use]
    pub fn profile(&self) -> &Profile {
        &self.profile
    }
}

/// A surface load: the sum of its [`LoadPatch`]es.
#[derive(Debug, Clone, Default)]
pub struct SurfaceLoad {
    patches: Vec<LoadPatch>,
}

impl SurfaceLoad {
    /// An empty load (add patches with [`SurfaceLoad::with_patch`]).
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Add a patch (builder style).
    #[must_use]
    pub fn with_patch(mut self, patch: LoadPatch) -> Self {
        self.patches.push(patch);
        self
    }

    /// The patches.
    #[must_use]
    pub fn patches(&self) -> &[LoadPatch] {
        &self.patches
    }

    /// The rigid-cylinder pressure on the graded half-plane with sliding friction $q = \mu p$
    /// (FORMULAS.md A4; seed 000 eqs 17–25 with the load inside the integral, A2):
    /// $p(s) = p_0(1-s^2/a^2)^{(1+k)/2}$. `friction = 0` gives frictionless indentation.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for $a \le 0$, non-finite $p_0$ or friction $\mu$, or $k \notin [0,1)$.
    pub fn cylinder(a: f64, p0: f64, k: f64, friction: f64) -> Result<Self, Error> {
        require(p0.is_finite(), "p0", p0, "finite")?;
        require(friction.is_finite(), "friction", friction, "finite")?;
        require(k.is_finite() && (0.0..1.0).contains(&k), "k", k, "0 <= k < 1")?;
        let patch =
            LoadPatch::new(0.0, a, 0.5 * (1.0 + k), Profile::Uniform { p: p0, q: friction * p0 })?;
        Ok(Self::new().with_patch(patch))
    }

    /// A Cattaneo-type partial-slip load on the graded half-plane: the sliding traction
    /// $\mu p$ on $[-a,a]$ minus a stick-zone correction of the same shape on $[-c,c]$,
    ///
    /// $$q(s) = \mu p_0 (1-s^2/a^2)^{\gamma} - \mu p_0 (c/a)^{1+k}(1-s^2/c^2)^{\gamma},
    ///   \quad \gamma = \tfrac{1+k}{2},$$
    ///
    /// whose $q$-induced $u_x$ (FORMULAS.md A3 with the spectral relation A4) is constant on
    /// $|x| < c$. Like Cattaneo–Mindlin (FORMULAS.md C) this neglects the pressure-induced odd
    /// part of $u_x$ (A5); for $k = 0$ it is exactly the 2D Cattaneo–Mindlin traction.
    ///
    /// # Errors
    /// As [`SurfaceLoad::cylinder`], plus $0 < c \le a$ required.
    pub fn partial_slip(a: f64, c: f64, p0: f64, k: f64, friction: f64) -> Result<Self, Error> {
        let base = Self::cylinder(a, p0, k, friction)?;
        require(c > 0.0 && c <= a, "c", c, "0 < c <= a")?;
        let amp = -friction * p0 * (c / a).powf(1.0 + k);
        let patch = LoadPatch::new(0.0, c, 0.5 * (1.0 + k), Profile::Uniform { p: 0.0, q: amp })?;
        Ok(base.with_patch(patch))
    }

    /// Total $(p(s), q(s))$ at $s$.
    #[must_use]
    pub fn traction(&self, s: f64) -> (f64, f64) {
        self.patches.iter().fold((0.0, 0.0), |(p, q), pa| {
            let (dp, dq) = pa.traction(s);
            (p + dp, q + dq)
        })
    }

    /// The extent $[\min_i (c_i - b_i),\ \max_i (c_i + b_i)]$ of the loaded strip, or `None`
    /// for an empty load.
    #[must_use]
    pub fn extent(&self) -> Option<(f64, f64)> {
        let lo = self.patches.iter().map(|p| p.centre - p.half_width).reduce(f64::min)?;
        let hi = self.patches.iter().map(|p| p.centre + p.half_width).reduce(f64::max)?;
        Some((lo, hi))
    }
}
