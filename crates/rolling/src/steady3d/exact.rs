//! Exact steady rolling on a contact grid (Kalker's boundary-element theory).
//!
//! Discretisation (Kalker 1990, ch. 2; as in CONTACT's steady state): uniform traction per
//! rectangular element, the exact uniform-rectangle influence tensor $K$ for
//! $\mathbf u = K*\mathbf q$ ([`TensorConvolution`], zero-padded FFT), and the convective
//! derivative as the upwind difference between an element and its neighbour one cell towards
//! the leading edge, at which the material was one element length earlier:
//! $$\mathbf s_I = \mathbf w(x_I, y_I) + \frac{\mathbf u_I - \mathbf u_{I^+}}{h_x}.$$
//! The neighbour $I^+$ may lie outside the contact (carrying no traction, but displaced); the
//! lattice is extended by those cells. The rigid slip is taken at the element centre (taking
//! it at the midpoint of the difference instead was tried: the spin coefficient $C_{23}$
//! then converges more slowly, 5 % high at 40 cells across against 0.6 % here).
//!
//! Solution (Kalker's active-set idea, with Krylov inner solves):
//! 1. classify each element by the trial traction $\mathbf t = \mathbf q - \mathbf s/D$
//!    ($D$ the element's own slip stiffness, the coefficient of $\mathbf q_I$ in
//!    $\mathbf s_I$): stick if $|\mathbf t|\le fp$, else slip with
//!    $\mathbf q = fp\,\mathbf t/|\mathbf t|$;
//! 2. stop when the natural residual $\max_I|\mathbf q_I - \Pi(\mathbf t_I)|/\max fp$ is
//!    below the tolerance ($\Pi$ the projection on the disc $|\mathbf q|\le fp$; zero exactly
//!    when Coulomb's law holds on every element);
//! 3. otherwise solve $\mathbf s_I = 0$ on the stick elements with the slip tractions fixed,
//!    by GMRES with FFT products, right-preconditioned by the local (FASTSIM-like) operator
//!    $D(\mathbf z_I - \mathbf z_{I^+})$, inverted by marching from the leading edge.

use super::gmres::gmres;
use super::{Creepage, RollingInfo, RollingMethod, RollingSolution, Rows};
use crate::error::{Error, Result};
use stickslip_halfspace::rectangle::{shear_x_displacement, shear_y_displacement, Rect};
use stickslip_halfspace::Material;
use stickslip_lattice::influence::{Compliance, InfluenceModel};
use stickslip_lattice::ContactGrid;
use stickslip_lattice::{ConvScratch, TensorConvolution};

/// Name in error messages.
const SOLVER: &str = "exact steady rolling";

/// The exact steady-rolling problem of one contact grid and pair of bodies.
#[derive(Debug)]
pub struct SteadyRolling {
    /// Contact elements (centres, pressure).
    contact: ContactGrid,
    /// Extended lattice element of each contact element's leading-side neighbour.
    up: Vec<usize>,
    /// Elements of the extended lattice (contact first, then the added neighbours).
    n_ext: usize,
    /// Contact elements ordered from the leading edge (largest x) to the trailing edge.
    order: Vec<usize>,
    conv: TensorConvolution,
    /// Own slip stiffness per unit traction, x and y.
    d: [f64; 2],
    friction: f64,
    /// The two bodies (for the coarser lattices of the nested start).
    bodies: [Material; 2],
    tolerance: f64,
    max_iterations: usize,
    /// Start from the coarser lattices' solution where the lattice is large enough.
    nested: bool,
}

/// A grid at least twice this many cells across in both directions starts from the
/// solution on its lattice coarsened 2 x 2 ([`SteadyRolling::solve`]).
pub const NEST_MIN_CELLS: usize = 16;

/// The coarse levels' tolerance: a start, not a result, so its active set need only be
/// settled (the fine level iterates on to its own tolerance).
const COARSE_TOLERANCE: f64 = 1e-4;

/// Relative tolerances accepted by [`SteadyRolling::with_tolerance`].
pub const TOLERANCE_RANGE: (f64, f64) = (1e-10, 1e-1);

/// How an element's projection acts at the current iterate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    /// Inside the bound: the projection is the identity.
    Stick,
    /// On the bound: the derivative of the projection is $\kappa(I - \hat t\hat t^T)$.
    Slip,
    /// No traction allowed ($fp = 0$): the projection is zero.
    Free,
}

/// The residual $\Phi$ and the derivative of the projection at one iterate.
struct Newton {
    kind: Vec<Kind>,
    /// The projection's derivative at each element, a symmetric $2\times2$ matrix
    /// $(P_{xx}, P_{xy}, P_{yy})$: the identity (stick), zero (free) or
    /// $\kappa(I - \hat t\hat t^{\mathsf T})$ with $\kappa = fp/|\mathbf t|$ (slip).
    jac: Vec<[f64; 3]>,
    /// $\Phi$, x components then y.
    phi: Vec<f64>,
    /// Largest $|\Phi_I|$.
    worst: f64,
}

impl Newton {
    fn new(n: usize) -> Self {
        Self {
            kind: vec![Kind::Free; n],
            jac: vec![[0.0; 3]; n],
            phi: vec![0.0; 2 * n],
            worst: 0.0,
        }
    }

    /// Evaluate $\Phi$ and the projection's derivative; returns $\lVert\Phi\rVert_2$.
    fn linearise(&mut self, d: [f64; 2], g: &[f64], q: [&[f64]; 2], s: [&[f64]; 2]) -> f64 {
        let n = g.len();
        let mut sum = 0.0;
        self.worst = 0.0;
        for k in 0..n {
            let t = [q[0][k] - s[0][k] / d[0], q[1][k] - s[1][k] / d[1]];
            let tn = t[0].hypot(t[1]);
            let proj = if g[k] <= 0.0 {
                self.kind[k] = Kind::Free;
                self.jac[k] = [0.0; 3];
                [0.0, 0.0]
            } else if tn <= g[k] {
                self.kind[k] = Kind::Stick;
                self.jac[k] = [1.0, 0.0, 1.0];
                t
            } else {
                self.kind[k] = Kind::Slip;
                let c = g[k] / tn;
                let d = [t[0] / tn, t[1] / tn];
                self.jac[k] = [c * (1.0 - d[0] * d[0]), -c * d[0] * d[1], c * (1.0 - d[1] * d[1])];
                [g[k] * t[0] / tn, g[k] * t[1] / tn]
            };
            let f = [q[0][k] - proj[0], q[1][k] - proj[1]];
            self.phi[k] = f[0];
            self.phi[n + k] = f[1];
            sum += f[0] * f[0] + f[1] * f[1];
            self.worst = self.worst.max(f[0].hypot(f[1]));
        }
        sum.sqrt()
    }

    /// The projection's derivative at element `k` applied to `v`.
    fn apply_p(&self, k: usize, v: [f64; 2]) -> [f64; 2] {
        let m = self.jac[k];
        [m[0] * v[0] + m[1] * v[1], m[1] * v[0] + m[2] * v[1]]
    }
}

struct Work {
    qx: Vec<f64>,
    qy: Vec<f64>,
    ux: Vec<f64>,
    uy: Vec<f64>,
    scratch: ConvScratch,
}

impl SteadyRolling {
    /// Plan the problem on `grid` (the contact elements with their pressure; all on one
    /// lattice) for bodies 1 and 2 (quasi-identical: the normal–tangential coupling is
    /// neglected) and friction coefficient `friction`.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a negative or non-finite friction coefficient or a grid
    /// off its lattice, [`Error::EmptyGrid`] for an empty grid.
    pub fn new(grid: &ContactGrid, bodies: [Material; 2], friction: f64) -> Result<Self> {
        if !(friction.is_finite() && friction >= 0.0) {
            return Err(Error::OutOfDomain {
                name: "friction coefficient",
                value: friction,
                allowed: "finite and >= 0",
            });
        }
        if grid.is_empty() {
            return Err(Error::EmptyGrid { reason: "no contact element to roll on" });
        }
        let (hx, hy) = (grid.hx, grid.hy);
        let rows = Rows::of(grid)?;
        // The lattice extended by each row's cell ahead of its leading element: displaced,
        // never loaded.
        let (ext, up) = rows.extended(grid);
        let c = Compliance::pair(&bodies[0], &bodies[1]);
        let conv = TensorConvolution::new(&ext, &c, InfluenceModel::ExactRectangle)?;
        // Own stiffness: K(0) - K(h_x, 0) per unit traction, over h_x (K_xy vanishes on the axis).
        let rect = Rect { x1: -0.5 * hx, x2: 0.5 * hx, y1: -0.5 * hy, y2: 0.5 * hy };
        let dxx = shear_x_displacement(&c, &rect, 0.0, 0.0).x
            - shear_x_displacement(&c, &rect, hx, 0.0).x;
        let dyy = shear_y_displacement(&c, &rect, 0.0, 0.0).y
            - shear_y_displacement(&c, &rect, hx, 0.0).y;
        Ok(Self {
            contact: grid.clone(),
            up,
            n_ext: ext.len(),
            order: rows.order,
            conv,
            d: [dxx / hx, dyy / hx],
            friction,
            bodies,
            tolerance: 1e-6,
            max_iterations: 100,
            nested: true,
        })
    }

    /// Set the relative tolerance of the natural residual (default $10^{-6}$).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] outside [`TOLERANCE_RANGE`].
    pub fn with_tolerance(mut self, tolerance: f64) -> Result<Self> {
        if !(TOLERANCE_RANGE.0..=TOLERANCE_RANGE.1).contains(&tolerance) {
            return Err(Error::OutOfDomain {
                name: "steady-rolling tolerance",
                value: tolerance,
                allowed: "1e-10 to 1e-1",
            });
        }
        self.tolerance = tolerance;
        Ok(self)
    }

    /// Set the budget of outer (slip-area) iterations (default 100).
    #[must_use]
    pub fn with_max_iterations(mut self, max_iterations: usize) -> Self {
        self.max_iterations = max_iterations.max(1);
        self
    }

    /// Solve from the no-slip state on this lattice alone, without the nested start of
    /// [`SteadyRolling::solve`] (for comparisons; the nested start is the default).
    #[must_use]
    pub fn without_nesting(mut self) -> Self {
        self.nested = false;
        self
    }

    /// Contact elements.
    #[must_use]
    pub fn len(&self) -> usize {
        self.contact.len()
    }

    /// Whether the grid has no element (never true for a planned problem).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.contact.is_empty()
    }

    /// One slip stiffness for both directions, the mean of the two: the projection in
    /// $\Phi$ must scale both slip components alike, or its fixed point would tilt the
    /// traction away from the slip direction.
    fn d_scalar(&self) -> [f64; 2] {
        let m = 0.5 * (self.d[0] + self.d[1]);
        [m, m]
    }

    fn work(&self) -> Work {
        Work {
            qx: vec![0.0; self.n_ext],
            qy: vec![0.0; self.n_ext],
            ux: vec![0.0; self.n_ext],
            uy: vec![0.0; self.n_ext],
            scratch: self.conv.make_scratch(),
        }
    }

    /// $(\mathbf u_I - \mathbf u_{I^+})/h_x$ for every contact element under the contact
    /// tractions in `w.qx`, `w.qy` (the added neighbours carry none).
    fn difference(&self, w: &mut Work, dx: &mut [f64], dy: &mut [f64]) {
        self.conv.apply(&w.qx, &w.qy, &mut w.ux, &mut w.uy, &mut w.scratch);
        let hx = self.contact.hx;
        for k in 0..self.contact.len() {
            let u = self.up[k];
            dx[k] = (w.ux[k] - w.ux[u]) / hx;
            dy[k] = (w.uy[k] - w.uy[u]) / hx;
        }
    }

    fn rigid(&self, creep: &Creepage, k: usize) -> [f64; 2] {
        creep.rigid_slip(self.contact.x[k], self.contact.y[k])
    }

    /// The slip of every contact element under the tractions `q`.
    fn slip(&self, w: &mut Work, creep: &Creepage, q: [&[f64]; 2], s: [&mut [f64]; 2]) {
        let n = self.contact.len();
        w.qx[..n].copy_from_slice(q[0]);
        w.qy[..n].copy_from_slice(q[1]);
        w.qx[n..].fill(0.0);
        w.qy[n..].fill(0.0);
        let [sx, sy] = s;
        self.difference(w, sx, sy);
        for k in 0..n {
            let r = self.rigid(creep, k);
            sx[k] += r[0];
            sy[k] += r[1];
        }
    }

    /// Solve $\mathbf s_I = 0$ on the elements `stick` with the other elements' tractions as
    /// in `q` (updated in place; the stick entries are the initial guess). Returns the FFT
    /// products used and the relative linear residual.
    fn solve_stick(
        &self,
        w: &mut Work,
        creep: &Creepage,
        stick: &[usize],
        q: [&mut [f64]; 2],
        tol: f64,
    ) -> (usize, f64) {
        let n = self.contact.len();
        let ns = stick.len();
        let [qx, qy] = q;
        if ns == 0 {
            return (0, 0.0);
        }
        let mut pos = vec![usize::MAX; n];
        for (p, &k) in stick.iter().enumerate() {
            pos[k] = p;
        }
        // Right-hand side: minus the slip of the stick elements with their tractions zero.
        let mut dxv = vec![0.0; n];
        let mut dyv = vec![0.0; n];
        w.qx[..n].copy_from_slice(qx);
        w.qy[..n].copy_from_slice(qy);
        w.qx[n..].fill(0.0);
        w.qy[n..].fill(0.0);
        for &k in stick {
            w.qx[k] = 0.0;
            w.qy[k] = 0.0;
        }
        self.difference(w, &mut dxv, &mut dyv);
        let mut b = vec![0.0; 2 * ns];
        for (p, &k) in stick.iter().enumerate() {
            let r = self.rigid(creep, k);
            b[p] = -(r[0] + dxv[k]);
            b[ns + p] = -(r[1] + dyv[k]);
        }
        let mut x: Vec<f64> =
            stick.iter().map(|&k| qx[k]).chain(stick.iter().map(|&k| qy[k])).collect();
        let marching: Vec<usize> =
            self.order.iter().copied().filter(|&k| pos[k] != usize::MAX).collect();
        let (up, d) = (&self.up, self.d);
        let precondition = |r: &[f64], z: &mut [f64]| {
            for &k in &marching {
                let p = pos[k];
                let u = up[k];
                let (zx, zy) = if u < n && pos[u] != usize::MAX {
                    (z[pos[u]], z[ns + pos[u]])
                } else {
                    (0.0, 0.0)
                };
                z[p] = r[p] / d[0] + zx;
                z[ns + p] = r[ns + p] / d[1] + zy;
            }
        };
        let apply = |v: &[f64], out: &mut [f64]| {
            w.qx.fill(0.0);
            w.qy.fill(0.0);
            for (p, &k) in stick.iter().enumerate() {
                w.qx[k] = v[p];
                w.qy[k] = v[ns + p];
            }
            self.difference(w, &mut dxv, &mut dyv);
            for (p, &k) in stick.iter().enumerate() {
                out[p] = dxv[k];
                out[ns + p] = dyv[k];
            }
        };
        let info = gmres(apply, precondition, &b, &mut x, tol, 60, 4000);
        for (p, &k) in stick.iter().enumerate() {
            qx[k] = x[p];
            qy[k] = x[ns + p];
        }
        (info.products, info.residual)
    }

    /// The linear (no-slip) theory: $\mathbf s = 0$ on every element, no traction bound.
    /// Kalker's creepage coefficients are its forces per unit creepage.
    ///
    /// # Errors
    /// [`Error::NotConverged`] if the linear solve misses the tolerance; as
    /// [`Creepage`] validation.
    pub fn solve_no_slip(&self, creep: &Creepage) -> Result<RollingSolution> {
        creep.validate()?;
        let n = self.contact.len();
        let mut w = self.work();
        let (mut qx, mut qy) = (vec![0.0; n], vec![0.0; n]);
        let all: Vec<usize> = (0..n).collect();
        let (products, lin) =
            self.solve_stick(&mut w, creep, &all, [&mut qx, &mut qy], self.tolerance);
        if lin > self.tolerance {
            return Err(Error::NotConverged {
                solver: SOLVER,
                iterations: products,
                residual: lin,
                tolerance: self.tolerance,
            });
        }
        let (mut sx, mut sy) = (vec![0.0; n], vec![0.0; n]);
        self.slip(&mut w, creep, [&qx, &qy], [&mut sx, &mut sy]);
        Ok(self.solution(
            qx,
            qy,
            sx,
            sy,
            vec![true; n],
            RollingInfo {
                method: RollingMethod::Exact,
                iterations: 1,
                products: products + 1,
                residual: lin,
            },
        ))
    }

    /// Solve the rolling problem with Coulomb friction for the creepages `creep`.
    ///
    /// Semismooth Newton on $\Phi(\mathbf q) = \mathbf q - \Pi(\mathbf q - \mathbf s/D) = 0$
    /// (Alart & Curnier's formulation of Coulomb's law), each step solved by GMRES with FFT
    /// products and a marching preconditioner, with a backtracking line search on
    /// $\lVert\Phi\rVert_2$. A creepage large enough that every element slides is a result
    /// (no stick element, $|\mathbf F| \to fP$), not an error.
    ///
    /// On a lattice at least $2\times$[`NEST_MIN_CELLS`] cells across in both directions the
    /// iteration starts from the solution of the same creepages on the lattice coarsened
    /// 2 x 2 (itself solved the same way, to a looser tolerance), its tractions interpolated
    /// bilinearly between the coarse elements' centres: the slip area is then nearly right, and the fine lattice
    /// needs a few Newton steps instead of growing the slip area from the no-slip state.
    /// If that start does not converge, the fine lattice is solved again from the no-slip
    /// state, so the nesting never turns a solvable problem into a failure. The products of
    /// every level are counted in [`RollingInfo::products`] (a coarse one costs about a
    /// quarter of a fine one).
    ///
    /// # Errors
    /// [`Error::NotConverged`] if the residual has not met the tolerance within the iteration
    /// budget (the residual reached is given); as [`Creepage`] validation.
    pub fn solve(&self, creep: &Creepage) -> Result<RollingSolution> {
        // On rayon's pool: the solve's loops are then split without a hand-over each.
        stickslip_lattice::on_pool(|| self.solve_here(creep))
    }

    fn solve_here(&self, creep: &Creepage) -> Result<RollingSolution> {
        creep.validate()?;
        let g: Vec<f64> =
            self.contact.pressure.iter().map(|p| self.friction * p.max(0.0)).collect();
        let gmax = g.iter().copied().fold(0.0, f64::max);
        if gmax > 0.0 {
            if let Some((start, coarse_products)) = self.coarse_start(creep) {
                if let Ok(mut s) = self.newton(creep, &g, Some(start)) {
                    s.info.products += coarse_products;
                    return Ok(s);
                }
            }
        }
        self.newton(creep, &g, None)
    }

    /// The nested start of [`SteadyRolling::solve`]: the coarse lattice's tractions carried
    /// to this one, and the products spent on the coarse levels; `None` when the lattice is
    /// too small or the coarse problem fails.
    fn coarse_start(&self, creep: &Creepage) -> Option<([Vec<f64>; 2], usize)> {
        if !self.nested {
            return None;
        }
        let (coarse, parent) = self.contact.coarsened(NEST_MIN_CELLS)?;
        let problem = SteadyRolling::new(&coarse, self.bodies, self.friction)
            .ok()?
            .with_tolerance(self.tolerance.max(COARSE_TOLERANCE))
            .ok()?
            .with_max_iterations(self.max_iterations);
        let s = problem.solve(creep).ok()?;
        let [qx, qy] = prolong(&self.contact, &parent, [&s.qx, &s.qy])?;
        Some(([qx, qy], s.info.products))
    }

    /// Semismooth Newton from `start` (tractions per element, projected on the bound
    /// here), or from the no-slip state projected on the bound.
    fn newton(
        &self,
        creep: &Creepage,
        g: &[f64],
        start: Option<[Vec<f64>; 2]>,
    ) -> Result<RollingSolution> {
        let n = self.contact.len();
        let gmax = g.iter().copied().fold(0.0, f64::max);
        let mut w = self.work();
        let (mut sx, mut sy) = (vec![0.0; n], vec![0.0; n]);
        if gmax == 0.0 {
            let (qx, qy) = (vec![0.0; n], vec![0.0; n]);
            self.slip(&mut w, creep, [&qx, &qy], [&mut sx, &mut sy]);
            let info = RollingInfo {
                method: RollingMethod::Exact,
                iterations: 0,
                products: 1,
                residual: 0.0,
            };
            return Ok(self.solution(qx, qy, sx, sy, vec![false; n], info));
        }
        let mut products = 0;
        let mut state = Newton::new(n);
        let mut residual;
        let (mut qx, mut qy) = match start {
            Some([qx, qy]) => (qx, qy),
            None => {
                // The no-slip state projected on the bound: close to the answer at small
                // creepage, and the slip area grows from the trailing edge as in the true
                // solution.
                let (mut qx, mut qy) = (vec![0.0; n], vec![0.0; n]);
                let all: Vec<usize> = (0..n).collect();
                let (p, _) = self.solve_stick(&mut w, creep, &all, [&mut qx, &mut qy], 1e-3);
                products += p;
                (qx, qy)
            }
        };
        for k in 0..n {
            let qn = qx[k].hypot(qy[k]);
            if qn > g[k] {
                let f = if qn > 0.0 { g[k] / qn } else { 0.0 };
                qx[k] *= f;
                qy[k] *= f;
            }
        }
        self.slip(&mut w, creep, [&qx, &qy], [&mut sx, &mut sy]);
        products += 1;
        let mut phi_norm = state.linearise(self.d_scalar(), g, [&qx, &qy], [&sx, &sy]);
        residual = state.worst / gmax;
        for iteration in 1..=self.max_iterations {
            if residual <= self.tolerance {
                let stick = state.kind.iter().map(|&k| k == Kind::Stick).collect();
                let info = RollingInfo {
                    method: RollingMethod::Exact,
                    iterations: iteration - 1,
                    products,
                    residual,
                };
                return Ok(self.solution(qx, qy, sx, sy, stick, info));
            }
            let step = self.newton_step(&mut w, &state, (0.1 * residual).clamp(1e-10, 1e-2));
            products += step.1;
            let delta = step.0;
            // Backtracking line search on the 2-norm of the residual.
            let (mut alpha, mut accepted) = (1.0, false);
            let (qx0, qy0) = (qx.clone(), qy.clone());
            for _ in 0..12 {
                for k in 0..n {
                    qx[k] = qx0[k] + alpha * delta[k];
                    qy[k] = qy0[k] + alpha * delta[n + k];
                }
                self.slip(&mut w, creep, [&qx, &qy], [&mut sx, &mut sy]);
                products += 1;
                let mut trial = Newton::new(n);
                let norm = trial.linearise(self.d_scalar(), g, [&qx, &qy], [&sx, &sy]);
                if norm <= (1.0 - 1e-4 * alpha) * phi_norm {
                    state = trial;
                    phi_norm = norm;
                    accepted = true;
                    break;
                }
                alpha *= 0.5;
            }
            if !accepted {
                // Keep the smallest step: the residual is reported honestly either way.
                let mut trial = Newton::new(n);
                phi_norm = trial.linearise(self.d_scalar(), g, [&qx, &qy], [&sx, &sy]);
                state = trial;
            }
            residual = state.worst / gmax;
        }
        Err(Error::NotConverged {
            solver: SOLVER,
            iterations: self.max_iterations,
            residual,
            tolerance: self.tolerance,
        })
    }

    /// One Newton step: solve $J\boldsymbol\delta = -\Phi$ with
    /// $J\mathbf v = \mathbf v - P(\mathbf v - B\mathbf v/D)$ by GMRES. Returns
    /// $\boldsymbol\delta$ (x components, then y) and the products used.
    fn newton_step(&self, w: &mut Work, state: &Newton, tol: f64) -> (Vec<f64>, usize) {
        let n = self.contact.len();
        let d = self.d_scalar();
        let b: Vec<f64> = state.phi.iter().map(|v| -v).collect();
        let mut delta = vec![0.0; 2 * n];
        let mut dxv = vec![0.0; n];
        let mut dyv = vec![0.0; n];
        let apply = |v: &[f64], out: &mut [f64]| {
            w.qx[..n].copy_from_slice(&v[..n]);
            w.qy[..n].copy_from_slice(&v[n..]);
            w.qx[n..].fill(0.0);
            w.qy[n..].fill(0.0);
            self.difference(w, &mut dxv, &mut dyv);
            for k in 0..n {
                let r = [v[k] - dxv[k] / d[0], v[n + k] - dyv[k] / d[1]];
                let pr = state.apply_p(k, r);
                out[k] = v[k] - pr[0];
                out[n + k] = v[n + k] - pr[1];
            }
        };
        // Local model B v / D ~ v_I - v_{I+}: J v ~ v_I - P v_{I+}, solved by marching.
        let (up, order) = (&self.up, &self.order);
        let precondition = |r: &[f64], z: &mut [f64]| {
            for &k in order {
                let u = up[k];
                let zu = if u < n { [z[u], z[n + u]] } else { [0.0, 0.0] };
                let pz = state.apply_p(k, zu);
                z[k] = r[k] + pz[0];
                z[n + k] = r[n + k] + pz[1];
            }
        };
        let info = gmres(apply, precondition, &b, &mut delta, tol, 60, 3000);
        (delta, info.products)
    }

    fn solution(
        &self,
        qx: Vec<f64>,
        qy: Vec<f64>,
        sx: Vec<f64>,
        sy: Vec<f64>,
        stick: Vec<bool>,
        info: RollingInfo,
    ) -> RollingSolution {
        RollingSolution::on_grid(&self.contact, [qx, qy], [sx, sy], stick, info)
    }
}

/// The coarse tractions carried to the fine elements by bilinear interpolation between the
/// centres of the coarse elements (weights 9/16, 3/16, 3/16, 1/16 from the fine element's own
/// block and its three nearest neighbours), renormalised over the neighbours that exist (a
/// block outside the coarse contact carries nothing to interpolate from).
fn prolong(fine: &ContactGrid, parent: &[usize], q: [&[f64]; 2]) -> Option<[Vec<f64>; 2]> {
    let (nx, ny, _, _, cell) = fine.lattice_cells().ok()?;
    let (cx, cy) = (nx.div_ceil(2), ny.div_ceil(2));
    let mut block = vec![usize::MAX; cx * cy];
    for (k, &c) in cell.iter().enumerate() {
        block[(c / nx / 2) * cx + (c % nx) / 2] = parent[k];
    }
    let mut out = [vec![0.0; cell.len()], vec![0.0; cell.len()]];
    for (k, &c) in cell.iter().enumerate() {
        let (i, j) = (c % nx, c / nx);
        let (bi, bj) = (i / 2, j / 2);
        // The neighbouring block towards the element's side of its block's centre.
        let ni = if i % 2 == 0 { bi.checked_sub(1) } else { Some(bi + 1).filter(|&v| v < cx) };
        let nj = if j % 2 == 0 { bj.checked_sub(1) } else { Some(bj + 1).filter(|&v| v < cy) };
        let mut acc = [0.0; 2];
        let mut wsum = 0.0;
        let mut add = |bi: Option<usize>, bj: Option<usize>, w: f64| {
            if let (Some(bi), Some(bj)) = (bi, bj) {
                let b = block[bj * cx + bi];
                if b != usize::MAX {
                    acc[0] += w * q[0][b];
                    acc[1] += w * q[1][b];
                    wsum += w;
                }
            }
        };
        add(Some(bi), Some(bj), 9.0);
        add(ni, Some(bj), 3.0);
        add(Some(bi), nj, 3.0);
        add(ni, nj, 1.0);
        out[0][k] = acc[0] / wsum;
        out[1][k] = acc[1] / wsum;
    }
    Some(out)
}
