//! Normal and tangential contact of dissimilar elastic bodies, coupled through Dundurs' $\beta$.
//!
//! # The coupling
//!
//! When the two bodies differ, a pressure moves their surfaces tangentially by different
//! amounts and a shear traction moves them normally by different amounts. On the lattice of
//! [`crate::solver`] (cells $h_x\times h_y$, uniform pressure $p_k$ and traction
//! $\mathbf q_k$ per cell) the relative displacements are
//! $$u^n_k = \sum_j K^{nn}_{kj}p_j + K^{nx}_{kj}q_{x,j} + K^{ny}_{kj}q_{y,j},\qquad
//!   \mathbf u^t_k = \sum_j \mathbf K^{tn}_{kj}p_j + (K^{tt}\mathbf q)_k,$$
//! with the uniform-rectangle coefficients of `stickslip_halfspace::rectangle` for the pair
//! ([`Compliance::pair`]): the cross terms
//! $$K^{nx} = \frac{c_3}{4\pi}\iint\frac{X}{\rho^2},\qquad
//!   K^{tn}_x = -\frac{c_3}{4\pi}\iint\frac{X}{\rho^2},\qquad
//!   c_3 = \frac{1-2\nu_1}{G_1} - \frac{1-2\nu_2}{G_2}$$
//! (Love's potentials for a uniformly loaded rectangle; FORMULAS.md F; Johnson, *Contact
//! Mechanics*, §3.2 and §5.1), proportional to the numerator of Dundurs' $\beta$
//! ([`stickslip_halfspace::material::dundurs_beta`]). They vanish for identical materials
//! ($\beta = 0$), and the normal and tangential problems separate.
//!
//! # The method
//!
//! The alternating process of Panagiotopoulos (1975; used for contact of dissimilar bodies by
//! Chen & Wang 2008 and in CONTACT): starting from $\mathbf q = 0$,
//!
//! 1. solve the normal problem ([`NormalProblem`], Polonsky–Keer) with the initial gap
//!    corrected by the traction's normal displacement, $g^0_k + (K^{nx}q_x + K^{ny}q_y)_k$;
//! 2. solve the tangential problem on the new contact ([`FastProblem`]) with the pressure's
//!    tangential displacement $K^{tn}p$ added to the elastic one
//!    ([`FastProblem::with_prescribed_displacement`]);
//!
//! until both fields change by at most the tolerance between passes:
//! $\lVert p - p'\rVert_2 \le \varepsilon\lVert p\rVert_2$ and
//! $\lVert\mathbf q - \mathbf q'\rVert_2 \le \varepsilon\lVert\mathbf q\rVert_2$. The cross
//! products are zero-padded FFT convolutions of the odd kernels (complex spectra), $O(N\log N)$;
//! on a periodic surface ([`CoupledProblem::with_boundary`]) all three operators are the
//! periodic ones (continuous Fourier transfers on the period, mean mode zero:
//! [`CrossOperator::periodic`]).
//! The process contracts roughly by the factor $|\beta|$ per pass for a fixed contact set.
//!
//! With $\beta = 0$ the caller should not use this module: the uncoupled solvers give the
//! exact answer (and [`CoupledProblem::new`] refuses $c_3 = 0$ to say so).

use crate::error::{positive, tolerance_in, Error, Result};
use crate::solver::{NormalLoad, NormalProblem, NormalSolution};
use std::time::Instant;
use stickslip_halfspace::rectangle::Compliance;
use stickslip_halfspace::Material;
use stickslip_lattice::{Boundary, CrossOperator, PeriodicLattice};
use stickslip_quad::Tolerance;
use stickslip_traction::{FastConfig, FastProblem, FastSolution, Load};

/// The coupling iteration's name (as in [`Error::NotConverged`]).
pub const SOLVER_NAME: &str = "Dundurs coupling (Panagiotopoulos)";

/// Default limit of alternation passes.
pub const DEFAULT_MAX_PASSES: usize = 100;

/// A normal plus tangential contact problem of two dissimilar bodies on a lattice (free by
/// default, or one period of a periodic surface).
#[derive(Debug, Clone)]
pub struct CoupledProblem<'a> {
    nx: usize,
    ny: usize,
    cell: (f64, f64),
    origin: (f64, f64),
    gap: &'a [f64],
    bodies: [Material; 2],
    friction: f64,
    tangential: Load,
    tolerance: Tolerance,
    max_passes: usize,
    boundary: Boundary,
}

/// Termination information of the coupling iteration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoupledInfo {
    /// Alternation passes (normal solve + tangential solve each).
    pub passes: usize,
    /// $\lVert p - p'\rVert_2/\lVert p\rVert_2$ between the last two passes.
    pub pressure_change: f64,
    /// $\lVert\mathbf q - \mathbf q'\rVert_2/\lVert\mathbf q\rVert_2$ between the last two
    /// passes.
    pub traction_change: f64,
    /// The larger of the two (the coupling residual).
    pub residual: f64,
    /// Dundurs' $\beta$ of the pair.
    pub beta: f64,
    /// Normal CCG iterations, summed over the passes.
    pub normal_iterations: usize,
    /// Tangential Newton steps, summed over the passes.
    pub tangential_iterations: usize,
    /// The tolerance requested.
    pub tolerance: Tolerance,
    /// Wall time, seconds.
    pub seconds: f64,
}

/// The solution: the last normal and tangential solves, consistent to the tolerance.
#[derive(Debug, Clone, PartialEq)]
pub struct CoupledSolution {
    /// The normal solution (gap including the traction's normal displacement).
    pub normal: NormalSolution,
    /// The tangential solution on the normal solution's contact cells.
    pub tangential: FastSolution,
    /// The traction on the lattice (Pa, row-major; zero outside the contact).
    pub traction: Vec<(f64, f64)>,
    /// Termination information.
    pub info: CoupledInfo,
}

impl<'a> CoupledProblem<'a> {
    /// A problem on `nx` × `ny` cells of `cell` (m) with the initial gap `gap` (m, row-major,
    /// as [`NormalProblem::new`]), bodies [substrate, indenter], friction coefficient `friction`
    /// and tangential load `tangential` (a zero force is allowed: the coupling alone drives a
    /// traction). The lattice is centred on the origin; tolerance $10^{-10}$.
    ///
    /// # Errors
    /// As [`NormalProblem::new`]; [`Error::OutOfDomain`] for a friction coefficient that is not
    /// finite and $> 0$, an invalid load, or bodies without coupling ($\beta = 0$: "bodies",
    /// use the uncoupled solvers).
    pub fn new(
        nx: usize,
        ny: usize,
        cell: (f64, f64),
        gap: &'a [f64],
        bodies: [Material; 2],
        friction: f64,
        tangential: Load,
    ) -> Result<Self> {
        NormalProblem::new(nx, ny, cell, gap, bodies, Boundary::Free)?;
        positive("friction coefficient", friction)?;
        tangential.validate()?;
        let c = Compliance::pair(&bodies[0], &bodies[1]);
        if c.one_minus_two_nu == 0.0 {
            return Err(Error::OutOfDomain {
                name: "bodies",
                value: 0.0,
                allowed: "dissimilar bodies (Dundurs beta != 0); beta = 0 needs no coupling",
            });
        }
        Ok(Self {
            nx,
            ny,
            cell,
            origin: (-0.5 * nx as f64 * cell.0, -0.5 * ny as f64 * cell.1),
            gap,
            bodies,
            friction,
            tangential,
            tolerance: Tolerance::default(),
            max_passes: DEFAULT_MAX_PASSES,
            boundary: Boundary::Free,
        })
    }

    /// Free (an isolated contact, the default) or periodic (the lattice is one period of a
    /// periodic surface: the normal, tangential and cross operators all periodic; the
    /// tangential load may then not hold a moment).
    #[must_use]
    pub fn with_boundary(mut self, boundary: Boundary) -> Self {
        self.boundary = boundary;
        self
    }

    /// Put the lattice corner at `origin` (m).
    #[must_use]
    pub fn with_origin(mut self, origin: (f64, f64)) -> Self {
        self.origin = origin;
        self
    }

    /// The tolerance of the coupling and of both inner solves (within
    /// [`NormalProblem::TOLERANCE_RANGE`]).
    #[must_use]
    pub fn with_tolerance(mut self, tolerance: Tolerance) -> Self {
        self.tolerance = tolerance;
        self
    }

    /// Limit the alternation passes (default [`DEFAULT_MAX_PASSES`], at least 1).
    #[must_use]
    pub fn with_max_passes(mut self, passes: usize) -> Self {
        self.max_passes = passes.max(1);
        self
    }

    /// Solve under the normal load `load` by the alternating process of the module docs.
    ///
    /// # Errors
    /// Those of [`NormalProblem::solve_with`] and [`FastProblem::solve`];
    /// [`Error::ToleranceOutOfRange`]; [`Error::NotConverged`] (named [`SOLVER_NAME`]) when
    /// the fields still change by more than the tolerance after the last pass.
    pub fn solve(&self, load: NormalLoad) -> Result<CoupledSolution> {
        let t0 = Instant::now();
        let tol = tolerance_in(SOLVER_NAME, self.tolerance, NormalProblem::TOLERANCE_RANGE)?;
        let (nx, ny, n) = (self.nx, self.ny, self.nx * self.ny);
        let c = Compliance::pair(&self.bodies[0], &self.bodies[1]);
        let cross = match self.boundary {
            Boundary::Free => CrossOperator::new(nx, ny, self.cell, &c),
            Boundary::Periodic => CrossOperator::periodic(nx, ny, self.cell, &c),
        };
        let lattice = PeriodicLattice {
            cells: (nx, ny),
            origin: (self.origin.0 + 0.5 * self.cell.0, self.origin.1 + 0.5 * self.cell.1),
        };
        let base = NormalProblem::new(nx, ny, self.cell, self.gap, self.bodies, self.boundary)?
            .with_origin(self.origin)
            .with_tolerance(self.tolerance);
        let nop = base.operator();
        let config = FastConfig::new(self.tolerance, FastConfig::default().max_iterations())?;
        let mut qx = vec![0.0; n];
        let mut qy = vec![0.0; n];
        let mut p_old: Option<Vec<f64>> = None;
        let mut gap = self.gap.to_vec();
        let (mut n_its, mut t_its) = (0, 0);
        let (mut dp, mut dq) = (f64::INFINITY, f64::INFINITY);
        for pass in 1..=self.max_passes {
            let un = cross.normal_from_traction(&qx, &qy);
            for ((g, g0), u) in gap.iter_mut().zip(self.gap).zip(&un) {
                *g = g0 + u;
            }
            let np = NormalProblem::new(nx, ny, self.cell, &gap, self.bodies, self.boundary)?
                .with_origin(self.origin)
                .with_tolerance(self.tolerance);
            let normal = np.solve_with(&nop, load, p_old.as_deref())?;
            n_its += normal.info.iterations;
            let grid = normal.contact_grid()?;
            let (ux, uy) = cross.traction_from_pressure(&normal.pressure);
            let cells: Vec<usize> = (0..n).filter(|&k| normal.contact[k]).collect();
            let u0: Vec<(f64, f64)> = cells.iter().map(|&k| (ux[k], uy[k])).collect();
            let mut tp = FastProblem::new(&grid, self.bodies, self.friction, self.tangential)?
                .with_config(config)
                .with_prescribed_displacement(&u0)?;
            if self.boundary == Boundary::Periodic {
                tp = tp.with_periodic(lattice)?;
            }
            let tangential = tp.solve()?;
            t_its += tangential.info.iterations;
            let mut nqx = vec![0.0; n];
            let mut nqy = vec![0.0; n];
            for (&k, q) in cells.iter().zip(&tangential.traction) {
                nqx[k] = q.0;
                nqy[k] = q.1;
            }
            dq = rel_change(&nqx, &qx, &nqy, &qy);
            dp = match &p_old {
                Some(po) => rel_change(&normal.pressure, po, &[], &[]),
                None => f64::INFINITY,
            };
            qx = nqx;
            qy = nqy;
            p_old = Some(normal.pressure.clone());
            if dp <= tol && dq <= tol {
                let traction = qx.iter().zip(&qy).map(|(a, b)| (*a, *b)).collect();
                return Ok(CoupledSolution {
                    normal,
                    tangential,
                    traction,
                    info: CoupledInfo {
                        passes: pass,
                        pressure_change: dp,
                        traction_change: dq,
                        residual: dp.max(dq),
                        beta: stickslip_halfspace::material::dundurs_beta(
                            &self.bodies[0],
                            &self.bodies[1],
                        ),
                        normal_iterations: n_its,
                        tangential_iterations: t_its,
                        tolerance: self.tolerance,
                        seconds: t0.elapsed().as_secs_f64(),
                    },
                });
            }
        }
        Err(Error::NotConverged {
            solver: SOLVER_NAME,
            iterations: self.max_passes,
            residual: dp.max(dq),
            tolerance: tol,
        })
    }
}

/// $\lVert(a, b) - (a', b')\rVert_2/\lVert(a, b)\rVert_2$ (0 when both are zero).
fn rel_change(a: &[f64], a_old: &[f64], b: &[f64], b_old: &[f64]) -> f64 {
    let d: f64 = a.iter().zip(a_old).chain(b.iter().zip(b_old)).map(|(x, y)| (x - y).powi(2)).sum();
    let s: f64 = a.iter().chain(b).map(|x| x * x).sum();
    if s > 0.0 {
        (d / s).sqrt()
    } else if d > 0.0 {
        f64::INFINITY
    } else {
        0.0
    }
}
