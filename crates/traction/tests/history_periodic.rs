//! Load paths on a periodic surface (`HistoryProblem::with_periodic`): a sphere's fretting
//! loop in a growing period against the isolated contact's and against
//! Mindlin–Deresiewicz, and Masing's rule, an identity of the scalar problem, on the
//! periodic operator.

mod fast_common;
use fast_common::steel;
use stickslip_lattice::{ContactGrid, PeriodicLattice};
use stickslip_traction::closed::Deresiewicz;
use stickslip_traction::history::{
    HistoryDirections, HistoryOutcome, HistoryProblem, LoadPath, PathControl,
};

/// Tolerances, each with its reason.
mod tol {
    /// Energy per cycle against Mindlin–Deresiewicz on 48 cells across with 10 steps per
    /// half cycle, in a period of 8 diameters: the isolated contact on this lattice is
    /// measured at -1.16 % (the lattice's compliance and the trapezoidal rule in the step;
    /// the history tests measure -0.56 % at 128 cells and 20 steps), and the images of the
    /// period add -0.40 % (-1.12 % at 4 diameters, -7.3 % at 2).
    pub const MD_ENERGY: f64 = 0.02;
    /// Masing's identity under the one-direction assumption: exact for the discrete scalar
    /// problem, up to the solver's residual (1e-10 of |q|, the worst cell up to sqrt(N) of
    /// it), as on an isolated contact.
    pub const MASING_LINE: f64 = 1e-7;
}

/// Seed 002 Example 1 proportions: P = 2160 lbf (in N: any unit serves), f = 0.1, R = 1.
const P: f64 = 2160.0;
const F: f64 = 0.1;
const ACROSS: usize = 48;
const PER: usize = 10;

fn hertz_radius() -> f64 {
    (3.0 * P * 2.0 * steel().normal_compliance() / 4.0).cbrt()
}

/// The cycle 0 -> T* -> -T* -> T* (T* = fP/2) on the Hertz circle of 48 cells across, in a
/// period of `periods` contact diameters (`None`: the isolated contact).
fn cycle(periods: Option<usize>, directions: HistoryDirections) -> HistoryOutcome {
    let grid = ContactGrid::hertz_circle(hertz_radius(), P, ACROSS).unwrap();
    let ts = 0.5 * F * P;
    let path = LoadPath::new(PathControl::Force, vec![0.0, ts, -ts, ts], vec![P], PER).unwrap();
    let s = steel();
    let mut problem = HistoryProblem::new(&grid, [s, s], F)
        .unwrap()
        .with_angle(0.0)
        .unwrap()
        .with_directions(directions);
    if let Some(k) = periods {
        let cells = k * ACROSS;
        problem = problem.with_periodic(PeriodicLattice {
            cells: (cells, cells),
            origin: (grid.x[0], grid.y[0]),
        });
    }
    let pressure = grid.pressure.clone();
    problem
        .run::<stickslip_traction::Error, _>(&path, |_| Ok(pressure.clone()))
        .unwrap_or_else(|e| panic!("period {periods:?}: {e}"))
}

#[test]
fn a_fretting_loop_in_a_growing_period_approaches_the_isolated_one() {
    let s = steel();
    let a = hertz_radius();
    let ts = 0.5 * F * P;
    let md = Deresiewicz::new(a, P, F, ts).unwrap();
    let w = 2.0 * md.energy_per_cycle(&s);
    let free = cycle(None, HistoryDirections::Free);
    let e_free = free.loops[0].energy;
    println!(
        "isolated: energy per cycle {e_free:.6e} against M-D {w:.6e} ({:+.3} %)",
        100.0 * (e_free / w - 1.0)
    );
    let mut last = f64::INFINITY;
    for k in [2usize, 4, 8] {
        let out = cycle(Some(k), HistoryDirections::Free);
        assert_eq!(out.loops.len(), 1, "{:?}", out.loops);
        let l = out.loops[0];
        let off = (l.energy / e_free - 1.0).abs();
        // The stick fraction of each step against the isolated contact's.
        let stick = out
            .steps
            .iter()
            .zip(&free.steps)
            .map(|(p, f)| (p.stick_fraction - f.stick_fraction).abs())
            .fold(0.0, f64::max);
        println!(
            "period {k} diameters: energy per cycle {:.6e} ({:+.4} % from the isolated, {:+.3} % from M-D), \
             stick fraction within {stick:.4}, loop drift {:.2e} m",
            l.energy,
            100.0 * (l.energy / e_free - 1.0),
            100.0 * (l.energy / w - 1.0),
            l.shift_drift
        );
        // The images' effect falls as the period grows, at least as 1/L (measured about
        // 1/L^1.5 from 4 to 8 diameters).
        assert!(off < 0.5 * last, "period {k}: {off:.3e} after {last:.3e}");
        last = off;
        if k == 8 {
            assert!(
                (l.energy / w - 1.0).abs() <= tol::MD_ENERGY,
                "period {k}: {} against {w}",
                l.energy
            );
        }
        // Every step balances its load and keeps Coulomb's law (the run audits each step's
        // residual; the force is the step's resultant).
        for st in &out.steps {
            assert!((st.tangential - st.target).abs() <= 1e-8 * F * P, "{st:?}");
        }
    }
}

/// Masing: after loading to T*, the unloading branch at T is delta* - 2 delta_L((T* - T)/2)
/// with delta_L the first (virgin) branch; with as many equal steps from 0 to T* as from T*
/// to -T* (twice as long), unloading step k meets first-branch step k.
#[test]
fn masing_holds_on_a_periodic_surface() {
    let out = cycle(Some(2), HistoryDirections::Line);
    let sh: Vec<f64> = out.steps.iter().map(|s| s.shift).collect();
    let dstar = sh[PER] - sh[0];
    let mut worst = 0.0f64;
    for k in 0..=PER {
        let want = sh[PER] - 2.0 * (sh[k] - sh[0]);
        let got = sh[PER + k];
        worst = worst.max((got - want).abs() / dstar.abs());
    }
    println!("Masing on the period of 2 diameters: worst {worst:.2e} of delta*");
    assert!(worst <= tol::MASING_LINE, "{worst:e}");
}
