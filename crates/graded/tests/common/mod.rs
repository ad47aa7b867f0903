//! Shared test helpers: tolerances (with reasons) and the reference-data reader.
#![allow(dead_code)]

/// Tolerances of this crate's tests, each with its reason.
pub mod tol {
    /// Stresses against the mpmath reference at y/a >= 1e-3: the target (1e-10
    /// relative). The quadrature runs at `Accuracy::new(1e-12)`.
    pub const STRESS_REL: f64 = 1e-10;
    /// Near-surface limit sigma_yy -> -p, sigma_xy -> -q at y/a = 1e-6 (issue target); the
    /// physical deviation is O(y q'(x)) ~ 1e-6 * mu * x/(a - x), so it is checked for
    /// |x| <= a/2.
    pub const NEAR_SURFACE_REL: f64 = 1e-6;
    /// Near-surface stresses against mpmath at y/a = 1e-6, including the contact edges: the
    /// rounding of x - s at that scale costs ~1e-16 * a / y = 1e-10.
    pub const NEAR_SURFACE_REF_REL: f64 = 1e-8;
    /// Equilibrium: integral of sigma over x equals -P (or -Q) (issue target).
    pub const EQUILIBRIUM_REL: f64 = 1e-10;
    /// Table 1 of seed 000, quoted to 7 significant digits: half a unit in the last digit.
    pub const TABLE1_BETA_ABS: f64 = 5e-7;
    /// Homogeneous limit at k = 1e-6: the graded forms differ from Flamant/Hertz by O(k).
    pub const HOMOGENEOUS_REL: f64 = 1e-6;
    /// Outside the contact the graded kernels differ from the homogeneous ones by
    /// k ln|x - s| + O(k) (physics, not numerics): the relative difference is bounded by
    /// this coefficient times k for |x - s| <= 3 (lengths of order one).
    pub const HOMOGENEOUS_O_K: f64 = 2.0;
    /// Spectral relation of FORMULAS.md A4 (closed form): issue target 1e-12.
    pub const SPECTRAL_REL: f64 = 1e-12;
    /// Surface integrals and relative approach against mpmath: limited by f64 (a few ulps
    /// times condition numbers ~ 100).
    pub const SURFACE_REL: f64 = 1e-12;
    /// The relative approach at tiny k: the connection formula of 2F1 costs ~eps/k.
    pub const APPROACH_SMALL_K_REL: f64 = 1e-9;
    /// Speed-test grid accuracy (issue target).
    pub const GRID_REL: f64 = 1e-8;
}

/// Read a whitespace-separated numeric table, skipping `#` comment lines.
pub fn read_table(name: &str) -> Vec<Vec<f64>> {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.lines()
        .filter(|l| !l.trim_start().starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            l.split_whitespace()
                .map(|t| t.parse::<f64>().unwrap_or_else(|e| panic!("{t}: {e}")))
                .collect()
        })
        .collect()
}

/// Relative error |got - want| / |want| (absolute if want == 0).
pub fn rel(got: f64, want: f64) -> f64 {
    if want == 0.0 {
        got.abs()
    } else {
        ((got - want) / want).abs()
    }
}

/// Running max/RMS error with the worst row.
#[derive(Debug, Default)]
pub struct ErrStats {
    pub max: f64,
    pub sum_sq: f64,
    pub n: usize,
    pub worst: String,
}

impl ErrStats {
    pub fn add(&mut self, e: f64, row: impl FnOnce() -> String) {
        assert!(e.is_finite(), "non-finite error");
        self.n += 1;
        self.sum_sq += e * e;
        if e > self.max || self.n == 1 {
            self.max = e;
            self.worst = row();
        }
    }
    pub fn rms(&self) -> f64 {
        (self.sum_sq / self.n.max(1) as f64).sqrt()
    }
    pub fn report(&self, what: &str) {
        println!(
            "{what}: n = {}, max rel err = {:.3e}, rms = {:.3e}, worst row: {}",
            self.n,
            self.max,
            self.rms(),
            self.worst
        );
    }
}
