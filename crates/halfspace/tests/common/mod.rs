//! Shared test helpers: tolerances (with reasons), reference-table reader, error statistics.
#![allow(dead_code)]

pub mod quad;

/// Test tolerances, each with its reason.
pub mod tol {
    /// Rectangle influence coefficients against a 24x24 Gauss product rule at d/h >= 3, where
    /// both are accurate to rounding: the corner sums lose eps (d/h)^2 up to the switch at
    /// 6 element sizes (8e-15), the 6x6 far-field rule beyond it is exact to ~1e-16.
    pub const FAR_FIELD: f64 = 2e-14;
    /// Closed form against closed form (two algebraically equal expressions): a few hundred
    /// ulps of relative error from the different operation orders.
    pub const IDENTITY: f64 = 1e-13;
    /// Against mpmath (40 digits) for well-conditioned closed forms: 1e-13 relative leaves room
    /// for the O(10) roundings of a closed form and of the f64 input conversion.
    pub const MPMATH: f64 = 1e-13;
    /// Elliptic Hertz against mpmath: the root of g(m) = ratio conditions b/a at about
    /// cond * eps with cond up to ~100 at ratio 1e4 (m close to 1, 1 - m rounded).
    pub const HERTZ_ELLIPSE: f64 = 1e-11;
    /// Target of the brief for stresses vs quadrature of Flamant (1e-9) ...
    pub const MCEWEN_VS_QUAD: f64 = 1e-9;
    /// ... and of the rectangle influence coefficients vs nested quadrature (1e-10).
    pub const RECT_VS_QUAD: f64 = 1e-10;
    /// Finite-difference strain check: central differences with step h = 1e-4 min(R, z) have
    /// truncation error ~(h/z)^2 ~ 1e-8 times the growth of the third derivative near the
    /// surface (R/z up to ~70 at the test points), and rounding ~eps u/h.
    pub const FD: f64 = 1e-6;
    /// Quadrature-based equilibrium and reciprocity checks: the (nested) integrators are asked
    /// for 1e-11 relative, so 1e-10 leaves room for the accumulated estimate.
    pub const QUAD: f64 = 1e-10;
    /// Rectangle stresses at depth z = 1e-9 under the interior against the surface traction:
    /// the field differs from its surface value by O(z / distance to the nearest edge) ~ 2e-8.
    pub const RECT_SURFACE_LIMIT: f64 = 1e-7;
    /// Rectangle of side h against the point force of the same resultant at distance d: the
    /// quadrupole correction is O((h/d)^2) <= 2e-2 times a coefficient below 1/4 here.
    pub const RECT_POINT_FORCE: f64 = 5e-3;
    /// Corner sums against the far-field Gauss rule beyond the switch: the corner sums lose
    /// eps (d/h)^2 ~ 1e-11 at d/h ~ 30.
    pub const RECT_CORNER_VS_FAR: f64 = 1e-9;
    /// Hertz sphere field against nested quadrature asked for 1e-12 relative: 1e-9 of p0
    /// leaves room for the accumulated estimate of the 2D rule.
    pub const HERTZ_FIELD_QUAD: f64 = 1e-9;
    /// Hertz sphere off-axis formula 1e-3 a from the axis against the axis closed form: the
    /// field changes by O(r^2/a^2) = 1e-6 there, and the cancellation costs eps a^2/r^2.
    pub const HERTZ_NEAR_AXIS: f64 = 1e-5;
    /// Sliding sphere 1e-6 a below the surface inside the contact: the field differs from the
    /// surface traction by O(z/a) times gradients of order 1, plus the quadrature's 1e-10.
    pub const SLIDING_SURFACE: f64 = 1e-5;
    /// The elliptic Hertz field (one s-integral asked for 1e-11 of p0) against the sphere's
    /// closed form: the integral's tolerance plus rounding in the generated terms.
    pub const ELLIPSE_FIELD_VS_CLOSED: f64 = 1e-10;
    /// The sliding field against the Cerruti quadrature asked for 1e-11 relative.
    pub const SLIDING_FIELD_VS_QUAD: f64 = 1e-8;
}

/// Parse a CSV table: skip `#` comments and the header line, return rows of f64.
pub fn read_table(path: &str) -> Vec<Vec<f64>> {
    let full = format!("{}/tests/data/{}", env!("CARGO_MANIFEST_DIR"), path);
    let text = std::fs::read_to_string(&full).unwrap_or_else(|e| panic!("{full}: {e}"));
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .skip(1)
        .map(|l| l.split(',').map(|v| v.trim().parse::<f64>().expect("number")).collect())
        .collect()
}

/// Running max/RMS of relative errors with the worst row.
#[derive(Debug, Default)]
pub struct ErrStats {
    pub name: String,
    pub max: f64,
    pub sum2: f64,
    pub n: usize,
    pub worst: String,
}

impl ErrStats {
    pub fn new(name: &str) -> Self {
        Self { name: name.to_string(), ..Default::default() }
    }
    /// Record relative error |got - want| / max(|want|, floor).
    pub fn add(&mut self, got: f64, want: f64, floor: f64, row: &str) -> f64 {
        let e = (got - want).abs() / want.abs().max(floor);
        assert!(e.is_finite(), "{}: non-finite error at {row}: got {got}, want {want}", self.name);
        self.sum2 += e * e;
        self.n += 1;
        if e >= self.max {
            self.max = e;
            self.worst = format!("{row}: got {got:e}, want {want:e}");
        }
        e
    }
    pub fn rms(&self) -> f64 {
        (self.sum2 / self.n.max(1) as f64).sqrt()
    }
    /// Print and assert max <= tol.
    pub fn check(&self, tol: f64) {
        println!(
            "[{}] n = {}, max rel err = {:.3e}, rms = {:.3e}, worst: {}",
            self.name,
            self.n,
            self.max,
            self.rms(),
            self.worst
        );
        assert!(self.n > 0, "{}: nothing compared", self.name);
        assert!(self.max <= tol, "{}: max error {:.3e} > tol {:.1e}", self.name, self.max, tol);
    }
}
