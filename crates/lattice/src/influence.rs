//! Tangential influence coefficients on a contact grid (seed 002 §3.3.2; FORMULAS.md F).
//!
//! For elements $k$ (field, at its centre) and $j$ (source, uniform traction over its
//! rectangle) the in-plane displacement per unit FORCE on $j$ is a $2\times2$ tensor
//! $U_{ab}$; for traction along unit vectors $t_j$ and displacement read along $t_k$ the
//! coefficient is $A_{kj} = t_k \cdot U \cdot t_j$ (FORMULAS.md F, tensor form).
//!
//! The elastic constants enter through [`Compliance`] ($c_1 = (1-\nu)/G$, $c_2 = \nu/G$):
//! one body's, or [`Compliance::pair`] for the relative displacement of two bodies, which is
//! the sum $A^{(1)} + A^{(2)}$ of the per-body matrices (a rigid body contributes zero). The
//! normal–tangential coupling ($c_3$) is neglected, as in Mindlin and the seed.

use crate::grid::ContactGrid;
use std::f64::consts::PI;
pub use stickslip_halfspace::rectangle::Compliance;
use stickslip_halfspace::rectangle::{shear_in_plane, Rect};

/// How the element-to-element coefficients are computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum InfluenceModel {
    /// Exact displacement at the field centre due to uniform traction on the whole source
    /// rectangle (FORMULAS.md F, element-to-point formula; halfspace `rectangle`).
    #[default]
    ExactRectangle,
    /// The seed's approximation: the Cerruti point load at the centre distance for
    /// $k \ne j$ (seed 002 §3.3.2), with the exact rectangle self-term $A_{kk}$ (the seed's
    /// missing $k = j$ formula; FORMULAS.md F).
    PointLoad,
}

/// The $2\times2$ displacement tensor at the centre of element `k` per unit force on element
/// `j`, as `[uxx, uxy, uyy]` (symmetric: $U_{xy} = U_{yx}$).
///
/// Exact model: $U = \frac{1}{h_xh_y}[u(\tau_x), u(\tau_y)]$ from the uniform-rectangle
/// formulas; point model ($k \ne j$):
/// $U_{ab} = \frac{c_1\delta_{ab} + c_2 r_ar_b/r^2}{2\pi r}$ (Cerruti; FORMULAS.md F).
#[must_use]
pub fn tensor(
    grid: &ContactGrid,
    c: &Compliance,
    model: InfluenceModel,
    k: usize,
    j: usize,
) -> [f64; 3] {
    let (hx, hy) = (grid.hx, grid.hy);
    let area = hx * hy;
    let dx = grid.x[k] - grid.x[j];
    let dy = grid.y[k] - grid.y[j];
    if model == InfluenceModel::PointLoad && k != j {
        let r2 = dx * dx + dy * dy;
        let r = r2.sqrt();
        let f = 1.0 / (2.0 * PI * r);
        return [
            f * (c.one_minus_nu + c.nu * dx * dx / r2),
            f * c.nu * dx * dy / r2,
            f * (c.one_minus_nu + c.nu * dy * dy / r2),
        ];
    }
    // Source rectangle centred at the origin, field point at the offset.
    let rect = Rect { x1: -0.5 * hx, x2: 0.5 * hx, y1: -0.5 * hy, y2: 0.5 * hy };
    // One pass of the kernel integrals for both shear directions (u_y under x-shear and u_x
    // under y-shear are the same integral).
    let [uxx, uxy, uyy] = shear_in_plane(c, &rect, dx, dy);
    [uxx / area, uxy / area, uyy / area]
}

/// Dense $N\times N$ matrix $A_{kj} = t_k\cdot U_{kj}\cdot t_j$ (row-major), with `dirs[k]`
/// the unit direction $(t_x, t_y)$ of element $k$ and $U_{kj}$ from [`tensor`] (FORMULAS.md F,
/// tensor form projected on the traction directions; seed 002 §3.3.2, there with all
/// $t_k = \hat x$).
///
/// On a uniform lattice $U_{kj}$ depends only on the lattice offset, so each distinct
/// offset is evaluated once (a map keyed by the integer offset).
#[must_use]
pub fn projected_matrix(
    grid: &ContactGrid,
    c: &Compliance,
    model: InfluenceModel,
    dirs: &[(f64, f64)],
) -> Vec<f64> {
    let n = grid.len();
    let cache = OffsetCache::new(grid, c, model);
    let mut a = vec![0.0; n * n];
    for k in 0..n {
        let (tkx, tky) = dirs[k];
        let row = &mut a[k * n..(k + 1) * n];
        for (j, v) in row.iter_mut().enumerate() {
            let [uxx, uxy, uyy] = cache.get(grid, k, j);
            let (tjx, tjy) = dirs[j];
            *v = tkx * (uxx * tjx + uxy * tjy) + tky * (uxy * tjx + uyy * tjy);
        }
    }
    a
}

/// The full $2N\times2N$ tensor matrix (row-major; unknown order
/// $(\tau_{0x}, \tau_{0y}, \tau_{1x}, \dots)$), used by the twist preprocessor: block $(k, j)$
/// is the symmetric $2\times2$ tensor $U_{kj}$ of [`tensor`] (FORMULAS.md F, tensor form).
#[must_use]
pub fn tensor_matrix(grid: &ContactGrid, c: &Compliance, model: InfluenceModel) -> Vec<f64> {
    let n = grid.len();
    let m = 2 * n;
    let cache = OffsetCache::new(grid, c, model);
    let mut a = vec![0.0; m * m];
    for k in 0..n {
        for j in 0..n {
            let [uxx, uxy, uyy] = cache.get(grid, k, j);
            a[2 * k * m + 2 * j] = uxx;
            a[2 * k * m + 2 * j + 1] = uxy;
            a[(2 * k + 1) * m + 2 * j] = uxy;
            a[(2 * k + 1) * m + 2 * j + 1] = uyy;
        }
    }
    a
}

/// Tensors by integer lattice offset (the grid is a uniform lattice).
struct OffsetCache {
    x0: f64,
    y0: f64,
    nx: i64,
    ny: i64,
    data: Vec<[f64; 3]>,
}

impl OffsetCache {
    fn new(grid: &ContactGrid, c: &Compliance, model: InfluenceModel) -> Self {
        let idx = |v: f64, v0: f64, h: f64| ((v - v0) / h).round() as i64;
        let x0 = grid.x.iter().copied().fold(f64::INFINITY, f64::min);
        let y0 = grid.y.iter().copied().fold(f64::INFINITY, f64::min);
        let nx = grid.x.iter().map(|&x| idx(x, x0, grid.hx)).max().unwrap_or(0) + 1;
        let ny = grid.y.iter().map(|&y| idx(y, y0, grid.hy)).max().unwrap_or(0) + 1;
        // Offsets (di, dj) in [-(nx-1), nx-1] x [-(ny-1), ny-1].
        let wx = 2 * nx - 1;
        let wy = 2 * ny - 1;
        let mut data = vec![[0.0; 3]; (wx * wy) as usize];
        // Evaluate with a two-element probe grid: field at the offset, source at the origin.
        let mut probe = ContactGrid {
            hx: grid.hx,
            hy: grid.hy,
            x: vec![0.0, 0.0],
            y: vec![0.0, 0.0],
            pressure: vec![0.0, 0.0],
            patch: vec![0, 0],
        };
        for dj in -(ny - 1)..ny {
            for di in -(nx - 1)..nx {
                probe.x[0] = di as f64 * grid.hx;
                probe.y[0] = dj as f64 * grid.hy;
                let (kk, jj) = if di == 0 && dj == 0 { (1, 1) } else { (0, 1) };
                let t = tensor(&probe, c, model, kk, jj);
                data[((dj + ny - 1) * wx + di + nx - 1) as usize] = t;
            }
        }
        Self { x0, y0, nx, ny, data }
    }

    fn get(&self, grid: &ContactGrid, k: usize, j: usize) -> [f64; 3] {
        let ix = |v: f64| ((v - self.x0) / grid.hx).round() as i64;
        let iy = |v: f64| ((v - self.y0) / grid.hy).round() as i64;
        let di = ix(grid.x[k]) - ix(grid.x[j]);
        let dj = iy(grid.y[k]) - iy(grid.y[j]);
        let wx = 2 * self.nx - 1;
        self.data[((dj + self.ny - 1) * wx + di + self.nx - 1) as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use stickslip_halfspace::Material;

    /// Square self-term: $(2-\nu)\ln(1+\sqrt2)/(\pi G h)$ (FORMULAS.md F).
    #[test]
    fn square_self_term() {
        let m = Material::new(30e6, 0.3).unwrap();
        let c = m.compliance();
        let g = ContactGrid::uniform_square(1.0, 1.0, 4).unwrap();
        let h = 0.25;
        let want = (2.0 - 0.3) * (1.0 + 2f64.sqrt()).ln() / (PI * m.shear_modulus() * h);
        for model in [InfluenceModel::ExactRectangle, InfluenceModel::PointLoad] {
            let t = tensor(&g, &c, model, 3, 3);
            assert!((t[0] / want - 1.0).abs() < 1e-14, "{} {}", t[0], want);
            assert!((t[2] / want - 1.0).abs() < 1e-14);
            assert!(t[1].abs() < 1e-14 * want);
        }
        // Nearest neighbour along x: point load is about -0.8 % off along x (FORMULAS.md F).
        let ex = tensor(&g, &c, InfluenceModel::ExactRectangle, 0, 1);
        let pt = tensor(&g, &c, InfluenceModel::PointLoad, 0, 1);
        let rel = pt[0] / ex[0] - 1.0;
        println!("nearest neighbour along the load: point/exact - 1 = {rel:.4e}");
        assert!((rel + 0.008).abs() < 0.002, "{rel}");
    }
}
