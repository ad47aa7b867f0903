//! Contact grids: rectangular elements of uniform size on a common lattice, with the normal
//! pressure of each element.
//!
//! Seed 002 §3.3.1 discretises the contact area "into a finite number of rectangular grid
//! elements"; the discrete normal force of element $k$ is $P_k = p_k h_x h_y$ with $p_k$ the
//! pressure at the element centre.
//!
//! Lattice: element $(i, j)$ has centre
//! $(x_0 + (i + \tfrac12) h_x,\; y_0 + (j + \tfrac12) h_y)$; a patch takes the elements whose
//! centres lie strictly inside its shape.

use crate::error::{non_negative, positive, Error, Result};

/// A plane shape that selects lattice elements by their centres.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// Circle of centre `(cx, cy)` and radius `r`.
    Circle {
        /// Centre x.
        cx: f64,
        /// Centre y.
        cy: f64,
        /// Radius.
        r: f64,
    },
    /// Axis-aligned ellipse of centre `(cx, cy)`, semi-axis `a` along $x$ and `b` along $y$.
    Ellipse {
        /// Centre x.
        cx: f64,
        /// Centre y.
        cy: f64,
        /// Semi-axis along x.
        a: f64,
        /// Semi-axis along y.
        b: f64,
    },
    /// Axis-aligned rectangle of centre `(cx, cy)` and full sides `wx`, `wy`.
    Rectangle {
        /// Centre x.
        cx: f64,
        /// Centre y.
        cy: f64,
        /// Full side along x.
        wx: f64,
        /// Full side along y.
        wy: f64,
    },
}

impl Shape {
    fn validate(&self) -> Result<()> {
        let check_centre = |cx: f64, cy: f64| -> Result<()> {
            for (name, v) in [("shape centre x", cx), ("shape centre y", cy)] {
                if !v.is_finite() {
                    return Err(Error::OutOfDomain { name, value: v, allowed: "finite" });
                }
            }
            Ok(())
        };
        match *self {
            Shape::Circle { cx, cy, r } => {
                check_centre(cx, cy)?;
                positive("circle radius", r)?;
            }
            Shape::Ellipse { cx, cy, a, b } => {
                check_centre(cx, cy)?;
                positive("ellipse semi-axis a", a)?;
                positive("ellipse semi-axis b", b)?;
            }
            Shape::Rectangle { cx, cy, wx, wy } => {
                check_centre(cx, cy)?;
                positive("rectangle side wx", wx)?;
                positive("rectangle side wy", wy)?;
            }
        }
        Ok(())
    }

    /// Whether the point lies strictly inside.
    #[must_use]
    pub fn contains(&self, x: f64, y: f64) -> bool {
        match *self {
            Shape::Circle { cx, cy, r } => (x - cx).powi(2) + (y - cy).powi(2) < r * r,
            Shape::Ellipse { cx, cy, a, b } => {
                ((x - cx) / a).powi(2) + ((y - cy) / b).powi(2) < 1.0
            }
            Shape::Rectangle { cx, cy, wx, wy } => {
                (x - cx).abs() < 0.5 * wx && (y - cy).abs() < 0.5 * wy
            }
        }
    }

    /// Centre and half-extents of the bounding box.
    fn bounds(&self) -> (f64, f64, f64, f64) {
        match *self {
            Shape::Circle { cx, cy, r } => (cx, cy, r, r),
            Shape::Ellipse { cx, cy, a, b } => (cx, cy, a, b),
            Shape::Rectangle { cx, cy, wx, wy } => (cx, cy, 0.5 * wx, 0.5 * wy),
        }
    }
}

/// How the normal pressure of a patch is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PatchPressure {
    /// The same pressure on every element of the patch.
    Uniform(f64),
    /// Hertz pressure $p = p_0\sqrt{1 - \hat x^2/a^2 - \hat y^2/b^2}$ over a circle or ellipse
    /// patch, with $p_0 = 3P/(2\pi a b)$ (FORMULAS.md E; Johnson eq. 4.37). The element
    /// pressures sampled at the centres are rescaled so that the element forces sum to
    /// exactly `load` (the discrete force balance the LP needs).
    Hertz {
        /// Total normal load $P$ on the patch.
        load: f64,
    },
}

/// One contact patch: a shape and its pressure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridPatch {
    /// Which lattice elements belong to the patch.
    pub shape: Shape,
    /// Their pressure.
    pub pressure: PatchPressure,
}

/// A contact grid of equal rectangular elements.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactGrid {
    /// Element side along $x$.
    pub hx: f64,
    /// Element side along $y$.
    pub hy: f64,
    /// Element centres, x.
    pub x: Vec<f64>,
    /// Element centres, y.
    pub y: Vec<f64>,
    /// Normal pressure of each element.
    pub pressure: Vec<f64>,
    /// Patch index of each element (0 for single-shape grids).
    pub patch: Vec<usize>,
}

impl ContactGrid {
    /// Build a grid from several patches on the lattice of spacing `(hx, hy)` and origin
    /// `(x0, y0)`.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for non-positive spacings or bad shapes/pressures,
    /// [`Error::OverlappingPatches`] if two patches select the same element,
    /// [`Error::EmptyGrid`] if no element is selected (or a patch selects none).
    pub fn from_patches(
        hx: f64,
        hy: f64,
        origin: (f64, f64),
        patches: &[GridPatch],
    ) -> Result<Self> {
        positive("element side hx", hx)?;
        positive("element side hy", hy)?;
        for (name, v) in [("lattice origin x", origin.0), ("lattice origin y", origin.1)] {
            if !v.is_finite() {
                return Err(Error::OutOfDomain { name, value: v, allowed: "finite" });
            }
        }
        if patches.is_empty() {
            return Err(Error::EmptyGrid { reason: "no patch given" });
        }
        // (i, j) -> patch, collected per patch in lattice order.
        let mut cells: Vec<(i64, i64, usize)> = Vec::new();
        for (pi, p) in patches.iter().enumerate() {
            p.shape.validate()?;
            match p.pressure {
                PatchPressure::Uniform(v) => {
                    non_negative("patch pressure", v)?;
                }
                PatchPressure::Hertz { load } => {
                    positive("patch Hertz load", load)?;
                    if matches!(p.shape, Shape::Rectangle { .. }) {
                        return Err(Error::OutOfDomain {
                            name: "Hertz pressure on a rectangle patch",
                            value: load,
                            allowed: "a circle or ellipse patch",
                        });
                    }
                }
            }
            let (cx, cy, ex, ey) = p.shape.bounds();
            let i0 = ((cx - ex - origin.0) / hx).floor() as i64 - 1;
            let i1 = ((cx + ex - origin.0) / hx).ceil() as i64 + 1;
            let j0 = ((cy - ey - origin.1) / hy).floor() as i64 - 1;
            let j1 = ((cy + ey - origin.1) / hy).ceil() as i64 + 1;
            let before = cells.len();
            for j in j0..=j1 {
                for i in i0..=i1 {
                    let x = origin.0 + (i as f64 + 0.5) * hx;
                    let y = origin.1 + (j as f64 + 0.5) * hy;
                    if p.shape.contains(x, y) {
                        cells.push((i, j, pi));
                    }
                }
            }
            if cells.len() == before {
                return Err(Error::EmptyGrid { reason: "a patch contains no element centre" });
            }
        }
        let mut sorted = cells.clone();
        sorted.sort_unstable();
        for w in sorted.windows(2) {
            if w[0].0 == w[1].0 && w[0].1 == w[1].1 {
                return Err(Error::OverlappingPatches {
                    first: w[0].2.min(w[1].2),
                    second: w[0].2.max(w[1].2),
                    x: origin.0 + (w[0].0 as f64 + 0.5) * hx,
                    y: origin.1 + (w[0].1 as f64 + 0.5) * hy,
                });
            }
        }
        let n = cells.len();
        let mut grid = ContactGrid {
            hx,
            hy,
            x: Vec::with_capacity(n),
            y: Vec::with_capacity(n),
            pressure: Vec::with_capacity(n),
            patch: Vec::with_capacity(n),
        };
        for &(i, j, pi) in &cells {
            let x = origin.0 + (i as f64 + 0.5) * hx;
            let y = origin.1 + (j as f64 + 0.5) * hy;
            let p = match (patches[pi].pressure, patches[pi].shape) {
                (PatchPressure::Uniform(v), _) => v,
                (PatchPressure::Hertz { .. }, Shape::Circle { cx, cy, r }) => {
                    (1.0 - ((x - cx) / r).powi(2) - ((y - cy) / r).powi(2)).max(0.0).sqrt()
                }
                (PatchPressure::Hertz { .. }, Shape::Ellipse { cx, cy, a, b }) => {
                    (1.0 - ((x - cx) / a).powi(2) - ((y - cy) / b).powi(2)).max(0.0).sqrt()
                }
                (PatchPressure::Hertz { .. }, Shape::Rectangle { .. }) => 0.0,
            };
            grid.x.push(x);
            grid.y.push(y);
            grid.pressure.push(p);
            grid.patch.push(pi);
        }
        // Hertz patches: scale the shape function so the element forces sum to the load.
        let area = hx * hy;
        for (pi, p) in patches.iter().enumerate() {
            if let PatchPressure::Hertz { load } = p.pressure {
                let sum: f64 =
                    (0..n).filter(|&k| grid.patch[k] == pi).map(|k| grid.pressure[k]).sum();
                let scale = load / (sum * area);
                for k in 0..n {
                    if grid.patch[k] == pi {
                        grid.pressure[k] *= scale;
                    }
                }
            }
        }
        Ok(grid)
    }

    /// Hertz circle of radius `a` carrying `load`, on a square lattice with `n_across`
    /// elements across the diameter, centred at the origin (a lattice corner at the centre
    /// when `n_across` is even). `n_across = 10` gives seed 002's 80 elements. The element
    /// pressures are the Hertz shape sampled at the centres and scaled to the load,
    /// $p_k = s\sqrt{1 - r_k^2/a^2}$ with $s$ such that $h_xh_y\sum_k p_k = P$ (so
    /// $s \approx p_0 = 3P/(2\pi a^2)$; Hertz, FORMULAS.md E; seed 002 §3.3.1).
    ///
    /// # Errors
    /// As [`ContactGrid::from_patches`]; `n_across` must be at least 2.
    pub fn hertz_circle(a: f64, load: f64, n_across: usize) -> Result<Self> {
        Self::hertz_ellipse(a, a, load, n_across, n_across)
    }

    /// Hertz ellipse (semi-axes `a` along $x$, `b` along $y$) carrying `load`, with
    /// `nx` × `ny` lattice cells over its bounding box, centred at the origin. Element
    /// pressures $p_k = s\sqrt{1 - x_k^2/a^2 - y_k^2/b^2}$ with $h_xh_y\sum_k p_k = P$ (so
    /// $s \approx p_0 = 3P/(2\pi ab)$; see [`PatchPressure::Hertz`]).
    ///
    /// # Errors
    /// As [`ContactGrid::from_patches`]; `nx`, `ny` must be at least 2.
    pub fn hertz_ellipse(a: f64, b: f64, load: f64, nx: usize, ny: usize) -> Result<Self> {
        check_count("nx", nx)?;
        check_count("ny", ny)?;
        positive("ellipse semi-axis a", a)?;
        positive("ellipse semi-axis b", b)?;
        let hx = 2.0 * a / nx as f64;
        let hy = 2.0 * b / ny as f64;
        let shape = Shape::Ellipse { cx: 0.0, cy: 0.0, a, b };
        Self::from_patches(
            hx,
            hy,
            (-a, -b),
            &[GridPatch { shape, pressure: PatchPressure::Hertz { load } }],
        )
    }

    /// Uniformly pressed square of side `side` centred at the origin, `n` × `n` elements.
    ///
    /// # Errors
    /// As [`ContactGrid::from_patches`].
    pub fn uniform_square(side: f64, pressure: f64, n: usize) -> Result<Self> {
        check_count("n", n)?;
        positive("square side", side)?;
        let h = side / n as f64;
        let shape = Shape::Rectangle { cx: 0.0, cy: 0.0, wx: side, wy: side };
        Self::from_patches(
            h,
            h,
            (-0.5 * side, -0.5 * side),
            &[GridPatch { shape, pressure: PatchPressure::Uniform(pressure) }],
        )
    }

    /// A grid from a boolean mask over an `nx` × `ny` lattice (`mask[j * nx + i]`), with
    /// the pressure of each lattice cell (`pressure[j * nx + i]`; ignored where the mask is
    /// false).
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] for wrong slice lengths, [`Error::OutOfDomain`] for bad
    /// spacing or a negative pressure, [`Error::EmptyGrid`] for an all-false mask.
    pub fn from_mask(
        hx: f64,
        hy: f64,
        origin: (f64, f64),
        nx: usize,
        ny: usize,
        mask: &[bool],
        pressure: &[f64],
    ) -> Result<Self> {
        positive("element side hx", hx)?;
        positive("element side hy", hy)?;
        if mask.len() != nx * ny {
            return Err(Error::LengthMismatch { name: "mask", expected: nx * ny, got: mask.len() });
        }
        if pressure.len() != nx * ny {
            return Err(Error::LengthMismatch {
                name: "pressure",
                expected: nx * ny,
                got: pressure.len(),
            });
        }
        let mut grid =
            ContactGrid { hx, hy, x: vec![], y: vec![], pressure: vec![], patch: vec![] };
        for j in 0..ny {
            for i in 0..nx {
                if mask[j * nx + i] {
                    grid.x.push(origin.0 + (i as f64 + 0.5) * hx);
                    grid.y.push(origin.1 + (j as f64 + 0.5) * hy);
                    grid.pressure.push(non_negative("cell pressure", pressure[j * nx + i])?);
                    grid.patch.push(0);
                }
            }
        }
        if grid.x.is_empty() {
            return Err(Error::EmptyGrid { reason: "the mask selects no cell" });
        }
        Ok(grid)
    }

    /// Number of elements $N$.
    #[must_use]
    pub fn len(&self) -> usize {
        self.x.len()
    }

    /// Whether the grid has no element (never true for a constructed grid).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.x.is_empty()
    }

    /// Element area $h_x h_y$.
    #[must_use]
    pub fn element_area(&self) -> f64 {
        self.hx * self.hy
    }

    /// Discrete normal force of each element, $P_k = p_k h_x h_y$ (seed 002 §3.3.1).
    #[must_use]
    pub fn normal_force(&self) -> Vec<f64> {
        let area = self.element_area();
        self.pressure.iter().map(|p| p * area).collect()
    }

    /// Total normal force $\sum_k P_k$.
    #[must_use]
    pub fn total_normal_force(&self) -> f64 {
        self.normal_force().iter().sum()
    }

    /// Centre of the normal force, $\sum_k P_k \mathbf{x}_k / \sum_k P_k$ (the element
    /// centroid if all pressures vanish).
    #[must_use]
    pub fn force_centroid(&self) -> (f64, f64) {
        let p = self.normal_force();
        let total: f64 = p.iter().sum();
        let n = self.len() as f64;
        if total > 0.0 {
            let sx: f64 = p.iter().zip(&self.x).map(|(p, x)| p * x).sum();
            let sy: f64 = p.iter().zip(&self.y).map(|(p, y)| p * y).sum();
            (sx / total, sy / total)
        } else {
            (self.x.iter().sum::<f64>() / n, self.y.iter().sum::<f64>() / n)
        }
    }
}

impl ContactGrid {
    /// The lattice the element centres lie on: `(nx, ny, x0, y0, cell)` with the lowest
    /// centres `(x0, y0)`, the lattice size spanning all elements, and `cell[k] = j nx + i`
    /// the lattice cell of element `k` (the FFT operators work on this lattice).
    ///
    /// # Errors
    /// [`Error::EmptyGrid`] for an empty grid; [`Error::OutOfDomain`] if an element centre is
    /// not on the lattice of spacing $(h_x, h_y)$ through the lowest centre (by more than
    /// $10^{-6}$ cells), or two elements share a lattice cell.
    pub fn lattice_cells(&self) -> Result<(usize, usize, f64, f64, Vec<usize>)> {
        let n = self.len();
        if n == 0 {
            return Err(Error::EmptyGrid { reason: "the grid has no element" });
        }
        let x0 = self.x.iter().copied().fold(f64::INFINITY, f64::min);
        let y0 = self.y.iter().copied().fold(f64::INFINITY, f64::min);
        let mut idx = Vec::with_capacity(n);
        for k in 0..n {
            let fi = (self.x[k] - x0) / self.hx;
            let fj = (self.y[k] - y0) / self.hy;
            let (i, j) = (fi.round(), fj.round());
            if (fi - i).abs() > 1e-6 || (fj - j).abs() > 1e-6 {
                return Err(Error::OutOfDomain {
                    name: "element centre offset from the lattice (cells)",
                    value: (fi - i).abs().max((fj - j).abs()),
                    allowed: "<= 1e-6: all centres on one lattice of spacing (hx, hy)",
                });
            }
            idx.push((i as usize, j as usize));
        }
        let nx = idx.iter().map(|p| p.0).max().unwrap_or(0) + 1;
        let ny = idx.iter().map(|p| p.1).max().unwrap_or(0) + 1;
        let cell: Vec<usize> = idx.iter().map(|&(i, j)| j * nx + i).collect();
        let mut seen = vec![false; nx * ny];
        for (k, &c) in cell.iter().enumerate() {
            if seen[c] {
                return Err(Error::OutOfDomain {
                    name: "element sharing a lattice cell (index)",
                    value: k as f64,
                    allowed: "one element per lattice cell",
                });
            }
            seen[c] = true;
        }
        Ok((nx, ny, x0, y0, cell))
    }

    /// The grid on the lattice coarsened 2 x 2 (spacing $2h_x, 2h_y$), with `parent[k]` the
    /// coarse element holding fine element `k`: a coarse element wherever its block holds a
    /// fine one, with the block's mean pressure (missing cells counting zero, so the total
    /// normal force is kept) and the patch of its first fine element. `None` unless the
    /// lattice is at least `2 min_cells` across in both directions.
    pub fn coarsened(&self, min_cells: usize) -> Option<(ContactGrid, Vec<usize>)> {
        let (nx, ny, x0, y0, cell) = self.lattice_cells().ok()?;
        if nx < 2 * min_cells || ny < 2 * min_cells {
            return None;
        }
        let cx = nx.div_ceil(2);
        let mut index = vec![usize::MAX; cx * ny.div_ceil(2)];
        let mut coarse = ContactGrid {
            hx: 2.0 * self.hx,
            hy: 2.0 * self.hy,
            x: Vec::new(),
            y: Vec::new(),
            pressure: Vec::new(),
            patch: Vec::new(),
        };
        let mut parent = Vec::with_capacity(self.len());
        for (k, &c) in cell.iter().enumerate() {
            let (i, j) = (c % nx, c / nx);
            let b = (j / 2) * cx + i / 2;
            if index[b] == usize::MAX {
                index[b] = coarse.x.len();
                coarse.x.push(x0 + (2.0 * (i / 2) as f64 + 0.5) * self.hx);
                coarse.y.push(y0 + (2.0 * (j / 2) as f64 + 0.5) * self.hy);
                coarse.pressure.push(0.0);
                coarse.patch.push(self.patch[k]);
            }
            coarse.pressure[index[b]] += 0.25 * self.pressure[k];
            parent.push(index[b]);
        }
        Some((coarse, parent))
    }

    /// The full-slip moment about the centre of the normal force,
    /// $M_f = f\,h_xh_y\sum_k p_k\,\lvert\mathbf x_k - \mathbf c\rvert$: every element
    /// slipping at $f p_k$ perpendicular to its radius. A twisting moment alone makes the
    /// contact spin about the pivot where the full-slip traction has no resultant, and the
    /// full-slip moment about any point is least there (its gradient is that resultant), so
    /// the torsional capacity is at most $M_f$, and equal to it when the contact is
    /// symmetric about $\mathbf c$ (Lubkin's $3\pi fPa/16$ for a Hertz circle, in the limit
    /// of fine lattices). A moment above $M_f$ cannot be carried.
    #[must_use]
    pub fn spin_capacity(&self, friction: f64) -> f64 {
        let (cx, cy) = self.force_centroid();
        let sum: f64 = (0..self.len())
            .map(|k| self.pressure[k] * (self.x[k] - cx).hypot(self.y[k] - cy))
            .sum();
        friction * self.element_area() * sum
    }

    /// How far a tangential force $\mathbf T$ and a moment $M$ (about the centre of the normal
    /// force) acting together can be scaled before the contact slides: the largest $\lambda$
    /// with $\lambda(\mathbf T, M)$ inside the limit surface of Coulomb friction, estimated
    /// from above.
    ///
    /// The friction resultants the contact can carry form a convex set whose support function
    /// is the dissipation of a rigid sliding motion $(\mathbf v, \omega)$,
    /// $D = f h_xh_y\sum_k p_k\lvert\mathbf v + \omega\,\hat{\mathbf z}\times(\mathbf x_k -
    /// \mathbf c)\rvert$; so $\lambda = \min D/(\mathbf T\cdot\mathbf v + M\omega)$ over the
    /// motions that do work. The minimum is searched on a grid of 31 x 36 directions of
    /// $(\mathbf v, \bar r\omega)$ and refined by pattern search: any direction found is a
    /// certificate, so $\lambda < 1$ proves the load beyond gross slip, while a value just
    /// above 1 may still be (by the refinement's last step, about $10^{-4}$ relative).
    /// Infinite for a zero load.
    #[must_use]
    pub fn load_capacity_factor(&self, friction: f64, t: (f64, f64), m: f64) -> f64 {
        let (cx, cy) = self.force_centroid();
        let n = self.len();
        let (dx, dy): (Vec<f64>, Vec<f64>) =
            (0..n).map(|k| (self.x[k] - cx, self.y[k] - cy)).unzip();
        let wsum: f64 = self.pressure.iter().sum();
        let rbar = if wsum > 0.0 {
            (0..n).map(|k| self.pressure[k] * dx[k].hypot(dy[k])).sum::<f64>() / wsum
        } else {
            1.0
        };
        let scale = friction * self.element_area();
        // (theta, phi) -> (vx, vy, omega) with |(v, rbar omega)| = 1.
        let ratio = |th: f64, ph: f64| -> f64 {
            let (vx, vy, w) =
                (th.cos() * ph.cos(), th.cos() * ph.sin(), th.sin() / rbar.max(1e-300));
            let work = t.0 * vx + t.1 * vy + m * w;
            if work <= 0.0 {
                return f64::INFINITY;
            }
            let d: f64 =
                (0..n).map(|k| self.pressure[k] * (vx - w * dy[k]).hypot(vy + w * dx[k])).sum();
            scale * d / work
        };
        if t.0 == 0.0 && t.1 == 0.0 && m == 0.0 {
            return f64::INFINITY;
        }
        let half = std::f64::consts::FRAC_PI_2;
        let (mut best, mut bt, mut bp) = (f64::INFINITY, 0.0, 0.0);
        for i in 0..31 {
            let th = -half + std::f64::consts::PI * i as f64 / 30.0;
            for j in 0..36 {
                let ph = std::f64::consts::TAU * j as f64 / 36.0;
                let r = ratio(th, ph);
                if r < best {
                    (best, bt, bp) = (r, th, ph);
                }
            }
        }
        // Pattern search from the best sample.
        let mut step = std::f64::consts::PI / 30.0;
        while step > 1e-5 {
            let mut moved = false;
            for (a, b) in [(step, 0.0), (-step, 0.0), (0.0, step), (0.0, -step)] {
                let th = (bt + a).clamp(-half, half);
                let r = ratio(th, bp + b);
                if r < best {
                    (best, bt, bp) = (r, th, bp + b);
                    moved = true;
                }
            }
            if !moved {
                step *= 0.5;
            }
        }
        best
    }
}

fn check_count(name: &'static str, n: usize) -> Result<()> {
    if n < 2 {
        return Err(Error::OutOfDomain { name, value: n as f64, allowed: "at least 2" });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The limit surface of a Hertz circle in its two pure directions: a force alone is
    /// carried up to f P, a moment alone up to the full-slip moment (both independent sums),
    /// and a combination inside both but beyond their interaction is not.
    #[test]
    fn load_capacity_factor_matches_the_pure_capacities() {
        let (a, load, f) = (1e-3, 100.0, 0.3);
        let g = ContactGrid::hertz_circle(a, load, 64).unwrap();
        let fp = f * g.total_normal_force();
        let lam = g.load_capacity_factor(f, (0.5 * fp, 0.0), 0.0);
        assert!((lam - 2.0).abs() < 1e-6, "{lam}");
        let cap = g.spin_capacity(f);
        let lam = g.load_capacity_factor(f, (0.0, 0.0), 0.25 * cap);
        assert!((lam - 4.0).abs() < 1e-6, "{lam}");
        // Both at 0.7 of their capacity: beyond the interaction curve (the certificate is a
        // rotation about a centre off the contact).
        let lam = g.load_capacity_factor(f, (0.7 * fp, 0.0), 0.7 * cap);
        assert!(lam < 1.0, "{lam}");
    }

    /// On a fine Hertz circle the full-slip moment tends to Lubkin's gross-slip moment
    /// $3\pi fPa/16$ (an independent closed form: the integral of $f p_0\sqrt{1-r^2/a^2}$
    /// times $r$ over the disc).
    #[test]
    fn spin_capacity_of_a_hertz_circle_is_lubkins() {
        let (a, load, f) = (1e-3, 100.0, 0.3);
        let want = 3.0 * std::f64::consts::PI * f * load * a / 16.0;
        let mut last = f64::INFINITY;
        for n in [32, 128, 512] {
            let g = ContactGrid::hertz_circle(a, load, n).unwrap();
            let err = (g.spin_capacity(f) - want).abs() / want;
            assert!(err < last, "n = {n}: error {err} did not fall");
            last = err;
        }
        assert!(last < 1e-4, "error {last} at n = 512");
    }

    #[test]
    fn seed_circle_has_80_elements() {
        let g = ContactGrid::hertz_circle(0.046148, 2160.0, 10).unwrap();
        assert_eq!(g.len(), 80);
        assert!((g.total_normal_force() - 2160.0).abs() < 1e-9);
    }

    #[test]
    fn two_squares_and_overlap() {
        let sq = |cx: f64, p: f64| GridPatch {
            shape: Shape::Rectangle { cx, cy: 0.0, wx: 0.6, wy: 0.6 },
            pressure: PatchPressure::Uniform(p),
        };
        let g = ContactGrid::from_patches(0.05, 0.05, (-0.8, -0.3), &[sq(-0.5, 2e4), sq(0.5, 1e4)])
            .unwrap();
        assert_eq!(g.len(), 288);
        let f = g.normal_force();
        let p0: f64 = (0..288).filter(|&k| g.patch[k] == 0).map(|k| f[k]).sum();
        assert!((p0 - 2e4 * 0.36).abs() < 1e-8, "{p0}");
        let e = ContactGrid::from_patches(0.06, 0.06, (0.0, -0.3), &[sq(-0.5, 1.0), sq(-0.2, 1.0)]);
        assert!(matches!(e, Err(Error::OverlappingPatches { first: 0, second: 1, .. })), "{e:?}");
        let e = ContactGrid::from_patches(0.06, 0.06, (0.0, 0.0), &[]);
        assert!(matches!(e, Err(Error::EmptyGrid { .. })));
        let e = ContactGrid::from_mask(1.0, 1.0, (0.0, 0.0), 2, 2, &[false; 4], &[1.0; 4]);
        assert!(matches!(e, Err(Error::EmptyGrid { .. })));
    }
}
