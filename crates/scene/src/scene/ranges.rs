//! The magnitudes a scene may hold: for each kind of quantity the range in which the
//! solvers' f64 arithmetic has been run and audited (the tests run both ends of every range).
//! A value outside is refused before anything is solved, naming the key, the range and why.
//!
//! The ranges are generous on purpose: each spans many decades beyond the engineering uses
//! (nano-indentation to wheel–rail), and their ends come from the arithmetic, not from
//! taste. Products of the extremes stay far from overflow and underflow: the largest
//! intermediate of the closed forms is about $E R^2 \le 10^{13} \cdot 10^{8}$, the smallest
//! about $P/E \ge 10^{-12}/10^{13}$, both well inside f64 ($10^{\pm 307}$). The contact
//! itself is bounded by the dimensionless checks of the planner (`stickslip-run`: contact
//! size over radius, mean pressure over modulus), which need the composite modulus.

/// One range: `lo <= |v| <= hi`, in SI `unit`, with the reason for its ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    /// What the quantity is ("modulus", "length" ...).
    pub name: &'static str,
    /// The smallest magnitude accepted (SI).
    pub lo: f64,
    /// The largest magnitude accepted (SI).
    pub hi: f64,
    /// The SI unit.
    pub unit: &'static str,
    /// Why the ends are where they are (the hint of a refusal).
    pub why: &'static str,
}

/// Young's modulus of a body (and the graded modulus at 1 m depth): 1 Pa (softer than any
/// gel) to 10 TPa (ten times diamond).
pub const MODULUS: Range = Range {
    name: "modulus",
    lo: 1.0,
    hi: 1e13,
    unit: "Pa",
    why: "moduli from 1 Pa (softer than any gel) to 1e13 Pa (ten times diamond) are solved and audited",
};

/// A force in 3D.
pub const FORCE: Range = Range {
    name: "force",
    lo: 1e-12,
    hi: 1e12,
    unit: "N",
    why: "forces from 1e-12 N (below atomic-force microscopy) to 1e12 N (a hundred thousand tonnes-force) are solved and audited",
};

/// A force per unit length in 2D.
pub const FORCE_PER_LENGTH: Range = Range {
    name: "load per unit length",
    lo: 1e-9,
    hi: 1e12,
    unit: "N/m",
    why: "loads per unit length from 1e-9 N/m to 1e12 N/m are solved and audited",
};

/// The size of a body or of a contact: radii, semi-axes, half-widths, patch sides, the
/// lattice size, profile lengths and wavelengths.
pub const LENGTH: Range = Range {
    name: "length",
    lo: 1e-9,
    hi: 1e4,
    unit: "m",
    why: "body and contact sizes from 1 nm (continuum mechanics ends near here) to 10 km are solved and audited",
};

/// A small length: an approach, a waviness amplitude, a crown drop, a tangential shift.
pub const SMALL_LENGTH: Range = Range {
    name: "length",
    lo: 1e-15,
    hi: 1e3,
    unit: "m",
    why: "approaches, amplitudes and shifts from 1e-15 m to 1e3 m are solved and audited",
};

/// A contact pressure given directly (patches).
pub const PRESSURE: Range = Range {
    name: "pressure",
    lo: 1e-3,
    hi: 1e12,
    unit: "Pa",
    why: "pressures from 1e-3 Pa to 1e12 Pa are solved and audited (a pressure above about a tenth of the modulus is refused with it)",
};

/// The Coulomb friction coefficient (0 is allowed: frictionless).
pub const FRICTION: Range = Range {
    name: "friction coefficient",
    lo: 1e-6,
    hi: 10.0,
    unit: "",
    why: "f = 0 (frictionless) or 1e-6 <= f <= 10: measured coefficients lie within 1e-3..5, and below 1e-6 write 0",
};

/// A twisting moment (0 is allowed).
pub const MOMENT: Range = Range {
    name: "moment",
    lo: 1e-21,
    hi: 1e16,
    unit: "N m",
    why: "moments of 0 or from 1e-21 N m to 1e16 N m (the extreme forces times the extreme lengths) are solved and audited",
};

/// A time of the viscoelastic solid.
pub const TIME: Range = Range {
    name: "time",
    lo: 1e-9,
    hi: 1e9,
    unit: "s",
    why: "times from 1 ns to 1e9 s (thirty years) are solved and audited",
};

/// A rolling speed.
pub const SPEED: Range = Range {
    name: "speed",
    lo: 1e-9,
    hi: 1e4,
    unit: "m/s",
    why: "speeds from 1 nm/s to 10 km/s are solved and audited (a steady-state theory; elastic waves are not modelled)",
};

/// A creep ratio or a creepage (0 is allowed).
pub const CREEP: Range = Range {
    name: "creep",
    lo: 1e-12,
    hi: 1e6,
    unit: "",
    why: "0, or a magnitude from 1e-12 to 1e6 (beyond about f a / R the contact slides fully; larger values are full sliding too)",
};

/// Every range, in the order of docs/SCENES.md's table.
pub const ALL: [Range; 11] = [
    MODULUS,
    FORCE,
    FORCE_PER_LENGTH,
    LENGTH,
    SMALL_LENGTH,
    PRESSURE,
    FRICTION,
    MOMENT,
    TIME,
    SPEED,
    CREEP,
];

/// The smallest and largest ratio of the contact size to the radius of curvature (Hertz
/// $a/R$) the planner accepts: below $10^{-6}$ the indentation $\delta \approx a^2/R$ is
/// below $10^{-12} R$, where the heights of the gap, measured from a radius-sized origin,
/// keep fewer than four digits in f64; above 0.3 the parabolic gap $r^2/(2R)$ of Hertz
/// theory differs from the circle by more than 2 % at the contact edge, so the contact is
/// no longer a Hertz (small-strain, half-space) contact.
pub const CONTACT_OVER_RADIUS: (f64, f64) = (1e-6, 0.3);

/// The smallest and largest mean contact pressure over the composite modulus accepted for
/// flat contacts (patches, punches, contacts given by semi-axes, flat or wavy surfaces):
/// above 0.1 the strains are beyond linear elasticity; below $10^{-12}$ the surface
/// displacements are below $10^{-12}$ of the contact size, where f64 keeps fewer than four
/// digits of them.
pub const PRESSURE_OVER_MODULUS: (f64, f64) = (1e-12, 0.1);

/// `v` is not subnormal: 0 or at least the smallest normal f64 in magnitude.
pub(crate) fn is_normal_or_zero(v: f64) -> bool {
    v == 0.0 || v.is_normal()
}
