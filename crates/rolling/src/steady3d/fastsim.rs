//! FASTSIM: Kalker's simplified theory of rolling contact (Kalker 1982, *Vehicle System
//! Dynamics* 11).
//!
//! The elastic displacement difference is replaced by a local one, each creepage term with
//! its own flexibility chosen so that the simplified theory reproduces the linear theory's
//! forces: $L_1 = 8a/(3GC_{11})$ for $\xi$, $L_2 = 8a/(3GC_{22})$ for $\eta$ and
//! $L_3 = \pi a^2/(4G\sqrt{ab}\,C_{23})$ for $\phi$ ($C_{ij}$ from [`super::kalker`]). The
//! stick condition then integrates along each row from the leading edge, where the traction
//! is zero, with the traction clipped to the bound $fp$ (the slip zone):
//! $$\mathbf q_I = \Pi\Big(\mathbf q_{I^+} - h_x\big(\tfrac{\xi}{L_1} - \tfrac{\phi y}{L_3},\
//! \tfrac{\eta}{L_2} + \tfrac{\phi x}{L_3}\big)\Big).$$
//! Kalker's original weights one flexibility by the creepages,
//! $L = (|\xi|L_1 + |\eta|L_2 + \sqrt{ab}|\phi|L_3)/\sqrt{\xi^2+\eta^2+ab\,\phi^2}$; for
//! combined creepage that under-predicts even the linear theory (by $1/\sqrt2$ at
//! $\xi = \eta$, measured 31 % against the exact theory here), so each term keeps its own
//! flexibility, which reproduces the linear theory for any combination.
//!
//! An element whose unclipped traction exceeds $fp$ slips; its slip and traction direction
//! come from the local model with one mean flexibility $\bar L = (L_1 + L_2)/2$:
//! $\mathbf s = \mathbf w - \bar L\,\partial\mathbf q/\partial x$ and
//! $\mathbf q = -fp\,\mathbf s/|\mathbf s|$, so that at large creepage the traction opposes
//! the rigid slip $\mathbf w$ as it must (per-term flexibilities would tilt it). On the same grid as the exact theory; the first
//! element of a row is half a cell from the leading edge. Cost: one pass over the elements.

use super::{kalker, Creepage, RollingInfo, RollingMethod, RollingSolution, Rows};
use crate::error::{Error, Result};
use std::f64::consts::PI;
use stickslip_lattice::ContactGrid;

/// The flexibilities $(L_1, L_2, L_3)$ (m/Pa) for semi-axes `a` (rolling direction) and `b`,
/// combined shear modulus `g` and Poisson ratio `nu`.
///
/// # Errors
/// As [`kalker::coefficients`] (a/b in [0.1, 10], nu in [0, 0.5]).
pub fn flexibilities(a: f64, b: f64, g: f64, nu: f64) -> Result<[f64; 3]> {
    let c = kalker::coefficients(a / b, nu)?;
    let r = (a * b).sqrt();
    Ok([
        8.0 * a / (3.0 * c.c11 * g),
        8.0 * a / (3.0 * c.c22 * g),
        PI * a * a / (4.0 * g * r * c.c23),
    ])
}

/// FASTSIM on `grid` (contact elements with pressure) for an elliptical contact of semi-axes
/// `a`, `b` (for the flexibility), combined shear modulus `g`, Poisson ratio `nu` and
/// friction `friction`.
///
/// # Errors
/// As [`flexibilities`]; [`Error::OutOfDomain`] for a non-positive modulus or negative friction.
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
    let l = flexibilities(a, b, g, nu)?;
    let mean = 0.5 * (l[0] + l[1]);
    let n = grid.len();
    let hx = grid.hx;
    let rows = Rows::of(grid)?;
    let (mut qx, mut qy) = (vec![0.0; n], vec![0.0; n]);
    let (mut sx, mut sy) = (vec![0.0; n], vec![0.0; n]);
    let mut stick = vec![true; n];
    for &k in &rows.order {
        // Upstream traction, or the leading edge half a cell ahead.
        let (prev, step) = match rows.up[k] {
            Some(u) => ([qx[u], qy[u]], hx),
            None => ([0.0, 0.0], 0.5 * hx),
        };
        let (x, y) = (grid.x[k] + 0.5 * step, grid.y[k]);
        let rate = [
            creep.longitudinal / l[0] - creep.spin * y / l[2],
            creep.lateral / l[1] + creep.spin * x / l[2],
        ];
        let t = [prev[0] - step * rate[0], prev[1] - step * rate[1]];
        let bound = friction * grid.pressure[k].max(0.0);
        let q = if t[0].hypot(t[1]) <= bound {
            t
        } else {
            // Slipping: with the mean flexibility the slip is s = (L/h)(q - u) for
            // u = prev - h w / L, so q = fp u/|u| is opposite to it (and to w at large
            // creepage).
            stick[k] = false;
            let w = creep.rigid_slip(x, y);
            let u = [prev[0] - step * w[0] / mean, prev[1] - step * w[1] / mean];
            let un = u[0].hypot(u[1]);
            let q = if un > 0.0 { [bound * u[0] / un, bound * u[1] / un] } else { [0.0, 0.0] };
            sx[k] = mean * (q[0] - u[0]) / step;
            sy[k] = mean * (q[1] - u[1]) / step;
            q
        };
        qx[k] = q[0];
        qy[k] = q[1];
    }
    let info =
        RollingInfo { method: RollingMethod::Fastsim, iterations: 1, products: 0, residual: 0.0 };
    Ok(RollingSolution::on_grid(grid, [qx, qy], [sx, sy], stick, info))
}
