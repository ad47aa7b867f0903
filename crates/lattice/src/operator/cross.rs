//! The cross influence operators of a lattice, for two dissimilar bodies (Dundurs
//! coupling): the normal displacement under shear traction and the tangential displacement
//! under pressure, free (zero-padded FFT of the exact rectangle kernels) or periodic (the
//! continuous Fourier transfers on the period, mean mode zero).

use super::{complex_fft2, fast_size, signed};
use rustfft::num_complex::Complex;
use rustfft::Fft;
use std::sync::Arc;
use stickslip_halfspace::rectangle::{
    pressure_displacement, shear_x_displacement, shear_y_displacement, Compliance, Rect,
};

type C64 = Complex<f64>;

/// The four cross-influence kernels of a lattice as zero-padded FFT convolutions.
pub struct CrossOperator {
    nx: usize,
    ny: usize,
    mx: usize,
    my: usize,
    row: [Arc<dyn Fft<f64>>; 2],
    col: [Arc<dyn Fft<f64>>; 2],
    /// Spectra of $K^{nx}$, $K^{ny}$, $K^{tn}_x$, $K^{tn}_y$ (scaled by $1/(M_xM_y)$).
    spec: [Vec<C64>; 4],
}

impl std::fmt::Debug for CrossOperator {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CrossOperator")
            .field("lattice", &(self.nx, self.ny))
            .field("fft_size", &(self.mx, self.my))
            .finish_non_exhaustive()
    }
}

impl CrossOperator {
    /// Plan the cross kernels of an `nx` × `ny` lattice of `cell = (hx, hy)` for the pair
    /// compliance `c` (`Compliance::pair(substrate, indenter)`).
    #[must_use]
    pub fn new(nx: usize, ny: usize, cell: (f64, f64), c: &Compliance) -> Self {
        let (hx, hy) = cell;
        let (mx, my) = (fast_size(2 * nx), fast_size(2 * ny));
        let row = [super::plans::forward(mx), super::plans::inverse(mx)];
        let col = [super::plans::forward(my), super::plans::inverse(my)];
        let rect = Rect { x1: -0.5 * hx, x2: 0.5 * hx, y1: -0.5 * hy, y2: 0.5 * hy };
        let mut lay = [(); 4].map(|()| vec![C64::new(0.0, 0.0); mx * my]);
        let (ix, iy) = (nx as isize, ny as isize);
        for dj in -(iy - 1)..iy {
            for di in -(ix - 1)..ix {
                let (x, y) = (di as f64 * hx, dj as f64 * hy);
                let sx = shear_x_displacement(c, &rect, x, y);
                let sy = shear_y_displacement(c, &rect, x, y);
                let pd = pressure_displacement(c, &rect, x, y);
                let a = di.rem_euclid(mx as isize) as usize;
                let b = dj.rem_euclid(my as isize) as usize;
                let idx = b * mx + a;
                for (l, v) in lay.iter_mut().zip([sx.z, sy.z, pd.x, pd.y]) {
                    l[idx] = C64::new(v, 0.0);
                }
            }
        }
        let mut op = Self { nx, ny, mx, my, row, col, spec: [vec![], vec![], vec![], vec![]] };
        let scale = 1.0 / (mx * my) as f64;
        for (s, mut l) in op.spec.iter_mut().zip(lay) {
            complex_fft2(&*op.row[0], &*op.col[0], mx, my, &mut l);
            for v in &mut l {
                *v *= scale;
            }
            *s = l;
        }
        op
    }

    /// The cross kernels of one period of a periodic surface (`nx` × `ny` cells of `cell`):
    /// the Fourier transfers of the point-force terms $u_x = -c_3x/(4\pi r^2)$ (pressure) and
    /// $u_z = c_3x/(4\pi r^2)$ (tangential force), with
    /// $\mathcal F[x/r^2] = -2\pi i k_x/|\mathbf k|^2$:
    /// $\hat K^{tn}_x = i c_3k_x/(2|\mathbf k|^2)$, $\hat K^{nx} = -i c_3k_x/(2|\mathbf k|^2)$
    /// (and the same with $k_y$), on the $n_x\times n_y$ torus (no padding), the mean mode
    /// zero. The same continuous transfers as the periodic normal and tangential operators.
    #[must_use]
    pub fn periodic(nx: usize, ny: usize, cell: (f64, f64), c: &Compliance) -> Self {
        let (mx, my) = (nx, ny);
        let row = [super::plans::forward(mx), super::plans::inverse(mx)];
        let col = [super::plans::forward(my), super::plans::inverse(my)];
        let (lx, ly) = (nx as f64 * cell.0, ny as f64 * cell.1);
        let two_pi = 2.0 * std::f64::consts::PI;
        let scale = 1.0 / (mx * my) as f64;
        let mut spec = [(); 4].map(|()| vec![C64::new(0.0, 0.0); mx * my]);
        for j in 0..my {
            let ky = two_pi * signed(j, my) / ly;
            for i in 0..mx {
                let kx = two_pi * signed(i, mx) / lx;
                let k2 = kx * kx + ky * ky;
                if k2 == 0.0 {
                    continue;
                }
                let f = 0.5 * c.one_minus_two_nu / k2 * scale;
                let idx = j * mx + i;
                spec[0][idx] = C64::new(0.0, -f * kx);
                spec[1][idx] = C64::new(0.0, -f * ky);
                spec[2][idx] = C64::new(0.0, f * kx);
                spec[3][idx] = C64::new(0.0, f * ky);
            }
        }
        Self { nx, ny, mx, my, row, col, spec }
    }

    fn padded(&self, a: &[f64]) -> Vec<C64> {
        let mut out = vec![C64::new(0.0, 0.0); self.mx * self.my];
        for j in 0..self.ny {
            for i in 0..self.nx {
                out[j * self.mx + i] = C64::new(a[j * self.nx + i], 0.0);
            }
        }
        complex_fft2(&*self.row[0], &*self.col[0], self.mx, self.my, &mut out);
        out
    }

    fn back(&self, mut s: Vec<C64>) -> Vec<f64> {
        complex_fft2(&*self.row[1], &*self.col[1], self.mx, self.my, &mut s);
        let mut out = vec![0.0; self.nx * self.ny];
        for j in 0..self.ny {
            for i in 0..self.nx {
                out[j * self.nx + i] = s[j * self.mx + i].re;
            }
        }
        out
    }

    /// The relative normal displacement $K^{nx}q_x + K^{ny}q_y$ (m) of lattice tractions
    /// (Pa, row-major).
    #[must_use]
    pub fn normal_from_traction(&self, qx: &[f64], qy: &[f64]) -> Vec<f64> {
        let (a, b) = (self.padded(qx), self.padded(qy));
        let s: Vec<C64> = a
            .iter()
            .zip(&b)
            .zip(self.spec[0].iter().zip(&self.spec[1]))
            .map(|((a, b), (kx, ky))| a * kx + b * ky)
            .collect();
        self.back(s)
    }

    /// The relative tangential displacement $(K^{tn}_xp, K^{tn}_yp)$ (m) of a lattice
    /// pressure (Pa, row-major).
    #[must_use]
    pub fn traction_from_pressure(&self, p: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let a = self.padded(p);
        let sx: Vec<C64> = a.iter().zip(&self.spec[2]).map(|(a, k)| a * k).collect();
        let sy: Vec<C64> = a.iter().zip(&self.spec[3]).map(|(a, k)| a * k).collect();
        (self.back(sx), self.back(sy))
    }
}
