//! Load histories: a contact driven along a path of tangential loads (and normal loads, and
//! a twisting moment), each step solved from the previous step's traction, so that
//! unloading and reversal show the memory of Coulomb friction (fretting loops, locked-in
//! traction, energy dissipated where it is dissipated).
//!
//! # The incremental problem
//!
//! The state after step $n-1$ is the traction $\mathbf q^{n-1}_k$ of every cell, the
//! accumulated rigid shift $\boldsymbol\delta^{n-1}$ and rotation $\omega^{n-1}$. Step $n$
//! prescribes the loads $\mathbf T^n$ (and $M^n$) and the pressure $p^n_k$. Coulomb's law
//! is a law for the slip *increment*: with
//! $$\Delta\mathbf s_k = \Delta\mathbf w_k - \big(K(\mathbf q^n - \mathbf q^{n-1})\big)_k,
//!   \qquad \Delta\mathbf w_k = \Delta\boldsymbol\delta + \Delta\omega\,\hat z\times
//!   (\mathbf x_k - \mathbf c),$$
//! the increment of the relative tangential displacement of the two surfaces at cell $k$
//! (the sign convention of [`crate::fast`]: slip = rigid motion minus elastic displacement),
//! $$|\mathbf q^n_k| \le fp^n_k,\qquad \Delta\mathbf s_k = \lambda_k\mathbf q^n_k,\
//!   \lambda_k \ge 0,\qquad \lambda_k\,(fp^n_k - |\mathbf q^n_k|) = 0,\qquad
//!   h_xh_y\textstyle\sum_k\mathbf q^n_k = \mathbf T^n$$
//! (and the moment). This is the fast solver's problem ([`crate::FastProblem`]) with the
//! prescribed displacement $\mathbf u^0 = -K\mathbf q^{n-1}$
//! ([`crate::FastProblem::with_prescribed_displacement`]): its slip
//! $\mathbf w - K\mathbf q - \mathbf u^0$ is then exactly $\Delta\mathbf s$, its rigid motion
//! is the increment $(\Delta\boldsymbol\delta, \Delta\omega)$, and its load constraint is on
//! the total traction, as it must be. It is a backward-Euler (implicit) step of the rate
//! problem: the slip direction of the step is that of the traction at its end. Each step is
//! solved by [`crate::FastProblem::solve_from`] from the previous state, on one operator
//! planned for the whole path. The start of a step that continues in the direction of the
//! last one extrapolates the tractions along the last increment (cells whose extrapolated
//! traction reaches the disc start slipping); after a reversal every cell starts sticking;
//! if the iteration fails from one start the other is tried, then a cold start.
//!
//! **Cells entering and leaving contact.** The path runs on one lattice, the caller's grid,
//! which holds every cell that may touch during the path; the pressure of each step is given
//! per cell, zero where the surfaces are apart. A cell with $p^n_k = 0$ carries no traction
//! ($fp_k = 0$ forces $\mathbf q_k = 0$), whatever it carried before: a cell leaving contact
//! releases its traction within the step. A cell entering contact starts from zero traction
//! and sticks or slips from its position at the start of the step (its slip increment counts
//! the whole step, also the part before it touched: an error of the order of the step). A
//! cell whose capacity falls below its traction slips until its traction is on the smaller
//! disc.
//!
//! **Dissipation.** The energy dissipated in step $n$ is, per unit area of cell $k$,
//! $$\Delta D_k = \tfrac12\big(\mathbf q^{n-1}_k + \mathbf q^n_k\big)\cdot\Delta\mathbf s_k$$
//! (J/m², the midpoint rule in the traction), summed over the cells that are in contact at
//! the start or the end of the step (the others carry no traction at either end and
//! contribute nothing), and $D^n = h_xh_y\sum_k\sum_{m\le n}\Delta D_k$ in J. This rule
//! closes the discrete energy balance exactly: because $K$ is symmetric,
//! $$h_xh_y\sum_k\tfrac12(\mathbf q^{n-1}_k + \mathbf q^n_k)\cdot\Delta\mathbf s_k =
//!   \tfrac12(\mathbf T^{n-1} + \mathbf T^n)\cdot\Delta\boldsymbol\delta +
//!   \tfrac12(M^{n-1} + M^n)\,\Delta\omega - (U^n - U^{n-1}),\qquad
//!   U = \tfrac12 h_xh_y\,\mathbf q\cdot K\mathbf q,$$
//! so over a closed cycle the dissipated energy equals the area of the force–displacement
//! loop by the trapezoidal rule, which is second-order accurate in the step. At constant
//! pressure every $\Delta D_k \ge 0$ (a slipping cell is on its disc, $|\mathbf q^n_k| =
//! fp_k \ge |\mathbf q^{n-1}_k|$). When the pressure falls, a cell whose disc shrinks can
//! have a slightly negative midpoint value in one step (it is the rule's error, of the order
//! of the step). The backward-Euler value $\mathbf q^n\cdot\Delta\mathbf s$ would be
//! non-negative always but first-order, and would not close the balance.
//!
//! **Slip range.** The accumulated slip $\mathbf s_k = \sum\Delta\mathbf s_k$ of a cell
//! (counted while the cell is in contact at the end of a step) traces a curve; its *slip
//! range* is the largest distance between two of its points (the fretting engineer's
//! peak-to-peak slip, twice the slip amplitude). It is tracked without storing the curve:
//! the extent of $\mathbf s_k$ along eight directions $\theta + j\pi/8$ ($\theta$ the path
//! direction), whose largest is exact for a slip along one of them (any uniaxial path) and
//! within $\cos(\pi/16) = 0.981$ of the true range otherwise.
//!
//! **Gross slip.** Under force control a load at the friction capacity $f\sum_k p_kh_xh_y$
//! is solved as sliding (every cell at its capacity along the force; the shift is the least
//! one at which it slides, the fast solver's onset) and a load beyond it has no equilibrium:
//! [`HistoryProblem::run`] refuses such a corner before solving ([`crate::Error::PathCorner`]).
//! Under shift control ([`PathControl::Shift`]) the force is found for the prescribed shift
//! increment (a bracketed secant search on the force, each trial a warm fast solve); a shift
//! beyond the onset of sliding is solved as sliding at the capacity.
//!
//! **Dissimilar bodies** (Dundurs' $\beta \ne 0$). A pressure then moves the two surfaces
//! tangentially by different amounts ($K^{tn}p$) and a traction moves them normally
//! ($K^{nt}\mathbf q$; `stickslip_lattice::CrossOperator`). The slip increment of a step
//! counts the change of the whole relative tangential displacement,
//! $$\Delta\mathbf s_k = \Delta\mathbf w_k - \big(K(\mathbf q^n - \mathbf q^{n-1})\big)_k -
//!   \big(K^{tn}(p^n - p^{n-1})\big)_k,$$
//! so the prescribed displacement becomes
//! $\mathbf u^0 = K^{tn}p^n - (K\mathbf q^{n-1} + K^{tn}p^{n-1})$: the previous step's total
//! displacement, its coupling part included, and this step's pressure's share
//! ([`LoadHistory::trial`]). The pressure of a step depends on its traction through the gap
//! $g^0 + K^{nt}\mathbf q^n$, so [`HistoryProblem::run_coupled`] alternates, as
//! the single-state coupled solve of `stickslip-normal` does (Panagiotopoulos 1975): a normal
//! solve with the gap corrected by the traction of the last pass (the first pass: the last
//! step's traction), then the tangential step with that pressure, warm from the last pass,
//! until the traction of a pass differs from the one that made its pressure by at most the
//! tolerance ([`PathCoupling::with_tolerance`]). Each step records its passes and that
//! residual ([`HistoryStep::coupling_passes`]). A prescribed pressure ([`PathCoupling::one_way`])
//! takes one pass, and so does $\beta = 0$, which is then exactly the uncoupled step.
//! With coupling, `work` $=$ `elastic_energy` $+$ `dissipated` no longer holds step by step
//! (the pressure works on the tangential displacement and the traction on the normal one);
//! over a closed cycle at constant normal load the state returns and the loop area is still
//! the energy dissipated.
//!
//! Units: consistent units (SI in practice): forces in N, lengths in m, tractions in Pa,
//! energies in J and energies per area in J/m².
//!
//! Sources: Mindlin & Deresiewicz (1953), *J. Appl. Mech.* 20 (loops and the oblique
//! loading of §7.6 of Johnson, *Contact Mechanics*, 1985) for the tests; the fast solver's
//! sources ([`crate::fast`]); FORMULAS.md E (Mindlin, Mindlin–Deresiewicz). Derivation and
//! verification: `docs/load-histories.md`.

mod coupled;
mod path;
mod problem;
mod solves;
mod stepper;

pub use coupled::{PathCoupling, COUPLING_NAME, DEFAULT_COUPLING_PASSES};
pub use path::{find_loops, HistoryLoop, LoadPath, PathControl, PathPoint};
pub use problem::{
    HistoryDirections, HistoryOutcome, HistoryProblem, HistoryStep, StepTarget,
    SLIP_RANGE_DIRECTIONS,
};
pub use stepper::{LoadHistory, StepTrial};
