//! Wheel on rail from real profiles: the contact of one wheel of a wheelset with its rail,
//! as a railway engineer poses it to CONTACT.
//!
//! * [`profile`]: rail and wheel profiles from SIMPACK (`.prr`, `.prw`), MiniProf (`.ban`,
//!   `.whl`) or plain two-column files (the caller hands over the text and a name), checked
//!   (finite, at least 10 points, no loops, no back-steps beyond a near-vertical face, a
//!   plausible size for the unit, the shape of a rail or a wheel) and interpolated by a
//!   parametric cubic smoothing spline ([`spline`]);
//! * [`placement`]: CONTACT's track coordinates ($x$ rolling, $y$ right, $z$ down), the rail
//!   canted, on the track plane and at the gauge, the wheel at its flange back distance and
//!   radius, the wheelset shifted, yawed and rolled; left sides as mirror images;
//! * [`search`]: the interpenetration regions across the profiles and along $x$, one patch
//!   each (tread and flange at once);
//! * [`patch`]: each patch's tangent plane, contact angle and exact undeformed gap on its own
//!   lattice;
//! * [`kinematics`]: the creepages (longitudinal, lateral, spin) of each patch from the
//!   wheelset's speed, pitch rate and yaw;
//! * [`solve`]: the normal contact of every patch with `stickslip-normal`'s solver under the
//!   vertical wheel load (the wheelset height follows) or a given approach, and the creep
//!   forces of `stickslip-rolling`'s exact steady-rolling theory or FASTSIM per patch, in
//!   patch and track coordinates.
//!
//! ```
//! use stickslip_halfspace::Material;
//! use stickslip_wheelrail::{
//!     Cache, Motion, Position, Profile, ProfileOptions, Role, Side, Tangential, Track,
//!     VerticalLoad, WheelRail, Wheelset,
//! };
//! // A rail head crowned with radius 300 mm and a wheel of conicity 1:40 (metres).
//! let rail: Vec<(f64, f64)> = (-30..=30)
//!     .map(|i| {
//!         let y = f64::from(i) * 1e-3;
//!         (y, 0.3 - (0.09 - y * y).sqrt())
//!     })
//!     .collect();
//! let wheel: Vec<(f64, f64)> =
//!     (-40..=60).map(|i| (f64::from(i) * 1e-3, -f64::from(i) * 1e-3 / 40.0)).collect();
//! let o = ProfileOptions::default();
//! let rail = Profile::from_points("crown", Role::Rail, &rail, &o).unwrap();
//! let wheel = Profile::from_points("cone", Role::Wheel, &wheel, &o).unwrap();
//! let track = Track::new(rail, 1.435, 1e-3, 0.0).unwrap();
//! let wheelset = Wheelset::new(wheel, 1.36, -0.0475, 0.46).unwrap();
//! let steel = Material::new(210e9, 0.28).unwrap();
//! let pb = WheelRail::new(Side::Right, track, wheelset, steel, steel, 0.3, (2e-4, 2e-4)).unwrap();
//! let sol = pb
//!     .solve(
//!         &Position::default(),
//!         &Motion::free_rolling(2.0, 0.46),
//!         VerticalLoad::Force(1e4),
//!         Tangential::None,
//!         &mut Cache::new(),
//!     )
//!     .unwrap();
//! let fz: f64 = sol.patches.iter().map(|p| p.normal_force * p.contact_angle.cos()).sum();
//! assert!((fz - 1e4).abs() < 1e-6 * 1e4);
//! ```
//!
//! Units: SI (m, rad, N, Pa, s).
#![cfg_attr(docsrs, feature(doc_auto_cfg))]

pub mod error;
pub mod kinematics;
pub mod patch;
pub mod placement;
pub mod profile;
pub mod search;
pub mod solve;
pub mod spline;

pub use error::{Error, Result};
pub use kinematics::Motion;
pub use placement::{Position, Side, Track, Wheelset};
pub use profile::{Format, Profile, ProfileOptions, Role};
pub use solve::{
    Cache, PatchLattice, PatchSolution, Solution, SolveInfo, Tangential, VerticalLoad, WheelRail,
};
pub use stickslip_rolling::Creepage;
