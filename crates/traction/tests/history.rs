//! Load histories (issue 31) against independent references: Mindlin–Deresiewicz loops and
//! energy per cycle (FORMULAS.md E), the monotonic fast solve, Masing's rule, the locked-in
//! traction of M–D, Mindlin & Deresiewicz's oblique loading (Johnson §7.6), gross slip.

mod fast_common;
use fast_common::{centred_lattice, hertz_on_lattice, hertz_radius, steel};
use std::f64::consts::PI;
use std::sync::OnceLock;
use stickslip_lattice::ContactGrid;
use stickslip_traction::closed::{Deresiewicz, Mindlin};
use stickslip_traction::history::{
    HistoryDirections, HistoryProblem, HistoryStep, LoadPath, PathControl, StepTarget,
};
use stickslip_traction::{Error, FastProblem, Load, Regime, TractionDirections};

/// Tolerances, each with its reason.
mod tol {
    /// Issue 31: energy per cycle within 1 % of Mindlin–Deresiewicz at 128 cells across.
    /// Measured -0.56 % with 20 steps per half cycle: about -0.31 % is the lattice (the
    /// 128-cell grid's compliance) and -0.25 % the trapezoidal rule in the step (it falls
    /// like the square of the step: -1.32 % at 10 steps, -0.37 % at 40).
    pub const MD_ENERGY: f64 = 0.01;
    /// Loop branches against M–D's δ(T), relative to the loop's half range δ*: the
    /// grid's own compliance error at 128 cells across (the monotonic solve is 5.5e-4 below
    /// Mindlin at T* = fP/2) with a factor 2 of room.
    pub const MD_BRANCH: f64 = 1e-3;
    /// The energy balance work = U + D is an identity of the midpoint rule (module docs):
    /// rounding of sums over 13k cells and 60 steps.
    pub const BALANCE: f64 = 1e-12;
    /// First branch (free directions) versus monotonic solves: x traction relative to
    /// f p0, measured 8.2e-4 (the path effect on the transverse traction feeds back
    /// weakly); bound 2e-3.
    pub const FIRST_BRANCH_X: f64 = 2e-3;
    /// The transverse traction's path effect, measured 6.4e-3 of f p0: bounded by a third
    /// of the transverse traction itself (3.1e-2 of f p0 at fP/2), which Mindlin neglects.
    pub const FIRST_BRANCH_Y: f64 = 1e-2;
    /// Shift, measured 2.6e-5 relative: a twentieth of the grid's own compliance error
    /// (5.5e-4 at 128 across) is allowed.
    pub const FIRST_BRANCH_SHIFT: f64 = 1e-4;
    /// Masing's identity under the one-direction assumption (exact for the discrete scalar
    /// problem): solver residual 1e-10 of |q| (the worst cell up to sqrt(N) of it).
    pub const MASING_LINE: f64 = 1e-7;
    /// Masing with free directions on the rough patch (load at 0.3 rad): not an identity
    /// there, the transverse traction's path effect (as in the first branch) breaks it;
    /// measured 3.9e-5 of delta* in the shift, bound 2e-4.
    pub const MASING_FREE_SHIFT: f64 = 2e-4;
    /// As above, traction relative to f p_max: measured 1.7e-2, bound 3e-2.
    pub const MASING_FREE_TRACTION: f64 = 3e-2;
    /// Oblique loading: traction against kappa p, RMS over the contact relative to f p0;
    /// measured 1.24 % at half a cell of growth per step (first order in the step).
    pub const OBLIQUE_RMS: f64 = 0.02;
    /// Oblique loading: shift against Johnson's, measured -0.40 %.
    pub const OBLIQUE_SHIFT: f64 = 0.01;
    /// Oblique loading: energy dissipated relative to the work (zero in the continuum;
    /// the cells entering contact slip a little within their step, measured 1.0e-5; Mindlin
    /// loading to the same T/fP at constant P dissipates 7 % of its work).
    pub const OBLIQUE_DISSIPATED: f64 = 1e-4;
    /// Locked-in traction after gross slip on 48 cells across (RMS relative to f p0; the
    /// profile's kinks at 24 cells in radius).
    pub const LOCKED_RMS_COARSE: f64 = 0.02;
    /// Shift control: the force at the turning points against the force-controlled T*.
    /// The search stops at 1e-9 of the shift range, but the two runs step through
    /// different loads (equal steps in T or in delta), and with free directions the
    /// transverse traction's path effect moves the turning force: measured 4.9e-7 and
    /// 1.2e-6.
    pub const SHIFT_CONTROL: f64 = 1e-5;
    /// Torsion: first branch and Masing's rule for the rotation, relative to omega*: on
    /// the circle the traction is nearly circumferential and the problem nearly scalar;
    /// the lattice has the square's symmetry, not the axial one (measured 4.9e-7).
    pub const TORSION: f64 = 1e-5;
    /// Locked-in traction against M–D's closed form, RMS over the contact relative to
    /// f p0: cell averages against point values of a profile with square-root kinks at
    /// three radii, 64 cells in radius; measured 0.4 %.
    pub const LOCKED_RMS: f64 = 0.01;
}

/// Seed 002 Example 1 proportions: P = 2160 lbf, f = 0.1, R = 1 in, steel on steel.
const P: f64 = 2160.0;
const F: f64 = 0.1;

/// Hertz's p0 = 3P/(2 pi a^2).
fn p0(p: f64, a: f64) -> f64 {
    3.0 * p / (2.0 * PI * a * a)
}

/// Component of a traction along x.
fn rms_and_max(v: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut s, mut m, mut n) = (0.0, 0.0f64, 0usize);
    for x in v {
        s += x * x;
        m = m.max(x.abs());
        n += 1;
    }
    ((s / n.max(1) as f64).sqrt(), m)
}

/// The cycle 0 -> T* -> -T* -> T* (T* = fP/2, 20 steps between corners) on the Hertz
/// circle of 128 cells across, with the tractions of the first branch and of the zero
/// crossing on the way down kept.
struct Cycle {
    grid: ContactGrid,
    a: f64,
    ts: f64,
    steps: Vec<HistoryStep>,
    first_branch: Vec<Vec<(f64, f64)>>,
    locked: Vec<(f64, f64)>,
    loops: Vec<stickslip_traction::history::HistoryLoop>,
}

const PER: usize = 20;

fn cycle() -> &'static Cycle {
    static C: OnceLock<Cycle> = OnceLock::new();
    C.get_or_init(|| {
        let a = hertz_radius(P, 1.0);
        let grid = ContactGrid::hertz_circle(a, P, 128).unwrap();
        let s = steel();
        let ts = 0.5 * F * P;
        let path = LoadPath::new(PathControl::Force, vec![0.0, ts, -ts, ts], vec![P], PER).unwrap();
        let mut h = HistoryProblem::new(&grid, [s, s], F).unwrap().start().unwrap();
        let (mut first_branch, mut locked) = (Vec::new(), Vec::new());
        for (i, pt) in path.points().iter().enumerate() {
            let target =
                StepTarget { control: PathControl::Force, tangential: pt.tangential, moment: None };
            h.step(None, target).unwrap();
            if i <= PER {
                first_branch.push(h.traction().to_vec());
            }
            if i == PER + PER / 2 {
                locked = h.traction().to_vec();
            }
        }
        let loops = h.loops();
        let steps = h.steps().to_vec();
        Cycle { grid: grid.clone(), a, ts, steps, first_branch, locked, loops }
    })
}

/// Issue 31, item 3: on the Hertz sphere at constant normal load the loop and the energy per
/// cycle match Mindlin–Deresiewicz within 1 % at 128 cells across.
#[test]
fn sphere_loop_matches_mindlin_deresiewicz() {
    let c = cycle();
    let s = steel();
    let md = Deresiewicz::new(c.a, P, F, c.ts).unwrap();
    let dstar = 2.0 * md.delta_unloading(c.ts, &s).unwrap();
    let mut worst = (0.0f64, 0usize);
    for (i, st) in c.steps.iter().enumerate().skip(PER) {
        let t = st.target;
        // Relative displacement of two identical bodies: twice the per-body branch.
        let want = if i <= 2 * PER {
            2.0 * md.delta_unloading(t, &s).unwrap()
        } else {
            2.0 * md.delta_reloading(t, &s).unwrap()
        };
        let e = (st.shift - want).abs() / dstar;
        if e > worst.0 {
            worst = (e, i);
        }
    }
    assert_eq!(c.loops.len(), 1, "{:?}", c.loops);
    let l = c.loops[0];
    assert_eq!((l.first_step, l.last_step), (PER, 3 * PER));
    let w = 2.0 * md.energy_per_cycle(&s);
    let rel = l.energy / w - 1.0;
    println!(
        "M-D loop, 128 across, {PER} steps per half cycle: branch error max {:.2e} of delta* \
         (step {}); energy per cycle {:.6e} vs M-D {:.6e} ({:+.3} %); loop work {:.6e}; \
         shift drift over the loop {:.2e} of delta*",
        worst.0,
        worst.1,
        l.energy,
        w,
        100.0 * rel,
        l.work,
        l.shift_drift / dstar
    );
    assert!(worst.0 <= tol::MD_BRANCH, "{worst:?}");
    assert!(rel.abs() <= tol::MD_ENERGY, "{rel}");
    // The loop closes: the reloading branch ends where the first unloading began.
    assert!(l.shift_drift.abs() <= tol::MD_BRANCH * dstar, "{}", l.shift_drift);
}

/// The discrete energy balance of the midpoint rule, work = U + D at every step (an
/// identity given a symmetric influence operator, module docs), and D never decreasing at
/// constant pressure.
#[test]
fn energy_balance_closes() {
    let c = cycle();
    let mut worst = 0.0f64;
    for w in c.steps.windows(2) {
        assert!(w[1].dissipated >= w[0].dissipated, "{} < {}", w[1].dissipated, w[0].dissipated);
    }
    let scale = c.steps.iter().map(|s| s.work.abs()).fold(0.0, f64::max);
    for st in &c.steps {
        worst = worst.max((st.work - st.elastic_energy - st.dissipated).abs() / scale);
    }
    println!("energy balance: worst |W - U - D| / max W = {worst:.2e}");
    assert!(worst <= tol::BALANCE, "{worst}");
}

/// Issue 31, item 3: the first loading branch against today's monotonic solve at every
/// step, with free traction directions. The x traction and the shift agree closely; the
/// small transverse traction (Mindlin's approximation sets it to zero) does not: the
/// incremental path slips along each step's traction where the monotonic solve slips along
/// the final one, and with steps refined the difference converges to a path effect, not to
/// zero (64 across, 0 to fP/2: 4.0e-3, 6.4e-3 and 7.1e-3 of f p0 in q_y at 5, 20 and 80
/// steps; shift -1.1e-5, -2.6e-5, -3.1e-5). Under the one-direction assumption the two are
/// equal to the solver's tolerance (`masing_rule_on_a_rough_patch`).
#[test]
fn first_branch_against_monotonic_solve() {
    let c = cycle();
    let s = steel();
    let scale = F * p0(P, c.a);
    let (mut wx, mut wy, mut ws, mut qy_mono) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for (i, q) in c.first_branch.iter().enumerate().skip(1) {
        let t = c.steps[i].target;
        let m = FastProblem::new(&c.grid, [s, s], F, Load::polar(t, 0.0).unwrap())
            .unwrap()
            .solve()
            .unwrap();
        for (a, b) in q.iter().zip(&m.traction) {
            wx = wx.max((a.0 - b.0).abs() / scale);
            wy = wy.max((a.1 - b.1).abs() / scale);
            qy_mono = qy_mono.max(b.1.abs() / scale);
        }
        ws = ws.max((c.steps[i].shift - m.shift.0).abs() / m.shift.0);
    }
    println!(
        "first branch vs monotonic solves (128 across, {PER} steps to fP/2): q_x {wx:.2e}, \
         q_y {wy:.2e} of f p0 (the monotonic transverse traction reaches {qy_mono:.2e}), \
         shift {ws:.2e} relative"
    );
    assert!(wx <= tol::FIRST_BRANCH_X, "{wx}");
    assert!(wy <= tol::FIRST_BRANCH_Y, "{wy}");
    assert!(ws <= tol::FIRST_BRANCH_SHIFT, "{ws}");
}

/// Issue 31, item 3: a path returning to zero tangential load leaves a locked-in traction
/// that sums to zero, and it is M–D's: q = q*(rho) - 2 q_M(rho; b) at T = 0.
#[test]
fn locked_in_traction_sums_to_zero_and_is_mindlin_deresiewicz() {
    let c = cycle();
    let md = Deresiewicz::new(c.a, P, F, c.ts).unwrap();
    let area = c.grid.element_area();
    let (sx, sy) =
        c.locked.iter().fold((0.0, 0.0), |acc, q| (acc.0 + area * q.0, acc.1 + area * q.1));
    let scale = F * p0(P, c.a);
    let (rms, max) = rms_and_max(c.locked.iter().enumerate().map(|(k, q)| {
        let rho = c.grid.x[k].hypot(c.grid.y[k]);
        (q.0 - md.unloading_traction(rho, 0.0).unwrap()) / scale
    }));
    let peak = c.locked.iter().map(|q| q.0.abs()).fold(0.0, f64::max) / scale;
    println!(
        "locked-in traction at T = 0: resultant ({sx:.2e}, {sy:.2e}) for T* = {:.1}; peak {peak:.3} f p0; \
         vs M-D: RMS {rms:.2e}, max {max:.2e} of f p0",
        c.ts
    );
    // The resultant: the solver's load residual (1e-10 relative to the traction's own
    // contributions, a zero load having no scale of its own).
    assert!(sx.abs() <= 1e-8 * c.ts && sy.abs() <= 1e-8 * c.ts, "{sx} {sy}");
    assert!(peak > 0.1, "no locked-in traction: {peak}");
    assert!(rms <= tol::LOCKED_RMS, "{rms}");
}

/// A patch that is no Hertz contact: an ellipse (semi-axes 1 and 0.7) on a 48 x 48 lattice
/// with the pressure p = (1 - x^2 - y^2/0.49)^0.3 (1 + 0.3 sin 7x cos 5y) (Pa, f = 0.3),
/// every lattice cell an element (zero pressure outside), steel on steel.
fn rough_patch() -> ContactGrid {
    let n = 48;
    let h = 2.0 / n as f64;
    let mut pr = vec![0.0; n * n];
    for j in 0..n {
        for i in 0..n {
            let x = -1.0 + (i as f64 + 0.5) * h;
            let y = -1.0 + (j as f64 + 0.5) * h;
            let r = 1.0 - x * x - y * y / 0.49;
            if r > 0.0 {
                pr[j * n + i] = 1e6 * r.powf(0.3) * (1.0 + 0.3 * (7.0 * x).sin() * (5.0 * y).cos());
            }
        }
    }
    ContactGrid::from_mask(h, h, (-1.0, -1.0), n, n, &vec![true; n * n], &pr).unwrap()
}

/// Masing's rule on the rough patch: after loading to T*, the unloading branch at T is
/// q*(x) - 2 q_L(x; (T* - T)/2) and delta* - 2 delta_L((T* - T)/2), with q_L and delta_L the
/// monotonic (virgin) solution, here solved independently from zero at each load. Under the
/// one-direction assumption (`HistoryDirections::Line`, the load along y to exercise a zero
/// force at an angle) the discrete problem is scalar and the rule holds to the solver's
/// tolerance, and so does the first branch against the monotonic solves. With free
/// directions it holds up to the transverse traction's path effect (printed, bounded).
#[test]
fn masing_rule_on_a_rough_patch() {
    let grid = rough_patch();
    let s = steel();
    let f = 0.3;
    let cap = f * grid.total_normal_force();
    let ts = 0.6 * cap;
    let n = 10;
    let pmax = grid.pressure.iter().fold(0.0f64, |m, p| m.max(*p));
    let path = LoadPath::new(PathControl::Force, vec![0.0, ts, -ts], vec![1.0], n).unwrap();
    for (dirs, angle) in [(HistoryDirections::Line, PI / 2.0), (HistoryDirections::Free, 0.3)] {
        let e = (angle.cos(), angle.sin());
        let prob = HistoryProblem::new(&grid, [s, s], f)
            .unwrap()
            .with_angle(angle)
            .unwrap()
            .with_directions(dirs);
        let mut h = prob.start().unwrap();
        let mut hist = Vec::new();
        for pt in path.points() {
            let target =
                StepTarget { control: PathControl::Force, tangential: pt.tangential, moment: None };
            let st = *h.step(None, target).unwrap();
            hist.push((st, h.traction().to_vec()));
        }
        // Monotonic solves at tau_j = j T*/n from zero.
        let mono: Vec<_> = (0..=n)
            .map(|j| {
                let tau = ts * j as f64 / n as f64;
                let mut fp =
                    FastProblem::new(&grid, [s, s], f, Load::polar(tau, angle).unwrap()).unwrap();
                if dirs == HistoryDirections::Line {
                    fp =
                        fp.with_directions(TractionDirections::Fixed(vec![e; grid.len()])).unwrap();
                }
                let m = fp.solve().unwrap();
                (m.shift.0 * e.0 + m.shift.1 * e.1, m.traction)
            })
            .collect();
        let dstar = mono[n].0;
        let (mut load_q, mut load_d, mut mas_q, mut mas_d) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        for j in 1..=n {
            let (st, q) = &hist[j];
            load_d = load_d.max((st.shift - mono[j].0).abs() / dstar);
            for (a, b) in q.iter().zip(&mono[j].1) {
                load_q = load_q.max((a.0 - b.0).hypot(a.1 - b.1) / (f * pmax));
            }
            let (st, q) = &hist[n + j];
            mas_d = mas_d.max((st.shift - (dstar - 2.0 * mono[j].0)).abs() / dstar);
            for ((a, qs), ql) in q.iter().zip(&mono[n].1).zip(&mono[j].1) {
                let want = (qs.0 - 2.0 * ql.0, qs.1 - 2.0 * ql.1);
                mas_q = mas_q.max((a.0 - want.0).hypot(a.1 - want.1) / (f * pmax));
            }
        }
        println!(
            "rough patch, {dirs:?}: first branch vs monotonic: traction {load_q:.2e} of f p_max, \
             shift {load_d:.2e} of delta*; Masing: traction {mas_q:.2e} of f p_max, shift {mas_d:.2e} of delta*"
        );
        match dirs {
            HistoryDirections::Line => {
                for v in [load_q, load_d, mas_q, mas_d] {
                    assert!(v <= tol::MASING_LINE, "{v}");
                }
            }
            HistoryDirections::Free => {
                assert!(mas_d <= tol::MASING_FREE_SHIFT, "{mas_d}");
                assert!(mas_q <= tol::MASING_FREE_TRACTION, "{mas_q}");
            }
        }
    }
}

/// Issue 31, item 3 (Mindlin & Deresiewicz's oblique loading, Johnson §7.6): when T and P
/// grow together from zero with T/P = kappa < f, nothing slips, the traction is
/// q = kappa p everywhere and the shift is delta = 3 kappa P (2 - nu)/(8 G a) for two
/// identical bodies (the full-stick compliance (2 - nu)/(8 G a) per body integrated over the
/// growing contact). The contact grows from 1 to 48 cells in radius on a 96 x 96 lattice,
/// half a cell per step (corners P_i = P (i/48)^3, two steps between corners). The discrete
/// path converges to this at first order in the growth per step (traction RMS 2.05 %,
/// 1.24 %, 0.70 % of f p0 and shift -1.22 %, -0.40 %, -0.03 % at 1, 1/2 and 1/4 cell per
/// step): a cell entering contact starts the step at zero traction.
#[test]
fn oblique_proportional_loading_matches_johnson() {
    let s = steel();
    let n = 96;
    let a = hertz_radius(P, 1.0);
    let h = 2.0 * a / n as f64;
    let kappa = 0.5 * F;
    let corners = 48;
    let normal: Vec<f64> = (1..=corners).map(|i| P * (i as f64 / corners as f64).powi(3)).collect();
    let tangential: Vec<f64> = normal.iter().map(|p| kappa * p).collect();
    let path = LoadPath::new(PathControl::Force, tangential, normal, 2).unwrap();
    let grid = centred_lattice(n, h, &hertz_on_lattice(P, n, h));
    let out = HistoryProblem::new(&grid, [s, s], F)
        .unwrap()
        .run(&path, |p| Ok::<_, Error>(hertz_on_lattice(p, n, h)))
        .unwrap();
    let scale = F * p0(P, a);
    let (rms, max) = rms_and_max(
        out.traction
            .iter()
            .zip(&out.pressure)
            .filter(|(_, p)| **p > 0.0)
            .map(|(q, p)| (q.0 - kappa * p) / scale),
    );
    let qy = out.traction.iter().map(|q| q.1.abs()).fold(0.0, f64::max) / scale;
    // Slipping cells of the last step: how far inside the edge the deepest one lies.
    let deepest = (0..grid.len())
        .filter(|&k| {
            out.pressure[k] > 0.0 && out.state[k] == stickslip_traction::ElementState::Slip
        })
        .map(|k| (a - grid.x[k].hypot(grid.y[k])) / h)
        .fold(0.0f64, f64::max);
    let (rms_in, _) = rms_and_max(
        (0..grid.len())
            .filter(|&k| grid.x[k].hypot(grid.y[k]) < a - 2.0 * h)
            .map(|k| (out.traction[k].0 - kappa * out.pressure[k]) / scale),
    );
    let last_stick = out.steps.last().unwrap().stick_fraction;
    let last = out.steps.last().unwrap();
    let g = s.shear_modulus();
    let want = 3.0 * kappa * P * (2.0 - s.poisson_ratio()) / (8.0 * g * a);
    let shift_rel = last.shift / want - 1.0;
    let mono = Mindlin::new(a, P, F, kappa * P).unwrap().compliance_relative(&s, &s);
    println!(
        "oblique loading T = {kappa} P: traction - kappa p: RMS {rms:.2e}, max {max:.2e} of f p0; \
         (RMS {rms_in:.2e} more than 2 cells inside the edge); |q_y| <= {qy:.2e}; \
         stick fraction at the end {last_stick:.4}, the deepest slipping cell {deepest:.2} cells \
         inside the edge; shift {:.6e} vs Johnson {want:.6e} \
         ({:+.2} %), Mindlin at constant P would give {mono:.6e}; dissipated {:.2e} of the work",
        last.shift,
        100.0 * shift_rel,
        last.dissipated / last.work
    );
    assert!(rms <= tol::OBLIQUE_RMS, "{rms}");
    assert!(shift_rel.abs() <= tol::OBLIQUE_SHIFT, "{shift_rel}");
    assert!(deepest <= 2.0, "{deepest}");
    assert!(last.dissipated <= tol::OBLIQUE_DISSIPATED * last.work, "{}", last.dissipated);
}

/// A Hertz circle of `across` cells across under P (steel, f = 0.1).
fn small_sphere(across: usize) -> (ContactGrid, f64) {
    let a = hertz_radius(P, 1.0);
    (ContactGrid::hertz_circle(a, P, across).unwrap(), a)
}

/// Issue 31, item 6: a force-controlled corner beyond the friction capacity is refused
/// before anything is solved, naming the corner; a normal load that reaches zero is
/// refused at its corner; mismatched lengths name the key.
#[test]
fn bad_paths_are_refused_before_solving() {
    let (grid, _) = small_sphere(16);
    let s = steel();
    let prob = HistoryProblem::new(&grid, [s, s], F).unwrap();
    let cap = prob.capacity(&grid.pressure);
    let path = LoadPath::new(PathControl::Force, vec![0.0, 0.5 * cap, -1.2 * cap, 0.0], vec![P], 4)
        .unwrap();
    let mut calls = 0;
    let pr = grid.pressure.clone();
    let err = prob
        .run(&path, |_| {
            calls += 1;
            Ok::<_, Error>(pr.clone())
        })
        .unwrap_err();
    println!("{err}");
    match err {
        Error::PathCorner { corner, value, .. } => {
            assert_eq!(corner, 2);
            assert!((value - 1.2).abs() < 1e-9, "{value}");
        }
        e => panic!("{e:?}"),
    }
    // One pressure for the constant normal load, and no step solved.
    assert_eq!(calls, 1);
    let err =
        LoadPath::new(PathControl::Force, vec![0.0, 1.0, 2.0], vec![P, 0.0, P], 4).unwrap_err();
    println!("{err}");
    assert!(matches!(err, Error::PathCorner { corner: 1, .. }), "{err:?}");
    let err = LoadPath::new(PathControl::Force, vec![0.0, 1.0, 2.0], vec![P, P], 4).unwrap_err();
    println!("{err}");
    assert!(
        matches!(
            err,
            Error::LengthMismatch { name: "load path normal (corner values)", expected: 3, got: 2 }
        ),
        "{err:?}"
    );
    let path = LoadPath::new(PathControl::Shift, vec![0.0, 1e-6], vec![P], 2).unwrap();
    let err = path.clone().with_moment(vec![0.0]).unwrap_err();
    assert!(matches!(err, Error::LengthMismatch { name: "load path moment (corner values)", .. }));
    let err = prob
        .run(&path.with_moment(vec![0.0, 1.0]).unwrap(), |_| Ok::<_, Error>(pr.clone()))
        .unwrap_err();
    println!("{err}");
    assert!(matches!(err, Error::OutOfDomain { name: "moment on a shift-controlled path", .. }));
}

/// Issue 31, item 6: a corner exactly at the capacity is solved as sliding (every cell
/// slips at f p along the force) and said so in the step's regime; unloading from it, the
/// stick zone is M–D's disc of radius b = a (1 - (T* - T)/(2fP))^(1/3), and the locked-in
/// traction at T = 0 is M–D's at T* = fP.
#[test]
fn force_at_capacity_slides_and_unloads() {
    let (grid, a) = small_sphere(48);
    let s = steel();
    let prob = HistoryProblem::new(&grid, [s, s], F).unwrap();
    let cap = prob.capacity(&grid.pressure);
    let path = LoadPath::new(PathControl::Force, vec![0.0, cap, 0.0], vec![P], 4).unwrap();
    let pr = grid.pressure.clone();
    let out = prob.run(&path, |_| Ok::<_, Error>(pr.clone())).unwrap();
    let top = out.steps[4];
    assert_eq!(top.regime, Regime::GrossSlip);
    assert_eq!(top.stick_fraction, 0.0);
    let md = Deresiewicz::new(a, P, F, F * P).unwrap();
    // Stick area fraction (b/a)^2 on the way down, within a ring of one cell (2 h/a).
    let h = grid.hx;
    let mut worst = 0.0f64;
    for st in &out.steps[5..] {
        let b = md.reversal_radius(st.tangential.clamp(-cap, cap) * (F * P) / cap).unwrap();
        worst = worst.max((st.stick_fraction - (b / a).powi(2)).abs());
    }
    assert!(worst <= 2.0 * h / a, "{worst}");
    let scale = F * p0(P, a);
    let (rms, _) = rms_and_max(out.traction.iter().enumerate().map(|(k, q)| {
        (q.0 - md.unloading_traction(grid.x[k].hypot(grid.y[k]), 0.0).unwrap()) / scale
    }));
    println!(
        "after gross slip and back to zero (48 across): stick fraction vs (b/a)^2 within {worst:.3} \
         (one cell ring: {:.3}); locked-in traction vs M-D RMS {rms:.2e} of f p0",
        2.0 * h / a
    );
    assert!(rms <= tol::LOCKED_RMS_COARSE, "{rms}");
}

/// Issue 31, item 6 and the shift control: a shift-controlled cycle of amplitude twice the
/// onset of sliding. Its loop is M–D's loop at T* = fP with its curved branches pulled
/// apart by the sliding, so its energy is W_MD(fP) + 4 fP (delta_a - delta_s), delta_s the
/// shift at the onset of sliding (Mindlin at T = fP; FORMULAS.md E); the force is at the
/// capacity at both ends.
#[test]
fn shift_cycle_through_gross_slip() {
    let (grid, a) = small_sphere(64);
    let s = steel();
    let delta_s = Mindlin::new(a, P, F, F * P).unwrap().compliance_relative(&s, &s);
    let da = 2.0 * delta_s;
    let per = 40;
    let path = LoadPath::new(PathControl::Shift, vec![0.0, da, -da, da], vec![P], per).unwrap();
    let prob = HistoryProblem::new(&grid, [s, s], F).unwrap();
    let cap = prob.capacity(&grid.pressure);
    let pr = grid.pressure.clone();
    let out = prob.run(&path, |_| Ok::<_, Error>(pr.clone())).unwrap();
    let md = Deresiewicz::new(a, P, F, F * P).unwrap();
    let want = 2.0 * md.energy_per_cycle(&s) + 4.0 * F * P * (da - delta_s);
    assert_eq!(out.loops.len(), 1, "{:?}", out.loops);
    let l = out.loops[0];
    let rel = l.energy / want - 1.0;
    let solves: usize = out.steps.iter().map(|s| s.solves).sum();
    println!(
        "shift cycle +-2 delta_s (64 across, {per} steps per half): energy {:.6e} vs \
         W_MD(fP) + 4 fP (delta_a - delta_s) = {want:.6e} ({:+.3} %); force at the ends {:.6} and {:.6} of fP; \
         {solves} fast solves for {} steps",
        l.energy,
        100.0 * rel,
        out.steps[per].tangential / cap,
        out.steps[2 * per].tangential / cap,
        out.steps.len()
    );
    assert!(rel.abs() <= tol::MD_ENERGY, "{rel}");
    assert_eq!(out.steps[per].regime, Regime::GrossSlip);
    assert_eq!(out.steps[2 * per].regime, Regime::GrossSlip);
    // The shift is met: the prescribed value at every step.
    for st in &out.steps {
        assert!((st.shift - st.target).abs() <= 1e-8 * da, "{} {}", st.shift, st.target);
    }
}

/// Shift control in partial slip: the shift cycle through the turning points of the force
/// cycle +-fP/2 (their shifts taken from the force-controlled run) finds the same forces
/// there, and the energy per cycle of both is M–D's.
#[test]
fn shift_cycle_in_partial_slip_matches_force_cycle() {
    let (grid, a) = small_sphere(64);
    let s = steel();
    let ts = 0.5 * F * P;
    let prob = HistoryProblem::new(&grid, [s, s], F).unwrap();
    let pr = grid.pressure.clone();
    let per = 20;
    let force = LoadPath::new(PathControl::Force, vec![0.0, ts, -ts, ts], vec![P], per).unwrap();
    let fo = prob.run(&force, |_| Ok::<_, Error>(pr.clone())).unwrap();
    let (top, bottom) = (fo.steps[per].shift, fo.steps[2 * per].shift);
    let shift =
        LoadPath::new(PathControl::Shift, vec![0.0, top, bottom, top], vec![P], per).unwrap();
    let so = prob.run(&shift, |_| Ok::<_, Error>(pr.clone())).unwrap();
    let md = 2.0 * Deresiewicz::new(a, P, F, ts).unwrap().energy_per_cycle(&s);
    let (ef, es) = (fo.loops[0].energy, so.loops[0].energy);
    let t_top = so.steps[per].tangential / ts - 1.0;
    let t_bottom = so.steps[2 * per].tangential / ts + 1.0;
    let solves: usize = so.steps.iter().map(|s| s.solves).sum();
    println!(
        "shift vs force control (64 across): force at the turning points {t_top:+.2e}, \
         {t_bottom:+.2e} relative to T*; bottom shift {:.6} of -top; energy {es:.6e} \
         (shift) vs {ef:.6e} (force) vs M-D {md:.6e}; {solves} fast solves for {} steps",
        -bottom / top,
        so.steps.len()
    );
    for t in [t_top, t_bottom] {
        assert!(t.abs() <= tol::SHIFT_CONTROL, "{t}");
    }
    // The same loop, stepped equally in T and in delta (two trapezoidal rules).
    assert!((es / ef - 1.0).abs() <= tol::MD_ENERGY, "{es} {ef}");
    assert!((es / md - 1.0).abs() <= tol::MD_ENERGY, "{es} {md}");
}

/// A twisting-moment cycle (torsional fretting) on the Hertz circle: the loop is found, the
/// energy balance closes, and Masing's rule holds for the rotation up to the lattice's
/// departure from axial symmetry (on the circle the traction is circumferential and the
/// problem scalar in the continuum; Lubkin 1951, FORMULAS.md G).
#[test]
fn torsion_cycle_masing() {
    let (grid, a) = small_sphere(48);
    let s = steel();
    let mcap = 3.0 * PI * F * P * a / 16.0;
    let ms = 0.5 * mcap;
    let n = 10;
    let path = LoadPath::new(PathControl::Force, vec![0.0; 4], vec![P], n)
        .unwrap()
        .with_moment(vec![0.0, ms, -ms, ms])
        .unwrap();
    let prob = HistoryProblem::new(&grid, [s, s], F).unwrap();
    let pr = grid.pressure.clone();
    let out = prob.run(&path, |_| Ok::<_, Error>(pr.clone())).unwrap();
    assert_eq!(out.loops.len(), 1, "{:?}", out.loops);
    // Monotonic rotations at tau_j = j M*/n.
    let mono: Vec<f64> = (0..=n)
        .map(|j| {
            let tau = ms * j as f64 / n as f64;
            FastProblem::new(&grid, [s, s], F, Load::moment(tau, Some((0.0, 0.0))).unwrap())
                .unwrap()
                .solve()
                .unwrap()
                .rotation
        })
        .collect();
    let wstar = mono[n];
    let (mut load, mut mas) = (0.0f64, 0.0f64);
    for (j, m) in mono.iter().enumerate().skip(1) {
        load = load.max((out.steps[j].rotation - m).abs() / wstar);
        mas = mas.max((out.steps[n + j].rotation - (wstar - 2.0 * m)).abs() / wstar);
    }
    let l = out.loops[0];
    let scale = out.steps.iter().map(|s| s.work.abs()).fold(0.0, f64::max);
    let bal = out
        .steps
        .iter()
        .map(|s| (s.work - s.elastic_energy - s.dissipated).abs())
        .fold(0.0, f64::max)
        / scale;
    println!(
        "torsion cycle M* = 0.5 M_Lubkin (48 across): first branch vs monotonic {load:.2e}, Masing \
         {mas:.2e} of omega*; energy per cycle {:.4e}, loop work {:.4e}; balance {bal:.1e}",
        l.energy, l.work
    );
    assert!(load <= tol::TORSION && mas <= tol::TORSION, "{load} {mas}");
    assert!(bal <= tol::BALANCE, "{bal}");
    assert!(l.energy > 0.0);
}

/// A normal load that falls and rises at constant tangential force (a fretting test with a
/// varying clamp): cells leave and re-enter contact. Checked: the conditions every step
/// must meet (no traction where the surfaces are apart, Coulomb's disc on every cell, the
/// resultant equal to the force, the energy balance), and shakedown. The first fall to
/// P/2 slips; from then on the traction it left is admissible at every load between P/2
/// and P (the Hertz pressure grows with P at every point), so the increment zero solves
/// every later step: the cycle P/2 -> P -> P/2 is found as a loop and dissipates nothing.
#[test]
fn falling_and_rising_normal_load() {
    let s = steel();
    let n = 64;
    let a = hertz_radius(P, 1.0);
    let h = 2.0 * a / n as f64;
    let grid = centred_lattice(n, h, &hertz_on_lattice(P, n, h));
    let t = 0.4 * F * P;
    let path = LoadPath::new(
        PathControl::Force,
        vec![0.0, t, t, t, t],
        vec![P, P, 0.5 * P, P, 0.5 * P],
        10,
    )
    .unwrap();
    let prob = HistoryProblem::new(&grid, [s, s], F).unwrap();
    let mut h_ = prob.start().unwrap();
    let (mut worst_cone, mut worst_apart) = (0.0f64, 0.0f64);
    for pt in path.points() {
        let pr = hertz_on_lattice(pt.normal, n, h);
        let target =
            StepTarget { control: PathControl::Force, tangential: pt.tangential, moment: None };
        let st = *h_.step(Some(&pr), target).unwrap();
        assert!((st.tangential - pt.tangential).abs() <= 1e-8 * t, "{st:?}");
        for (q, p) in h_.traction().iter().zip(&pr) {
            let m = q.0.hypot(q.1);
            if *p == 0.0 {
                worst_apart = worst_apart.max(m);
            } else {
                worst_cone = worst_cone.max((m - F * p) / (F * p0(P, a)));
            }
        }
    }
    let steps = h_.steps().to_vec();
    let loops = h_.loops();
    let scale = steps.iter().map(|s| s.work.abs()).fold(0.0, f64::max);
    let bal =
        steps.iter().map(|s| (s.work - s.elastic_energy - s.dissipated).abs()).fold(0.0, f64::max)
            / scale;
    let negative: f64 =
        h_.dissipation().iter().filter(|d| **d < 0.0).sum::<f64>() * grid.element_area();
    println!(
        "normal load P -> P/2 -> P -> P/2 at T = 0.4 f P: (|q| - f p) / (f p0) <= {worst_cone:.1e}, \
         |q| apart {worst_apart:.1e}; balance {bal:.1e}; loops {:?}; cells with negative \
         dissipation sum to {negative:.2e} J against {:.2e} J dissipated; stick fraction at P/2 {:.3}",
        loops.iter().map(|l| (l.first_step, l.last_step, l.energy)).collect::<Vec<_>>(),
        steps.last().unwrap().dissipated,
        steps[20].stick_fraction
    );
    assert_eq!(worst_apart, 0.0);
    // Stick cells meet the disc to the solver's residual (1e-10 of |q| in the 2-norm).
    assert!(worst_cone <= 1e-8, "{worst_cone}");
    assert!(bal <= tol::BALANCE, "{bal}");
    assert_eq!(loops.len(), 1, "{loops:?}");
    assert_eq!((loops[0].first_step, loops[0].last_step), (20, 40));
    let first_fall = steps[20].dissipated - steps[10].dissipated;
    assert!(first_fall > 0.0);
    // Zero to the solver's residual (1e-10) and the rounding of the running sum of D.
    assert!(loops[0].energy.abs() <= 1e-10 * first_fall, "{loops:?}");
}
