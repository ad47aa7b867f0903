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
//! penetrating non-contact cells with the conjugacy reset, and (force control) the approach
//! estimated as the mean of $g^0 + u$ over $I_c$ and the pressure rescaled to the load after
//! every step. Every product with $K$ is one FFT convolution, $O(N\log N)$: one for the
//! direction, $K\mathbf t$, and $u = Kp$ updated from it ($u \leftarrow u - \tau K\mathbf t$
//! plus the columns of the few cells clipped or re-entered, added directly when at most 32,
//! else a full product of the new $p$), with a full product every 50 iterations and before the stop.
//! Displacement control is the same iteration with $\delta$ fixed, without the mean
//! subtraction and the rescaling (the bound-constrained quadratic program
//! $\min \tfrac12 p^{\mathsf T}Kp + (g^0-\delta)^{\mathsf T}p$, $p\ge0$).
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
const DIRECT_CHANGES: usize = 32;

/// The incrementally updated $u = Kp$ is recomputed by a full product this often (and before
/// every certified stop).
const REFRESH: usize = 50;

/// Default iteration budget.
pub const DEFAULT_MAX_ITERATIONS: usize = 10_000;

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
}

/// Termination information of a normal solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NormalInfo {
    /// Which solver ([`SOLVER_NAME`]).
    pub solver: &'static str,
    /// Conjugate-gradient iterations.
    pub iterations: usize,
    /// FFT convolutions performed (one or two per iteration, module docs).
    pub products: usize,
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

    /// Plan the operator and solve under `load`.
    ///
    /// # Errors
    /// See [`NormalProblem::solve_with`].
    pub fn solve(&self, load: NormalLoad) -> Result<NormalSolution> {
        let op = self.operator();
        self.solve_with(&op, load, None)
    }

    /// Solve under `load` with a planned operator (from [`NormalProblem::operator`] of this
    /// problem's lattice, boundary and bodies) and an optional initial pressure (a warm start,
    /// e.g. the previous step of a load sweep; negative values are clipped).
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
        let tol = tolerance_in(SOLVER_NAME, self.tolerance, Self::TOLERANCE_RANGE)?;
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
        if let Some(w) = warm {
            if w.len() != n {
                return Err(Error::LengthMismatch {
                    name: "warm start",
                    expected: n,
                    got: w.len(),
                });
            }
        }
        let t0 = Instant::now();
        let area = self.hx * self.hy;
        let g0 = self.gap;
        let gmin = g0.iter().copied().fold(f64::INFINITY, f64::min);

        if let (NormalLoad::Approach(d), Boundary::Periodic) = (load, self.boundary) {
            let mean = g0.iter().sum::<f64>() / n as f64;
            if d >= mean {
                return Err(Error::OutOfDomain {
                    name: "approach",
                    value: d,
                    allowed: "below the mean initial gap for a periodic surface (full contact: \
                              unbounded force under displacement control; use force control)",
                });
            }
        }
        // Displacement control where the gap never closes: zero load, said so.
        if let NormalLoad::Approach(d) = load {
            if d <= gmin {
                return Ok(self.finish(
                    op,
                    vec![0.0; n],
                    g0.iter().map(|g| g - d).collect(),
                    d,
                    NormalInfo {
                        solver: SOLVER_NAME,
                        iterations: 0,
                        products: 0,
                        gap_residual: 0.0,
                        complementarity_residual: 0.0,
                        force_residual: 0.0,
                        residual: 0.0,
                        gap_scale: 0.0,
                        tolerance: self.tolerance,
                        fft_size: op.fft_size(),
                        setup_seconds: op.setup_seconds(),
                        solve_seconds: t0.elapsed().as_secs_f64(),
                    },
                ));
            }
        }

        let mut p = vec![0.0; n];
        match (warm, load) {
            (Some(w), _) => p.iter_mut().zip(w).for_each(|(p, w)| *p = w.max(0.0)),
            (None, NormalLoad::Approach(d)) => {
                let k0 = op.self_term();
                p.iter_mut().zip(g0).for_each(|(p, g)| *p = ((d - g) / k0).max(0.0));
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

        let mut scratch = op.make_scratch();
        let mut u = vec![0.0; n];
        let mut g = vec![0.0; n];
        let mut t = vec![0.0; n];
        let mut r = vec![0.0; n];
        let mut g_old = 1.0;
        let mut conjugate = false;
        let mut iterations = 0;
        let mut products = 0;
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
            // Gap without the approach (and the pending rescaling), then the approach (force
            // control: mean over I_c).
            let f = pending;
            pending = 1.0;
            let (gs, gc) = in_order(
                g.par_chunks_mut(BLOCK)
                    .zip(u.par_chunks_mut(BLOCK))
                    .zip(g0.par_chunks(BLOCK).zip(p.par_chunks_mut(BLOCK)))
                    .map(|((g, u), (g0, p))| {
                        let (mut gs, mut gc) = (0.0, 0usize);
                        for (g, (u, (g0, p))) in
                            g.iter_mut().zip(u.iter_mut().zip(g0.iter().zip(p)))
                        {
                            *p *= f;
                            *u *= f;
                            *g = *u + g0;
                            if *p > 0.0 {
                                gs += *g;
                                gc += 1;
                            }
                        }
                        (gs, gc)
                    }),
            )
            .into_iter()
            .fold((0.0, 0), |a, b| (a.0 + b.0, a.1 + b.1));
            delta = match load {
                NormalLoad::Approach(d) => d,
                NormalLoad::Force(_) => gs / gc.max(1) as f64,
            };
            // The gap, the residuals and the squared gap on I_c in one pass.
            let (emax, pg, ps, gg) =
                in_order(g.par_chunks_mut(BLOCK).zip(p.par_chunks(BLOCK)).map(|(g, p)| {
                    let mut acc = (0.0f64, 0.0, 0.0, 0.0);
                    for (g, &p) in g.iter_mut().zip(p) {
                        *g -= delta;
                        let g = *g;
                        if p > 0.0 {
                            acc =
                                (acc.0.max(g.abs()), acc.1 + p * g.abs(), acc.2 + p, acc.3 + g * g);
                        } else {
                            acc.0 = acc.0.max((-g).max(0.0));
                        }
                    }
                    acc
                }))
                .into_iter()
                .fold((0.0f64, 0.0, 0.0, 0.0), |a, b| {
                    (a.0.max(b.0), a.1 + b.1, a.2 + b.2, a.3 + b.3)
                });
            res = residuals(emax, pg, ps, delta - gmin, sum_target);
            if res.3 <= tol {
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
                    residual: res.3,
                    tolerance: tol,
                });
            }
            iterations += 1;
            // Conjugate direction on the contact set.
            let beta = if conjugate { gg / g_old } else { 0.0 };
            g_old = gg;
            t.par_iter_mut().zip(p.par_iter().zip(g.par_iter())).for_each(|(t, (p, g))| {
                *t = if *p > 0.0 { g + beta * *t } else { 0.0 };
            });
            op.apply(&t, &mut r, &mut scratch);
            products += 1;
            // tau = sum g t / sum (r - rbar) t over I_c (force control: rbar the mean of r).
            let (num, den, rs, ts, c) = in_order(
                p.par_chunks(BLOCK)
                    .zip(g.par_chunks(BLOCK).zip(t.par_chunks(BLOCK).zip(r.par_chunks(BLOCK))))
                    .map(|(p, (g, (t, r)))| {
                        let mut acc = (0.0, 0.0, 0.0, 0.0, 0usize);
                        for (p, (g, (t, r))) in p.iter().zip(g.iter().zip(t.iter().zip(r))) {
                            if *p > 0.0 {
                                acc =
                                    (acc.0 + g * t, acc.1 + r * t, acc.2 + r, acc.3 + t, acc.4 + 1);
                            }
                        }
                        acc
                    }),
            )
            .into_iter()
            .fold((0.0, 0.0, 0.0, 0.0, 0), |a, b| {
                (a.0 + b.0, a.1 + b.1, a.2 + b.2, a.3 + b.3, a.4 + b.4)
            });
            let rbar = if force.is_some() { rs / c.max(1) as f64 } else { 0.0 };
            let den = den - rbar * ts;
            let tau = if den > 0.0 { num / den } else { 0.0 };
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
                            } else if *g < 0.0 {
                                *p = -tau.max(0.0) * g;
                                if *p > 0.0 {
                                    ch.push((k, *p));
                                }
                            }
                            sum += *p;
                        }
                        (ch, sum)
                    }),
            );
            let sum = blocks.iter().fold(0.0, |a, b| a + b.1);
            let changes: Vec<(usize, f64)> = blocks.into_iter().flat_map(|b| b.0).collect();
            let entered = changes.iter().filter(|&&(k, _)| t[k] == 0.0).count();
            conjugate = entered == 0;
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
                    if p.iter().all(|&v| v == 0.0) {
                        // Everything left the contact: restart from the rigid interference.
                        let (k0, d) = (op.self_term(), delta);
                        p.iter_mut().zip(g0).for_each(|(p, g)| *p = ((d - g) / k0).max(0.0));
                        conjugate = false;
                        fresh = false;
                    }
                }
            }
        }
        drop((u, t, r, scratch));
        let info = NormalInfo {
            solver: SOLVER_NAME,
            iterations,
            products,
            gap_residual: res.0,
            complementarity_residual: res.1,
            force_residual: res.2,
            residual: res.3,
            gap_scale: delta - gmin,
            tolerance: self.tolerance,
            fft_size: op.fft_size(),
            setup_seconds: op.setup_seconds(),
            solve_seconds: t0.elapsed().as_secs_f64(),
        };
        let s = self.finish(op, p, g, delta, info);
        if s.contact_cells < self.min_contact_cells {
            return Err(Error::UnresolvedContact {
                cells: s.contact_cells,
                minimum: self.min_contact_cells,
            });
        }
        Ok(s)
    }

    fn finish(
        &self,
        _op: &NormalOperator,
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
        }
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

/// $(r_g, r_c, r_F, \max)$ of the module docs from the pass's $\max_k e_k$,
/// $\sum_k p_k|g_k|$ and $\sum_k p_k$; `scale` the gap scale, `sum` the prescribed
/// $\sum_k p_k$ (force control).
fn residuals(emax: f64, pg: f64, ps: f64, scale: f64, sum: Option<f64>) -> (f64, f64, f64, f64) {
    let scale = if scale > 0.0 { scale } else { f64::MIN_POSITIVE };
    let rg = emax / scale;
    let rc = if ps > 0.0 { pg / (ps * scale) } else { 0.0 };
    let rf = sum.map_or(0.0, |s| (ps - s).abs() / s);
    (rg, rc, rf, rg.max(rc).max(rf))
}
