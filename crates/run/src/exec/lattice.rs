//! The lattice of a 3D result: element-centre coordinates and the per-cell pressure,
//! traction and stick flag that result.json and the CSV files carry.

use super::outcome::SurfaceOut;

/// Lattice arrays, `p[i][j]` at (`x[i]`, `y[j]`).
#[derive(Debug, Clone)]
pub(crate) struct Lattice {
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    pub p: Vec<Vec<f64>>,
    pub qx: Vec<Vec<f64>>,
    pub qy: Vec<Vec<f64>>,
    /// 1 stick, 0 slip, -1 outside the contact.
    pub stick: Vec<Vec<i8>>,
    /// 3D rolling: micro-slip velocity (x, y) per cell (m/s).
    pub slip: Option<[Vec<Vec<f64>>; 2]>,
    /// A load path: energy dissipated per unit area over the path (J/m^2).
    pub dissipation: Option<Vec<Vec<f64>>>,
    /// A load path: slip range per cell (m).
    pub slip_range: Option<Vec<Vec<f64>>>,
    /// A load path on a free surface: the Ruiz parameter per cell (Pa·J/m²).
    pub ruiz: Option<Vec<Vec<f64>>>,
}

impl Lattice {
    /// `nx` x `ny` cells of `hx` x `hy` from the corner (`x0`, `y0`), all outside the contact.
    pub fn new(x0: f64, y0: f64, hx: f64, hy: f64, nx: usize, ny: usize) -> Self {
        Lattice {
            x: (0..nx).map(|i| x0 + (i as f64 + 0.5) * hx).collect(),
            y: (0..ny).map(|j| y0 + (j as f64 + 0.5) * hy).collect(),
            p: vec![vec![0.0; ny]; nx],
            qx: vec![vec![0.0; ny]; nx],
            qy: vec![vec![0.0; ny]; nx],
            stick: vec![vec![-1; ny]; nx],
            slip: None,
            dissipation: None,
            slip_range: None,
            ruiz: None,
        }
    }

    /// No cells (3D results without surface output).
    pub fn empty() -> Self {
        Lattice::new(0.0, 0.0, 1.0, 1.0, 0, 0)
    }

    /// The cell whose centre is nearest (`x`, `y`), if it lies on the lattice.
    pub fn index(&self, x: f64, y: f64) -> Option<(usize, usize)> {
        let hx = if self.x.len() > 1 { self.x[1] - self.x[0] } else { 1.0 };
        let hy = if self.y.len() > 1 { self.y[1] - self.y[0] } else { 1.0 };
        let i = ((x - self.x[0]) / hx).round();
        let j = ((y - self.y[0]) / hy).round();
        (i >= 0.0 && j >= 0.0 && (i as usize) < self.x.len() && (j as usize) < self.y.len())
            .then_some((i as usize, j as usize))
    }

    /// The lattice arrays as result.json's `surface`, with a surface's gap map.
    pub fn into_surface(self, gap: Option<Vec<Vec<f64>>>) -> SurfaceOut {
        let (slip_x, slip_y) = match self.slip {
            Some([sx, sy]) => (Some(sx), Some(sy)),
            None => (None, None),
        };
        SurfaceOut::Grid {
            slip_x,
            slip_y,
            x: self.x,
            y: self.y,
            p: self.p,
            qx: self.qx,
            qy: self.qy,
            stick: self.stick,
            gap,
            dissipation: self.dissipation,
            slip_amplitude: self.slip_range,
            ruiz: self.ruiz,
            plastic: None,
            plastic_displacement: None,
        }
    }
}
