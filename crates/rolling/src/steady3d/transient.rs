//! Transient (instationary) rolling on a contact grid: the contact solved in steps of one
//! element length of rolling, each from the state of the step before, so that a contact can
//! start from any state (at rest, or after a Cattaneo shift) and roll into the steady state.
//!
//! # The step
//!
//! Conventions as in [`crate::steady3d`]: $x$ is the rolling direction, material enters at
//! the leading edge (largest $x$), $\mathbf q$ is the traction on body 1 and
//! $\mathbf u = K*\mathbf q$ the difference of the surface displacements. When the contact
//! rolls on by $\Delta = h_x$ (one element length), the material now at element $I$ was at
//! its leading-side neighbour $I^+$ one step earlier, so the slip of body 1 over body 2 at
//! $I$ in the step is (Kalker 1990, ch. 2, the transient form of the steady discretisation
//! of [`SteadyRolling`](super::SteadyRolling))
//! $$\mathbf S_I = \Delta\,\mathbf w(x_I, y_I) + \mathbf u^n_I - \mathbf u^{n-1}_{I^+},\qquad
//!   \mathbf w = (\xi - \phi y,\ \eta + \phi x),$$
//! and Coulomb's law asks $\mathbf S_I = 0$, $|\mathbf q_I| \le fp_I$ (stick) or
//! $\mathbf q_I = -fp_I\,\mathbf S_I/|\mathbf S_I|$ (slip). At rest ([`TransientRolling::shift`],
//! a Cattaneo shift) the material does not move and $\mathbf S_I = \Delta\boldsymbol\delta +
//! \mathbf u^n_I - \mathbf u^{n-1}_I$. In a steady state ($\mathbf q^n = \mathbf q^{n-1}$)
//! $\mathbf S_I/\Delta$ is exactly the steady slip of [`SteadyRolling`](super::SteadyRolling).
//!
//! Each step is the partial-slip problem of the fast solver (`stickslip-traction`) for the
//! traction $-\mathbf q$ under the prescribed creep force $-\mathbf F$, with the prescribed
//! displacement $\mathbf u^0_I = \mathbf u^{n-1}_{I^+} - \Delta\,\phi\,(-y_I, x_I)$: its
//! slip $\boldsymbol\delta_f - K(-\mathbf q^n) - \mathbf u^0$ is then $\mathbf S$ and points
//! along its traction $-\mathbf q$, as Coulomb's law asks, and its rigid shift
//! $\boldsymbol\delta_f$ is $\Delta\,(\xi, \eta)$: the creepages of the step follow from the
//! force. The creep force is prescribed (and may change from step to step); the spin
//! creepage is prescribed with it. The grid is the contact extended by each row's cell
//! ahead of its leading element (displaced, never loaded), as in the steady theory.
//!
//! Sources: Kalker (1990), *Three-dimensional elastic bodies in rolling contact*, ch. 2
//! (the transient and steady discretisations); FORMULAS.md R3 (conventions).

use super::{RollingInfo, RollingMethod, RollingSolution, Rows};
use crate::error::{Error, Result};
use stickslip_halfspace::Material;
use stickslip_lattice::influence::{Compliance, InfluenceModel};
use stickslip_lattice::{ContactGrid, ConvScratch, TensorConvolution};
use stickslip_traction::{ElementState, FastConfig, FastProblem, FastSolution, Load, WarmStart};

/// One step of a transient rolling history.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TransientStep {
    /// Distance rolled since the start, $n\,h_x$ (m).
    pub distance: f64,
    /// Creep force $(F_x, F_y)$ on body 1 (N), the resultant of the solved traction.
    pub force: (f64, f64),
    /// Creepages $(\xi, \eta)$ of a rolling step: the rigid slip per unit rolling distance
    /// that carries the force (`None` for a step at rest).
    pub creepage: Option<(f64, f64)>,
    /// Rigid displacement of body 1 over body 2 in the step (m): $\Delta\,(\xi, \eta)$ when
    /// rolling, the shift when at rest.
    pub shift: (f64, f64),
    /// Contact elements that do not slip in the step over those in contact.
    pub stick_fraction: f64,
    /// Newton steps of the fast solver.
    pub newton_iterations: usize,
    /// Operator products of the step (the solve's and one for $K\mathbf q$).
    pub products: usize,
    /// The fast solver's final relative residual (the larger of complementarity and load).
    pub residual: f64,
    /// Energy dissipated by friction over the contact in this step (J):
    /// $\sum_I |\mathbf q_I|\,|\mathbf S_I|\,h_xh_y$, the traction times the slip of the step
    /// (they are parallel where the element slips; zero where it sticks).
    pub dissipated: f64,
    /// Elastic energy stored by the tangential traction after the step (J):
    /// $\tfrac12\sum_I \mathbf q_I\cdot\mathbf u_I\,h_xh_y$ with $\mathbf u = K\mathbf q$.
    pub elastic_energy: f64,
    /// Spin moment $M_z$ on body 1 about the lattice origin (N m), as
    /// [`TransientRolling::solution`]'s `mz`, without building the solution.
    pub mz: f64,
}

/// A contact rolling in steps of one element length from a given state.
#[derive(Debug)]
pub struct TransientRolling {
    /// The contact elements first, then the cells ahead of each row (zero pressure).
    grid: ContactGrid,
    n_contact: usize,
    /// Extended element of each element's leading-side neighbour (the cells ahead: their own).
    up: Vec<usize>,
    bodies: [Material; 2],
    friction: f64,
    config: FastConfig,
    op: TensorConvolution,
    scratch: ConvScratch,
    /// The fast solver's traction, $-\mathbf q$, per extended element.
    traction: Vec<(f64, f64)>,
    /// $K(-\mathbf q)$ per extended element.
    kq: Vec<(f64, f64)>,
    state: Vec<ElementState>,
    /// Slip of the last step (fast solver's sign, $\mathbf S$) per extended element.
    slip: Vec<(f64, f64)>,
    /// Whether the last step rolled (its slip is per unit distance over $h_x$).
    rolled: bool,
    steps: usize,
    rolled_steps: usize,
    last_info: RollingInfo,
    /// Creep force on body 1 after the last step.
    force: (f64, f64),
    /// The last secant estimate of d(shift)/d(force) of a creepage-controlled step (row-major
    /// 2 x 2), carried to the next step.
    jacobian: Option<[f64; 4]>,
}

impl TransientRolling {
    /// Plan the problem on `grid` (the contact elements with their pressure, on one lattice)
    /// for bodies 1 and 2 (quasi-identical: the normal–tangential coupling is neglected) and
    /// friction coefficient $f > 0$, at rest and free of traction. The fast solver's default
    /// configuration (relative residual $10^{-10}$).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a friction coefficient that is not finite and positive;
    /// [`Error::EmptyGrid`]; the lattice's errors for a grid off its lattice.
    pub fn new(grid: &ContactGrid, bodies: [Material; 2], friction: f64) -> Result<Self> {
        if !(friction.is_finite() && friction > 0.0) {
            return Err(Error::OutOfDomain {
                name: "friction coefficient",
                value: friction,
                allowed: "finite and > 0",
            });
        }
        if grid.is_empty() {
            return Err(Error::EmptyGrid { reason: "no contact element to roll on" });
        }
        let n = grid.len();
        let rows = Rows::of(grid)?;
        let (ext, mut up) = rows.extended(grid);
        up.extend(n..ext.len());
        let c = Compliance::pair(&bodies[0], &bodies[1]);
        let op = TensorConvolution::new(&ext, &c, InfluenceModel::ExactRectangle)?;
        let scratch = op.make_scratch();
        let m = ext.len();
        Ok(Self {
            grid: ext,
            n_contact: n,
            up,
            bodies,
            friction,
            config: FastConfig::default(),
            op,
            scratch,
            traction: vec![(0.0, 0.0); m],
            kq: vec![(0.0, 0.0); m],
            state: vec![ElementState::Stick; m],
            slip: vec![(0.0, 0.0); m],
            rolled: false,
            steps: 0,
            rolled_steps: 0,
            last_info: RollingInfo {
                method: RollingMethod::Transient,
                iterations: 0,
                products: 0,
                residual: 0.0,
            },
            force: (0.0, 0.0),
            jacobian: None,
        })
    }

    /// The fast solver's configuration for every step (its tolerance is each step's).
    #[must_use]
    pub fn with_config(mut self, config: FastConfig) -> Self {
        self.config = config;
        self
    }

    /// A step at rest: the bodies shift by $\Delta\boldsymbol\delta$ under the creep force
    /// $\mathbf F$ on body 1 (from the unloaded state: a Cattaneo shift), with
    /// $\mathbf S_I = \Delta\boldsymbol\delta + \mathbf u^n_I - \mathbf u^{n-1}_I$ (module
    /// docs).
    ///
    /// # Errors
    /// As [`TransientRolling::roll`].
    pub fn shift(&mut self, force: (f64, f64)) -> Result<TransientStep> {
        self.step(force, None)
    }

    /// Roll one element length $h_x$ under the creep force $\mathbf F$ on body 1 and the spin
    /// creepage $\phi$ (1/m), with
    /// $\mathbf S_I = h_x\,\mathbf w(x_I, y_I) + \mathbf u^n_I - \mathbf u^{n-1}_{I^+}$ (module
    /// docs); the creepages $(\xi, \eta)$ are found.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a non-finite force or spin; the fast solver's errors
    /// (carried in [`Error::Tangential`]): a force beyond $f\sum_kP_k$ has no partial-slip
    /// state ([`stickslip_traction::Error::CapacityExceeded`]), non-convergence. After an
    /// error the state is that of the last solved step.
    pub fn roll(&mut self, force: (f64, f64), spin: f64) -> Result<TransientStep> {
        if !spin.is_finite() {
            return Err(Error::OutOfDomain {
                name: "spin creepage",
                value: spin,
                allowed: "finite",
            });
        }
        self.step(force, Some(spin))
    }

    fn step(&mut self, force: (f64, f64), spin: Option<f64>) -> Result<TransientStep> {
        for (name, v) in [("creep force F_x", force.0), ("creep force F_y", force.1)] {
            if !v.is_finite() {
                return Err(Error::OutOfDomain { name, value: v, allowed: "finite" });
            }
        }
        stickslip_lattice::on_pool(|| {
            let sol = self.trial(force, spin)?;
            Ok(self.commit(&sol, spin.is_some(), self.grid.hx))
        })
    }

    /// Roll one element length $h_x$ at the prescribed creepages $(\xi, \eta)$ and spin $\phi$
    /// (1/m): the creep force that makes the step's rigid slip $h_x(\xi, \eta)$ is found by a
    /// secant (Broyden) iteration on the force, each trial a warm fast solve of the step
    /// (the step is the force-controlled one of [`TransientRolling::roll`], whose rigid shift
    /// grows monotonically with the force). The first creepage-controlled step estimates
    /// d(shift)/d(force) by two extra solves; later steps start from the last step's force
    /// and estimate (measured over the tests' 679 rolling steps: 2 solves in most, 2.6 on
    /// average, at most 7 after the first, whose secant took 4 to 20 besides the estimate's
    /// two; `crates/rolling/tests/transient_creepage.rs`). The iteration
    /// stops when the creepages are met to $10^{-9}$ of the larger of $|(\xi, \eta)|$ and
    /// $10^{-3}\,f\bar p\,(1/G_1 + 1/G_2)$ ($\bar p$ the mean pressure).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for non-finite creepages or spin, or for creepages whose creep
    /// force would come within $10^{-9}$ of the capacity $f\sum_kP_k$ (a force-controlled
    /// step cannot be solved at the capacity itself; full sliding just below it is solved);
    /// [`Error::NotConverged`] when 40 trials do not meet the creepages or the secant's
    /// estimate becomes singular; the fast solver's errors as in [`TransientRolling::roll`].
    /// After an error the state is that of the last solved step.
    pub fn roll_at_creepage(&mut self, creepage: (f64, f64), spin: f64) -> Result<TransientStep> {
        stickslip_lattice::on_pool(|| self.roll_at_creepage_here(creepage, spin))
    }

    fn roll_at_creepage_here(&mut self, creepage: (f64, f64), spin: f64) -> Result<TransientStep> {
        for (name, v) in [
            ("longitudinal creepage", creepage.0),
            ("lateral creepage", creepage.1),
            ("spin creepage", spin),
        ] {
            if !v.is_finite() {
                return Err(Error::OutOfDomain { name, value: v, allowed: "finite" });
            }
        }
        let h = self.grid.hx;
        let target = (creepage.0 * h, creepage.1 * h);
        let cap = self.friction * self.grid.total_normal_force();
        let mut force = self.force;
        let mut sol = self.trial(force, Some(spin))?;
        let mut r = (sol.shift.0 - target.0, sol.shift.1 - target.1);
        let mut j = match self.jacobian {
            Some(j) => j,
            None => {
                // Central differences would cost four solves; forward ones at a hundredth
                // of the capacity (in the direction away from it) are enough for a start.
                let mut j = [0.0; 4];
                for c in 0..2 {
                    let d = 1e-2 * cap * if [force.0, force.1][c] > 0.0 { -1.0 } else { 1.0 };
                    let f2 = if c == 0 { (force.0 + d, force.1) } else { (force.0, force.1 + d) };
                    let s2 = self.trial(f2, Some(spin))?;
                    j[c] = (s2.shift.0 - sol.shift.0) / d;
                    j[2 + c] = (s2.shift.1 - sol.shift.1) / d;
                }
                j
            }
        };
        // The creepage scale: f times the mean pressure over the shear modulus of the pair,
        // as a rigid slip per step.
        let contact = self.grid.pressure.iter().filter(|p| **p > 0.0).count().max(1) as f64;
        let mean_p = self.grid.total_normal_force() / (contact * self.grid.hx * self.grid.hy);
        let compliance: f64 =
            self.bodies.iter().filter(|b| !b.is_rigid()).map(|b| 1.0 / b.shear_modulus()).sum();
        let scale = h * self.friction * mean_p * compliance;
        let tol = 1e-9 * target.0.hypot(target.1).max(1e-3 * scale);
        let mut trials = 0;
        for _ in 0..40 {
            if r.0.hypot(r.1) <= tol {
                self.jacobian = Some(j);
                return Ok(self.commit(&sol, true, h));
            }
            let det = j[0] * j[3] - j[1] * j[2];
            if !(det.is_finite() && det != 0.0) {
                break;
            }
            let mut df = ((-r.0 * j[3] + r.1 * j[1]) / det, (r.0 * j[2] - r.1 * j[0]) / det);
            // Stay inside the friction disc: at most half way to its edge per trial.
            let next = (force.0 + df.0, force.1 + df.1);
            let limit = 0.5 * (cap + force.0.hypot(force.1));
            if next.0.hypot(next.1) > limit {
                let room = cap - force.0.hypot(force.1);
                if room <= 1e-9 * cap {
                    return Err(Error::OutOfDomain {
                        name: "creepage (its creep force would reach the capacity f P)",
                        value: creepage.0.hypot(creepage.1),
                        allowed: "creepages that leave part of the contact sticking",
                    });
                }
                let t = 0.5 * room / df.0.hypot(df.1);
                df = (df.0 * t, df.1 * t);
            }
            force = (force.0 + df.0, force.1 + df.1);
            trials += 1;
            let s2 = self.trial(force, Some(spin))?;
            let r2 = (s2.shift.0 - target.0, s2.shift.1 - target.1);
            // Broyden's update: J += (dr - J df) df^T / |df|^2.
            let dr = (r2.0 - r.0, r2.1 - r.1);
            let jd = (j[0] * df.0 + j[1] * df.1, j[2] * df.0 + j[3] * df.1);
            let nn = df.0 * df.0 + df.1 * df.1;
            if nn > 0.0 {
                j[0] += (dr.0 - jd.0) * df.0 / nn;
                j[1] += (dr.0 - jd.0) * df.1 / nn;
                j[2] += (dr.1 - jd.1) * df.0 / nn;
                j[3] += (dr.1 - jd.1) * df.1 / nn;
            }
            sol = s2;
            r = r2;
        }
        Err(Error::NotConverged {
            solver: "transient rolling at prescribed creepages (secant on the creep force)",
            iterations: trials,
            residual: r.0.hypot(r.1) / target.0.hypot(target.1).max(1e-3 * scale),
            tolerance: 1e-9,
        })
    }

    /// Solve a step under `force` (and `spin` when rolling) from the current state, without
    /// taking it.
    fn trial(&mut self, force: (f64, f64), spin: Option<f64>) -> Result<FastSolution> {
        let m = self.grid.len();
        let h = self.grid.hx;
        // u0 = u^{n-1} at the element the material came from (the fast solver's K(-q) is
        // -u), less the spin part of the rigid slip.
        let u0: Vec<(f64, f64)> = (0..m)
            .map(|k| {
                let from = if spin.is_some() { self.up[k] } else { k };
                let v = self.kq[from];
                let phi = spin.unwrap_or(0.0);
                (-v.0 + h * phi * self.grid.y[k], -v.1 - h * phi * self.grid.x[k])
            })
            .collect();
        let load = Load::force(-force.0, -force.1).map_err(Error::Tangential)?;
        let fp = FastProblem::new(&self.grid, self.bodies, self.friction, load)
            .and_then(|p| p.with_prescribed_displacement(&u0))
            .map_err(Error::Tangential)?
            .with_config(self.config);
        // The traction is nearly stationary in the contact frame (steady rolling: exactly),
        // so the last step's traction and state start this one at the same elements.
        let warm = WarmStart {
            traction: self.traction.clone(),
            shift: (0.0, 0.0),
            rotation: 0.0,
            state: if self.steps == 0 { Vec::new() } else { self.state.clone() },
        };
        let sol = match fp.solve_from(&self.op, &mut self.scratch, &warm) {
            Ok(s) => s,
            Err(
                stickslip_traction::Error::NotConverged { .. }
                | stickslip_traction::Error::NoStickLeft { .. }
                | stickslip_traction::Error::NotPositiveDefinite { .. },
            ) => fp.solve_with(&self.op, &mut self.scratch).map_err(Error::Tangential)?,
            Err(e) => return Err(Error::Tangential(e)),
        };
        Ok(sol)
    }

    fn commit(&mut self, sol: &FastSolution, rolled: bool, h: f64) -> TransientStep {
        let m = self.grid.len();
        let (qx, qy): (Vec<f64>, Vec<f64>) = sol.traction.iter().copied().unzip();
        let (mut ux, mut uy) = (vec![0.0; m], vec![0.0; m]);
        self.op.apply(&qx, &qy, &mut ux, &mut uy, &mut self.scratch);
        for k in 0..m {
            self.kq[k] = (ux[k], uy[k]);
        }
        self.traction.clone_from(&sol.traction);
        self.state.clone_from(&sol.state);
        self.slip.clone_from(&sol.slip);
        self.rolled = rolled;
        self.force = (-sol.resultant.0, -sol.resultant.1);
        self.steps += 1;
        if rolled {
            self.rolled_steps += 1;
        }
        let n = self.n_contact;
        let area = self.grid.hx * self.grid.hy;
        // The fast solver's traction is -q and its K(-q) is -u: both products keep their sign.
        let (mut dissipated, mut stored) = (0.0, 0.0);
        for k in 0..m {
            let (t, s, u) = (self.traction[k], self.slip[k], self.kq[k]);
            dissipated += (t.0 * s.0 + t.1 * s.1) * area;
            stored += 0.5 * (t.0 * u.0 + t.1 * u.1) * area;
        }
        // Body 1's traction is minus the fast solver's (as in `solution`).
        let mz = -area
            * (0..n)
                .map(|k| self.grid.x[k] * self.traction[k].1 - self.grid.y[k] * self.traction[k].0)
                .sum::<f64>();
        let (mut contact, mut stick) = (0usize, 0usize);
        for k in 0..n {
            if self.grid.pressure[k] > 0.0 {
                contact += 1;
                if sol.state[k] == ElementState::Stick {
                    stick += 1;
                }
            }
        }
        self.last_info = RollingInfo {
            method: RollingMethod::Transient,
            iterations: sol.info.iterations,
            products: sol.info.products + 1,
            residual: sol.info.residual.max(sol.info.load_residual),
        };
        TransientStep {
            distance: self.rolled_steps as f64 * h,
            force: (-sol.resultant.0, -sol.resultant.1),
            creepage: rolled.then(|| (sol.shift.0 / h, sol.shift.1 / h)),
            shift: sol.shift,
            stick_fraction: if contact > 0 { stick as f64 / contact as f64 } else { 0.0 },
            newton_iterations: sol.info.iterations,
            products: sol.info.products + 1,
            residual: sol.info.residual.max(sol.info.load_residual),
            dissipated,
            elastic_energy: stored,
            mz,
        }
    }

    /// Distance rolled so far (m).
    #[must_use]
    pub fn distance(&self) -> f64 {
        self.rolled_steps as f64 * self.grid.hx
    }

    /// The current state on the contact elements as a [`RollingSolution`]: the traction on
    /// body 1, the slip of the last step per unit rolling distance ($\mathbf S/h_x$ after a
    /// rolling step; the slip itself, m, after a step at rest), stick flags, the resultants.
    #[must_use]
    pub fn solution(&self) -> RollingSolution {
        let n = self.n_contact;
        let contact = ContactGrid {
            hx: self.grid.hx,
            hy: self.grid.hy,
            x: self.grid.x[..n].to_vec(),
            y: self.grid.y[..n].to_vec(),
            pressure: self.grid.pressure[..n].to_vec(),
            patch: self.grid.patch[..n].to_vec(),
        };
        let scale = if self.rolled { 1.0 / self.grid.hx } else { 1.0 };
        // Body 1's traction is minus the fast solver's; the slip S keeps its sign (it
        // points along the fast solver's traction, against body 1's).
        let q = [
            self.traction[..n].iter().map(|v| -v.0).collect(),
            self.traction[..n].iter().map(|v| -v.1).collect(),
        ];
        let s = [
            self.slip[..n].iter().map(|v| v.0 * scale).collect(),
            self.slip[..n].iter().map(|v| v.1 * scale).collect(),
        ];
        let stick = self.state[..n].iter().map(|s| *s == ElementState::Stick).collect();
        RollingSolution::on_grid(&contact, q, s, stick, self.last_info)
    }
}
