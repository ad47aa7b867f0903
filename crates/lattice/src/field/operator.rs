//! The per-layer FFT operator of [`super`]: kernel spectra of the exact rectangle stresses,
//! the load spectra, and their products.

use super::{Boundary, Lattice, SurfaceTraction};
use crate::error::{Error, Result};
use crate::operator::fast_size;
use rayon::prelude::*;
use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealToComplex};
use rustfft::Fft;
use std::f64::consts::PI;
use std::sync::Arc;
use stickslip_halfspace::rect_stress::{
    corner_derivatives, stress_from_potential, PotentialDerivatives, Traction,
};

use super::result::{StressField, StressLayer};

type C64 = Complex<f64>;

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

pub(super) fn check_depth(z: f64) -> Result<f64> {
    if z.is_finite() && z > 0.0 {
        Ok(z)
    } else {
        Err(Error::OutOfDomain { name: "depth z", value: z, allowed: "finite and > 0" })
    }
}

pub(super) fn check_nu(nu: f64) -> Result<f64> {
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
        Ok(Self {
            lattice,
            nu,
            boundary,
            mx,
            my,
            mxh: mx / 2 + 1,
            r2c: crate::operator::plans::r2c(mx),
            c2r: crate::operator::plans::c2r(mx),
            col_fwd: crate::operator::plans::forward(my),
            col_inv: crate::operator::plans::inverse(my),
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
