//! The parametric cubic smoothing spline through a profile's points.
//!
//! A profile is a plane curve given by points $\mathbf P_i = (y_i, z_i)$, $i = 0\dots n-1$.
//! It is parametrised by the cumulative chord length $t_0 = 0$,
//! $t_{i+1} = t_i + |\mathbf P_{i+1} - \mathbf P_i|$, and each coordinate $c \in \{y, z\}$ is
//! the natural cubic spline $f_c(t)$ that minimises (Reinsch 1967, *Numer. Math.* 10;
//! Green & Silverman 1994, *Nonparametric Regression and Generalized Linear Models*, §2.3)
//! $$\sum_{i} \big(c_i - f_c(t_i)\big)^2 + \alpha \int \big(f_c''(t)\big)^2\,dt .$$
//! With $h_i = t_{i+1} - t_i$, the knot values $\mathbf g$ and the second derivatives
//! $\boldsymbol\gamma$ at the interior knots ($\gamma_0 = \gamma_{n-1} = 0$: natural) satisfy
//! $Q^{\mathsf T}\mathbf g = R\boldsymbol\gamma$, where $Q$ ($n\times(n-2)$) has the entries
//! $1/h_{j-1}$, $-1/h_{j-1} - 1/h_j$, $1/h_j$ in column $j$ and $R$ is tridiagonal with
//! $R_{jj} = (h_{j-1} + h_j)/3$, $R_{j,j+1} = h_j/6$; the minimiser solves the pentadiagonal
//! symmetric positive definite system
//! $$(R + \alpha Q^{\mathsf T}Q)\,\boldsymbol\gamma = Q^{\mathsf T}\mathbf c,\qquad
//! \mathbf g = \mathbf c - \alpha Q\boldsymbol\gamma .$$
//! $\alpha = 0$ gives the interpolating natural cubic spline (twice continuously
//! differentiable: the curvature, which the contact gap depends on, is continuous).
//!
//! **The smoothing length.** On points spaced $h$ apart the sum approximates
//! $h^{-1}\int(c - f)^2\,dt$, so the smoothing spline passes a sinusoid of wavelength $L$
//! with the gain $1/(1 + \alpha h(2\pi/L)^4)$ (per Fourier mode the Euler-Lagrange equation
//! is $f - c + \alpha h f^{(4)} = 0$; Silverman 1984, *Ann. Statist.* 12, on the spline's
//! equivalent kernel): the gain is one half at $L_c = 2\pi(\alpha h)^{1/4}$. The caller gives
//! $L_c$ (the smoothing length, m), and $\alpha = (L_c/2\pi)^4/\bar h$ with $\bar h$ the mean
//! point spacing. Features much longer than $L_c$ pass unchanged, measurement noise much
//! shorter is removed.

/// A parametric natural cubic (smoothing) spline $t \mapsto (y(t), z(t))$.
#[derive(Debug, Clone, PartialEq)]
pub struct ParametricSpline {
    t: Vec<f64>,
    /// Interval of parameter `m * bucket` (a lookup table, so evaluation does not search).
    buckets: Vec<u32>,
    bucket: f64,
    /// Knot values of y and z.
    g: [Vec<f64>; 2],
    /// Second derivatives of y and z at the knots.
    c2: [Vec<f64>; 2],
}

/// A point of the curve with its first and second derivatives in $t$.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurvePoint {
    /// $(y, z)$.
    pub p: [f64; 2],
    /// $(y', z')$.
    pub d1: [f64; 2],
    /// $(y'', z'')$.
    pub d2: [f64; 2],
}

impl ParametricSpline {
    /// The smoothing spline of the points `(y[i], z[i])` (at least 3, consecutive points
    /// distinct) with penalty weight $\alpha \ge 0$ (module docs; [`alpha_for_length`]).
    ///
    /// # Panics
    /// If fewer than three points are given or two consecutive points coincide: callers
    /// (the profile reader) have checked both.
    #[must_use]
    pub fn new(y: &[f64], z: &[f64], alpha: f64) -> Self {
        let n = y.len();
        assert!(n >= 3 && z.len() == n, "a spline needs at least 3 points");
        let mut t = Vec::with_capacity(n);
        t.push(0.0);
        for i in 1..n {
            let d = (y[i] - y[i - 1]).hypot(z[i] - z[i - 1]);
            assert!(d > 0.0, "consecutive profile points coincide");
            t.push(t[i - 1] + d);
        }
        let (gy, cy) = fit(&t, y, alpha);
        let (gz, cz) = fit(&t, z, alpha);
        let bucket = t[n - 1] / (n - 1) as f64;
        let mut buckets = Vec::with_capacity(n + 1);
        let mut i = 0usize;
        for m in 0..=n {
            let u = m as f64 * bucket;
            while i + 2 < n && t[i + 1] <= u {
                i += 1;
            }
            buckets.push(i as u32);
        }
        Self { t, buckets, bucket, g: [gy, gz], c2: [cy, cz] }
    }

    /// Parameter range $[t_0, t_{n-1}]$ (chord length of the data, m).
    #[must_use]
    pub fn range(&self) -> (f64, f64) {
        (self.t[0], self.t[self.t.len() - 1])
    }

    /// Knot parameters $t_i$.
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        &self.t
    }

    /// The fitted knot values (equal to the data when $\alpha = 0$).
    #[must_use]
    pub fn knot_values(&self) -> (&[f64], &[f64]) {
        (&self.g[0], &self.g[1])
    }

    /// The interval $i$ with $t_i \le u < t_{i+1}$ (clamped to the first and last).
    #[must_use]
    pub fn interval(&self, u: f64) -> usize {
        let n = self.t.len();
        if u.is_nan() || u <= 0.0 {
            return 0;
        }
        let m = (u / self.bucket) as usize;
        if m >= self.buckets.len() {
            return n - 2;
        }
        let mut i = self.buckets[m] as usize;
        while i + 2 < n && self.t[i + 1] <= u {
            i += 1;
        }
        i
    }

    /// The curve and its derivatives at $u$; beyond the ends the curve continues as its
    /// end tangent (the natural spline's zero end curvature makes this the $C^2$ extension).
    #[must_use]
    pub fn eval(&self, u: f64) -> CurvePoint {
        self.eval_in(self.interval(u), u)
    }

    /// As [`ParametricSpline::eval`] on a known interval `i` (no search).
    #[must_use]
    pub fn eval_in(&self, i: usize, u: f64) -> CurvePoint {
        let (t0, t1) = (self.t[i], self.t[i + 1]);
        let h = t1 - t0;
        let mut out = CurvePoint { p: [0.0; 2], d1: [0.0; 2], d2: [0.0; 2] };
        // Beyond the ends: linear continuation from the end point.
        let (lo, hi) = self.range();
        let (uu, ext) = if u < lo {
            (lo, u - lo)
        } else if u > hi {
            (hi, u - hi)
        } else {
            (u, 0.0)
        };
        let a = (t1 - uu) / h;
        let b = 1.0 - a;
        for c in 0..2 {
            let (g0, g1) = (self.g[c][i], self.g[c][i + 1]);
            let (k0, k1) = (self.c2[c][i], self.c2[c][i + 1]);
            let p = a * g0 + b * g1 + ((a * a * a - a) * k0 + (b * b * b - b) * k1) * h * h / 6.0;
            let d1 = (g1 - g0) / h - (3.0 * a * a - 1.0) / 6.0 * h * k0
                + (3.0 * b * b - 1.0) / 6.0 * h * k1;
            let d2 = a * k0 + b * k1;
            if ext == 0.0 {
                out.p[c] = p;
                out.d1[c] = d1;
                out.d2[c] = d2;
            } else {
                out.p[c] = p + ext * d1;
                out.d1[c] = d1;
                out.d2[c] = 0.0;
            }
        }
        out
    }
}

/// $\alpha = (L_c/2\pi)^4/\bar h$ for the smoothing length $L_c$ (m) and mean point spacing
/// $\bar h$ (module docs); $L_c = 0$ gives $\alpha = 0$ (interpolation).
#[must_use]
pub fn alpha_for_length(smoothing_length: f64, mean_spacing: f64) -> f64 {
    let r = smoothing_length / (2.0 * std::f64::consts::PI);
    r * r * r * r / mean_spacing
}

/// Knot values and second derivatives of one coordinate (module docs).
fn fit(t: &[f64], c: &[f64], alpha: f64) -> (Vec<f64>, Vec<f64>) {
    let n = t.len();
    let h: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
    let m = n - 2;
    // Column j (interior knot j = 1..n-2, unknown index j-1) of Q has the entries
    // qa = 1/h_{j-1} (row j-1), qb = -1/h_{j-1} - 1/h_j (row j), qc = 1/h_j (row j+1).
    let qa = |j: usize| 1.0 / h[j - 1];
    let qb = |j: usize| -1.0 / h[j - 1] - 1.0 / h[j];
    let qc = |j: usize| 1.0 / h[j];
    // Bands of A = R + alpha Q^T Q: d0 (diagonal), d1 (first), d2 (second off-diagonal).
    let mut d0 = vec![0.0; m];
    let mut d1 = vec![0.0; m];
    let mut d2 = vec![0.0; m];
    let mut rhs = vec![0.0; m];
    for k in 0..m {
        let j = k + 1;
        d0[k] = (h[j - 1] + h[j]) / 3.0 + alpha * (qa(j) * qa(j) + qb(j) * qb(j) + qc(j) * qc(j));
        if k + 1 < m {
            d1[k] = h[j] / 6.0 + alpha * (qb(j) * qa(j + 1) + qc(j) * qb(j + 1));
        }
        if k + 2 < m {
            d2[k] = alpha * qc(j) * qa(j + 2);
        }
        rhs[k] = qa(j) * c[j - 1] + qb(j) * c[j] + qc(j) * c[j + 1];
    }
    let gamma_inner = solve_penta(&d0, &d1, &d2, &rhs);
    let mut gamma = vec![0.0; n];
    gamma[1..n - 1].copy_from_slice(&gamma_inner);
    let mut g = c.to_vec();
    if alpha > 0.0 {
        for i in 0..n {
            // (Q gamma)_i from the columns j = i-1, i, i+1 that are interior.
            let mut qg = 0.0;
            if i >= 2 {
                qg += qc(i - 1) * gamma[i - 1];
            }
            if i >= 1 && i <= n - 2 {
                qg += qb(i) * gamma[i];
            }
            if i < n - 2 {
                qg += qa(i + 1) * gamma[i + 1];
            }
            g[i] = c[i] - alpha * qg;
        }
    }
    (g, gamma)
}

/// Solve the symmetric pentadiagonal system with diagonal `d0`, first and second
/// off-diagonals `d1`, `d2` by the banded $LDL^{\mathsf T}$ factorisation (the matrix is
/// positive definite, so no pivoting).
fn solve_penta(d0: &[f64], d1: &[f64], d2: &[f64], b: &[f64]) -> Vec<f64> {
    let m = d0.len();
    // L has unit diagonal and sub-diagonals l1 (i, i-1), l2 (i, i-2).
    let mut d = vec![0.0; m];
    let mut l1 = vec![0.0; m];
    let mut l2 = vec![0.0; m];
    for i in 0..m {
        // A(i, i-2) = l2_i d_{i-2}
        if i >= 2 {
            l2[i] = d2[i - 2] / d[i - 2];
        }
        // A(i, i-1) = l1_i d_{i-1} + l2_i d_{i-2} l1_{i-1}
        if i >= 1 {
            let mut v = d1[i - 1];
            if i >= 2 {
                v -= l2[i] * d[i - 2] * l1[i - 1];
            }
            l1[i] = v / d[i - 1];
        }
        let mut v = d0[i];
        if i >= 1 {
            v -= l1[i] * l1[i] * d[i - 1];
        }
        if i >= 2 {
            v -= l2[i] * l2[i] * d[i - 2];
        }
        d[i] = v;
    }
    let mut x = b.to_vec();
    for i in 0..m {
        if i >= 1 {
            x[i] -= l1[i] * x[i - 1];
        }
        if i >= 2 {
            x[i] -= l2[i] * x[i - 2];
        }
    }
    for i in 0..m {
        x[i] /= d[i];
    }
    for i in (0..m).rev() {
        if i + 1 < m {
            x[i] -= l1[i + 1] * x[i + 1];
        }
        if i + 2 < m {
            x[i] -= l2[i + 2] * x[i + 2];
        }
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The interpolating spline reproduces a cubic in the interior only approximately
    /// (natural ends), but a straight line exactly, and passes through the data.
    #[test]
    fn interpolates_and_reproduces_lines() {
        let y: Vec<f64> = (0..20).map(|i| f64::from(i) * 0.5).collect();
        let z: Vec<f64> = y.iter().map(|v| 2.0 * v - 1.0).collect();
        let s = ParametricSpline::new(&y, &z, 0.0);
        let (_, hi) = s.range();
        for k in 0..=100 {
            let u = hi * f64::from(k) / 100.0;
            let p = s.eval(u);
            assert!((p.p[1] - (2.0 * p.p[0] - 1.0)).abs() < 1e-12);
            assert!(p.d2[0].abs() < 1e-12 && p.d2[1].abs() < 1e-12);
        }
        for (i, &u) in s.knots().iter().enumerate() {
            let p = s.eval(u);
            assert!((p.p[0] - y[i]).abs() < 1e-12 && (p.p[1] - z[i]).abs() < 1e-12);
        }
    }

    /// The pentadiagonal solver against a dense solve of a random SPD band matrix.
    #[test]
    fn penta_solver_matches_dense() {
        let m = 9;
        let d0: Vec<f64> = (0..m).map(|i| 4.0 + 0.1 * i as f64).collect();
        let d1: Vec<f64> = (0..m).map(|i| 0.5 - 0.03 * i as f64).collect();
        let d2: Vec<f64> = (0..m).map(|i| 0.2 + 0.01 * i as f64).collect();
        let b: Vec<f64> = (0..m).map(|i| (i as f64).sin()).collect();
        let x = solve_penta(&d0, &d1, &d2, &b);
        for i in 0..m {
            let mut r = d0[i] * x[i];
            if i >= 1 {
                r += d1[i - 1] * x[i - 1];
            }
            if i + 1 < m {
                r += d1[i] * x[i + 1];
            }
            if i >= 2 {
                r += d2[i - 2] * x[i - 2];
            }
            if i + 2 < m {
                r += d2[i] * x[i + 2];
            }
            assert!((r - b[i]).abs() < 1e-13, "row {i}: {r} vs {}", b[i]);
        }
    }

    /// The smoothing gain: a sinusoid of wavelength L_c on uniform points keeps about half
    /// its amplitude (module docs), a ten times longer one almost all of it.
    #[test]
    fn smoothing_length_halves_the_amplitude() {
        let h = 1e-4;
        let lc = 2e-3;
        let n = 2001;
        for (wave, expected, tol) in [(lc, 0.5, 0.05), (10.0 * lc, 1.0, 0.01)] {
            let y: Vec<f64> = (0..n).map(|i| i as f64 * h).collect();
            // Small amplitude so the chord length stays close to y.
            let amp = 1e-7;
            let z: Vec<f64> =
                y.iter().map(|v| amp * (2.0 * std::f64::consts::PI * v / wave).sin()).collect();
            let s = ParametricSpline::new(&y, &z, alpha_for_length(lc, h));
            let (_, gz) = s.knot_values();
            // Amplitude in the middle (away from the ends).
            let mid = &gz[n / 4..3 * n / 4];
            let a = mid.iter().fold(0.0f64, |m, v| m.max(v.abs())) / amp;
            assert!((a - expected).abs() < tol, "wave {wave}: gain {a}, expected {expected}");
        }
    }
}
