//! Transient 3D rolling at prescribed creepages (issue 31, item 4: creep forces along the way
//! are results): from rest or from a Cattaneo shift, the contact rolls at fixed creepages
//! and spin into the steady state of the exact steady theory (`SteadyRolling`) at those
//! creepages, which is the independent reference here (a different discretisation of time:
//! the steady solver has no steps).
//!
//! Under prescribed creepages the start's memory decays more slowly than under a prescribed
//! force (transient3d.rs: a factor of about 50 per contact length): the total force is then
//! itself part of the transient. Measured here, the distance to the steady traction falls by
//! about 9 per contact length on the circle and 4.5 on the ellipse with spin, so two contact
//! lengths leave 0.11 and 0.32 of f p0, and the steady state is reached to the solvers'
//! tolerances only after 10 to 14 lengths.

use std::f64::consts::PI;
use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
use stickslip_rolling::steady3d::{Creepage, SteadyRolling, TransientRolling};

/// Tolerances, each with its reason.
mod tol {
    /// Traction after the last length rolled against the steady solution, relative to f p0,
    /// as in transient3d.rs: both solvers stop at relative residuals of 1e-10 and the start's
    /// memory has decayed below them; 1e-8 leaves room.
    pub const STEADY: f64 = 1e-8;
    /// The distance to the steady traction falls by at least this factor per contact length
    /// (measured 8.9 to 10.5 on the circle, 2.0 to 4.9 on the ellipse with spin, the
    /// smallest in the first length).
    pub const DECAY_PER_LENGTH: f64 = 1.8;
    /// Each step meets its creepages to 1e-9 of their size (the secant's stopping rule; the
    /// creepages here are above its floor), with room for the rounding of dividing the
    /// step's shift by the element length (measured 0.94e-9 and 1.0e-9).
    pub const CREEPAGE: f64 = 1.1e-9;
}

fn steel() -> Material {
    Material::new(210e9, 0.28).unwrap()
}

/// Roll `lengths` contact lengths at creepages (xi, eta) given in units of f p0 / G (and spin in
/// those units over sqrt(ab)), from rest or after a Cattaneo shift under `shift_force`
/// (in fP); compare with the steady theory at the same creepages.
fn rolls_into_steady(
    a: f64,
    b: f64,
    nx: usize,
    ny: usize,
    creep: (f64, f64, f64),
    shift_force: Option<(f64, f64)>,
    lengths: usize,
) {
    let (p, f) = (1e5, 0.3);
    let m = steel();
    let grid = ContactGrid::hertz_ellipse(a, b, p, nx, ny).unwrap();
    let p0 = 1.5 * p / (PI * a * b);
    let unit = f * p0 / m.shear_modulus();
    let (xi, eta, spin) = (creep.0 * unit, creep.1 * unit, creep.2 * unit / (a * b).sqrt());
    let mut t = TransientRolling::new(&grid, [m, m], f).unwrap();
    if let Some(fs) = shift_force {
        t.shift((fs.0 * f * p, fs.1 * f * p)).unwrap();
    }
    let steady = SteadyRolling::new(&grid, [m, m], f).unwrap().with_tolerance(1e-10).unwrap();
    let s = steady.solve(&Creepage { longitudinal: xi, lateral: eta, spin }).unwrap();
    let fp0 = f * p0;
    let (mut diff, mut worst_creep, mut products, mut steps) = (Vec::new(), 0.0f64, 0usize, 0);
    let mut last_force = (0.0, 0.0);
    for i in 1..=lengths * nx {
        let st = t.roll_at_creepage((xi, eta), spin).unwrap();
        let (cx, cy) = st.creepage.unwrap();
        worst_creep = worst_creep.max((cx - xi).hypot(cy - eta) / xi.hypot(eta).max(1e-3 * unit));
        products += st.products;
        steps += 1;
        last_force = st.force;
        if i % nx == 0 {
            let now = t.solution();
            let d = (0..now.qx.len())
                .map(|k| (now.qx[k] - s.qx[k]).hypot(now.qy[k] - s.qy[k]))
                .fold(0.0, f64::max)
                / fp0;
            diff.push(d);
        }
    }
    let force_err = (last_force.0 - s.fx).hypot(last_force.1 - s.fy) / (f * p);
    let decay: Vec<f64> = diff.windows(2).map(|w| w[0] / w[1]).collect();
    let shown: Vec<String> = diff.iter().map(|d| format!("{d:.1e}")).collect();
    println!(
        "a/b = {:.2}, {nx} x {ny}, creepages ({:.2}, {:.2}, spin {:.2}) f p0/G, start {}: traction \
         vs steady after each length [{}] of f p0 (decay per length {decay:.1?}); creep force \
         ({:.6}, {:.6}) fP, steady ({:.6}, {:.6}) fP, off by {force_err:.1e}; creepages met to \
         {worst_creep:.1e}; {:.1} products a step",
        a / b,
        creep.0,
        creep.1,
        creep.2,
        if shift_force.is_some() { "a Cattaneo shift" } else { "rest" },
        shown.join(", "),
        last_force.0 / (f * p),
        last_force.1 / (f * p),
        s.fx / (f * p),
        s.fy / (f * p),
        products as f64 / steps as f64,
    );
    assert!(worst_creep <= tol::CREEPAGE, "{worst_creep}");
    assert!(diff[lengths - 1] <= tol::STEADY, "{diff:?}");
    assert!(force_err <= tol::STEADY, "{force_err}");
    // Until the solvers' tolerances are reached, every length brings the state closer.
    for (k, d) in decay.iter().enumerate() {
        if diff[k + 1] > 1e3 * tol::STEADY {
            assert!(*d >= tol::DECAY_PER_LENGTH, "{decay:?}");
        }
    }
}

/// A circle braking at a longitudinal creepage, from rest.
#[test]
fn rolls_from_rest_into_steady_state_at_prescribed_creepage() {
    rolls_into_steady(6e-3, 6e-3, 32, 32, (-0.5, 0.0, 0.0), None, 10);
}

/// CONTACT's `catt_to_cart` in 3D with the creepage prescribed: a Cattaneo shift under a
/// braking force, then rolling at a creepage and spin on an ellipse long across.
#[test]
fn cattaneo_shift_then_prescribed_creepage_and_spin() {
    rolls_into_steady(4e-3, 8e-3, 24, 48, (-0.4, 0.2, 0.3), Some((-0.3, 0.1)), 14);
}

/// Non-finite creepages are refused. A creepage far beyond saturation is full sliding: no
/// element sticks and the creep force is f times the pressure along each element's slip,
/// just below f P (the slip directions differ slightly), not a refusal.
#[test]
fn creepage_refusals_and_full_sliding() {
    let (p, f) = (1e5, 0.3);
    let grid = ContactGrid::hertz_ellipse(6e-3, 6e-3, p, 12, 12).unwrap();
    let m = steel();
    let mut t = TransientRolling::new(&grid, [m, m], f).unwrap();
    assert!(t.roll_at_creepage((f64::NAN, 0.0), 0.0).is_err());
    assert!(t.roll_at_creepage((0.0, 0.0), f64::INFINITY).is_err());
    assert_eq!(t.distance(), 0.0);
    for _ in 0..24 {
        let st = t.roll_at_creepage((-0.05, 0.0), 0.0).unwrap();
        let (cx, cy) = st.creepage.unwrap();
        assert!((cx + 0.05).hypot(cy) <= 1e-9 * 0.05, "{st:?}");
        assert_eq!(st.stick_fraction, 0.0);
        let ratio = st.force.0.hypot(st.force.1) / (f * p);
        assert!(st.force.0 > 0.0 && ratio < 1.0 && ratio > 0.999, "{ratio}");
    }
}
