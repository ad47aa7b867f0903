//! One position from start to end: the search, the patches' lattices, the vertical load,
//! the frames moved to the pressure centroids, the tangential solves; flange climb.

use super::*;

impl WheelRail {
    pub(super) fn solve_here(
        &self,
        position: &Position,
        motion: &Motion,
        load: VerticalLoad,
        tangential: Tangential,
        cache: &mut Cache,
    ) -> Result<Solution> {
        let t_start = Instant::now();
        position.validate()?;
        if !matches!(tangential, Tangential::None) {
            motion.validate()?;
        }
        match load {
            VerticalLoad::Force(f) | VerticalLoad::TotalForce(f) => {
                crate::error::positive("load.normal", f)?
            }
            VerticalLoad::Approach(d) => crate::error::positive("load.approach", d)?,
        };
        let total = match (load, tangential) {
            (VerticalLoad::TotalForce(f), t) if !matches!(t, Tangential::None) => Some(f),
            _ => None,
        };
        let load = match load {
            VerticalLoad::TotalForce(f) => VerticalLoad::Force(f),
            l => l,
        };
        let mut info = SolveInfo::default();
        let pos = self.right_position(position);
        let motion_r = if self.side == Side::Left { motion.mirrored() } else { *motion };
        let rail = self.rail();
        let wheel0 = PlacedWheel::new(&self.wheelset, &pos, 0.0);
        let t0 = Instant::now();
        let s0 = search(&rail, &wheel0)?;
        if !s0.min_gap.is_finite() || s0.min_gap > MAX_NOMINAL_GAP {
            return Err(Error::NoContact {
                min_gap: s0.min_gap,
                y: self.side.sign() * s0.y[s0.k_min],
                overlap: true,
            });
        }
        let z_touch = s0.min_gap;
        // The previous position's patches: the first guesses of this one.
        let memory = std::mem::take(&mut cache.memory);
        let ratio = match (total, memory.first()) {
            (Some(_), Some(m)) => m.total_ratio,
            _ => 1.0,
        };
        let load = match load {
            VerticalLoad::Force(f) => VerticalLoad::Force(f / ratio),
            l => l,
        };
        let estimate = match (load, memory.first()) {
            (VerticalLoad::Approach(d), _) => d,
            (_, Some(m)) => m.approach,
            (VerticalLoad::Force(f) | VerticalLoad::TotalForce(f), None) => {
                self.estimate_approach(&rail, &wheel0, &s0, f)?
            }
        };
        info.geometry_seconds += t0.elapsed().as_secs_f64();
        let mut z_layout = z_touch + 1.3 * estimate;
        let mut z_start = z_touch + estimate;
        let (z, mut patches) = loop {
            info.layouts += 1;
            let mut patches =
                self.layout(&rail, &wheel0, &s0, z_start, z_layout, &memory, &mut info)?;
            let predicted = !patches.is_empty() && patches.iter().all(|p| p.predicted);
            let mut z =
                self.height(&mut patches, load, z_touch, z_start, predicted, cache, &mut info)?;
            let coarse = patches.iter().any(|p| p.fine.is_some());
            if coarse {
                // The coarse first pass done: each coarse patch takes its lattice of the
                // given cell size at its pressure centroid (where it has pressure), and the
                // height is found again on the fine lattices, warm.
                let tg = Instant::now();
                let wheel = wheel0.at_height(z);
                patches = patches
                    .into_iter()
                    .map(|p| {
                        if p.fine.is_none() {
                            return Ok(p);
                        }
                        let c = self.centroid(&rail, &p)?;
                        info.frames_moved += usize::from(c.is_some());
                        let c = c.unwrap_or((0.0, 0.0, p.frame.delta));
                        self.refine(&rail, &wheel, z, p, c)
                    })
                    .collect::<Result<_>>()?;
                info.geometry_seconds += tg.elapsed().as_secs_f64();
                z = self.height(&mut patches, load, z_touch, z, true, cache, &mut info)?;
            }
            patches.retain(|p| p.sol.as_ref().is_some_and(|s| !s.no_contact));
            let tg = Instant::now();
            let moved: Vec<Option<(f64, f64, f64)>> =
                patches.iter().map(|p| self.off_centre(&rail, p)).collect::<Result<_>>()?;
            info.geometry_seconds += tg.elapsed().as_secs_f64();
            info.frames_moved += moved.iter().filter(|m| m.is_some()).count();
            if moved.iter().any(Option::is_some) {
                // Once more, in the frame of each patch's pressure centroid.
                let tg = Instant::now();
                let wheel = wheel0.at_height(z);
                patches = patches
                    .into_iter()
                    .zip(moved)
                    .map(|(p, m)| match m {
                        Some(c) => self.refine(&rail, &wheel, z, p, c),
                        None => Ok(p),
                    })
                    .collect::<Result<_>>()?;
                info.geometry_seconds += tg.elapsed().as_secs_f64();
                z = self.height(&mut patches, load, z_touch, z, true, cache, &mut info)?;
            } else if !predicted && !coarse {
                // The frames stand; the first pass's looser tolerances are tightened.
                z = self.height(&mut patches, load, z_touch, z, true, cache, &mut info)?;
            }
            // The interpenetration at the final height must stay inside every lattice.
            let inside = patches.iter().all(|p| !touches_border(&p.gap, &p.lattice));
            if inside || info.layouts >= 6 {
                break (z, patches);
            }
            z_layout = z + 0.6 * (z - z_touch);
            z_start = z;
        };
        // Keep the patches that carry load.
        patches.retain(|p| p.sol.as_ref().is_some_and(|s| !s.no_contact));
        let mut z = z;
        let mut tang =
            self.tangential_all(&wheel0.at_height(z), &patches, &motion_r, tangential, &mut info)?;
        if let (Some(target), [_]) = (total, patches.as_slice()) {
            // One patch: the total vertical force G(Fn) = Fn cos d + Fs(Fn) sin d, secant on
            // the normal force, each trial a force-controlled normal solve and a tangential
            // solve (Fs grows about in proportion to Fn: the first slope).
            let (sd, cd) = patches[0].frame.delta.sin_cos();
            let mut fnt = patches[0].sol.as_ref().map_or(0.0, |s| s.force);
            let mut g = fnt * cd + tang[0].fs() * sd - target;
            let mut slope = cd + tang[0].fs() / fnt.max(f64::MIN_POSITIVE) * sd;
            let mut converged = false;
            for _ in 0..MAX_LOAD_ITERATIONS {
                info.load_residual = g.abs() / target;
                if info.load_residual <= self.load_tolerance {
                    converged = true;
                    break;
                }
                let step = if slope > 0.0 { -g / slope } else { -g / cd };
                let fnew = (fnt + step).max(0.05 * fnt);
                z = self.force_patch(
                    &mut patches[0],
                    fnew,
                    z,
                    self.normal_tolerance,
                    cache,
                    &mut info,
                )?;
                tang = self.tangential_all(
                    &wheel0.at_height(z),
                    &patches,
                    &motion_r,
                    tangential,
                    &mut info,
                )?;
                let gnew = fnew * cd + tang[0].fs() * sd - target;
                if fnew != fnt {
                    slope = (gnew - g) / (fnew - fnt);
                }
                (fnt, g) = (fnew, gnew);
            }
            if !converged {
                return Err(Error::NotConverged {
                    iterations: MAX_LOAD_ITERATIONS,
                    residual: info.load_residual,
                });
            }
        } else if let Some(target) = total {
            // The total vertical force: secant on F^(2/3) in the height, each trial with the
            // normal solves (approach control, warm) and the tangential solves.
            let vertical = |patches: &[Working], tang: &[Tangent]| {
                patches
                    .iter()
                    .zip(tang)
                    .map(|(p, t)| {
                        let (sd, cd) = p.frame.delta.sin_cos();
                        p.sol.as_ref().map_or(0.0, |s| s.force) * cd + t.fs() * sd
                    })
                    .sum::<f64>()
            };
            let g_target = target.powf(2.0 / 3.0);
            let mut prev = (z_touch, 0.0);
            let mut converged = false;
            for _ in 0..MAX_LOAD_ITERATIONS {
                let f = vertical(&patches, &tang);
                info.load_residual = (f - target).abs() / target;
                if info.load_residual <= self.load_tolerance {
                    converged = true;
                    break;
                }
                let g = f.max(0.0).powf(2.0 / 3.0);
                let slope = if g != prev.1 { (z - prev.0) / (g - prev.1) } else { 0.0 };
                prev = (z, g);
                let mut zn = z + (g_target - g) * slope;
                if !zn.is_finite() || zn <= z_touch || slope <= 0.0 {
                    zn = z_touch
                        + (z - z_touch)
                            * (target / f.max(f64::MIN_POSITIVE)).powf(2.0 / 3.0).min(4.0);
                }
                z = zn;
                for p in patches.iter_mut() {
                    self.normal_patch(
                        p,
                        z,
                        NormalLoad::Approach(0.0),
                        self.normal_tolerance,
                        cache,
                        &mut info,
                    )?;
                }
                info.load_iterations += 1;
                tang = self.tangential_all(
                    &wheel0.at_height(z),
                    &patches,
                    &motion_r,
                    tangential,
                    &mut info,
                )?;
            }
            if !converged {
                return Err(Error::NotConverged {
                    iterations: MAX_LOAD_ITERATIONS,
                    residual: info.load_residual,
                });
            }
        }
        let normal_vertical: f64 = patches
            .iter()
            .map(|p| p.sol.as_ref().map_or(0.0, |s| s.force) * p.frame.delta.cos())
            .sum();
        let all_vertical: f64 = normal_vertical
            + patches.iter().zip(&tang).map(|(p, t)| t.fs() * p.frame.delta.sin()).sum::<f64>();
        cache.memory = patches
            .iter()
            .filter_map(|p| {
                let sol = p.sol.as_ref()?;
                Some(Memory {
                    region: p.region,
                    offset: (
                        p.frame.origin.y - p.region.0,
                        p.frame.origin.x - p.region.1,
                        p.frame.delta - p.region.2,
                    ),
                    approach: z - z_touch,
                    total_ratio: if normal_vertical > 0.0 {
                        all_vertical / normal_vertical
                    } else {
                        1.0
                    },
                    lattice: p.lattice,
                    pressure: sol.pressure.clone(),
                })
            })
            .collect();
        let mut out = Vec::with_capacity(patches.len());
        for (p, t) in patches.into_iter().zip(tang) {
            out.push(self.finish_patch(&rail, p, t));
        }
        let mut sum = [0.0; 3];
        for p in &out {
            for (t, f) in sum.iter_mut().zip(p.force_on_rail) {
                *t += f;
            }
        }
        info.total_seconds = t_start.elapsed().as_secs_f64();
        Ok(Solution {
            side: self.side,
            z_wheelset: z,
            approach: z - z_touch,
            total_on_rail: sum,
            patches: out,
            info,
        })
    }

    /// Flange climb: a wheel contact point on the flange side of its steepest point and
    /// within `band` of the flange tip's height ([`FLANGE_TIP_BAND`]). A wheel without a
    /// flange (no face steeper than [`FLANGE_MIN_ANGLE`]) cannot climb.
    pub(super) fn check_climb(&self, w: [f64; 2], band: f64) -> Result<()> {
        let (ys, angle) = self.wheelset.flange();
        if angle < FLANGE_MIN_ANGLE {
            return Ok(());
        }
        let (wy, wz) = self.wheelset.wheel().points();
        let (ktip, ztip) = wz.iter().copied().enumerate().fold((0, f64::NEG_INFINITY), |a, b| {
            if b.1 > a.1 {
                b
            } else {
                a
            }
        });
        if w[0] < ys && ztip - w[1] < band {
            return Err(Error::FlangeClimb {
                what: format!(
                    "the wheel touches the rail at (y_w, z_w) = ({:.4e}, {:.4e}) m of its profile, {:.3e} m below its flange tip (y_w = {:.4e} m), beyond the flange's steepest point (flange angle {:.4} rad)",
                    self.side.sign() * w[0],
                    w[1],
                    ztip - w[1],
                    self.side.sign() * wy[ktip],
                    angle
                ),
            });
        }
        Ok(())
    }
}
