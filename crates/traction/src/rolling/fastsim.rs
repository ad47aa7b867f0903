//! FASTSIM: Kalker's simplified theory of rolling contact (Kalker 1982, *Vehicle System
//! Dynamics* 11).
//!
//! The elastic displacement difference is replaced by a local one, $\mathbf u = L\mathbf q$,
//! with one flexibility $L$ chosen so that the simplified theory reproduces the linear
//! theory's forces (Kalker's weighting of $L_1 = 8a/(3GC_{11})$,
//! $L_2 = 8a/(3GC_{22})$, $L_3 = \pi a^2/(4G\sqrt{ab}\,C_{23})$ by the creepages, with
//! $C_{ij}$ from [`super::kalker`]). The stick condition $\mathbf s = \mathbf w - L\,\partial
//! \mathbf q/\partial x = 0$ then integrates along each row from the leading edge, where the
//! traction is zero, with the traction clipped to the bound $fp$ (the slip zone):
//! $$\mathbf q_I = \Pi\Big(\mathbf q_{I^+} - \frac{h_x}{L}\,\mathbf w\big(x_I + \tfrac{h_x}2, y_I\big)\Big).$$
//! On the same grid as the exact theory; the first element of a row is half a cell from the
//! leading edge. Cost: one pass over the elements.

use super::{kalker, Creepage, RollingInfo, RollingMethod, RollingSolution};
use crate::error::{Error, Result};
use crate::grid::ContactGrid;
use std::collections::HashMap;
use std::f64::consts::PI;

/// The flexibility $L$ (m/Pa) for semi-axes `a` (rolling direction) and `b`, combined shear
/// modulus `g` and Poisson ratio `nu`, weighted by the creepages.
///
/// # Errors
/// As [`kalker::coefficients`] (a/b in [0.1, 10], nu in [0, 0.5]).
pub fn flexibility(a: f64, b: f64, g: f64, nu: f64, creep: &Creepage) -> Result<f64> {
    let c = kalker::coefficients(a / b, nu)?;
    let l1 = 8.0 * a / (3.0 * c.c11 * g);
    let l2 = 8.0 * a / (3.0 * c.c22 * g);
    let r = (a * b).sqrt();
    let l3 = PI * a * a / (4.0 * g * r * c.c23);
    let (xi, eta, phi) = (creep.longitudinal.abs(), creep.lateral.abs(), (r * creep.spin).abs());
    let norm = (xi * xi + eta * eta + phi * phi).sqrt();
    Ok(if norm == 0.0 { l1 } else { (xi * l1 + eta * l2 + phi * l3) / norm })
}

/// FASTSIM on `grid` (contact elements with pressure) for an elliptical contact of semi-axes
/// `a`, `b` (for the flexibility), combined shear modulus `g`, Poisson ratio `nu` and
/// friction `friction`.
///
/// # Errors
/// As [`flexibility`]; [`Error::OutOfDomain`] for a non-positive modulus or negative friction.
pub fn solve(
    grid: &ContactGrid,
    a: f64,
    b: f64,
    g: f64,
    nu: f64,
    friction: f64,
    creep: &Creepage,
) -> Result<RollingSolution> {
    creep.validate()?;
    if !(g.is_finite() && g > 0.0) {
        return Err(Error::OutOfDomain {
            name: "shear modulus",
            value: g,
            allowed: "finite and > 0",
        });
    }
    if !(friction.is_finite() && friction >= 0.0) {
        return Err(Error::OutOfDomain {
            name: "friction coefficient",
            value: friction,
            allowed: "finite and >= 0",
        });
    }
    let l = flexibility(a, b, g, nu, creep)?;
    let n = grid.len();
    let (hx, hy) = (grid.hx, grid.hy);
    let x0 = grid.x.iter().copied().fold(f64::INFINITY, f64::min);
    let y0 = grid.y.iter().copied().fold(f64::INFINITY, f64::min);
    let cell =
        |k: usize| (((grid.x[k] - x0) / hx).round() as i64, ((grid.y[k] - y0) / hy).round() as i64);
    let index: HashMap<(i64, i64), usize> = (0..n).map(|k| (cell(k), k)).collect();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by_key(|&k| std::cmp::Reverse(cell(k).0));
    let (mut qx, mut qy) = (vec![0.0; n], vec![0.0; n]);
    let (mut sx, mut sy) = (vec![0.0; n], vec![0.0; n]);
    let mut stick = vec![true; n];
    for &k in &order {
        let (i, j) = cell(k);
        // Upstream traction, or the leading edge half a cell ahead.
        let (prev, step) = match index.get(&(i + 1, j)) {
            Some(&u) => ([qx[u], qy[u]], hx),
            None => ([0.0, 0.0], 0.5 * hx),
        };
        let w = creep.rigid_slip(grid.x[k] + 0.5 * step, grid.y[k]);
        let t = [prev[0] - step * w[0] / l, prev[1] - step * w[1] / l];
        let bound = friction * grid.pressure[k].max(0.0);
        let tn = t[0].hypot(t[1]);
        let q = if tn <= bound {
            t
        } else {
            stick[k] = false;
            if tn > 0.0 {
                [bound * t[0] / tn, bound * t[1] / tn]
            } else {
                [0.0, 0.0]
            }
        };
        qx[k] = q[0];
        qy[k] = q[1];
        // s = w - L dq/dx with dq/dx = (prev - q)/step.
        sx[k] = w[0] - l * (prev[0] - q[0]) / step;
        sy[k] = w[1] - l * (prev[1] - q[1]) / step;
        if stick[k] {
            sx[k] = 0.0;
            sy[k] = 0.0;
        }
    }
    Ok(RollingSolution {
        x: grid.x.clone(),
        y: grid.y.clone(),
        element_area: grid.element_area(),
        pressure: grid.pressure.clone(),
        qx,
        qy,
        sx,
        sy,
        stick,
        fx: 0.0,
        fy: 0.0,
        mz: 0.0,
        info: RollingInfo {
            method: RollingMethod::Fastsim,
            iterations: 1,
            products: 0,
            residual: 0.0,
        },
    }
    .with_resultants())
}
