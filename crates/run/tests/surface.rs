//! Scenes of any surface (`geometry.kind = "surface"`): the normal-contact solver on the
//! lattice against Hertz and Westergaard, force and displacement control, roughness files,
//! partial slip on the computed contact, and the refusals of what is not solved.

use std::f64::consts::PI;

use stickslip_run::{run, Execute, Outcome, RunOptions};
use stickslip_scene::{ErrorKind, Scene};

const BASE: &str = "[geometry]\nkind = \"surface\"\nBOUNDARY\nsize = [\"0.8 mm\", \"0.8 mm\"]\ncells = [128, 128]\n[geometry.profile]\nPROFILE\nROUGH\n[substrate]\nmodel = \"homogeneous\"\ne = \"210 GPa\"\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nLOAD\n";

const SPHERE: &str = "shape = \"sphere\"\nradius = \"10 mm\"";

#[allow(clippy::result_large_err)]
fn go(
    boundary: &str,
    profile: &str,
    rough: &str,
    load: &str,
) -> Result<Outcome, stickslip_scene::SceneError> {
    let src = BASE
        .replace("BOUNDARY", boundary)
        .replace("PROFILE", profile)
        .replace("ROUGH", rough)
        .replace("LOAD", load);
    let dir = std::env::temp_dir();
    run(&Scene::from_toml_str(&src, Some(dir.join("s.toml")))?, &RunOptions::default())
}

/// E* of steel on steel.
fn e_star() -> f64 {
    210e9 / (2.0 * (1.0 - 0.3 * 0.3))
}

#[test]
fn a_sphere_given_as_a_surface_is_hertz() {
    let out = go("", SPHERE, "", "normal = \"10 N\"").unwrap();
    let (p, r) = (10.0, 0.01);
    let a = (3.0 * p * r / (4.0 * e_star())).cbrt();
    let p0 = 3.0 * p / (2.0 * PI * a * a);
    let h = 0.8e-3 / 128.0;
    let c = &out.contact;
    assert!((c.a - a).abs() <= h, "a = {} vs {a} (cell {h})", c.a);
    assert!((c.p0 - p0).abs() <= 0.01 * p0, "p0 {} vs {p0}", c.p0);
    let delta = a * a / r;
    let d = c.indentation.unwrap();
    assert!((d - delta).abs() <= 0.005 * delta, "approach {d} vs {delta}");
    assert!((c.area.unwrap() - PI * a * a).abs() <= 2.0 * PI * a * h, "area {:?}", c.area);
    assert!(out.audit.passed);
    // Displacement control at that approach gives the same force.
    let out2 = go("", SPHERE, "", &format!("approach = {d}")).unwrap();
    assert!((out2.forces.normal - 10.0).abs() <= 1e-6 * 10.0, "force {}", out2.forces.normal);
}

/// result.json's `solver` carries the normal solver's own figures for a surface (issue 30,
/// item 6): its record in `solver.normal`, and, with no grid solver after it, the top-level
/// iterations, residual, elements and solve time.
#[test]
fn the_normal_solver_reports_its_figures() {
    let out = go("", SPHERE, "", "normal = \"10 N\"").unwrap();
    let n = out.solver.normal.expect("solver.normal for a surface");
    println!("{n:?}");
    assert!(n.iterations > 0 && n.products >= n.iterations && n.preconditioner_products > 0);
    assert_eq!(n.levels, 2, "128 -> 64 -> 32");
    assert!(n.coarse_iterations > 0);
    assert!(n.residual > 0.0 && n.residual <= 1e-10);
    assert_eq!(n.steps, 1);
    assert!(n.solve_seconds > 0.0 && n.setup_seconds > 0.0);
    let s = &out.solver;
    assert_eq!((s.iterations, s.inner_iterations), (n.iterations, n.products));
    assert_eq!(s.residual, n.residual);
    assert_eq!(s.elements, 128 * 128);
    assert!(s.solve_seconds >= n.solve_seconds);
    // With a grid solver after it, the top level is the grid solver's; the record stays.
    let out =
        go("", SPHERE, "", "normal = \"10 N\"\ntangential = \"1 N\"\nfriction = 0.3").unwrap();
    let n2 = out.solver.normal.expect("solver.normal for a surface");
    assert_eq!(n2.iterations, n.iterations);
    assert!(out.solver.elements < 128 * 128 && out.solver.inner_iterations > 0);
    assert!(out.solver.solve_seconds > n2.solve_seconds);
}

#[test]
fn partial_slip_on_the_computed_contact_follows_mindlin() {
    let out =
        go("", SPHERE, "", "normal = \"10 N\"\ntangential = \"1 N\"\nfriction = 0.2").unwrap();
    let g = out.zones.grid.unwrap();
    // Mindlin: stick radius a (1 - T/fP)^(1/3), so a stick area fraction (1 - 0.5)^(2/3).
    let want = 0.5f64.powf(2.0 / 3.0);
    assert!((g.stick_area_fraction - want).abs() < 0.03, "{} vs {want}", g.stick_area_fraction);
    assert!(out.audit.passed);
}

#[test]
fn partial_slip_on_a_periodic_surface_follows_mindlin_and_the_isolated_contact() {
    // The sphere's contact (about 0.17 mm across) in a 0.8 mm period: the images barely
    // act, so the stick zone is Mindlin's and close to the isolated contact's.
    let load = "normal = \"10 N\"\ntangential = \"1 N\"\nfriction = 0.2";
    let per = go("boundary = \"periodic\"", SPHERE, "", load).unwrap();
    let free = go("", SPHERE, "", load).unwrap();
    let (gp, gf) = (per.zones.grid.unwrap(), free.zones.grid.unwrap());
    let want = 0.5f64.powf(2.0 / 3.0);
    assert!((gp.stick_area_fraction - want).abs() < 0.03, "{} vs {want}", gp.stick_area_fraction);
    assert!(
        (gp.stick_area_fraction - gf.stick_area_fraction).abs() < 0.02,
        "periodic {} vs free {}",
        gp.stick_area_fraction,
        gf.stick_area_fraction
    );
    assert!(per.audit.passed);
    assert!((per.forces.tangential - 1.0).abs() < 1e-6, "{}", per.forces.tangential);
    assert!(per.notes.iter().any(|l| l.contains("periodic operator")), "{:?}", per.notes);
}

#[test]
fn a_periodic_wave_in_full_contact_carries_westergaards_pressure() {
    // Westergaard: full contact from p* = pi E* amplitude / wavelength; above it the pressure
    // is the mean plus p* cos.
    let (lambda, amp) = (0.8e-3, 0.05e-6);
    let pstar = PI * e_star() * amp / lambda;
    let mean = 1.5 * pstar;
    let load = mean * 0.8e-3 * 0.8e-3;
    let profile = format!("shape = \"wavy\"\nwavelength = {lambda}\namplitude = {amp}");
    let out = go("boundary = \"periodic\"", &profile, "", &format!("normal = {load}")).unwrap();
    let c = &out.contact;
    assert_eq!(c.fraction, Some(1.0), "full contact");
    assert!((c.p0 - (mean + pstar)).abs() <= 0.01 * pstar, "peak {} vs {}", c.p0, mean + pstar);
}

#[test]
fn a_roughness_file_is_added_to_the_profile() {
    let dir = std::env::temp_dir().join(format!("stickslip-surface-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // A flat (zero) roughness in um as CSV gives the smooth sphere's answer exactly.
    let mut csv = String::from("# heights in um\n");
    for _ in 0..128 {
        csv.push_str(&vec!["0"; 128].join(","));
        csv.push('\n');
    }
    std::fs::write(dir.join("flat.csv"), csv).unwrap();
    let file = dir.join("flat.csv");
    let rough = format!("[geometry.roughness]\nfile = \"{}\"\nunit = \"um\"", file.display());
    let smooth = go("", SPHERE, "", "normal = \"10 N\"").unwrap();
    let with = go("", SPHERE, &rough, "normal = \"10 N\"").unwrap();
    // (the solver's parallel sums make runs agree to its tolerance, not bit for bit)
    let (a, b) = (smooth.contact.p0, with.contact.p0);
    assert!((a - b).abs() <= 1e-9 * a, "{a} vs {b}");
    // A wrong shape is refused at the file key.
    std::fs::write(dir.join("short.csv"), "1,2,3\n").unwrap();
    let rough = format!("[geometry.roughness]\nfile = \"{}\"", dir.join("short.csv").display());
    let e = go("", SPHERE, &rough, "normal = \"10 N\"").unwrap_err();
    assert_eq!(e.key.as_deref(), Some("geometry.roughness.file"), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn what_is_not_solved_is_refused_with_its_key() {
    let cases = [
        (
            "",
            "shape = \"cylinder\"\nradius = \"10 mm\"\nlength = \"2 mm\"",
            "",
            "normal = \"10 N\"",
            "geometry.size",
            ErrorKind::OutOfRange,
        ),
        (
            "",
            "shape = \"cylinder\"\nradius = \"10 mm\"\nlength = \"0.6 mm\"\ncrown = \"5 um\"",
            "",
            "normal = \"10 N\"",
            "geometry.profile.end_radius",
            ErrorKind::Schema,
        ),
        (
            "",
            "shape = \"cylinder\"\nradius = \"10 mm\"\nlength = \"0.6 mm\"\ncrown = \"5 um\"\nend_radius = \"10 mm\"",
            "",
            "normal = \"10 N\"",
            "geometry.profile.crown",
            ErrorKind::OutOfRange,
        ),
        (
            "",
            SPHERE,
            "[geometry.roughness]\nhurst = 0.8",
            "normal = \"10 N\"",
            "geometry.roughness",
            ErrorKind::Schema,
        ),
        (
            "",
            SPHERE,
            "[geometry.roughness]\nhurst = 0.8\nrms_height = \"0.05 um\"\nk_high = 100",
            "normal = \"10 N\"",
            "geometry.roughness.k_high",
            ErrorKind::OutOfRange,
        ),
        (
            "",
            SPHERE,
            "[geometry.roughness]\nhurst = 1.5\nrms_height = \"0.05 um\"",
            "normal = \"10 N\"",
            "geometry.roughness.hurst",
            ErrorKind::OutOfRange,
        ),
        (
            "boundary = \"periodic\"",
            SPHERE,
            "",
            "normal = \"10 N\"\nmoment = \"1e-5 N m\"\nfriction = 0.2",
            "load.moment",
            ErrorKind::Unsupported,
        ),
        (
            "boundary = \"periodic\"",
            SPHERE,
            "",
            "normal = \"10 N\"\ntangential = \"1 N\"\nfriction = 0.2\n[solver]\nmethod = \"lp\"",
            "solver.method",
            ErrorKind::Unsupported,
        ),
        ("", SPHERE, "", "half_width = \"0.1 mm\"", "load.half_width", ErrorKind::Schema),
        ("", SPHERE, "", "approach = \"-1 um\"", "load.approach", ErrorKind::OutOfRange),
    ];
    for (b, p, r, l, key, kind) in cases {
        let e = go(b, p, r, l).unwrap_err();
        assert_eq!((e.key.as_deref(), e.kind), (Some(key), kind), "{e}");
        assert!(e.hint.is_some() && e.position.is_some(), "{e}");
    }
    // The approach is for surfaces only.
    let sphere = "[geometry]\nkind = \"sphere\"\nradius = 0.01\n[substrate]\nmodel = \"homogeneous\"\ne = 2e11\nnu = 0.3\n[load]\napproach = 1e-6\n";
    let e = Scene::from_toml_str(sphere, None).unwrap_err();
    assert_eq!(e.key.as_deref(), Some("load.approach"), "{e}");
}

#[test]
fn generated_roughness_is_reproducible_and_shrinks_the_contact() {
    let rough = "[geometry.roughness]\nhurst = 0.8\nrms_height = \"0.05 um\"\nk_low = 2\nk_rolloff = 4\nk_high = 32\nseed = 7";
    let a = go("", SPHERE, rough, "normal = \"10 N\"").unwrap();
    let b = go("", SPHERE, rough, "normal = \"10 N\"").unwrap();
    let smooth = go("", SPHERE, "", "normal = \"10 N\"").unwrap();
    // the same seed gives the same surface (the solver agrees to its tolerance)
    assert!((a.contact.p0 - b.contact.p0).abs() <= 1e-9 * a.contact.p0);
    // roughness concentrates the load: a smaller real area and a higher peak than Hertz
    assert!(a.contact.area.unwrap() < smooth.contact.area.unwrap());
    assert!(a.contact.p0 > smooth.contact.p0);
    assert!(a.audit.passed);
}

/// The scene of `go` with another indenter material.
#[allow(clippy::result_large_err)]
fn go_with(
    indenter: &str,
    cells: usize,
    load: &str,
) -> Result<(stickslip_run::Plan, Outcome), stickslip_scene::SceneError> {
    let src = BASE
        .replace("BOUNDARY", "")
        .replace("PROFILE", SPHERE)
        .replace("ROUGH", "")
        .replace("LOAD", load)
        .replace("cells = [128, 128]", &format!("cells = [{cells}, {cells}]"))
        .replace("model = \"same\"", indenter);
    let dir = std::env::temp_dir();
    let plan = stickslip_run::Plan::new(&Scene::from_toml_str(&src, Some(dir.join("s.toml")))?)?;
    let out = plan.execute(&RunOptions::default())?;
    Ok((plan, out))
}

const ALUMINIUM: &str = "model = \"homogeneous\"\ne = \"70 GPa\"\nnu = 0.33";

#[test]
fn dissimilar_bodies_are_solved_coupled_and_the_plan_says_so() {
    let tl = "normal = \"10 N\"\ntangential = \"1 N\"\nfriction = 0.2";
    let (plan, out) = go_with(ALUMINIUM, 64, tl).unwrap();
    let friction = plan.effects.iter().find(|e| e.effect == stickslip_run::Effect::Friction);
    let reason = &friction.unwrap().reason;
    assert!(reason.contains("Dundurs beta = -0.1167"), "{reason}");
    let c = out.solver.coupling.expect("coupling record in result.json");
    assert!(c.passes >= 2 && c.residual <= 1e-10, "{c:?}");
    assert!((c.beta + 0.116_735_969_636_926_87).abs() < 1e-12, "{c:?}");
    assert!(out.audit.passed);
    assert!((out.forces.tangential - 1.0).abs() < 1e-12);
    // The coupling moves the pressure: against the same bodies without a tangential load (no
    // traction, so no coupling), the peak pressure differs, by little (|beta| = 0.12).
    let (_, plain) = go_with(ALUMINIUM, 64, "normal = \"10 N\"").unwrap();
    assert!(plain.solver.coupling.is_none());
    let d = (out.contact.p0 - plain.contact.p0).abs() / plain.contact.p0;
    eprintln!("p0 coupled {:.6e}, uncoupled {:.6e}: {d:.3e}", out.contact.p0, plain.contact.p0);
    assert!(d > 1e-4 && d < 0.05, "relative change of p0 {d}");
}

#[test]
fn identical_bodies_take_the_uncoupled_route() {
    let tl = "normal = \"10 N\"\ntangential = \"1 N\"\nfriction = 0.2";
    let (plan, out) = go_with("model = \"same\"", 64, tl).unwrap();
    let friction = plan.effects.iter().find(|e| e.effect == stickslip_run::Effect::Friction);
    assert!(!friction.unwrap().reason.contains("Dundurs"));
    assert!(out.solver.coupling.is_none());
    assert!(!out.notes.iter().any(|n| n.contains("Dundurs")), "{:?}", out.notes);
}

#[test]
fn a_coupled_load_sweep_is_refused_with_its_key() {
    let tl = "normal = [\"1 N\", \"10 N\", 4]\ntangential = \"0.1 N\"\nfriction = 0.2";
    let e = go_with(ALUMINIUM, 64, tl).unwrap_err();
    assert_eq!((e.key.as_deref(), e.kind), (Some("load.normal"), ErrorKind::Unsupported), "{e}");
    assert!(e.hint.is_some(), "{e}");
}

/// A steel roller (R = 10 mm, L = 2 mm, axis along y) on a steel flat at P = 200 N
/// (P/L = 100 N/mm): lattice 0.4 mm x 2.2 mm, 64 x 176 cells (hx = 6.25 um, hy = 12.5 um).
/// Returns the pressure map p[i][j] (x index i, y index j) and the cell sides.
fn roller(crown: &str) -> (Vec<Vec<f64>>, f64, f64) {
    let src = format!(
        "[geometry]\nkind = \"surface\"\nsize = [\"0.4 mm\", \"2.2 mm\"]\ncells = [64, 176]\n[geometry.profile]\nshape = \"cylinder\"\nradius = \"10 mm\"\nlength = \"2 mm\"\n{crown}\n[substrate]\nmodel = \"homogeneous\"\ne = \"210 GPa\"\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = \"200 N\"\n[outputs]\nsurface = true\n"
    );
    let dir = std::env::temp_dir();
    let out =
        run(&Scene::from_toml_str(&src, Some(dir.join("r.toml"))).unwrap(), &RunOptions::default())
            .unwrap();
    assert!(out.audit.passed);
    let stickslip_run::SurfaceOut::Grid { p, .. } = out.surface else { panic!("no lattice") };
    (p, 0.4e-3 / 64.0, 2.2e-3 / 176.0)
}

#[test]
fn a_long_uncrowned_roller_is_hertz_line_contact_at_mid_length_with_edge_spikes() {
    let (p, hx, hy) = roller("");
    let (nx, ny) = (p.len(), p[0].len());
    // mid-length: the two rows either side of y = 0, averaged
    let mid: Vec<f64> = (0..nx).map(|i| 0.5 * (p[i][ny / 2 - 1] + p[i][ny / 2])).collect();
    let load_per_length: f64 = mid.iter().sum::<f64>() * hx;
    let r = 0.01;
    let e_star = e_star();
    let p0 = (load_per_length * e_star / (PI * r)).sqrt();
    let b = (4.0 * load_per_length * r / (PI * e_star)).sqrt();
    let peak = mid.iter().copied().fold(0.0, f64::max);
    // half-width from the cells in contact at mid-length
    let cells = mid.iter().filter(|v| **v > 0.0).count() as f64;
    eprintln!(
        "mid-length P' = {load_per_length:.4e} N/m (P/L = 1e5): p0 {peak:.5e} vs Hertz {p0:.5e} ({:.2e}); contact width {:.4e} vs 2b = {:.4e}",
        (peak - p0) / p0,
        cells * hx,
        2.0 * b
    );
    assert!((peak - p0).abs() <= 0.01 * p0);
    assert!((cells * hx - 2.0 * b).abs() <= 2.0 * hx);
    // the sharp ends carry more than their share: mid-length carries less than P/L
    assert!(load_per_length < 1e5);
    // the sharp ends: the centre line's pressure rises well above the mid-length value
    let centre: Vec<f64> = (0..ny).map(|j| 0.5 * (p[nx / 2 - 1][j] + p[nx / 2][j])).collect();
    let end = centre.iter().copied().fold(0.0, f64::max);
    eprintln!(
        "uncrowned: centre-line maximum {end:.4e} = {:.3} x mid-length; hy = {hy:e}",
        end / peak
    );
    assert!(end >= 1.3 * peak, "edge spike {end:e} vs mid {peak:e}");
}

#[test]
fn a_crown_removes_the_edge_spike() {
    // The centre line's pressure, its mid-length value, its maximum, where that is, and the
    // maximum over the last 0.1 mm of the roller (|y| > 0.9 mm).
    let profile = |crown: &str| {
        let (p, _, hy) = roller(crown);
        let (nx, ny) = (p.len(), p[0].len());
        let c: Vec<f64> = (0..ny).map(|j| 0.5 * (p[nx / 2 - 1][j] + p[nx / 2][j])).collect();
        let y = |j: usize| -1.1e-3 + (j as f64 + 0.5) * hy;
        let mid = 0.5 * (c[ny / 2 - 1] + c[ny / 2]);
        let (jmax, max) =
            c.iter()
                .copied()
                .enumerate()
                .fold((0, 0.0), |a, (j, v)| if v > a.1 { (j, v) } else { a });
        let ends = (0..ny).filter(|&j| y(j).abs() > 0.9e-3).map(|j| c[j]).fold(0.0, f64::max);
        (mid, max, y(jmax), ends)
    };
    let (mid0, max0, y0, ends0) = profile("");
    // crown 5 um over rounded ends of sqrt(2 rho c) = 0.4 mm (rho = 16 mm)
    let (mid1, max1, y1, ends1) = profile("crown = \"5 um\"\nend_radius = \"16 mm\"");
    eprintln!(
        "uncrowned: mid {mid0:.4e}, max {max0:.4e} ({:.3} x mid) at y = {y0:.3e} m, last 0.1 mm {ends0:.4e}",
        max0 / mid0
    );
    eprintln!(
        "crowned:   mid {mid1:.4e}, max {max1:.4e} ({:.3} x mid) at y = {y1:.3e} m, last 0.1 mm {ends1:.4e}",
        max1 / mid1
    );
    // Uncrowned: the peak sits at the ends and is far above mid-length.
    assert!(y0.abs() > 0.98e-3 && max0 > 2.0 * mid0, "uncrowned peak {max0:e} at {y0:e}");
    // Crowned: no pressure on the last 0.1 mm, the peak moves inside, to the start of the
    // crown (|y| = 0.6 mm, where the curvature jumps: the known weakness of a straight part
    // with circular ends; a logarithmic crown avoids it), and is well below the sharp end's.
    assert_eq!(ends1, 0.0);
    assert!((y1.abs() - 0.6e-3).abs() < 0.1e-3, "crowned peak at {y1:e}");
    assert!(max1 < 0.6 * max0, "crowned peak {max1:e} vs sharp ends {max0:e}");
}

#[test]
fn the_field_below_a_periodic_wave_in_full_contact_is_the_plane_strain_solution() {
    // Westergaard: the wave gap A (1 - cos kx) pressed into full contact carries
    // p = mean + p1 cos kx, p1 = pi E* A / lambda. The cosine part's plane-strain field
    // (z depth, compression negative): sxx = -p1 (1 - kz) e^-kz cos kx,
    // szz = -p1 (1 + kz) e^-kz cos kx, sxz = -p1 kz e^-kz sin kx, syy = nu (sxx + szz); the
    // mean adds szz = -mean (its in-plane stresses are not determined by a periodic
    // half-space and are left out).
    let (lambda, amp, nu) = (0.8e-3, 0.05e-6, 0.3);
    let p1 = PI * e_star() * amp / lambda;
    let mean = 1.5 * p1;
    let force = mean * 0.8e-3 * 0.8e-3;
    let profile = format!("shape = \"wavy\"\nwavelength = {lambda}\namplitude = {amp}");
    let load = format!(
        "normal = {force}\n[outputs]\nfield = {{ x = [-0.0004, 0.0004, 17], y = [0, 0, 1], \
         z = [0.00005, 0.0004, 4], scale = \"m\" }}"
    );
    let out = go("boundary = \"periodic\"", &profile, "", &load).unwrap();
    assert_eq!(out.contact.fraction, Some(1.0));
    let f = match &out.field {
        stickslip_run::Field::Volume(v) => v,
        other => panic!("no volume field: {other:?}"),
    };
    assert!(f.method.contains("periodic"), "{}", f.method);
    let k = 2.0 * PI / lambda;
    let mut worst: f64 = 0.0;
    for (iz, &z) in f.z.iter().enumerate() {
        let d = (-k * z).exp();
        for (ix, &x) in f.x.iter().enumerate() {
            let idx = ix + f.x.len() * iz;
            let (c, s) = ((k * x).cos(), (k * x).sin());
            let sxx = -p1 * (1.0 - k * z) * d * c;
            let szz = -p1 * (1.0 + k * z) * d * c - mean;
            let sxz = -p1 * k * z * d * s;
            let syy = nu * (sxx + (szz + mean));
            let a = &f.arrays;
            for (got, want) in
                [(a.sxx[idx], sxx), (a.szz[idx], szz), (a.sxz[idx], sxz), (a.syy[idx], syy)]
            {
                worst = worst.max((got - want).abs() / p1);
            }
            assert!(a.sxy[idx].abs() < 1e-9 * p1 && a.syz[idx].abs() < 1e-9 * p1);
        }
    }
    // 128 cells per wavelength: piecewise-constant pressure and bilinear interpolation
    // between cell centres, both O((kh)^2) ~ 2.4e-3.
    assert!(worst < 2e-3, "worst stress error {worst:.2e} p1");
    println!("periodic wave field: worst error {worst:.2e} p1");
}

#[test]
fn dissimilar_bodies_on_a_periodic_surface_are_solved_coupled() {
    // A rigid sphere on steel (Dundurs beta = 0.286 > 0) in a 0.8 mm period, with a
    // tangential force: the coupled solve runs with periodic operators.
    let src = BASE
        .replace("BOUNDARY", "boundary = \"periodic\"")
        .replace("PROFILE", SPHERE)
        .replace("ROUGH", "")
        .replace("model = \"same\"", "model = \"rigid\"")
        .replace("LOAD", "normal = \"10 N\"\ntangential = \"1 N\"\nfriction = 0.2");
    let dir = std::env::temp_dir();
    let out =
        run(&Scene::from_toml_str(&src, Some(dir.join("s.toml"))).unwrap(), &RunOptions::default())
            .unwrap();
    let c = out.solver.coupling.as_ref().expect("a coupled solve");
    assert!(c.beta > 0.2 && c.passes > 1, "{c:?}");
    assert!(out.audit.passed);
    assert!((out.forces.tangential - 1.0).abs() < 1e-6, "{}", out.forces.tangential);
    assert!((out.forces.normal - 10.0).abs() < 1e-6, "{}", out.forces.normal);
}

/// The sharp-edged flat punch (`edge_radius` left out, or 0) pressed by an approach d,
/// against Boussinesq: F = 2 a E* d and p(r) = E* d / (pi sqrt(a^2 - r^2)). The face on
/// the square lattice is the set of cells whose centres lie within the radius; the closed
/// form is evaluated at the radius of the circle of the same area (counted here, from the
/// lattice), and the error of the discretised face is first order in the cell size, so a
/// refinement halves it. The peak pressure is the edge singularity's and grows as the cells
/// shrink; the result says so.
#[test]
fn the_sharp_punch_follows_boussinesq_within_half_a_percent_at_256_cells_across() {
    let (radius, d) = (0.5e-3, 1e-7);
    let punch = |cells: usize, edge: &str| {
        // The lattice is 1.25 face diameters wide: `cells` across it, 0.8 cells across the face.
        let size = 2.5 * radius;
        let src = format!(
            "[geometry]\nkind = \"surface\"\nsize = [{size:e}, {size:e}]\ncells = [{cells}, {cells}]\n[geometry.profile]\nshape = \"punch\"\nradius = {radius:e}\n{edge}\n[substrate]\ne = \"210 GPa\"\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\napproach = {d:e}\n[solver]\ntolerance = 1e-10\n"
        );
        let out = run(&Scene::from_toml_str(&src, None).unwrap(), &RunOptions::default()).unwrap();
        // The face cells, counted from the lattice.
        let h = size / cells as f64;
        let mut face = 0usize;
        for j in 0..cells {
            for i in 0..cells {
                let (x, y) = ((i as f64 + 0.5) * h - 0.5 * size, (j as f64 + 0.5) * h - 0.5 * size);
                if x.hypot(y) <= radius {
                    face += 1;
                }
            }
        }
        let a = (face as f64 * h * h / PI).sqrt();
        let exact = 2.0 * a * e_star() * d;
        let err = (out.contact.normal_load - exact) / exact;
        (out, err, a)
    };
    let (out, err256, a) = punch(320, "");
    let p = out.punch.as_ref().expect("the sharp punch reports its check");
    println!(
        "256 across: F = {:.6e} N, Boussinesq at a_eq = {a:.6e} m: {:.6e} N, error {err256:+.3e}; at the written radius {:+.3e}; interior pressure {:.2e}; p0 {:.4e} Pa",
        out.contact.normal_load,
        2.0 * a * e_star() * d,
        (out.contact.normal_load - 2.0 * radius * e_star() * d) / (2.0 * radius * e_star() * d),
        p.interior_pressure_error,
        out.contact.p0
    );
    assert!(err256.abs() <= 5e-3, "force error {err256:e} at 256 cells across");
    assert!((p.force_error - err256).abs() <= 1e-12, "{} vs {err256}", p.force_error);
    assert_eq!(p.cells_across, 256.0);
    assert!(p.peak_pressure_grid_dependent);
    assert!(out.notes.iter().any(|n| n.contains("singular at the edge")), "{:?}", out.notes);
    // Away from the edge (r <= a/2) the pressure is Boussinesq's.
    assert!(p.interior_pressure_error <= 5e-3, "interior pressure {:e}", p.interior_pressure_error);
    // edge_radius = 0 is the same punch as leaving it out.
    let (zero, err0, _) = punch(320, "edge_radius = 0");
    assert_eq!(zero.contact.normal_load, out.contact.normal_load);
    assert_eq!(err0, err256);
    // First order: half the cells, about twice the error; the edge peak is lower on the
    // coarser lattice (p ~ 1/sqrt(h): about 1/sqrt(2)).
    let (coarse, err128, _) = punch(160, "");
    println!("128 across: error {err128:+.3e}, p0 {:.4e} Pa", coarse.contact.p0);
    assert!(err128.abs() > 1.5 * err256.abs() && err128.abs() < 2.5 * err256.abs());
    let peak = out.contact.p0 / coarse.contact.p0;
    assert!((peak - 2f64.sqrt()).abs() < 0.1, "peak pressure ratio {peak}");
}
