//! Partial-slip traction on a contact grid: a tangential force in any in-plane direction, or a
//! twisting moment, solved by the modified LP of seed 002 (§3.3, Fig. 3.5; twist §3.4), with
//! the influence coefficients of FORMULAS.md F.

use crate::contract::{check_pair, Load};
use crate::error::{Error, Result};
use crate::lp::{modified_lp, LpConfig};
use std::time::Instant;
use stickslip_halfspace::Material;
use stickslip_lattice::influence::{projected_matrix, tensor_matrix, Compliance, InfluenceModel};
use stickslip_lattice::ContactGrid;

/// Directions, mode, load magnitude and the assumption record, as prepared for the LP.
type Setup = (Vec<(f64, f64)>, Vec<f64>, f64, DirectionAssumption);

/// Unit directions, relative residual and iterations of the full-stick preprocessor.
type Preprocessed = (Vec<(f64, f64)>, f64, usize);

/// Contact regime of a solution.
#[non_exhaustive]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Regime {
    /// No element slips.
    FullStick,
    /// Some elements stick, some slip.
    PartialSlip,
    /// The load reaches (or exceeds) the friction capacity $\sum_k g_k f P_k$: every element
    /// slips and the bodies slide.
    GrossSlip,
}

/// State of one element.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ElementState {
    /// Moves with the rigid body (slip $Y_{1k} = 0$).
    Stick,
    /// Slips (traction at $fP_k$, $Y_{1k} > 0$).
    Slip,
}

/// The direction assumption under which the solution holds (stated in every result).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DirectionAssumption {
    /// Every element's traction is parallel to the applied force (seed 002 §3.3.1).
    ParallelToLoad {
        /// Load direction, radians from $+x$.
        angle: f64,
    },
    /// Traction directions fixed from the full-stick solution for a rigid rotation about
    /// `centre` (seed 002 §3.4.1); they are not updated as slip spreads.
    FromFullStick {
        /// Centre of rotation.
        centre: (f64, f64),
        /// Relative residual of the full-stick conjugate-gradient solve.
        residual: f64,
        /// Its iterations.
        iterations: usize,
    },
}

/// Per-patch summary.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchSummary {
    /// Sum of the element forces $\sum F_k$ (along the load for a force).
    pub force: f64,
    /// Sum of the capacities $\sum f P_k$.
    pub capacity: f64,
    /// Force-weighted centre of the traction, $\sum F_k\mathbf{x}_k/\sum F_k$.
    pub centre: (f64, f64),
    /// Elements of the patch.
    pub elements: usize,
    /// Slipping elements of the patch.
    pub slipping: usize,
}

/// Solver diagnostics.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveInfo {
    /// LP pivots.
    pub iterations: usize,
    /// Whether a degenerate pivot sequence was met.
    pub degenerate: bool,
    /// Number of degenerate pivots.
    pub degenerate_pivots: usize,
    /// Longest run of consecutive degenerate pivots.
    pub longest_degenerate_run: usize,
    /// Entering candidates refused by the modified entry rule.
    pub rejected_entries: usize,
    /// Wall time to assemble the influence matrices, seconds.
    pub assembly_seconds: f64,
    /// Wall time in the LP, seconds.
    pub lp_seconds: f64,
}

/// The solution on a grid.
#[derive(Debug, Clone, PartialEq)]
pub struct TractionSolution {
    /// Contact regime.
    pub regime: Regime,
    /// Direction assumption used.
    pub assumption: DirectionAssumption,
    /// Unit traction direction of each element.
    pub direction: Vec<(f64, f64)>,
    /// Force per element $F_k$ (along `direction[k]`).
    pub force: Vec<f64>,
    /// Traction per element $F_k/(h_xh_y)$.
    pub traction: Vec<f64>,
    /// Stick or slip per element.
    pub state: Vec<ElementState>,
    /// Slip per element, $\beta g_k - u_k$ (relative displacement units).
    pub slip: Vec<f64>,
    /// Relative elastic displacement per element along its direction, $u = AF$.
    pub displacement: Vec<f64>,
    /// Rigid-body movement $\beta$ of the two bodies relative to each other (a displacement
    /// for a force, a rotation for a moment). For gross slip: the value at the onset of
    /// sliding, $\max_k u_k/g_k$.
    pub rigid: f64,
    /// Per-body share of `rigid`: the mean over stick elements of $u^{(i)}_k/g_k$ (over all
    /// elements with $g_k>0$ taking the maximiser of $u_k/g_k$ when nothing sticks).
    pub rigid_per_body: [f64; 2],
    /// Mode $g_k$ (1 for a force, lever arm for a moment).
    pub mode: Vec<f64>,
    /// Resultant force vector $\sum_k F_k t_k$.
    pub resultant: (f64, f64),
    /// Moment of the traction about the origin, $\sum_k (x_kF_{ky} - y_kF_{kx})$.
    pub moment_about_origin: f64,
    /// Point of application of the resultant: the force-weighted centre
    /// $\sum F_k\mathbf{x}_k/\sum F_k$ (the centre of parallel forces for a force load).
    pub centre_of_traction: (f64, f64),
    /// The friction capacity of the load's mode, $\sum_k fP_k\max(g_k, 0)$: the largest
    /// $|T|$ (or $|M|$ under the fixed twist directions) the contact carries.
    pub capacity: f64,
    /// Load in excess of the friction capacity (0 unless gross slip beyond onset).
    pub excess_load: f64,
    /// Per-patch summaries.
    pub patches: Vec<PatchSummary>,
    /// Diagnostics.
    pub info: SolveInfo,
}

/// A validated problem: grid, the two bodies, friction, load, influence model.
#[derive(Debug, Clone)]
pub struct TractionProblem<'a> {
    grid: &'a ContactGrid,
    bodies: [Material; 2],
    friction: f64,
    load: Load,
    model: InfluenceModel,
    lp: LpConfig,
}

impl<'a> TractionProblem<'a> {
    /// Validate: $f > 0$, a non-empty grid, finite load (force magnitude $\ge 0$), at least
    /// one deformable body, a moment centre that is finite.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] naming the offending input, [`Error::EmptyGrid`],
    /// [`Error::UnsupportedLoad`] for [`Load::ForceAndMoment`] (the LP takes a force or a
    /// moment).
    pub fn new(
        grid: &'a ContactGrid,
        bodies: [Material; 2],
        friction: f64,
        load: Load,
    ) -> Result<Self> {
        check_pair(grid, &bodies, friction)?;
        load.validate()?;
        if let Load::ForceAndMoment { .. } = load {
            return Err(Error::UnsupportedLoad { solver: "modified LP", load: load.kind() });
        }
        Ok(Self {
            grid,
            bodies,
            friction,
            load,
            model: InfluenceModel::default(),
            lp: LpConfig::default(),
        })
    }

    /// Use another influence model (the seed's point-load approximation for like-for-like
    /// comparison with its examples).
    #[must_use]
    pub fn with_model(mut self, model: InfluenceModel) -> Self {
        self.model = model;
        self
    }

    /// Use other LP tolerances.
    #[must_use]
    pub fn with_lp_config(mut self, lp: LpConfig) -> Self {
        self.lp = lp;
        self
    }

    /// The relative compliance constants of the pair, $c_1 = \sum_i(1-\nu_i)/G_i$,
    /// $c_2 = \sum_i\nu_i/G_i$ ([`Compliance::pair`]; FORMULAS.md F, $A = A^{(1)} + A^{(2)}$).
    #[must_use]
    pub fn compliance(&self) -> Compliance {
        Compliance::pair(&self.bodies[0], &self.bodies[1])
    }

    /// Directions, mode and load for the LP, plus the assumption record.
    fn setup(&self) -> Result<Setup> {
        let g = self.grid;
        let n = g.len();
        match self.load {
            Load::Force { magnitude, angle } => {
                let t = (angle.cos(), angle.sin());
                Ok((
                    vec![t; n],
                    vec![1.0; n],
                    magnitude,
                    DirectionAssumption::ParallelToLoad { angle },
                ))
            }
            Load::Moment { moment, centre } => {
                let centre = centre.unwrap_or_else(|| g.force_centroid());
                let sign = if moment < 0.0 { -1.0 } else { 1.0 };
                let (dirs, residual, iterations) =
                    full_stick_directions(g, &self.compliance(), self.model, centre, sign)?;
                let mode: Vec<f64> = (0..n)
                    .map(|k| {
                        let (dx, dy) = (g.x[k] - centre.0, g.y[k] - centre.1);
                        sign * (-dy * dirs[k].0 + dx * dirs[k].1)
                    })
                    .collect();
                Ok((
                    dirs,
                    mode,
                    moment.abs(),
                    DirectionAssumption::FromFullStick { centre, residual, iterations },
                ))
            }
            _ => Err(Error::UnsupportedLoad { solver: "modified LP", load: self.load.kind() }),
        }
    }

    /// Solve seed 002 eq. (3.13) on the grid with [`modified_lp`]: the influence matrix is
    /// $A = c_1B_1 + c_2B_2$, the pair's projected matrix ([`projected_matrix`]; FORMULAS.md
    /// F), the capacities are $c_k = fP_k$, the mode is $g_k = 1$ for a force or the lever arm
    /// $g_k = \hat z\cdot\big((\mathbf x_k - \mathbf c)\times\mathbf t_k\big)$ for a moment
    /// (seed 002 §3.4), and $L = |T|$ or $|M|$. When $L \ge \sum_k c_k\max(g_k, 0)$ every
    /// element slips at its capacity (gross slip) and the LP is skipped; $L = 0$ gives zero
    /// traction.
    ///
    /// # Errors
    /// [`Error::Infeasible`] / [`Error::NotConverged`] (pivot budget) from the LP;
    /// [`Error::NotPositiveDefinite`] if the twist preprocessor fails.
    pub fn solve(&self) -> Result<TractionSolution> {
        let grid = self.grid;
        let n = grid.len();
        let t0 = Instant::now();
        let (dirs, mode, load, assumption) = self.setup()?;
        // Unit-compliance component matrices: A = c1 B1 + c2 B2 for any body or pair.
        let b1 = projected_matrix(
            grid,
            &Compliance { one_minus_nu: 1.0, nu: 0.0, one_minus_two_nu: 0.0 },
            self.model,
            &dirs,
        );
        let b2 = projected_matrix(
            grid,
            &Compliance { one_minus_nu: 0.0, nu: 1.0, one_minus_two_nu: 0.0 },
            self.model,
            &dirs,
        );
        let c = self.compliance();
        let a: Vec<f64> = b1.iter().zip(&b2).map(|(x, y)| c.one_minus_nu * x + c.nu * y).collect();
        let assembly_time = t0.elapsed();

        let cap: Vec<f64> = grid.normal_force().iter().map(|p| self.friction * p).collect();
        let capacity: f64 = cap.iter().zip(&mode).map(|(c, g)| c * g.max(0.0)).sum();
        let t1 = Instant::now();
        let (force, beta, slip, mut info, gross) = if load >= capacity * (1.0 - 1e-12) {
            let u = matvec(&a, &cap);
            let beta = (0..n)
                .filter(|&k| mode[k] > 0.0)
                .map(|k| u[k] / mode[k])
                .fold(f64::NEG_INFINITY, f64::max);
            let slip: Vec<f64> = (0..n).map(|k| beta * mode[k] - u[k]).collect();
            (cap.clone(), beta, slip, SolveInfo::zero(), true)
        } else if load == 0.0 {
            (vec![0.0; n], 0.0, vec![0.0; n], SolveInfo::zero(), false)
        } else {
            let s = modified_lp(&a, &mode, &cap, load, &self.lp)?;
            let info = SolveInfo {
                iterations: s.iterations,
                degenerate: s.degenerate(),
                degenerate_pivots: s.degenerate_pivots,
                longest_degenerate_run: s.longest_degenerate_run,
                rejected_entries: s.rejected_entries,
                assembly_seconds: 0.0,
                lp_seconds: 0.0,
            };
            (s.force, s.rigid, s.slip, info, false)
        };
        info.assembly_seconds = assembly_time.as_secs_f64();
        info.lp_seconds = t1.elapsed().as_secs_f64();

        let u = matvec(&a, &force);
        let gmax = mode.iter().map(|g| g.abs()).fold(0.0, f64::max);
        let slip_tol = 1e-9 * (beta.abs() * gmax).max(f64::MIN_POSITIVE);
        let state: Vec<ElementState> =
            (0..n)
                .map(|k| {
                    if gross || slip[k] > slip_tol {
                        ElementState::Slip
                    } else {
                        ElementState::Stick
                    }
                })
                .collect();
        let n_slip = state.iter().filter(|s| **s == ElementState::Slip).count();
        let regime = if gross {
            Regime::GrossSlip
        } else if n_slip == 0 {
            Regime::FullStick
        } else {
            Regime::PartialSlip
        };

        // Per-body rigid movement.
        let mut rigid_per_body = [0.0; 2];
        for (i, body) in self.bodies.iter().enumerate() {
            let cb = body.compliance();
            let ub: Vec<f64> = {
                let u1 = matvec(&b1, &force);
                let u2 = matvec(&b2, &force);
                u1.iter().zip(&u2).map(|(x, y)| cb.one_minus_nu * x + cb.nu * y).collect()
            };
            let stick: Vec<usize> =
                (0..n).filter(|&k| state[k] == ElementState::Stick && mode[k] > 0.0).collect();
            rigid_per_body[i] = if stick.is_empty() {
                let kmax = (0..n)
                    .filter(|&k| mode[k] > 0.0)
                    .max_by(|&p, &q| (u[p] / mode[p]).total_cmp(&(u[q] / mode[q])))
                    .unwrap_or(0);
                ub[kmax] / mode[kmax]
            } else {
                stick.iter().map(|&k| ub[k] / mode[k]).sum::<f64>() / stick.len() as f64
            };
        }

        let area = grid.element_area();
        let traction: Vec<f64> = force.iter().map(|f| f / area).collect();
        let (mut rx, mut ry, mut mz) = (0.0, 0.0, 0.0);
        for k in 0..n {
            let (fx, fy) = (force[k] * dirs[k].0, force[k] * dirs[k].1);
            rx += fx;
            ry += fy;
            mz += grid.x[k] * fy - grid.y[k] * fx;
        }
        let centre_of = |ks: &mut dyn Iterator<Item = usize>| {
            let (mut s, mut sx, mut sy) = (0.0, 0.0, 0.0);
            for k in ks {
                s += force[k];
                sx += force[k] * grid.x[k];
                sy += force[k] * grid.y[k];
            }
            if s > 0.0 {
                (s, (sx / s, sy / s))
            } else {
                (0.0, (f64::NAN, f64::NAN))
            }
        };
        let (_, centre_of_traction) = centre_of(&mut (0..n));
        let npatch = grid.patch.iter().copied().max().unwrap_or(0) + 1;
        let patches = (0..npatch)
            .map(|p| {
                let (s, centre) = centre_of(&mut (0..n).filter(|&k| grid.patch[k] == p));
                PatchSummary {
                    force: s,
                    capacity: (0..n).filter(|&k| grid.patch[k] == p).map(|k| cap[k]).sum(),
                    centre,
                    elements: grid.patch.iter().filter(|&&q| q == p).count(),
                    slipping: (0..n)
                        .filter(|&k| grid.patch[k] == p && state[k] == ElementState::Slip)
                        .count(),
                }
            })
            .collect();
        let sign = match self.load {
            Load::Moment { moment, .. } if moment < 0.0 => -1.0,
            _ => 1.0,
        };
        Ok(TractionSolution {
            regime,
            assumption,
            direction: dirs,
            force,
            traction,
            state,
            slip,
            displacement: u,
            rigid: sign * beta,
            rigid_per_body: [sign * rigid_per_body[0], sign * rigid_per_body[1]],
            mode,
            resultant: (rx, ry),
            moment_about_origin: mz,
            centre_of_traction,
            capacity,
            excess_load: (load - capacity).max(0.0),
            patches,
            info,
        })
    }
}

impl SolveInfo {
    fn zero() -> Self {
        Self {
            iterations: 0,
            degenerate: false,
            degenerate_pivots: 0,
            longest_degenerate_run: 0,
            rejected_entries: 0,
            assembly_seconds: 0.0,
            lp_seconds: 0.0,
        }
    }
}

fn matvec(a: &[f64], x: &[f64]) -> Vec<f64> {
    let n = x.len();
    (0..n).map(|k| a[k * n..(k + 1) * n].iter().zip(x).map(|(p, q)| p * q).sum()).collect()
}

/// The seed's twist preprocessor (§3.4.1): solve the full-stick problem
/// $U\tau = \omega\,\hat z\times(\mathbf x_k - \mathbf c)$ for a unit rotation by conjugate
/// gradients on the symmetric positive definite $2N\times2N$ tensor matrix, and return the
/// unit traction directions (circumferential where the traction vanishes).
fn full_stick_directions(
    grid: &ContactGrid,
    c: &Compliance,
    model: InfluenceModel,
    centre: (f64, f64),
    sign: f64,
) -> Result<Preprocessed> {
    let n = grid.len();
    let m = 2 * n;
    let u = tensor_matrix(grid, c, model);
    let mut b = vec![0.0; m];
    for k in 0..n {
        let (dx, dy) = (grid.x[k] - centre.0, grid.y[k] - centre.1);
        b[2 * k] = -dy;
        b[2 * k + 1] = dx;
    }
    let bnorm = b.iter().map(|v| v * v).sum::<f64>().sqrt();
    let mut x = vec![0.0; m];
    let mut r = b.clone();
    let mut p = r.clone();
    let mut rr: f64 = r.iter().map(|v| v * v).sum();
    let mut it = 0;
    let max_it = 10 * m + 100;
    while rr.sqrt() > 1e-12 * bnorm && it < max_it {
        let ap = matvec(&u, &p);
        let pap: f64 = p.iter().zip(&ap).map(|(a, b)| a * b).sum();
        if pap <= 0.0 {
            return Err(Error::NotPositiveDefinite { index: it });
        }
        let alpha = rr / pap;
        for i in 0..m {
            x[i] += alpha * p[i];
            r[i] -= alpha * ap[i];
        }
        let rr_new: f64 = r.iter().map(|v| v * v).sum();
        let beta = rr_new / rr;
        rr = rr_new;
        for i in 0..m {
            p[i] = r[i] + beta * p[i];
        }
        it += 1;
    }
    let residual = if bnorm > 0.0 { rr.sqrt() / bnorm } else { 0.0 };
    let dirs = (0..n)
        .map(|k| {
            let (tx, ty) = (x[2 * k], x[2 * k + 1]);
            let norm = tx.hypot(ty);
            if norm > 0.0 {
                (sign * tx / norm, sign * ty / norm)
            } else {
                (sign, 0.0)
            }
        })
        .collect();
    Ok((dirs, residual, it))
}
