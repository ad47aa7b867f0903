//! Three-dimensional steady rolling with longitudinal and lateral creepage and spin.
//!
//! Conventions (docs/FORMULAS.md, section R3): $x$ is the rolling direction. The contact moves
//! in $+x$ over both surfaces, so material enters at the leading edge (largest $x$) and leaves
//! at the trailing edge. The creepages $\xi$ (longitudinal), $\eta$ (lateral) and $\phi$ (spin,
//! 1/m) give the rigid slip of body 1 over body 2 per unit rolling distance,
//! $$\mathbf w = (\xi - \phi y,\ \eta + \phi x).$$
//! $\mathbf q$ is the tangential traction on body 1 and $\mathbf u = \mathbf u_1 - \mathbf u_2$
//! the difference of the surface displacements ($\mathbf u = K * \mathbf q$ for quasi-identical
//! bodies). In steady state a surface point crosses the contact at the rolling speed $V$, so
//! the slip per unit rolling distance is
//! $$\mathbf s = \mathbf w - \frac{\partial \mathbf u}{\partial x},$$
//! and Coulomb's law asks $\mathbf s = 0$, $|\mathbf q|\le fp$ (stick) or
//! $\mathbf q = -fp\,\mathbf s/|\mathbf s|$ (slip). The micro-slip velocity is $V\mathbf s$.
//! In the small-creepage limit $F_x = -GabC_{11}\xi$ (Kalker's sign).
//!
//! - [`SteadyRolling`]: the exact theory on a contact grid (Kalker's boundary-element
//!   discretisation, solved with FFT products);
//! - [`TransientRolling`]: the same contact rolled in steps of one element length from any
//!   state (at rest, a Cattaneo shift) under a prescribed creep force, each step the fast
//!   partial-slip solver of `stickslip-traction` with the displacement memory carried one
//!   element along; it reaches the steady state of [`SteadyRolling`];
//! - [`fastsim`]: Kalker's simplified theory (FASTSIM);
//! - [`polach`]: Polach's closed creep-force law (no spin);
//! - [`kalker`]: Kalker's creepage coefficients $C_{11}, C_{22}, C_{23}$.

mod exact;
pub mod fastsim;
mod gmres;
pub mod kalker;
pub mod polach;
mod transient;

pub use exact::{SteadyRolling, NEST_MIN_CELLS, TOLERANCE_RANGE};
pub use transient::{TransientRolling, TransientStep};

/// The largest force error of [`fastsim`] against the exact theory, relative to $fN$, over
/// the sweep of `tests/rolling3d.rs` (a/b = 0.3, 1, 3; pure and combined longitudinal,
/// lateral and spin creepage from 0.1 to 5 times the saturation scale $fp_0/G$): measured
/// 0.090 (40 cells across; 0.088 at 60); the planner uses FASTSIM only when the requested tolerance is at least this.
pub const FASTSIM_FORCE_ERROR: f64 = 0.1;

/// As [`FASTSIM_FORCE_ERROR`] for [`polach`] (no spin): measured 0.108 (0.103 at 60 cells).
pub const POLACH_FORCE_ERROR: f64 = 0.15;

/// The creepages of a rolling contact.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Creepage {
    /// Longitudinal creepage $\xi$ (dimensionless).
    pub longitudinal: f64,
    /// Lateral creepage $\eta$ (dimensionless).
    pub lateral: f64,
    /// Spin creepage $\phi$ (1/m).
    pub spin: f64,
}

impl Creepage {
    /// The rigid slip $\mathbf w$ at $(x, y)$.
    #[must_use]
    pub fn rigid_slip(&self, x: f64, y: f64) -> [f64; 2] {
        [self.longitudinal - self.spin * y, self.lateral + self.spin * x]
    }

    pub(crate) fn validate(&self) -> crate::Result<()> {
        for (name, v) in [
            ("longitudinal creepage", self.longitudinal),
            ("lateral creepage", self.lateral),
            ("spin creepage", self.spin),
        ] {
            if !v.is_finite() {
                return Err(crate::Error::OutOfDomain { name, value: v, allowed: "finite" });
            }
        }
        Ok(())
    }
}

/// Which theory produced a rolling solution.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum RollingMethod {
    /// The exact theory on the grid ([`SteadyRolling`]).
    Exact,
    /// Kalker's simplified theory ([`fastsim`]).
    Fastsim,
    /// Polach's closed creep-force law ([`polach`]): forces only.
    Polach,
    /// One step of transient rolling ([`TransientRolling`]; the fast solver's Newton steps
    /// and residual).
    Transient,
}

/// How a rolling solve went.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollingInfo {
    /// The theory used.
    pub method: RollingMethod,
    /// Outer (slip-area) iterations.
    pub iterations: usize,
    /// FFT products (inner linear iterations) in all.
    pub products: usize,
    /// Final residual: the largest $|\mathbf q - \Pi(\mathbf q - \mathbf s/D)|$ over the
    /// elements, relative to the largest traction bound $fp$ ($\Pi$: projection on the
    /// traction bound, $D$: the element's own slip stiffness); 0 means Coulomb's law holds
    /// exactly on every element. FASTSIM: 0 (it is exact for its own model).
    pub residual: f64,
}

/// The traction, slip and forces of a rolling contact on its grid.
#[derive(Debug, Clone, PartialEq)]
pub struct RollingSolution {
    /// Element centres, x (m).
    pub x: Vec<f64>,
    /// Element centres, y (m).
    pub y: Vec<f64>,
    /// Element area (m²).
    pub element_area: f64,
    /// Normal pressure (Pa).
    pub pressure: Vec<f64>,
    /// Tangential traction on body 1, x (Pa).
    pub qx: Vec<f64>,
    /// Tangential traction on body 1, y (Pa).
    pub qy: Vec<f64>,
    /// Slip per unit rolling distance, x (dimensionless; the micro-slip velocity over $V$).
    pub sx: Vec<f64>,
    /// Slip per unit rolling distance, y.
    pub sy: Vec<f64>,
    /// True where the element sticks.
    pub stick: Vec<bool>,
    /// Creep force $F_x$ on body 1 (N).
    pub fx: f64,
    /// Creep force $F_y$ on body 1 (N).
    pub fy: f64,
    /// Spin moment $M_z$ about the contact centre (N m).
    pub mz: f64,
    /// Solver report.
    pub info: RollingInfo,
}

/// The rows of a contact grid along the rolling direction: each element's lattice cell, its
/// neighbour towards the leading edge when that is a contact element, and the elements
/// ordered from the leading edge (largest x) to the trailing edge.
pub(crate) struct Rows {
    /// Lattice cell (i, j) of each element.
    pub cell: Vec<(usize, usize)>,
    /// The contact element in cell (i + 1, j), if any.
    pub up: Vec<Option<usize>>,
    /// Elements by decreasing i.
    pub order: Vec<usize>,
    /// x of the lattice's first column of centres.
    pub x0: f64,
}

impl Rows {
    /// The rows of `grid` (one lattice, no shared cells: `ContactGrid::lattice_cells`).
    pub(crate) fn of(grid: &stickslip_lattice::ContactGrid) -> crate::Result<Self> {
        let (nx, _, x0, _, cells) = grid.lattice_cells()?;
        let cell: Vec<(usize, usize)> = cells.iter().map(|&c| (c % nx, c / nx)).collect();
        let index: std::collections::HashMap<(usize, usize), usize> =
            cell.iter().enumerate().map(|(k, &c)| (c, k)).collect();
        let up = cell.iter().map(|&(i, j)| index.get(&(i + 1, j)).copied()).collect();
        let mut order: Vec<usize> = (0..cell.len()).collect();
        order.sort_by_key(|&k| std::cmp::Reverse(cell[k].0));
        Ok(Self { cell, up, order, x0 })
    }

    /// `grid` extended by the cell just ahead of each row's leading element (displaced by the
    /// rolling, never loaded; zero pressure), and for every contact element the index of its
    /// neighbour towards the leading edge in the extended grid.
    pub(crate) fn extended(
        &self,
        grid: &stickslip_lattice::ContactGrid,
    ) -> (stickslip_lattice::ContactGrid, Vec<usize>) {
        let mut ext = grid.clone();
        let up = (0..grid.len())
            .map(|k| match self.up[k] {
                Some(u) => u,
                None => {
                    ext.x.push(self.x0 + (self.cell[k].0 + 1) as f64 * grid.hx);
                    ext.y.push(grid.y[k]);
                    ext.pressure.push(0.0);
                    ext.patch.push(0);
                    ext.len() - 1
                }
            })
            .collect();
        (ext, up)
    }
}

impl RollingSolution {
    /// The solution on `grid`'s elements, with the resultants summed from the tractions.
    pub(crate) fn on_grid(
        grid: &stickslip_lattice::ContactGrid,
        q: [Vec<f64>; 2],
        s: [Vec<f64>; 2],
        stick: Vec<bool>,
        info: RollingInfo,
    ) -> Self {
        let [qx, qy] = q;
        let [sx, sy] = s;
        let a = grid.element_area();
        let fx = a * qx.iter().sum::<f64>();
        let fy = a * qy.iter().sum::<f64>();
        let mz = a * (0..grid.len()).map(|k| grid.x[k] * qy[k] - grid.y[k] * qx[k]).sum::<f64>();
        RollingSolution {
            x: grid.x.clone(),
            y: grid.y.clone(),
            element_area: a,
            pressure: grid.pressure.clone(),
            qx,
            qy,
            sx,
            sy,
            stick,
            fx,
            fy,
            mz,
            info,
        }
    }

    /// Fraction of the contact elements that stick.
    #[must_use]
    pub fn stick_fraction(&self) -> f64 {
        if self.stick.is_empty() {
            return 0.0;
        }
        self.stick.iter().filter(|&&s| s).count() as f64 / self.stick.len() as f64
    }
}
