//! The set-up the load-history examples share (`history_speed`, `warm_probe`): seed 002
//! Example 1's sphere (steel on steel, E = 30e6 psi, nu = 0.3, P = 2160 lbf, f = 0.1, the
//! Hertz radius from FORMULAS.md E) on a lattice of `across` cells over the contact
//! diameter, and the command line's first three arguments: cells across (default 128),
//! steps between corners (50) and the relative tolerance (1e-10).

use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
use stickslip_traction::{FastConfig, Tolerance};

/// The sphere, its lattice and the solver configuration of a history example.
pub struct HistoryBench {
    /// Cells across the contact diameter.
    pub across: usize,
    /// Steps between two corners of the path.
    pub per: usize,
    /// Relative tolerance of every solve.
    pub tol: f64,
    /// Normal load (lbf).
    pub p: f64,
    /// Coefficient of friction.
    pub f: f64,
    /// Both bodies' material.
    pub steel: Material,
    /// Hertz contact radius (in).
    pub a: f64,
    /// Cells inside the Hertz circle, with the Hertz pressure.
    pub grid: ContactGrid,
    /// The fast solver's configuration at `tol` (at most 100 Newton steps).
    pub config: FastConfig,
}

impl HistoryBench {
    /// From the command line (`across per tol`, each optional).
    pub fn from_args() -> Self {
        let arg = |i: usize| std::env::args().nth(i);
        let across: usize = arg(1).and_then(|a| a.parse().ok()).unwrap_or(128);
        let per: usize = arg(2).and_then(|a| a.parse().ok()).unwrap_or(50);
        let tol: f64 = arg(3).and_then(|a| a.parse().ok()).unwrap_or(1e-10);
        let (p, f) = (2160.0, 0.1);
        let steel = Material::new(30e6, 0.3).expect("material");
        let a = (3.0 * p * 2.0 * steel.normal_compliance() / 4.0).cbrt();
        let grid = ContactGrid::hertz_circle(a, p, across).expect("grid");
        let config = FastConfig::new(Tolerance::relative(tol).expect("tol"), 100).expect("config");
        Self { across, per, tol, p, f, steel, a, grid, config }
    }
}
