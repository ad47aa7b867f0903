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
//!   *Wear* 243, "DC-FFT"; as in [`crate::operator`]).
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

mod operator;
mod result;

use operator::{check_depth, check_nu};

pub use operator::{FieldOperator, FieldScratch, LayerKernel, LoadSpectra};
pub use result::{invariants, Extremum, FieldMaxima, Invariants, StressField, StressLayer};

use crate::error::{Error, Result};
use crate::grid::ContactGrid;
pub use crate::Boundary;
use stickslip_halfspace::rect_stress::{rect_stress, Traction};
use stickslip_halfspace::rectangle::Rect;
use stickslip_halfspace::Stress3;

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
        let (nx, ny, x0, y0, cell) = grid.lattice_cells()?;
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
