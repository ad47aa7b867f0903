//! Load paths (corner values, linear sub-steps between them) and the closed loops found
//! along a solved path.

use super::HistoryStep;
use crate::error::{Error, Result};

/// What a path prescribes along its direction.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PathControl {
    /// The tangential force $T$ (N) along the path direction: the rigid shift follows.
    Force,
    /// The rigid tangential shift $\delta$ (m) of the two bodies along the path direction,
    /// with zero force across it: the force follows, and beyond the onset of sliding the
    /// contact slides at its capacity.
    Shift,
}

/// A load path: corner values of the tangential load (force or shift along one direction),
/// of the normal load and optionally of a twisting moment, applied in order and linearly
/// interpolated with `steps` sub-steps between two corners.
///
/// The path starts from the unloaded, traction-free state: the first corner is reached in
/// one step (so a path that should load gradually starts at zero tangential load).
#[derive(Debug, Clone, PartialEq)]
pub struct LoadPath {
    control: PathControl,
    tangential: Vec<f64>,
    normal: Vec<f64>,
    moment: Option<Vec<f64>>,
    steps: usize,
}

/// One step of a [`LoadPath`]: the loads to reach in that step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathPoint {
    /// Tangential force (N) or shift (m) along the path direction, by [`LoadPath::control`].
    pub tangential: f64,
    /// Normal load $P$ (N).
    pub normal: f64,
    /// Twisting moment (N m), if the path has one.
    pub moment: Option<f64>,
    /// The corner this step reaches, if it is one (0-based).
    pub corner: Option<usize>,
}

fn finite_all(name: &'static str, v: &[f64]) -> Result<()> {
    match v.iter().find(|x| !x.is_finite()) {
        Some(&x) => Err(Error::OutOfDomain { name, value: x, allowed: "finite" }),
        None => Ok(()),
    }
}

impl LoadPath {
    /// A path of corner values `tangential` (force in N or shift in m along the path
    /// direction, by `control`) and `normal` (N; one value for a constant normal load, or one
    /// per corner), `steps` $\ge 1$ sub-steps between two corners.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for no corner, a
    /// non-finite value or `steps == 0`; [`Error::LengthMismatch`] (name
    /// `"load path normal (corner values)"`) when `normal` has neither 1 nor as many entries
    /// as `tangential`; [`Error::PathCorner`] for a normal load $\le 0$ at a corner (a path
    /// that separates the bodies is not solved).
    pub fn new(
        control: PathControl,
        tangential: Vec<f64>,
        normal: Vec<f64>,
        steps: usize,
    ) -> Result<Self> {
        if tangential.is_empty() {
            return Err(Error::OutOfDomain {
                name: "load path corners",
                value: 0.0,
                allowed: ">= 1 corner",
            });
        }
        if steps == 0 {
            return Err(Error::OutOfDomain {
                name: "load path steps between corners",
                value: 0.0,
                allowed: ">= 1",
            });
        }
        finite_all("load path tangential (corner values)", &tangential)?;
        finite_all("load path normal (corner values)", &normal)?;
        let normal = match normal.len() {
            1 => vec![normal[0]; tangential.len()],
            n if n == tangential.len() => normal,
            n => {
                return Err(Error::LengthMismatch {
                    name: "load path normal (corner values)",
                    expected: tangential.len(),
                    got: n,
                })
            }
        };
        if let Some((corner, &value)) = normal.iter().enumerate().find(|(_, p)| **p <= 0.0) {
            return Err(Error::PathCorner {
                corner,
                name: "normal load",
                value,
                allowed: "> 0 (a path that separates the bodies is not solved)",
            });
        }
        Ok(Self { control, tangential, normal, moment: None, steps })
    }

    /// Add a twisting moment per corner (N m, same length as the tangential values), about
    /// the history's fixed centre ([`crate::history::HistoryProblem::with_centre`]).
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] (name `"load path moment (corner values)"`),
    /// [`Error::OutOfDomain`] for a non-finite value.
    pub fn with_moment(mut self, moment: Vec<f64>) -> Result<Self> {
        finite_all("load path moment (corner values)", &moment)?;
        if moment.len() != self.tangential.len() {
            return Err(Error::LengthMismatch {
                name: "load path moment (corner values)",
                expected: self.tangential.len(),
                got: moment.len(),
            });
        }
        self.moment = Some(moment);
        Ok(self)
    }

    /// Force or shift control.
    #[must_use]
    pub fn control(&self) -> PathControl {
        self.control
    }

    /// Number of corners.
    #[must_use]
    pub fn corners(&self) -> usize {
        self.tangential.len()
    }

    /// Sub-steps between two corners.
    #[must_use]
    pub fn steps_between(&self) -> usize {
        self.steps
    }

    /// The corner values: tangential, normal and moment (0 when the path has none).
    #[must_use]
    pub fn corner(&self, i: usize) -> Option<(f64, f64, f64)> {
        let m = self.moment.as_ref().map_or(0.0, |m| m[i]);
        Some((*self.tangential.get(i)?, self.normal[i], m))
    }

    /// Whether the path prescribes a moment.
    #[must_use]
    pub fn has_moment(&self) -> bool {
        self.moment.is_some()
    }

    /// Step index of corner `i`: $i\,n_s$ with $n_s$ the sub-steps between corners.
    #[must_use]
    pub fn corner_step(&self, i: usize) -> usize {
        i * self.steps
    }

    /// Every step of the path, $1 + (n_c - 1)\,n_s$ of them: the first corner, then between
    /// corners $i$ and $i+1$ the values $v_i + (j/n_s)(v_{i+1} - v_i)$, $j = 1\dots n_s$
    /// (the last one set to $v_{i+1}$ exactly, so corners are hit without rounding).
    #[must_use]
    pub fn points(&self) -> Vec<PathPoint> {
        let nc = self.tangential.len();
        let mut out = Vec::with_capacity(1 + (nc - 1) * self.steps);
        let at =
            |i: usize| (self.tangential[i], self.normal[i], self.moment.as_ref().map(|m| m[i]));
        let (t0, p0, m0) = at(0);
        out.push(PathPoint { tangential: t0, normal: p0, moment: m0, corner: Some(0) });
        for i in 0..nc - 1 {
            let (ta, pa, ma) = at(i);
            let (tb, pb, mb) = at(i + 1);
            for j in 1..=self.steps {
                let point = if j == self.steps {
                    PathPoint { tangential: tb, normal: pb, moment: mb, corner: Some(i + 1) }
                } else {
                    let s = j as f64 / self.steps as f64;
                    let lerp = |a: f64, b: f64| a + s * (b - a);
                    PathPoint {
                        tangential: lerp(ta, tb),
                        normal: lerp(pa, pb),
                        moment: ma.zip(mb).map(|(a, b)| lerp(a, b)),
                        corner: None,
                    }
                };
                out.push(point);
            }
        }
        out
    }
}

/// A closed cycle of a solved path: from a turning point of the prescribed loads back to the
/// same loads (tangential value, normal load and moment) through at least one turning point
/// between.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HistoryLoop {
    /// Step where the loop starts (a turning point).
    pub first_step: usize,
    /// Step where it closes (the turning point two later).
    pub last_step: usize,
    /// Energy dissipated over the loop, $D_\text{last} - D_\text{first}$ (J): the energy per
    /// cycle.
    pub energy: f64,
    /// Work of the tangential loads over the loop, $\oint \mathbf T\cdot d\boldsymbol\delta +
    /// M\,d\omega$ (J, trapezoidal rule, the same rule as the dissipation; it equals
    /// `energy` plus the change of the stored elastic energy, zero when the state closes).
    pub work: f64,
    /// Range of the tangential force along the path direction over the loop (N).
    pub force_range: f64,
    /// Range of the rigid shift along the path direction over the loop (m).
    pub shift_range: f64,
    /// Shift at the end minus the shift at the start, along the path direction (m): zero for
    /// a closed loop in force and shift; non-zero under force control means the contact
    /// ratchets.
    pub shift_drift: f64,
}

/// The closed loops of a solved path (see [`HistoryLoop`]), in order and not overlapping.
///
/// Turning points are the steps where one of the prescribed values (the tangential value
/// [`HistoryStep::target`]: the force under [`PathControl::Force`], the shift under
/// [`PathControl::Shift`]; the prescribed moment; the normal load) changes the sign of its
/// increment (changes within $10^{-9}$ of their largest magnitude count as none), and the
/// last step. From a turning point $r_j$, the loop closes at the first
/// turning point $r_m$, $m \ge j + 2$, where the three values agree with those at $r_j$ (to
/// $10^{-9}$ of their largest magnitude along the path); the search then continues from
/// $r_m$, or from $r_{j+1}$ when no such point exists.
#[must_use]
pub fn find_loops(steps: &[HistoryStep]) -> Vec<HistoryLoop> {
    // The prescribed values: the solved resultants differ from them by the solver's
    // tolerance, which would make a hold look like a zig-zag.
    let values: [&dyn Fn(&HistoryStep) -> f64; 3] =
        [&|s| s.target, &|s| s.target_moment.unwrap_or(0.0), &|s| s.normal];
    let scales =
        values.map(|v| steps.iter().map(|s| v(s).abs()).fold(0.0, f64::max).max(f64::MIN_POSITIVE));
    let mut turn = vec![false; steps.len()];
    for (value, sc) in values.iter().zip(&scales) {
        let mut dir = 0.0f64;
        for i in 1..steps.len() {
            let d = value(&steps[i]) - value(&steps[i - 1]);
            // Changes within 1e-9 of the scale are a hold: the normal force of a step whose
            // pressure comes from a normal solve (coupled paths) varies by its tolerance.
            if d.abs() > 1e-9 * sc {
                if dir != 0.0 && d.signum() != dir {
                    turn[i - 1] = true;
                }
                dir = d.signum();
            }
        }
    }
    if let Some(last) = turn.last_mut() {
        *last = steps.len() > 1;
    }
    let turns: Vec<usize> = (0..steps.len()).filter(|&i| turn[i]).collect();
    let same = |a: &HistoryStep, b: &HistoryStep| {
        values.iter().zip(&scales).all(|(v, sc)| (v(a) - v(b)).abs() <= 1e-9 * sc)
    };
    let mut out = Vec::new();
    let mut j = 0;
    while j + 2 < turns.len() {
        let a = turns[j];
        let Some(m) = (j + 2..turns.len()).find(|&m| same(&steps[a], &steps[turns[m]])) else {
            j += 1;
            continue;
        };
        let b = turns[m];
        let range = |f: &dyn Fn(&HistoryStep) -> f64| {
            let (lo, hi) = steps[a..=b]
                .iter()
                .map(f)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| (l.min(v), h.max(v)));
            hi - lo
        };
        out.push(HistoryLoop {
            first_step: a,
            last_step: b,
            energy: steps[b].dissipated - steps[a].dissipated,
            work: steps[b].work - steps[a].work,
            force_range: range(&|s| s.tangential),
            shift_range: range(&|s| s.shift),
            shift_drift: steps[b].shift - steps[a].shift,
        });
        j = m;
    }
    out
}
