//! 3D subsurface fields from scenes: `[outputs] field = { x, y, z, scale }` on a box of
//! points, by the Hertz sphere's closed form or by FFT of the lattice traction, checked
//! against closed forms; refusals for boxes that make no sense; field.csv columns and the
//! .npy arrays of large boxes.

use stickslip_run::{run, Outcome, RunOptions};
use stickslip_scene::{ErrorKind, Scene};

const SPHERE: &str = "[geometry]\nkind = \"sphere\"\nradius = \"10 mm\"\n[substrate]\nmodel = \"homogeneous\"\ne = \"210 GPa\"\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = \"100 N\"\nLOAD\n[outputs]\nfield = FIELD\n[solver]\nSOLVER\n";

#[allow(clippy::result_large_err)]
fn go(load: &str, field: &str, solver: &str) -> Result<Outcome, stickslip_scene::SceneError> {
    let src = SPHERE.replace("LOAD", load).replace("FIELD", field).replace("SOLVER", solver);
    run(&Scene::from_toml_str(&src, Some("f.toml".into()))?, &RunOptions::default())
}

const AXIS: &str = "{ x = [0, 0, 1], y = [0, 0, 1], z = [0.05, 3.0, 60], scale = \"a\" }";

/// sigma_z on the axis of a Hertz sphere, -p0 / (1 + z^2/a^2) (Johnson eq. 3.45).
fn axis_error(out: &Outcome) -> f64 {
    let v = out.field.volume().expect("a volume field");
    let vals = v.values.as_ref().unwrap();
    let (a, p0) = (out.contact.a, out.contact.p0);
    v.z.iter()
        .zip(&vals.szz)
        .map(|(z, s)| (s + p0 / (1.0 + (z / a).powi(2))).abs() / p0)
        .fold(0.0, f64::max)
}

#[test]
fn the_closed_form_and_the_lattice_agree_with_johnson_on_the_axis() {
    let closed = go("", AXIS, "grid = 32").unwrap();
    assert!(closed.field.volume().unwrap().method.contains("closed form"));
    assert!(axis_error(&closed) < 1e-12, "{}", axis_error(&closed));
    // The lattice (the fast solver's path) at 128 cells across: within 0.5 % of p0.
    let lattice = go("", AXIS, "grid = 128\nmethod = \"fast\"").unwrap();
    assert!(lattice.field.volume().unwrap().method.contains("lattice"));
    let err = axis_error(&lattice);
    assert!(err < 5e-3, "lattice on the axis: {err}");
    println!(
        "Hertz sphere, sigma_z on the axis: closed form exact, lattice (128 across) {err:.2e} p0"
    );
}

#[test]
fn the_maximum_shear_is_031_p0_at_048_a() {
    let out =
        go("", "{ x = [0, 0, 1], y = [0, 0, 1], z = [0.3, 0.7, 41], scale = \"a\" }", "grid = 32")
            .unwrap();
    let m = out.field.volume().unwrap().max.tresca;
    let (a, p0) = (out.contact.a, out.contact.p0);
    assert!((m.value / p0 - 0.31).abs() < 0.005, "{}", m.value / p0);
    assert!((m.z / a - 0.48).abs() < 0.011, "{}", m.z / a);
}

#[test]
fn sliding_puts_the_tensile_peak_at_the_trailing_edge() {
    // Mindlin under T = 0.5 f P along +x: the traction on the substrate drags it along +x,
    // so the surface tension peaks behind the contact (x < 0), near x = -a.
    let out = go(
        "tangential = \"10 N\"\nfriction = 0.2",
        "{ x = [-1.5, 1.5, 61], y = [0, 0, 1], z = [0.02, 1.0, 10], scale = \"a\" }",
        "grid = 64",
    )
    .unwrap();
    let m = out.field.volume().unwrap().max.max_principal;
    let a = out.contact.a;
    assert!(m.value > 0.0, "{m:?}");
    assert!(m.x < -0.8 * a && m.x > -1.2 * a, "peak at x/a = {}", m.x / a);
    assert!(out.audit.passed);
}

#[test]
fn boxes_that_make_no_sense_are_refused_with_their_key() {
    let cases = [
        ("{ x = [-1, 1, 11], y = [0, 0, 1], z = [0.0, 1.0, 5] }", "outputs.field.z"),
        ("{ x = [-1, 1, 11], y = [0, 0, 1], z = [-0.5, 1.0, 5] }", "outputs.field.z"),
        ("{ x = [-1, 1, 11], y = [0, 0, 1] }", "outputs.field"),
        ("{ x = [-50, 1, 11], y = [0, 0, 1], z = [0.1, 1.0, 5] }", "outputs.field.x"),
        ("{ x = [-1, 1, 11], y = [0, 0, 1], z = [0.1, 40.0, 5] }", "outputs.field.z"),
        ("{ x = [1, -1, 11], y = [0, 0, 1], z = [0.1, 1.0, 5] }", "outputs.field.x"),
    ];
    for (field, key) in cases {
        let e = go("", field, "grid = 16").unwrap_err();
        assert_eq!(e.key.as_deref(), Some(key), "{field}: {e}");
        assert!(e.position.is_some() && e.hint.is_some(), "{field}: {e}");
        assert!(matches!(e.kind, ErrorKind::OutOfRange | ErrorKind::Schema), "{field}: {e}");
    }
}

/// Largest |closed - lattice| over the box points at depth >= `zmin` (units of a) and all six
/// components, in units of p0; and the difference of the tensile peaks.
fn field_gap(closed: &Outcome, lattice: &Outcome, zmin: f64) -> (f64, f64) {
    let (c, l) = (closed.field.volume().unwrap(), lattice.field.volume().unwrap());
    let (cv, lv) = (c.values.as_ref().unwrap(), l.values.as_ref().unwrap());
    let p0 = closed.contact.p0;
    let pairs = [
        (&cv.sxx, &lv.sxx),
        (&cv.syy, &lv.syy),
        (&cv.szz, &lv.szz),
        (&cv.sxy, &lv.sxy),
        (&cv.sxz, &lv.sxz),
        (&cv.syz, &lv.syz),
    ];
    let (nx, ny, a) = (c.x.len(), c.y.len(), closed.contact.a);
    let worst = pairs
        .iter()
        .flat_map(|(u, w)| u.iter().zip(w.iter()).enumerate())
        .filter(|(i, _)| c.z[i / (nx * ny)] >= zmin * a * (1.0 - 1e-12))
        .map(|(_, (x, y))| (x - y).abs() / p0)
        .fold(0.0, f64::max);
    let peak = (c.max.max_principal.value - l.max.max_principal.value).abs() / p0;
    (worst, peak)
}

#[test]
fn the_sliding_sphere_uses_hamiltons_field_and_the_lattice_agrees_within_1_percent() {
    // x-z section through the contact down to 1.5 a, including the trailing edge x = -a at
    // z = 0.02 a where the surface tension peaks.
    let section = "{ x = [-1.5, 1.5, 31], y = [0, 0, 1], z = [0.02, 1.5, 16], scale = \"a\" }";
    for f in [0.25, 0.5] {
        let load = format!("sliding = true\nfriction = {f}");
        let closed = go(&load, section, "grid = 32").unwrap();
        let v = closed.field.volume().unwrap();
        assert!(v.method.contains("Hamilton"), "{}", v.method);
        // the tensile peak sits at the trailing edge; its value is the library's field there
        // (the approach to the surface value, like sqrt(z/a), is checked in the halfspace
        // crate's tests: at z = 0.02 a it is about half of it)
        let m = v.max.max_principal;
        let (a, p0) = (closed.contact.a, closed.contact.p0);
        assert!((m.x / a + 1.0).abs() < 0.11 && m.z / a < 0.03, "peak at {m:?}");
        let lib = stickslip_halfspace::hertz::ellipse_field::HertzLoadField::new(a, a, p0, f, 0.3)
            .unwrap()
            .stress(m.x, m.y, m.z)
            .unwrap()
            .stress;
        let sxx_surface =
            stickslip_halfspace::hertz::sphere_field::sliding_trailing_edge_tension(p0, 0.3, f);
        println!(
            "f = {f}: peak max principal {:.4} p0 at x = {:.2} a, z = {:.2} a (sigma_xx there {:.4} p0; surface value {:.4} p0)",
            m.value / p0,
            m.x / a,
            m.z / a,
            lib.xx / p0,
            sxx_surface / p0
        );
        assert!(m.value >= lib.xx * (1.0 - 1e-12), "{} vs sigma_xx {}", m.value, lib.xx);
        let lattice = go(&load, section, "grid = 128\nmethod = \"fast\"").unwrap();
        assert!(lattice.field.volume().unwrap().method.contains("lattice"));
        // The lattice's cells are 2a/128 = 0.016 a: at z = 0.02 a (about one cell) its
        // piecewise-constant pressure edge leaves up to 1.4 % of p0 in sigma_zz at x = -a;
        // from z = 0.118 a (the second layer, 7.5 cells) down all six components agree within
        // 1 %. The tensile peak (at z = 0.02 a) agrees within 1 %.
        let (all, peak) = field_gap(&closed, &lattice, 0.0);
        let (deep, _) = field_gap(&closed, &lattice, 0.1);
        println!(
            "sliding sphere f = {f}: lattice (128 across) vs Hamilton, max |diff| {all:.2e} p0 over the section, {deep:.2e} p0 below z = 0.1 a, tensile peak {peak:.2e} p0"
        );
        assert!(deep < 0.01 && peak < 0.01, "f = {f}: {deep} {peak}");
        assert!(all < 0.015, "f = {f}: {all}");
        // Twice finer (z = 0.02 a is 2.6 cells deep): within 1 % everywhere on the section.
        let fine = go(&load, section, "grid = 256\nmethod = \"fast\"").unwrap();
        let (all, peak) = field_gap(&closed, &fine, 0.0);
        println!(
            "sliding sphere f = {f}: lattice (256 across) vs Hamilton, max |diff| {all:.2e} p0 over the section, tensile peak {peak:.2e} p0"
        );
        assert!(all < 0.01 && peak < 0.01, "f = {f}: {all} {peak}");
    }
}

#[test]
fn the_frictionless_ellipse_uses_its_field_and_the_lattice_agrees_within_1_percent() {
    let src = |solver: &str| {
        format!(
            "[geometry]\nkind = \"ellipsoid\"\nsemi_axes = [\"2 mm\", \"1 mm\"]\n[substrate]\nmodel = \"homogeneous\"\ne = \"210 GPa\"\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = \"500 N\"\n[outputs]\nfield = {{ x = [-1.5, 1.5, 31], y = [0, 0, 1], z = [0.02, 1.5, 16], scale = \"a\" }}\n[solver]\n{solver}\n"
        )
    };
    let run_it = |solver: &str| {
        run(
            &Scene::from_toml_str(&src(solver), Some("e.toml".into())).unwrap(),
            &RunOptions::default(),
        )
        .unwrap()
    };
    let closed = run_it("grid = 32");
    let v = closed.field.volume().unwrap();
    assert!(v.method.contains("ellipse"), "{}", v.method);
    // (the field itself is checked against point-force quadrature and the sphere's closed
    // form in the halfspace crate's tests/hertz_load_field.rs)
    let lattice = run_it("grid = 128\nmethod = \"fast\"");
    assert!(lattice.field.volume().unwrap().method.contains("lattice"));
    let (all, _) = field_gap(&closed, &lattice, 0.0);
    let (deep, _) = field_gap(&closed, &lattice, 0.1);
    println!(
        "Hertz ellipse b/a = 0.5: lattice (128 across) vs the ellipse field, max |diff| {all:.2e} p0 over the x-z section, {deep:.2e} p0 below z = 0.1 a"
    );
    assert!(deep < 0.01, "{deep}");
    assert!(closed.audit.passed);
}

#[test]
fn box_ends_may_be_lengths_with_units_when_the_scale_is_metres() {
    let numbers = go(
        "",
        "{ x = [-0.0003, 0.0003, 7], y = [0, 0, 1], z = [0.00002, 0.0004, 5], scale = \"m\" }",
        "grid = 16",
    )
    .unwrap();
    let units = go(
        "",
        "{ x = [\"-0.3 mm\", \"300 um\", 7], y = [0, 0, 1], z = [\"20 um\", \"0.4 mm\", 5], scale = \"m\" }",
        "grid = 16",
    )
    .unwrap();
    let (n, u) = (numbers.field.volume().unwrap(), units.field.volume().unwrap());
    for (p, q) in n.x.iter().zip(&u.x).chain(n.z.iter().zip(&u.z)) {
        assert!((p - q).abs() <= 1e-15 * p.abs().max(1e-6), "{p} vs {q}");
    }
    assert_eq!(n.values.as_ref().unwrap().szz.len(), u.values.as_ref().unwrap().szz.len());
    // a unit in multiples of a, a count with a unit, a unit that is not a length
    let cases = [
        (
            "{ x = [\"-1 mm\", 1, 11], y = [0, 0, 1], z = [0.1, 1.0, 5], scale = \"a\" }",
            "outputs.field.x",
            ErrorKind::Unit,
        ),
        (
            "{ x = [-1, 1, \"11\"], y = [0, 0, 1], z = [0.1, 1.0, 5] }",
            "outputs.field.x",
            ErrorKind::OutOfRange,
        ),
        (
            "{ x = [-0.001, 0.001, 11], y = [0, 0, 1], z = [\"0.1 N\", \"1 mm\", 5], scale = \"m\" }",
            "outputs.field.z",
            ErrorKind::Unit,
        ),
    ];
    for (field, key, kind) in cases {
        let e = go("", field, "grid = 16").unwrap_err();
        assert_eq!(e.key.as_deref(), Some(key), "{field}: {e}");
        assert_eq!(e.kind, kind, "{field}: {e}");
        assert!(e.position.is_some() && e.hint.is_some(), "{field}: {e}");
    }
}

#[test]
fn a_sliding_ellipse_at_30_degrees_superposes_two_shears_and_the_lattice_agrees() {
    // b/a = 0.5, shear f p at 30 degrees: the x-shear on the ellipse plus the y-shear as the
    // x-shear of the swapped ellipse turned by 90 degrees. An off-axis section (y = 0.3 a)
    // so that every component is non-zero.
    let src = |solver: &str| {
        format!(
            "[geometry]\nkind = \"ellipsoid\"\nsemi_axes = [\"2 mm\", \"1 mm\"]\n[substrate]\nmodel = \"homogeneous\"\ne = \"210 GPa\"\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = \"500 N\"\nsliding = true\nfriction = 0.3\ndirection_deg = 30\n[outputs]\nfield = {{ x = [-1.5, 1.5, 31], y = [0.3, 0.3, 1], z = [0.02, 1.5, 16], scale = \"a\" }}\n[solver]\n{solver}\n"
        )
    };
    let run_it = |solver: &str| {
        run(
            &Scene::from_toml_str(&src(solver), Some("s.toml".into())).unwrap(),
            &RunOptions::default(),
        )
        .unwrap()
    };
    let closed = run_it("grid = 32");
    let v = closed.field.volume().unwrap();
    assert!(v.method.contains("sliding Hertz ellipse"), "{}", v.method);
    let lattice = run_it("grid = 128\nmethod = \"fast\"");
    let (all, peak) = field_gap(&closed, &lattice, 0.0);
    let (deep, _) = field_gap(&closed, &lattice, 0.1);
    println!(
        "sliding ellipse b/a = 0.5, f = 0.3 at 30 deg: lattice (128 across) vs the superposed field, max |diff| {all:.2e} p0 on the section y = 0.3 a, {deep:.2e} p0 below z = 0.1 a, tensile peak {peak:.2e} p0"
    );
    assert!(deep < 0.01 && peak < 0.01, "{deep} {peak}");
}

#[test]
fn a_sphere_sliding_at_30_degrees_turns_hamiltons_field() {
    let section = "{ x = [-1.5, 1.5, 31], y = [0.3, 0.3, 1], z = [0.02, 1.5, 16], scale = \"a\" }";
    let load = "sliding = true\nfriction = 0.5\ndirection_deg = 30";
    let closed = go(load, section, "grid = 32").unwrap();
    assert!(closed.field.volume().unwrap().method.contains("sliding Hertz sphere"));
    let lattice = go(load, section, "grid = 128\nmethod = \"fast\"").unwrap();
    let (all, peak) = field_gap(&closed, &lattice, 0.0);
    let (deep, _) = field_gap(&closed, &lattice, 0.1);
    println!(
        "sliding sphere f = 0.5 at 30 deg: lattice (128 across) vs Hamilton turned, max |diff| {all:.2e} p0 on y = 0.3 a, {deep:.2e} p0 below z = 0.1 a, tensile peak {peak:.2e} p0"
    );
    assert!(deep < 0.01 && peak < 0.01, "{deep} {peak}");
}
