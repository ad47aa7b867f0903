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
//! columns of the few cells clipped or re-entered, added directly when at most 24 on a
//! periodic lattice and about four times as many on a free one, else a full product of the
//! new $p$), with a full product every 50 iterations and before the stop.
//! The preconditioner is one more FFT pair, unpadded and in single precision (a quarter to
//! a half of a product). The passes over the lattice that the iteration needs ride along
//! with the transforms' own row passes where they can ([`NormalOperator::apply_rows`]): the
//! masked residual and the previous one with the preconditioner, the direction with the
//! product $K\mathbf t$, the pending rescaling of $p$ with a full product; after a step that
//! clipped and re-entered no cell, the step itself writes the next gap, its sums and the
//! free set (at the rescaling that will bring the force back to the load, known before the
//! step in that case), so that no separate pass over the gap is needed. The passes that only
//! need the free set read it as a byte a cell. Displacement control is
//! the same iteration with $\delta$ fixed, without the centring and the rescaling (the
//! bound-constrained quadratic program $\min \tfrac12 p^{\mathsf T}Kp + (g^0-\delta)^{\mathsf T}p$,
//! $p\ge0$); on a periodic lattice, where a uniform pressure moves nothing, a step whose
//! curvature falls below that of the softest non-uniform mode goes only to the first cell
//! that leaves the contact.
//!
//! # Hardness
//!
//! With [`NormalProblem::with_hardness`] the pressure is capped at the hardness $H$ (an
//! elastic–perfectly plastic interface, as tamaas's saturated pressure): $0 \le p_k \le H$,
//! with $g_k = 0$ where $0 < p_k < H$, $g_k \ge 0$ where $p_k = 0$ and $g_k \le 0$ where
//! $p_k = H$ (plastic: the interpenetration $-g_k$ is the plastic displacement that plastic
//! flow removes; the solution reports the gap there as 0). Under displacement control this is
//! the quadratic program above on the box $0 \le p \le H$, and the iteration is the same
//! with the box: the conjugate directions live on the free set $0 < p < H$, the step is
//! projected onto $[0, H]$, and besides the re-entry of penetrating cells a plastic cell
//! whose gap has opened leaves the cap by $\tau_e(g_k - \delta)$. The gap residual counts an
//! open gap at the cap as a violation. Under force control the approach is the unknown and
//! the force a constraint: the same iteration with the direction centred on the free set
//! (as the elastic force-controlled iteration centres it on the contact set), and after a
//! step that has moved the force (cells clipped at 0 or $H$, re-entered or released) the
//! pressure is projected back onto the force: the Euclidean projection onto
//! $\{0 \le p \le H,\ h_xh_y\sum_k p_k = P\}$ restricted to the free cells,
//! $p_k \leftarrow \min(\max(p_k - \mu, 0), H)$ with the scalar $\mu$ found exactly by a
//! search over the pieces of the monotone, piecewise-linear sum (no product with $K$); over
//! every pressed cell when the free ones cannot carry the force, and over all cells (those
//! off the contact at the value a gradient step would give them, $\tau_e(\delta - g_k) < 0$,
//! so that the nearest enter first) when those cannot either. The projection is done when
//! the force is off by more than a tenth of the tolerance (the stop checks the force
//! residual all the same), and $u = Kp$ is then recomputed by a full product. Rescaling the
//! pressure to the load, as the elastic iteration does, would push plastic cells off the
//! cap or through it (tried: it oscillates at 1024² once most of the contact is plastic).
//! With the approach of the free cells' mean gap (with no free cell, the approach that
//! best closes the plastic gaps), measured on the rough surface of `docs/peers.md` at
//! 1024² (tolerance $10^{-8}$): 15 to 24 fine iterations for caps that leave 37 % to 98 %
//! of the contact plastic, where the elastic solve takes 20. Should that iteration not
//! converge within 400 steps, the force is reached instead by a secant on $F(\delta)$
//! (continuous, non-decreasing), kept inside the bracket of the approaches tried (false
//! position when it leaves it), over displacement-controlled solves from a cold start,
//! each from the previous pressure and, far from the load, to a looser tolerance (a
//! thousandth of the force error); [`NormalInfo::approach_steps`] counts them (0 when the
//! projected iteration converged). The nested start carries the coarse capped pressure,
//! projected onto the force (a rescaling would move its plastic cells off the cap). A force at or above $H$
//! times the lattice area is refused ([`Error::AboveCapacity`]).
//!
//! # Adhesion
//!
//! [`NormalProblem::solve_adhesive`] adds a Maugis–Dugdale interface ([`Adhesion`]: the work
//! of adhesion $w$ and the range $h_0$; Maugis 1992, *J. Colloid Interface Sci.* 150): the
//! constant tensile traction $\sigma_0 = w/h_0$ acts wherever the gap is below the range,
//! the contact ($g = 0$) included. With $f_k \in [0, 1]$ the share of cell $k$ where the gap
//! is below the range (below) and $p^c \ge 0$ the contact pressure, the total pressure is
//! $p_k = p^c_k - \sigma_0f_k$ and $g = g^0 + Kp - \delta$ with $p^c_kg_k = 0$, $g_k \ge 0$.
//! For fixed shares this is the elastic contact problem above with the initial gap
//! $g^0 - \sigma_0Kf$, solved by the same iteration; the shares are then replaced by those
//! of that solution's gap, $f \leftarrow F(g)$, until they reproduce themselves (below).
//! Each contact solve starts from the previous contact pressure. Force control is not
//! offered: on the unstable branch of adhesion the force does not determine the state.
//! Adhesion and a hardness together are refused.
//!
//! **The zone inside a cell.** The cohesive zone of a stiff, strongly adhesive contact (the
//! JKR end, Maugis parameter $\lambda > 5$) is a ring of width about $0.02a$ at the pull-off
//! for $\lambda = 6$: one cell of a 256² lattice. Counting a cell wholly in the zone when its
//! centre's gap is below the range makes the traction a step function of the gap; the
//! discrete problem then holds its zone edge at a cell boundary over a range of approaches
//! (the edge is trapped by the lattice, as a crack front is), and the pull-off comes out too
//! tensile by an error that falls only like the cell size (measured at $\lambda = 6$: 35 %
//! at 256², 13.5 % at 512²). Instead, $F_k(g)$ is the share of the cell's area where an
//! interpolation of the gap is below the range: over each quarter of the cell the gap is the
//! plane through the cell's gap at its centre and the means with the two neighbours at the
//! middles of the quarter's outer sides (the cell's own gap repeated beyond the edge of a
//! free lattice, wrapped round on a periodic one); the share of a quarter is then the
//! distribution function of a sum of two uniform variables, in closed form. $F$ is
//! continuous in the gap, so the discrete force is continuous in the approach and the zone
//! edge moves through the cells; it is non-increasing in every gap (each interpolated gap is
//! a combination of cell gaps with non-negative weights), which keeps the order argument
//! below. Measured on the sphere (`tests/adhesion.rs`) against Maugis's closed form: at
//! $\lambda = 6$ the pull-off is within 5.1 % of JKR's $1.5\pi wR$ at 128² and 1.2 % at
//! 256² (cells of $0.036$ and $0.018$ contact-radius units; 0.02 % at 512²), and the
//! contact radius along the loading branch within 7.2 %, 1.6 % and 0.95 % of JKR's at the
//! computed load; at $\lambda = 1$ the pull-off is within 0.18 % of Maugis's at 64² and 0.09 % at 128²
//! (2.5 % before); at $\lambda = 0.05$ (DMT) within 1.8 % of $2\pi wR$ at 128². The
//! contact itself is still cell by cell (a cell's pressure is uniform and its gap closed at
//! its centre), so some lattice hysteresis is left: at $\lambda = 6$ the loading and the
//! unloading branch differ by up to $0.029\pi wR$ at the same approach at 128²,
//! $0.009\pi wR$ at 256² and $0.003\pi wR$ at 512², where Maugis's contact branch is one
//! curve.
//!
//! **The updates.** Under approach control the solution is the stationary state reached
//! from the start: larger shares pull the surfaces closer and so give larger shares, so from
//! shares below the solution's (the approach from far: none; or the previous step of an
//! approach path) the updates grow monotonically, and from shares above it (a retraction
//! path) they shrink; the contact therefore stays on its branch until that branch ends and
//! jumps in (or out) there, which is the hysteresis of adhesive contact. Where the zone edge
//! is steep the map is nearly neutral and the plain updates converge slowly (at
//! $\lambda = 6$ on 256², 200 to 750 updates a step: a ratio near 0.97 per update). When two
//! successive changes point the same way (cosine above 0.95) and shrink by a ratio
//! $\rho < 1$, the update goes $1/(1-\rho)$ (at most 20) times the new change, the limit of
//! a geometric sequence, clipped to $[0, 1]$, and the next two updates are plain (an
//! extrapolated update may step past the solution, and the plain ones then come back to it
//! from the other side; measured:
//! the same forces to $10^{-5}\pi wR$ with 3 to 5 times fewer contact solves). The updates
//! stop when no share changes by more than [`zone_tolerance`] of the contact solves'
//! tolerance ($\sqrt{\varepsilon}$, within $[10^{-6}, 10^{-3}]$: a share's change is the
//! gap's error over the gap's rise across the cell, so a tighter stop would chase the contact
//! solves' own error). [`AdhesiveSolution::zone_residual`] is that last change, and the
//! returned state is the contact solve at the returned shares, so the contact conditions
//! hold to the contact solve's residuals.
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
//! [`NormalInfo::residual`] is the largest of the three. $p \ge 0$ (and $p \le H$ under a
//! hardness) holds exactly.
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
//! [`ContactGrid`](stickslip_lattice::ContactGrid) for the tangential solvers (partial slip on the computed contact).

mod adhesive;
mod capped;
mod cohesive;
mod iteration;
mod nested;
mod passes;
mod solution;

pub use adhesive::{
    zone_tolerance, Adhesion, AdhesiveSolution, ADHESIVE_SOLVER_NAME, DEFAULT_MAX_ZONE_UPDATES,
};
pub use solution::{NormalInfo, NormalSolution};

use crate::error::{positive, tolerance_in, Error, Result};
use iteration::Start;
use passes::{in_order, BLOCK};
use rayon::prelude::*;
use std::time::Instant;
use stickslip_halfspace::rectangle::Compliance;
use stickslip_halfspace::Material;
pub use stickslip_lattice::{Boundary, NormalOperator, NormalScratch};
use stickslip_quad::Tolerance;

/// The solver's name (as in [`Error::NotConverged`]).
pub const SOLVER_NAME: &str = "normal CCG (Polonsky-Keer)";

/// Default minimum number of contact cells for a resolved contact.
pub const DEFAULT_MIN_CONTACT_CELLS: usize = 12;

/// At most this many clipped or re-entered cells per step are corrected by adding kernel
/// columns directly ($O(N)$ each) instead of one more FFT product, on a periodic lattice;
/// a free lattice's padded product costs about four times as much, so four times as many
/// there. Measured at 1024² (2 cores): a column 0.15 ms, a product 5.7 ms periodic and
/// 15 ms free.
const DIRECT_CHANGES: usize = 24;

/// The incrementally updated $u = Kp$ is recomputed by a full product this often (and before
/// every certified stop).
const REFRESH: usize = 50;

/// Under a hardness and a force: the force error, as a share of the tolerance, beyond which
/// a step is followed by the projection back onto the force (module docs, "Hardness").
const PROJECTION_SLACK: f64 = 0.1;

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
    memory_limit: Option<u64>,
    hardness: Option<f64>,
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
            memory_limit: None,
            hardness: None,
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

    /// Cap the pressure at the hardness `h` (Pa): an elastic–perfectly plastic interface
    /// (module docs, "Hardness"). Checked ($h > 0$, finite) by [`NormalProblem::solve`].
    #[must_use]
    pub fn with_hardness(mut self, h: f64) -> Self {
        self.hardness = Some(h);
        self
    }

    /// The hardness, if the pressure is capped.
    #[must_use]
    pub fn hardness(&self) -> Option<f64> {
        self.hardness
    }

    /// Refuse to solve ([`Error::MemoryExceeded`], before anything is planned) when the solve
    /// would need more than `bytes` of working memory ([`NormalProblem::memory_bytes`]).
    #[must_use]
    pub fn with_memory_limit(mut self, bytes: u64) -> Self {
        self.memory_limit = Some(bytes);
        self
    }

    /// The working memory of a solve on an `nx` x `ny` lattice (bytes), beyond the caller's
    /// initial gap: the operator (the kernel's half spectrum, the column $Ke_0$, the
    /// preconditioner's spectrum in single precision), the row spectra of the two transforms,
    /// the five lattice vectors of the iteration, the preconditioned residual and the
    /// previous gap in single precision, the free set (a byte a cell), and the contact flags
    /// of the result. The coarser levels of a nested start need about a quarter of it and are
    /// released before the finest lattice's vectors exist; the free kernel's set-up needs
    /// less than the iteration. In doubles per cell: about 9.1 periodic and 10.9 free
    /// (issue 30: at most 13 with the gap; measured peak resident memory of the whole
    /// process in `docs/peers.md`).
    #[must_use]
    pub fn memory_bytes(nx: usize, ny: usize, boundary: Boundary) -> u64 {
        let n = (nx * ny) as u64;
        let (mx, my, px, py) = match boundary {
            Boundary::Periodic => (nx, ny, nx, ny),
            Boundary::Free => (
                stickslip_lattice::fast_size(2 * nx - 1),
                stickslip_lattice::fast_size(2 * ny - 1),
                stickslip_lattice::fast_size(nx),
                stickslip_lattice::fast_size(ny),
            ),
        };
        let half = |m: usize| (m / 2 + 1) as u64;
        let operator = 8 * half(mx) * half(my) + 8 * n + 4 * half(px) * half(py);
        let scratch = 16 * ny as u64 * half(mx) + 8 * ny as u64 * half(px);
        let iteration = 5 * 8 * n + 2 * 4 * n + n;
        operator + scratch + iteration + n
    }

    /// [`NormalProblem::memory_bytes`] of this problem's lattice.
    #[must_use]
    pub fn memory_needed(&self) -> u64 {
        // Under a cap the plastic cells' displacement is kept apart: one more lattice vector.
        let extra = if self.hardness.is_some() { 8 * (self.nx * self.ny) as u64 } else { 0 };
        Self::memory_bytes(self.nx, self.ny, self.boundary) + extra
    }

    /// [`Error::MemoryExceeded`] when the solve needs more than the limit.
    fn check_memory(&self) -> Result<()> {
        let Some(limit) = self.memory_limit else { return Ok(()) };
        let needed = self.memory_needed();
        if needed <= limit {
            return Ok(());
        }
        let cells = self.nx * self.ny;
        let fits = (cells as f64 * limit as f64 / needed as f64) as usize;
        Err(Error::MemoryExceeded { cells, needed, limit, fits })
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
        // On rayon's pool: the solve's loops are then split without a hand-over each.
        stickslip_lattice::on_pool(|| self.solve_here(load))
    }

    fn solve_here(&self, load: NormalLoad) -> Result<NormalSolution> {
        let (tol, force) = self.check_load(load)?;
        if let (Some(cap), NormalLoad::Approach(_)) = (self.hardness, load) {
            let op = self.operator();
            return self.capped_from_elastic(&op, load, tol, cap);
        }
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
    /// [`Error::UnresolvedContact`] for a contact on fewer cells than the minimum;
    /// [`Error::MemoryExceeded`] (before anything else runs) beyond a memory limit.
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
            return self.run(op, load, tol, force, Start::Borrowed(w)).map(|(s, _)| s);
        }
        if let (Some(cap), NormalLoad::Approach(_)) = (self.hardness, load) {
            return self.capped_from_elastic(op, load, tol, cap);
        }
        let t0 = Instant::now();
        let coarse = self.coarse_start(load);
        let coarse_seconds = t0.elapsed().as_secs_f64();
        self.run_from(op, load, tol, force, coarse, coarse_seconds)
    }

    /// A capped solve under approach control without a warm start: from the elastic
    /// solution at the same approach (nested), capped at `cap`. (The capped iteration from
    /// a cold or nested start stalls when the cap lies near the elastic peak: a Hertz
    /// sphere on 128² at a cap from 0.9 to 2.3 times its elastic peak stopped at residual 1
    /// to 3 after 10,000 iterations, tested in tests/hardness.rs.) The counts and times
    /// include the elastic solve's. Without contact at that approach, the plain start.
    fn capped_from_elastic(
        &self,
        op: &NormalOperator,
        load: NormalLoad,
        tol: f64,
        cap: f64,
    ) -> Result<NormalSolution> {
        let mut elastic = self.clone();
        elastic.hardness = None;
        elastic.min_contact_cells = 1;
        let e = elastic.solve_with(op, load, None)?;
        if e.no_contact || e.pressure.iter().all(|&p| p <= 0.0) {
            let t0 = Instant::now();
            let coarse = self.coarse_start(load);
            let coarse_seconds = t0.elapsed().as_secs_f64();
            return self.run_from(op, load, tol, None, coarse, coarse_seconds);
        }
        let p: Vec<f64> = e.pressure.iter().map(|&p| p.min(cap)).collect();
        let (mut s, _) = self.run(op, load, tol, None, Start::Owned(p))?;
        s.info.iterations += e.info.iterations;
        s.info.products += e.info.products;
        s.info.preconditioner_products += e.info.preconditioner_products;
        s.info.coarse_iterations += e.info.coarse_iterations;
        s.info.setup_seconds += e.info.setup_seconds;
        s.info.solve_seconds += e.info.solve_seconds;
        s.info.levels = e.info.levels;
        s.levels = e.levels;
        Ok(s)
    }

    /// The tolerance and the prescribed force of `load`, checked, and the memory.
    fn check_load(&self, load: NormalLoad) -> Result<(f64, Option<f64>)> {
        let tol = tolerance_in(SOLVER_NAME, self.tolerance, Self::TOLERANCE_RANGE)?;
        self.check_memory()?;
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
        if let Some(h) = self.hardness {
            positive("hardness", h)?;
            if let Some(f) = force {
                let area = self.hx * self.hy * (self.nx * self.ny) as f64;
                if f >= h * area {
                    return Err(Error::AboveCapacity {
                        force: f,
                        hardness: h,
                        area,
                        capacity: h * area,
                    });
                }
            }
        }
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
}
