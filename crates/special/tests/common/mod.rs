//! Shared test helpers: tolerances, golden-table loading, error statistics.
#![allow(dead_code)] // each test binary uses a different subset

/// Tolerances of this crate's tests, each with its reason.
pub mod tol {
    /// The accuracy contract of the crate: relative error at most 1e-14 (about 45 ulp)
    /// on the documented domains. Golden values are mpmath at 60 digits rounded once to
    /// f64 (0.5 ulp), so the measured error is the function's own to within 0.5 ulp.
    pub const REL: f64 = 1e-14;
    /// Identities evaluated in f64 (Wronskian, Legendre relation, recurrence, reflection)
    /// combine several function values; they are held to the same 1e-14 contract as the
    /// functions themselves because each term is O(1) and there is no cancellation beyond a
    /// factor of about 3 in the Legendre relation at the ends of the range used.
    pub const IDENTITY: f64 = 1e-14;
    /// $\Gamma(n)=(n-1)!$ for $n\le 23$ is an exact f64 integer; the products in the
    /// recurrence are exact and only the final exp or Stirling step rounds, so 2 ulp.
    pub const FACTORIAL: f64 = 2.0 * f64::EPSILON;
}

/// One golden row: input, reference value.
pub type Row = (f64, f64);

/// Reads `tests/data/<name>.tsv`: '#' lines are headers, others `x<TAB>value`.
pub fn load(name: &str) -> Vec<Row> {
    let path = format!("{}/tests/data/{name}.tsv", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let mut it = l.split('\t');
            let x: f64 = it.next().unwrap().trim().parse().unwrap();
            let v: f64 = it.next().unwrap().trim().parse().unwrap();
            (x, v)
        })
        .collect()
}

/// Relative error, measured against `max(|ref|, f64::MIN_POSITIVE)` so that a subnormal
/// reference is judged by its absolute error on the scale of the smallest normal number.
pub fn rel_err(got: f64, want: f64) -> f64 {
    if got == want {
        return 0.0;
    }
    if !got.is_finite() {
        return f64::INFINITY;
    }
    (got - want).abs() / want.abs().max(f64::MIN_POSITIVE)
}

/// Error statistics over a set of rows.
#[derive(Debug, Clone, Copy)]
pub struct Stats {
    /// Number of rows.
    pub n: usize,
    /// Largest relative error.
    pub max: f64,
    /// Root mean square of the relative errors.
    pub rms: f64,
    /// Row with the largest error: (x, got, want).
    pub worst: (f64, f64, f64),
}

/// Evaluates `f` on every row and returns the statistics (also printed).
pub fn measure(label: &str, rows: &[Row], f: impl Fn(f64) -> f64) -> Stats {
    let mut max = 0.0_f64;
    let mut sum2 = 0.0;
    let mut worst = (f64::NAN, f64::NAN, f64::NAN);
    for &(x, want) in rows {
        let got = f(x);
        let e = rel_err(got, want);
        sum2 += if e.is_finite() { e * e } else { f64::INFINITY };
        let e = if e.is_nan() { f64::INFINITY } else { e };
        if e > max || worst.0.is_nan() {
            max = e;
            worst = (x, got, want);
        }
    }
    let rms = (sum2 / rows.len() as f64).sqrt();
    let eps = f64::EPSILON;
    println!(
        "{label:>20}: n = {:4}, max = {:.2e} ({:.1} ulp), rms = {:.2e} ({:.2} ulp), worst x = {:e} got {:e} want {:e}",
        rows.len(),
        max,
        max / eps,
        rms,
        rms / eps,
        worst.0,
        worst.1,
        worst.2
    );
    Stats { n: rows.len(), max, rms, worst }
}

/// Measures `f` on the golden table `name` and asserts the crate's 1e-14 contract.
pub fn check_table(name: &str, f: impl Fn(f64) -> f64) -> Stats {
    let rows = load(name);
    assert!(rows.len() >= 100, "{name}: only {} rows", rows.len());
    let s = measure(name, &rows, f);
    assert!(
        s.max <= tol::REL,
        "{name}: max relative error {:e} at x = {:e} (got {:e}, want {:e})",
        s.max,
        s.worst.0,
        s.worst.1,
        s.worst.2
    );
    s
}
