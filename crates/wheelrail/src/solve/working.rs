//! A patch while it is solved (its frame, lattice and gap at a trial height) and what it
//! hands to the next position.

use super::*;

/// A patch while solving: frame, lattice, the allowed lateral band, the geometry at a base
/// height, and its last state.
pub(super) struct Working {
    pub(super) frame: Frame,
    pub(super) lattice: Lattice,
    /// Track-$y$ band of this region (the gap is ignored outside it).
    pub(super) band: (f64, f64),
    /// Height at which the wheel layer was evaluated.
    pub(super) z_base: f64,
    /// Rail normal coordinate and parameter per column; columns outside the band.
    pub(super) nr: Vec<f64>,
    pub(super) rail_t: Vec<f64>,
    pub(super) masked: Vec<bool>,
    /// Wheel normal coordinate and slope per cell at `z_base`.
    pub(super) nw: Vec<f64>,
    pub(super) dnw: Vec<f64>,
    /// The gap at the last height asked.
    pub(super) gap: Vec<f64>,
    pub(super) sol: Option<NormalSolution>,
    /// The region's centre at the frame height, $(y, x, \delta)$ (right-side track
    /// coordinates), which the frame's offsets in [`Memory`] are taken from.
    pub(super) region: (f64, f64, f64),
    /// The frame came from the previous position's offsets.
    pub(super) predicted: bool,
    /// A pressure to start the first solve from (the previous position's).
    pub(super) warm: Option<Vec<f64>>,
    /// A coarse patch of the first pass: the lattice of the final cell size (in this frame)
    /// that replaces its lattice when the frame moves to the pressure centroid
    /// ([`COARSE_MIN_CELLS`]).
    pub(super) fine: Option<Lattice>,
}

/// What a patch of one position hands to the next ([`Cache`]): where its frame lay relative
/// to its interpenetration region's centre, how far the wheelset was pressed down, and its
/// pressure.
#[derive(Debug, Clone)]
pub(super) struct Memory {
    pub(super) region: (f64, f64, f64),
    pub(super) offset: (f64, f64, f64),
    pub(super) approach: f64,
    /// Total vertical force over the normal forces' vertical part.
    pub(super) total_ratio: f64,
    pub(super) lattice: Lattice,
    pub(super) pressure: Vec<f64>,
}

impl Memory {
    /// The remembered pressure at the cells of `lat` (same patch coordinates; zero outside).
    pub(super) fn pressure_on(&self, lat: &Lattice) -> Option<Vec<f64>> {
        let m = &self.lattice;
        if (m.hx - lat.hx).abs() > 1e-12 * m.hx || (m.hs - lat.hs).abs() > 1e-12 * m.hs {
            return None;
        }
        let mut out = vec![0.0; lat.len()];
        for j in 0..lat.ns {
            let jm = ((lat.s(j) - m.s0) / m.hs).floor();
            if jm < 0.0 || jm as usize >= m.ns {
                continue;
            }
            for i in 0..lat.nx {
                let im = ((lat.x(i) - m.x0) / m.hx).floor();
                if im >= 0.0 && (im as usize) < m.nx {
                    out[j * lat.nx + i] = self.pressure[jm as usize * m.nx + im as usize];
                }
            }
        }
        out.iter().any(|&p| p > 0.0).then_some(out)
    }
}

/// The pressure `p` of the lattice `from` sampled at the cell centres of `to`, whose
/// coordinates are those of `from` shifted by `shift` (each cell takes the value of the
/// cell of `from` it lies in; zero outside): a warm start on another lattice.
pub(super) fn resample(p: &[f64], from: &Lattice, to: &Lattice, shift: (f64, f64)) -> Vec<f64> {
    let mut out = vec![0.0; to.len()];
    for j in 0..to.ns {
        let jm = ((to.s(j) + shift.1 - from.s0) / from.hs).floor();
        if jm < 0.0 || jm as usize >= from.ns {
            continue;
        }
        for i in 0..to.nx {
            let im = ((to.x(i) + shift.0 - from.x0) / from.hx).floor();
            if im >= 0.0 && (im as usize) < from.nx {
                out[j * to.nx + i] = p[jm as usize * from.nx + im as usize];
            }
        }
    }
    out
}

impl Working {
    /// The geometry of a patch with the wheel at height `wheel.z`.
    pub(super) fn new(
        rail: &PlacedRail<'_>,
        wheel: &PlacedWheel<'_>,
        z: f64,
        frame: Frame,
        lattice: Lattice,
        band: (f64, f64),
    ) -> Result<Self> {
        let (nr, rail_t) = patch::rail_column(rail, &frame, &lattice)?;
        let masked = (0..lattice.ns)
            .map(|j| {
                let y = frame.global([0.0, lattice.s(j), nr[j]]).y;
                y < band.0 || y > band.1
            })
            .collect();
        let (nw, dnw) = patch::wheel_layer(wheel, &frame, &lattice)?;
        let n = lattice.len();
        Ok(Self {
            frame,
            lattice,
            band,
            z_base: z,
            nr,
            rail_t,
            masked,
            nw,
            dnw,
            gap: vec![0.0; n],
            sol: None,
            region: (frame.origin.y, frame.origin.x, frame.delta),
            predicted: false,
            warm: None,
            fine: None,
        })
    }

    /// The gap at height `z`: the wheel moved rigidly by $\Delta z$ along track $z$, i.e. by
    /// $\Delta z\sin\delta$ along $s$ and $\Delta z\cos\delta$ along $n$, so
    /// $n_{wheel}(x, s; z) = n_{wheel}(x, s - \Delta z\sin\delta; z_b) + \Delta z\cos\delta$,
    /// the shifted value from the cubic Hermite interpolant of the cell values and slopes
    /// along $s$ (error of order $h_s^4\,\partial^4 n/\partial s^4$, below $10^{-11}$ m for
    /// profile radii above 10 mm at 0.2 mm cells).
    pub(super) fn gap_at(&mut self, z: f64) {
        let lat = self.lattice;
        let dz = z - self.z_base;
        let (sd, cd) = self.frame.delta.sin_cos();
        let shift = dz * sd / lat.hs;
        let (nx, ns, hs) = (lat.nx, lat.ns, lat.hs);
        for j in 0..ns {
            let u = j as f64 - shift;
            let k = u.floor();
            let tau = u - k;
            for i in 0..nx {
                let w = if k >= 0.0 && (k as usize) + 1 < ns {
                    let k = k as usize;
                    let (f0, f1) = (self.nw[k * nx + i], self.nw[(k + 1) * nx + i]);
                    let (m0, m1) = (self.dnw[k * nx + i] * hs, self.dnw[(k + 1) * nx + i] * hs);
                    let (t2, t3) = (tau * tau, tau * tau * tau);
                    (2.0 * t3 - 3.0 * t2 + 1.0) * f0
                        + (t3 - 2.0 * t2 + tau) * m0
                        + (-2.0 * t3 + 3.0 * t2) * f1
                        + (t3 - t2) * m1
                } else {
                    // Beyond the lattice: the tangent of the end row.
                    let e = if k < 0.0 { 0 } else { ns - 1 };
                    self.nw[e * nx + i] + (u - e as f64) * hs * self.dnw[e * nx + i]
                };
                let g = self.nr[j] - (w + dz * cd);
                self.gap[j * nx + i] = if self.masked[j] { g.max(MASKED_GAP) } else { g };
            }
        }
    }
}

/// Whether any cell with negative gap lies on the lattice border.
pub(super) fn touches_border(g: &[f64], lat: &Lattice) -> bool {
    (0..lat.ns).any(|j| {
        (0..lat.nx).any(|i| {
            (i == 0 || j == 0 || i + 1 == lat.nx || j + 1 == lat.ns) && g[j * lat.nx + i] < 0.0
        })
    })
}
