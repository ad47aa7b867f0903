//! A wheel on its rail through a scene (issue 29 item 8): profile files written here, a
//! rail crowned with radius R = 300 mm and a conical wheel of conicity 1/40, both circular
//! arcs across (the cone straight), so the one patch is Hertzian. Its semi-axes, peak
//! pressure and normal force are checked against the Hertz ellipse (`stickslip-halfspace`,
//! from the closed-form curvatures), its creepages against their closed forms and its creep
//! forces against the ellipsoid rolling solver (`stickslip-rolling`'s exact theory on the
//! Hertz ellipse's own grid): references computed independently of the scene, the planner
//! and the wheel-rail crate. The wheel-rail crate's tests/hertz.rs makes the same checks on
//! the library directly; the tolerances are theirs.

use stickslip_halfspace::hertz::HertzEllipse;
use stickslip_halfspace::material::composite_modulus;
use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
use stickslip_rolling::{Creepage, SteadyRolling};
use stickslip_run::{run, RunOptions};
use stickslip_scene::Scene;

const R_RAIL: f64 = 0.3;
const GAMMA: f64 = 1.0 / 40.0;
const R0: f64 = 0.46;
const LOAD: f64 = 1e4;
const V: f64 = 2.0;

fn steel() -> Material {
    let (g, nu) = (82e9, 0.28);
    Material::new(2.0 * g * (1.0 + nu), nu).unwrap()
}

#[test]
fn circular_arc_profiles_give_the_hertz_ellipse_and_its_creep_forces() {
    let dir = std::env::temp_dir().join(format!("stickslip-wr-hertz-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    // Profiles in mm: the crown z = R - sqrt(R^2 - y^2) for |y| <= 30 mm, the cone
    // z = -gamma y for -40 mm <= y <= 60 mm.
    let rmm = R_RAIL * 1e3;
    let rail: Vec<String> = (-300..=300)
        .map(|i| {
            let y = f64::from(i) * 0.1;
            format!("{y},{}", rmm - (rmm * rmm - y * y).sqrt())
        })
        .collect();
    let wheel: Vec<String> =
        (-40..=60).map(|i| format!("{},{}", f64::from(i), -GAMMA * f64::from(i))).collect();
    std::fs::write(dir.join("crown.csv"), rail.join("\n")).unwrap();
    std::fs::write(dir.join("cone.csv"), wheel.join("\n")).unwrap();
    // Gauge measured 1 mm below the top: the crown's top lies at G/2 + sqrt(2 R h - h^2);
    // the wheel's profile origin is put straight above it.
    let (gauge, h) = (1.435, 1e-3);
    let crown_y = 0.5 * gauge + (2.0 * R_RAIL * h - h * h).sqrt();
    let fb_distance = 1.36;
    let fb_position = 0.5 * fb_distance - crown_y;
    // Closed-form geometry of the first touch (right side): the crown's slope equals the
    // cone's where y_r = -gamma R / sqrt(1 + gamma^2); contact angle -atan(gamma); rolling
    // radius r0 - gamma y_r.
    let touch_y = -GAMMA * R_RAIL / (1.0 + GAMMA * GAMMA).sqrt();
    let rc = R0 - GAMMA * touch_y;
    let delta = -GAMMA.atan();
    // Braking slightly: xi about 5e-4, with the cone's spin.
    let pitch_rate = -V / rc * (1.0 - 5e-4);
    let scene = format!(
        "[geometry]\nkind = \"wheel-rail\"\nside = \"right\"\nrail_profile = \"crown.csv\"\n\
         wheel_profile = \"cone.csv\"\nprofile_unit = \"mm\"\ngauge = \"{gauge} m\"\n\
         gauge_height = \"{h} m\"\nflange_back_distance = \"{fb_distance} m\"\n\
         flange_back_position = \"{fb_position:e} m\"\nwheel_radius = \"{R0} m\"\n\
         [substrate]\nmodel = \"homogeneous\"\ne = \"209.92 GPa\"\nnu = 0.28\n\
         [indenter]\nmodel = \"same\"\n[load]\nnormal = \"{LOAD} N\"\nfriction = 0.3\n\
         [motion]\nkind = \"rolling\"\nspeed = \"{V} m/s\"\npitch_rate = \"{pitch_rate:e} rad/s\"\n\
         [solver]\ncell = [\"0.15 mm\", \"0.15 mm\"]\ntolerance = 1e-8\n"
    );
    let file = dir.join("cone_on_crown.toml");
    std::fs::write(&file, &scene).unwrap();
    let out =
        run(&Scene::from_toml_str(&scene, Some(file)).unwrap(), &RunOptions::default()).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    let w = out.wheel_rail.as_ref().unwrap();
    assert_eq!(w.patches.len(), 1, "one patch");
    let p = &w.patches[0];

    // Geometry.
    assert!((p.contact_angle - delta).abs() < 1e-5, "delta {} vs {delta}", p.contact_angle);
    assert!((p.y_rail - touch_y).abs() < 0.05 * 1.5e-4, "y_r {} vs {touch_y}", p.y_rail);
    assert!((p.rolling_radius - rc).abs() < 1e-7, "r_c {} vs {rc}", p.rolling_radius);
    // The vertical load carried by Fn cos(delta).
    let fn_ = LOAD / delta.cos();
    assert!((p.fn_ / fn_ - 1.0).abs() < 1e-6, "Fn {} vs {fn_}", p.fn_);

    // Hertz: relative curvatures 1/R across, cos(atan gamma)/r_c along x.
    let kx = 1.0 / (rc * (1.0 + GAMMA * GAMMA).sqrt());
    let hz =
        HertzEllipse::from_curvatures(kx, 1.0 / R_RAIL, fn_, composite_modulus(&steel(), &steel()))
            .unwrap();
    // Semi-axes from the pressure map's second moments: for Hertz, <x^2> = a^2/5.
    let m = &p.maps;
    let nx = m.x.len();
    let (mut sw, mut sx, mut ss) = (0.0, 0.0, 0.0);
    for (k, &pk) in m.pressure.iter().enumerate() {
        let (x, s) = (m.x[k % nx], m.s[k / nx]);
        sw += pk;
        sx += pk * x;
        ss += pk * s;
    }
    let (cx, cs) = (sx / sw, ss / sw);
    let (mut vx, mut vs) = (0.0, 0.0);
    for (k, &pk) in m.pressure.iter().enumerate() {
        vx += pk * (m.x[k % nx] - cx).powi(2);
        vs += pk * (m.s[k / nx] - cs).powi(2);
    }
    let (a, b) = ((5.0 * vx / sw).sqrt(), (5.0 * vs / sw).sqrt());
    let (ah, bh) = (hz.semi_axis_x(), hz.semi_axis_y());
    eprintln!(
        "a {a:.5e} vs {ah:.5e}, b {b:.5e} vs {bh:.5e}, pmax {:.5e} vs {:.5e}",
        p.pmax,
        hz.max_pressure()
    );
    assert!((a / ah - 1.0).abs() < 1e-2, "a {a} vs Hertz {ah}");
    assert!((b / bh - 1.0).abs() < 1e-2, "b {b} vs Hertz {bh}");
    assert!(
        (p.pmax / hz.max_pressure() - 1.0).abs() < 1.5e-2,
        "pmax {} vs {}",
        p.pmax,
        hz.max_pressure()
    );

    // Creepages in closed form: V_r = (V + |w_p| r_c)/2, xi = -(V + w_p r_c)/V_r,
    // eta = 0 (no lateral motion), phi = w_p sin(delta)/V_r.
    let wr = pitch_rate * rc;
    let vr = 0.5 * (V + wr.abs());
    let (xi, phi) = (-(V + wr) / vr, pitch_rate * delta.sin() / vr);
    let k = &p.creepage;
    assert!((k.longitudinal - xi).abs() < 1e-4 * xi.abs(), "xi {} vs {xi}", k.longitudinal);
    assert!(k.lateral.abs() < 1e-4 * xi.abs(), "eta {}", k.lateral);
    assert!((k.spin - phi).abs() < 1e-4 * phi.abs(), "phi {} vs {phi}", k.spin);

    // The ellipsoid solver on the Hertz ellipse's own grid, 60 cells across.
    let creep = Creepage { longitudinal: xi, lateral: 0.0, spin: phi };
    let grid = ContactGrid::hertz_ellipse(ah, bh, fn_, 60, 60).unwrap();
    let reference = SteadyRolling::new(&grid, [steel(); 2], 0.3)
        .unwrap()
        .with_tolerance(1e-8)
        .unwrap()
        .solve(&creep)
        .unwrap();
    let fmax = 0.3 * fn_;
    eprintln!(
        "Fx {:.3} vs {:.3}, Fs {:.3} vs {:.3}, Mn {:.5} vs {:.5}",
        p.fx, reference.fx, p.fs, reference.fy, p.mn, reference.mz
    );
    assert!((p.fx - reference.fx).abs() < 1e-2 * fmax, "Fx {} vs {}", p.fx, reference.fx);
    assert!((p.fs - reference.fy).abs() < 1e-2 * fmax, "Fs {} vs {}", p.fs, reference.fy);
    let mref = fmax * (ah * bh).sqrt();
    assert!((p.mn - reference.mz).abs() < 2e-2 * mref, "Mn {} vs {}", p.mn, reference.mz);
}
