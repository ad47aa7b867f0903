//! Subsurface stresses under any surface traction on a lattice: the six stress components, von
//! Mises, Tresca and the largest principal stress at depths $z_1\dots z_m$ below every cell of
//! a uniform lattice carrying piecewise-constant pressure $p$ and shears $q_x$, $q_y$.
//!
//! # Conventions and units
//!
//! Any consistent units (SI in practice): lengths in one unit, tractions and stresses in
//! another. $x, y$ span the surface, $z > 0$ is the depth into the body; compression is
//! negative; $p > 0$ pushes into the body; $q_x$ ($q_y$) acts **on the body** along $+x$
//! ($+y$). So just below a loaded cell $\sigma_{zz} \approx -p$, $\sigma_{xz} \approx -q_x$,
//! $\sigma_{yz} \approx -q_y$. A sliding counter-body moving in $+x$ drags the surface with
//! $q_x = +fp$ (the leading edge is then at $+x$ and the surface tension peak at the trailing
//! edge $x = -a$).
//!
//! # Method
//!
//! Cell $(i, j)$ of the [`Lattice`] has centre $(x_0 + ih_x, y_0 + jh_y)$ and carries the
//! uniform traction $(p, q_x, q_y)_{ij}$. The stress at the centre of cell $k$ at depth $z$ is
//! the discrete convolution
//! $$\sigma_c(\mathbf i_k, z) = \sum_{t\in\{p, q_x, q_y\}}\sum_{\mathbf j}
//! K_{c,t}(\mathbf i_k - \mathbf j, z)\,t_{\mathbf j},$$
//! with $K_{c,t}$ the exact stress below a uniformly loaded rectangle of the half-space
//! (`stickslip_halfspace::rect_stress`: Love 1929 for $p$, Cerruti integrated in closed form
//! for $q_x, q_y$). The kernels are built once per depth from the corner antiderivatives at
//! the lattice nodes (every node is shared by four cells), completed from one quadrant by the
//! parity of each component, and transformed once; each depth costs $O(N\log N)$.
//!
//! - [`Boundary::Free`]: the half-space is not periodic. The kernel is laid out for offsets
//!   $-(n-1)\dots n-1$ on a circular array of size $M \ge 2n-1$ per axis and the tractions are
//!   zero-padded, so the circular convolution equals the linear one (Liu, Wang & Liu 2000,
//!   *Wear* 243, "DC-FFT"; as in [`crate::fast`]).
//! - [`Boundary::Periodic`]: the tractions repeat with period $(n_xh_x, n_yh_y)$. The kernel
//!   spectrum is the Fourier transfer of the half-space (Love's potential
//!   $\hat\Phi = 2\pi e^{-\kappa z}/\kappa^3$, $\kappa = |\mathbf k|$, times the transforms of
//!   the rectangle, $h_x\,\mathrm{sinc}(k_xh_x/2)\,h_y\,\mathrm{sinc}(k_yh_y/2)$), summed over
//!   the aliases $\mathbf k + 2\pi\mathbf m/\mathbf h$ (Poisson summation) until
//!   $e^{-\kappa z} < 10^{-17}$: the exact periodic sum of the rectangle kernels. The cost per
//!   depth grows like $(h/z)^2$ aliases per frequency, so shallow periodic layers
//!   ($z \ll h$) are slow. The mean traction's in-plane stresses
//!   ($\sigma_{xx}, \sigma_{yy}, \sigma_{xy}$ of the zero frequency) are not determined by a
//!   periodic half-space and are set to zero; its $\sigma_{zz} = -\bar p$,
//!   $\sigma_{xz} = -\bar q_x$, $\sigma_{yz} = -\bar q_y$ are exact.
//!
//! # Accuracy
//!
//! Exact for the piecewise-constant traction up to rounding: the FFT adds about
//! $\epsilon\log N$ relative to the largest stress, and the corner sums lose about
//! $\epsilon(d/h)^2$ relative to the (small) kernel entries at distance $d$. The test
//! `field.rs` checks the FFT against the dense sum of
//! `stickslip_halfspace::rect_stress::rect_stress` to $10^{-12}$ relative. The
//! discretisation error of representing a smooth traction by cell values is the caller's
//! (for the Hertz sphere sampled with 128 cells across the contact, about $10^{-3}$ relative
//! on the axis at depth $\gtrsim 0.1a$; see the tests).

use crate::error::{Error, Result};
use crate::grid::ContactGrid;
use rayon::prelude::*;
use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};
use std::f64::consts::PI;
use std::sync::Arc;
use stickslip_halfspace::rect_stress::{
    corner_derivatives, rect_stress, stress_from_potential, PotentialDerivatives, Traction,
};
use stickslip_halfspace::rectangle::Rect;
use stickslip_halfspace::Stress3;

type C64 = Complex<f64>;

/// A uniform lattice of $n_x\times n_y$ rectangular cells of sides $h_x, h_y$; cell $(i, j)$
/// has centre $(x_0 + ih_x, y_0 + jh_y)$ and index $j\,n_x + i$ in every array of this module.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lattice {
    /// Cells along $x$.
    pub nx: usize,
    /// Cells along $y$.
    pub ny: usize,
    /// Cell side along $x$.
    pub hx: f64,
    /// Cell side along $y$.
    pub hy: f64,
    /// Centre $x$ of cell $(0, 0)$.
    pub x0: f64,
    /// Centre $y$ of cell $(0, 0)$.
    pub y0: f64,
}

impl Lattice {
    /// A validated lattice.
    ///
    /// # Errors
    /// [`Error::EmptyGrid`] for zero cells; [`Error::OutOfDomain`] for non-positive or
    /// non-finite sides or a non-finite origin.
    pub fn new(nx: usize, ny: usize, hx: f64, hy: f64, x0: f64, y0: f64) -> Result<Self> {
        let l = Self { nx, ny, hx, hy, x0, y0 };
        l.validate()?;
        Ok(l)
    }

    fn validate(&self) -> Result<()> {
        if self.nx == 0 || self.ny == 0 {
            return Err(Error::EmptyGrid { reason: "the lattice has no cell" });
        }
        crate::error::positive("lattice cell side hx", self.hx)?;
        crate::error::positive("lattice cell side hy", self.hy)?;
        for (name, v) in [("lattice origin x0", self.x0), ("lattice origin y0", self.y0)] {
            if !v.is_finite() {
                return Err(Error::OutOfDomain { name, value: v, allowed: "finite" });
            }
        }
        Ok(())
    }

    /// Number of cells $n_xn_y$.
    #[must_use]
    pub fn len(&self) -> usize {
        self.nx * self.ny
    }

    /// Whether the lattice has no cell.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Centre $(x_0 + ih_x, y_0 + jh_y)$ of cell $(i, j)$.
    #[must_use]
    pub fn centre(&self, i: usize, j: usize) -> (f64, f64) {
        (self.x0 + i as f64 * self.hx, self.y0 + j as f64 * self.hy)
    }

    /// The lattice spanned by the elements of a contact grid, and the cell index of each
    /// element (so that `values[cell[k]] = element_value[k]`, see [`Lattice::scatter`]).
    ///
    /// # Errors
    /// [`Error::EmptyGrid`] for an empty grid; [`Error::OutOfDomain`] if an element centre is
    /// off the lattice of spacing $(h_x, h_y)$ through the lowest centres (by more than
    /// $10^{-6}$ cells) or two elements share a cell.
    pub fn from_grid(grid: &ContactGrid) -> Result<(Self, Vec<usize>)> {
        let n = grid.len();
        if n == 0 {
            return Err(Error::EmptyGrid { reason: "the grid has no element" });
        }
        let x0 = grid.x.iter().copied().fold(f64::INFINITY, f64::min);
        let y0 = grid.y.iter().copied().fold(f64::INFINITY, f64::min);
        let mut idx = Vec::with_capacity(n);
        for k in 0..n {
            let fi = (grid.x[k] - x0) / grid.hx;
            let fj = (grid.y[k] - y0) / grid.hy;
            let (i, j) = (fi.round(), fj.round());
            if !((fi - i).abs() <= 1e-6 && (fj - j).abs() <= 1e-6) {
                return Err(Error::OutOfDomain {
                    name: "element centre offset from the lattice (cells)",
                    value: (fi - i).abs().max((fj - j).abs()),
                    allowed: "<= 1e-6: all centres on one lattice of spacing (hx, hy)",
                });
            }
            idx.push((i as usize, j as usize));
        }
        let nx = idx.iter().map(|p| p.0).max().unwrap_or(0) + 1;
        let ny = idx.iter().map(|p| p.1).max().unwrap_or(0) + 1;
        let cell: Vec<usize> = idx.iter().map(|&(i, j)| j * nx + i).collect();
        let mut seen = vec![false; nx * ny];
        for (k, &c) in cell.iter().enumerate() {
            if seen[c] {
                return Err(Error::OutOfDomain {
                    name: "element sharing a lattice cell (index)",
                    value: k as f64,
                    allowed: "one element per lattice cell",
                });
            }
            seen[c] = true;
        }
        Ok((Self::new(nx, ny, grid.hx, grid.hy, x0, y0)?, cell))
    }

    /// Lattice array (zero in cells without an element) from per-element values and the
    /// cell map of [`Lattice::from_grid`].
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] if `values` and `cell` differ in length;
    /// [`Error::OutOfDomain`] if a cell index is outside the lattice.
    pub fn scatter(&self, cell: &[usize], values: &[f64]) -> Result<Vec<f64>> {
        if values.len() != cell.len() {
            return Err(Error::LengthMismatch {
                name: "element values",
                expected: cell.len(),
                got: values.len(),
            });
        }
        let mut out = vec![0.0; self.len()];
        for (&c, &v) in cell.iter().zip(values) {
            if c >= out.len() {
                return Err(Error::OutOfDomain {
                    name: "cell index",
                    value: c as f64,
                    allowed: "< nx * ny",
                });
            }
            out[c] = v;
        }
        Ok(out)
    }
}

/// The surface traction per lattice cell (index $j\,n_x + i$): pressure `p` (into the body)
/// and shears `qx`, `qy` on the body. An empty slice means zero everywhere (and saves that
/// load's kernels); otherwise each has length $n_xn_y$.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SurfaceTraction<'a> {
    /// Pressure per cell.
    pub p: &'a [f64],
    /// Shear along $+x$ per cell.
    pub qx: &'a [f64],
    /// Shear along $+y$ per cell.
    pub qy: &'a [f64],
}

impl SurfaceTraction<'_> {
    fn parts(&self) -> [&[f64]; 3] {
        [self.p, self.qx, self.qy]
    }

    fn validate(&self, n: usize) -> Result<()> {
        for (name, v) in [("p", self.p), ("qx", self.qx), ("qy", self.qy)] {
            if !v.is_empty() && v.len() != n {
                return Err(Error::LengthMismatch { name, expected: n, got: v.len() });
            }
            if let Some(bad) = v.iter().find(|x| !x.is_finite()) {
                return Err(Error::OutOfDomain { name, value: *bad, allowed: "finite" });
            }
        }
        Ok(())
    }
}

/// Boundary condition of the lattice in the surface plane.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Boundary {
    /// The loaded lattice is all there is; the half-space beyond it is traction free
    /// (zero-padded, aperiodic convolution).
    #[default]
    Free,
    /// The traction repeats with the lattice's period in $x$ and $y$.
    Periodic,
}

/// Options of [`subsurface_field`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FieldConfig {
    /// Free or periodic lattice.
    pub boundary: Boundary,
    /// Process depth layers in parallel with rayon (one layer per task).
    pub parallel: bool,
}

impl Default for FieldConfig {
    fn default() -> Self {
        Self { boundary: Boundary::Free, parallel: true }
    }
}

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
    fn zeros(z: f64, n: usize) -> Self {
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

    fn comps_mut(&mut self) -> [&mut Vec<f64>; 6] {
        [&mut self.xx, &mut self.yy, &mut self.zz, &mut self.xy, &mut self.xz, &mut self.yz]
    }

    fn fill_invariants(&mut self) {
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

/// Tile side of the blocked transposes.
const TILE: usize = 32;

/// `dst[i * ld + j] = src[j * cols + i]` for `j < rows`, `i < cols` (blocked).
fn transpose(src: &[C64], rows: usize, cols: usize, dst: &mut [C64], ld: usize) {
    for jb in (0..rows).step_by(TILE) {
        for ib in (0..cols).step_by(TILE) {
            for j in jb..(jb + TILE).min(rows) {
                for i in ib..(ib + TILE).min(cols) {
                    dst[i * ld + j] = src[j * cols + i];
                }
            }
        }
    }
}

/// `dst[j * cols + i] = src[i * ld + j]` for `j < rows`, `i < cols` (blocked).
fn transpose_rows(src: &[C64], cols: usize, ld: usize, rows: usize, dst: &mut [C64]) {
    for ib in (0..cols).step_by(TILE) {
        for jb in (0..rows).step_by(TILE) {
            for i in ib..(ib + TILE).min(cols) {
                for j in jb..(jb + TILE).min(rows) {
                    dst[j * cols + i] = src[i * ld + j];
                }
            }
        }
    }
}

/// Smallest even 5-smooth integer $\ge n$ (fast FFT sizes).
fn fast_size(n: usize) -> usize {
    let mut m = n.max(2);
    loop {
        if m % 2 == 0 {
            let mut r = m;
            for p in [2, 3, 5] {
                while r % p == 0 {
                    r /= p;
                }
            }
            if r == 1 {
                return m;
            }
        }
        m += 1;
    }
}

/// Component order of the kernels: xx, yy, zz, xy, xz, yz as index pairs (0 = x, 1 = y,
/// 2 = z).
const PAIRS: [(usize, usize); 6] = [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)];

/// Parity of kernel $K_{c,t}$ in $x$ and $y$ (true = odd): the number of $x$ (or $y$) among
/// the component's indices and the load's direction ($p$ is along $z$), modulo 2 (the
/// reflection $x \to -x$ flips each $x$ index once).
fn parity(c: usize, t: usize) -> (bool, bool) {
    let (i, j) = PAIRS[c];
    let cnt = |ax: usize| {
        usize::from(i == ax)
            + usize::from(j == ax)
            + usize::from((t == 1 && ax == 0) || (t == 2 && ax == 1))
    };
    (cnt(0) % 2 == 1, cnt(1) % 2 == 1)
}

/// The linear map from the 25 potential derivatives to the six stresses, per load
/// (0 = $p$, 1 = $q_x$, 2 = $q_y$), at one depth: sparse rows of (slot, coefficient), slots
/// 0..10 third, 10..25 fourth derivatives.
struct StressMap {
    rows: [[Vec<(usize, f64)>; 6]; 3],
}

impl StressMap {
    fn new(nu: f64, z: f64) -> Self {
        let loads = [Traction::PRESSURE, Traction::SHEAR_X, Traction::SHEAR_Y];
        let mut rows: [[Vec<(usize, f64)>; 6]; 3] = Default::default();
        for s in 0..25 {
            let mut d = PotentialDerivatives::default();
            if s < 10 {
                d.d3[s] = 1.0;
            } else {
                d.d4[s - 10] = 1.0;
            }
            for (t, load) in loads.iter().enumerate() {
                let st = stress_from_potential(nu, z, load, &d);
                for (c, v) in [st.xx, st.yy, st.zz, st.xy, st.xz, st.yz].into_iter().enumerate() {
                    if v != 0.0 {
                        rows[t][c].push((s, v));
                    }
                }
            }
        }
        Self { rows }
    }

    #[inline]
    fn apply(&self, t: usize, c: usize, d: &[f64; 25]) -> f64 {
        self.rows[t][c].iter().map(|&(s, v)| v * d[s]).sum()
    }
}

fn flat(d: &PotentialDerivatives) -> [f64; 25] {
    let mut o = [0.0; 25];
    o[..10].copy_from_slice(&d.d3);
    o[10..].copy_from_slice(&d.d4);
    o
}

/// The kernel spectra of one depth: for each load present and each component, the real
/// or imaginary part of the 2D DFT (the other part is zero by parity), layout
/// `[i * my + j]`, $i < M_x/2+1$.
pub struct LayerKernel {
    z: f64,
    /// `spec[t][c]`: `None` if load `t` is absent.
    spec: [[Option<Vec<f64>>; 6]; 3],
}

impl std::fmt::Debug for LayerKernel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LayerKernel").field("z", &self.z).finish_non_exhaustive()
    }
}

impl LayerKernel {
    /// The depth of the layer.
    #[must_use]
    pub fn depth(&self) -> f64 {
        self.z
    }
}

/// Forward spectra of the surface traction (zero-padded for [`Boundary::Free`]), built once
/// and shared by all layers.
#[derive(Debug, Clone)]
pub struct LoadSpectra {
    spec: [Option<Vec<C64>>; 3],
}

/// Caller-owned work space of [`FieldOperator::apply`] and [`FieldOperator::layer_kernel`].
#[derive(Debug, Clone)]
pub struct FieldScratch {
    lat: Vec<f64>,
    row: Vec<f64>,
    rowspec: Vec<C64>,
    spec: Vec<C64>,
    acc: Vec<C64>,
    r2c: Vec<C64>,
    c2r: Vec<C64>,
    col: Vec<C64>,
    quad: [[Vec<f64>; 6]; 3],
    nodes: [Vec<[f64; 25]>; 2],
}

/// The planned subsurface-field operator of one lattice and material: FFT plans, sizes and
/// the boundary condition. Kernels are built per depth ([`FieldOperator::layer_kernel`]).
pub struct FieldOperator {
    lattice: Lattice,
    nu: f64,
    boundary: Boundary,
    mx: usize,
    my: usize,
    mxh: usize,
    r2c: Arc<dyn RealToComplex<f64>>,
    c2r: Arc<dyn ComplexToReal<f64>>,
    col_fwd: Arc<dyn Fft<f64>>,
    col_inv: Arc<dyn Fft<f64>>,
}

impl std::fmt::Debug for FieldOperator {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("FieldOperator")
            .field("lattice", &self.lattice)
            .field("nu", &self.nu)
            .field("boundary", &self.boundary)
            .field("fft", &(self.mx, self.my))
            .finish_non_exhaustive()
    }
}

fn check_depth(z: f64) -> Result<f64> {
    if z.is_finite() && z > 0.0 {
        Ok(z)
    } else {
        Err(Error::OutOfDomain { name: "depth z", value: z, allowed: "finite and > 0" })
    }
}

fn check_nu(nu: f64) -> Result<f64> {
    if nu.is_finite() && nu > -1.0 && nu <= 0.5 {
        Ok(nu)
    } else {
        Err(Error::OutOfDomain { name: "Poisson ratio nu", value: nu, allowed: "-1 < nu <= 0.5" })
    }
}

impl FieldOperator {
    /// Plan the operator of `lattice` for Poisson ratio $\nu$ (only $\nu$ enters the
    /// stresses of prescribed tractions) and the boundary condition.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for $\nu \notin (-1, 1/2]$ or a bad lattice;
    /// [`Error::EmptyGrid`] for an empty lattice.
    pub fn new(lattice: Lattice, nu: f64, boundary: Boundary) -> Result<Self> {
        lattice.validate()?;
        check_nu(nu)?;
        let (mx, my) = match boundary {
            Boundary::Free => (fast_size(2 * lattice.nx - 1), fast_size(2 * lattice.ny - 1)),
            Boundary::Periodic => (lattice.nx, lattice.ny),
        };
        let mut rplan = RealFftPlanner::<f64>::new();
        let mut cplan = FftPlanner::<f64>::new();
        Ok(Self {
            lattice,
            nu,
            boundary,
            mx,
            my,
            mxh: mx / 2 + 1,
            r2c: rplan.plan_fft_forward(mx),
            c2r: rplan.plan_fft_inverse(mx),
            col_fwd: cplan.plan_fft_forward(my),
            col_inv: cplan.plan_fft_inverse(my),
        })
    }

    /// The lattice.
    #[must_use]
    pub fn lattice(&self) -> Lattice {
        self.lattice
    }

    /// FFT size $(M_x, M_y)$: the smallest even 5-smooth sizes $\ge 2n-1$ (free) or $n$
    /// (periodic).
    #[must_use]
    pub fn fft_size(&self) -> (usize, usize) {
        (self.mx, self.my)
    }

    /// Work space for [`FieldOperator::apply`] and [`FieldOperator::layer_kernel`].
    #[must_use]
    pub fn make_scratch(&self) -> FieldScratch {
        let z = C64::new(0.0, 0.0);
        FieldScratch {
            lat: vec![0.0; self.mx * self.my],
            row: vec![0.0; self.mx],
            rowspec: vec![z; self.my * self.mxh],
            spec: vec![z; self.mxh * self.my],
            acc: vec![z; self.mxh * self.my],
            r2c: self.r2c.make_scratch_vec(),
            c2r: self.c2r.make_scratch_vec(),
            col: vec![
                z;
                self.col_fwd
                    .get_inplace_scratch_len()
                    .max(self.col_inv.get_inplace_scratch_len())
            ],
            quad: Default::default(),
            nodes: Default::default(),
        }
    }

    /// 2D real forward FFT of `lat` (row-major $M_y\times M_x$, rows `rows..` zero) into
    /// `s.spec` (layout `[i * my + j]`).
    fn forward(&self, lat: &[f64], rows: usize, s: &mut FieldScratch) {
        self.forward_rows(lat, rows, s);
        self.forward_cols(rows, s);
    }

    /// Row FFTs of the first `rows` rows of `lat` into `s.rowspec`.
    fn forward_rows(&self, lat: &[f64], rows: usize, s: &mut FieldScratch) {
        let (mx, mxh) = (self.mx, self.mxh);
        for j in 0..rows {
            s.row.copy_from_slice(&lat[j * mx..(j + 1) * mx]);
            // Lengths are consistent by construction; realfft only errs on lengths.
            let _ = self.r2c.process_with_scratch(
                &mut s.row,
                &mut s.rowspec[j * mxh..(j + 1) * mxh],
                &mut s.r2c,
            );
        }
    }

    /// Column FFTs of the first `rows` rows of `s.rowspec` (the rest zero) into `s.spec`.
    fn forward_cols(&self, rows: usize, s: &mut FieldScratch) {
        let (my, mxh) = (self.my, self.mxh);
        // Blocked transpose rowspec[j * mxh + i] -> spec[i * my + j] (cache friendly).
        for i in 0..mxh {
            s.spec[i * my + rows..(i + 1) * my].fill(C64::new(0.0, 0.0));
        }
        transpose(&s.rowspec[..rows * mxh], rows, mxh, &mut s.spec, my);
        self.col_fwd.process_with_scratch(&mut s.spec, &mut s.col);
    }

    /// Inverse of [`Self::forward`] of `s.acc` for the first $n_y$ rows and $n_x$ columns,
    /// scaled by $1/(M_xM_y)$, into `out` (row-major $n_y\times n_x$).
    fn inverse(&self, s: &mut FieldScratch, out: &mut [f64]) {
        let (mx, my, mxh) = (self.mx, self.my, self.mxh);
        let (nx, ny) = (self.lattice.nx, self.lattice.ny);
        self.col_inv.process_with_scratch(&mut s.acc, &mut s.col);
        let scale = 1.0 / (mx as f64 * my as f64);
        // Blocked transpose of the first ny rows: acc[i * my + j] -> rowspec[j * mxh + i].
        transpose_rows(&s.acc, mxh, my, ny, &mut s.rowspec);
        for j in 0..ny {
            let rs = &mut s.rowspec[j * mxh..(j + 1) * mxh];
            // The DC (and, for even sizes, Nyquist) bins of a real signal are real.
            rs[0].im = 0.0;
            if mx % 2 == 0 {
                rs[mxh - 1].im = 0.0;
            }
            let _ = self.c2r.process_with_scratch(rs, &mut s.row, &mut s.c2r);
            for (o, r) in out[j * nx..(j + 1) * nx].iter_mut().zip(&s.row) {
                *o = r * scale;
            }
        }
    }

    /// Forward spectra of the traction (checked against the lattice).
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] if a non-empty array is not of length $n_xn_y$;
    /// [`Error::OutOfDomain`] for a non-finite value.
    pub fn load_spectra(
        &self,
        t: &SurfaceTraction<'_>,
        s: &mut FieldScratch,
    ) -> Result<LoadSpectra> {
        let (nx, ny, mx) = (self.lattice.nx, self.lattice.ny, self.mx);
        t.validate(nx * ny)?;
        let mut spec: [Option<Vec<C64>>; 3] = [None, None, None];
        for (k, part) in t.parts().into_iter().enumerate() {
            if part.is_empty() {
                continue;
            }
            s.lat.fill(0.0);
            for j in 0..ny {
                s.lat[j * mx..j * mx + nx].copy_from_slice(&part[j * nx..(j + 1) * nx]);
            }
            let lat = std::mem::take(&mut s.lat);
            self.forward(&lat, ny, s);
            s.lat = lat;
            spec[k] = Some(s.spec.clone());
        }
        Ok(LoadSpectra { spec })
    }

    /// The kernel spectra of depth $z$ for the loads present in `loads`
    /// (`[p, qx, qy]`): free lattices from the exact rectangle stresses at all offsets
    /// (corner antiderivatives at the lattice nodes, one quadrant, completed by parity), then
    /// one FFT per kernel; periodic lattices from the alias-summed Fourier transfer (module
    /// documentation).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a depth that is not finite and positive.
    pub fn layer_kernel(
        &self,
        z: f64,
        loads: [bool; 3],
        s: &mut FieldScratch,
    ) -> Result<LayerKernel> {
        let mut k = LayerKernel { z, spec: Default::default() };
        self.layer_kernel_into(z, loads, &mut k, s)?;
        Ok(k)
    }

    /// [`FieldOperator::layer_kernel`] into an existing kernel, reusing its buffers (no
    /// allocation after the first layer of a worker).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a depth that is not finite and positive.
    pub fn layer_kernel_into(
        &self,
        z: f64,
        loads: [bool; 3],
        kernel: &mut LayerKernel,
        s: &mut FieldScratch,
    ) -> Result<()> {
        check_depth(z)?;
        let map = StressMap::new(self.nu, z);
        kernel.z = z;
        let n = self.mxh * self.my;
        for (kt, &on) in kernel.spec.iter_mut().zip(&loads) {
            for kc in kt.iter_mut() {
                if !on {
                    *kc = None;
                } else if kc.as_ref().is_none_or(|v| v.len() != n) {
                    *kc = Some(vec![0.0; n]);
                }
            }
        }
        match self.boundary {
            Boundary::Free => self.free_kernel(z, loads, &map, s, &mut kernel.spec),
            Boundary::Periodic => self.periodic_kernel(z, loads, &map, &mut kernel.spec),
        }
        Ok(())
    }

    fn free_kernel(
        &self,
        z: f64,
        loads: [bool; 3],
        map: &StressMap,
        s: &mut FieldScratch,
        out: &mut [[Option<Vec<f64>>; 6]; 3],
    ) {
        let Lattice { nx, ny, hx, hy, .. } = self.lattice;
        let (mx, my) = (self.mx, self.my);
        // Quadrant kernels K[t][c][dj * nx + di], offsets di, dj >= 0 (scratch buffers).
        let mut quad = std::mem::take(&mut s.quad);
        for (t, q) in quad.iter_mut().enumerate() {
            if loads[t] {
                for v in q.iter_mut() {
                    v.resize(nx * ny, 0.0);
                }
            }
        }
        // Nodes at X = (u - 1/2) hx, u = 0..=nx; two rows of nodes at a time.
        let node_row = |v: usize, row: &mut Vec<[f64; 25]>| {
            let y = (v as f64 - 0.5) * hy;
            row.clear();
            row.extend((0..=nx).map(|u| flat(&corner_derivatives((u as f64 - 0.5) * hx, y, z))));
        };
        let mut lo = std::mem::take(&mut s.nodes[0]);
        let mut hi = std::mem::take(&mut s.nodes[1]);
        node_row(0, &mut lo);
        for dj in 0..ny {
            node_row(dj + 1, &mut hi);
            for di in 0..nx {
                // X1 = (di + 1/2) hx (node di + 1), X2 = (di - 1/2) hx (node di); same in y.
                let mut d = [0.0; 25];
                for (k, v) in d.iter_mut().enumerate() {
                    *v = hi[di + 1][k] - lo[di + 1][k] - hi[di][k] + lo[di][k];
                }
                for (t, q) in quad.iter_mut().enumerate() {
                    if !loads[t] {
                        continue;
                    }
                    for (c, qc) in q.iter_mut().enumerate() {
                        qc[dj * nx + di] = map.apply(t, c, &d);
                    }
                }
            }
            std::mem::swap(&mut lo, &mut hi);
        }
        s.nodes = [lo, hi];
        for t in 0..3 {
            if !loads[t] {
                continue;
            }
            for c in 0..6 {
                let (ox, oy) = parity(c, t);
                let k = &quad[t][c];
                // Rows dj = 0..ny, mirrored in x with the x parity; odd kernels vanish on
                // their zero-offset column (and row), exactly.
                for dj in 0..ny {
                    let row = &mut s.lat[dj * mx..(dj + 1) * mx];
                    row.fill(0.0);
                    if oy && dj == 0 {
                        continue;
                    }
                    for di in 0..nx {
                        let v = k[dj * nx + di];
                        row[di] = v;
                        row[(mx - di) % mx] = if ox { -v } else { v };
                    }
                    if ox {
                        row[0] = 0.0;
                    }
                }
                let lat = std::mem::take(&mut s.lat);
                self.forward_rows(&lat, ny, s);
                s.lat = lat;
                // Rows my - dj are the rows dj times the y parity (their row FFTs too), and
                // the rows in between are zero.
                let mxh = self.mxh;
                for dj in 1..ny {
                    let (lo, hi) = s.rowspec.split_at_mut((my - dj) * mxh);
                    let src = &lo[dj * mxh..(dj + 1) * mxh];
                    for (d, v) in hi[..mxh].iter_mut().zip(src) {
                        *d = if oy { -v } else { *v };
                    }
                }
                s.rowspec[ny * mxh..(my - ny + 1) * mxh].fill(C64::new(0.0, 0.0));
                self.forward_cols(my, s);
                let imag = ox ^ oy;
                if let Some(o) = out[t][c].as_mut() {
                    for (o, v) in o.iter_mut().zip(&s.spec) {
                        *o = if imag { v.im } else { v.re };
                    }
                }
            }
        }
        s.quad = quad;
    }

    fn periodic_kernel(
        &self,
        z: f64,
        loads: [bool; 3],
        map: &StressMap,
        out: &mut [[Option<Vec<f64>>; 6]; 3],
    ) {
        let Lattice { nx, ny, hx, hy, .. } = self.lattice;
        let (my, mxh) = (self.my, self.mxh);
        // Aliases: e^{-kappa z} < 1e-17 beyond |k| > 40/z, i.e. |m| > 40 h/(2 pi z) + 1.
        let mmx = (40.0 * hx / (2.0 * PI * z)).ceil() as i64 + 1;
        let mmy = (40.0 * hy / (2.0 * PI * z)).ceil() as i64 + 1;
        let kcut = 40.0 / z;
        let sinc = |u: f64| if u == 0.0 { 1.0 } else { u.sin() / u };
        for i in 0..mxh {
            let kx0 = 2.0 * PI * i as f64 / (nx as f64 * hx);
            for j in 0..my {
                let jj = if 2 * j <= my { j as f64 } else { j as f64 - my as f64 };
                let ky0 = 2.0 * PI * jj / (ny as f64 * hy);
                let mut acc = [[[0.0f64; 2]; 6]; 3];
                for mx_ in -mmx..=mmx {
                    let kx = kx0 + 2.0 * PI * mx_ as f64 / hx;
                    if kx.abs() > kcut {
                        continue;
                    }
                    for my_ in -mmy..=mmy {
                        let ky = ky0 + 2.0 * PI * my_ as f64 / hy;
                        let kappa = kx.hypot(ky);
                        if kappa > kcut {
                            continue;
                        }
                        let w = sinc(0.5 * kx * hx) * sinc(0.5 * ky * hy);
                        if kappa == 0.0 {
                            // Mean traction: sigma_zz = -p, sigma_xz = -qx, sigma_yz = -qy;
                            // in-plane stresses undetermined, set to zero.
                            acc[0][2][0] -= w;
                            acc[1][4][0] -= w;
                            acc[2][5][0] -= w;
                            continue;
                        }
                        // d^alpha Phi = (i kx)^a (i ky)^b (-kappa)^c 2 pi e^{-kappa z}/kappa^3.
                        let base = 2.0 * PI * (-kappa * z).exp() / (kappa * kappa * kappa) * w;
                        let mut dre = [0.0; 25];
                        let mut dim = [0.0; 25];
                        let mut slot = 0;
                        for n in [3usize, 4] {
                            for a in (0..=n).rev() {
                                for b in (0..=n - a).rev() {
                                    let c = n - a - b;
                                    let v = base
                                        * kx.powi(a as i32)
                                        * ky.powi(b as i32)
                                        * (-kappa).powi(c as i32);
                                    match (a + b) % 4 {
                                        0 => dre[slot] = v,
                                        1 => dim[slot] = v,
                                        2 => dre[slot] = -v,
                                        _ => dim[slot] = -v,
                                    }
                                    slot += 1;
                                }
                            }
                        }
                        for (t, at) in acc.iter_mut().enumerate() {
                            if !loads[t] {
                                continue;
                            }
                            for (c, ac) in at.iter_mut().enumerate() {
                                ac[0] += map.apply(t, c, &dre);
                                ac[1] += map.apply(t, c, &dim);
                            }
                        }
                    }
                }
                for t in 0..3 {
                    for c in 0..6 {
                        if let Some(v) = out[t][c].as_mut() {
                            let (ox, oy) = parity(c, t);
                            v[i * my + j] = acc[t][c][usize::from(ox ^ oy)];
                        }
                    }
                }
            }
        }
    }

    /// The stresses of one layer: for each component the spectrum
    /// $\sum_t\hat K_{c,t}\hat t$, inverse transformed, then the invariants.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] if the kernel lacks a load that `load` has (build the kernel
    /// with the loads present).
    pub fn apply(
        &self,
        kernel: &LayerKernel,
        load: &LoadSpectra,
        s: &mut FieldScratch,
    ) -> Result<StressLayer> {
        let n = self.lattice.len();
        let mut layer = StressLayer::zeros(kernel.z, n);
        for (t, l) in load.spec.iter().enumerate() {
            if l.is_some() && kernel.spec[t][0].is_none() {
                return Err(Error::OutOfDomain {
                    name: "load index without a kernel (0 = p, 1 = qx, 2 = qy)",
                    value: t as f64,
                    allowed: "a kernel built for every load present",
                });
            }
        }
        for (c, out) in layer.comps_mut().into_iter().enumerate() {
            s.acc.fill(C64::new(0.0, 0.0));
            for t in 0..3 {
                let (Some(l), Some(k)) = (&load.spec[t], &kernel.spec[t][c]) else {
                    continue;
                };
                let (ox, oy) = parity(c, t);
                if ox ^ oy {
                    for ((a, lv), kv) in s.acc.iter_mut().zip(l).zip(k) {
                        // (i k) * l
                        *a += C64::new(-kv * lv.im, kv * lv.re);
                    }
                } else {
                    for ((a, lv), kv) in s.acc.iter_mut().zip(l).zip(k) {
                        *a += lv * kv;
                    }
                }
            }
            self.inverse(s, out);
        }
        layer.fill_invariants();
        Ok(layer)
    }

    /// The full field: traction spectra once, then for each depth its kernel, the product and
    /// the inverse transforms (depths in parallel with rayon when `parallel`, each task with
    /// its own scratch; the kernel spectra of a layer are dropped when it is done).
    ///
    /// # Errors
    /// As [`FieldOperator::load_spectra`] and [`FieldOperator::layer_kernel`];
    /// [`Error::EmptyGrid`] for no depth.
    pub fn compute(
        &self,
        t: &SurfaceTraction<'_>,
        depths: &[f64],
        parallel: bool,
    ) -> Result<StressField> {
        if depths.is_empty() {
            return Err(Error::EmptyGrid { reason: "no depth requested" });
        }
        for &z in depths {
            check_depth(z)?;
        }
        let mut s = self.make_scratch();
        let load = self.load_spectra(t, &mut s)?;
        let present = [0, 1, 2].map(|k| load.spec[k].is_some());
        let one = |z: f64, (s, k): &mut (FieldScratch, LayerKernel)| -> Result<StressLayer> {
            self.layer_kernel_into(z, present, k, s)?;
            self.apply(k, &load, s)
        };
        let fresh = || LayerKernel { z: 0.0, spec: Default::default() };
        let layers: Result<Vec<StressLayer>> = if parallel {
            depths
                .par_iter()
                .map_init(|| (self.make_scratch(), fresh()), |w, &z| one(z, w))
                .collect()
        } else {
            let mut w = (s, fresh());
            depths.iter().map(|&z| one(z, &mut w)).collect()
        };
        Ok(StressField { lattice: self.lattice, layers: layers? })
    }
}

/// The subsurface stress field of the lattice traction `t` at the given depths, Poisson
/// ratio $\nu$: [`FieldOperator::new`] then [`FieldOperator::compute`] (module documentation
/// for the equations, conventions and units).
///
/// # Errors
/// [`Error::OutOfDomain`] for a depth that is not finite and positive, a non-finite traction,
/// $\nu \notin (-1, 1/2]$ or a bad lattice; [`Error::LengthMismatch`] for traction arrays of
/// the wrong length; [`Error::EmptyGrid`] for an empty lattice or no depth.
pub fn subsurface_field(
    lattice: Lattice,
    nu: f64,
    t: &SurfaceTraction<'_>,
    depths: &[f64],
    config: FieldConfig,
) -> Result<StressField> {
    FieldOperator::new(lattice, nu, config.boundary)?.compute(t, depths, config.parallel)
}

/// Reference: the stress at any point $(x, y, z)$ by direct summation over every loaded cell
/// of the exact rectangle stresses,
/// $\sigma(x, y, z) = \sum_{\mathbf j}\sigma^{\text{rect}}_{\mathbf j}(x, y, z)$
/// (`stickslip_halfspace::rect_stress::rect_stress`; Love 1929, Cerruti), free boundary.
/// $O(N)$ per point.
///
/// # Errors
/// As [`subsurface_field`] for the lattice, $\nu$, the traction and $z$; a non-finite $x$ or
/// $y$ is [`Error::OutOfDomain`].
pub fn direct_stress(
    lattice: &Lattice,
    nu: f64,
    t: &SurfaceTraction<'_>,
    x: f64,
    y: f64,
    z: f64,
) -> Result<Stress3> {
    lattice.validate()?;
    check_nu(nu)?;
    check_depth(z)?;
    t.validate(lattice.len())?;
    for (name, v) in [("x", x), ("y", y)] {
        if !v.is_finite() {
            return Err(Error::OutOfDomain { name, value: v, allowed: "finite" });
        }
    }
    let get = |a: &[f64], k: usize| if a.is_empty() { 0.0 } else { a[k] };
    let mut acc = Stress3::default();
    for j in 0..lattice.ny {
        for i in 0..lattice.nx {
            let k = j * lattice.nx + i;
            let tr = Traction { p: get(t.p, k), qx: get(t.qx, k), qy: get(t.qy, k) };
            if tr.p == 0.0 && tr.qx == 0.0 && tr.qy == 0.0 {
                continue;
            }
            let (cx, cy) = lattice.centre(i, j);
            let r = Rect {
                x1: cx - 0.5 * lattice.hx,
                x2: cx + 0.5 * lattice.hx,
                y1: cy - 0.5 * lattice.hy,
                y2: cy + 0.5 * lattice.hy,
            };
            let s = rect_stress(nu, &r, &tr, x, y, z);
            acc.xx += s.xx;
            acc.yy += s.yy;
            acc.zz += s.zz;
            acc.xy += s.xy;
            acc.xz += s.xz;
            acc.yz += s.yz;
        }
    }
    Ok(acc)
}
