//! Subsurface stresses under an arbitrary surface load by full integration of the line-load
//! field (FORMULAS.md A2; the corrected form of seed 000 eqs 17–25).

use crate::error::{require, Error};
use crate::load::SurfaceLoad;
use crate::material::GradedMaterial;
use crate::panels::{breakpoints, integrate, Grading, RuleSet};
use rayon::prelude::*;
pub use stickslip_halfspace::Stress2;
use stickslip_quad::Tolerance;

/// The accuracy knob of the integrators: the number of nodes per panel of the composite
/// Gauss–Jacobi rule (see the `panels` module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Accuracy {
    nodes: usize,
}

impl Accuracy {
    /// The relative tolerances this knob supports, $[10^{-15}, 10^{-2}]$ (the calibrated
    /// range of the nodes-per-panel mapping of [`Accuracy::new`]).
    pub const TOLERANCE_RANGE: (f64, f64) = (1e-15, 1e-2);

    /// Choose the rule for a target relative accuracy `tolerance.rel()` in
    /// [`Accuracy::TOLERANCE_RANGE`] (the tolerance must be purely relative, `abs() == 0`).
    ///
    /// The mapping (nodes per panel) was calibrated on the worst panels (merged end panels next
    /// to a field point just outside the load), which converge like $\approx 2.3^{-2n}$;
    /// checked against the mpmath reference of `scripts/graded_reference.py` in the tests.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a relative part outside the range above (never clamped) or a
    /// non-zero absolute part.
    pub fn new(tolerance: Tolerance) -> Result<Self, Error> {
        require(tolerance.abs() == 0.0, "tolerance abs", tolerance.abs(), "0 (relative only)")?;
        let rel_tol = tolerance.rel();
        let (lo, hi) = Self::TOLERANCE_RANGE;
        require((lo..=hi).contains(&rel_tol), "tolerance rel", rel_tol, "1e-15 <= rel <= 1e-2")?;
        // 2 n log10(2.3) >= -log10(tol), plus a margin of two nodes.
        let n = (-rel_tol.log10() / (2.0 * 2.3f64.log10())).ceil() as usize + 2;
        Ok(Self { nodes: n })
    }

    /// Set the nodes per panel directly ($2 \le n \le 64$).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] outside that range.
    pub fn with_nodes(nodes: usize) -> Result<Self, Error> {
        require((2..=64).contains(&nodes), "nodes", nodes as f64, "2 <= nodes <= 64")?;
        Ok(Self { nodes })
    }

    /// Nodes per panel.
    #[must_use]
    pub fn nodes(&self) -> usize {
        self.nodes
    }
}

impl Default for Accuracy {
    /// About $10^{-13}$ relative (20 nodes per panel).
    fn default() -> Self {
        Self { nodes: 20 }
    }
}

/// Smallest admissible depth, relative to the widest patch half-width. Below it the kernel
/// peak is narrower than the resolution of $x - s$ in `f64`; there the stress is the surface
/// traction itself ($\sigma_{yy} = -p$, $\sigma_{xy} = -q$).
pub const MIN_RELATIVE_DEPTH: f64 = 1e-12;

/// The stress field of a [`SurfaceLoad`] on a graded half-plane, planned once (rules built,
/// constants computed) and evaluated at many points.
///
/// $$\sigma_{ij}(x,y) = -\int \Bigl[\frac{p(s)\cos\beta\theta_s}{2I_k} + \frac{q(s)\sin\beta\theta_s}{2J_k}\Bigr]\,
///   \frac{y^k\,\{(x-s)^2,\ y^2,\ y(x-s)\}}{((x-s)^2+y^2)^{(3+k)/2}}\,ds,
///   \qquad \theta_s = \arctan\frac{x-s}{y},$$
///
/// for $(xx, yy, xy)$ respectively (FORMULAS.md A2, correcting seed 000 eqs 17–25: exponent
/// $(3+k)/2$, load inside the integral, limits $\pm a$). Convention: $y > 0$ is depth, $p > 0$
/// pushes into the substrate, $q > 0$ acts on it in $+x$, compression negative; as
/// $y \to 0$, $\sigma_{yy} \to -p(x)$ and $\sigma_{xy} \to -q(x)$.
///
/// Each patch is integrated by a composite Gauss–Jacobi rule graded geometrically about
/// $s = x$ with first panel $\min(y, \text{distance to the patch edge})$, the edge factor
/// $(1-s^2/b^2)^\gamma$ in the weight of the end panels.
#[derive(Debug, Clone)]
pub struct StressField {
    load: SurfaceLoad,
    rules: Vec<RuleSet>,
    k: f64,
    beta: f64,
    inv_2i: f64,
    inv_2j: f64,
    min_depth: f64,
    grading: Grading,
}

impl StressField {
    /// Plan the field of `load` on `material` at the given accuracy.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for an empty load; [`Error::Numerical`] if a quadrature rule
    /// cannot be built.
    pub fn new(
        material: &GradedMaterial,
        load: SurfaceLoad,
        accuracy: Accuracy,
    ) -> Result<Self, Error> {
        require(!load.patches().is_empty(), "load.patches", 0.0, "at least one patch")?;
        let rules = load
            .patches()
            .iter()
            .map(|p| RuleSet::new(accuracy.nodes, p.exponent(), 0.0))
            .collect::<Result<Vec<_>, _>>()?;
        let bmax = load.patches().iter().map(|p| p.half_width()).fold(0.0, f64::max);
        Ok(Self {
            load,
            rules,
            k: material.k(),
            beta: material.beta(),
            inv_2i: 0.5 / material.i_k(),
            inv_2j: 0.5 / material.j_k(),
            min_depth: MIN_RELATIVE_DEPTH * bmax,
            grading: Grading::default(),
        })
    }

    /// The load.
    #[must_use]
    pub fn load(&self) -> &SurfaceLoad {
        &self.load
    }

    /// $(\sigma_{xx}, \sigma_{yy}, \sigma_{xy})$ at $(x, y)$: the integral of the type docs,
    /// i.e. the line-load field of FORMULAS.md A2 superposed over the load (corrected seed 000
    /// eqs 17–25; Giannakopoulos & Pallot 2000).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] unless $x$ is finite and $y \ge 10^{-12} b_{\max}$ is finite
    /// (see [`MIN_RELATIVE_DEPTH`]).
    pub fn stress(&self, x: f64, y: f64) -> Result<Stress2, Error> {
        require(x.is_finite(), "x", x, "finite")?;
        require(
            y.is_finite() && y >= self.min_depth,
            "y",
            y,
            "1e-12 * (widest patch half-width) <= y < inf",
        )?;
        let mut buf = Vec::with_capacity(96);
        Ok(self.stress_with(x, y, &mut buf))
    }

    fn stress_with(&self, x: f64, y: f64, buf: &mut Vec<f64>) -> Stress2 {
        let mut out = Stress2::default();
        let k = self.k;
        let beta = self.beta;
        let (inv_2i, inv_2j) = (self.inv_2i, self.inv_2j);
        for (patch, rules) in self.load.patches().iter().zip(&self.rules) {
            let b = patch.half_width();
            let c = patch.centre();
            let xx = (x - c) / b;
            let yy = y / b;
            let d_edge = (xx - 1.0).abs().min((xx + 1.0).abs());
            let h0 = if d_edge > 0.0 { yy.min(d_edge) } else { yy };
            breakpoints(xx, h0, self.grading, buf);
            let profile = patch.profile();
            let [sxx, syy, sxy] = integrate::<3>(rules, xx, buf, |t, d| {
                let s = c + b * t;
                let dx = b * d;
                let r = dx.hypot(y);
                let ct = y / r;
                let st = dx / r;
                let theta = dx.atan2(y);
                let (sb, cb) = (beta * theta).sin_cos();
                let (ph, qh) = profile.eval(s);
                let amp = -(ph * cb * inv_2i + qh * sb * inv_2j);
                let common = if k == 0.0 { amp / r } else { amp * ct.powf(k) / r };
                [common * st * st, common * ct * ct, common * st * ct]
            });
            out.xx += b * sxx;
            out.yy += b * syy;
            out.xy += b * sxy;
        }
        out
    }

    /// Stresses at many points, in parallel over points (rayon).
    ///
    /// # Errors
    /// As [`StressField::stress`], for the first offending point.
    pub fn stress_at(&self, points: &[(f64, f64)]) -> Result<Vec<Stress2>, Error> {
        for &(x, y) in points {
            require(x.is_finite(), "x", x, "finite")?;
            require(
                y.is_finite() && y >= self.min_depth,
                "y",
                y,
                "1e-12 * (widest patch half-width) <= y < inf",
            )?;
        }
        Ok(points
            .par_iter()
            .map_init(|| Vec::with_capacity(96), |buf, &(x, y)| self.stress_with(x, y, buf))
            .collect())
    }

    /// Stresses on the tensor grid `xs` × `ys`, row-major (index `iy * xs.len() + ix`),
    /// in parallel over points.
    ///
    /// # Errors
    /// As [`StressField::stress`].
    pub fn grid(&self, xs: &[f64], ys: &[f64]) -> Result<Vec<Stress2>, Error> {
        let pts: Vec<(f64, f64)> =
            ys.iter().flat_map(|&y| xs.iter().map(move |&x| (x, y))).collect();
        self.stress_at(&pts)
    }
}
