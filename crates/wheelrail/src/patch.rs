//! A contact patch's own frame and lattice, and the undeformed gap on it.
//!
//! **The patch frame** (right side): origin $\mathbf o$ (the reference point on the rail
//! surface, [`crate::search`]) and, for the contact angle $\delta$,
//! $$\mathbf e_x = (1, 0, 0),\quad \mathbf e_s = (0, \cos\delta, \sin\delta),\quad
//! \mathbf e_n = (0, -\sin\delta, \cos\delta) = \mathbf e_x\times\mathbf e_s:$$
//! $x$ rolling, $s$ across the patch in the tangent plane, $n$ the normal into the rail.
//! A point's patch coordinates are $(x, s, n) = ((\mathbf p - \mathbf o)\cdot\mathbf e_x,
//! \dots)$.
//!
//! **The gap** at lattice cell centre $(x, s)$ is measured along $\mathbf e_n$ between the
//! two undeformed surfaces, exactly (no quadratic or Hertzian approximation):
//! $$h(x, s) = n_{rail}(s) - n_{wheel}(x, s),$$
//! positive where they are apart. The rail is straight along $x$, so $n_{rail}$ depends on
//! $s$ only: the rail parameter $t$ solves $(\mathbf r(t) - \mathbf o)\cdot\mathbf e_s = s$
//! (Newton). The wheel point solves $(\mathbf w(t, \theta) - \mathbf o)\cdot\mathbf e_x = x$,
//! $(\mathbf w(t, \theta) - \mathbf o)\cdot\mathbf e_s = s$ for $(t, \theta)$ (Newton in two
//! unknowns on the surface of revolution of [`crate::placement`]); the longitudinal
//! curvature of the wheel and the yaw of the wheelset enter through $\mathbf w$. Each cell
//! starts from its neighbour's solution, marching out from the reference point.

use crate::error::{Error, Result};
use crate::placement::{PlacedRail, PlacedWheel};
use nalgebra::Vector3;

/// Newton iterations per cell, at most.
const NEWTON_MAX: usize = 40;
/// Newton stops when the residual is below this (m; 0.1 pm, six orders below the gaps that
/// matter).
const NEWTON_TOL: f64 = 1e-13;

/// A patch's frame (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Frame {
    pub origin: Vector3<f64>,
    pub delta: f64,
    pub ex: Vector3<f64>,
    pub es: Vector3<f64>,
    pub en: Vector3<f64>,
    /// Rail parameter at the origin.
    pub rail_t: f64,
    /// Wheel parameters near the origin (a start for Newton).
    pub wheel_t: f64,
    pub wheel_theta: f64,
}

impl Frame {
    pub fn new(origin: Vector3<f64>, delta: f64, rail_t: f64, wheel_t: f64, theta: f64) -> Self {
        let (s, c) = delta.sin_cos();
        Self {
            origin,
            delta,
            ex: Vector3::new(1.0, 0.0, 0.0),
            es: Vector3::new(0.0, c, s),
            en: Vector3::new(0.0, -s, c),
            rail_t,
            wheel_t,
            wheel_theta: theta,
        }
    }

    /// Patch coordinates of a track point.
    pub fn local(&self, p: &Vector3<f64>) -> [f64; 3] {
        let d = p - self.origin;
        [d.dot(&self.ex), d.dot(&self.es), d.dot(&self.en)]
    }

    /// Track coordinates of a patch point.
    pub fn global(&self, l: [f64; 3]) -> Vector3<f64> {
        self.origin + self.ex * l[0] + self.es * l[1] + self.en * l[2]
    }
}

/// A rectangular lattice in the patch plane: `nx` × `ns` cells of `hx` × `hs`, lower corner
/// `(x0, s0)` (patch coordinates); cell `(i, j)` is index `j * nx + i`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Lattice {
    pub nx: usize,
    pub ns: usize,
    pub hx: f64,
    pub hs: f64,
    pub x0: f64,
    pub s0: f64,
}

impl Lattice {
    pub fn x(&self, i: usize) -> f64 {
        self.x0 + (i as f64 + 0.5) * self.hx
    }

    pub fn s(&self, j: usize) -> f64 {
        self.s0 + (j as f64 + 0.5) * self.hs
    }

    pub fn len(&self) -> usize {
        self.nx * self.ns
    }

    /// The cell index nearest to coordinate `v` on an axis of `n` cells from `v0`, step `h`.
    fn nearest(v: f64, v0: f64, h: f64, n: usize) -> usize {
        (((v - v0) / h - 0.5).round().max(0.0) as usize).min(n - 1)
    }
}

/// The rail's normal coordinate $n_{rail}(s)$ at the lattice's columns, and the rail
/// parameter of each.
pub(crate) fn rail_column(
    rail: &PlacedRail<'_>,
    f: &Frame,
    lat: &Lattice,
) -> Result<(Vec<f64>, Vec<f64>)> {
    let mut n = vec![0.0; lat.ns];
    let mut ts = vec![0.0; lat.ns];
    let j0 = Lattice::nearest(0.0, lat.s0, lat.hs, lat.ns);
    let (c, s) = (f.delta.cos(), f.delta.sin());
    let solve = |target: f64, mut t: f64| -> Result<(f64, f64)> {
        for _ in 0..NEWTON_MAX {
            let (p, d1, _) = rail.at(t);
            let (dy, dz) = (p[0] - f.origin.y, p[1] - f.origin.z);
            let g = dy * c + dz * s - target;
            let gp = d1[0] * c + d1[1] * s;
            if g.abs() < NEWTON_TOL {
                return Ok((t, -dy * s + dz * c));
            }
            if gp <= 0.0 {
                break;
            }
            t -= g / gp;
        }
        Err(Error::FlangeClimb {
            what: format!(
                "the rail surface folds over in the patch plane of contact angle {:.4} rad at s = {target:.4e} m",
                f.delta
            ),
        })
    };
    let mut t = f.rail_t;
    for j in (0..=j0).rev() {
        let r = solve(lat.s(j), t)?;
        t = r.0;
        (ts[j], n[j]) = r;
    }
    t = ts[j0];
    for j in j0 + 1..lat.ns {
        let r = solve(lat.s(j), t)?;
        t = r.0;
        (ts[j], n[j]) = r;
    }
    Ok((n, ts))
}

/// The wheel surface at patch coordinates `(x, s)`: its parameters, normal coordinate and
/// slope $\partial n/\partial s$ at fixed $x$.
#[derive(Debug, Clone, Copy)]
pub(crate) struct WheelAt {
    pub t: f64,
    pub theta: f64,
    pub n: f64,
    pub dn_ds: f64,
}

/// Solve for the wheel point at patch coordinates `(x, s)` from the start `(t, theta)`.
pub(crate) fn wheel_point(
    wheel: &PlacedWheel<'_>,
    f: &Frame,
    x: f64,
    s: f64,
    start: (f64, f64),
) -> Option<WheelAt> {
    let (mut t, mut th) = start;
    for _ in 0..NEWTON_MAX {
        let p = wheel.point(t, th);
        let d = p.w - f.origin;
        let r = [d.dot(&f.ex) - x, d.dot(&f.es) - s];
        let (a, b) = (p.dt.dot(&f.ex), p.dtheta.dot(&f.ex));
        let (c, e) = (p.dt.dot(&f.es), p.dtheta.dot(&f.es));
        let det = a * e - b * c;
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        if r[0].abs() < NEWTON_TOL && r[1].abs() < NEWTON_TOL {
            // d(t, theta)/ds at fixed x: J (dt, dtheta) = (0, 1).
            let (dt, dth) = (-b / det, a / det);
            let dn = p.dt.dot(&f.en) * dt + p.dtheta.dot(&f.en) * dth;
            return Some(WheelAt { t, theta: th, n: d.dot(&f.en), dn_ds: dn });
        }
        t -= (e * r[0] - b * r[1]) / det;
        th -= (-c * r[0] + a * r[1]) / det;
        if !(t.is_finite() && th.is_finite()) {
            return None;
        }
    }
    None
}

/// The wheel's normal coordinate $n_{wheel}(x, s)$ and its slope $\partial n/\partial s$ at
/// every cell centre of the lattice (row-major `j * nx + i`).
pub(crate) fn wheel_layer(
    wheel: &PlacedWheel<'_>,
    f: &Frame,
    lat: &Lattice,
) -> Result<(Vec<f64>, Vec<f64>)> {
    let mut n = vec![0.0; lat.len()];
    let mut dn = vec![0.0; lat.len()];
    let i0 = Lattice::nearest(0.0, lat.x0, lat.hx, lat.nx);
    let j0 = Lattice::nearest(0.0, lat.s0, lat.hs, lat.ns);
    let fail = |x: f64, s: f64| {
        Error::FlangeClimb {
        what: format!(
            "the wheel surface cannot be followed in the patch plane of contact angle {:.4} rad at (x, s) = ({x:.4e}, {s:.4e}) m",
            f.delta
        ),
    }
    };
    let solve = |x: f64, s: f64, start: (f64, f64)| {
        wheel_point(wheel, f, x, s, start).ok_or_else(|| fail(x, s))
    };
    let column =
        |j: usize, start: (f64, f64), n: &mut [f64], dn: &mut [f64]| -> Result<(f64, f64)> {
            let s = lat.s(j);
            let c = solve(lat.x(i0), s, start)?;
            n[j * lat.nx + i0] = c.n;
            dn[j * lat.nx + i0] = c.dn_ds;
            for dir in [-1i64, 1] {
                // Each cell starts from the straight continuation of the last two.
                let (mut last, mut before) = ((c.t, c.theta), (c.t, c.theta));
                let mut i = i0 as i64 + dir;
                while i >= 0 && (i as usize) < lat.nx {
                    let guess = (2.0 * last.0 - before.0, 2.0 * last.1 - before.1);
                    let p = solve(lat.x(i as usize), s, guess)?;
                    (before, last) = (last, (p.t, p.theta));
                    n[j * lat.nx + i as usize] = p.n;
                    dn[j * lat.nx + i as usize] = p.dn_ds;
                    i += dir;
                }
            }
            Ok((c.t, c.theta))
        };
    let first = column(j0, (f.wheel_t, f.wheel_theta), &mut n, &mut dn)?;
    // Columns outwards, each from the straight continuation of the last two centres.
    for range in [(0..j0).rev().collect::<Vec<_>>(), (j0 + 1..lat.ns).collect()] {
        let (mut last, mut before) = (first, first);
        for j in range {
            let guess = (2.0 * last.0 - before.0, 2.0 * last.1 - before.1);
            (before, last) = (last, column(j, guess, &mut n, &mut dn)?);
        }
    }
    Ok((n, dn))
}
