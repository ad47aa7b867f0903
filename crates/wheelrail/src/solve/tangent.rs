//! The creepages and tangential solution of each patch, its forces in track coordinates,
//! the mirror image for a left side, and FASTSIM's ellipse.

use super::*;

impl WheelRail {
    /// The kinematics and tangential solution of every patch with the wheel at its height.
    pub(super) fn tangential_all(
        &self,
        wheel: &PlacedWheel<'_>,
        patches: &[Working],
        motion: &Motion,
        tangential: Tangential,
        info: &mut SolveInfo,
    ) -> Result<Vec<Tangent>> {
        if motion.creepage.is_some() && patches.len() > 1 && !matches!(tangential, Tangential::None)
        {
            return Err(Error::OutOfDomain {
                name: "motion.creepage",
                value: patches.len() as f64,
                allowed: "creepages given directly for a position with one contact patch; with more patches each has its own creepages: give the wheelset's motion (speed, pitch rate) instead",
            });
        }
        patches.iter().map(|p| self.tangential_patch(wheel, p, motion, tangential, info)).collect()
    }

    /// The wheel point at the reference, the flange-climb check, the creepages and the
    /// tangential solution of one patch.
    pub(super) fn tangential_patch(
        &self,
        wheel: &PlacedWheel<'_>,
        p: &Working,
        motion: &Motion,
        tangential: Tangential,
        info: &mut SolveInfo,
    ) -> Result<Tangent> {
        let f = p.frame;
        let sol = p.sol.as_ref().expect("solved patches only");
        let q = patch::wheel_point(wheel, &f, 0.0, 0.0, (f.wheel_t, f.wheel_theta)).ok_or_else(
            || Error::FlangeClimb {
                what: "the wheel surface cannot be followed at the reference point".to_string(),
            },
        )?;
        let qw = self.wheelset.wheel().eval(q.t).p;
        let qpt = f.global([0.0, 0.0, q.n]);
        self.check_climb(qw, FLANGE_TIP_BAND)?;
        let tt = Instant::now();
        let (creep, vr, rolling, axes) = match tangential {
            Tangential::None => (Creepage::default(), 0.0, None, None),
            t => {
                let (creep, vr) = match motion.creepage {
                    Some(c) => (c, motion.speed),
                    None => creepages(wheel, motion, &f, &qpt)?,
                };
                let grid = sol.contact_grid()?;
                let (r, axes) = match t {
                    Tangential::Exact { tolerance } => (
                        SteadyRolling::new(&grid, self.bodies, self.friction)?
                            .with_tolerance(tolerance)?
                            .solve(&creep)?,
                        None,
                    ),
                    _ => {
                        let (a, b) = fastsim_axes(&grid);
                        let c = Compliance::pair(&self.bodies[0], &self.bodies[1]);
                        let sum = c.one_minus_nu + c.nu;
                        let r = fastsim::solve(
                            &grid,
                            a,
                            b,
                            2.0 / sum,
                            c.nu / sum,
                            self.friction,
                            &creep,
                        )?;
                        (r, Some((a, b)))
                    }
                };
                (creep, vr, Some(r), axes)
            }
        };
        info.tangential_seconds += tt.elapsed().as_secs_f64();
        Ok(Tangent { wheel_point: qw, creep, vr, rolling, fastsim_axes: axes })
    }

    /// The patch's solution as reported, mirrored for a left side.
    pub(super) fn finish_patch(
        &self,
        rail: &PlacedRail<'_>,
        p: Working,
        t: Tangent,
    ) -> PatchSolution {
        let f = p.frame;
        let sol = p.sol.expect("solved patches only");
        let rail_pt = rail.to_profile([f.origin.y, f.origin.z]);
        let (fx, fs, mn) = t.rolling.as_ref().map_or((0.0, 0.0, 0.0), |r| (r.fx, r.fy, r.mz));
        let force = f.ex * fx + f.es * fs + f.en * sol.force;
        let lattice =
            PatchLattice { nx: sol.nx, ns: sol.ny, hx: sol.hx, hs: sol.hy, origin: sol.origin };
        let mut out = PatchSolution {
            reference: [f.origin.x, f.origin.y, f.origin.z],
            rail_point: rail_pt,
            wheel_point: t.wheel_point,
            contact_angle: f.delta,
            rolling_radius: self.wheelset.wheel_radius() + t.wheel_point[1],
            rolling_speed: t.vr,
            creepage: t.creep,
            normal_force: sol.force,
            fx,
            fs,
            mn,
            pmax: sol.peak_pressure,
            area: sol.area,
            contact_cells: sol.contact_cells,
            stick_fraction: t.rolling.as_ref().map(RollingSolution::stick_fraction),
            fastsim_axes: t.fastsim_axes,
            force_on_rail: [force.x, force.y, force.z],
            lattice,
            gap: p.gap,
            normal: sol,
            rolling: t.rolling,
        };
        if self.side == Side::Left {
            mirror(&mut out);
        }
        out
    }
}

/// A patch's kinematics and tangential solution (right side).
pub(super) struct Tangent {
    pub(super) wheel_point: [f64; 2],
    pub(super) creep: Creepage,
    pub(super) vr: f64,
    pub(super) rolling: Option<RollingSolution>,
    pub(super) fastsim_axes: Option<(f64, f64)>,
}

impl Tangent {
    pub(super) fn fs(&self) -> f64 {
        self.rolling.as_ref().map_or(0.0, |r| r.fy)
    }
}

/// Mirror a right-side patch solution into the left side (module [`crate::placement`]).
pub(super) fn mirror(p: &mut PatchSolution) {
    p.reference[1] = -p.reference[1];
    p.rail_point[0] = -p.rail_point[0];
    p.wheel_point[0] = -p.wheel_point[0];
    p.contact_angle = -p.contact_angle;
    p.creepage.lateral = -p.creepage.lateral;
    p.creepage.spin = -p.creepage.spin;
    p.fs = -p.fs;
    p.mn = -p.mn;
    p.force_on_rail[1] = -p.force_on_rail[1];
    // Lattices: s -> -s reverses the rows.
    let (nx, ns) = (p.lattice.nx, p.lattice.ns);
    let flip = |v: &mut Vec<f64>| {
        let old = v.clone();
        for j in 0..ns {
            v[j * nx..(j + 1) * nx].copy_from_slice(&old[(ns - 1 - j) * nx..(ns - j) * nx]);
        }
    };
    let s0 = -(p.lattice.origin.1 + ns as f64 * p.lattice.hs);
    p.lattice.origin.1 = s0;
    flip(&mut p.gap);
    let n = &mut p.normal;
    n.origin.1 = s0;
    flip(&mut n.pressure);
    flip(&mut n.gap);
    let old = n.contact.clone();
    for j in 0..ns {
        n.contact[j * nx..(j + 1) * nx].copy_from_slice(&old[(ns - 1 - j) * nx..(ns - j) * nx]);
    }
    if let Some(r) = &mut p.rolling {
        r.y.iter_mut().for_each(|v| *v = -*v);
        r.qy.iter_mut().for_each(|v| *v = -*v);
        r.sy.iter_mut().for_each(|v| *v = -*v);
        r.fy = -r.fy;
        r.mz = -r.mz;
    }
}

/// The semi-axes $(a, b)$ FASTSIM takes its flexibilities from: the ellipse with the
/// contact's area and the aspect ratio of its extents along $x$ and $s$, $\pi ab = A$,
/// $a/b = L_x/L_s$, the ratio kept within Kalker's table, $0.1 \le a/b \le 10$ (a narrow
/// flange contact can be longer; it is then given the coefficients of $a/b = 10$).
#[must_use]
pub fn fastsim_axes(grid: &ContactGrid) -> (f64, f64) {
    let ext = |v: &[f64]| {
        v.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, &x| (a.0.min(x), a.1.max(x)))
    };
    let (x0, x1) = ext(&grid.x);
    let (y0, y1) = ext(&grid.y);
    let lx = x1 - x0 + grid.hx;
    let ly = y1 - y0 + grid.hy;
    let area = grid.len() as f64 * grid.element_area();
    // Inside the table with a margin for the rounding of a/b.
    let ratio = (lx / ly).clamp(0.1 * (1.0 + 1e-9), 10.0 * (1.0 - 1e-9));
    ((area * ratio / std::f64::consts::PI).sqrt(), (area / (ratio * std::f64::consts::PI)).sqrt())
}
