//! The magnitudes a scene may hold (`stickslip_scene::ranges`, docs/SCENES.md "Magnitudes"):
//! every range is run at both ends, just inside (solved, and the audit passes) and just
//! outside (refused before solving, exit status 2, naming the key and the range). The
//! extreme scenes of issue 33's corpus are refused the same way, and random magnitudes over
//! all of f64 either solve with a passing audit or are refused with exit 2: never a failed
//! audit or solver (exit 3), never a panic.

// SceneError carries file, position, key and hint; tests return it as is.
#![allow(clippy::result_large_err)]

use stickslip_run::{run, RunOptions};
use stickslip_scene::ranges::{self, CONTACT_OVER_RADIUS, PRESSURE_OVER_MODULUS};
use stickslip_scene::{Scene, SceneError};

fn solve(src: &str) -> Result<stickslip_run::Outcome, SceneError> {
    let s = Scene::from_toml_str(src, Some("m.toml".into()))?;
    run(&s, &RunOptions::default())
}

/// A sphere of radius `r` on a flat, both of modulus `e` (nu = 0.3), pressed by `p`, with
/// friction `f` and a tangential force `t`.
fn sphere(r: f64, e: f64, p: f64, f: f64, t: f64) -> String {
    format!(
        "[geometry]\nkind = \"sphere\"\nradius = {r:e}\n[substrate]\ne = {e:e}\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = {p:e}\nfriction = {f:e}\ntangential = {t:e}\n"
    )
}

/// A cylinder (2D) of radius `r`, modulus `e`, pressed by `p` per unit length.
fn cylinder(r: f64, e: f64, p: f64) -> String {
    format!(
        "[geometry]\nkind = \"cylinder\"\nradius = {r:e}\n[substrate]\ne = {e:e}\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = {p:e}\nfriction = 0.3\ntangential = {:e}\n",
        0.1 * p
    )
}

/// The Hertz load of a sphere of radius `r` (same material, modulus `e`, nu = 0.3) whose
/// contact radius is `ratio` r: P = 4 E* a^3 / (3 R).
fn sphere_load(r: f64, e: f64, ratio: f64) -> f64 {
    let es = e / (2.0 * (1.0 - 0.09));
    4.0 * es * (ratio * r).powi(3) / (3.0 * r)
}

fn expect_solved(name: &str, src: &str) {
    match solve(src) {
        Ok(out) => {
            assert!(out.audit.checks.iter().all(|c| c.pass), "{name}: audit {:?}", out.audit);
            assert!(out.contact.normal_load > 0.0, "{name}: no load carried");
        }
        Err(e) => panic!("{name}: refused, expected solved: {e}"),
    }
}

fn expect_refused(name: &str, src: &str, key: &str) {
    match solve(src) {
        Ok(_) => panic!("{name}: solved, expected refused at {key}"),
        Err(e) => {
            let msg = e.to_string();
            assert_eq!(e.exit_code(), 2, "{name}: exit {} ({msg})", e.exit_code());
            assert_eq!(e.key.as_deref(), Some(key), "{name}: {msg}");
            assert!(e.position.is_some(), "{name}: no line:column: {msg}");
            assert!(e.hint.as_deref().is_some_and(|h| !h.is_empty()), "{name}: no hint");
            assert!(!msg.contains("please report"), "{name}: {msg}");
        }
    }
}

/// Just inside and just outside: the ends times (1 +- 1e-3) and times 0.5 / 2.
const IN: f64 = 1.001;
const OUT: f64 = 2.0;

#[test]
fn moduli_at_both_ends() {
    let r = ranges::MODULUS;
    for (e, r0) in [(r.lo * IN, 1e-2), (r.hi / IN, 1e-2)] {
        let p = sphere_load(r0, e, 0.01);
        expect_solved(&format!("E = {e:e}"), &sphere(r0, e, p, 0.3, 0.1 * p));
    }
    for e in [r.lo / OUT, r.hi * OUT, 5e-324, 1.7e308] {
        expect_refused(&format!("E = {e:e}"), &sphere(1e-2, e, 1.0, 0.3, 0.0), "substrate.e");
    }
}

#[test]
fn forces_at_both_ends() {
    let f = ranges::FORCE;
    // E and R chosen so that a/R stays inside its range at the extreme loads.
    expect_solved("P = lo", &sphere(1e-2, 1e3, f.lo * IN, 0.3, 0.0));
    expect_solved("P = hi", &sphere(1e2, 1e12, f.hi / IN, 0.3, 0.1 * f.hi));
    for p in [f.lo / OUT, f.hi * OUT, 1e300, 5e-324] {
        expect_refused(&format!("P = {p:e}"), &sphere(1e-2, 1e9, p, 0.3, 0.0), "load.normal");
    }
    let l = ranges::FORCE_PER_LENGTH;
    expect_solved("P' = lo", &cylinder(1e-3, 1e2, l.lo * IN));
    expect_solved("P' = hi", &cylinder(1e3, 1e13, l.hi / IN));
    for p in [l.lo / OUT, l.hi * OUT] {
        expect_refused(&format!("P' = {p:e}"), &cylinder(1e-2, 1e9, p), "load.normal");
    }
}

#[test]
fn lengths_at_both_ends() {
    let l = ranges::LENGTH;
    for r in [l.lo * IN, l.hi / IN] {
        let e = if r < 1.0 { 1e13 } else { 1e9 };
        let p = sphere_load(r, e, 0.01);
        expect_solved(&format!("R = {r:e}"), &sphere(r, e, p, 0.3, 0.1 * p));
    }
    for r in [l.lo / OUT, l.hi * OUT, 1e-300] {
        expect_refused(&format!("R = {r:e}"), &sphere(r, 1e9, 1.0, 0.3, 0.0), "geometry.radius");
    }
    let semi = |a: f64, b: f64, p: f64| {
        format!("[geometry]\nkind = \"ellipsoid\"\nsemi_axes = [{a:e}, {b:e}]\n[substrate]\ne = 2e11\nnu = 0.3\n[load]\nnormal = {p:e}\nfriction = 0.3\n")
    };
    // A mean pressure of 1e-4 E at the lower end of the lengths (the other semi-axis 2 a)
    // and 1e-9 E at the upper end (the other semi-axis a/2), so the load stays in range.
    for (a, b, ratio) in [(l.lo * IN, 2.0 * l.lo, 1e-4), (l.hi / IN, 0.5 * l.hi, 1e-9)] {
        let p = ratio * 2e11 * std::f64::consts::PI * a * b;
        expect_solved(&format!("semi-axes {a:e}, {b:e}"), &semi(a, b, p));
    }
    expect_refused("semi-axes 1e30", &semi(1e30, 1e30, 1.0), "geometry.semi_axes");
}

#[test]
fn friction_at_both_ends() {
    let f = ranges::FRICTION;
    let p = sphere_load(1e-2, 2e11, 0.01);
    for mu in [0.0, f.lo * IN, f.hi / IN] {
        expect_solved(&format!("f = {mu:e}"), &sphere(1e-2, 2e11, p, mu, 0.5 * mu * p));
    }
    for mu in [f.lo / OUT, f.hi * OUT, 1e300, 5e-324] {
        expect_refused(&format!("f = {mu:e}"), &sphere(1e-2, 2e11, p, mu, 0.0), "load.friction");
    }
}

/// A viscoelastic cylinder rolling on its own material (Goryacheva), with times `alpha`,
/// `beta` and speed `w`.
fn visco(alpha: f64, beta: f64, w: f64) -> String {
    format!(
        "[geometry]\nkind = \"cylinder\"\nradius = 0.05\n[substrate]\nmodel = \"viscoelastic\"\ne = 5e6\nnu = 0.49\nalpha = {alpha:e}\nbeta = {beta:e}\n[indenter]\nmodel = \"same\"\n[load]\nnormal = 1000\nfriction = 0.8\n[motion]\nspeed = {w:e}\ncreep = 0.0176\n"
    )
}

#[test]
fn times_and_speeds_at_both_ends() {
    let (t, s) = (ranges::TIME, ranges::SPEED);
    expect_solved("times lo", &visco(t.lo * 100.0, t.lo * IN, 1e-2));
    expect_solved("times hi", &visco(t.hi / IN, t.hi / 100.0, 1e-2));
    expect_solved("speed lo", &visco(1e-4, 1e-6, s.lo * IN));
    expect_solved("speed hi", &visco(1e-4, 1e-6, s.hi / IN));
    expect_refused("beta below", &visco(1e-4, t.lo / OUT, 1e-2), "substrate.beta");
    expect_refused("alpha above", &visco(t.hi * OUT, 1e-6, 1e-2), "substrate.alpha");
    expect_refused("speed below", &visco(1e-4, 1e-6, s.lo / OUT), "motion.speed");
    expect_refused("speed above", &visco(1e-4, 1e-6, s.hi * OUT), "motion.speed");
}

#[test]
fn contact_size_over_radius_at_both_ends() {
    let (lo, hi) = CONTACT_OVER_RADIUS;
    let (r, e) = (1e-2, 2e11);
    for ratio in [lo * IN, hi / IN] {
        let p = sphere_load(r, e, ratio);
        expect_solved(&format!("a/R = {ratio:e}"), &sphere(r, e, p, 0.3, 0.5 * 0.3 * p));
    }
    for ratio in [lo / OUT, hi * OUT] {
        let p = sphere_load(r, e, ratio);
        expect_refused(&format!("a/R = {ratio:e}"), &sphere(r, e, p, 0.3, 0.0), "load.normal");
    }
    // A cylinder: P' = pi E* a^2 / (4 R).
    let es = e / (2.0 * 0.91);
    let line = |ratio: f64| std::f64::consts::PI * es * (ratio * r).powi(2) / (4.0 * r);
    for ratio in [lo * IN, hi / IN] {
        expect_solved(&format!("cylinder a/R = {ratio:e}"), &cylinder(r, e, line(ratio)));
    }
    for ratio in [lo / OUT, hi * OUT] {
        expect_refused(
            &format!("cylinder a/R = {ratio:e}"),
            &cylinder(r, e, line(ratio)),
            "load.normal",
        );
    }
}

#[test]
fn mean_pressure_over_modulus_at_both_ends() {
    let (lo, hi) = PRESSURE_OVER_MODULUS;
    // A flat punch in 2D (half-width b): the mean pressure is P/(2 b); E* of a rigid
    // punch on E = 1e9, nu = 0.3.
    let es = 1e9 / 0.91;
    let punch = |ratio: f64| {
        format!(
            "[geometry]\nkind = \"punch\"\nhalf_width = 0.01\n[substrate]\ne = 1e9\nnu = 0.3\n[load]\nnormal = {:e}\n",
            ratio * es * 0.02
        )
    };
    for ratio in [lo * IN, hi / IN] {
        expect_solved(&format!("punch p/E* = {ratio:e}"), &punch(ratio));
    }
    for ratio in [lo / OUT, hi * OUT] {
        expect_refused(&format!("punch p/E* = {ratio:e}"), &punch(ratio), "load.normal");
    }
}

#[test]
fn a_graded_roller_with_a_subnormal_load_is_refused() {
    let src = "[geometry]\nkind = \"cylinder\"\nradius = 0.3\n[substrate]\nmodel = \"graded\"\nk = 0.1\ne0 = \"1767600 kgf/m^2.1\"\nnu = 0.3\n[load]\nnormal = 5e-324\n";
    expect_refused("graded 5e-324 N/m", src, "load.normal");
    // Just inside the load range, the graded contact is too small against its radius.
    expect_refused("graded 1e-9 N/m", &src.replace("5e-324", "1e-9"), "load.normal");
    expect_solved("graded 10 kN/m", &src.replace("5e-324", "1e4"));
}

#[test]
fn subnormal_numbers_are_refused_wherever_they_are_written() {
    let p = sphere_load(1e-2, 2e11, 0.01);
    let base = sphere(1e-2, 2e11, p, 0.3, 0.0);
    expect_refused(
        "subnormal tangential",
        &base.replace("tangential = 0e0", "tangential = 1e-310"),
        "load.tangential",
    );
    expect_refused(
        "subnormal direction",
        &base.replace("tangential = 0e0", "direction_deg = 1e-310"),
        "load.direction_deg",
    );
    expect_refused(
        "subnormal moment",
        &base.replace("tangential = 0e0", "moment = 4e-320"),
        "load.moment",
    );
}

/// A small deterministic generator (SplitMix64), so the test is the same on every run.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    /// A magnitude log-uniform over all of f64's range, subnormals included.
    fn magnitude(&mut self) -> f64 {
        let u = (self.next() >> 11) as f64 / (1u64 << 53) as f64;
        10f64.powf(-323.0 + u * (308.0 + 323.0))
    }
    /// A magnitude log-uniform over [10^lo, 10^hi].
    fn within(&mut self, lo: f64, hi: f64) -> f64 {
        let u = (self.next() >> 11) as f64 / (1u64 << 53) as f64;
        10f64.powf(lo + u * (hi - lo))
    }
}

#[test]
fn random_magnitudes_are_solved_or_refused_with_exit_2_never_3_never_a_panic() {
    let mut rng = Rng(33);
    let t0 = std::time::Instant::now();
    let (mut solved, mut refused) = (0, 0);
    for i in 0..2000 {
        // Half the draws over all of f64, half near the accepted ranges, so both outcomes
        // are exercised.
        let wide = i % 2 == 0;
        let mut draw = |lo: f64, hi: f64| if wide { rng.magnitude() } else { rng.within(lo, hi) };
        let (r, e, f) = (draw(-9.5, 4.5), draw(-0.5, 13.5), draw(-6.5, 1.2));
        // Near the ranges, the load follows from a dimensionless contact size drawn around
        // its accepted range (a/R for the sphere and the cylinder, p/E* for the punch).
        let s = draw(-6.5, -0.3);
        let es = e / (2.0 * 0.91);
        let kind = i % 4;
        let p = if wide {
            rng.magnitude()
        } else {
            match kind {
                0 | 1 => 4.0 * es * (s * r).powi(3) / (3.0 * r),
                2 => std::f64::consts::PI * es * (s * r).powi(2) / (4.0 * r),
                _ => s * 1e-6 * 2.0 * r * e / 0.91,
            }
        };
        let src = match kind {
            0 | 1 => sphere(r, e, p, f, 0.5 * f * p),
            2 => cylinder(r, e, p),
            _ => format!(
                "[geometry]\nkind = \"punch\"\nhalf_width = {r:e}\n[substrate]\ne = {e:e}\nnu = 0.3\n[load]\nnormal = {p:e}\nfriction = {f:e}\n"
            ),
        };
        let res = std::panic::catch_unwind(|| solve(&src));
        match res {
            Err(_) => panic!("panic on\n{src}"),
            Ok(Ok(out)) => {
                assert!(out.audit.checks.iter().all(|c| c.pass), "audit on\n{src}");
                solved += 1;
            }
            Ok(Err(e)) => {
                assert_eq!(e.exit_code(), 2, "exit {} on\n{src}\n{e}", e.exit_code());
                refused += 1;
            }
        }
    }
    println!(
        "random magnitudes: {solved} solved, {refused} refused in {:.2} s",
        t0.elapsed().as_secs_f64()
    );
    assert!(solved > 400 && refused > 400, "{solved} solved, {refused} refused");
}

/// One square patch of side 1 cm at pressure `p` on a body of modulus `e`, with a tangential
/// force of a quarter of what friction carries.
fn patch(p: f64, e: f64) -> String {
    let f = 0.3;
    let t = 0.25 * f * p * 1e-4;
    format!(
        "[geometry]\nkind = \"patches\"\npatches = [{{ shape = \"square\", centre = [0.0, 0.0], side = 0.01, pressure = {p:e} }}]\n[substrate]\ne = {e:e}\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\ntangential = {t:e}\nfriction = {f}\n[solver]\ngrid = 8\n"
    )
}

#[test]
fn patch_pressures_at_both_ends() {
    let (p, e) = (ranges::PRESSURE, ranges::MODULUS);
    // The low end on the softest body allowed.
    expect_solved("pressure lo", &patch(p.lo * IN, e.lo * IN));
    // The high end: 1e12 Pa is more than a tenth of the stiffest composite modulus allowed
    // (E* = 1e13 / (2 (1 - nu^2)) = 5.5e12 Pa), so just inside the pressure's own range it
    // is the combination p/E* that refuses it, at the load's key, not the pressure's range;
    // a tenth of E* below that is solved.
    let es_max = e.hi / IN / (2.0 * (1.0 - 0.09));
    expect_solved("pressure 0.09 E*max", &patch(0.09 * es_max, e.hi / IN));
    match solve(&patch(p.hi / IN, e.hi / IN)) {
        Ok(_) => {
            panic!("p = 1e12 Pa on E = 1e13 Pa solved: p/E* = 0.18 is beyond linear elasticity")
        }
        Err(err) => {
            assert_eq!(err.exit_code(), 2, "{err}");
            assert!(err.to_string().contains("dimensionless size"), "{err}");
        }
    }
    let key = "geometry.patches[0].pressure";
    expect_refused("pressure below", &patch(p.lo / OUT, e.lo * IN), key);
    expect_refused("pressure above", &patch(p.hi * OUT, e.hi / IN), key);
    expect_refused("pressure 5e-324", &patch(5e-324, 2e11), key);
}

/// A sphere of radius `r` and modulus `e` pressed by `p`, twisted by `m`, friction `f`.
fn twisted(r: f64, e: f64, p: f64, f: f64, m: f64) -> String {
    format!(
        "[geometry]\nkind = \"sphere\"\nradius = {r:e}\n[substrate]\ne = {e:e}\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = {p:e}\nfriction = {f:e}\nmoment = {m:e}\n"
    )
}

#[test]
fn moments_at_both_ends() {
    let m = ranges::MOMENT;
    // Low end: a micrometre sphere at a nanonewton; the full-slip moment (3 pi/16) f P a is
    // about 2e-18 N m, far above 1e-21 N m.
    expect_solved("moment lo", &twisted(1e-6, 1e9, 1e-9, 0.3, m.lo * IN));
    // High end: a 10 km sphere of a soft solid (E = 1 MPa) under 1e12 N: a = 2.4 km
    // (a/R = 0.24) and the full-slip moment at f = 10 is 1.4e16 N m, above 1e16 N m.
    let f = ranges::FRICTION.hi / IN;
    expect_solved("moment hi", &twisted(1e4, 1e6, 1e12, f, m.hi / IN));
    expect_refused("moment below", &twisted(1e-6, 1e9, 1e-9, 0.3, m.lo / OUT), "load.moment");
    expect_refused("moment above", &twisted(1e4, 1e6, 1e12, f, m.hi * OUT), "load.moment");
    expect_refused("moment 5e-324", &twisted(1e-2, 2e11, 100.0, 0.3, 5e-324), "load.moment");
}

/// A steel cylinder (2D, Carter) rolling with creep ratio `c`.
fn carter(c: f64) -> String {
    format!(
        "[geometry]\nkind = \"cylinder\"\nradius = 0.46\n[substrate]\ne = 2.1e11\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = 5e5\nfriction = 0.3\n[motion]\nkind = \"rolling\"\nspeed = 20\ncreep = {c:e}\n"
    )
}

/// An ellipsoid rolling in 3D with creepages (xi, eta, spin).
fn rolling3d(xi: f64, eta: f64, spin: f64) -> String {
    format!(
        "[geometry]\nkind = \"ellipsoid\"\nradii = [0.46, 0.3]\n[substrate]\ne = 2.1e11\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = 1e5\nfriction = 0.3\n[motion]\nkind = \"rolling\"\nspeed = 20\ncreepage = {{ longitudinal = {xi:e}, lateral = {eta:e}, spin = {spin:e} }}\n[solver]\nmethod = \"fastsim\"\n"
    )
}

#[test]
fn creep_at_both_ends() {
    let c = ranges::CREEP;
    for v in [0.0, c.lo * IN, -c.lo * IN, c.hi / IN, -c.hi / IN] {
        expect_solved(&format!("creep {v:e}"), &carter(v));
    }
    for v in [c.lo / OUT, c.hi * OUT, 1e300, 5e-324] {
        expect_refused(&format!("creep {v:e}"), &carter(v), "motion.creep");
    }
    for v in [c.lo * IN, c.hi / IN] {
        expect_solved(&format!("creepage {v:e}"), &rolling3d(v, 0.0, 0.0));
        expect_solved(&format!("lateral creepage {v:e}"), &rolling3d(0.0, -v, 0.0));
    }
    expect_refused(
        "creepage below",
        &rolling3d(c.lo / OUT, 0.0, 0.0),
        "motion.creepage.longitudinal",
    );
    expect_refused("creepage above", &rolling3d(0.0, c.hi * OUT, 0.0), "motion.creepage.lateral");
    expect_refused("spin above", &rolling3d(0.0, 0.0, c.hi * OUT), "motion.creepage.spin");
}

/// Issue 33 item 2: a refusal writes its quantities in engineering units (four significant
/// digits, an SI prefix per value), and the planner's reasons do too.
#[test]
fn refusals_and_reasons_are_written_in_engineering_units() {
    let e = solve(&sphere(1e-2, 1.7e308, 100.0, 0.3, 0.0)).unwrap_err();
    let msg = e.to_string();
    assert!(msg.contains("1.700e308 Pa") && msg.contains("1.000 Pa to 10.00 TPa"), "{msg}");
    let e = solve(&twisted(1e-2, 2e11, 100.0, 0.3, 1e3)).unwrap_err();
    assert!(e.to_string().contains("|M| = 1.000 kN m exceeds"), "{e}");
    let s = Scene::from_toml_str(&twisted(1e-2, 2e11, 100.0, 0.3, 2.5e-3), None).unwrap();
    let plan = stickslip_run::Plan::new(&s).unwrap();
    assert!(plan.explain().contains("moment M = 2.500 mN m"), "{}", plan.explain());
    // Gross slip found by a grid solver (the normal force follows from an approach, so the
    // planner cannot see it): the load and the capacity with their units.
    let src = "[geometry]\nkind = \"surface\"\nsize = [\"2 mm\", \"2 mm\"]\ncells = [64, 64]\n[geometry.profile]\nshape = \"sphere\"\nradius = \"10 mm\"\n[substrate]\ne = \"200 GPa\"\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\napproach = \"1 um\"\nfriction = 0.3\ntangential = \"10 N\"\n";
    let e = solve(src).unwrap_err();
    let msg = e.to_string();
    assert!(msg.contains("tangential force 10.00 N exceeds the friction capacity 4.4"), "{msg}");
    assert_eq!(e.key.as_deref(), Some("load.tangential"), "{e}");
}
