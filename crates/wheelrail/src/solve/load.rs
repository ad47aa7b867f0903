//! The normal contact of the patches under the vertical load: the approach estimate, one
//! patch under force control, all patches at a trial height, the height iteration.

use super::*;

impl WheelRail {
    /// A Hertz estimate of the vertical approach under the load `f`, from the curvatures of
    /// the two profiles at the first touch.
    pub(super) fn estimate_approach(
        &self,
        rail: &PlacedRail<'_>,
        wheel: &PlacedWheel<'_>,
        s: &Search,
        f: f64,
    ) -> Result<f64> {
        let k = s.k_min;
        let (_, d1, d2) = rail.at(s.rail_t[k]);
        let slope = d1[1] / d1[0];
        let zr2 = (d2[1] * d1[0] - d1[1] * d2[0]) / d1[0].powi(3);
        let (theta, _) = wheel.lowest(0.0);
        let tw = s.wheel_t[k];
        let h = 1e-4;
        let locus = |t: f64| {
            let w = wheel.point(t, theta).w;
            (w.y, w.z)
        };
        let (a, b, c) = (locus(tw - h), locus(tw), locus(tw + h));
        let (dy1, dz1) = ((c.0 - a.0) / (2.0 * h), (c.1 - a.1) / (2.0 * h));
        let (dy2, dz2) = ((c.0 - 2.0 * b.0 + a.0) / (h * h), (c.1 - 2.0 * b.1 + a.1) / (h * h));
        let zw2 = (dz2 * dy1 - dz1 * dy2) / dy1.powi(3);
        let cosd = 1.0 / (1.0 + slope * slope).sqrt();
        let rho = wheel.point(tw, theta).rho;
        let kx = cosd / rho;
        let ks = ((zr2 - zw2) * cosd.powi(3)).max(2.0);
        let e_star = composite_modulus(&self.bodies[0], &self.bodies[1]);
        let hz = HertzEllipse::from_curvatures(kx, ks, f / cosd, e_star)?;
        Ok(hz.approach() / cosd)
    }

    /// One patch pressed with the normal force `fn_target`: the normal solver's force
    /// control gives the approach $\delta_n$ still missing, which moves the wheelset by
    /// $\delta_n/\cos\delta$; the move is accepted without another solve when its tangential
    /// part $\delta_n\tan\delta$ changes the gap over the contact by less than
    /// [`HEIGHT_CONSISTENCY`] of the interpenetration. Returns the height.
    pub(super) fn force_patch(
        &self,
        p: &mut Working,
        fn_target: f64,
        z_start: f64,
        ntol: f64,
        cache: &mut Cache,
        info: &mut SolveInfo,
    ) -> Result<f64> {
        let (sd, cd) = p.frame.delta.sin_cos();
        let mut z = z_start;
        for _ in 0..MAX_LOAD_ITERATIONS {
            self.normal_patch(p, z, NormalLoad::Force(fn_target), ntol, cache, info)?;
            info.load_iterations += 1;
            let sol = p.sol.as_ref().expect("solved");
            let scale = -p.gap.iter().copied().fold(0.0, f64::min) + sol.approach.abs();
            let slope = sol
                .contact
                .iter()
                .zip(&p.dnw)
                .filter(|(c, _)| **c)
                .fold(0.0f64, |m, (_, d)| m.max(d.abs()));
            z += sol.approach / cd;
            info.load_residual = 0.0;
            if (sol.approach / cd * sd).abs() * slope <= HEIGHT_CONSISTENCY * scale {
                return Ok(z);
            }
        }
        Err(Error::NotConverged { iterations: MAX_LOAD_ITERATIONS, residual: f64::NAN })
    }

    /// Solve the normal contact of one patch at height `z`.
    pub(super) fn normal_patch(
        &self,
        p: &mut Working,
        z: f64,
        load: NormalLoad,
        tolerance: f64,
        cache: &mut Cache,
        info: &mut SolveInfo,
    ) -> Result<()> {
        let tg = Instant::now();
        p.gap_at(z);
        info.geometry_seconds += tg.elapsed().as_secs_f64();
        let tn = Instant::now();
        let lat = p.lattice;
        let tol = Tolerance::relative(tolerance).map_err(|_| Error::OutOfDomain {
            name: "normal tolerance",
            value: tolerance,
            allowed: "a valid relative tolerance",
        })?;
        let pb = NormalProblem::new(
            lat.nx,
            lat.ns,
            (lat.hx, lat.hs),
            &p.gap,
            self.bodies,
            Boundary::Free,
        )?
        .with_origin((lat.x0, lat.s0))
        .with_tolerance(tol)
        .with_min_contact_cells(1);
        let warm = match p.sol.as_ref().filter(|s| !s.no_contact) {
            Some(s) => Some(s.pressure.clone()),
            None => p.warm.take(),
        };
        let op = cache.operator(&pb);
        let sol = pb.solve_with(op, load, warm.as_deref())?;
        info.normal_solves += 1;
        info.normal_iterations += sol.info.iterations;
        info.normal_products += sol.info.products;
        info.normal_seconds += tn.elapsed().as_secs_f64();
        p.sol = Some(sol);
        Ok(())
    }

    /// The wheelset height under `load` (module docs). One patch under a force: the normal
    /// solver's force control gives the approach $\delta_n$ still missing, which moves the
    /// wheelset by $\delta_n/\cos\delta$; the move is accepted without another solve when
    /// its tangential part $\delta_n\tan\delta$ changes the gap over the contact by less
    /// than the tolerance (relative to the interpenetration). Several patches: approach
    /// control at trial heights, secant on $F^{2/3}$. The first pass (`final_pass` false,
    /// before the frames move to the pressure centroids) uses looser tolerances
    /// ([`FIRST_PASS_TOLERANCE`]).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn height(
        &self,
        patches: &mut [Working],
        load: VerticalLoad,
        z_touch: f64,
        z_start: f64,
        final_pass: bool,
        cache: &mut Cache,
        info: &mut SolveInfo,
    ) -> Result<f64> {
        let (ntol, ltol) = if final_pass {
            (self.normal_tolerance, self.load_tolerance)
        } else {
            (
                self.normal_tolerance.max(FIRST_PASS_TOLERANCE),
                self.load_tolerance.max(FIRST_PASS_TOLERANCE),
            )
        };
        let target = match load {
            VerticalLoad::Approach(d) => {
                for p in patches.iter_mut() {
                    self.normal_patch(
                        p,
                        z_touch + d,
                        NormalLoad::Approach(0.0),
                        ntol,
                        cache,
                        info,
                    )?;
                }
                info.load_iterations += 1;
                return Ok(z_touch + d);
            }
            VerticalLoad::Force(f) | VerticalLoad::TotalForce(f) => f,
        };
        if let [p] = patches {
            let cd = p.frame.delta.cos();
            return self.force_patch(p, target / cd, z_start, ntol, cache, info);
        }
        let g_target = target.powf(2.0 / 3.0);
        let mut z = z_start;
        let mut prev = (z_touch, 0.0);
        let mut residual = f64::INFINITY;
        for _ in 0..MAX_LOAD_ITERATIONS {
            let mut f = 0.0;
            for p in patches.iter_mut() {
                self.normal_patch(p, z, NormalLoad::Approach(0.0), ntol, cache, info)?;
                f += p.sol.as_ref().map_or(0.0, |s| s.force) * p.frame.delta.cos();
            }
            info.load_iterations += 1;
            residual = (f - target).abs() / target;
            info.load_residual = residual;
            if residual <= ltol {
                return Ok(z);
            }
            let g = f.powf(2.0 / 3.0);
            let (zp, gp) = prev;
            let slope = if g != gp { (z - zp) / (g - gp) } else { 0.0 };
            prev = (z, g);
            let mut zn = z + (g_target - g) * slope;
            // Safeguards: stay above first touch, and move if the secant stalls.
            if !zn.is_finite() || zn <= z_touch || slope <= 0.0 {
                zn = z_touch
                    + (z - z_touch) * (target / f.max(f64::MIN_POSITIVE)).powf(2.0 / 3.0).min(4.0);
            }
            z = zn;
        }
        Err(Error::NotConverged { iterations: MAX_LOAD_ITERATIONS, residual })
    }
}
