//! Each patch's lattice over its interpenetration region, and its frame moved to the
//! pressure centroid.

use super::working::resample;
use super::*;

/// The coarse lattice of the first pass over the lattice `fine`: cells of twice its sides,
/// at least covering it, about the same centre, its sizes rounded up to [`LATTICE_ROUND`];
/// `None` when `fine` has fewer than [`COARSE_MIN_CELLS`] cells along a side.
fn coarse_of(fine: &Lattice) -> Option<Lattice> {
    if fine.nx < COARSE_MIN_CELLS || fine.ns < COARSE_MIN_CELLS {
        return None;
    }
    let round = |n: usize| n.div_ceil(2).div_ceil(LATTICE_ROUND) * LATTICE_ROUND;
    let (nx, ns) = (round(fine.nx), round(fine.ns));
    let (hx, hs) = (2.0 * fine.hx, 2.0 * fine.hs);
    let (xc, sc) =
        (fine.x0 + 0.5 * fine.nx as f64 * fine.hx, fine.s0 + 0.5 * fine.ns as f64 * fine.hs);
    Some(Lattice { nx, ns, hx, hs, x0: xc - 0.5 * nx as f64 * hx, s0: sc - 0.5 * ns as f64 * hs })
}

impl WheelRail {
    /// Lay out the patches: frames from the interpenetration regions with the wheel at
    /// height `z_frame`, lattices holding the interpenetration at the deeper `z_lattice`.
    pub(super) fn layout(
        &self,
        rail: &PlacedRail<'_>,
        wheel0: &PlacedWheel<'_>,
        s0: &Search,
        z_frame: f64,
        z_lattice: f64,
        memory: &[Memory],
        info: &mut SolveInfo,
    ) -> Result<Vec<Working>> {
        let tg = Instant::now();
        // Gaps on the search lines move with the wheel: g(z) = g(0) - z.
        let at = |z: f64| {
            let mut s = s0.clone();
            s.gap.iter_mut().for_each(|g| *g -= z);
            s
        };
        let (sf, sl) = (at(z_frame), at(z_lattice));
        let regions = sl.regions();
        let wheel = wheel0.at_height(z_lattice);
        let n = sl.y.len();
        let mut out = Vec::with_capacity(regions.len());
        for (r, reg) in regions.iter().enumerate() {
            if reg.k0 == 0 || reg.k1 + 1 == n {
                return Err(Error::FlangeClimb {
                    what: format!(
                        "the interpenetration reaches the end of the profiles' common lateral range at y = {:.4e} m",
                        self.side.sign() * sl.y[if reg.k0 == 0 { 0 } else { n - 1 }]
                    ),
                });
            }
            let lo = if r == 0 {
                f64::NEG_INFINITY
            } else {
                0.5 * (sl.y[regions[r - 1].k1] + sl.y[reg.k0])
            };
            let hi = if r + 1 == regions.len() {
                f64::INFINITY
            } else {
                0.5 * (sl.y[reg.k1] + sl.y[regions[r + 1].k0])
            };
            // The frame: the region's interpenetration at the expected height if it has one
            // there, else at the lattice height.
            let inner = sf.regions().into_iter().find(|q| q.k0 <= reg.k1 && q.k1 >= reg.k0);
            let (_yc, tr, tw, xw) = match inner {
                Some(q) => sf.centre(q),
                None => sl.centre(*reg),
            };
            // On the flange tip already at the layout height: refused before any solve.
            self.check_climb(self.wheelset.wheel().eval(tw).p, 0.3 * FLANGE_TIP_BAND)?;
            let (p, d1, _) = rail.at(tr);
            let (theta, _) = wheel.lowest(0.0);
            let wp = wheel.point(tw, theta);
            let delta = 0.5 * (d1[1].atan2(d1[0]) + wp.dt.z.atan2(wp.dt.y));
            let region = (p[0], xw, delta);
            // The previous position's patch nearest this region, if near enough.
            let remembered =
                memory.iter().filter(|m| (m.region.0 - region.0).abs() < MEMORY_MATCH).min_by(
                    |a, b| (a.region.0 - region.0).abs().total_cmp(&(b.region.0 - region.0).abs()),
                );
            let frame = match remembered {
                Some(m) => {
                    // Its frame's offsets from its region's centre, on this region.
                    let y = region.0 + m.offset.0;
                    let mut t = tr;
                    for _ in 0..30 {
                        let (q, d, _) = rail.at(t);
                        let step = (q[0] - y) / d[0];
                        t -= step;
                        if step.abs() < 1e-15 {
                            break;
                        }
                    }
                    let q = rail.at(t).0;
                    Frame::new(
                        Vector3::new(xw + m.offset.1, q[0], q[1]),
                        delta + m.offset.2,
                        t,
                        tw,
                        theta,
                    )
                }
                None => Frame::new(Vector3::new(xw, p[0], p[1]), delta, tr, tw, theta),
            };
            // The lattice: the bounding box, in the patch frame, of the interpenetration on
            // the search lines (at line k it spans x = x_k -+ sqrt(2 d_k rho_k) along the wheel's
            // circle of radius rho_k), plus the margin; grown if the gap says it is short.
            let (hx, hs) = self.cell;
            let (mut x0, mut x1, mut s0, mut s1) =
                (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
            let r0 = self.wheelset.wheel_radius();
            for k in reg.k0..=reg.k1 {
                let d = -sl.gap[k];
                if d <= 0.0 {
                    continue;
                }
                let rho = r0 + self.wheelset.wheel().eval(sl.wheel_t[k]).p[1];
                let h = (2.0 * d * rho).sqrt();
                let xc = sl.wheel_x[k] - frame.origin.x;
                let q = rail.at(sl.rail_t[k]).0;
                let sk = frame.local(&Vector3::new(0.0, q[0], q[1]))[1];
                (x0, x1, s0, s1) = (x0.min(xc - h), x1.max(xc + h), s0.min(sk), s1.max(sk));
            }
            if !x0.is_finite() {
                (x0, x1, s0, s1) = (-hx, hx, -hs, hs);
            }
            // Without a remembered patch the first pass runs on a coarse lattice
            // ([`COARSE_MIN_CELLS`]).
            let coarse = remembered.is_none();
            let mut extra = 0.0;
            let mut w = loop {
                let (mx, ms) = (
                    (LATTICE_MARGIN as f64 + 0.5) * hx + extra * (x1 - x0),
                    (LATTICE_MARGIN as f64 + 0.5) * hs + extra * (s1 - s0),
                );
                let round =
                    |n: f64| ((n / LATTICE_ROUND as f64).ceil() as usize).max(1) * LATTICE_ROUND;
                let (nx, ns) = (round((x1 - x0 + 2.0 * mx) / hx), round((s1 - s0 + 2.0 * ms) / hs));
                let lat = Lattice {
                    nx,
                    ns,
                    hx,
                    hs,
                    x0: 0.5 * (x0 + x1) - 0.5 * nx as f64 * hx,
                    s0: 0.5 * (s0 + s1) - 0.5 * ns as f64 * hs,
                };
                let mut w = match coarse_of(&lat) {
                    Some(c) if coarse => {
                        let mut w = Working::new(rail, &wheel, z_lattice, frame, c, (lo, hi))?;
                        w.fine = Some(lat);
                        w
                    }
                    _ => Working::new(rail, &wheel, z_lattice, frame, lat, (lo, hi))?,
                };
                w.gap_at(z_lattice);
                if !touches_border(&w.gap, &w.lattice) || extra > 2.0 {
                    break w;
                }
                extra = 2.0 * extra + 0.25;
            };
            w.gap_at(z_lattice);
            w.region = region;
            if let Some(m) = remembered {
                w.predicted = true;
                w.warm = m.pressure_on(&w.lattice);
            }
            out.push(w);
        }
        info.geometry_seconds += tg.elapsed().as_secs_f64();
        Ok(out)
    }

    /// The pressure centroid $(\bar x, \bar s)$ of a solved patch in its frame and the
    /// pressure-weighted mean inclination of the rail surface, if they are further from the
    /// frame than [`FRAME_ACCEPT`] allows.
    pub(super) fn off_centre(
        &self,
        rail: &PlacedRail<'_>,
        p: &Working,
    ) -> Result<Option<(f64, f64, f64)>> {
        let Some((xb, sb, delta)) = self.centroid(rail, p)? else { return Ok(None) };
        let lat = p.lattice;
        let (fx, fs, fd) = FRAME_ACCEPT;
        let off =
            xb.abs() > fx * lat.hx || sb.abs() > fs * lat.hs || (delta - p.frame.delta).abs() > fd;
        Ok(off.then_some((xb, sb, delta)))
    }

    /// The pressure centroid $(\bar x, \bar s)$ of a solved patch in its frame and the
    /// pressure-weighted mean inclination of the rail surface (`None` without pressure).
    pub(super) fn centroid(
        &self,
        rail: &PlacedRail<'_>,
        p: &Working,
    ) -> Result<Option<(f64, f64, f64)>> {
        let Some(sol) = &p.sol else { return Ok(None) };
        let lat = p.lattice;
        let (mut ps, mut px, mut pss, mut pa) = (0.0, 0.0, 0.0, 0.0);
        for j in 0..lat.ns {
            let (_, d1, _) = rail.at(p.rail_t[j]);
            let angle = d1[1].atan2(d1[0]);
            for i in 0..lat.nx {
                let pr = sol.pressure[j * lat.nx + i];
                ps += pr;
                px += pr * lat.x(i);
                pss += pr * lat.s(j);
                pa += pr * angle;
            }
        }
        if ps <= 0.0 {
            return Ok(None);
        }
        Ok(Some((px / ps, pss / ps, pa / ps)))
    }

    /// The patch once more with its frame at the pressure centroid $(\bar x, \bar s)$ and the
    /// pressure-weighted mean inclination of the rail surface as its contact angle
    /// ([`WheelRail::off_centre`]); the lattice keeps its size and moves with the frame, so
    /// the pressure carries over cell by cell as the next warm start. A coarse patch of the
    /// first pass takes its lattice of the final cell size instead, moved with the frame, and
    /// its pressure sampled there as the warm start.
    pub(super) fn refine(
        &self,
        rail: &PlacedRail<'_>,
        wheel: &PlacedWheel<'_>,
        z: f64,
        p: Working,
        centroid: (f64, f64, f64),
    ) -> Result<Working> {
        let lat = p.lattice;
        let (xb, sb, delta) = centroid;
        // The rail point at s = sb in the old frame.
        let probe =
            Lattice { nx: 1, ns: 1, hx: lat.hx, hs: lat.hs, x0: 0.0, s0: sb - 0.5 * lat.hs };
        let (nr, tr) = patch::rail_column(rail, &p.frame, &probe)?;
        let origin = p.frame.global([xb, sb, nr[0]]);
        let w = patch::wheel_point(wheel, &p.frame, xb, sb, (p.frame.wheel_t, p.frame.wheel_theta))
            .ok_or_else(|| Error::FlangeClimb {
                what: "the wheel surface cannot be followed at the pressure centroid".to_string(),
            })?;
        let frame = Frame::new(origin, delta, tr[0], w.t, w.theta);
        let target = p.fine.unwrap_or(lat);
        let moved = Lattice { x0: target.x0 - xb, s0: target.s0 - sb, ..target };
        let mut out = Working::new(rail, wheel, z, frame, moved, p.band)?;
        out.gap_at(z);
        if p.fine.is_some() {
            out.warm = p
                .sol
                .filter(|s| !s.no_contact)
                .map(|s| resample(&s.pressure, &lat, &moved, (xb, sb)))
                .filter(|w| w.iter().any(|&v| v > 0.0));
        } else {
            out.sol = p.sol;
        }
        out.region = p.region;
        Ok(out)
    }
}
