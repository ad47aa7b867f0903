//! One fast solve of a step, at a force or at a shift, from the first start that converges.

use super::problem::HistoryProblem;
use crate::contract::Load;
use crate::error::{Error, Result};
use crate::fast::{FastProblem, FastSolution, TractionDirections, WarmStart};
use std::f64::consts::PI;
use stickslip_lattice::{ContactGrid, ConvScratch, TensorConvolution};

/// What one fast solve needs, borrowed from the stepper.
pub(super) struct Ctx<'x> {
    pub(super) grid: &'x ContactGrid,
    pub(super) p: &'x HistoryProblem<'x>,
    pub(super) op: &'x TensorConvolution,
    pub(super) fixed: &'x Option<Vec<(f64, f64)>>,
    pub(super) centre: (f64, f64),
    /// The step continues a converged state (not the path's first step).
    pub(super) increment: bool,
}

/// Tallies of the solves of one step.
#[derive(Debug, Clone, Default)]
pub(super) struct Tally {
    pub(super) solves: usize,
    pub(super) newton: usize,
    pub(super) products: usize,
}

impl Ctx<'_> {
    /// One fast solve at the force $T$ along the path (negative: the opposite way) and the
    /// moment, with the prescribed displacement `u0`, from the first of `starts` that
    /// converges (`None`: the solver's cold start). A load beyond the capacity or bad input
    /// fails at once; a start from which the iteration does not converge
    /// ([`Error::NotConverged`], [`Error::NoStickLeft`], [`Error::NotPositiveDefinite`])
    /// passes to the next, and the last one's error is returned.
    pub(super) fn solve_force(
        &self,
        scratch: &mut ConvScratch,
        t: f64,
        moment: Option<f64>,
        u0: Option<&[(f64, f64)]>,
        starts: &[Option<&WarmStart>],
        tally: &mut Tally,
    ) -> Result<FastSolution> {
        let angle = self.p.angle;
        let (mag, ang) = if t >= 0.0 { (t, angle) } else { (-t, angle + PI) };
        let mut load = Load::polar(mag, ang)?;
        if let Some(m) = moment {
            load = load.with_moment(m, Some(self.centre))?;
        }
        let mut fp = FastProblem::new(self.grid, self.p.bodies, self.p.friction, load)?
            .with_model(self.p.model)
            .with_config(self.p.config);
        if let Some(lattice) = self.p.periodic {
            fp = fp.with_periodic(lattice)?;
        }
        if let Some(d) = self.fixed {
            fp = fp.with_directions(TractionDirections::Fixed(d.clone()))?;
        }
        if let Some(u0) = u0 {
            fp = fp.with_prescribed_displacement(u0)?;
            if self.increment {
                fp = fp.with_increment_start();
            }
        }
        let mut last = Error::EmptyGrid { reason: "no start given" };
        for start in starts {
            let solved = match start {
                Some(w) => fp.solve_from(self.op, scratch, w),
                None => fp.solve_with(self.op, scratch),
            };
            tally.solves += 1;
            match solved {
                Ok(s) => {
                    tally.newton += s.info.iterations;
                    tally.products += s.info.products;
                    return Ok(s);
                }
                Err(
                    e @ (Error::NotConverged { .. }
                    | Error::NoStickLeft { .. }
                    | Error::NotPositiveDefinite { .. }),
                ) => last = e,
                Err(e) => return Err(e),
            }
        }
        Err(last)
    }

    /// Shift control: the force whose solution shifts by `inc` along the path (module docs).
    /// Returns the solution (shift and slip set to the prescribed increment when sliding).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn solve_shift(
        &self,
        scratch: &mut ConvScratch,
        inc: f64,
        u0: Option<&[(f64, f64)]>,
        starts: &[Option<&WarmStart>],
        t_prev: f64,
        stiffness: Option<f64>,
        tally: &mut Tally,
    ) -> Result<FastSolution> {
        let e = (self.p.angle.cos(), self.p.angle.sin());
        let along = |s: &FastSolution| s.shift.0 * e.0 + s.shift.1 * e.1;
        let cap = self.p.capacity(&self.grid.pressure);
        // Sliding forward or backward: the onset shifts bound what partial slip reaches.
        let slide = |mut s: FastSolution| {
            let extra = inc - along(&s);
            s.shift = (s.shift.0 + extra * e.0, s.shift.1 + extra * e.1);
            for v in &mut s.slip {
                v.0 += extra * e.0;
                v.1 += extra * e.1;
            }
            s
        };
        let hi = self.solve_force(scratch, cap, None, u0, starts, tally)?;
        let g_hi = along(&hi) - inc;
        if g_hi <= 0.0 {
            return Ok(slide(hi));
        }
        let lo = self.solve_force(scratch, -cap, None, u0, starts, tally)?;
        let g_lo = along(&lo) - inc;
        if g_lo >= 0.0 {
            return Ok(slide(lo));
        }
        let tol = 1e-9 * (along(&hi) - along(&lo));
        let (mut a, mut b) = (-cap, cap);
        // First trial from the last step's secant stiffness (or the mean one over the
        // partial-slip range).
        let k = stiffness
            .filter(|k| k.is_finite() && *k > 0.0)
            .unwrap_or(2.0 * cap / (along(&hi) - along(&lo)));
        let inside = |t: f64, a: f64, b: f64| {
            let m = 1e-6 * (b - a);
            t.clamp(a + m, b - m)
        };
        let mut t = inside(t_prev + k * inc, a, b);
        let mut prev: Option<(f64, f64)> = None;
        let mut warm: Option<WarmStart> = None;
        for _ in 0..60 {
            let mut tries: Vec<Option<&WarmStart>> = Vec::with_capacity(starts.len() + 1);
            if let Some(w) = &warm {
                tries.push(Some(w));
            }
            tries.extend_from_slice(starts);
            let s = self.solve_force(scratch, t, None, u0, &tries, tally)?;
            let g = along(&s) - inc;
            if g.abs() <= tol || b - a <= 1e-13 * cap {
                return Ok(s);
            }
            if g < 0.0 {
                a = t;
            } else {
                b = t;
            }
            // Secant through the last two trials when it stays inside the bracket, else
            // bisection.
            let next = match prev {
                Some((tp, gp)) if g != gp => t - g * (t - tp) / (g - gp),
                _ => t - g * k,
            };
            prev = Some((t, g));
            t = if next > a && next < b { next } else { 0.5 * (a + b) };
            warm = Some(WarmStart::from(&s));
        }
        Err(Error::NotConverged {
            solver: "load history shift search",
            iterations: 60,
            residual: prev.map_or(f64::INFINITY, |p| p.1.abs()),
            tolerance: tol,
        })
    }
}
