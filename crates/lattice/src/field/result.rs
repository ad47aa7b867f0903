//! What a subsurface field computation returns: the stress layers, invariants and maxima.

use super::Lattice;
use std::f64::consts::PI;
use stickslip_halfspace::Stress3;

/// Stress invariants of one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Invariants {
    /// Principal stresses $\sigma_1 \ge \sigma_2 \ge \sigma_3$ (tension positive).
    pub principal: [f64; 3],
    /// Von Mises stress $\sqrt{\tfrac12[(\sigma_{xx}-\sigma_{yy})^2 + (\sigma_{yy}-
    /// \sigma_{zz})^2 + (\sigma_{zz}-\sigma_{xx})^2] + 3(\sigma_{xy}^2 + \sigma_{yz}^2 +
    /// \sigma_{xz}^2)}$.
    pub von_mises: f64,
    /// Tresca (maximum shear) stress $(\sigma_1 - \sigma_3)/2$.
    pub tresca: f64,
}

/// Principal stresses, von Mises and Tresca of a stress tensor. The eigenvalues of the
/// symmetric $3\times3$ tensor by the trigonometric closed form (Smith 1961, *Comm. ACM* 4,
/// 168): with $m = \mathrm{tr}\,\sigma/3$, $B = (\sigma - mI)/s$,
/// $s^2 = \tfrac16\|\sigma - mI\|_F^2$, $\theta = \tfrac13\arccos(\det B/2)$,
/// $\sigma_k = m + 2s\cos(\theta + 2\pi k/3)$; von Mises $= \sqrt{3J_2}$, $J_2 = 3s^2$.
#[must_use]
pub fn invariants(s: &Stress3) -> Invariants {
    let m = (s.xx + s.yy + s.zz) / 3.0;
    let (a, b, c) = (s.xx - m, s.yy - m, s.zz - m);
    let off = s.xy * s.xy + s.xz * s.xz + s.yz * s.yz;
    let j2 = (a * a + b * b + c * c) / 2.0 + off;
    let von_mises = (3.0 * j2).sqrt();
    let q = j2 / 3.0; // = s^2
    if q <= 0.0 {
        return Invariants { principal: [m, m, m], von_mises, tresca: 0.0 };
    }
    let sq = q.sqrt();
    let det = a * (b * c - s.yz * s.yz) - s.xy * (s.xy * c - s.yz * s.xz)
        + s.xz * (s.xy * s.yz - b * s.xz);
    let r = (det / (2.0 * sq * sq * sq)).clamp(-1.0, 1.0);
    let th = r.acos() / 3.0;
    let s1 = m + 2.0 * sq * th.cos();
    let s3 = m + 2.0 * sq * (th + 2.0 * PI / 3.0).cos();
    let s2 = 3.0 * m - s1 - s3;
    Invariants { principal: [s1, s2, s3], von_mises, tresca: 0.5 * (s1 - s3) }
}

/// The stress field of one depth layer: arrays over the lattice (index $j\,n_x + i$).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StressLayer {
    /// Depth $z$.
    pub z: f64,
    /// $\sigma_{xx}$.
    pub xx: Vec<f64>,
    /// $\sigma_{yy}$.
    pub yy: Vec<f64>,
    /// $\sigma_{zz}$.
    pub zz: Vec<f64>,
    /// $\sigma_{xy}$.
    pub xy: Vec<f64>,
    /// $\sigma_{xz}$.
    pub xz: Vec<f64>,
    /// $\sigma_{yz}$.
    pub yz: Vec<f64>,
    /// Von Mises stress.
    pub von_mises: Vec<f64>,
    /// Tresca (maximum shear) stress $(\sigma_1-\sigma_3)/2$.
    pub tresca: Vec<f64>,
    /// Largest principal stress $\sigma_1$ (tension positive).
    pub max_principal: Vec<f64>,
}

impl StressLayer {
    pub(super) fn zeros(z: f64, n: usize) -> Self {
        let v = || vec![0.0; n];
        Self {
            z,
            xx: v(),
            yy: v(),
            zz: v(),
            xy: v(),
            xz: v(),
            yz: v(),
            von_mises: v(),
            tresca: v(),
            max_principal: v(),
        }
    }

    /// The stress tensor at cell index `k`.
    ///
    /// # Panics
    /// If `k` is outside the lattice (an index error of the caller, not user input).
    #[must_use]
    pub fn stress(&self, k: usize) -> Stress3 {
        Stress3 {
            xx: self.xx[k],
            yy: self.yy[k],
            zz: self.zz[k],
            xy: self.xy[k],
            xz: self.xz[k],
            yz: self.yz[k],
        }
    }

    pub(super) fn comps_mut(&mut self) -> [&mut Vec<f64>; 6] {
        [&mut self.xx, &mut self.yy, &mut self.zz, &mut self.xy, &mut self.xz, &mut self.yz]
    }

    pub(super) fn fill_invariants(&mut self) {
        for k in 0..self.xx.len() {
            let inv = invariants(&self.stress(k));
            self.von_mises[k] = inv.von_mises;
            self.tresca[k] = inv.tresca;
            self.max_principal[k] = inv.principal[0];
        }
    }
}

/// Where a maximum over the box is reached.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Extremum {
    /// The maximum value.
    pub value: f64,
    /// Cell index $i$ along $x$.
    pub i: usize,
    /// Cell index $j$ along $y$.
    pub j: usize,
    /// Layer index.
    pub layer: usize,
    /// Cell centre $x$.
    pub x: f64,
    /// Cell centre $y$.
    pub y: f64,
    /// Depth $z$.
    pub z: f64,
}

/// The maxima of the derived quantities over the whole box (all cells, all layers).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldMaxima {
    /// Largest von Mises stress.
    pub von_mises: Extremum,
    /// Largest Tresca (maximum shear) stress.
    pub tresca: Extremum,
    /// Largest principal stress (the largest tension, or the least compression).
    pub max_principal: Extremum,
}

/// The subsurface stress field on a lattice at the requested depths.
#[derive(Debug, Clone, PartialEq)]
pub struct StressField {
    /// The lattice.
    pub lattice: Lattice,
    /// One layer per requested depth, in the order given.
    pub layers: Vec<StressLayer>,
}

impl StressField {
    /// Location and value of the maxima of von Mises, Tresca and the largest principal stress
    /// over all cells and layers (the first occurrence in layer, then cell order wins ties).
    #[must_use]
    pub fn maxima(&self) -> FieldMaxima {
        let l = &self.lattice;
        let find = |get: &dyn Fn(&StressLayer) -> &Vec<f64>| -> Extremum {
            let mut best = (f64::NEG_INFINITY, 0usize, 0usize);
            for (li, layer) in self.layers.iter().enumerate() {
                for (k, &v) in get(layer).iter().enumerate() {
                    if v > best.0 {
                        best = (v, li, k);
                    }
                }
            }
            let (value, layer, k) = best;
            let (i, j) = (k % l.nx, k / l.nx);
            let (x, y) = l.centre(i, j);
            let z = self.layers.get(layer).map_or(f64::NAN, |s| s.z);
            Extremum { value, i, j, layer, x, y, z }
        };
        FieldMaxima {
            von_mises: find(&|s| &s.von_mises),
            tresca: find(&|s| &s.tresca),
            max_principal: find(&|s| &s.max_principal),
        }
    }
}
