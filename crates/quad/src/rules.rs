//! Fixed (non-adaptive) Gauss rules, planned once and applied many times.
//!
//! Every rule stores its $n$ nodes $t_i$ and weights $w_i$ on the reference interval $[-1,1]$
//! together with a *companion* rule of the same family with $m = \lfloor n/2 \rfloor$ nodes
//! ($m = 0$, i.e. the value $0$, when $n = 1$). [`Rule::integrate`] evaluates both and reports
//! $$\text{error} = |Q_n - Q_m| + 50\,\varepsilon \sum_i |w_i f(x_i)|\,s,$$
//! where $s$ is the interval scale factor. The difference is an estimate of the error of the
//! *coarser* rule, so for integrands on which Gauss rules converge it over-estimates the error
//! of $Q_n$: the estimate is honest at the price of $n + m$ evaluations. [`Rule::sum`] applies
//! the $n$-point rule alone ($n$ evaluations, no estimate) for callers that have verified the
//! order elsewhere.
//!
//! Reference: Gautschi, *Orthogonal Polynomials: Computation and Approximation* (2004),
//! §1.4 (Gauss rules), §3.1.1 (Golub–Welsch).

use std::f64::consts::PI;

use crate::gamma::jacobi_mass;
use crate::types::checked;
use crate::{Error, Estimate};

/// Common interface of the fixed rules.
pub trait Rule {
    /// Reference nodes on $[-1,1]$, ascending.
    fn nodes(&self) -> &[f64];
    /// Reference weights, matching [`Rule::nodes`].
    fn weights(&self) -> &[f64];
    /// Apply the rule and its companion on the physical interval $\lbrack a,b\rbrack$, with the
    /// honest error estimate described in the [module docs](self).
    ///
    /// # Errors
    /// [`Error::NonFinite`] if the integrand is NaN or infinite at a node;
    /// [`Error::InvalidInterval`] for unusable ends (see each rule).
    fn integrate<F: FnMut(f64) -> f64>(&self, f: F, a: f64, b: f64) -> Result<Estimate, Error>;
    /// Apply the $n$-point rule only (no error estimate, $n$ evaluations).
    ///
    /// # Errors
    /// As [`Rule::integrate`].
    fn sum<F: FnMut(f64) -> f64>(&self, f: F, a: f64, b: f64) -> Result<f64, Error>;
}

/// Nodes and weights of one rule and of its companion.
#[derive(Debug, Clone, PartialEq)]
struct Pair {
    nodes: Vec<f64>,
    weights: Vec<f64>,
    lo_nodes: Vec<f64>,
    lo_weights: Vec<f64>,
}

/// $\sum_i w_i f(c + h t_i)$ and $\sum_i |w_i f|$.
fn apply(
    nodes: &[f64],
    weights: &[f64],
    f: &mut impl FnMut(f64) -> Result<f64, Error>,
    c: f64,
    h: f64,
) -> Result<(f64, f64), Error> {
    let mut s = 0.0;
    let mut sa = 0.0;
    for (&t, &w) in nodes.iter().zip(weights) {
        let v = w * f(c + h * t)?;
        s += v;
        sa += v.abs();
    }
    Ok((s, sa))
}

impl Pair {
    fn estimate(
        &self,
        f: &mut impl FnMut(f64) -> Result<f64, Error>,
        c: f64,
        h: f64,
        scale: f64,
    ) -> Result<Estimate, Error> {
        let (q, qa) = apply(&self.nodes, &self.weights, f, c, h)?;
        let (ql, _) = apply(&self.lo_nodes, &self.lo_weights, f, c, h)?;
        let value = scale * q;
        // 50 eps (QUADPACK's floor): computed nodes and weights carry a few ulps each.
        let error = scale.abs() * ((q - ql).abs() + 50.0 * f64::EPSILON * qa);
        Ok(Estimate { value, error, evals: self.nodes.len() + self.lo_nodes.len() })
    }
}

// ---------------------------------------------------------------------------------------------
// Gauss–Legendre

/// $P_n(\cos\theta)$ and $P_{n-1}(\cos\theta)$ by the three-term recurrence written for
/// differences $d_j = P_j - P_{j-1}$ with $u = 1-\cos\theta = 2\sin^2(\theta/2)$ (Reinsch's
/// modification): $(j+1)d_{j+1} = -(2j+1)u P_j + j d_j$. Accurate for $\cos\theta \ge 0$, in
/// particular near $x = 1$ where forming $x$ itself would lose the digits of $1-x$.
fn legendre_theta(n: usize, u: f64) -> (f64, f64) {
    let mut p = 1.0; // P_j
    let mut d = 0.0; // P_j - P_{j-1}
    let mut pm = 1.0; // P_{j-1}
    for j in 0..n {
        let jf = j as f64;
        d = (-(2.0 * jf + 1.0) * u * p + jf * d) / (jf + 1.0);
        pm = p;
        p += d;
    }
    (p, pm)
}

/// Gauss–Legendre nodes and weights on $[-1,1]$, ascending.
///
/// Newton's method in the angle $\theta$ ($x = \cos\theta$) on the recurrence above, started
/// from Tricomi's approximation $x_k \approx (1 - \tfrac{1}{8n^2} + \tfrac{1}{8n^3})
/// \cos\tfrac{(4k-1)\pi}{4n+2}$; weights
/// $$w_k = \frac{2}{(1-x_k^2)P_n'(x_k)^2} = \frac{2\sin^2\theta_k}{n^2\,(P_{n-1} - x_kP_n)^2},$$
/// computed from $\theta_k$ so that they keep full relative accuracy near $\pm1$.
/// Cost $O(n^2)$ (about 5 ms at $n = 1000$).
fn legendre(n: usize) -> Result<(Vec<f64>, Vec<f64>), Error> {
    let mut xs = vec![0.0; n];
    let mut ws = vec![0.0; n];
    let nf = n as f64;
    let half = n.div_ceil(2);
    for k in 1..=half {
        let (theta, u, s) = if n % 2 == 1 && k == half {
            (PI / 2.0, 1.0, 1.0)
        } else {
            let t0 = (4.0 * k as f64 - 1.0) * PI / (4.0 * nf + 2.0);
            let x0 = (1.0 - 1.0 / (8.0 * nf * nf) + 1.0 / (8.0 * nf * nf * nf)) * t0.cos();
            let mut th = x0.acos();
            let mut converged = false;
            // Quadratic convergence: once a step is below 1e-9 relative, one more step lands
            // at rounding level.
            let mut polish = false;
            for _ in 0..40 {
                let u = 2.0 * (0.5 * th).sin().powi(2);
                let (p, pm) = legendre_theta(n, u);
                let x = 1.0 - u;
                let dth = p * th.sin() / (nf * (pm - x * p));
                th += dth;
                if polish {
                    converged = true;
                    break;
                }
                polish = dth.abs() <= 1e-9 * th;
            }
            if !converged || !th.is_finite() {
                return Err(Error::RuleConstruction { rule: "Gauss-Legendre", n });
            }
            (th, 2.0 * (0.5 * th).sin().powi(2), th.sin())
        };
        let (p, pm) = legendre_theta(n, u);
        let x = if n % 2 == 1 && k == half { 0.0 } else { theta.cos() };
        let w = 2.0 * s * s / (nf * nf * (pm - x * p).powi(2));
        // k-th largest node goes to position n - k (ascending order), its mirror to k - 1.
        xs[n - k] = x;
        ws[n - k] = w;
        xs[k - 1] = -x;
        ws[k - 1] = w;
    }
    // Sanity: strictly increasing nodes.
    if xs.windows(2).any(|p| p[0] >= p[1]) && n > 1 {
        return Err(Error::RuleConstruction { rule: "Gauss-Legendre", n });
    }
    Ok((xs, ws))
}

/// The $n$-point Gauss–Legendre rule,
/// $$\int_a^b f(x)\,dx \approx \frac{b-a}{2}\sum_{i=1}^n w_i\, f\!\Big(\frac{a+b}{2} + \frac{b-a}{2}t_i\Big),$$
/// exact for polynomials of degree $\le 2n-1$ (Gautschi 2004, §1.4.2). Nodes and weights are
/// accurate to a few units in the last place for any $n$ (tested against mpmath for
/// $n \le 1000$); construction costs $O(n^2)$.
///
/// `integrate(f, a, b)` accepts $a > b$ (giving $-\int_b^a$) and $a = b$ (zero); the ends must
/// be finite.
#[derive(Debug, Clone, PartialEq)]
pub struct GaussLegendre {
    pair: Pair,
}

impl GaussLegendre {
    /// Plan the $n$-point rule (and its $\lfloor n/2\rfloor$-point companion).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if $n = 0$.
    pub fn new(n: usize) -> Result<Self, Error> {
        if n == 0 {
            return Err(Error::OutOfDomain { name: "n", value: 0.0, allowed: ">= 1" });
        }
        let (nodes, weights) = legendre(n)?;
        let (lo_nodes, lo_weights) = if n >= 2 { legendre(n / 2)? } else { (vec![], vec![]) };
        Ok(GaussLegendre { pair: Pair { nodes, weights, lo_nodes, lo_weights } })
    }

    /// Number of nodes $n$.
    #[must_use]
    pub fn len(&self) -> usize {
        self.pair.nodes.len()
    }

    /// Always `false` (a rule has at least one node); present for clippy's `len_without_is_empty`.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.pair.nodes.is_empty()
    }
}

fn affine(a: f64, b: f64) -> Result<Option<(f64, f64)>, Error> {
    crate::types::check_finite_ends(a, b)?;
    if a == b {
        return Ok(None);
    }
    Ok(Some((0.5 * (a + b), 0.5 * (b - a))))
}

impl Rule for GaussLegendre {
    fn nodes(&self) -> &[f64] {
        &self.pair.nodes
    }
    fn weights(&self) -> &[f64] {
        &self.pair.weights
    }
    fn integrate<F: FnMut(f64) -> f64>(&self, f: F, a: f64, b: f64) -> Result<Estimate, Error> {
        let Some((c, h)) = affine(a, b)? else {
            return Ok(Estimate { value: 0.0, error: 0.0, evals: 0 });
        };
        self.pair.estimate(&mut checked(f), c, h, h)
    }
    fn sum<F: FnMut(f64) -> f64>(&self, f: F, a: f64, b: f64) -> Result<f64, Error> {
        let Some((c, h)) = affine(a, b)? else { return Ok(0.0) };
        Ok(h * apply(&self.pair.nodes, &self.pair.weights, &mut checked(f), c, h)?.0)
    }
}

// ---------------------------------------------------------------------------------------------
// Gauss–Jacobi

/// Eigenvalues of the symmetric tridiagonal matrix with diagonal `d` and off-diagonal `e`
/// (`e[i]` couples `i` and `i+1`; `e[n-1]` is ignored), by the implicit QL method with
/// Wilkinson shifts (Golub & Van Loan, *Matrix Computations*, §8.3). `d` is overwritten.
fn tridiagonal_eigenvalues(d: &mut [f64], e: &mut [f64]) -> bool {
    let n = d.len();
    if n == 0 {
        return true;
    }
    e[n - 1] = 0.0;
    for l in 0..n {
        let mut iter = 0;
        loop {
            let mut m = l;
            while m + 1 < n {
                let dd = d[m].abs() + d[m + 1].abs();
                if e[m].abs() <= f64::EPSILON * dd {
                    break;
                }
                m += 1;
            }
            if m == l {
                break;
            }
            iter += 1;
            if iter > 60 {
                return false;
            }
            let mut g = (d[l + 1] - d[l]) / (2.0 * e[l]);
            let mut r = g.hypot(1.0);
            g = d[m] - d[l] + e[l] / (g + r.copysign(g));
            let (mut s, mut c, mut p) = (1.0, 1.0, 0.0);
            let mut i = m;
            let mut deflated = false;
            while i > l {
                i -= 1;
                let f = s * e[i];
                let b = c * e[i];
                r = f.hypot(g);
                e[i + 1] = r;
                if r == 0.0 {
                    d[i + 1] -= p;
                    e[m] = 0.0;
                    deflated = true;
                    break;
                }
                s = f / r;
                c = g / r;
                g = d[i + 1] - p;
                r = (d[i] - g) * s + 2.0 * c * b;
                p = s * r;
                d[i + 1] = g + p;
                g = c * r - b;
            }
            if deflated {
                continue;
            }
            d[l] -= p;
            e[l] = g;
            e[m] = 0.0;
        }
    }
    true
}

/// Recurrence coefficients of the orthonormal Jacobi polynomials for the weight
/// $(1-t)^\alpha(1+t)^\beta$: diagonal $a_j$ ($j = 0..n-1$) and off-diagonal $b_j$ ($j = 1..n$,
/// stored at index $j-1$). Gautschi (2004), Table 1.1.
fn jacobi_coefficients(n: usize, alpha: f64, beta: f64) -> (Vec<f64>, Vec<f64>) {
    let ab = alpha + beta;
    let mut a = Vec::with_capacity(n);
    let mut b = Vec::with_capacity(n);
    for j in 0..n {
        let jf = j as f64;
        if j == 0 {
            a.push((beta - alpha) / (ab + 2.0));
        } else {
            let s = 2.0 * jf + ab;
            a.push((beta - alpha) * (beta + alpha) / (s * (s + 2.0)));
        }
    }
    for j in 1..=n {
        let jf = j as f64;
        let s = 2.0 * jf + ab;
        let b2 = if j == 1 {
            4.0 * (1.0 + alpha) * (1.0 + beta) / ((2.0 + ab).powi(2) * (3.0 + ab))
        } else {
            4.0 * jf * (jf + alpha) * (jf + beta) * (jf + ab) / (s * s * (s + 1.0) * (s - 1.0))
        };
        b.push(b2.sqrt());
    }
    (a, b)
}

/// Orthonormal $p_n(t)$, $p_n'(t)$ and $\sum_{j<n} p_j(t)^2$ (with $p_0 = 1$, i.e. for the
/// weight normalised to unit mass).
fn orthonormal_eval(t: f64, a: &[f64], b: &[f64]) -> (f64, f64, f64) {
    let n = a.len();
    let (mut p, mut pm) = (1.0, 0.0);
    let (mut dp, mut dpm) = (0.0, 0.0);
    let mut sum = 0.0;
    for j in 0..n {
        sum += p * p;
        let bj = if j == 0 { 0.0 } else { b[j - 1] };
        let pn = ((t - a[j]) * p - bj * pm) / b[j];
        let dpn = (p + (t - a[j]) * dp - bj * dpm) / b[j];
        pm = p;
        p = pn;
        dpm = dp;
        dp = dpn;
    }
    (p, dp, sum)
}

/// Gauss–Jacobi nodes and weights for $(1-t)^\alpha(1+t)^\beta$ on $[-1,1]$, ascending:
/// Golub–Welsch eigenvalues, one or two Newton steps on the orthonormal recurrence, and
/// Christoffel weights $w_i = \mu_0 / \sum_{j<n} p_j(t_i)^2$.
fn jacobi(n: usize, alpha: f64, beta: f64) -> Result<(Vec<f64>, Vec<f64>), Error> {
    let (a, b) = jacobi_coefficients(n, alpha, beta);
    let mut d = a.clone();
    let mut e: Vec<f64> = b.clone();
    if !tridiagonal_eigenvalues(&mut d, &mut e) {
        return Err(Error::RuleConstruction { rule: "Gauss-Jacobi", n });
    }
    d.sort_by(f64::total_cmp);
    let mu0 = jacobi_mass(alpha, beta);
    let mut ws = vec![0.0; n];
    for i in 0..n {
        // Newton polish, guarded so that a step never leaves the gap to the neighbours.
        let gap_lo = if i > 0 { d[i] - d[i - 1] } else { 1.0 + d[i] };
        let gap_hi = if i + 1 < n { d[i + 1] - d[i] } else { 1.0 - d[i] };
        let guard = 0.25 * gap_lo.min(gap_hi);
        let mut t = d[i];
        for _ in 0..3 {
            let (p, dp, _) = orthonormal_eval(t, &a, &b);
            if dp == 0.0 {
                break;
            }
            let step = p / dp;
            if step.is_nan() || step.abs() >= guard {
                break;
            }
            t -= step;
            if step.abs() <= f64::EPSILON * t.abs().max(f64::MIN_POSITIVE) {
                break;
            }
        }
        let (_, _, sum) = orthonormal_eval(t, &a, &b);
        d[i] = t;
        ws[i] = mu0 / sum;
    }
    if d.iter().chain(&ws).any(|v| !v.is_finite())
        || (n > 1 && d.windows(2).any(|p| p[0] >= p[1]))
        || d.iter().any(|&t| t.abs() >= 1.0)
    {
        return Err(Error::RuleConstruction { rule: "Gauss-Jacobi", n });
    }
    Ok((d, ws))
}

/// The $n$-point Gauss–Jacobi rule for the weight $(1-t)^\alpha(1+t)^\beta$, $\alpha,\beta>-1$,
/// applied on a physical interval:
/// $$\int_a^b f(x)\,(b-x)^\alpha(x-a)^\beta\,dx = h^{\alpha+\beta+1}\!\int_{-1}^1 f(c+ht)(1-t)^\alpha(1+t)^\beta\,dt
/// \approx h^{\alpha+\beta+1}\sum_i w_i f(c + h t_i),$$
/// $c = (a+b)/2$, $h = (b-a)/2$; exact when $f$ is a polynomial of degree $\le 2n-1$
/// (Gautschi 2004, §1.4; Golub & Welsch, Math. Comp. 23 (1969)). Note the convention: $\alpha$
/// is the exponent at the **right** end $b$, $\beta$ at the left end $a$.
///
/// Weights keep relative accuracy $\approx 10^{-16}/(1-|t_i|)$ near the ends (they are computed
/// at the rounded node); nodes are accurate to a few ulps. Construction costs $O(n^2)$.
/// `integrate` needs finite $a < b$.
#[derive(Debug, Clone, PartialEq)]
pub struct GaussJacobi {
    pair: Pair,
    alpha: f64,
    beta: f64,
}

impl GaussJacobi {
    /// Plan the rule.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if $n = 0$, or $\alpha \le -1$, or $\beta \le -1$ (or either
    /// is not finite).
    pub fn new(n: usize, alpha: f64, beta: f64) -> Result<Self, Error> {
        if n == 0 {
            return Err(Error::OutOfDomain { name: "n", value: 0.0, allowed: ">= 1" });
        }
        for (name, v) in [("alpha", alpha), ("beta", beta)] {
            if !(v.is_finite() && v > -1.0) {
                return Err(Error::OutOfDomain { name, value: v, allowed: "> -1, finite" });
            }
        }
        let (nodes, weights) = jacobi(n, alpha, beta)?;
        let (lo_nodes, lo_weights) =
            if n >= 2 { jacobi(n / 2, alpha, beta)? } else { (vec![], vec![]) };
        Ok(GaussJacobi { pair: Pair { nodes, weights, lo_nodes, lo_weights }, alpha, beta })
    }

    /// Exponent $\alpha$ at the right end.
    #[must_use]
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// Exponent $\beta$ at the left end.
    #[must_use]
    pub fn beta(&self) -> f64 {
        self.beta
    }

    /// Number of nodes $n$.
    #[must_use]
    pub fn len(&self) -> usize {
        self.pair.nodes.len()
    }

    /// Always `false`; present for clippy's `len_without_is_empty`.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.pair.nodes.is_empty()
    }

    fn scale(&self, a: f64, b: f64) -> Result<(f64, f64, f64), Error> {
        crate::types::check_ordered(a, b)?;
        let h = 0.5 * (b - a);
        Ok((0.5 * (a + b), h, h.powf(self.alpha + self.beta + 1.0)))
    }
}

/// The [`Rule`] impl shared by the weighted rules (Jacobi, Chebyshev): map $[a,b]$ to
/// $[-1,1]$ and multiply by the weight's scale factor from the rule's own `scale(a, b)`.
macro_rules! weighted_rule {
    ($t:ty) => {
        impl Rule for $t {
            fn nodes(&self) -> &[f64] {
                &self.pair.nodes
            }
            fn weights(&self) -> &[f64] {
                &self.pair.weights
            }
            fn integrate<F: FnMut(f64) -> f64>(
                &self,
                f: F,
                a: f64,
                b: f64,
            ) -> Result<Estimate, Error> {
                let (c, h, s) = self.scale(a, b)?;
                self.pair.estimate(&mut checked(f), c, h, s)
            }
            fn sum<F: FnMut(f64) -> f64>(&self, f: F, a: f64, b: f64) -> Result<f64, Error> {
                let (c, h, s) = self.scale(a, b)?;
                Ok(s * apply(&self.pair.nodes, &self.pair.weights, &mut checked(f), c, h)?.0)
            }
        }
    };
}

weighted_rule!(GaussJacobi);

// ---------------------------------------------------------------------------------------------
// Gauss–Chebyshev

/// Which Chebyshev weight.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChebyshevKind {
    /// $1/\sqrt{(b-x)(x-a)}$.
    First,
    /// $\sqrt{(b-x)(x-a)}$.
    Second,
}

fn chebyshev(n: usize, kind: ChebyshevKind) -> (Vec<f64>, Vec<f64>) {
    let nf = n as f64;
    let mut xs = Vec::with_capacity(n);
    let mut ws = Vec::with_capacity(n);
    // Ascending order: k runs from n down to 1. Nodes written as sines so that they are
    // exactly antisymmetric and the middle one is exactly 0.
    for k in (1..=n).rev() {
        let kf = k as f64;
        match kind {
            ChebyshevKind::First => {
                xs.push((PI * (nf - 2.0 * kf + 1.0) / (2.0 * nf)).sin());
                ws.push(PI / nf);
            }
            ChebyshevKind::Second => {
                xs.push((PI * (nf + 1.0 - 2.0 * kf) / (2.0 * (nf + 1.0))).sin());
                ws.push(PI / (nf + 1.0) * (kf * PI / (nf + 1.0)).sin().powi(2));
            }
        }
    }
    (xs, ws)
}

/// Gauss–Chebyshev rules in closed form (Abramowitz & Stegun 25.4.38–25.4.40):
///
/// first kind, $t_k = \cos\frac{(2k-1)\pi}{2n}$, $w_k = \pi/n$:
/// $$\int_a^b \frac{f(x)}{\sqrt{(b-x)(x-a)}}\,dx \approx \frac{\pi}{n}\sum_k f(c+ht_k);$$
/// second kind, $t_k = \cos\frac{k\pi}{n+1}$, $w_k = \frac{\pi}{n+1}\sin^2\frac{k\pi}{n+1}$:
/// $$\int_a^b f(x)\sqrt{(b-x)(x-a)}\,dx \approx h^2\sum_k w_k f(c+ht_k).$$
/// They are the Gauss–Jacobi rules with $\alpha=\beta=\mp\tfrac12$. `integrate` needs finite
/// $a < b$.
#[derive(Debug, Clone, PartialEq)]
pub struct GaussChebyshev {
    pair: Pair,
    kind: ChebyshevKind,
}

impl GaussChebyshev {
    fn build(n: usize, kind: ChebyshevKind) -> Result<Self, Error> {
        if n == 0 {
            return Err(Error::OutOfDomain { name: "n", value: 0.0, allowed: ">= 1" });
        }
        let (nodes, weights) = chebyshev(n, kind);
        let (lo_nodes, lo_weights) = chebyshev(n / 2, kind);
        Ok(GaussChebyshev { pair: Pair { nodes, weights, lo_nodes, lo_weights }, kind })
    }

    /// $n$-point rule of the first kind (weight $1/\sqrt{(b-x)(x-a)}$).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if $n = 0$.
    pub fn first_kind(n: usize) -> Result<Self, Error> {
        Self::build(n, ChebyshevKind::First)
    }

    /// $n$-point rule of the second kind (weight $\sqrt{(b-x)(x-a)}$).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if $n = 0$.
    pub fn second_kind(n: usize) -> Result<Self, Error> {
        Self::build(n, ChebyshevKind::Second)
    }

    /// Which weight this rule integrates against.
    #[must_use]
    pub fn kind(&self) -> ChebyshevKind {
        self.kind
    }

    fn scale(&self, a: f64, b: f64) -> Result<(f64, f64, f64), Error> {
        crate::types::check_ordered(a, b)?;
        let h = 0.5 * (b - a);
        let s = match self.kind {
            ChebyshevKind::First => 1.0,
            ChebyshevKind::Second => h * h,
        };
        Ok((0.5 * (a + b), h, s))
    }
}

weighted_rule!(GaussChebyshev);

/// Crate-internal access for the singular integrators: apply a Jacobi rule to a fallible
/// integrand (returns value and $\sum|w f|$ scaled).
pub(crate) fn jacobi_apply(
    rule: &GaussJacobi,
    f: &mut dyn FnMut(f64) -> Result<f64, Error>,
    a: f64,
    b: f64,
) -> Result<(f64, f64), Error> {
    let (c, h, s) = rule.scale(a, b)?;
    let mut g = |x: f64| f(x);
    let (q, qa) = apply(&rule.pair.nodes, &rule.pair.weights, &mut g, c, h)?;
    Ok((s * q, s.abs() * qa))
}
