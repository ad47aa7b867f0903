//! A load path between dissimilar bodies: each step solved coupled with its normal contact
//! through Dundurs' $\beta$ (module docs of [`crate::history`], "Dissimilar bodies").

use super::path::{LoadPath, PathControl};
use super::problem::{HistoryOutcome, HistoryProblem, StepTarget};
use super::stepper::{LoadHistory, StepTrial};
use crate::error::{Error, Result};
use crate::fast::WarmStart;
use stickslip_halfspace::material::dundurs_beta;
use stickslip_halfspace::rectangle::Compliance;
use stickslip_lattice::{ContactGrid, CrossOperator};

/// The coupling iteration's name (as in [`Error::NotConverged`]).
pub const COUPLING_NAME: &str = "load path Dundurs coupling (alternating passes)";

/// The loads of a step: tangential, normal, moment.
type Loads = (f64, f64, f64);

/// Default limit of coupling passes per step.
pub const DEFAULT_COUPLING_PASSES: usize = 60;

/// The cross operators of a load path between dissimilar bodies, on the lattice that holds
/// the history's grid: the tangential displacement of a pressure, $K^{tn}p$, and the normal
/// displacement of a traction, $K^{nt}\mathbf q$ (`stickslip_lattice::CrossOperator`, free or
/// periodic), with the stopping rule of the alternation.
#[derive(Debug)]
pub struct PathCoupling {
    op: CrossOperator,
    lattice: (usize, usize),
    index: Vec<usize>,
    beta: f64,
    active: bool,
    two_way: bool,
    tolerance: f64,
    max_passes: usize,
}

impl PathCoupling {
    /// The coupling of `bodies` = [substrate, indenter] on an `nx` × `ny` lattice of cells
    /// `grid.hx` × `grid.hy` whose lowest cell edges are at `origin` (m): every grid cell must
    /// be a cell of it. `periodic`: the lattice is one period (the periodic cross operators).
    /// The pressure is taken to respond to the traction (two-way coupling: the caller's
    /// normal solve takes $K^{nt}\mathbf q$ into its gap); tolerance $10^{-8}$, at most
    /// [`DEFAULT_COUPLING_PASSES`] passes.
    ///
    /// With $\beta = 0$ (identical bodies, or any pair with
    /// $(1-2\nu_1)/G_1 = (1-2\nu_2)/G_2$) the cross terms vanish: every step is one uncoupled
    /// pass, exactly [`HistoryProblem::run`]'s step.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a grid cell outside the lattice or an empty lattice.
    pub fn new(
        grid: &ContactGrid,
        bodies: [stickslip_halfspace::Material; 2],
        (nx, ny): (usize, usize),
        origin: (f64, f64),
        periodic: bool,
    ) -> Result<Self> {
        if nx == 0 || ny == 0 {
            return Err(Error::OutOfDomain {
                name: "coupling lattice cells",
                value: 0.0,
                allowed: "at least one cell each way",
            });
        }
        let c = Compliance::pair(&bodies[0], &bodies[1]);
        let cell = (grid.hx, grid.hy);
        let op = if periodic {
            CrossOperator::periodic(nx, ny, cell, &c)
        } else {
            CrossOperator::new(nx, ny, cell, &c)
        };
        let mut index = Vec::with_capacity(grid.len());
        for (x, y) in grid.x.iter().zip(&grid.y) {
            let i = ((x - origin.0) / grid.hx - 0.5).round();
            let j = ((y - origin.1) / grid.hy - 0.5).round();
            if !(i >= 0.0 && j >= 0.0 && (i as usize) < nx && (j as usize) < ny) {
                return Err(Error::OutOfDomain {
                    name: "history grid cell outside the coupling lattice (x)",
                    value: *x,
                    allowed: "cells of the lattice",
                });
            }
            index.push(j as usize * nx + i as usize);
        }
        Ok(Self {
            op,
            lattice: (nx, ny),
            index,
            beta: dundurs_beta(&bodies[0], &bodies[1]),
            active: c.one_minus_two_nu != 0.0,
            two_way: true,
            tolerance: 1e-8,
            max_passes: DEFAULT_COUPLING_PASSES,
        })
    }

    /// The pressure is prescribed (it does not respond to the traction: a given pressure
    /// shape, patches): only $K^{tn}\Delta p$ enters the slip, one pass per step.
    #[must_use]
    pub fn one_way(mut self) -> Self {
        self.two_way = false;
        self
    }

    /// The relative tolerance of the alternation (at most $10^{-1}$, at least $10^{-14}$):
    /// a step is accepted when its traction differs from the traction that made its
    /// pressure by at most this much ($L^2$, relative).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] outside that range.
    pub fn with_tolerance(mut self, tolerance: f64) -> Result<Self> {
        if !(1e-14..=1e-1).contains(&tolerance) {
            return Err(Error::OutOfDomain {
                name: "coupling tolerance",
                value: tolerance,
                allowed: "1e-14 to 1e-1",
            });
        }
        self.tolerance = tolerance;
        Ok(self)
    }

    /// Limit the passes per step (at least 1).
    #[must_use]
    pub fn with_max_passes(mut self, passes: usize) -> Self {
        self.max_passes = passes.max(1);
        self
    }

    /// Dundurs' $\beta$ of the pair.
    #[must_use]
    pub fn beta(&self) -> f64 {
        self.beta
    }

    /// Whether the steps alternate (the cross terms are not zero and the pressure responds
    /// to the traction).
    #[must_use]
    pub fn alternates(&self) -> bool {
        self.active && self.two_way
    }

    /// Whether the cross terms are not zero ($c_3 \ne 0$).
    #[must_use]
    pub fn is_active(&self) -> bool {
        self.active
    }

    /// The tolerance of the alternation.
    #[must_use]
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// The tangential displacement $K^{tn}p$ (m) of a pressure per grid cell (Pa).
    #[must_use]
    pub fn tangential_of_pressure(&self, pressure: &[f64]) -> Vec<(f64, f64)> {
        let (nx, ny) = self.lattice;
        let mut p = vec![0.0; nx * ny];
        for (&k, v) in self.index.iter().zip(pressure) {
            p[k] = *v;
        }
        let (ux, uy) = self.op.traction_from_pressure(&p);
        self.index.iter().map(|&k| (ux[k], uy[k])).collect()
    }

    /// The normal displacement $K^{nt}\mathbf q$ (m) of a traction per grid cell (Pa), on
    /// every lattice cell (row-major `j * nx + i`), to be added to the initial gap.
    #[must_use]
    pub fn normal_of_traction(&self, traction: &[(f64, f64)]) -> Vec<f64> {
        let (nx, ny) = self.lattice;
        let (mut qx, mut qy) = (vec![0.0; nx * ny], vec![0.0; nx * ny]);
        for (&k, q) in self.index.iter().zip(traction) {
            qx[k] = q.0;
            qy[k] = q.1;
        }
        self.op.normal_from_traction(&qx, &qy)
    }
}

impl HistoryProblem<'_> {
    /// Solve a whole path between dissimilar bodies (module docs, "Dissimilar bodies"):
    /// each step alternates a normal solve and a tangential pass until the traction settles.
    ///
    /// `pressure(P, un)` gives the pressure of every grid cell under the normal load $P$ when
    /// the traction's normal displacement on the coupling lattice is `un` (to be added to the
    /// initial gap; `None`: no traction, as for the corner checks). A prescribed pressure
    /// ([`PathCoupling::one_way`]) ignores `un`. `observe` as in
    /// [`HistoryProblem::run_observed`].
    ///
    /// # Errors
    /// As [`HistoryProblem::run`]; [`Error::HistoryStep`] wrapping [`Error::NotConverged`]
    /// (named [`COUPLING_NAME`]) when a step's traction still changes by more than the
    /// tolerance after the last pass.
    pub fn run_coupled<E, F, O>(
        &self,
        path: &LoadPath,
        coupling: &PathCoupling,
        mut pressure: F,
        mut observe: O,
    ) -> std::result::Result<HistoryOutcome, E>
    where
        E: From<Error>,
        F: FnMut(f64, Option<&[f64]>) -> std::result::Result<Vec<f64>, E>,
        O: FnMut(usize, Option<usize>, &LoadHistory<'_>) -> std::result::Result<(), E>,
    {
        if coupling.index.len() != self.grid.len() {
            return Err(Error::LengthMismatch {
                name: "coupling lattice map (one per grid cell)",
                expected: self.grid.len(),
                got: coupling.index.len(),
            }
            .into());
        }
        // The corners first, on the uncoupled pressure (the capacity f P does not depend on
        // how the pressure is distributed).
        self.check_corners(path, |p| pressure(p, None))?;
        let mut h = self.start()?;
        let mut cache: Option<(f64, Vec<f64>)> = None;
        // The last step's loads and traction, for the first pass's traction (below).
        let mut before: Option<(Loads, Vec<(f64, f64)>)> = None;
        let mut loads_prev: Option<(f64, f64, f64)> = None;
        for (i, pt) in path.points().into_iter().enumerate() {
            let loads = (pt.tangential, pt.normal, pt.moment.unwrap_or(0.0));
            let target = StepTarget {
                control: path.control(),
                tangential: pt.tangential,
                moment: pt.moment,
            };
            let wrap = |e: Error| Error::HistoryStep { step: i, source: Box::new(e) };
            if !coupling.alternates() {
                if cache.as_ref().is_none_or(|(q, _)| *q != pt.normal) {
                    cache = Some((pt.normal, pressure(pt.normal, None)?));
                }
                let pr = cache.as_ref().map(|c| c.1.as_slice());
                let c = match (coupling.active, pr) {
                    (true, Some(p)) => Some(coupling.tangential_of_pressure(p)),
                    _ => None,
                };
                let trial = h.trial(pr, target, c.as_deref(), None).map_err(wrap)?;
                h.accept(trial, 1, (0.0, 0.0));
            } else {
                // The first pass's gap takes the traction extrapolated along the last
                // increment when the loads continue along it (ratio r of the increments),
                // else the last step's: only a start, the stopping test compares each pass
                // with the traction that made its gap.
                let mut used = h.traction().to_vec();
                if let (Some(lp), Some((lb, qb))) = (loads_prev, &before) {
                    if let Some(r) = continuation(loads, lp, *lb) {
                        for (u, b) in used.iter_mut().zip(qb) {
                            *u = (u.0 + r * (u.0 - b.0), u.1 + r * (u.1 - b.1));
                        }
                    }
                }
                let q_last = h.traction().to_vec();
                let mut warm: Option<WarmStart> = None;
                let mut last = f64::INFINITY;
                let mut done = false;
                let mut earlier: Option<StepTrial> = None;
                for pass in 1..=coupling.max_passes {
                    let un = coupling.normal_of_traction(&used);
                    let p = pressure(pt.normal, Some(&un))?;
                    let c = coupling.tangential_of_pressure(&p);
                    let mut trial =
                        h.trial(Some(&p), target, Some(&c), warm.as_ref()).map_err(wrap)?;
                    last = rel_change(trial.traction(), &used);
                    let dp = earlier.as_ref().map_or(0.0, |e| rel_change_scalar(&p, e.pressure()));
                    if let Some(e) = &earlier {
                        trial.absorb(e);
                    }
                    if last <= coupling.tolerance {
                        h.accept(trial, pass, (last, dp));
                        done = true;
                        break;
                    }
                    used = trial.traction().to_vec();
                    warm = Some(WarmStart::from(trial.solution()));
                    earlier = Some(trial);
                }
                before = loads_prev.map(|lp| (lp, q_last));
                if !done {
                    return Err(wrap(Error::NotConverged {
                        solver: COUPLING_NAME,
                        iterations: coupling.max_passes,
                        residual: last,
                        tolerance: coupling.tolerance,
                    })
                    .into());
                }
            }
            loads_prev = Some(loads);
            observe(i, pt.corner, &h)?;
        }
        Ok(h.into_outcome())
    }

    /// The corner checks of [`HistoryProblem::run`] (force control) with a plain pressure
    /// function.
    fn check_corners<E, F>(&self, path: &LoadPath, mut pressure: F) -> std::result::Result<(), E>
    where
        E: From<Error>,
        F: FnMut(f64) -> std::result::Result<Vec<f64>, E>,
    {
        if path.has_moment() {
            self.check_moment_allowed(path.control(), path.corner(0).map_or(0.0, |c| c.2))?;
        }
        if path.control() != PathControl::Force {
            return Ok(());
        }
        let e = (self.angle.cos(), self.angle.sin());
        for i in 0..path.corners() {
            let (t, p, m) = path.corner(i).unwrap_or((0.0, 1.0, 0.0));
            let pr = pressure(p)?;
            if pr.len() != self.grid.len() {
                return Err(Error::LengthMismatch {
                    name: "history pressure (one per grid cell)",
                    expected: self.grid.len(),
                    got: pr.len(),
                }
                .into());
            }
            self.check_corner(i, t, m, &pr, e, path.has_moment())?;
        }
        Ok(())
    }
}

/// The ratio $r \ge 0$ of the load increment `now - last` to `last - before` when the
/// two are parallel (to $10^{-9}$ of the larger), else `None`.
fn continuation(
    now: (f64, f64, f64),
    last: (f64, f64, f64),
    before: (f64, f64, f64),
) -> Option<f64> {
    let d1 = [now.0 - last.0, now.1 - last.1, now.2 - last.2];
    let d0 = [last.0 - before.0, last.1 - before.1, last.2 - before.2];
    let n0: f64 = d0.iter().map(|v| v * v).sum::<f64>().sqrt();
    if n0 == 0.0 {
        return None;
    }
    let r = d1.iter().zip(&d0).map(|(a, b)| a * b).sum::<f64>() / (n0 * n0);
    let off: f64 = d1.iter().zip(&d0).map(|(a, b)| (a - r * b).powi(2)).sum::<f64>().sqrt();
    let n1: f64 = d1.iter().map(|v| v * v).sum::<f64>().sqrt();
    ((0.0..=4.0).contains(&r) && off <= 1e-9 * n0.max(n1)).then_some(r)
}

/// $\lVert\mathbf a - \mathbf b\rVert_2/\lVert\mathbf a\rVert_2$ over the (a, b) component
/// pairs (0 when both are zero).
fn rel_change_of(pairs: impl Iterator<Item = (f64, f64)>) -> f64 {
    let (mut d, mut s) = (0.0, 0.0);
    for (x, y) in pairs {
        d += (x - y).powi(2);
        s += x * x;
    }
    if s > 0.0 {
        (d / s).sqrt()
    } else if d > 0.0 {
        f64::INFINITY
    } else {
        0.0
    }
}

/// The relative change of a scalar field.
fn rel_change_scalar(a: &[f64], b: &[f64]) -> f64 {
    rel_change_of(a.iter().copied().zip(b.iter().copied()))
}

/// The relative change of a traction field (both components).
fn rel_change(a: &[(f64, f64)], b: &[(f64, f64)]) -> f64 {
    rel_change_of(a.iter().zip(b).flat_map(|(x, y)| [(x.0, y.0), (x.1, y.1)]))
}
