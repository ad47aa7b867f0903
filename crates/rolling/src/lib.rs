//! Rolling contact with stick and slip: every rolling theory of stickslip, in 2D (plane
//! strain: Carter's elastic cylinders, Goryacheva's viscoelastic cylinder) and in 3D
//! (steady rolling of any contact patch with longitudinal and lateral creepage and spin).
//!
//! - [`carter`](mod@carter): elastic cylinders, closed form (half-width, stick zone, creep law, tractions).
//! - [`goryacheva`]: the viscoelastic problem of Goryacheva, PMM 37(5) 1973 (seed 001), in the
//!   corrected forms of `docs/FORMULAS.md` section D, solved through scaled
//!   equations that contain only the bounded ratios $I_1/I_0$ and $K_0/K_1$, with analytic
//!   brackets for both roots; pressure and shear (eqs 12, 13) by quadrature.
//! - [`steady3d`]: three-dimensional steady rolling on a contact grid: the exact theory
//!   ([`SteadyRolling`], semismooth Newton with FFT products), FASTSIM, Polach's law and
//!   Kalker's creepage coefficients.
//! - [`sweep`]: the seed's claim $l\approx\sqrt{8KRP\beta/\alpha}$ over its stated grid.
//!
//! ```
//! use stickslip_rolling::{carter, CarterParams};
//! // A steel wheel (R = 0.46 m) on steel, P = 500 kN/m, friction 0.3, creep 5e-4.
//! let p = CarterParams::new(210e9, 0.3, 0.46, 500e3, 0.3, 5e-4).unwrap();
//! let s = carter(&p);
//! // The stick zone is shorter than the contact, and the creep force below f P.
//! assert!(s.stick_length > 0.0 && s.stick_length < 2.0 * s.half_width);
//! assert!(s.tangential_force.abs() < 0.3 * 500e3);
//! // The normal load is carried: P = pi a p0 / 2 (Hertz).
//! assert!((std::f64::consts::PI * s.half_width * s.peak_pressure / 2.0 - 500e3).abs() < 1e-6);
//! ```
//!
//! Units are SI throughout: $E$ \[Pa\], $R$ and lengths \[m\], $P$ and $Q$ \[N/m\] (per unit length
//! of the cylinders), stresses \[Pa\], moments \[N\] (N·m per m), $\alpha, \beta$ \[s\], $w$ \[m/s\];
//! creep $\delta$, friction $\rho$ and $\nu$ are dimensionless.
//!
//! Sign conventions: the cylinder moves in $+x$, the contact is $(-a, b)$ with the trailing
//! edge at $-a$, slip at the trailing edge and stick at the leading edge; see [`carter`](mod@carter).
#![cfg_attr(docsrs, feature(doc_auto_cfg))]

pub mod carter;
mod error;
pub mod goryacheva;
mod kernel;
mod ratios;
mod roots;
pub mod steady3d;
pub mod sweep;

pub use carter::{carter, carter_creep_force, compliance, CarterParams, CarterSolution};
pub use error::{Error, Result};
pub use goryacheva::{
    contact_length, solve, ContactLength, GoryachevaParams, GoryachevaSolution, Response, SolveInfo,
};
pub use steady3d::{Creepage, RollingInfo, RollingMethod, RollingSolution, SteadyRolling};
pub use stickslip_quad::{Estimate, Tolerance};
pub use sweep::{claim_sweep, ClaimRow, SweepMaterial};

/// Which parts of the contact stick.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Regime {
    /// A slip zone at the trailing edge and a stick zone at the leading edge.
    StickSlip,
    /// No stick zone: $|Q| = \rho P$.
    FullSlip,
    /// The stick zone covers the whole contact ($\delta = 0$, $Q = 0$).
    FullStick,
}

/// Accuracy knob of the stress quadratures ([`GoryachevaSolution::pressure`],
/// [`GoryachevaSolution::shear`]).
///
/// The quadrature error is bounded by $\max(\text{abs}, \text{rel}\cdot S)$, where $S$ is the
/// integral of the absolute value of the integrand's terms (the natural stress scale at
/// that point, so that points where the stress passes through zero do not demand an
/// impossible relative accuracy).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StressConfig {
    /// Requested accuracy (`tol.rel()` is relative to the stress scale $S$).
    pub tol: Tolerance,
    /// Subdivision limit of the adaptive Gauss–Kronrod integrator.
    pub max_subdivisions: usize,
}

impl StressConfig {
    /// Relative tolerances the stress quadratures are meant for: below $10^{-14}$ the
    /// Gauss–Kronrod error estimate sits at the rounding level of the stress scale and
    /// cannot be promised; above $10^{-3}$ the pressure and shear are too rough to show.
    pub const TOLERANCE_RANGE: (f64, f64) = (1e-14, 1e-3);
}

impl Default for StressConfig {
    /// $10^{-12}$ relative, at most 200 subintervals.
    fn default() -> Self {
        StressConfig {
            tol: Tolerance::relative(1e-12).expect("1e-12 is a valid relative tolerance"),
            max_subdivisions: 200,
        }
    }
}
