//! Symmetries: the left side is the mirror image of the right; reversing the yaw reverses
//! the lateral creepage and mirrors the patch along x.

mod common;

use common::{a22_case, manchester, Cone};
use stickslip_wheelrail::{Cache, Motion, Position, Side, Tangential, VerticalLoad};

/// The left wheel at (y, psi, phi) and the right wheel at (-y, -psi, -phi) are mirror images
/// in the plane y = 0: every lateral quantity changes sign, everything else is equal. The
/// left side is computed as the mirror of a right side, so this checks the mirror map of
/// every output (positions, angles, creepages, forces, moments, the lattice arrays).
#[test]
fn left_is_the_mirrored_right() {
    let (y, psi, phi, fz, v, wp) = a22_case("left", 5);
    let motion = Motion::rolling(v, wp);
    let t = Tangential::Exact { tolerance: 1e-8 };
    let l = manchester(Side::Left)
        .solve(
            &Position { lateral: y, yaw: psi, roll: phi },
            &motion,
            VerticalLoad::Force(fz),
            t,
            &mut Cache::new(),
        )
        .unwrap();
    let r = manchester(Side::Right)
        .solve(
            &Position { lateral: -y, yaw: -psi, roll: -phi },
            &motion,
            VerticalLoad::Force(fz),
            t,
            &mut Cache::new(),
        )
        .unwrap();
    assert_eq!(l.patches.len(), r.patches.len());
    let close = |a: f64, b: f64, scale: f64, what: &str| {
        assert!((a - b).abs() <= 1e-9 * scale, "{what}: {a} vs {b}");
    };
    close(l.z_wheelset, r.z_wheelset, 1e-3, "z_ws");
    close(l.total_on_rail[0], r.total_on_rail[0], fz, "Fx");
    close(l.total_on_rail[1], -r.total_on_rail[1], fz, "Fy");
    close(l.total_on_rail[2], r.total_on_rail[2], fz, "Fz");
    for (a, b) in l.patches.iter().zip(&r.patches) {
        close(a.reference[0], b.reference[0], 1e-3, "x");
        close(a.reference[1], -b.reference[1], 1e-3, "y");
        close(a.rail_point[0], -b.rail_point[0], 1e-3, "y_r");
        close(a.wheel_point[0], -b.wheel_point[0], 1e-3, "y_w");
        close(a.contact_angle, -b.contact_angle, 1.0, "delta");
        close(a.creepage.longitudinal, b.creepage.longitudinal, 1e-3, "xi");
        close(a.creepage.lateral, -b.creepage.lateral, 1e-3, "eta");
        close(a.creepage.spin, -b.creepage.spin, 1.0, "phi");
        close(a.normal_force, b.normal_force, fz, "Fn");
        close(a.fx, b.fx, fz, "Fx");
        close(a.fs, -b.fs, fz, "Fs");
        close(a.mn, -b.mn, fz * 1e-2, "Mn");
        // Lattices: s -> -s.
        let (la, lb) = (a.lattice, b.lattice);
        assert_eq!((la.nx, la.ns), (lb.nx, lb.ns));
        close(la.origin.1, -(lb.origin.1 + lb.ns as f64 * lb.hs), 1e-3, "s0");
        for j in 0..la.ns {
            for i in 0..la.nx {
                let (ka, kb) = (j * la.nx + i, (la.ns - 1 - j) * la.nx + i);
                close(a.normal.pressure[ka], b.normal.pressure[kb], a.pmax, "pressure");
            }
        }
    }
}

/// Yaw reversed: the lateral creepage changes sign (it comes from the yaw), the patch moves
/// from x to -x; the normal contact, the longitudinal creepage and the spin are unchanged.
/// The lattices are laid out centred on the interpenetration's bounding box, so the
/// discrete problems are mirror images too: to rounding (asserted 1e-9).
#[test]
fn reversing_the_yaw_reverses_the_lateral_creepage() {
    let c = Cone::new(0.3, 1.0 / 40.0);
    let pb = c.problem(Side::Right, 2e-4);
    let motion = Motion::rolling(2.0, -2.0 / c.rolling_radius());
    let solve = |yaw: f64| {
        pb.solve(
            &Position { lateral: 0.0, yaw, roll: 0.0 },
            &motion,
            VerticalLoad::Force(1e4),
            Tangential::Exact { tolerance: 1e-8 },
            &mut Cache::new(),
        )
        .unwrap()
    };
    let (a, b) = (solve(4e-3), solve(-4e-3));
    let (pa, pb_) = (&a.patches[0], &b.patches[0]);
    eprintln!(
        "eta {:e} / {:e}, xi {:e} / {:e}",
        pa.creepage.lateral,
        pb_.creepage.lateral,
        pa.creepage.longitudinal,
        pb_.creepage.longitudinal
    );
    eprintln!(
        "x {:e} / {:e}, spin {:e} / {:e}, Fn {} / {}",
        pa.reference[0],
        pb_.reference[0],
        pa.creepage.spin,
        pb_.creepage.spin,
        pa.normal_force,
        pb_.normal_force
    );
    // eta ~ yaw: 4e-3.
    assert!(pa.creepage.lateral.abs() > 3e-3);
    assert!((pa.creepage.lateral + pb_.creepage.lateral).abs() < 1e-4 * pa.creepage.lateral.abs());
    assert!(
        (pa.creepage.longitudinal - pb_.creepage.longitudinal).abs()
            < 1e-4 * pa.creepage.lateral.abs()
    );
    assert!((pa.creepage.spin - pb_.creepage.spin).abs() < 1e-4 * pa.creepage.spin.abs());
    assert!(
        (pa.reference[0] + pb_.reference[0]).abs() < 5e-3 * 2e-4,
        "x {} / {}",
        pa.reference[0],
        pb_.reference[0]
    );
    assert!((pa.normal_force - pb_.normal_force).abs() < 1e-6 * pa.normal_force);
    // Forces: the lateral creep force changes its sign with eta, up to the spin's share,
    // which does not change sign: Fs(eta) + Fs(-eta) = 2 Fs(spin part), well below |Fs|.
    assert!(pa.fs.signum() != pb_.fs.signum(), "Fs {} / {}", pa.fs, pb_.fs);
}
