//! Transient 3D rolling (issue 31, item 4): from a Cattaneo shift at rest into steady
//! rolling, against the steady exact theory (`SteadyRolling`) at the creepages the transient
//! run settles on (FORMULAS.md R3, "Transient rolling").

use std::f64::consts::PI;
use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
use stickslip_rolling::steady3d::{Creepage, RollingSolution, SteadyRolling, TransientRolling};

/// Tolerances, each with its reason.
mod tol {
    /// Traction after six contact lengths against the steady solution, relative to f p0:
    /// both solvers stop at relative residuals of 1e-10 (the steady one in the max norm
    /// over f p_max, the fast one in the 2-norm over |q|), and by then the transient's
    /// memory of the start has decayed below them (circle at -0.4 fP: 2.9e-10); 1e-8
    /// leaves room.
    pub const STEADY: f64 = 1e-8;
    /// After two contact lengths (issue 31 asks for the steady solution "within its
    /// tolerance" there): the start's memory decays by a factor of about 7 per half contact
    /// length (circle, -0.4 fP: 3.7e-2, 1.0e-2, 1.4e-3, 2.0e-4, 2.8e-5 of f p0 after 1, 1.5,
    /// 2, 2.5 and 3 lengths), so after two lengths the traction is within 1.4e-3 of f p0,
    /// not within the steady solver's 1e-6 default; bound 3e-3.
    pub const TWO_LENGTHS: f64 = 3e-3;
}

fn steel() -> Material {
    Material::new(210e9, 0.28).unwrap()
}

/// Largest traction difference between two solutions on the same elements, over f p0.
fn traction_difference(a: &RollingSolution, b: &RollingSolution, fp0: f64) -> f64 {
    (0..a.qx.len()).map(|k| (a.qx[k] - b.qx[k]).hypot(a.qy[k] - b.qy[k])).fold(0.0, f64::max) / fp0
}

/// Shift at rest under the creep force F (a Cattaneo shift), then roll six contact lengths
/// under the same force and spin; the steady exact theory at the creepages reached must give
/// the same traction and carry the same force. Printed: the distance to the steady solution
/// (at each step's own creepages) after 1, 2, 3 and 6 contact lengths.
fn cattaneo_into_rolling(a: f64, b: f64, nx: usize, ny: usize, force: (f64, f64), spin: f64) {
    let (p, f) = (1e5, 0.3);
    let grid = ContactGrid::hertz_ellipse(a, b, p, nx, ny).unwrap();
    let fp0 = f * 1.5 * p / (PI * a * b);
    let m = steel();
    let force = (force.0 * f * p, force.1 * f * p);
    let mut t = TransientRolling::new(&grid, [m, m], f).unwrap();
    let rest = t.shift(force).unwrap();
    assert!(rest.creepage.is_none() && rest.distance == 0.0);
    let steady = SteadyRolling::new(&grid, [m, m], f).unwrap().with_tolerance(1e-10).unwrap();
    let mut diff = Vec::new();
    let mut last = None;
    for i in 1..=6 * nx {
        let st = t.roll(force, spin).unwrap();
        assert!((st.force.0 - force.0).hypot(st.force.1 - force.1) <= 1e-9 * f * p, "{st:?}");
        let (xi, eta) = st.creepage.unwrap();
        if i % nx == 0 {
            let s = steady.solve(&Creepage { longitudinal: xi, lateral: eta, spin }).unwrap();
            let now = t.solution();
            // The step's spin moment is the state's (the same sum, taken without the copy).
            assert!((st.mz - now.mz).abs() <= 1e-12 * f * p * a, "{} vs {}", st.mz, now.mz);
            diff.push(traction_difference(&now, &s, fp0));
            last = Some((s, xi, eta));
        }
    }
    let (s, xi, eta) = last.unwrap();
    let tr = t.solution();
    let force_err = (s.fx - force.0).hypot(s.fy - force.1) / (f * p);
    println!(
        "a/b = {:.2}, {nx} x {ny}, F = ({:.2}, {:.2}) fP, spin {spin} 1/m: Cattaneo stick fraction \
         {:.3}; creepages after 6 lengths ({xi:.8e}, {eta:.8e}); traction vs steady after 1, 2, \
         3, 6 lengths {:.2e}, {:.2e}, {:.2e}, {:.2e} of f p0; steady force at the final creepages \
         off by {force_err:.1e} of fP; stick fraction {:.3} (steady {:.3}); M_z {:.6e} (steady \
         {:.6e})",
        a / b,
        force.0 / (f * p),
        force.1 / (f * p),
        rest.stick_fraction,
        diff[0],
        diff[1],
        diff[2],
        diff[5],
        tr.stick_fraction(),
        s.stick_fraction(),
        tr.mz,
        s.mz,
    );
    assert!(diff[5] <= tol::STEADY, "{diff:?}");
    assert!(force_err <= tol::STEADY, "{force_err}");
    assert_eq!(tr.stick, s.stick);
    assert!(diff[1] <= tol::TWO_LENGTHS, "{diff:?}");
}

/// A circle under a braking force, no spin (CONTACT's `catt_to_cart` in 3D).
#[test]
fn cattaneo_shift_rolls_into_steady_state() {
    cattaneo_into_rolling(6e-3, 6e-3, 32, 32, (-0.4, 0.0), 0.0);
}

/// An ellipse long across the rolling direction, a longitudinal and a lateral force and
/// spin.
#[test]
fn cattaneo_shift_with_spin_rolls_into_steady_state() {
    cattaneo_into_rolling(4e-3, 8e-3, 24, 48, (-0.3, 0.2), 2.0);
}

/// Bad input is refused, and a force beyond the capacity is the fast solver's error.
#[test]
fn transient_refusals() {
    let grid = ContactGrid::hertz_ellipse(6e-3, 6e-3, 1e5, 8, 8).unwrap();
    let m = steel();
    assert!(TransientRolling::new(&grid, [m, m], 0.0).is_err());
    let mut t = TransientRolling::new(&grid, [m, m], 0.3).unwrap();
    assert!(t.roll((0.0, 0.0), f64::NAN).is_err());
    let err = t.roll((-1.1 * 0.3 * 1e5, 0.0), 0.0).unwrap_err();
    println!("{err}");
    assert!(matches!(
        err,
        stickslip_rolling::Error::Tangential(stickslip_traction::Error::CapacityExceeded { .. })
    ));
}
