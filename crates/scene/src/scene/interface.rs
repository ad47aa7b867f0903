//! `[interface]` (a hardness cap, Maugis–Dugdale adhesion) and the approach path that
//! poses an adhesive contact, with the lattice checks they need.

use super::Surface;

/// The interface between the bodies beyond elastic contact with Coulomb friction
/// (`[interface]`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Interface {
    /// The hardness H (Pa): the contact pressure is capped at H (an elastic–perfectly
    /// plastic interface; cells at H are plastic and their gap closes by plastic flow).
    /// Solved on a surface lattice only.
    pub hardness: Option<f64>,
    /// Maugis–Dugdale adhesion (`interface.adhesion`), solved on a surface lattice under an
    /// approach.
    pub adhesion: Option<AdhesionKeys>,
}

/// `interface.adhesion`: a Maugis–Dugdale interface, the constant attraction
/// $\sigma_0 = w/h_0$ wherever the gap is below $h_0$.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdhesionKeys {
    /// The work of adhesion w (J/m^2).
    pub work: f64,
    /// The range h0 of the attraction (m).
    pub range: f64,
}

/// An approach path `[from, to, steps]`: the approach goes from corner to corner in
/// `steps` equal steps per leg, each step solved from the one before (so an
/// approach–retraction curve follows its branch: jump-in, adhesion hysteresis, pull-off).
#[derive(Debug, Clone, PartialEq)]
pub struct ApproachPath {
    /// The corners (m), at least two; any sign (negative: the surfaces held apart).
    pub corners: Vec<f64>,
    /// Points per leg, the two corners included (>= 2).
    pub steps: usize,
}

impl ApproachPath {
    /// The largest number of points per leg.
    pub const MAX_STEPS: usize = 1000;
    /// The largest number of points of the whole path.
    pub const MAX_POINTS: usize = 10_000;

    /// The deepest (largest) approach of the path (m).
    #[must_use]
    pub fn deepest(&self) -> f64 {
        self.corners.iter().copied().fold(f64::NEG_INFINITY, f64::max)
    }

    /// The approach of every point of the path, in order; a corner shared by two legs
    /// appears once.
    #[must_use]
    pub fn approaches(&self) -> Vec<f64> {
        let n = self.steps.max(2);
        let mut out = vec![self.corners[0]];
        for w in self.corners.windows(2) {
            for i in 1..n {
                // weighted so that the corners are exact and a zero crossing at a
                // point of the path lands on 0
                let (u, v) = ((n - 1 - i) as f64, i as f64);
                out.push((w[0] * u + w[1] * v) / (n - 1) as f64);
            }
        }
        out
    }
}

impl Surface {
    /// The initial gap on the lattice (m, positive = apart): the profile minus the
    /// roughness at the cell centres, row-major `j * nx + i`, the lattice centred on the
    /// origin.
    #[must_use]
    pub fn initial_gap(&self) -> Vec<f64> {
        let [nx, ny] = self.cells;
        let (hx, hy) = (self.size[0] / nx as f64, self.size[1] / ny as f64);
        let (x0, y0) = (-0.5 * self.size[0], -0.5 * self.size[1]);
        let mut gap = Vec::with_capacity(nx * ny);
        for j in 0..ny {
            for i in 0..nx {
                let (x, y) = (x0 + (i as f64 + 0.5) * hx, y0 + (j as f64 + 0.5) * hy);
                let h = self.roughness.as_ref().map_or(0.0, |h| h[j * nx + i]);
                gap.push(self.profile.gap(x, y) - h);
            }
        }
        gap
    }
}

/// How finely a lattice resolves an adhesive range: the largest step of the initial gap
/// between two neighbouring cells (along x or y, across the period on a periodic lattice)
/// among the cells that come within the range at the deepest approach without deformation
/// ($g^0_k - \delta_{max} < h_0$, either cell of the pair).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeightStep {
    /// The largest step (m); 0 when no cell comes within range.
    pub step: f64,
    /// The lower-left cell of the pair `(i, j)`.
    pub cell: (usize, usize),
    /// Cells in reach.
    pub cells_in_reach: usize,
}

impl HeightStep {
    /// The step of `gap` (an `nx` x `ny` lattice, row-major) within reach of `range` at the
    /// approach `deepest`.
    #[must_use]
    pub fn of(gap: &[f64], nx: usize, ny: usize, periodic: bool, deepest: f64, range: f64) -> Self {
        let reach = |k: usize| gap[k] - deepest < range;
        let mut out = Self { step: 0.0, cell: (0, 0), cells_in_reach: 0 };
        for j in 0..ny {
            for i in 0..nx {
                let k = j * nx + i;
                if reach(k) {
                    out.cells_in_reach += 1;
                }
                let right = if i + 1 < nx { Some(k + 1) } else { periodic.then_some(j * nx) };
                let up = if j + 1 < ny { Some(k + nx) } else { periodic.then_some(i) };
                for m in [right, up].into_iter().flatten() {
                    if reach(k) || reach(m) {
                        let d = (gap[k] - gap[m]).abs();
                        if d > out.step {
                            out.step = d;
                            out.cell = (i, j);
                        }
                    }
                }
            }
        }
        out
    }
}
