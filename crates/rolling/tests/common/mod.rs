//! Shared test helpers: tolerances (with reasons), reference-table reader, error statistics.
#![allow(dead_code)]

/// Tolerances, each with its reason.
pub mod tol {
    /// Issue 4 target for l, d, m, C2, Q, M1 against the mpmath reference. The solver's
    /// forms are cancellation-free and the roots converge to a few ulps; what remains is
    /// the conditioning of m (about l/m) and of Q near zero creep, both moderate in the table.
    pub const REFERENCE_REL: f64 = 1e-10;
    /// Issue 4 target for alpha = beta (1 + 1e-12) against Carter: the viscoelastic
    /// corrections are O(1e-12) relative, plus rounding.
    pub const ELASTIC_LIMIT_REL: f64 = 1e-9;
    /// alpha = beta exactly is solved as Carter: identical up to the rounding of l_H = 2a.
    pub const ELASTIC_EXACT_REL: f64 = 4.0 * f64::EPSILON;
    /// Issue 4 target for the quadratures of eqs 12/13: int sigma = P, int tau = Q,
    /// int x sigma = M1.
    pub const RESULTANT_REL: f64 = 1e-9;
    /// Pointwise pressure/shear in the near-elastic limit against Hertz/Carter, relative to
    /// the peak pressure: the viscoelastic terms are O(1e-12), the quadrature asked for 1e-12.
    pub const POINTWISE_ELASTIC: f64 = 1e-9;
    /// Carter's closed forms against quadrature of the same closed forms.
    pub const CARTER_QUAD_REL: f64 = 1e-11;
}

/// One row of tests/data/goryacheva_reference.txt.
#[derive(Debug, Clone)]
pub struct RefRow {
    pub material: String,
    pub e: f64,
    pub nu: f64,
    pub r: f64,
    pub p: f64,
    pub rho: f64,
    pub alpha: f64,
    pub beta: f64,
    pub w: f64,
    pub delta: f64,
    pub l: f64,
    pub d: f64,
    pub m: f64,
    pub c2: f64,
    pub q: f64,
    pub m1: f64,
    pub x1: f64,
    pub y1: f64,
}

/// Parse the reference table (mpmath, mp.dps = 50; see scripts/rolling_reference.py).
pub fn reference_rows() -> Vec<RefRow> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/goryacheva_reference.txt");
    let text =
        std::fs::read_to_string(path).expect("reference table (run scripts/rolling_reference.py)");
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|line| {
            let f: Vec<&str> = line.split_whitespace().collect();
            assert_eq!(f.len(), 18, "bad row: {line}");
            let v: Vec<f64> = f[1..].iter().map(|s| s.parse::<f64>().unwrap()).collect();
            RefRow {
                material: f[0].to_string(),
                e: v[0],
                nu: v[1],
                r: v[2],
                p: v[3],
                rho: v[4],
                alpha: v[5],
                beta: v[6],
                w: v[7],
                delta: v[8],
                l: v[9],
                d: v[10],
                m: v[11],
                c2: v[12],
                q: v[13],
                m1: v[14],
                x1: v[15],
                y1: v[16],
            }
        })
        .collect()
}

/// Max and RMS of a list of errors, with the index of the worst.
pub struct Stats {
    pub max: f64,
    pub rms: f64,
    pub worst: usize,
    pub n: usize,
}

impl Stats {
    pub fn new() -> Self {
        Stats { max: 0.0, rms: 0.0, worst: 0, n: 0 }
    }
    pub fn add(&mut self, i: usize, err: f64) {
        assert!(err.is_finite(), "non-finite error at row {i}");
        if err > self.max {
            self.max = err;
            self.worst = i;
        }
        self.rms += err * err;
        self.n += 1;
    }
    pub fn rms(&self) -> f64 {
        (self.rms / self.n.max(1) as f64).sqrt()
    }
}

/// Relative error with an absolute floor `floor` for reference values near zero.
pub fn rel_err(got: f64, want: f64) -> f64 {
    (got - want).abs() / want.abs()
}
