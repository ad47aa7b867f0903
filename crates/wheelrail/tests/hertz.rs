//! A conical wheel on a crowned rail: the contact is Hertzian, so the patch must match the
//! Hertz ellipse (`stickslip-halfspace`) and its creep forces the ellipsoid rolling solver
//! (`stickslip-rolling` on the Hertz ellipse's grid), both computed here from closed-form
//! geometry, not from the crate under test.
//!
//! Geometry (tests/common): rail crown radius R = 300 mm, cone of conicity 1/40, wheel radius
//! 460 mm, steel (G = 82 GPa, nu = 0.28), 10 kN. The centred wheelset first touches where the
//! crown's slope is -1/40: contact angle delta = -atan(1/40) (right side), rolling radius
//! r_c = r0 + gamma R / sqrt(1 + gamma^2). The relative curvatures are 1/R across and
//! cos(atan gamma)/r_c along x (the cone's normal curvature along its parallel circle;
//! the crown is straight along x, the cone straight along its generator).

mod common;

use common::Cone;
use stickslip_halfspace::hertz::HertzEllipse;
use stickslip_halfspace::material::composite_modulus;
use stickslip_lattice::ContactGrid;
use stickslip_rolling::steady3d::fastsim;
use stickslip_rolling::{Creepage, SteadyRolling};
use stickslip_wheelrail::{Cache, Motion, Position, Side, Solution, Tangential, VerticalLoad};

const LOAD: f64 = 1e4;
const GAMMA: f64 = 1.0 / 40.0;
const R_RAIL: f64 = 0.3;
const CELL: f64 = 1.5e-4;

fn hertz(c: &Cone) -> (HertzEllipse, f64) {
    let fn_ = LOAD * (1.0 + GAMMA * GAMMA).sqrt();
    let kx = 1.0 / (c.rolling_radius() * (1.0 + GAMMA * GAMMA).sqrt());
    let ks = 1.0 / R_RAIL;
    let e = composite_modulus(&common::steel(), &common::steel());
    (HertzEllipse::from_curvatures(kx, ks, fn_, e).unwrap(), fn_)
}

fn solve(motion: &Motion, t: Tangential) -> Solution {
    let c = Cone::new(R_RAIL, GAMMA);
    c.problem(Side::Right, CELL)
        .solve(&Position::default(), motion, VerticalLoad::Force(LOAD), t, &mut Cache::new())
        .unwrap()
}

/// Second moments of the pressure about its centroid: for the Hertz ellipse
/// int x^2 p dA / P = a^2/5 (Johnson eq. 4.37 integrated), so a = sqrt(5 <x^2>).
fn semi_axes(s: &Solution) -> (f64, f64) {
    let p = &s.patches[0].normal;
    let (mut w, mut mx, mut ms) = (0.0, 0.0, 0.0);
    for k in 0..p.pressure.len() {
        let (x, y) = p.centre(k);
        w += p.pressure[k];
        mx += p.pressure[k] * x;
        ms += p.pressure[k] * y;
    }
    let (cx, cs) = (mx / w, ms / w);
    let (mut vx, mut vs) = (0.0, 0.0);
    for k in 0..p.pressure.len() {
        let (x, y) = p.centre(k);
        vx += p.pressure[k] * (x - cx).powi(2);
        vs += p.pressure[k] * (y - cs).powi(2);
    }
    ((5.0 * vx / w).sqrt(), (5.0 * vs / w).sqrt())
}

#[test]
fn cone_on_crown_is_hertzian() {
    let c = Cone::new(R_RAIL, GAMMA);
    let (hz, fn_) = hertz(&c);
    let s = solve(&Motion::free_rolling(2.0, 0.46), Tangential::None);
    assert_eq!(s.patches.len(), 1, "one patch");
    let p = &s.patches[0];
    // Contact angle and the reference point where the slopes match (the pressure centroid
    // of a symmetric patch): exact geometry, up to the symmetry of the discrete pressure.
    let delta = -GAMMA.atan();
    assert!((p.contact_angle - delta).abs() < 1e-5, "delta {} vs {delta}", p.contact_angle);
    assert!(
        (p.rail_point[0] - c.touch_y()).abs() < 0.05 * CELL,
        "y_r {} vs {}",
        p.rail_point[0],
        c.touch_y()
    );
    assert!((p.rolling_radius - c.rolling_radius()).abs() < 1e-7, "r_c {}", p.rolling_radius);
    // Normal force: the load over cos(delta), to the load tolerance.
    assert!((p.normal_force - fn_).abs() < 1e-6 * fn_, "Fn {} vs {fn_}", p.normal_force);
    // Semi-axes from the second moments and the peak pressure. Tolerances: the lattice
    // solution converges as O(h/a) at the contact edge; measured errors at a/h ~ 40 are
    // below 0.3 % (axes) and 0.5 % (peak), so 1 % and 1.5 %.
    let (a, b) = semi_axes(&s);
    let (ah, bh) = (hz.semi_axis_x(), hz.semi_axis_y());
    eprintln!("a {a:.6e} vs {ah:.6e}, b {b:.6e} vs {bh:.6e}, pmax {:.6e} vs p0 {:.6e}, area {:.6e} vs {:.6e}",
        p.pmax, hz.max_pressure(), p.area, std::f64::consts::PI * ah * bh);
    assert!((a / ah - 1.0).abs() < 1e-2, "a {a} vs Hertz {ah}");
    assert!((b / bh - 1.0).abs() < 1e-2, "b {b} vs Hertz {bh}");
    assert!(
        (p.pmax / hz.max_pressure() - 1.0).abs() < 1.5e-2,
        "pmax {} vs {}",
        p.pmax,
        hz.max_pressure()
    );
    // Area: cells inside the ellipse, error of the order of its perimeter times h/2.
    let area = std::f64::consts::PI * ah * bh;
    assert!((p.area / area - 1.0).abs() < 3e-2, "area {} vs {area}", p.area);
    // The approach beyond first touch, along the normal: Hertz's delta = 3PK/(2 pi a E*),
    // vertical = delta / cos(contact angle).
    let approach = hz.approach() * (1.0 + GAMMA * GAMMA).sqrt();
    assert!((s.approach / approach - 1.0).abs() < 1e-2, "approach {} vs {approach}", s.approach);
}

/// Creepages from the motion in closed form, and creep forces against the exact theory on
/// the Hertz ellipse with the same creepages.
#[test]
fn cone_on_crown_creep_forces_match_the_ellipsoid_solver() {
    let c = Cone::new(R_RAIL, GAMMA);
    let (hz, fn_) = hertz(&c);
    let (v, rc) = (2.0, c.rolling_radius());
    // Braking slightly and sliding sideways: xi ~ 5e-4, eta ~ -4e-4, plus the cone's spin.
    let mut motion = Motion::rolling(v, -v / rc * (1.0 - 5e-4));
    motion.lateral_velocity = 8e-4;
    let s = solve(&motion, Tangential::Exact { tolerance: 1e-8 });
    let p = &s.patches[0];
    // Closed forms: v_q = (V + w_p r_c, v_y, 0), V_r = (V + |w_p| r_c)/2,
    // xi = -(V + w_p r_c)/V_r, eta = -v_y cos(delta)/V_r, phi = w_p sin(delta)/V_r.
    let delta = -GAMMA.atan();
    let wr = motion.pitch_rate * rc;
    let vr = 0.5 * (v + wr.abs());
    let xi = -(v + wr) / vr;
    let eta = -motion.lateral_velocity * delta.cos() / vr;
    let phi = motion.pitch_rate * delta.sin() / vr;
    let k = p.creepage;
    eprintln!("creepage {k:?} vs ({xi:e}, {eta:e}, {phi:e})");
    assert!((k.longitudinal - xi).abs() < 1e-4 * xi.abs(), "xi {} vs {xi}", k.longitudinal);
    assert!((k.lateral - eta).abs() < 1e-4 * eta.abs(), "eta {} vs {eta}", k.lateral);
    assert!((k.spin - phi).abs() < 1e-4 * phi.abs(), "phi {} vs {phi}", k.spin);
    // The ellipsoid solver: the Hertz ellipse's pressure on its own grid, 60 cells across.
    let creep = Creepage { longitudinal: xi, lateral: eta, spin: phi };
    let grid = ContactGrid::hertz_ellipse(hz.semi_axis_x(), hz.semi_axis_y(), fn_, 60, 60).unwrap();
    let reference = SteadyRolling::new(&grid, [common::steel(); 2], 0.3)
        .unwrap()
        .with_tolerance(1e-8)
        .unwrap()
        .solve(&creep)
        .unwrap();
    let fmax = 0.3 * fn_;
    eprintln!(
        "exact: Fx {:.2} vs {:.2}, Fs {:.2} vs {:.2}, Mn {:.4} vs {:.4}; stick {:?} vs {:.3}",
        p.fx,
        reference.fx,
        p.fs,
        reference.fy,
        p.mn,
        reference.mz,
        p.stick_fraction,
        reference.stick_fraction()
    );
    // Two discretisations of one problem (lattice contact at 0.15 mm against the analytic
    // ellipse at 60 cells across): PEERS.md measures 0.0025 f N between two solvers at 1k
    // elements; here 1 % of f N.
    assert!((p.fx - reference.fx).abs() < 1e-2 * fmax, "Fx {} vs {}", p.fx, reference.fx);
    assert!((p.fs - reference.fy).abs() < 1e-2 * fmax, "Fs {} vs {}", p.fs, reference.fy);
    let mref = fmax * (hz.semi_axis_x() * hz.semi_axis_y()).sqrt();
    assert!((p.mn - reference.mz).abs() < 2e-2 * mref, "Mn {} vs {}", p.mn, reference.mz);
    // The patch's forces in track coordinates: Fy = Fs cos d - Fn sin d, Fz = Fs sin d + Fn cos d.
    let (f, d) = (p.force_on_rail, p.contact_angle);
    assert!((f[1] - (p.fs * d.cos() - p.normal_force * d.sin())).abs() < 1e-9 * fn_);
    assert!((f[2] - (p.fs * d.sin() + p.normal_force * d.cos())).abs() < 1e-9 * fn_);

    // FASTSIM on the patch against FASTSIM on the Hertz ellipse with its semi-axes.
    let sf = solve(&motion, Tangential::Fastsim);
    let pf = &sf.patches[0];
    let g = 82e9;
    let rf =
        fastsim::solve(&grid, hz.semi_axis_x(), hz.semi_axis_y(), g, 0.28, 0.3, &creep).unwrap();
    eprintln!(
        "FASTSIM: Fx {:.2} vs {:.2}, Fs {:.2} vs {:.2}; axes {:?} vs ({:.4e}, {:.4e})",
        pf.fx,
        rf.fx,
        pf.fs,
        rf.fy,
        pf.fastsim_axes,
        hz.semi_axis_x(),
        hz.semi_axis_y()
    );
    assert!((pf.fx - rf.fx).abs() < 2e-2 * fmax, "FASTSIM Fx {} vs {}", pf.fx, rf.fx);
    assert!((pf.fs - rf.fy).abs() < 2e-2 * fmax, "FASTSIM Fs {} vs {}", pf.fs, rf.fy);
}

/// A free-rolling centred wheelset (pitch rate -V/r_c at the contact's rolling radius)
/// carries almost no longitudinal force: the rigid slip is spin alone, whose longitudinal
/// traction is odd across the symmetric patch.
#[test]
fn free_rolling_centred_wheelset_has_no_longitudinal_force() {
    let c = Cone::new(R_RAIL, GAMMA);
    let v = 2.0;
    let motion = Motion::rolling(v, -v / c.rolling_radius());
    let s = solve(&motion, Tangential::Exact { tolerance: 1e-8 });
    let p = &s.patches[0];
    eprintln!("free rolling: xi {:e}, Fx {:e} N, Fs {:.2} N", p.creepage.longitudinal, p.fx, p.fs);
    assert!(p.creepage.longitudinal.abs() < 1e-7, "xi {}", p.creepage.longitudinal);
    // 1e-3 f N: the discrete patch is symmetric about the centroid to a fraction of a cell.
    assert!(p.fx.abs() < 1e-3 * 0.3 * p.normal_force, "Fx {} N", p.fx);
    // The spin does give a lateral force.
    assert!(p.fs.abs() > 10.0 * p.fx.abs());
}

/// Force control carries the load: sum of Fn cos(delta) within 1e-6 (the target;
/// the iteration's own tolerance is 1e-9); the total vertical force under TotalForce.
#[test]
fn force_control_reproduces_the_load() {
    let c = Cone::new(R_RAIL, GAMMA);
    let pb = c.problem(Side::Right, 2e-4);
    let motion = Motion::rolling(2.0, -2.0 / 0.46);
    for load in [1e3, 1e4, 1e5] {
        let s = pb
            .solve(
                &Position { lateral: 1e-3, yaw: 2e-3, roll: 0.0 },
                &motion,
                VerticalLoad::Force(load),
                Tangential::None,
                &mut Cache::new(),
            )
            .unwrap();
        let fz: f64 = s.patches.iter().map(|p| p.normal_force * p.contact_angle.cos()).sum();
        assert!((fz - load).abs() < 1e-6 * load, "load {load}: {fz}");
        let s = pb
            .solve(
                &Position { lateral: 1e-3, yaw: 2e-3, roll: 0.0 },
                &motion,
                VerticalLoad::TotalForce(load),
                Tangential::Exact { tolerance: 1e-6 },
                &mut Cache::new(),
            )
            .unwrap();
        assert!(
            (s.total_on_rail[2] - load).abs() < 1e-6 * load,
            "total load {load}: {}",
            s.total_on_rail[2]
        );
    }
}
