//! The one place this crate builds quadrature rules (from `stickslip-quad`).

use crate::error::Error;
use crate::panels::Rule;
use stickslip_quad::Rule as _;

/// The `n`-point Gauss–Jacobi rule on $[-1,1]$ for the weight $(1-\xi)^\alpha(1+\xi)^\beta$
/// (plain Gauss–Legendre when both exponents vanish).
pub(crate) fn jacobi(n: usize, alpha: f64, beta: f64) -> Result<Rule, Error> {
    let wrap = |e: stickslip_quad::Error| Error::Numerical {
        what: "building a Gauss-Jacobi rule",
        detail: e.to_string(),
    };
    if alpha == 0.0 && beta == 0.0 {
        let r = stickslip_quad::GaussLegendre::new(n).map_err(wrap)?;
        return Ok(Rule { x: r.nodes().to_vec(), w: r.weights().to_vec() });
    }
    let r = stickslip_quad::GaussJacobi::new(n, alpha, beta).map_err(wrap)?;
    Ok(Rule { x: r.nodes().to_vec(), w: r.weights().to_vec() })
}
