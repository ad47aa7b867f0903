//! Thin wrappers over stickslip-quad for the tests.
use stickslip_quad::{gauss_kronrod, AdaptiveConfig, Tolerance};

/// Adaptive Gauss–Kronrod on [a, b] (ends may be infinite) with interior breakpoints (those
/// strictly inside are kept), relative tolerance `rel` and absolute floor `abs`.
pub fn gk<F: FnMut(f64) -> f64>(f: F, a: f64, b: f64, bps: &[f64], rel: f64, abs: f64) -> f64 {
    let (lo, hi) = if a < b { (a, b) } else { (b, a) };
    let inside: Vec<f64> = bps.iter().copied().filter(|&p| p > lo && p < hi).collect();
    let cfg = AdaptiveConfig::new(Tolerance::new(abs, rel).unwrap())
        .with_breakpoints(inside)
        .unwrap()
        .with_max_subdivisions(5000)
        .unwrap();
    match gauss_kronrod(f, a, b, &cfg) {
        Ok(e) => e.value,
        Err(e) => panic!("quadrature failed on [{a}, {b}]: {e:?}"),
    }
}

/// Nested 2D quadrature over [x1, x2] x [y1, y2] of f(xi, eta), with breakpoints at the field
/// point coordinates (px, py) so that a point singularity inside the rectangle sits on piece
/// boundaries.
pub fn gk2<F: Fn(f64, f64) -> f64>(
    f: F,
    (x1, x2, y1, y2): (f64, f64, f64, f64),
    (px, py): (f64, f64),
    rel: f64,
    abs: f64,
) -> f64 {
    gk(|xi| gk(|eta| f(xi, eta), y1, y2, &[py], rel, abs * 0.1), x1, x2, &[px], rel, abs)
}

/// Integral of f(xi, eta) over the rectangle [x1, x2] x [y1, y2] with a possible point
/// singularity of order 1/rho (or bounded times 1/rho) at the field point p, by the signed
/// decomposition into the four triangles (p, corner_k, corner_k+1) and Duffy's map
/// (xi, eta) = p + s (A - p + t (B - A)), dA = s |(A - p) x (B - A)| ds dt, which cancels the
/// singularity. Nested adaptive Gauss–Kronrod in t (outer) and s (inner). Valid for p inside,
/// on the boundary of, or outside the rectangle.
pub fn duffy_rect<F: Fn(f64, f64) -> f64>(
    f: F,
    (x1, x2, y1, y2): (f64, f64, f64, f64),
    (px, py): (f64, f64),
    rel: f64,
    abs: f64,
) -> f64 {
    let c = [(x1, y1), (x2, y1), (x2, y2), (x1, y2)];
    let mut total = 0.0;
    for k in 0..4 {
        let (ax, ay) = c[k];
        let (bx, by) = c[(k + 1) % 4];
        let (ux, uy) = (ax - px, ay - py);
        let (ex, ey) = (bx - ax, by - ay);
        let cross = ux * ey - uy * ex; // signed twice-area: + for counter-clockwise
        if cross == 0.0 {
            continue;
        }
        let v = gk(
            |t| {
                let (dx, dy) = (ux + t * ex, uy + t * ey);
                gk(|s| s * f(px + s * dx, py + s * dy), 0.0, 1.0, &[], rel, abs)
            },
            0.0,
            1.0,
            &[],
            rel,
            abs,
        );
        total += cross * v;
    }
    total
}
