//! Every scene in `scenes/` runs through `run(scene)`, fast; its key outputs match the
//! closed forms (or the mpmath table) of the physics they select; and every effect that is
//! off was never evaluated (instrumentation counters), every effect that is on was.

mod common;
use common::{rel, scenes_dir, tol, INCH, LBF, PSI};
use std::f64::consts::PI;
use std::time::Instant;
use stickslip_run::{run, Effect, Outcome, Plan, RunOptions, SurfaceOut};
use stickslip_scene::Scene;

fn run_file(name: &str) -> (Scene, Plan, Outcome, f64) {
    let path = scenes_dir().join(name);
    let scene = Scene::from_file(&path).unwrap_or_else(|e| panic!("{e}"));
    let plan = Plan::new(&scene).unwrap();
    let t0 = Instant::now();
    let out = run(&scene, &RunOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    (scene, plan, out, t0.elapsed().as_secs_f64())
}

type Arrays<'a> = (&'a [f64], &'a [f64], &'a [f64], &'a [f64], &'a [f64]);

fn line(out: &Outcome) -> Arrays<'_> {
    match &out.surface {
        SurfaceOut::Line { x, p, q, ux, uy, .. } => (x, p, q, ux, uy),
        SurfaceOut::Grid { .. } => panic!("expected a 2D surface"),
    }
}

/// Resultant of a grid traction: (sum qx dA, sum qy dA, moment about the origin).
fn grid_resultant(out: &Outcome) -> (f64, f64, f64, f64) {
    let SurfaceOut::Grid { x, y, p, qx, qy, stick, .. } = &out.surface else { panic!("grid") };
    let (hx, hy) = (x[1] - x[0], y[1] - y[0]);
    let (mut fx, mut fy, mut m, mut worst_cone) = (0.0, 0.0, 0.0, 0.0f64);
    let f = out.forces.normal; // placeholder to keep signature simple
    let _ = f;
    for i in 0..x.len() {
        for j in 0..y.len() {
            if stick[i][j] < 0 {
                continue;
            }
            let da = hx * hy;
            fx += qx[i][j] * da;
            fy += qy[i][j] * da;
            m += (x[i] * qy[i][j] - y[j] * qx[i][j]) * da;
            let _ = p[i][j];
            worst_cone = worst_cone.max(qx[i][j].hypot(qy[i][j]));
        }
    }
    (fx, fy, m, worst_cone)
}

/// The friction cone |q| <= f p on every element, relative to f p_max.
fn cone_violation(out: &Outcome, f: f64) -> f64 {
    let SurfaceOut::Grid { x, y, p, qx, qy, stick, .. } = &out.surface else { panic!("grid") };
    let pmax = p.iter().flatten().fold(0.0f64, |a, b| a.max(*b));
    let mut worst = 0.0f64;
    for i in 0..x.len() {
        for j in 0..y.len() {
            if stick[i][j] >= 0 {
                worst = worst.max((qx[i][j].hypot(qy[i][j]) - f * p[i][j]) / (f * pmax));
            }
        }
    }
    worst
}

fn check(name: &str, scene: &Scene, out: &Outcome) -> Vec<String> {
    let report = std::cell::RefCell::new(Vec::new());
    let expect = |what: &str, got: f64, want: f64, tol: f64| {
        let e = rel(got, want);
        report.borrow_mut().push(format!(
            "{name}: {what} = {got:.10e} vs {want:.10e}, rel {e:.2e} (tol {tol:.0e})"
        ));
        assert!(e <= tol, "{name}: {what}: {got} vs {want}, rel {e:.3e} > {tol:.1e}");
    };
    let c = out.contact;
    match name {
        "seed000_table1_roller.toml" => {
            // FORMULAS.md A4: P = 986.39 kgf/m, h = 0.0052807 m; A5 with the exact h at x = 0.
            expect("P", c.normal_load, 986.39 * 9.80665, tol::QUOTED5);
            expect("h", c.indentation.unwrap(), 0.0052807, tol::QUOTED5);
            let h = 0.0178f64 * 0.0178 / (2.0 * 0.3 * 0.1);
            expect("h = a^2/(2Rk)", c.indentation.unwrap(), h, tol::CLOSED);
            let nu = 0.3f64;
            let k = 0.1f64;
            let eq32 = (1.0 + k) * (1.0 - nu) / (1.0 - (1.0 + k) * nu) * h; // mu = 1, x = 0
            expect(
                "u_x(0) vs eq 32",
                out.rigid_displacement.tangential.unwrap(),
                eq32,
                tol::QUADRATURE,
            );
            expect(
                "u_x(0) vs Table 3 (exact h)",
                out.rigid_displacement.tangential.unwrap(),
                0.006069,
                1e-4,
            );
            expect("T = f P", out.forces.tangential, c.normal_load, tol::CLOSED);
        }
        "graded_roller_partial_slip.toml" => {
            let (a, k, f, t) = (0.0178, 0.1, 0.5, out.forces.tangential);
            let cst = out.zones.stick[0][1];
            expect(
                "c/a",
                cst / a,
                (1.0 - t / (f * c.normal_load)).powf(1.0 / (2.0 + k)),
                tol::CLOSED,
            );
            // The q-induced u_x is uniform on the stick zone (spectral relation, FORMULAS.md
            // A4): the even part of u_x, (u_x(x) + u_x(-x))/2, is constant for |x| < c.
            let (x, _, q, ux, _) = line(out);
            let n = x.len();
            let mid = n / 2;
            let even: Vec<f64> = (0..n)
                .filter(|&i| x[i].abs() < 0.95 * cst)
                .map(|i| 0.5 * (ux[i] + ux[n - 1 - i]))
                .collect();
            let spread = even.iter().fold(0.0f64, |m, v| m.max(rel(*v, even[0])));
            report.borrow_mut().push(format!(
                "{name}: even u_x spread over the stick zone {spread:.2e} ({} points)",
                even.len()
            ));
            assert!(spread < tol::QUADRATURE, "{spread}");
            // q(0) = f p0 (1 - (c/a)^(1+k))
            expect("q(0)", q[mid], f * c.p0 * (1.0 - (cst / a).powf(1.0 + k)), tol::CLOSED);
        }
        "hertz_cylinder_cattaneo.toml" => {
            let (e, nu, r) = (210e9, 0.3f64, 0.02);
            let es = e / (2.0 * (1.0 - nu * nu));
            let a = (4.0 * 1e5 * r / (PI * es)).sqrt();
            expect("a (2D Hertz)", c.a, a, tol::CLOSED);
            expect(
                "c/a",
                out.zones.stick[0][1] / a,
                (1.0f64 - 15.0 / (0.3 * 100.0)).sqrt(),
                tol::CLOSED,
            );
            // Even part of u_y relative to x = 0 is minus the per-body Hertz approach
            // (composite E* = 2 x body for identical materials): HertzLine::approach_relative / 2.
            let h = stickslip_halfspace::hertz::HertzLine::new(1e5, r, es).unwrap();
            let (x, _, _, _, uy) = line(out);
            let n = x.len();
            let mut worst = 0.0f64;
            for i in 0..n / 2 {
                let even = 0.5 * (uy[i] + uy[n - 1 - i]);
                let want = -0.5 * h.approach_relative(x[i]);
                worst = worst.max(rel(even, want));
            }
            report.borrow_mut().push(format!(
                "{name}: even u_y vs HertzLine::approach_relative/2, worst rel {worst:.2e}"
            ));
            assert!(worst < 1e-12, "{worst}");
            // Surface limit of the McEwen field: sigma_yy -> -p at the shallowest row centre.
            let f = out.field.plane();
            assert!(f.syy[0][f.x.len() / 2] < 0.0);
        }
        "seed001_goryacheva_rubber.toml" | "seed001_goryacheva_slow_relaxation.toml" => {
            let r = out.rolling.unwrap();
            let want: [f64; 6] = if name.contains("rubber") {
                [
                    0.00879689488238245073957544915267,
                    0.000000494971586920519713926281629887,
                    0.0065974236949354308322855159228,
                    -0.00272772378223279185189381773098,
                    -349.999995479556065087956554941,
                    0.000989886347684280991674404927739,
                ]
            } else {
                [
                    0.00000000890535757274609060977174972637,
                    0.0000000276289525526327295844339322659,
                    0.00000000299499617679491611535450587192,
                    -1145.74590408378461465679238931,
                    -707.549037845330681418168766071,
                    0.0000278747596326819390678313464536,
                ]
            };
            let got = [r.l, r.d, r.m, r.C2.unwrap(), r.Q, r.M1];
            for (k, nm) in ["l", "d", "m", "C2", "Q", "M1"].iter().enumerate() {
                expect(nm, got[k], want[k], tol::MPMATH);
            }
        }
        "seed001_elastic_limit.toml" | "carter_steel_rolling.toml" => {
            let (e, nu, rr, p, rho, delta) = if name.contains("seed001") {
                (5e6, 0.49f64, 0.05, 1000.0, 0.8, 0.01)
            } else {
                (210e9, 0.3f64, 0.46, 5e5, 0.3, 0.0005)
            };
            let kk = 4.0 * (1.0 - nu * nu) / (PI * e);
            let a = (2.0 * kk * rr * p).sqrt();
            let r = out.rolling.unwrap();
            expect("l = sqrt(8KRP)", r.l, (8.0 * kk * rr * p).sqrt(), tol::CLOSED);
            assert_eq!(r.d, 0.0);
            expect("c = -a + 2 delta R / rho", r.c, -a + 2.0 * delta * rr / rho, tol::CLOSED);
            let z = delta * rr / (rho * a);
            expect(
                "Q (Carter creep law)",
                r.Q,
                -rho * p * (1.0 - (1.0 - z) * (1.0 - z)),
                tol::CLOSED,
            );
        }
        "seed002_ex1_mindlin.toml" | "seed002_ex1_lp.toml" => {
            expect("a (in)", c.a / INCH, 0.046148, tol::QUOTED5 * 2.0);
            let per_body = out.rigid_displacement.per_body.unwrap()[0] / INCH;
            if name.contains("mindlin") {
                // FORMULAS.md E: exact reproduction needs E = 30.0003e6 psi (1e-5).
                expect("per-body delta (in)", per_body, 0.671394e-4, 2e-5);
                expect("a* (in)", out.zones.stick[0][1] / INCH, 0.031997, tol::QUOTED5 * 5.0);
            } else {
                let SurfaceOut::Grid { stick, .. } = &out.surface else { panic!() };
                let n = stick.iter().flatten().filter(|s| **s >= 0).count();
                assert_eq!(n, 80);
                expect("LP per-body delta vs Mindlin (in)", per_body, 0.671394e-4, tol::LP_80);
                let (fx, fy, _, _) = grid_resultant(out);
                expect("sum of element tractions = T", fx.hypot(fy), 144.0 * LBF, 1e-9);
                let v = cone_violation(out, 0.1);
                assert!(v < tol::CONE, "cone {v}");
            }
        }
        "seed002_ex2_rubber.toml" => {
            let pb = out.rigid_displacement.per_body.unwrap();
            expect("rubber per body (in)", pb[0] / INCH, 0.403917e-3, tol::QUOTED5);
            expect("steel per body (in)", pb[1] / INCH, 0.134639e-4, tol::QUOTED5);
            expect("ratio = E_s/E_r", pb[0] / pb[1], 30.0, tol::CLOSED);
        }
        n if n.starts_with("seed002_ex3") => {
            let al = c.a;
            expect("a*/a", out.zones.stick[0][1] / al, 0.5f64.cbrt(), tol::CLOSED);
            expect(
                "p0 = 3P/(2 pi a b)",
                c.p0,
                3.0 * 500.0 * LBF / (2.0 * PI * c.a * c.b),
                tol::CLOSED,
            );
        }
        n if n.starts_with("seed002_ex4") || n.starts_with("seed002_ex5") => {
            let (fx, fy, _, _) = grid_resultant(out);
            expect("|sum of element tractions| = T", fx.hypot(fy), scene.load.tangential, 1e-9);
            let dir = fy.atan2(fx).to_degrees();
            let ddir = (dir - scene.load.direction_deg).abs();
            report.borrow_mut().push(format!(
                "{name}: resultant direction {dir:.12} deg (|error| {ddir:.1e} deg)"
            ));
            assert!(ddir < 1e-9, "{name}: direction {dir}");
            let v = cone_violation(out, 0.12);
            assert!(v < tol::CONE, "cone {v}");
            expect(
                "P = sum p A",
                c.normal_load,
                if n.contains("ex4") {
                    1e4 * PSI * INCH * INCH
                } else if n.contains("case1") {
                    2.0 * 1e4 * PSI * 0.36 * INCH * INCH
                } else {
                    3.0 * 1e4 * PSI * 0.36 * INCH * INCH
                },
                tol::CLOSED,
            );
        }
        "seed002_twist_lubkin.toml" | "seed002_twist_lp.toml" => {
            let (p, f, m) = (2160.0 * LBF, 0.1, 0.39737);
            let es = 30e6 * PSI / (2.0 * (1.0 - 0.09));
            let a = (3.0 * p * INCH / (4.0 * es)).cbrt();
            expect("a", c.a, a, tol::CLOSED);
            let lub = stickslip_traction::closed::Lubkin::from_moment(a, p, f, m).unwrap();
            let g = 30e6 * PSI / 2.6;
            let kme = {
                // K(k) - E(k) with k^2 = 1 - c^2/a^2, from stickslip-special (parameter m = k^2)
                let mm = 1.0 - (lub.stick_radius() / a).powi(2);
                stickslip_special::ellipk(mm) - stickslip_special::ellipe(mm)
            };
            let omega = 2.0 * 3.0 * f * p / (4.0 * PI * g * a * a) * kme;
            let got = out.rigid_displacement.rotation.unwrap();
            if name.contains("lubkin") {
                expect("rotation (FORMULAS.md G)", got, omega, 1e-12);
                expect("M(c) = M", lub.moment().unwrap(), m, 1e-12);
            } else {
                expect("LP rotation vs Lubkin", got, omega, tol::LP_TWIST);
                let (_, _, mz, _) = grid_resultant(out);
                expect("moment of the element tractions", mz, m, 1e-6);
                assert!(cone_violation(out, f) < tol::CONE);
            }
        }
        "sphere_load_cycle.toml" => {
            let cy = out.cycle.as_ref().unwrap();
            let (p, f) = (2160.0 * LBF, 0.1);
            let nu = 0.3;
            let g = 30e6 * PSI / 2.6;
            let t = 0.5;
            let bracket = 1.0
                - (1.0f64 - t).powf(5.0 / 3.0)
                - 5.0 * t / 6.0 * (1.0 + (1.0f64 - t).powf(2.0 / 3.0));
            let w = 9.0 * (2.0 - nu) * f * f * p * p / (10.0 * g * c.a) * bracket;
            expect("W per body (FORMULAS.md E)", cy.energy_per_cycle[0], w, 1e-12);
            // Loop area (shoelace) equals the energy of both bodies.
            let n = cy.t.len();
            let mut area = 0.0;
            for i in 0..n - 1 {
                area += 0.5 * (cy.delta[i + 1] - cy.delta[i]) * (cy.t[i + 1] + cy.t[i]);
            }
            expect("loop area = 2 W", area.abs(), 2.0 * w, tol::LOOP_AREA);
        }
        "transient_rolling_cattaneo.toml" => {
            // The first step is Mindlin's shift of two identical spheres (Johnson eq. 7.42),
            // the creep force is held at every step, and the creepage has settled after two
            // contact lengths (crates/run/tests/transient_rolling.rs compares with the steady
            // solver).
            let h = out.history.as_ref().unwrap();
            let (e, nu, p, f, t) = (210e9, 0.3, 500.0, 0.3, 75.0);
            let g = e / (2.0 * (1.0 + nu));
            let delta = 3.0 * f * p * (2.0 - nu) / (8.0 * g * c.a)
                * (1.0 - (1.0f64 - t / (f * p)).powf(2.0 / 3.0));
            expect("shift at rest (Mindlin)", h.shift[0].abs(), delta, 0.02);
            for x in &h.tangential {
                expect("creep force held", *x, t, 1e-9);
            }
            let n = h.creepage_longitudinal.len() - 1;
            expect(
                "creepage settled (last two steps)",
                h.creepage_longitudinal[n],
                h.creepage_longitudinal[n - 1],
                1e-3,
            );
        }
        "transient_rolling_creepage.toml" => {
            // A Cattaneo shift under 75 N (Mindlin's shift), then every rolling step at the
            // prescribed creepage, the creep force found; after the default ten contact
            // lengths the force has settled (crates/run/tests/transient_rolling.rs compares a
            // run from rest with the steady solver).
            let h = out.history.as_ref().unwrap();
            let (e, nu, p, f, t) = (210e9, 0.3, 500.0, 0.3, 75.0);
            let g = e / (2.0 * (1.0 + nu));
            let delta = 3.0 * f * p * (2.0 - nu) / (8.0 * g * c.a)
                * (1.0 - (1.0f64 - t / (f * p)).powf(2.0 / 3.0));
            expect("shift at rest (Mindlin)", h.shift[0].abs(), delta, 0.02);
            expect("force of the shift", h.tangential[0], t, 1e-9);
            for x in &h.creepage_longitudinal[1..] {
                expect("creepage prescribed", *x, -1e-3, 1.1e-9);
            }
            let n = h.fx.len() - 1;
            expect("creep force settled (last two steps)", h.fx[n], h.fx[n - 1], 1e-7);
        }
        "sphere_fretting_history.toml" => {
            // The load path's two loops against Mindlin-Deresiewicz's energy per cycle
            // (FORMULAS.md E), both bodies.
            let h = out.history.as_ref().unwrap();
            let (p, f) = (2160.0 * LBF, 0.1);
            let nu = 0.3;
            let g = 30e6 * PSI / 2.6;
            let t = 0.5;
            let bracket = 1.0
                - (1.0f64 - t).powf(5.0 / 3.0)
                - 5.0 * t / 6.0 * (1.0 + (1.0f64 - t).powf(2.0 / 3.0));
            let w = 9.0 * (2.0 - nu) * f * f * p * p / (10.0 * g * c.a) * bracket;
            assert_eq!(h.loops.len(), 2);
            for l in &h.loops {
                expect(
                    "energy per cycle vs 2 W (FORMULAS.md E)",
                    l.energy,
                    2.0 * w,
                    tol::HISTORY_LOOP,
                );
            }
            assert!(out.audit.passed);
        }
        "rough_periodic_fretting.toml" => {
            // No closed form for a rough sphere; what every path must meet: the two loops
            // of the file's path, each over the full force range of 1 N; the dissipation map
            // summing to the path's dissipation; each loop dissipating less than the work
            // of sliding over its shift range at the largest normal load, 2 f P delta; the
            // final normal load; Coulomb's law.
            let h = out.history.as_ref().unwrap();
            assert_eq!(h.loops.len(), 2, "{:?}", h.loops);
            for l in &h.loops {
                expect("loop force range", l.force_range, 1.0, 1e-9);
                assert!(l.energy > 0.0 && l.energy < 2.0 * 0.2 * 5.0 * l.shift_range, "{l:?}");
            }
            let SurfaceOut::Grid { x, y, dissipation: Some(d), .. } = &out.surface else {
                panic!("no dissipation map")
            };
            let total = d.iter().flatten().sum::<f64>() * (x[1] - x[0]) * (y[1] - y[0]);
            expect(
                "dissipation map against the path's",
                total,
                *h.dissipated.last().unwrap(),
                1e-9,
            );
            expect("final normal load", out.forces.normal, 5.0, 1e-6);
            assert!(cone_violation(out, 0.2) < tol::CONE);
            assert!(out.audit.passed);
        }
        "two_patch_joint_twist.toml" => {
            let (_, _, mz, _) = grid_resultant(out);
            expect("moment of the element tractions", mz, 40.0, 1e-6);
            assert!(cone_violation(out, 0.12) < tol::CONE);
        }
        "fast_mindlin_sphere_256.toml" => {
            // Issue 6's target: the rigid shift within 0.5 % of Mindlin, the stick radius
            // within one cell, the residual at most 1e-8 (FORMULAS.md E).
            let (p, f, t) = (2160.0 * LBF, 0.1, 144.0 * LBF);
            let steel = stickslip_halfspace::Material::new(30e6 * PSI, 0.3).unwrap();
            let m = stickslip_traction::closed::Mindlin::new(c.a, p, f, t).unwrap();
            let delta = m.compliance_relative(&steel, &steel);
            let got = out.rigid_displacement.tangential.unwrap();
            expect("fast shift vs Mindlin", got, delta, tol::FAST_SHIFT);
            let pb = out.rigid_displacement.per_body.unwrap();
            expect(
                "fast per-body shift vs seed 002 (in)",
                pb[0] / INCH,
                0.671394e-4,
                tol::FAST_SHIFT,
            );
            let g = out.zones.grid.unwrap();
            let h = 2.0 * c.a / 256.0;
            let r_stick = (g.stick as f64 * h * h / PI).sqrt();
            let cells = (r_stick - m.stick_radius()) / h;
            report.borrow_mut().push(format!(
                "{name}: stick radius (area-equivalent) {r_stick:.6e} vs a* {:.6e}: {cells:+.3} cells; {} elements, {} Newton steps, {} CG, residual {:.2e}, solve {:.2} s",
                m.stick_radius(),
                out.solver.elements,
                out.solver.iterations,
                out.solver.inner_iterations,
                out.solver.residual,
                out.solver.solve_seconds
            ));
            assert!(cells.abs() <= 1.0, "{cells}");
            assert!(out.solver.residual <= tol::FAST_RESIDUAL, "{}", out.solver.residual);
            assert!(out.solver.iterations > 0 && out.solver.inner_iterations > 0);
            let (fx, fy, _, _) = grid_resultant(out);
            expect("sum of element tractions = T", fx.hypot(fy), t, tol::FAST_LOAD);
            assert!(cone_violation(out, f) < tol::CONE);
        }
        "fast_gasket_ring_force_and_twist.toml" => {
            let (fx, fy, mz, _) = grid_resultant(out);
            expect(
                "|sum of element tractions| = T",
                fx.hypot(fy),
                scene.load.tangential,
                tol::FAST_LOAD,
            );
            let dir = fy.atan2(fx).to_degrees();
            expect("resultant direction (deg)", dir, 30.0, tol::FAST_LOAD);
            // The frame is symmetric about the origin: the moment about its centroid.
            expect("moment of the element tractions", mz, 80.0, tol::FAST_LOAD);
            assert!(cone_violation(out, 0.15) < tol::CONE);
            let g = out.zones.grid.unwrap();
            assert_eq!(g.stick + g.slip, 17500);
            assert!(g.stick > 0 && g.slip > 0, "partial slip expected: {g:?}");
            assert!(out.rigid_displacement.tangential.is_some());
            assert!(out.rigid_displacement.rotation.unwrap() > 0.0);
        }
        "fast_two_patch_joint_fine.toml" => {
            let (fx, fy, _, _) = grid_resultant(out);
            expect(
                "|sum of element tractions| = T",
                fx.hypot(fy),
                scene.load.tangential,
                tol::FAST_LOAD,
            );
            expect("resultant direction (deg)", fy.atan2(fx).to_degrees(), 45.0, tol::FAST_LOAD);
            assert!(cone_violation(out, 0.12) < tol::CONE);
            expect("P = sum p A", c.normal_load, 22000.0 * PSI * 0.36 * INCH * INCH, tol::CLOSED);
            assert_eq!(out.solver.elements, 11250);
        }
        "seed000_frictionless_roller.toml" => {
            expect("P", c.normal_load, 986.39 * 9.80665, tol::QUOTED5);
            let (_, _, q, _, _) = line(out);
            assert!(q.iter().all(|v| *v == 0.0));
        }
        "sphere_subsurface_field.toml" => {
            // On the axis the shear (symmetric in x) adds nothing to sigma_zz, so sigma_zz is
            // Hertz's -p0 / (1 + z^2/a^2) (Johnson eq. 3.45), up to the lattice's resolution.
            let v = out.field.volume().expect("a 3D field");
            let vals = v.values.as_ref().expect("a small box is inline");
            let (nx, ny) = (v.x.len(), v.y.len());
            let i0 = nx / 2;
            assert!(v.x[i0].abs() < 1e-12 * c.a && ny == 1);
            let worst =
                v.z.iter()
                    .enumerate()
                    .map(|(k, z)| {
                        (vals.szz[k * nx + i0] + c.p0 / (1.0 + (z / c.a).powi(2))).abs() / c.p0
                    })
                    .fold(0.0, f64::max);
            report.borrow_mut().push(format!(
                "{name}: sigma_zz on the axis vs Johnson 3.45, worst {worst:.2e} p0"
            ));
            assert!(worst < 5e-3, "{worst}");
            // The tension behind the contact, near the trailing edge x = -a.
            let t = v.max.max_principal;
            assert!(t.value > 0.0 && t.x < -0.8 * c.a && t.x > -1.2 * c.a, "{t:?}");
            assert!(out.audit.passed);
        }
        "adhesive_sphere.toml" => {
            // Maugis's closed form (stickslip-halfspace, the dimensionless Maugis-Dugdale
            // equations) against the lattice's approach path: the pull-off within 3 % (the
            // path samples the curve every 1 nm), passed and let go; the approach and the
            // retraction meet at the turning corner.
            let m = stickslip_halfspace::adhesion::MaugisSphere::new(1e-6, 0.05, 2e-9, 1e9 / 0.75)
                .unwrap();
            assert_eq!(out.contact.pull_off_reached, Some(true));
            expect("pull-off vs Maugis", out.contact.pull_off.unwrap(), m.pull_off().force, 0.03);
            let c = out.load_curve.as_ref().unwrap();
            assert_eq!(c.normal.len(), 41);
            expect("deepest approach", c.approach[20], 16e-9, 1e-12);
            let e = m.force_at_approach(16e-9).unwrap();
            expect("force at 16 nm vs Maugis", c.normal[20], e, 0.01);
            assert_eq!(out.contact.area, Some(0.0), "let go at -4 nm");
            assert!(out.audit.passed);
        }
        "sphere_as_surface.toml" => {
            // The normal solve on the lattice against Hertz (a within one cell, p0 1 %,
            // approach 0.5 %), then the fast solver's partial slip on that contact.
            let e_star: f64 = 210e9 / (2.0 * (1.0 - 0.09));
            let (p, r): (f64, f64) = (10.0, 0.01);
            let a = (3.0 * p * r / (4.0 * e_star)).cbrt();
            let h = 0.8e-3 / 128.0;
            assert!((c.a - a).abs() <= h, "a {} vs {a}", c.a);
            expect("p0 (Hertz)", c.p0, 3.0 * p / (2.0 * PI * a * a), 0.01);
            expect("approach (Hertz)", c.indentation.unwrap(), a * a / r, 0.005);
            assert!(out.zones.grid.unwrap().stick > 0 && out.audit.passed);
        }
        "crowned_roller.toml" => {
            // Mid-length: Hertz line contact for the load per length carried there (peak
            // pressure 1 %); the crowned ends (last 0.1 mm) carry no pressure.
            let SurfaceOut::Grid { x, y, p, .. } = &out.surface else { panic!("grid") };
            let (nx, ny) = (x.len(), y.len());
            let hx = x[1] - x[0];
            let mid: Vec<f64> = (0..nx).map(|i| 0.5 * (p[i][ny / 2 - 1] + p[i][ny / 2])).collect();
            let load = mid.iter().sum::<f64>() * hx;
            let e_star: f64 = 210e9 / (2.0 * (1.0 - 0.09));
            let peak = mid.iter().copied().fold(0.0, f64::max);
            expect(
                "mid-length p0 (Hertz line, local P')",
                peak,
                (load * e_star / (PI * 0.01)).sqrt(),
                0.01,
            );
            let ends = (0..ny)
                .filter(|&j| y[j].abs() > 0.9e-3)
                .flat_map(|j| (0..nx).map(move |i| (i, j)))
                .map(|(i, j)| p[i][j])
                .fold(0.0, f64::max);
            assert!(ends == 0.0 && out.audit.passed, "pressure {ends} on the crowned ends");
        }
        "wheel_rail_creepage_spin.toml" | "wheel_rail_fastsim.toml" => {
            // The scene's theory against the other one on the same Hertz grid: the exact
            // theory and FASTSIM differ by at most FASTSIM's measured force error (0.1 fN).
            use stickslip_rolling::{
                steady3d::fastsim, steady3d::Creepage, steady3d::SteadyRolling,
                steady3d::FASTSIM_FORCE_ERROR,
            };
            let stickslip_scene::Motion::RollingCreepage { longitudinal, lateral, spin, .. } =
                scene.motion
            else {
                panic!("3D rolling expected")
            };
            let creep = Creepage { longitudinal, lateral, spin };
            let nu = 0.28;
            let m = stickslip_halfspace::Material::new(210e9, nu).unwrap();
            let g = m.shear_modulus();
            let n = scene.solver.grid;
            let (a, b) = (c.a, c.b);
            let h = 2.0 * a.max(b) / n as f64;
            let grid = stickslip_lattice::ContactGrid::hertz_ellipse(
                a,
                b,
                c.normal_load,
                (2.0 * a / h).round() as usize,
                (2.0 * b / h).round() as usize,
            )
            .unwrap();
            let other = if name == "wheel_rail_fastsim.toml" {
                SteadyRolling::new(&grid, [m, m], 0.3).unwrap().solve(&creep).unwrap()
            } else {
                fastsim::solve(&grid, a, b, g, nu, 0.3, &creep).unwrap()
            };
            let (fx, fy) = (out.forces.fx.unwrap(), out.forces.fy.unwrap());
            let fnorm = 0.3 * c.normal_load;
            let diff = (fx - other.fx).hypot(fy - other.fy) / fnorm;
            report.borrow_mut().push(format!(
                "{name}: F = ({fx:.6e}, {fy:.6e}) N vs the other theory ({:.6e}, {:.6e}) N: {diff:.3} fN",
                other.fx, other.fy
            ));
            assert!(diff <= FASTSIM_FORCE_ERROR, "{name}: {diff}");
            assert!(fx.hypot(fy) < fnorm && out.audit.passed);
            let z = out.zones.grid.unwrap();
            assert!(z.stick > 0 && z.slip > 0, "{z:?}");
        }
        "wheel_rail_manchester_a22.toml" => {
            report.borrow_mut().extend(wheel_rail_checks(name, scene, out));
        }
        other => panic!("no check for scene {other}: add one"),
    }
    report.into_inner()
}

/// What every wheel-rail result must meet: the load balance, Coulomb's law per patch, the
/// contact angle's sign, and the numbers of the library's own solve of the same position;
/// and against CONTACT's published output for the Manchester position it ships.
fn wheel_rail_checks(name: &str, scene: &Scene, out: &Outcome) -> Vec<String> {
    use stickslip_wheelrail as wr;
    let stickslip_scene::Geometry::WheelRail(g) = &scene.geometry else { panic!("wheel-rail") };
    let stickslip_scene::Motion::Wheelset { speed, pitch_rate, .. } = scene.motion else {
        panic!("a wheelset's motion")
    };
    let w = out.wheel_rail.as_ref().expect("wheel_rail in the result");
    let f = scene.load.friction;
    let stickslip_scene::NormalLoad::Force(load) = scene.load.normal else { panic!("load") };
    // Load balance and Coulomb, from the reported patches.
    let vertical: f64 = w.patches.iter().map(|p| p.fn_ * p.contact_angle.cos()).sum();
    assert!((vertical - load).abs() <= 1e-6 * load, "{name}: sum Fn cos = {vertical}");
    for p in &w.patches {
        assert!(p.fx.hypot(p.fs) <= f * p.fn_ * (1.0 + 1e-9), "{name}: creep force beyond f Fn");
        assert!(p.coulomb.unwrap() <= 1e-6, "{name}: Coulomb {:?}", p.coulomb);
        assert!(p.fn_ > 0.0 && p.area > 0.0 && p.pmax > 0.0);
    }
    // The library's own solve of the same position: the same numbers.
    let o = wr::ProfileOptions { unit: g.profile_unit, ..wr::ProfileOptions::default() };
    let read = |f: &stickslip_scene::ProfileFile, role| {
        wr::Profile::read(&f.text, &f.name, wr::Format::from_name(&f.name), role, &o).unwrap()
    };
    let track =
        wr::Track::new(read(&g.rail_profile, wr::Role::Rail), g.gauge, g.gauge_height, g.rail_cant)
            .unwrap();
    let ws = wr::Wheelset::new(
        read(&g.wheel_profile, wr::Role::Wheel),
        g.flange_back_distance,
        g.flange_back_position,
        g.wheel_radius,
    )
    .unwrap();
    let steel = stickslip_halfspace::Material::new(209.92e9, 0.28).unwrap();
    let side =
        if g.side == stickslip_scene::RailSide::Left { wr::Side::Left } else { wr::Side::Right };
    let cell = scene.solver.cell.unwrap();
    let pb = wr::WheelRail::new(side, track, ws, steel, steel, f, (cell[0], cell[1])).unwrap();
    let pos =
        wr::Position { lateral: g.position.lateral, yaw: g.position.yaw, roll: g.position.roll };
    let lib = pb
        .solve(
            &pos,
            &wr::Motion::rolling(speed, pitch_rate.unwrap()),
            wr::VerticalLoad::Force(load),
            wr::Tangential::Exact { tolerance: scene.solver.tolerance },
            &mut wr::Cache::new(),
        )
        .unwrap();
    assert_eq!(lib.patches.len(), w.patches.len());
    assert_eq!(lib.z_wheelset, w.z_wheelset);
    assert_eq!(lib.total_on_rail, [w.total_on_rail.fx, w.total_on_rail.fy, w.total_on_rail.fz]);
    for (a, b) in lib.patches.iter().zip(&w.patches) {
        assert_eq!(
            [a.normal_force, a.fx, a.fs, a.mn, a.pmax, a.area, a.contact_angle, a.rail_point[0]],
            [b.fn_, b.fx, b.fs, b.mn, b.pmax, b.area, b.contact_angle, b.y_rail]
        );
        assert_eq!(a.creepage.spin, b.creepage.spin);
    }
    // CONTACT's published output for this position (Manchester, left wheel,
    // position 5): one patch on the tread; CONTACT's force control counts the creep forces'
    // vertical components too, so its Fn differs from ours by about Fs sin(delta)/cos(delta).
    let p = &w.patches[0];
    // CONTACT (its exact theory, 0.2 mm cells): z_ws 0.1530 mm, Fn 1.004e4 N, Fx 546.3 N,
    // Fs -2961 N, delta 0.0134 rad, y_r 4.027 mm, pmax 465.9 MPa, one patch.
    assert_eq!(w.patches.len(), 1);
    assert!(p.contact_angle > 0.0, "the tread contact of a left wheel shifted right tilts +");
    let fnorm = f * 1.004e4;
    let diffs = [
        ((w.z_wheelset * 1e3 - 0.1530).abs(), 5e-3, "z_ws (mm)"),
        ((p.fn_ / 1.004e4 - 1.0).abs(), 1e-2, "Fn (relative)"),
        ((p.fx - 546.3).abs() / fnorm, 1e-2, "Fx (of f Fn)"),
        ((p.fs + 2961.0).abs() / fnorm, 1e-2, "Fs (of f Fn)"),
        ((p.contact_angle - 0.0134).abs(), 5e-4, "delta (rad)"),
        ((p.y_rail * 1e3 - 4.027).abs(), 0.1, "y_rail (mm)"),
        ((p.pmax * 1e-6 / 465.9 - 1.0).abs(), 1e-2, "pmax (relative)"),
    ];
    for (d, limit, what) in diffs {
        assert!(d <= limit, "{name}: {what} differs from CONTACT's by {d:.3e} (limit {limit:.0e})");
    }
    let mut lines = vec![format!(
        "{name}: {} patch(es); z_ws = {:.5} mm; Fn = {:.1} N, Fx = {:.1} N, Fs = {:.1} N, delta = {:.4} rad, y_rail = {:.3} mm, pmax = {:.1} MPa, stick {:.3}",
        w.patches.len(),
        w.z_wheelset * 1e3,
        p.fn_,
        p.fx,
        p.fs,
        p.contact_angle,
        p.y_rail * 1e3,
        p.pmax * 1e-6,
        p.stick_fraction.unwrap_or(f64::NAN)
    )];
    lines.push(format!("{name}: vertical balance {:.2e}", (vertical - load).abs() / load));
    lines.push(format!(
        "{name}: against CONTACT: {}",
        diffs.iter().map(|(d, _, w)| format!("{w} {d:.2e}")).collect::<Vec<_>>().join(", ")
    ));
    lines
}

#[test]
fn every_scene_runs_fast_matches_its_closed_forms_and_computes_only_what_is_on() {
    let mut names: Vec<String> = std::fs::read_dir(scenes_dir())
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".toml"))
        .collect();
    names.sort();
    assert!(names.len() >= 20, "scenes/ has {} scenes", names.len());
    let mut total = 0.0;
    for name in &names {
        let (scene, plan, out, secs) = run_file(name);
        total += secs;
        let on: Vec<&str> =
            Effect::ALL.iter().filter(|e| plan.is_on(**e)).map(|e| e.name()).collect();
        println!("{name}: {secs:.3} s; on: {}", on.join(", "));
        for e in Effect::ALL {
            let n = out.evaluations.get(e);
            if plan.is_on(e) {
                assert!(n > 0, "{name}: {e} is on but was never evaluated");
            } else {
                assert_eq!(n, 0, "{name}: {e} is off but was evaluated {n} times");
            }
        }
        assert_eq!(out.effects.on, on);
        for line in check(name, &scene, &out) {
            println!("  {line}");
        }
    }
    println!("{} scenes in {total:.2} s", names.len());
}

#[test]
fn default_run_is_fast_and_real() {
    let t0 = Instant::now();
    let out = run(&Scene::default_scene(), &RunOptions::default()).unwrap();
    let secs = t0.elapsed().as_secs_f64();
    println!(
        "default scene: {secs:.3} s, {} field points",
        out.field.plane().x.len() * out.field.plane().y.len()
    );
    assert_eq!(out.field.plane().sxx.len(), 40);
    assert_eq!(out.field.plane().sxx[0].len(), 61);
    assert!(rel(out.contact.normal_load, 986.39 * 9.80665) < tol::QUOTED5);
}

/// Off effects are not evaluated even when the scene carries their inputs: the same roller
/// with and without outputs.field; with friction 0 (friction off) and a sliding flag.
#[test]
fn switching_an_effect_off_removes_its_evaluations() {
    let base = stickslip_scene::DEFAULT_SCENE;
    let no_field =
        base.replace("field = { x = [-1.5, 1.5, 61], y = [0.02, 2.0, 40], scale = \"a\" }\n", "");
    let s = Scene::from_toml_str(&no_field, None).unwrap();
    let out = run(&s, &RunOptions::default()).unwrap();
    assert_eq!(out.evaluations.subsurface_field, 0);
    assert!(out.field.plane().x.is_empty());
    let frictionless = no_field.replace("friction = 1.0\nsliding = true\n", "friction = 0.0\n");
    let s = Scene::from_toml_str(&frictionless, None).unwrap();
    let out = run(&s, &RunOptions::default()).unwrap();
    assert_eq!(out.evaluations.friction, 0);
    assert!(out.evaluations.grading > 0);
    let k0 = frictionless.replace("k = 0.1", "k = 0.0").replace("kgf/m^2.1", "kgf/m^2");
    let s = Scene::from_toml_str(&k0, None).unwrap();
    let plan = Plan::new(&s).unwrap();
    assert!(!plan.is_on(Effect::Grading));
    let out = run(&s, &RunOptions::default()).unwrap();
    assert_eq!(out.evaluations.grading, 0);
    println!("k = 0: grading off, {} normal-contact evaluations", out.evaluations.normal_contact);
}

#[test]
fn explain_lists_every_effect_with_a_reason_and_computes_nothing() {
    let s = Scene::default_scene();
    let plan = Plan::new(&s).unwrap();
    let text = plan.explain();
    println!("{text}");
    for e in Effect::ALL {
        assert!(text.contains(e.name()), "{e} missing");
    }
    assert!(text.contains("effects off"));
    assert!(text.contains("estimated cost"));
    assert!(plan.cost.seconds < 10.0);
}
