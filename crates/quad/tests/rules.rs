//! Fixed rules against mpmath nodes and weights (`scripts/quad_rules.py`, mp.dps = 40), and
//! exactness identities.

mod common;

use common::tol;
use stickslip_quad::{GaussChebyshev, GaussJacobi, GaussLegendre, KronrodRule, Rule};

fn check_family(family: &str) {
    let data = common::rules_data();
    let mut keys: Vec<(usize, u64, u64)> = data
        .iter()
        .filter(|r| r.0 == family)
        .map(|r| (r.1, r.2.to_bits(), r.3.to_bits()))
        .collect();
    keys.dedup();
    assert!(!keys.is_empty());
    for (n, ab, bb) in keys {
        let (alpha, beta) = (f64::from_bits(ab), f64::from_bits(bb));
        let t0 = std::time::Instant::now();
        let (nodes, weights): (Vec<f64>, Vec<f64>) = if family == "legendre" {
            let r = GaussLegendre::new(n).unwrap();
            (r.nodes().to_vec(), r.weights().to_vec())
        } else {
            let r = GaussJacobi::new(n, alpha, beta).unwrap();
            (r.nodes().to_vec(), r.weights().to_vec())
        };
        let dt = t0.elapsed();
        let rows: Vec<_> = data
            .iter()
            .filter(|r| r.0 == family && r.1 == n && r.2 == alpha && r.3 == beta)
            .collect();
        assert_eq!(rows.len(), n);
        let (mut max_dx, mut max_dw, mut rms_dw, mut worst) = (0.0f64, 0.0f64, 0.0f64, 0usize);
        for r in &rows {
            let i = r.4;
            let dx = (nodes[i] - r.5).abs();
            // relative weight error, scaled by the node's distance to the nearer end for Jacobi
            let mut dw = (weights[i] - r.6).abs() / r.6;
            if family == "jacobi" {
                dw *= 1.0 - r.5.abs();
            }
            max_dx = max_dx.max(dx);
            rms_dw += dw * dw;
            if dw > max_dw {
                max_dw = dw;
                worst = i;
            }
        }
        rms_dw = (rms_dw / n as f64).sqrt();
        println!(
            "{family} n={n} alpha={alpha} beta={beta}: max |dx| = {max_dx:.2e}, max rel dw = {max_dw:.2e} (row {worst}), rms rel dw = {rms_dw:.2e}, build {dt:?}"
        );
        if family == "legendre" {
            // the brief's target: nodes and weights accurate to 1e-15 in absolute terms
            let max_abs_w = rows.iter().map(|r| (weights[r.4] - r.6).abs()).fold(0.0f64, f64::max);
            println!("  max |dw| = {max_abs_w:.2e}");
            assert!(max_abs_w <= tol::LEGENDRE_WEIGHT_ABS);
        }
        let (tx, tw) = if family == "legendre" {
            (tol::LEGENDRE_NODE_ABS, tol::LEGENDRE_WEIGHT_REL)
        } else {
            (tol::JACOBI_NODE_ABS, tol::JACOBI_WEIGHT_REL)
        };
        assert!(max_dx <= tx, "nodes n={n}: {max_dx:e}");
        assert!(max_dw <= tw, "weights n={n}: {max_dw:e} at {worst}");
    }
}

#[test]
fn legendre_matches_mpmath() {
    check_family("legendre");
}

#[test]
fn jacobi_matches_mpmath() {
    check_family("jacobi");
}

/// Chebyshev rules equal Jacobi rules with alpha = beta = -1/2 and +1/2 (Abramowitz & Stegun
/// 25.4.38-40 versus Golub-Welsch).
#[test]
fn chebyshev_equals_jacobi() {
    for n in [1usize, 2, 7, 50] {
        for (c, a) in [
            (GaussChebyshev::first_kind(n).unwrap(), -0.5),
            (GaussChebyshev::second_kind(n).unwrap(), 0.5),
        ] {
            let j = GaussJacobi::new(n, a, a).unwrap();
            let dx =
                c.nodes().iter().zip(j.nodes()).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
            let dw = c
                .weights()
                .iter()
                .zip(j.weights())
                .map(|(x, y)| (x - y).abs() / x)
                .fold(0.0, f64::max);
            println!("chebyshev vs jacobi n={n} a={a}: max dx {dx:.2e}, max rel dw {dw:.2e}");
            assert!(dx <= tol::JACOBI_NODE_ABS && dw <= 1e-13);
        }
    }
}

/// Exactness: the n-point Gauss rule integrates x^j exactly for j <= 2n-1; Kronrod K15 (K21) is
/// exact to degree 22 (31), its Gauss part to 13 (19).
#[test]
fn exactness_on_monomials() {
    let mono = |j: i32| if j % 2 == 1 { 0.0 } else { 2.0 / (j as f64 + 1.0) };
    let mut worst = 0.0f64;
    for n in [1usize, 2, 3, 10, 33] {
        let r = GaussLegendre::new(n).unwrap();
        for j in 0..(2 * n as i32) {
            let q = r.sum(|x| x.powi(j), -1.0, 1.0).unwrap();
            worst = worst.max((q - mono(j)).abs());
            assert!((q - mono(j)).abs() <= tol::EXACTNESS_ABS, "GL n={n} j={j}");
        }
        // one degree more must not be exact (the rule is not of higher degree by accident)
        // (checked for small n, where that error is large: 2^(2n+1) (n!)^4 / ((2n+1) ((2n)!)^2))
        let j = 2 * n as i32;
        if n <= 3 {
            assert!((r.sum(|x| x.powi(j), -1.0, 1.0).unwrap() - mono(j)).abs() > 1e-3);
        }
    }
    for (rule, dk, dg) in [(KronrodRule::G7K15, 22, 13), (KronrodRule::G10K21, 31, 19)] {
        let (xk, wk, xg, wg) = rule.nodes_and_weights();
        assert_eq!(xk.len(), rule.points());
        for j in 0..=dk {
            let q: f64 = xk.iter().zip(&wk).map(|(x, w)| w * x.powi(j)).sum();
            worst = worst.max((q - mono(j)).abs());
            assert!((q - mono(j)).abs() <= tol::EXACTNESS_ABS, "{rule:?} K j={j}");
        }
        for j in 0..=dg {
            let q: f64 = xg.iter().zip(&wg).map(|(x, w)| w * x.powi(j)).sum();
            assert!((q - mono(j)).abs() <= tol::EXACTNESS_ABS, "{rule:?} G j={j}");
        }
        // embedded Gauss nodes are the Gauss-Legendre nodes
        let gl = GaussLegendre::new(xg.len()).unwrap();
        for (x, y) in xg.iter().zip(gl.nodes()) {
            assert!((x - y).abs() <= tol::LEGENDRE_NODE_ABS);
        }
    }
    println!("worst monomial error: {worst:.2e}");
}

/// Jacobi on the physical interval: int_a^b (b-x)^alpha (x-a)^beta dx = (b-a)^(alpha+beta+1)
/// B(alpha+1, beta+1); with alpha = 0.5, beta = -0.5 on [1, 3]: 2 * B(3/2, 1/2) = pi.
#[test]
fn jacobi_physical_scaling() {
    let r = GaussJacobi::new(6, 0.5, -0.5).unwrap();
    let e = r.integrate(|_| 1.0, 1.0, 3.0).unwrap();
    println!(
        "jacobi scaling: {} vs pi, err {:.2e}, est {:.2e}",
        e.value,
        (e.value - std::f64::consts::PI).abs(),
        e.error
    );
    assert!((e.value - std::f64::consts::PI).abs() <= 4.0 * f64::EPSILON * std::f64::consts::PI);
    // int_1^3 x (3-x)^0.5 (x-1)^-0.5 dx = pi * (mean of x under the weight) = pi * 1.5
    let e = r.integrate(|x| x, 1.0, 3.0).unwrap();
    assert!((e.value - 1.5 * std::f64::consts::PI).abs() <= 1e-14 * e.value);
}

/// Large n: n = 5000 builds, nodes increase, weights sum to 2, and the cost is reported.
#[test]
fn legendre_large_n() {
    let t0 = std::time::Instant::now();
    let r = GaussLegendre::new(5000).unwrap();
    let dt = t0.elapsed();
    let s: f64 = r.weights().iter().sum();
    println!("GL n=5000: build {dt:?}, |sum w - 2| = {:.2e}", (s - 2.0).abs());
    assert!((s - 2.0).abs() < 1e-13);
    assert!(r.nodes().windows(2).all(|p| p[0] < p[1]));
}
