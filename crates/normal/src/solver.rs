//! Normal contact of any surface on a rectangular lattice: the pressure, contact area and
//! approach of two elastic half-spaces (or one against a rigid body) whose initial gap is
//! given cell by cell.
//!
//! # The discrete problem
//!
//! A lattice of $n_x\times n_y$ cells of $h_x\times h_y$ (cell $(i, j)$ at index
//! `j * nx + i`, centre $x_0 + (i+\tfrac12)h_x$, $y_0 + (j+\tfrac12)h_y$) carries a uniform
//! pressure $p_k \ge 0$ per cell (compressive positive, Pa). With $g^0_k$ the initial gap
//! (m, positive = separated) at the cell centre, $\delta$ the approach (rigid-body
//! displacement of the two bodies towards each other, positive = pressed together) and
//! $u_k = \sum_j K_{kj}p_j$ the relative normal elastic displacement (positive = the surfaces
//! recede), the gap after loading is
//! $$g_k = g^0_k + u_k - \delta,$$
//! and the contact conditions are $p_k \ge 0$, $g_k \ge 0$, $p_kg_k = 0$, with either the
//! force $P = h_xh_y\sum_k p_k$ prescribed (force control; $\delta$ unknown) or $\delta$
//! prescribed (displacement control; $P$ follows).
//!
//! **Influence coefficients.** [`Boundary::Free`]: the isolated half-space. $K_{kj}$ is the
//! displacement at the centre of cell $k$ due to unit uniform pressure on cell $j$, Love's
//! exact uniform-rectangle formula ([`stickslip_halfspace::rectangle::pressure_uz`],
//! FORMULAS.md F) with the two-body constant $c_1 = \sum_i (1-\nu_i)/G_i = 2/E^*$ — the same
//! rectangles as the tangential solvers. The product is the zero-padded (aperiodic) FFT
//! convolution of [`stickslip_lattice::TensorConvolution`] (DC-FFT, no periodic images).
//! [`Boundary::Periodic`]: the lattice is one period ($L_x = n_xh_x$, $L_y = n_yh_y$) of a
//! periodic surface. Its kernel is the Fourier transfer of the half-space,
//! $\hat u(\mathbf q) = \frac{2}{E^*|\mathbf q|}\hat p(\mathbf q)$ at the lattice wave vectors
//! $\mathbf q = 2\pi(m/L_x, n/L_y)$ (Stanley & Kato 1997, *J. Tribol.* 119; the choice of
//! tamaas), the mean ($\mathbf q = 0$) term set to zero: a periodic pressure of non-zero mean
//! gives an unbounded mean displacement, so in periodic mode $\delta$ is the approach
//! relative to the mean surface displacement. This kernel is exact for the trigonometric
//! interpolant of the cell pressures (a single Fourier mode, such as Westergaard's wave in
//! full contact, is solved exactly) and differs from the uniform-rectangle one by $O(h)$ at
//! the shortest wavelengths; the sum of images of the rectangle kernel was not chosen because
//! it diverges (the $1/r$ kernel) and needs a regularisation that this transfer gives
//! directly.
//!
//! # The method
//!
//! Constrained conjugate gradients (Polonsky & Keer 1999, *Wear* 231): conjugate directions on
//! the current contact set $I_c = \{p_k > 0\}$, projection onto $p\ge 0$, re-entry of
//! penetrating non-contact cells, and (force control) the approach estimated as the mean of
//! $g^0 + u$ over $I_c$ and the pressure rescaled to the load after every step, with two
//! additions that make the number of iterations nearly independent of the lattice
//! (issue 30; measured on one band-limited rough surface, 5 % contact, tolerance $10^{-8}$:
//! 19 to 20 iterations on the finest lattice from 256² to 2048², where the same iteration
//! without both needs 45, 58 and 77 at 256², 512² and 1024²; `docs/peers.md`):
//!
//! * **Spectral preconditioner** ([`Preconditioner::Spectral`]): the residual on the contact
//!   set is multiplied by the inverse of the half-space's transfer function,
//!   $\hat M(\mathbf q) = |\mathbf q|/c_1$ with $c_1 = 2/E^*$
//!   ([`NormalOperator::precondition_rows`]), restricted again to $I_c$ and (force control)
//!   centred there: $z = P_c M P_c\,(g - \delta)$. $K$ decays like $1/|\mathbf q|$, so the
//!   spread of $K$'s spectrum, which grows like the lattice size, is what $M$ removes; the
//!   restriction to the contact set leaves a spread that grows only slowly (for the
//!   single-layer operator preconditioned by the hypersingular one on an open surface,
//!   like $\log^2 n$: McLean & Steinbach 1999, *Adv. Comput. Math.* 11). The same idea as
//!   Vollebregt's FFT-based preconditioner for CONTACT (2014, *J. Comput. Phys.* 257). The
//!   conjugacy coefficient is Polak–Ribière's, clipped at zero,
//!   $\beta = \max(0, z_k\cdot(g_k - g_{k-1}) / z_{k-1}\cdot g_{k-1})$, which restarts by
//!   itself when the contact set has turned the residual, so no reset is needed when cells
//!   re-enter. A re-entering cell takes the pressure $\tau_e(\delta - g_k)$ with
//!   $\tau_e = \mathbf t\cdot\mathbf t / \mathbf t\cdot K\mathbf t$, the inverse stiffness
//!   along the step (independent of the preconditioner's scale; equal to Polonsky and
//!   Keer's step for the plain gradient). [`Preconditioner::Identity`] is the plain iteration.
//! * **Nested start** ([`Nesting::Nested`]): a cascadic (coarse-to-fine) start, as in
//!   multilevel multi-integration (Brandt & Lubrecht 1990, *J. Comput. Phys.* 90; Venner &
//!   Lubrecht 2000): the same problem is first solved on the lattice coarsened 2 x 2 (the
//!   initial gap averaged over each block, cells twice as large, the same load), itself
//!   nested, to a loose tolerance ($10^{-3}$); its pressure is carried to the four cells of
//!   each coarse cell, and with it the contact set. The fine iteration then only settles
//!   the contact edges and the fine-scale pressure. A coarse level without contact, a coarse
//!   solve that fails, or a warm start that does not converge leaves a cold start.
//!
//! Every product with $K$ is one FFT convolution, $O(N\log N)$: one for the direction,
//! $K\mathbf t$, and $u = Kp$ updated from it ($u \leftarrow u - \tau K\mathbf t$ plus the
//! columns of the few cells clipped or re-entered, added directly when at most 16, else a
//! full product of the new $p$), with a full product every 50 iterations and before the stop.
//! The preconditioner is one more FFT pair, unpadded and in single precision (a quarter to
//! a half of a product). The passes over the lattice that the iteration needs (the gap and
//! its sums, the masked residual, the direction, the step) ride along with the transforms'
//! own row passes where they can ([`NormalOperator::apply_rows`]). Displacement control is
//! the same iteration with $\delta$ fixed, without the centring and the rescaling (the
//! bound-constrained quadratic program $\min \tfrac12 p^{\mathsf T}Kp + (g^0-\delta)^{\mathsf T}p$,
//! $p\ge0$); on a periodic lattice, where a uniform pressure moves nothing, a step whose
//! curvature falls below that of the softest non-uniform mode goes only to the first cell
//! that leaves the contact.
//!
//! # Certified stop: the residuals
//!
//! At every iteration the current pressure $p$ is checked against the conditions above with
//! $u = Kp$ and the gap $g = g^0 + u - \delta$ (force control: $\delta$ the mean of
//! $g^0 + u$ over $I_c$); the stop is accepted only on a fresh product $u = Kp$ (not the
//! incrementally updated one). The gap scale is the rigid interference
//! $s = \delta - \min_k g^0_k$ (the largest overlap the bodies would have without
//! deformation; positive whenever they touch). The solve stops when all three are at most
//! the relative tolerance $\varepsilon$:
//!
//! * **gap residual** $r_g = \max_k e_k / s$, with $e_k = |g_k|$ where $p_k > 0$ (the gap
//!   must be closed where there is pressure) and $e_k = \max(-g_k, 0)$ where $p_k = 0$ (no
//!   penetration outside the contact);
//! * **complementarity residual** $r_c = \sum_k p_k|g_k| \,/\, (s\sum_k p_k)$, the
//!   pressure-weighted mean gap under pressure relative to the scale (the complementarity
//!   work $\sum p_kg_k$ per unit force and scale; $r_c \le r_g$);
//! * **force residual** $r_F = |h_xh_y\sum_k p_k - P|/P$ under force control (0 under
//!   displacement control, where the force is the output $h_xh_y\sum_k p_k$).
//!
//! [`NormalInfo::residual`] is the largest of the three. $p \ge 0$ holds exactly.
//!
//! # Outcomes
//!
//! * Displacement control with $\delta \le \min_k g^0_k$ (the gap never closes): zero load,
//!   no contact, [`NormalSolution::no_contact`] set — a result, not an error.
//! * Full contact (every cell, e.g. a periodic surface pressed flat) is a result.
//! * [`Boundary::Periodic`] under displacement control needs $\delta$ below the mean initial
//!   gap: a uniform pressure does not move a periodic surface relative to its mean, so at
//!   $\delta \ge \overline{g^0}$ (full contact) the force is unbounded; such an approach is
//!   refused ([`Error::OutOfDomain`], named "approach"); use force control there.
//! * A contact on fewer than [`NormalProblem::with_min_contact_cells`] cells
//!   (default [`DEFAULT_MIN_CONTACT_CELLS`]) is refused with [`Error::UnresolvedContact`].
//! * [`NormalSolution::touches_boundary`] says whether, under [`Boundary::Free`], the contact
//!   reaches the lattice edge (the lattice then truncates the surface).
//!
//! [`NormalSolution::contact_grid`] turns the contact cells and their pressure into a
//! [`ContactGrid`] for the tangential solvers (partial slip on the computed contact).

use crate::error::{positive, tolerance_in, Error, Result};
use rayon::prelude::*;
use std::time::Instant;
use stickslip_halfspace::rectangle::Compliance;
use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
pub use stickslip_lattice::{Boundary, NormalOperator, NormalScratch};
use stickslip_quad::Tolerance;

/// The solver's name (as in [`Error::NotConverged`]).
pub const SOLVER_NAME: &str = "normal CCG (Polonsky-Keer)";

/// Default minimum number of contact cells for a resolved contact.
pub const DEFAULT_MIN_CONTACT_CELLS: usize = 12;

/// At most this many clipped or re-entered cells per step are corrected by adding kernel
/// columns directly ($O(N)$ each) instead of one more FFT product.
const DIRECT_CHANGES: usize = 16;

/// The incrementally updated $u = Kp$ is recomputed by a full product this often (and before
/// every certified stop).
const REFRESH: usize = 50;

/// Default iteration budget.
pub const DEFAULT_MAX_ITERATIONS: usize = 10_000;

/// The smallest lattice, in cells across in each direction, that a nested solve starts from
/// a coarser lattice's solution: a lattice at least twice this across is coarsened 2 x 2,
/// down to between this and twice this (see [`Nesting`]).
pub const NEST_MIN_CELLS: usize = 32;

/// Relative tolerance at which the coarse levels of a nested solve stop (or the problem's
/// own tolerance if looser): their contact set and pressure are only a start, and a tighter
/// coarse solve does not shorten the fine one (measured: 1e-3, 1e-4 and 1e-6 give the same
/// fine iterations on a rough surface at 512² and 1024², within one).
const COARSE_TOLERANCE: f64 = 1e-3;

/// Where the iteration starts when no warm start is given.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Nesting {
    /// From the solution of the same problem on the lattice coarsened 2 x 2 (the initial gap
    /// averaged over each 2 x 2 block, cells twice as large, the same load), itself solved
    /// the same way to a looser tolerance; its pressure, and with it its contact set, is
    /// carried to the four cells of each coarse cell. Used when both sides have at least
    /// `2 * min_cells` cells (and, periodic, are even; a free lattice of odd size gets a last
    /// coarse column or row over one fine one); otherwise a cold start. The default, with
    /// `min_cells` = [`NEST_MIN_CELLS`].
    Nested {
        /// The fewest cells a side of a coarse lattice may have ($\ge 2$).
        min_cells: usize,
    },
    /// From a uniform pressure (force control) or the rigid interference (displacement
    /// control).
    Cold,
}

/// The preconditioner of the conjugate-gradient iteration.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Preconditioner {
    /// The inverse of the half-space's transfer function on the contact set
    /// ([`NormalOperator::precondition_rows`]): one more FFT pair per iteration (a quarter
    /// of a padded product on a free lattice), iterations nearly independent of the
    /// lattice size. The default.
    Spectral,
    /// None: Polonsky & Keer's conjugate gradients on the gap itself.
    Identity,
}

/// One coarse level of a nested solve ([`NormalSolution::levels`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelInfo {
    /// Its lattice $(n_x, n_y)$.
    pub lattice: (usize, usize),
    /// Conjugate-gradient iterations on it.
    pub iterations: usize,
    /// Operator products (FFT convolutions) on it.
    pub products: usize,
    /// Preconditioner applications (FFT pairs on its torus) on it.
    pub preconditioner_products: usize,
    /// The residual it stopped at (its tolerance is the looser of the problem's and
    /// $10^{-3}$).
    pub residual: f64,
    /// Wall time of its own iteration and operator planning (without the levels below), s.
    pub seconds: f64,
}

/// The normal load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NormalLoad {
    /// Force control: the total normal force $P > 0$ (N).
    Force(f64),
    /// Displacement control: the approach $\delta$ (m, positive = pressed together).
    Approach(f64),
}

/// A validated normal-contact problem on a lattice.
#[derive(Debug, Clone)]
pub struct NormalProblem<'a> {
    nx: usize,
    ny: usize,
    hx: f64,
    hy: f64,
    origin: (f64, f64),
    gap: &'a [f64],
    bodies: [Material; 2],
    boundary: Boundary,
    tolerance: Tolerance,
    max_iterations: usize,
    min_contact_cells: usize,
    nesting: Nesting,
    preconditioner: Preconditioner,
}

/// Termination information of a normal solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NormalInfo {
    /// Which solver ([`SOLVER_NAME`]).
    pub solver: &'static str,
    /// Conjugate-gradient iterations on this lattice (coarse levels: `coarse_iterations`).
    pub iterations: usize,
    /// FFT convolutions with $K$ on this lattice (one or two per iteration, module docs).
    pub products: usize,
    /// Applications of the preconditioner on this lattice (one per iteration; 0 without).
    pub preconditioner_products: usize,
    /// Coarser lattices solved first (a nested start; 0 for a cold or warm start).
    pub levels: usize,
    /// Iterations on the coarser lattices, summed.
    pub coarse_iterations: usize,
    /// Wall time of the coarser lattices, seconds (part of `solve_seconds`).
    pub coarse_seconds: f64,
    /// Gap residual $r_g$ (module docs).
    pub gap_residual: f64,
    /// Complementarity residual $r_c$ (module docs).
    pub complementarity_residual: f64,
    /// Force residual $r_F$ (module docs; 0 under displacement control).
    pub force_residual: f64,
    /// The largest of the three.
    pub residual: f64,
    /// The gap scale $s = \delta - \min_k g^0_k$ (m) of the relative residuals.
    pub gap_scale: f64,
    /// The tolerance requested.
    pub tolerance: Tolerance,
    /// FFT size $(M_x, M_y)$ of the convolution.
    pub fft_size: (usize, usize),
    /// Wall time of the operator planning (kernel and its spectrum), seconds.
    pub setup_seconds: f64,
    /// Wall time of the iteration, seconds.
    pub solve_seconds: f64,
}

/// The solution of a normal-contact problem. Arrays are row-major, index `j * nx + i`.
#[derive(Debug, Clone, PartialEq)]
pub struct NormalSolution {
    /// Cells along $x$.
    pub nx: usize,
    /// Cells along $y$.
    pub ny: usize,
    /// Cell side along $x$ (m).
    pub hx: f64,
    /// Cell side along $y$ (m).
    pub hy: f64,
    /// Lattice corner $(x_0, y_0)$ (m).
    pub origin: (f64, f64),
    /// Pressure per cell (Pa, compressive positive, $\ge 0$).
    pub pressure: Vec<f64>,
    /// Contact flag per cell ($p_k > 0$).
    pub contact: Vec<bool>,
    /// Gap after loading $g_k = g^0_k + u_k - \delta$ (m; zero to the residual in contact).
    pub gap: Vec<f64>,
    /// Approach $\delta$ (m, positive = pressed together; periodic: relative to the mean
    /// surface displacement).
    pub approach: f64,
    /// Total normal force $P = h_xh_y\sum_k p_k$ (N).
    pub force: f64,
    /// Number of contact cells.
    pub contact_cells: usize,
    /// Contact area $h_xh_y\cdot$`contact_cells` (m²).
    pub area: f64,
    /// Contact fraction: contact cells over all cells.
    pub fraction: f64,
    /// Peak pressure $\max_k p_k$ (Pa).
    pub peak_pressure: f64,
    /// Displacement control where the gap never closes: zero load, no contact.
    pub no_contact: bool,
    /// Free boundary: the contact reaches a lattice edge.
    pub touches_boundary: bool,
    /// Termination information.
    pub info: NormalInfo,
    /// The coarser levels of a nested start, coarsest first (empty for a cold or warm start).
    pub levels: Vec<LevelInfo>,
}

impl NormalSolution {
    /// The contact cells with their pressure as a [`ContactGrid`] (element centres on the
    /// lattice, one patch) for the tangential solvers ([`stickslip_traction::GridProblem`],
    /// [`stickslip_traction::FastProblem`]).
    ///
    /// # Errors
    /// [`Error::Lattice`] (an empty grid) when there is no contact.
    pub fn contact_grid(&self) -> Result<ContactGrid> {
        Ok(ContactGrid::from_mask(
            self.hx,
            self.hy,
            self.origin,
            self.nx,
            self.ny,
            &self.contact,
            &self.pressure,
        )?)
    }

    /// Centre of cell `k` (m).
    #[must_use]
    pub fn centre(&self, k: usize) -> (f64, f64) {
        let (i, j) = (k % self.nx, k / self.nx);
        (self.origin.0 + (i as f64 + 0.5) * self.hx, self.origin.1 + (j as f64 + 0.5) * self.hy)
    }
}

impl<'a> NormalProblem<'a> {
    /// Supported relative tolerances, inclusive: below $10^{-12}$ the gap residual reaches the
    /// rounding of the FFT products (about $10^{-15}\log N$ times the ratio of the largest
    /// elastic displacement to the gap scale); above $10^{-1}$ the contact is not meaningful.
    pub const TOLERANCE_RANGE: (f64, f64) = (1e-12, 1e-1);

    /// Plan the influence operator of this problem's lattice, boundary and bodies (reusable
    /// across loads with [`NormalProblem::solve_with`]).
    #[must_use]
    pub fn operator(&self) -> NormalOperator {
        let c = Compliance::pair(&self.bodies[0], &self.bodies[1]);
        NormalOperator::new(self.nx, self.ny, (self.hx, self.hy), &c, self.boundary)
    }

    /// A problem on `nx` × `ny` cells of `cell = (hx, hy)` (m) with the initial gap `gap`
    /// (m, row-major `j * nx + i`, positive = separated) between `bodies` = [substrate,
    /// indenter]. The lattice is centred on the origin (see [`NormalProblem::with_origin`]),
    /// the tolerance $10^{-10}$ relative.
    ///
    /// # Errors
    /// [`Error::EmptyGrid`] for no cell, [`Error::LengthMismatch`] for `gap.len() != nx*ny`,
    /// [`Error::OutOfDomain`] for a non-positive cell side, a non-finite gap value (named
    /// "initial gap", the value given) or two rigid bodies.
    pub fn new(
        nx: usize,
        ny: usize,
        cell: (f64, f64),
        gap: &'a [f64],
        bodies: [Material; 2],
        boundary: Boundary,
    ) -> Result<Self> {
        if nx == 0 || ny == 0 {
            return Err(Error::EmptyGrid { reason: "the lattice has no cell" });
        }
        positive("cell side hx", cell.0)?;
        positive("cell side hy", cell.1)?;
        if gap.len() != nx * ny {
            return Err(Error::LengthMismatch {
                name: "initial gap",
                expected: nx * ny,
                got: gap.len(),
            });
        }
        if let Some(&v) = gap.iter().find(|v| !v.is_finite()) {
            return Err(Error::OutOfDomain { name: "initial gap", value: v, allowed: "finite" });
        }
        if bodies[0].is_rigid() && bodies[1].is_rigid() {
            return Err(Error::OutOfDomain {
                name: "bodies",
                value: f64::INFINITY,
                allowed: "at least one deformable body",
            });
        }
        Ok(Self {
            nx,
            ny,
            hx: cell.0,
            hy: cell.1,
            origin: (-0.5 * nx as f64 * cell.0, -0.5 * ny as f64 * cell.1),
            gap,
            bodies,
            boundary,
            tolerance: Tolerance::default(),
            max_iterations: DEFAULT_MAX_ITERATIONS,
            min_contact_cells: DEFAULT_MIN_CONTACT_CELLS,
            nesting: Nesting::Nested { min_cells: NEST_MIN_CELLS },
            preconditioner: Preconditioner::Spectral,
        })
    }

    /// Put the lattice corner (lowest $x$, $y$ cell edges) at `origin` (m).
    #[must_use]
    pub fn with_origin(mut self, origin: (f64, f64)) -> Self {
        self.origin = origin;
        self
    }

    /// Request another tolerance (checked against [`NormalProblem::TOLERANCE_RANGE`] by
    /// [`NormalProblem::solve`]).
    #[must_use]
    pub fn with_tolerance(mut self, tolerance: Tolerance) -> Self {
        self.tolerance = tolerance;
        self
    }

    /// Limit the iterations (default [`DEFAULT_MAX_ITERATIONS`]).
    #[must_use]
    pub fn with_max_iterations(mut self, max_iterations: usize) -> Self {
        self.max_iterations = max_iterations;
        self
    }

    /// The fewest contact cells accepted as a resolved contact (default
    /// [`DEFAULT_MIN_CONTACT_CELLS`]; 1 accepts any contact).
    #[must_use]
    pub fn with_min_contact_cells(mut self, cells: usize) -> Self {
        self.min_contact_cells = cells.max(1);
        self
    }

    /// Where a solve without a warm start begins (default [`Nesting::Nested`] down to
    /// [`NEST_MIN_CELLS`]; a `min_cells` below 2 is taken as 2).
    #[must_use]
    pub fn with_nesting(mut self, nesting: Nesting) -> Self {
        self.nesting = match nesting {
            Nesting::Nested { min_cells } => Nesting::Nested { min_cells: min_cells.max(2) },
            Nesting::Cold => Nesting::Cold,
        };
        self
    }

    /// The preconditioner (default [`Preconditioner::Spectral`]).
    #[must_use]
    pub fn with_preconditioner(mut self, preconditioner: Preconditioner) -> Self {
        self.preconditioner = preconditioner;
        self
    }

    /// The lattice $(n_x, n_y)$.
    #[must_use]
    pub fn lattice(&self) -> (usize, usize) {
        (self.nx, self.ny)
    }

    /// The composite modulus $E^*$ of the two bodies (Pa).
    #[must_use]
    pub fn e_star(&self) -> f64 {
        stickslip_halfspace::material::composite_modulus(&self.bodies[0], &self.bodies[1])
    }

    /// Plan the operator and solve under `load`, from a nested start (see [`Nesting`]): the
    /// coarser levels are solved first, so that their memory is released before this
    /// lattice's operator is planned.
    ///
    /// # Errors
    /// See [`NormalProblem::solve_with`].
    pub fn solve(&self, load: NormalLoad) -> Result<NormalSolution> {
        let (tol, force) = self.check_load(load)?;
        let t0 = Instant::now();
        let coarse = self.coarse_start(load);
        let coarse_seconds = t0.elapsed().as_secs_f64();
        let op = self.operator();
        self.run_from(&op, load, tol, force, coarse, coarse_seconds)
    }

    /// Solve under `load` with a planned operator (from [`NormalProblem::operator`] of this
    /// problem's lattice, boundary and bodies) and an optional initial pressure (a warm start,
    /// e.g. the previous step of a load sweep; negative values are clipped). Without a warm
    /// start the iteration starts as [`NormalProblem::with_nesting`] says (by default from
    /// the coarser lattices' solution).
    ///
    /// # Errors
    /// [`Error::ToleranceOutOfRange`]; [`Error::OutOfDomain`] for a force that is not finite
    /// and $> 0$, a non-finite approach, (periodic) an approach at or above the mean
    /// initial gap, or an operator planned for other cells, boundary or bodies; [`Error::LengthMismatch`] for an operator or warm
    /// start of another lattice; [`Error::NotConverged`] with the residual reached;
    /// [`Error::UnresolvedContact`] for a contact on fewer cells than the minimum.
    pub fn solve_with(
        &self,
        op: &NormalOperator,
        load: NormalLoad,
        warm: Option<&[f64]>,
    ) -> Result<NormalSolution> {
        let (tol, force) = self.check_load(load)?;
        self.check_operator(op)?;
        if let Some(w) = warm {
            if w.len() != self.nx * self.ny {
                return Err(Error::LengthMismatch {
                    name: "warm start",
                    expected: self.nx * self.ny,
                    got: w.len(),
                });
            }
            return self.run(op, load, tol, force, Some(w)).map(|(s, _)| s);
        }
        let t0 = Instant::now();
        let coarse = self.coarse_start(load);
        let coarse_seconds = t0.elapsed().as_secs_f64();
        self.run_from(op, load, tol, force, coarse, coarse_seconds)
    }

    /// The tolerance and the prescribed force of `load`, checked.
    fn check_load(&self, load: NormalLoad) -> Result<(f64, Option<f64>)> {
        let tol = tolerance_in(SOLVER_NAME, self.tolerance, Self::TOLERANCE_RANGE)?;
        let force = match load {
            NormalLoad::Force(p) => Some(positive("normal force", p)?),
            NormalLoad::Approach(d) => {
                if !d.is_finite() {
                    return Err(Error::OutOfDomain {
                        name: "approach",
                        value: d,
                        allowed: "finite",
                    });
                }
                None
            }
        };
        if let (NormalLoad::Approach(d), Boundary::Periodic) = (load, self.boundary) {
            let mean = in_order(self.gap.par_chunks(BLOCK).map(|b| b.iter().sum::<f64>()))
                .iter()
                .sum::<f64>()
                / self.gap.len() as f64;
            if d >= mean {
                return Err(Error::OutOfDomain {
                    name: "approach",
                    value: d,
                    allowed: "below the mean initial gap for a periodic surface (full contact: \
                              unbounded force under displacement control; use force control)",
                });
            }
        }
        Ok((tol, force))
    }

    /// An operator planned for this problem's lattice, boundary and bodies.
    fn check_operator(&self, op: &NormalOperator) -> Result<()> {
        let n = self.nx * self.ny;
        if op.lattice() != (self.nx, self.ny) {
            return Err(Error::LengthMismatch {
                name: "operator lattice",
                expected: n,
                got: op.lattice().0 * op.lattice().1,
            });
        }
        let c1 = Compliance::pair(&self.bodies[0], &self.bodies[1]).one_minus_nu;
        if op.boundary() != self.boundary || op.planned() != (self.hx, self.hy, c1) {
            return Err(Error::OutOfDomain {
                name: "operator",
                value: f64::NAN,
                allowed: "planned by NormalProblem::operator for this lattice, boundary and bodies",
            });
        }
        Ok(())
    }

    /// Iterate from the nested start `coarse` (if any) and record its levels; if the warm
    /// iteration fails to converge, solve again from a cold start, so that the nesting never
    /// turns a solvable problem into a failure.
    fn run_from(
        &self,
        op: &NormalOperator,
        load: NormalLoad,
        tol: f64,
        force: Option<f64>,
        coarse: Option<Coarse>,
        coarse_seconds: f64,
    ) -> Result<NormalSolution> {
        let t0 = Instant::now();
        let (mut s, levels) = match coarse {
            Some(c) => match self.run(op, load, tol, force, Some(&c.pressure)) {
                Ok((s, _)) => (s, c.levels),
                Err(Error::NotConverged { .. }) => {
                    (self.run(op, load, tol, force, None)?.0, vec![])
                }
                Err(e) => return Err(e),
            },
            None => (self.run(op, load, tol, force, None)?.0, vec![]),
        };
        s.info.levels = levels.len();
        s.info.coarse_iterations = levels.iter().map(|l| l.iterations).sum();
        s.info.coarse_seconds = coarse_seconds;
        s.info.solve_seconds = coarse_seconds + t0.elapsed().as_secs_f64();
        s.levels = levels;
        Ok(s)
    }

    /// The nested start: this problem on the lattice coarsened 2 x 2 (see [`Nesting`]),
    /// solved, its pressure carried to this lattice; `None` when nesting is off, the lattice
    /// is too small (or, periodic, odd), or the coarse problem has no contact or fails.
    fn coarse_start(&self, load: NormalLoad) -> Option<Coarse> {
        let (nx, ny) = (self.nx, self.ny);
        let Nesting::Nested { min_cells } = self.nesting else { return None };
        if nx < 2 * min_cells
            || ny < 2 * min_cells
            || (self.boundary == Boundary::Periodic && (nx % 2 == 1 || ny % 2 == 1))
        {
            return None;
        }
        // A free lattice of odd size gets a last coarse column (row) over one fine column
        // (row): its gap is the mean of the children it has.
        let (cx, cy) = (nx.div_ceil(2), ny.div_ceil(2));
        let g0 = self.gap;
        let mut gap = vec![0.0; cx * cy];
        gap.par_chunks_mut(cx).enumerate().for_each(|(jc, row)| {
            for (ic, v) in row.iter_mut().enumerate() {
                let (mut sum, mut m) = (0.0, 0.0);
                for j in 2 * jc..(2 * jc + 2).min(ny) {
                    for i in 2 * ic..(2 * ic + 2).min(nx) {
                        sum += g0[j * nx + i];
                        m += 1.0;
                    }
                }
                *v = sum / m;
            }
        });
        let tolerance = Tolerance::relative(self.tolerance.rel().max(COARSE_TOLERANCE)).ok()?;
        let coarse = NormalProblem {
            nx: cx,
            ny: cy,
            hx: 2.0 * self.hx,
            hy: 2.0 * self.hy,
            origin: self.origin,
            gap: &gap,
            bodies: self.bodies,
            boundary: self.boundary,
            tolerance,
            max_iterations: self.max_iterations,
            min_contact_cells: 1,
            nesting: self.nesting,
            preconditioner: self.preconditioner,
        };
        let s = coarse.solve(load).ok()?;
        drop(gap);
        if s.contact_cells == 0 {
            return None;
        }
        let mut pressure = vec![0.0; nx * ny];
        pressure.par_chunks_mut(nx).enumerate().for_each(|(j, row)| {
            let src = &s.pressure[(j / 2) * cx..(j / 2 + 1) * cx];
            for (i, p) in row.iter_mut().enumerate() {
                *p = src[i / 2];
            }
        });
        let mut levels = s.levels;
        levels.push(LevelInfo {
            lattice: (cx, cy),
            iterations: s.info.iterations,
            products: s.info.products,
            preconditioner_products: s.info.preconditioner_products,
            residual: s.info.residual,
            seconds: s.info.setup_seconds + s.info.solve_seconds - s.info.coarse_seconds,
        });
        Some(Coarse { pressure, levels })
    }

    /// The iteration of the module docs on this lattice from `warm` (or a cold start); also
    /// returns whether it started warm.
    fn run(
        &self,
        op: &NormalOperator,
        load: NormalLoad,
        tol: f64,
        force: Option<f64>,
        warm: Option<&[f64]>,
    ) -> Result<(NormalSolution, bool)> {
        let (nx, n) = (self.nx, self.nx * self.ny);
        let t0 = Instant::now();
        let area = self.hx * self.hy;
        let g0 = self.gap;
        let gmin = g0.par_iter().copied().reduce(|| f64::INFINITY, f64::min);

        // Displacement control where the gap never closes: zero load, said so.
        if let NormalLoad::Approach(d) = load {
            if d <= gmin {
                let info = self.info(op, 0, 0, 0, (0.0, 0.0, 0.0, 0.0), 0.0, t0);
                return Ok((
                    self.finish(vec![0.0; n], g0.iter().map(|g| g - d).collect(), d, info),
                    false,
                ));
            }
        }

        let mut p = vec![0.0; n];
        match (warm, load) {
            (Some(w), _) => p.par_iter_mut().zip(w).for_each(|(p, w)| *p = w.max(0.0)),
            (None, NormalLoad::Approach(d)) => {
                let k0 = op.self_term();
                p.par_iter_mut().zip(g0).for_each(|(p, g)| *p = ((d - g) / k0).max(0.0));
            }
            (None, NormalLoad::Force(_)) => p.fill(1.0),
        }
        if let Some(pf) = force {
            if !rescale(&mut p, pf / area) {
                // A zero warm start: begin uniform.
                p.fill(1.0);
                rescale(&mut p, pf / area);
            }
        }

        let spectral = self.preconditioner == Preconditioner::Spectral;
        // Periodic displacement control: the smallest non-zero eigenvalue of K, c_1 / |q|_max
        // at the corner of the lattice's wave vectors (the mean mode's is zero).
        let null_mode = match (load, self.boundary) {
            (NormalLoad::Approach(_), Boundary::Periodic) => {
                let qmax = std::f64::consts::PI * (self.hx.powi(-2) + self.hy.powi(-2)).sqrt();
                Some(op.planned().2 / qmax)
            }
            _ => None,
        };
        let mut scratch = op.make_scratch();
        let mut u = vec![0.0; n];
        // The gap without the approach, g0 + u (the approach is subtracted where it is used).
        let mut g = vec![0.0; n];
        // The search direction, and the residual z (preconditioned) and K t in turn.
        let mut t = vec![0.0; n];
        let mut r = vec![0.0; n];
        // The previous gap on the contact set, for the Polak-Ribiere coefficient (single
        // precision: it only enters the coefficient).
        let mut gp = vec![0.0f32; n];
        let mut rz_old = 0.0;
        let mut conjugate = false;
        let (mut iterations, mut products, mut pre) = (0, 0, 0);
        // `u = Kp` is updated from the products of the step (one convolution per iteration
        // when few cells are clipped or re-enter); `fresh` says it is a full product of the
        // current p, which the certified stop requires.
        let mut fresh = false;
        // Force control: the rescaling factor of p (and of an incrementally updated u) still
        // to apply, fused into the next pass over the lattice.
        let mut pending = 1.0;
        let mut delta;
        let mut res;
        let sum_target = force.map(|f| f / area);
        loop {
            if !fresh {
                if pending != 1.0 {
                    let f = pending;
                    p.par_iter_mut().for_each(|p| *p *= f);
                    pending = 1.0;
                }
                op.apply(&p, &mut u, &mut scratch);
                products += 1;
                fresh = true;
            }
            // The pending rescaling, the gap without the approach, and what the approach and
            // the residuals need, in one pass.
            let f = pending;
            pending = 1.0;
            let a = in_order(
                g.par_chunks_mut(BLOCK)
                    .zip(u.par_chunks_mut(BLOCK))
                    .zip(g0.par_chunks(BLOCK).zip(p.par_chunks_mut(BLOCK)))
                    .map(|((g, u), (g0, p))| {
                        let mut a = GapSums::EMPTY;
                        for (g, (u, (g0, p))) in
                            g.iter_mut().zip(u.iter_mut().zip(g0.iter().zip(p)))
                        {
                            *p *= f;
                            *u *= f;
                            *g = *u + g0;
                            a.add(*g, *p);
                        }
                        a
                    }),
            )
            .into_iter()
            .fold(GapSums::EMPTY, GapSums::merge);
            delta = match load {
                NormalLoad::Approach(d) => d,
                NormalLoad::Force(_) => a.sum / a.cells.max(1) as f64,
            };
            res = a.residuals(delta, delta - gmin, sum_target);
            // The complementarity residual is at most the gap residual (module docs), so the
            // gap and force residuals decide the stop; it is computed at the end.
            if res.0.max(res.1) <= tol {
                if fresh {
                    break;
                }
                // Certify with a full product.
                continue;
            }
            if iterations >= self.max_iterations {
                return Err(Error::NotConverged {
                    solver: SOLVER_NAME,
                    iterations,
                    residual: res.0.max(res.1),
                    tolerance: tol,
                });
            }
            iterations += 1;
            let (c, mean_force) = (a.cells, force.is_some());
            // The preconditioned residual z = M (g - delta) on the contact set, into r, with
            // its sums: sum z, sum (g - delta) z, sum gp z, sum gp over the contact set.
            let zs = if spectral {
                pre += 1;
                let (p, g, gp) = (&p, &g, &gp);
                op.precondition_rows(
                    |j, row| {
                        let (p, g) = (&p[j * nx..(j + 1) * nx], &g[j * nx..(j + 1) * nx]);
                        for (v, (p, g)) in row.iter_mut().zip(p.iter().zip(g)) {
                            *v = if *p > 0.0 { (g - delta) as f32 } else { 0.0 };
                        }
                    },
                    &mut r,
                    |j, z| {
                        let cells = p[j * nx..(j + 1) * nx]
                            .iter()
                            .zip(&g[j * nx..(j + 1) * nx])
                            .zip(&gp[j * nx..(j + 1) * nx]);
                        let mut acc = [0.0; 4];
                        for (z, ((p, g), gp)) in z.iter_mut().zip(cells) {
                            if *p > 0.0 {
                                let gp = f64::from(*gp);
                                acc = [
                                    acc[0] + *z,
                                    acc[1] + (g - delta) * *z,
                                    acc[2] + gp * *z,
                                    acc[3] + gp,
                                ];
                            } else {
                                *z = 0.0;
                            }
                        }
                        acc
                    },
                    &mut scratch,
                )
            } else {
                in_order(
                    r.par_chunks_mut(BLOCK)
                        .zip(p.par_chunks(BLOCK).zip(g.par_chunks(BLOCK).zip(gp.par_chunks(BLOCK))))
                        .map(|(z, (p, (g, gp)))| {
                            let mut acc = [0.0; 4];
                            for (z, (p, (g, gp))) in
                                z.iter_mut().zip(p.iter().zip(g.iter().zip(gp)))
                            {
                                if *p > 0.0 {
                                    let gp = f64::from(*gp);
                                    *z = g - delta;
                                    acc = [
                                        acc[0] + *z,
                                        acc[1] + (g - delta) * *z,
                                        acc[2] + gp * *z,
                                        acc[3] + gp,
                                    ];
                                } else {
                                    *z = 0.0;
                                }
                            }
                            acc
                        }),
                )
            }
            .into_iter()
            .fold([0.0; 4], |x, y| [x[0] + y[0], x[1] + y[1], x[2] + y[2], x[3] + y[3]]);
            // Force control keeps sum p: the direction has zero sum on the contact set.
            let m = if mean_force { zs[0] / c.max(1) as f64 } else { 0.0 };
            let gd_sum = a.sum - delta * c as f64;
            let rz = zs[1] - m * gd_sum;
            let zgp = zs[2] - m * zs[3];
            // Polak-Ribiere, clipped at zero (a restart when the contact set has turned the
            // new residual against the old direction).
            let beta = if conjugate && rz_old > 0.0 { ((rz - zgp) / rz_old).max(0.0) } else { 0.0 };
            rz_old = rz;
            // The direction t = (z - m) + beta t on the contact set, gp = g - delta there, and
            // sum t, sum t^2, sum (g - delta) t, and the first breakpoint min p / t (t > 0).
            let e = in_order(
                t.par_chunks_mut(BLOCK)
                    .zip(gp.par_chunks_mut(BLOCK))
                    .zip(r.par_chunks(BLOCK).zip(g.par_chunks(BLOCK).zip(p.par_chunks(BLOCK))))
                    .map(|((t, gp), (z, (g, p)))| {
                        let mut acc = [0.0, 0.0, 0.0, f64::INFINITY];
                        for ((t, gp), (z, (g, p))) in
                            t.iter_mut().zip(gp.iter_mut()).zip(z.iter().zip(g.iter().zip(p)))
                        {
                            if *p > 0.0 {
                                let gd = g - delta;
                                *t = (z - m) + beta * *t;
                                *gp = gd as f32;
                                acc = [acc[0] + *t, acc[1] + *t * *t, acc[2] + gd * *t, acc[3]];
                                if *t > 0.0 {
                                    acc[3] = acc[3].min(p / *t);
                                }
                            } else {
                                *t = 0.0;
                                *gp = 0.0;
                            }
                        }
                        acc
                    }),
            )
            .into_iter()
            .fold([0.0, 0.0, 0.0, f64::INFINITY], |x, y| {
                [x[0] + y[0], x[1] + y[1], x[2] + y[2], x[3].min(y[3])]
            });
            // r = K t, with sum r and sum r t over the contact set.
            let kt = {
                let (p, t) = (&p, &t);
                op.apply_rows(
                    |j, row| row[..nx].copy_from_slice(&t[j * nx..(j + 1) * nx]),
                    &mut r,
                    |j, r| {
                        let cells = p[j * nx..(j + 1) * nx].iter().zip(&t[j * nx..(j + 1) * nx]);
                        let mut acc = [0.0; 2];
                        for (r, (p, t)) in r.iter().zip(cells) {
                            if *p > 0.0 {
                                acc = [acc[0] + r, acc[1] + r * t];
                            }
                        }
                        acc
                    },
                    &mut scratch,
                )
            }
            .into_iter()
            .fold([0.0; 2], |x, y| [x[0] + y[0], x[1] + y[1]]);
            products += 1;
            // tau = sum (g - delta) t / sum (r - rbar) t over I_c (force control: rbar the
            // mean of r there); re-entering cells take -(g - delta) sum t^2 / sum (r - rbar) t,
            // the step's own inverse stiffness, which does not depend on the
            // preconditioner's scale.
            let rbar = if mean_force { kt[0] / c.max(1) as f64 } else { 0.0 };
            let den = kt[1] - rbar * e[0];
            let num = e[2];
            if !(den > 0.0 && num > 0.0 && den.is_finite() && num.is_finite()) {
                // Not a descent direction (the contact set turned it): restart from the
                // residual; without a previous direction there is no step to take.
                if beta == 0.0 {
                    return Err(Error::NotConverged {
                        solver: SOLVER_NAME,
                        iterations,
                        residual: res.0.max(res.1),
                        tolerance: tol,
                    });
                }
                conjugate = false;
                continue;
            }
            let (mut tau, mut tau_e) = (num / den, e[1] / den);
            if let Some(kmin) = null_mode {
                // Periodic, displacement control: a uniform pressure moves nothing, so near
                // full contact the direction's mean has no curvature and the quadratic step
                // runs away. Below the smallest curvature of the other modes, step to the first
                // cell that leaves the contact instead (an active-set step), and let cells
                // re-enter with at most the softest mode's inverse stiffness.
                if den < kmin * e[1] {
                    tau = tau.min(e[3]);
                    tau_e = tau_e.min(1.0 / kmin);
                }
            }
            // Step, projection, re-entry of penetrating cells, u -= tau K t, and the new force,
            // in one pass; `changes` the departures from p - tau t (clipped or re-entered
            // cells), whose columns correct u.
            let blocks = in_order(
                p.par_chunks_mut(BLOCK)
                    .zip(u.par_chunks_mut(BLOCK))
                    .zip(g.par_chunks(BLOCK).zip(t.par_chunks(BLOCK).zip(r.par_chunks(BLOCK))))
                    .enumerate()
                    .map(|(b, ((p, u), (g, (t, r))))| {
                        let (mut ch, mut sum) = (Vec::new(), 0.0);
                        let cells =
                            p.iter_mut().zip(u.iter_mut().zip(g.iter().zip(t.iter().zip(r))));
                        for (i, (p, (u, (g, (t, r))))) in cells.enumerate() {
                            let k = b * BLOCK + i;
                            *u -= tau * r;
                            if *p > 0.0 {
                                let free = *p - tau * t;
                                *p = free.max(0.0);
                                if free < 0.0 {
                                    ch.push((k, -free));
                                }
                            } else if *g < delta {
                                *p = tau_e * (delta - g);
                                ch.push((k, *p));
                            }
                            sum += *p;
                        }
                        (ch, sum)
                    }),
            );
            let sum = blocks.iter().fold(0.0, |a, b| a + b.1);
            let changes: Vec<(usize, f64)> = blocks.into_iter().flat_map(|b| b.0).collect();
            conjugate = true;
            // Few changes: add their columns to u; many: a full product at the next check
            // (the same cost as correcting by one convolution, and exact).
            let incremental = changes.len() <= DIRECT_CHANGES;
            if incremental {
                op.add_columns(&changes, &mut u);
            }
            fresh = incremental && iterations % REFRESH != 0;
            match force {
                Some(pf) => {
                    if sum > 0.0 {
                        // Applied to p and u by the next pass (or before the next product).
                        pending = pf / area / sum;
                    } else {
                        // Everything left the contact: restart uniform.
                        p.fill(1.0);
                        rescale(&mut p, pf / area);
                        conjugate = false;
                        fresh = false;
                    }
                }
                None => {
                    if sum == 0.0 {
                        // Everything left the contact: restart from the rigid interference.
                        let (k0, d) = (op.self_term(), delta);
                        p.par_iter_mut().zip(g0).for_each(|(p, g)| *p = ((d - g) / k0).max(0.0));
                        conjugate = false;
                        fresh = false;
                    }
                }
            }
        }
        drop((u, t, r, gp, scratch));
        // The gap with the approach, and the complementarity residual.
        let (pg, ps) = in_order(g.par_chunks_mut(BLOCK).zip(p.par_chunks(BLOCK)).map(|(g, p)| {
            let mut acc = (0.0, 0.0);
            for (g, p) in g.iter_mut().zip(p) {
                *g -= delta;
                if *p > 0.0 {
                    acc = (acc.0 + p * g.abs(), acc.1 + p);
                }
            }
            acc
        }))
        .into_iter()
        .fold((0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1));
        let scale = (delta - gmin).max(f64::MIN_POSITIVE);
        let rc = if ps > 0.0 { pg / (ps * scale) } else { 0.0 };
        let residuals = (res.0, rc, res.1, res.0.max(res.1).max(rc));
        let info = self.info(op, iterations, products, pre, residuals, delta - gmin, t0);
        let s = self.finish(p, g, delta, info);
        if s.contact_cells < self.min_contact_cells {
            return Err(Error::UnresolvedContact {
                cells: s.contact_cells,
                minimum: self.min_contact_cells,
            });
        }
        Ok((s, warm.is_some()))
    }

    /// The termination information of a solve on this lattice; `residuals` = gap,
    /// complementarity, force and their largest.
    #[allow(clippy::too_many_arguments)]
    fn info(
        &self,
        op: &NormalOperator,
        iterations: usize,
        products: usize,
        preconditioner_products: usize,
        residuals: (f64, f64, f64, f64),
        gap_scale: f64,
        t0: Instant,
    ) -> NormalInfo {
        NormalInfo {
            solver: SOLVER_NAME,
            iterations,
            products,
            preconditioner_products,
            levels: 0,
            coarse_iterations: 0,
            coarse_seconds: 0.0,
            gap_residual: residuals.0,
            complementarity_residual: residuals.1,
            force_residual: residuals.2,
            residual: residuals.3,
            gap_scale,
            tolerance: self.tolerance,
            fft_size: op.fft_size(),
            setup_seconds: op.setup_seconds(),
            solve_seconds: t0.elapsed().as_secs_f64(),
        }
    }

    fn finish(
        &self,
        pressure: Vec<f64>,
        gap: Vec<f64>,
        approach: f64,
        info: NormalInfo,
    ) -> NormalSolution {
        let (nx, ny) = (self.nx, self.ny);
        let area = self.hx * self.hy;
        let contact: Vec<bool> = pressure.iter().map(|&p| p > 0.0).collect();
        let contact_cells = contact.iter().filter(|&&c| c).count();
        let touches_boundary = self.boundary == Boundary::Free
            && contact.iter().enumerate().any(|(k, &c)| {
                let (i, j) = (k % nx, k / nx);
                c && (i == 0 || j == 0 || i + 1 == nx || j + 1 == ny)
            });
        NormalSolution {
            nx,
            ny,
            hx: self.hx,
            hy: self.hy,
            origin: self.origin,
            force: area * pressure.iter().sum::<f64>(),
            peak_pressure: pressure.iter().copied().fold(0.0, f64::max),
            contact_cells,
            area: area * contact_cells as f64,
            fraction: contact_cells as f64 / (nx * ny) as f64,
            no_contact: contact_cells == 0,
            touches_boundary,
            pressure,
            contact,
            gap,
            approach,
            info,
            levels: Vec::new(),
        }
    }
}

/// A nested start: the coarse levels' pressure on this lattice, and the levels.
struct Coarse {
    pressure: Vec<f64>,
    levels: Vec<LevelInfo>,
}

/// What one pass over the gap $g^0 + u$ gathers for the approach and the residuals: over the
/// contact set ($p > 0$) the sum, count, largest and smallest gap and the pressure sum; off
/// it the smallest gap.
#[derive(Debug, Clone, Copy)]
struct GapSums {
    sum: f64,
    cells: usize,
    max_in: f64,
    min_in: f64,
    min_out: f64,
    pressure: f64,
}

impl GapSums {
    const EMPTY: Self = Self {
        sum: 0.0,
        cells: 0,
        max_in: f64::NEG_INFINITY,
        min_in: f64::INFINITY,
        min_out: f64::INFINITY,
        pressure: 0.0,
    };

    fn add(&mut self, g: f64, p: f64) {
        if p > 0.0 {
            self.sum += g;
            self.cells += 1;
            self.max_in = self.max_in.max(g);
            self.min_in = self.min_in.min(g);
            self.pressure += p;
        } else {
            self.min_out = self.min_out.min(g);
        }
    }

    fn merge(a: Self, b: Self) -> Self {
        Self {
            sum: a.sum + b.sum,
            cells: a.cells + b.cells,
            max_in: a.max_in.max(b.max_in),
            min_in: a.min_in.min(b.min_in),
            min_out: a.min_out.min(b.min_out),
            pressure: a.pressure + b.pressure,
        }
    }

    /// The gap residual $r_g$ and the force residual $r_F$ of the module docs at the approach
    /// `delta`, `scale` the gap scale, `sum` the prescribed $\sum_k p_k$ (force control).
    fn residuals(&self, delta: f64, scale: f64, sum: Option<f64>) -> (f64, f64) {
        let scale = if scale > 0.0 { scale } else { f64::MIN_POSITIVE };
        // |g - delta| on the contact set, penetration delta - g off it.
        let e = (self.max_in - delta).max(delta - self.min_in).max(delta - self.min_out).max(0.0);
        let rf = sum.map_or(0.0, |s| (self.pressure - s).abs() / s);
        (e / scale, rf)
    }
}

/// Cells per block of the parallel passes. Every sum over the lattice adds fixed blocks of
/// this many cells (each in index order) and then the block results in block order, so a
/// solve gives the same bits for any number of threads.
const BLOCK: usize = 4096;

/// The results of a parallel pass over blocks, in block order (their sum, taken by the caller
/// in this order, does not depend on how rayon split the work).
fn in_order<T: Send>(blocks: impl IndexedParallelIterator<Item = T>) -> Vec<T> {
    let mut out = Vec::with_capacity(blocks.len());
    blocks.collect_into_vec(&mut out);
    out
}

/// Scale `p` to the sum `target`; false if its sum is zero.
fn rescale(p: &mut [f64], target: f64) -> bool {
    let s = in_order(p.par_chunks(BLOCK).map(|b| b.iter().sum::<f64>())).iter().sum::<f64>();
    if s > 0.0 {
        let f = target / s;
        p.par_iter_mut().for_each(|p| *p *= f);
        true
    } else {
        false
    }
}
