//! The measurements, one function per method.

use super::{timed, Knob, MethodReport, Mode, Setting};
use crate::data;
use std::f64::consts::PI;
use stickslip_graded::{Accuracy, GradedMaterial, StressField, SurfaceLoad};
use stickslip_halfspace::hertz::HertzEllipse;
use stickslip_halfspace::Material;
use stickslip_lattice::{ContactGrid, InfluenceModel};
use stickslip_quad::battery::{self, Kind, Method};
use stickslip_quad::{gauss_kronrod, AdaptiveConfig, Tolerance};
use stickslip_rolling::{solve, GoryachevaParams, StressConfig};
use stickslip_traction::closed::Mindlin;
use stickslip_traction::{Load, TractionProblem};

/// Relative error, absolute when the reference is zero.
fn rel(got: f64, want: f64) -> f64 {
    if want == 0.0 {
        got.abs()
    } else {
        ((got - want) / want).abs()
    }
}

/// Decades from `10^-hi` to `10^-lo`, loosest first.
fn decades(lo: i32, hi: i32) -> Vec<f64> {
    (lo..=hi).map(|e| 10f64.powi(-e)).collect()
}

/// `tol=1e-8` style label.
fn tol_label(t: f64) -> String {
    format!("tol={t:.0e}")
}

/// Which adaptive integrator.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum QuadKind {
    /// Adaptive Gauss–Kronrod $G_{10}K_{21}$.
    Kronrod,
    /// Double-exponential (tanh–sinh).
    TanhSinh,
}

/// The adaptive integrators on every battery integral they apply to, at several tolerances.
pub(super) fn quad_adaptive(mode: Mode, kind: QuadKind) -> MethodReport {
    let (method, slug, title) = match kind {
        QuadKind::Kronrod => (Method::Gk21, "quad-gk21", "quad: adaptive Gauss-Kronrod G10K21"),
        QuadKind::TanhSinh => (Method::TanhSinh, "quad-tanh-sinh", "quad: tanh-sinh"),
    };
    let problems = battery::problems();
    let tols = match mode {
        Mode::Quick => vec![1e-4, 1e-8, 1e-12],
        Mode::Full => decades(3, 13),
    };
    let mut settings = Vec::new();
    for tol in tols {
        let t = Tolerance::new(0.0, tol).expect("valid tolerance");
        let sweep =
            || problems.iter().filter_map(|p| battery::run(method, p, t)).collect::<Vec<_>>();
        let (probe, cost) = timed(1, sweep);
        let (rows, secs) = timed(mode.reps(cost), sweep);
        drop(probe);
        let converged: Vec<_> = rows.iter().filter(|r| r.result.is_ok()).collect();
        let error = converged.iter().map(|r| r.true_error() / r.exact.abs()).fold(0.0, f64::max);
        let evals: usize = rows.iter().filter_map(battery::Row::estimate).map(|e| e.evals).sum();
        settings.push(Setting {
            label: tol_label(tol),
            knob: tol,
            error,
            claim: Some(tol),
            seconds: secs,
            work: format!("{}/{} integrals converged, {evals} evals", converged.len(), rows.len()),
        });
    }
    MethodReport {
        slug,
        title,
        knob: Knob::Tolerance,
        reference: "the 43-integrand battery of `stickslip_quad::battery` (closed forms and \
                    mpmath at 40 digits, `crates/quad/tests/data/battery.csv`)"
            .into(),
        error_measure: "max over the integrals that report convergence of |Q - I|/|I|; \
                        integrals that report non-convergence are counted in `work` (an \
                        honest refusal, not a wrong answer)"
            .into(),
        claim_source: "the requested relative tolerance".into(),
        settings,
        reading: String::new(),
    }
}

/// Fixed Gauss–Legendre rules on the smooth finite-interval integrals of the battery.
pub(super) fn quad_legendre(mode: Mode) -> MethodReport {
    let problems: Vec<_> = battery::problems()
        .into_iter()
        .filter(|p| matches!(p.kind, Kind::Plain { a, b, .. } if a.is_finite() && b.is_finite()))
        .filter(|p| p.name != "log01")
        .collect();
    let nodes: Vec<usize> = match mode {
        Mode::Quick => vec![8, 32, 128],
        Mode::Full => vec![4, 8, 16, 32, 64, 128],
    };
    let mut settings = Vec::new();
    for n in nodes {
        let t = Tolerance::new(0.0, 1e-12).expect("valid tolerance");
        let sweep = || {
            problems
                .iter()
                .filter_map(|p| battery::run(Method::Legendre(n), p, t))
                .collect::<Vec<_>>()
        };
        let (rows, secs) = timed(mode.reps(0.0), sweep);
        let error =
            rows.iter().map(|r| r.true_error() / r.exact.abs()).fold(0.0, |m: f64, e| m.max(e));
        settings.push(Setting {
            label: format!("n={n}"),
            knob: n as f64,
            error,
            claim: None,
            seconds: secs,
            work: format!("{} integrals, {} evals each", rows.len(), 2 * n),
        });
    }
    MethodReport {
        slug: "quad-legendre",
        title: "quad: fixed Gauss-Legendre",
        knob: Knob::Nodes,
        reference: format!(
            "the smooth finite-interval integrals of the battery ({}), closed forms",
            problems.iter().map(|p| p.name).collect::<Vec<_>>().join(", ")
        ),
        error_measure: "max |Q - I|/|I| (the rule plus its companion for the error estimate)"
            .into(),
        claim_source: "none (a fixed rule promises no accuracy; its estimate is tested in \
                       stickslip-quad)"
            .into(),
        settings,
        reading: String::new(),
    }
}

/// Graded subsurface stresses (full integration) against the mpmath table of
/// `crates/graded/tests/data/graded_stress.txt`.
pub(super) fn graded_stress(mode: Mode) -> MethodReport {
    let rows = data::rows(data::GRADED_STRESS, None, 0);
    let tols = match mode {
        Mode::Quick => vec![1e-4, 1e-8, 1e-12],
        Mode::Full => decades(2, 14),
    };
    // Group the rows by material and load (one planned field per group).
    let mut groups: Vec<(Vec<f64>, Vec<&Vec<f64>>)> = Vec::new();
    for r in &rows {
        match groups.iter_mut().find(|g| g.0[..5] == r[..5]) {
            Some(g) => g.1.push(r),
            None => groups.push((r[..5].to_vec(), vec![r])),
        }
    }
    let mut settings = Vec::new();
    for tol in tols {
        let acc = Accuracy::new(stickslip_graded::Tolerance::relative(tol).expect("tolerance"))
            .expect("tolerance in range");
        let sweep = || {
            let mut worst = 0.0f64;
            for (key, pts) in &groups {
                let (k, nu, mu, a, p0) = (key[0], key[1], key[2], key[3], key[4]);
                let m = GradedMaterial::new(1.0, k, nu).expect("valid material");
                let load = SurfaceLoad::cylinder(a, p0, k, mu).expect("valid load");
                let f = StressField::new(&m, load, acc).expect("valid field");
                for r in pts {
                    let s = f.stress(r[5], r[6]).expect("valid point");
                    worst = worst.max(stress_err([s.xx, s.yy, s.xy], [r[7], r[8], r[9]]));
                }
            }
            worst
        };
        let (error, secs) = timed(mode.reps(0.05), sweep);
        settings.push(Setting {
            label: tol_label(tol),
            knob: tol,
            error,
            claim: Some(tol.max(GRADED_ROUNDOFF)),
            seconds: secs,
            work: format!("{} points, {} nodes/panel", rows.len(), acc.nodes()),
        });
    }
    MethodReport {
        slug: "graded-stress",
        title: "graded: subsurface stresses (StressField)",
        knob: Knob::Tolerance,
        reference: format!(
            "{} points of `crates/graded/tests/data/graded_stress.txt` (mpmath, mp.dps = 40, \
             scripts/graded_reference.py); k from 0.01 to 0.95, y/a from 1e-3 to 4, at and \
             beyond the contact edges",
            rows.len()
        ),
        error_measure: "max over points and components of |got - want| / max(|want|, \
                        1e-3 max|sigma| at the point) (the floor keeps a component that \
                        crosses zero from dividing by ~0; same measure as the crate's tests)"
            .into(),
        claim_source: "the requested `Accuracy::new(tol)`, but not below 1e-12: the error \
                       measure divides by as little as 1e-3 max|sigma|, so the few-ulp \
                       rounding of the O(max|sigma|) sums shows as up to ~1e3 x 4 eps"
            .into(),
        settings,
        reading: String::new(),
    }
}

/// Floor of the graded-stress claim: f64 rounding of the sums (a few ulps of max|sigma|)
/// amplified by up to 1e3 by the error measure's floor (see [`stress_err`]).
const GRADED_ROUNDOFF: f64 = 1e-12;

/// Component error with a floor of 1e-3 of the largest component.
fn stress_err(got: [f64; 3], want: [f64; 3]) -> f64 {
    let big = want.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    got.iter().zip(&want).map(|(g, w)| (g - w).abs() / w.abs().max(1e-3 * big)).fold(0.0, f64::max)
}

/// Goryacheva's root solves (eqs 19, 20, 24, 25, 27, 28) against the mpmath table.
pub(super) fn rolling_solve(mode: Mode) -> MethodReport {
    let rows = data::goryacheva_rows();
    let sweep = || {
        let mut worst = 0.0f64;
        for r in &rows {
            let p =
                GoryachevaParams::new(r.e, r.nu, r.r, r.p, r.rho, r.delta, r.alpha, r.beta, r.w)
                    .expect("valid reference row");
            let s = solve(&p).expect("solvable reference row");
            let got =
                [s.contact_length, s.shift, s.stick_length, s.c2, s.tangential_force, s.moment_m1];
            for (g, w) in got.iter().zip(&r.want) {
                worst = worst.max(rel(*g, *w));
            }
        }
        worst
    };
    let (error, secs) = timed(mode.reps(0.0), sweep);
    MethodReport {
        slug: "rolling-solve",
        title: "rolling: Goryacheva root solves",
        knob: Knob::Fixed,
        reference: format!(
            "{} rows of `crates/rolling/tests/data/goryacheva_reference.txt` (unscaled eqs \
             19-28 by mpmath, mp.dps = 50; alpha, beta from 1e-6 to 1e6 s)",
            rows.len()
        ),
        error_measure: "max relative error of l, d, m, C2, Q, M1 over the rows".into(),
        claim_source: "1e-10 relative (issue 4 target, the crate's `REFERENCE_REL`)".into(),
        settings: vec![Setting {
            label: "brent".into(),
            knob: 0.0,
            error,
            claim: Some(1e-10),
            seconds: secs,
            work: format!("{} solves", rows.len()),
        }],
        reading: String::new(),
    }
}

/// $\int_{lo}^{hi} f\,dx$ with $x = $ mid $+$ half $\cos\phi$ (smooths the square-root ends),
/// adaptive at 1e-14; the estimate is used even if the integrator reports non-convergence
/// (the inner quadrature noise then shows up in the measured error, which is the point).
fn outer(f: impl Fn(f64) -> f64, lo: f64, hi: f64, scale: f64) -> f64 {
    let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
    let cfg = AdaptiveConfig::new(Tolerance::new(1e-14 * scale, 1e-14).expect("valid"))
        .with_max_subdivisions(2000)
        .expect("valid");
    match gauss_kronrod(|phi: f64| f(mid + half * phi.cos()) * half * phi.sin(), 0.0, PI, &cfg) {
        Ok(e) => e.value,
        Err(stickslip_quad::Error::NotConverged { estimate, .. }) => estimate.value,
        Err(_) => f64::NAN,
    }
}

/// Goryacheva's pressure and shear (eqs 12, 13 by quadrature): $\int\sigma_y = P$ and
/// $\int\tau = Q$ (mpmath) for three rows of the reference table.
pub(super) fn rolling_stress(mode: Mode) -> MethodReport {
    // Rows with moderate Bessel arguments (no boundary layer): the outer integral then
    // converges to 1e-14 and the error is the stress quadrature's.
    let all = data::goryacheva_rows();
    let mut rows: Vec<_> =
        all.iter().filter(|r| r.x1 > 0.05 && r.x1 < 20.0).take(2).copied().collect();
    // and one slow case (x1 = l/(2 beta w) large: a boundary layer of width beta w at the
    // trailing edge), where the stress quadratures have to work
    rows.extend(all.iter().filter(|r| r.x1 > 50.0 && r.x1 < 500.0).take(1).copied());
    let tols = match mode {
        Mode::Quick => vec![1e-4, 1e-8, 1e-12],
        Mode::Full => decades(3, 13),
    };
    let mut settings = Vec::new();
    for tol in tols {
        let cfg = StressConfig {
            tol: Tolerance::new(0.0, tol).expect("valid"),
            ..StressConfig::default()
        };
        let sweep = || {
            let mut worst = 0.0f64;
            for r in &rows {
                let p = GoryachevaParams::new(
                    r.e, r.nu, r.r, r.p, r.rho, r.delta, r.alpha, r.beta, r.w,
                )
                .expect("valid row");
                let s = solve(&p).expect("solvable");
                let (lo, hi, c) = (-s.rear, s.front, s.stick_start);
                let val =
                    |e: Result<stickslip_rolling::Estimate, _>| e.map_or(f64::NAN, |e| e.value);
                let pint = outer(|x| val(s.pressure(x, &cfg)), lo, hi, r.p);
                let q = outer(|x| val(s.shear(x, &cfg)), lo, c, r.p)
                    + outer(|x| val(s.shear(x, &cfg)), c, hi, r.p);
                worst = worst.max(rel(pint, r.p)).max(rel(q, r.want[4]));
            }
            worst
        };
        let (error, secs) = timed(mode.reps(0.3), sweep);
        settings.push(Setting {
            label: tol_label(tol),
            knob: tol,
            error,
            claim: Some(tol),
            seconds: secs,
            work: format!("{} cases, 3 outer integrals each", rows.len()),
        });
    }
    MethodReport {
        slug: "rolling-stress",
        title: "rolling: Goryacheva pressure and shear (StressConfig)",
        knob: Knob::Tolerance,
        reference: format!(
            "equilibrium: integral of the pressure = P, of the shear = Q from the mpmath table, \
             for {} rows with Bessel argument x1 in (0.05, 20)",
            rows.len()
        ),
        error_measure: "max of |int sigma_y dx - P|/P and |int tau dx - Q|/|Q|; the outer \
                        integral is adaptive Gauss-Kronrod at 1e-14 in x = mid + half cos(phi)"
            .into(),
        claim_source: "the requested `StressConfig::tol.rel()` (relative to the stress scale S; \
                       S is of order P/l here)"
            .into(),
        settings,
        reading: String::new(),
    }
}

/// The modified LP (seed 002 Fig. 3.5) on Hertz circles against Mindlin's compliance.
pub(super) fn lp_mindlin(mode: Mode) -> MethodReport {
    let across: Vec<usize> = match mode {
        Mode::Quick => vec![6, 10, 14],
        Mode::Full => vec![6, 8, 10, 14, 20, 28, 36, 50],
    };
    // Seed 002 Example 1: steel sphere R = 1 in on a steel flat, P = 2160 lbf, T = 144 lbf,
    // f = 0.1 (T/fP = 2/3).
    let (p, t, f) = (2160.0, 144.0, 0.1);
    let steel = Material::new(30e6, 0.3).expect("steel");
    let a = (3.0 * p * (2.0 * steel.normal_compliance()) / 4.0).cbrt();
    let want = Mindlin::new(a, p, f, t).expect("partial slip").compliance_per_body(&steel);
    let mut settings = Vec::new();
    for n in across {
        let grid = ContactGrid::hertz_circle(a, p, n).expect("grid");
        let run = || {
            TractionProblem::new(&grid, [steel, steel], f, Load::Force { magnitude: t, angle: 0.0 })
                .expect("valid problem")
                .with_model(InfluenceModel::ExactRectangle)
                .solve()
                .expect("LP solves")
        };
        let (probe, cost) = timed(1, run);
        let (sol, secs) = timed(mode.reps(cost), run);
        drop(probe);
        let error = rel(sol.rigid_per_body[0], want);
        settings.push(Setting {
            label: format!("N={}", grid.len()),
            knob: n as f64,
            error,
            claim: if grid.len() >= 1900 {
                Some(0.005)
            } else {
                (grid.len() >= 80).then_some(0.015)
            },
            seconds: secs,
            work: format!("{n} across, {} pivots", sol.info.iterations),
        });
    }
    MethodReport {
        slug: "traction-lp",
        title: "traction: modified LP on a Hertz circle",
        knob: Knob::GridSize,
        reference: "Mindlin's closed form for the tangential compliance (seed 002 Example 1, \
                    T/fP = 2/3; FORMULAS.md E)"
            .into(),
        error_measure: "|delta_LP / delta_Mindlin - 1|, delta the rigid displacement per body"
            .into(),
        claim_source: "issue 5: within 1.5 % from 80 elements, within 0.5 % from about \
                       2,000 elements (exact rectangle influence coefficients)"
            .into(),
        settings,
        reading: String::new(),
    }
}

/// The fast solver (FFT products, semismooth Newton) on Hertz circles against Mindlin.
pub(super) fn fast_mindlin(mode: Mode, notes: &mut Vec<String>) -> MethodReport {
    use stickslip_traction::{fast::FastProblem, fast::TractionDirections};
    let across: Vec<usize> = match mode {
        Mode::Quick => vec![16, 32],
        Mode::Full => vec![16, 32, 64, 128, 256],
    };
    let (p, t, f) = (2160.0, 144.0, 0.1);
    let steel = Material::new(30e6, 0.3).expect("steel");
    let a = (3.0 * p * (2.0 * steel.normal_compliance()) / 4.0).cbrt();
    let want = Mindlin::new(a, p, f, t).expect("partial slip").compliance_relative(&steel, &steel);
    let mut settings = Vec::new();
    for n in across {
        let grid = ContactGrid::hertz_circle(a, p, n).expect("grid");
        let run = || {
            FastProblem::new(&grid, [steel, steel], f, Load::polar(t, 0.0).expect("load"))
                .expect("valid problem")
                .with_directions(TractionDirections::ParallelToForce)
                .expect("directions")
                .solve()
        };
        let (probe, cost) = timed(1, run);
        if let Err(e) = probe {
            notes.push(format!(
                "traction-fast at {n} across (N = {}): solver error: {e}",
                grid.len()
            ));
            continue;
        }
        let (sol, secs) = timed(mode.reps(cost), run);
        let Ok(sol) = sol else { continue };
        let error = rel(sol.shift.0, want);
        settings.push(Setting {
            label: format!("N={}", grid.len()),
            knob: n as f64,
            error,
            claim: if grid.len() >= 1900 {
                Some(0.005)
            } else {
                (grid.len() >= 80).then_some(0.015)
            },
            seconds: secs,
            work: format!(
                "{n} across, {} Newton steps, {} CG iterations",
                sol.info.iterations, sol.info.cg_iterations
            ),
        });
    }
    MethodReport {
        slug: "traction-fast",
        title: "traction: fast solver on a Hertz circle",
        knob: Knob::GridSize,
        reference: "Mindlin's closed form for the relative tangential compliance (seed 002 \
                    Example 1, T/fP = 2/3; FORMULAS.md E); tractions parallel to the force as \
                    in Mindlin's solution"
            .into(),
        error_measure: "|shift_x / delta_Mindlin - 1|, the relative rigid shift of the bodies"
            .into(),
        claim_source: "the LP's issue-5 targets: 1.5 % from 80 elements, 0.5 % from about \
                       2,000"
            .into(),
        settings,
        reading: String::new(),
    }
}

/// Elliptic Hertz contact against the mpmath table, for ratios 1 to 1e6 (both orientations).
pub(super) fn hertz_ellipse(mode: Mode) -> MethodReport {
    let rows = data::rows(data::HERTZ_ELLIPSE, Some(','), 0);
    let sweep = || {
        let mut worst = 0.0f64;
        for r in &rows {
            for swap in [false, true] {
                let (rx, ry) = if swap { (1.0 / r[0], 1.0) } else { (1.0, 1.0 / r[0]) };
                let el = HertzEllipse::new(rx, ry, 1.0, 1.0).expect("valid ellipse");
                let (ax, bx) = if swap {
                    (el.semi_axis_y(), el.semi_axis_x())
                } else {
                    (el.semi_axis_x(), el.semi_axis_y())
                };
                for (g, w) in
                    [(ax, r[2]), (bx, r[3]), (el.max_pressure(), r[4]), (el.approach(), r[5])]
                {
                    worst = worst.max(rel(g, w));
                }
            }
        }
        worst
    };
    let (error, secs) = timed(mode.reps(0.0), sweep);
    MethodReport {
        slug: "hertz-ellipse",
        title: "halfspace: elliptic Hertz contact",
        knob: Knob::Fixed,
        reference: format!(
            "{} rows of `crates/halfspace/tests/data/hertz_ellipse.csv` (mpmath, mp.dps = 40), \
             radius ratios 1 to 1e6, both orientations",
            rows.len()
        ),
        error_measure: "max relative error of a, b, p0, delta".into(),
        claim_source: "1e-11 relative (the crate's `HERTZ_ELLIPSE` tolerance: conditioning of \
                       b/a near m = 1)"
            .into(),
        settings: vec![Setting {
            label: "root".into(),
            knob: 0.0,
            error,
            claim: Some(1e-11),
            seconds: secs,
            work: format!("{} contacts", 2 * rows.len()),
        }],
        reading: String::new(),
    }
}

/// Contact grid of an ellipse of semi-axes `a` (rolling direction) and `b` with about `n`
/// square cells across the longer axis, carrying `load`.
fn rolling_ellipse(a: f64, b: f64, n: usize, load: f64) -> ContactGrid {
    let h = 2.0 * a.max(b) / n as f64;
    let nx = ((2.0 * a / h).round() as usize).max(4);
    let ny = ((2.0 * b / h).round() as usize).max(4);
    ContactGrid::hertz_ellipse(a, b, load, nx, ny).expect("ellipse grid")
}

/// Exact 3D steady rolling in the linear (no-slip) limit against Kalker's creepage
/// coefficients: the grid convergence of C11, C22, C23 (a/b = 1, nu = 0.25).
pub(super) fn rolling3d_exact(mode: Mode) -> MethodReport {
    use stickslip_rolling::{steady3d::kalker, steady3d::Creepage, steady3d::SteadyRolling};
    let nu = 0.25;
    let g = 8e10;
    let m = Material::new(2.0 * g * (1.0 + nu), nu).expect("material");
    let (a, b) = (1e-3, 1e-3);
    let k = kalker::coefficients(a / b, nu).expect("table");
    let sizes: &[usize] = match mode {
        Mode::Quick => &[20, 40],
        Mode::Full => &[20, 40, 80, 120],
    };
    let mut settings = Vec::new();
    for &n in sizes {
        let grid = rolling_ellipse(a, b, n, 1e3);
        let run = || {
            let p = SteadyRolling::new(&grid, [m, m], 0.3)
                .and_then(|p| p.with_tolerance(1e-9))
                .expect("problem");
            let unit = 1e-4;
            let c = (a * b).sqrt();
            let s1 = p.solve_no_slip(&Creepage { longitudinal: unit, ..Default::default() });
            let s2 = p.solve_no_slip(&Creepage { lateral: unit, ..Default::default() });
            let s3 = p.solve_no_slip(&Creepage { spin: unit / c, ..Default::default() });
            let scale = g * a * b * unit;
            match (s1, s2, s3) {
                (Ok(s1), Ok(s2), Ok(s3)) => {
                    Some([-s1.fx / scale, -s2.fy / scale, -s3.fy / scale, s1.info.products as f64])
                }
                _ => None,
            }
        };
        let (probe, cost) = timed(1, run);
        if probe.is_none() {
            continue;
        }
        let (c, secs) = timed(mode.reps(cost), run);
        let Some(c) = c else { continue };
        let errs = [rel(c[0], k.c11), rel(c[1], k.c22), rel(c[2], k.c23)];
        settings.push(Setting {
            label: format!("n={n}"),
            knob: n as f64,
            error: errs.iter().copied().fold(0.0, f64::max),
            claim: (n >= 40).then_some(0.02),
            seconds: secs,
            work: format!(
                "{} elements; C11 {:.4}, C22 {:.4}, C23 {:.4}; {} GMRES products per solve",
                grid.len(),
                c[0],
                c[1],
                c[2],
                c[3]
            ),
        });
    }
    MethodReport {
        slug: "rolling3d-exact",
        title: "traction: exact 3D steady rolling, linear theory",
        knob: Knob::GridSize,
        reference: format!(
            "Kalker's tabulated creepage coefficients at a/b = 1, nu = 0.25 (C11 = {}, C22 = \
             {}, C23 = {}; `stickslip_rolling::steady3d::kalker`, Kalker 1990 Table E3)",
            k.c11, k.c22, k.c23
        ),
        error_measure: "max over C11, C22, C23 of the relative deviation from the table".into(),
        claim_source: "issue 18: Kalker's coefficients within 1-2 %".into(),
        settings,
        reading: String::new(),
    }
}

/// FASTSIM or Polach against the exact theory on the same grid: the largest force error over
/// shapes and creepages, relative to fN.
pub(super) fn rolling3d_approx(mode: Mode, polach: bool) -> MethodReport {
    use stickslip_rolling::{
        steady3d::fastsim, steady3d::polach as law, steady3d::Creepage, steady3d::SteadyRolling,
        steady3d::FASTSIM_FORCE_ERROR, steady3d::POLACH_FORCE_ERROR,
    };
    let (nu, g, f, load) = (0.28, 8e10, 0.3, 1e4);
    let m = Material::new(2.0 * g * (1.0 + nu), nu).expect("material");
    let sizes: &[usize] = match mode {
        Mode::Quick => &[24],
        Mode::Full => &[24, 40],
    };
    let dirs: &[[f64; 3]] = if polach {
        &[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.7, 0.7, 0.0]]
    } else {
        &[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.7, 0.7, 0.0], [0.6, 0.3, 0.5]]
    };
    let mut settings = Vec::new();
    for &n in sizes {
        let mut cases = Vec::new();
        for ab in [0.3, 1.0, 3.0] {
            let b = 5e-3;
            let a = ab * b;
            let grid = rolling_ellipse(a, b, n, load);
            let p0 = 1.5 * load / (PI * a * b);
            let scale = f * p0 / g;
            let exact = SteadyRolling::new(&grid, [m, m], f)
                .and_then(|p| p.with_tolerance(1e-8))
                .expect("problem");
            for d in dirs {
                for s in [0.1, 0.3, 0.6, 1.0, 2.0, 5.0] {
                    let creep = Creepage {
                        longitudinal: d[0] * s * scale,
                        lateral: d[1] * s * scale,
                        spin: d[2] * s * scale / (a * b).sqrt(),
                    };
                    if let Ok(e) = exact.solve(&creep) {
                        cases.push((grid.clone(), a, b, creep, e.fx, e.fy));
                    }
                }
            }
        }
        let run = || {
            let mut worst = 0.0f64;
            for (grid, a, b, creep, fx, fy) in &cases {
                let (gx, gy) = if polach {
                    law::forces(*a, *b, g, nu, load, f, creep).expect("Polach")
                } else {
                    let s = fastsim::solve(grid, *a, *b, g, nu, f, creep).expect("FASTSIM");
                    (s.fx, s.fy)
                };
                worst = worst.max((gx - fx).hypot(gy - fy) / (f * load));
            }
            worst
        };
        let (_, cost) = timed(1, run);
        let (error, secs) = timed(mode.reps(cost), run);
        settings.push(Setting {
            label: format!("n={n}"),
            knob: n as f64,
            error,
            claim: Some(if polach { POLACH_FORCE_ERROR } else { FASTSIM_FORCE_ERROR }),
            seconds: secs / cases.len().max(1) as f64,
            work: format!("{} creepage cases, time per case", cases.len()),
        });
    }
    let (slug, title) = if polach {
        ("rolling3d-polach", "traction: Polach's creep-force law against the exact theory")
    } else {
        ("rolling3d-fastsim", "traction: FASTSIM against the exact theory")
    };
    MethodReport {
        slug,
        title,
        knob: Knob::GridSize,
        reference: "the exact steady-rolling theory on the same grid (residual 1e-8), a/b = \
                    0.3, 1, 3, creepages 0.1 to 5 times f p0/G, pure and combined directions"
            .into(),
        error_measure: "max |F - F_exact| / (f N)".into(),
        claim_source: if polach {
            "POLACH_FORCE_ERROR, the bound the planner uses (measured 0.108 at 40 cells)".into()
        } else {
            "FASTSIM_FORCE_ERROR, the bound the planner uses (measured 0.090 at 40 cells)".into()
        },
        settings,
        reading: String::new(),
    }
}
