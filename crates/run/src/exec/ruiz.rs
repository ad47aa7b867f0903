//! The Ruiz fretting-damage parameter of a load path (Ruiz, Boddington & Chen 1984, *Exp.
//! Mech.* 24): per surface cell of the substrate, $\kappa = \max(\sigma_T, 0)\,|\mathbf q|$,
//! the tangential surface stress along the load direction (tension positive) times the
//! frictional shear, taken at the path's corners (its turning points, where both peak) and
//! kept at its largest; the parameter is $\kappa$ times the cell's slip range $\delta$:
//! $F_2 = \max_{\text{corners}}(\sigma_T\,\tau)\,\delta$ (Pa·J/m², i.e. Pa²·m: a stress times the frictional energy per area).
//!
//! The surface stress is that of the piecewise-constant traction on the history's lattice
//! (`stickslip_lattice::field`, exact rectangle stresses), evaluated at a depth of
//! $10^{-3}$ of a cell below the cell centres, where it equals the surface value at the
//! centre to about that fraction. The free boundary only: a periodic half-space at that
//! depth needs $(h/z)^2$ aliases per frequency, so periodic paths get no Ruiz map.

use stickslip_lattice::field::{
    Boundary as FieldBoundary, FieldOperator, Lattice as FieldLattice, SurfaceTraction,
};
use stickslip_lattice::ContactGrid;

use super::solver_err;
use stickslip_scene::SceneError;

/// Depth of the "surface" layer, in cells.
const DEPTH_IN_CELLS: f64 = 1e-3;

/// The running maximum of $\max(\sigma_T, 0)\,|\mathbf q|$ per grid cell.
pub(crate) struct RuizTracker {
    op: FieldOperator,
    cell: Vec<usize>,
    z: f64,
    /// Unit vector of the load direction.
    e: (f64, f64),
    kappa: Vec<f64>,
}

impl RuizTracker {
    /// On the lattice spanned by `grid`, for a substrate of Poisson ratio `nu`, the load
    /// along `angle` (rad from +x).
    pub fn new(grid: &ContactGrid, nu: f64, angle: f64) -> Result<Self, SceneError> {
        let (lattice, cell) =
            FieldLattice::from_grid(grid).map_err(|e| solver_err("Ruiz parameter lattice", e))?;
        let z = DEPTH_IN_CELLS * grid.hx.min(grid.hy);
        let op = FieldOperator::new(lattice, nu, FieldBoundary::Free)
            .map_err(|e| solver_err("Ruiz parameter surface stress", e))?;
        Ok(Self { op, cell, z, e: (angle.cos(), angle.sin()), kappa: vec![0.0; grid.len()] })
    }

    /// Take the state of one corner: the pressure and traction (on the substrate) of every
    /// grid cell.
    pub fn corner(&mut self, pressure: &[f64], traction: &[(f64, f64)]) -> Result<(), SceneError> {
        let s = self.surface_stress(pressure, traction)?;
        for (k, s) in s.iter().enumerate() {
            let q = traction[k].0.hypot(traction[k].1);
            self.kappa[k] = self.kappa[k].max(s.max(0.0) * q);
        }
        Ok(())
    }

    /// The surface stress along the load direction at every grid cell's centre (tension
    /// positive) under the given pressure and traction on the substrate.
    pub fn surface_stress(
        &self,
        pressure: &[f64],
        traction: &[(f64, f64)],
    ) -> Result<Vec<f64>, SceneError> {
        let lattice = self.op.lattice();
        let scatter = |v: Vec<f64>| {
            lattice.scatter(&self.cell, &v).map_err(|e| solver_err("Ruiz parameter", e))
        };
        let p = scatter(pressure.to_vec())?;
        let qx = scatter(traction.iter().map(|q| q.0).collect())?;
        let qy = scatter(traction.iter().map(|q| q.1).collect())?;
        let t = SurfaceTraction { p: &p, qx: &qx, qy: &qy };
        let field = self
            .op
            .compute(&t, &[self.z], false)
            .map_err(|e| solver_err("Ruiz parameter surface stress", e))?;
        let layer = &field.layers[0];
        let (ex, ey) = self.e;
        Ok(self
            .cell
            .iter()
            .map(|&c| layer.xx[c] * ex * ex + 2.0 * layer.xy[c] * ex * ey + layer.yy[c] * ey * ey)
            .collect())
    }

    /// The Ruiz parameter per grid cell: the largest $\sigma_T\tau$ times the slip range.
    pub fn parameter(&self, slip_range: &[f64]) -> Vec<f64> {
        self.kappa.iter().zip(slip_range).map(|(k, d)| k * d).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::RuizTracker;
    use stickslip_lattice::ContactGrid;

    /// The surface radial stress inside a Hertz circle (Johnson, Contact Mechanics, eq.
    /// 3.41a), $\sigma_r/p_0 = \frac{1-2\nu}{3}\frac{a^2}{r^2}\{1 - (1 - r^2/a^2)^{3/2}\} -
    /// (1 - r^2/a^2)^{1/2}$, on the x axis where $\sigma_{xx} = \sigma_r$: the stress the
    /// tracker reads at the cell centres of a 64-across lattice under the cell-sampled
    /// Hertz pressure.
    #[test]
    fn surface_stress_is_johnsons_radial_stress_under_hertz() {
        let (a, p0, nu) = (1e-3, 1e9, 0.3);
        let grid = ContactGrid::hertz_circle(a, 2.0 * std::f64::consts::PI * p0 * a * a / 3.0, 64)
            .unwrap();
        let t = RuizTracker::new(&grid, nu, 0.0).unwrap();
        let zero = vec![(0.0, 0.0); grid.len()];
        let s = t.surface_stress(&grid.pressure, &zero).unwrap();
        let h = grid.hx;
        let mut worst = 0.0f64;
        for (k, &sk) in s.iter().enumerate() {
            let (x, y) = (grid.x[k], grid.y[k]);
            // on the x axis, away from the centre and the edge by two cells
            if y.abs() > 0.6 * h || x.abs() < 2.0 * h || x.abs() > a - 2.0 * h {
                continue;
            }
            let u = (x / a).powi(2);
            let johnson =
                p0 * ((1.0 - 2.0 * nu) / 3.0 / u * (1.0 - (1.0 - u).powf(1.5)) - (1.0 - u).sqrt());
            worst = worst.max((sk - johnson).abs() / p0);
        }
        println!("surface sigma_xx on the axis against Johnson 3.41a: max error {worst:.3e} p0");
        // Measured 8.0e-4 p0: the cell sampling of the pressure, not the stress operator.
        assert!(worst < 2e-3, "{worst}");
    }
}
