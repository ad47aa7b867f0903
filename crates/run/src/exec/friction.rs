//! Stage 2, friction: the shear traction of a line contact (sliding, 2D Cattaneo–Mindlin,
//! graded partial slip) and the closed forms of 3D contacts under a tangential force
//! (sliding, Mindlin's circle, Cattaneo's ellipse).

use stickslip_graded::{LoadPatch, Profile, SurfaceLoad};
use stickslip_halfspace::cattaneo2d::Cattaneo2d;
use stickslip_halfspace::hertz::strip::Strip;
use stickslip_traction::{closed::Cattaneo, closed::Mindlin};

use super::lattice::Lattice;
use super::normal::{ContactSolution, LineContact};
use super::outcome::{RigidOut, Zones};
use super::{solver_err, Ctx};
use crate::plan::recipe::{ContactRecipe, Force, LineFriction};
use stickslip_scene::SceneError;

// ---------------------------------------------------------------------------------------
// 2D

/// The shear traction of a line contact.
#[derive(Debug, Clone)]
pub(crate) struct LineTraction {
    /// Which traction (None: no friction stage).
    pub kind: Option<LineFriction>,
    /// Stick half-width (m): a without friction, 0 in full sliding.
    pub c_stick: f64,
    /// Tangential force per unit length (N/m).
    pub tangential: f64,
    /// Semi-elliptical shear strips (homogeneous Hertz shapes).
    pub shear: Vec<Strip>,
    /// The signed friction coefficient of the graded / punch traction $q = \mu p$ (+ the
    /// partial-slip correction).
    pub mu: f64,
    /// The graded stick half-width, when partial slip leaves one.
    pub graded_stick: Option<f64>,
    /// The 2D Cattaneo–Mindlin solution.
    pub cattaneo: Option<Cattaneo2d>,
}

/// The traction of a line contact.
pub(crate) fn line(
    kind: Option<LineFriction>,
    n: &LineContact,
) -> Result<LineTraction, SceneError> {
    let a = n.a;
    let mut t = LineTraction {
        kind,
        c_stick: a,
        tangential: 0.0,
        shear: Vec::new(),
        mu: 0.0,
        graded_stick: None,
        cattaneo: None,
    };
    match kind {
        None => {}
        Some(LineFriction::Sliding { friction: f }) => {
            t.c_stick = 0.0;
            t.tangential = f * n.load;
            t.mu = f;
            t.shear.push(Strip { half_width: a, peak: f * n.p0 });
        }
        Some(LineFriction::Cattaneo { friction: f, tangential }) => {
            let cm = Cattaneo2d::new(a, n.p0, f, tangential)
                .map_err(|e| solver_err("2D Cattaneo-Mindlin", e))?;
            t.c_stick = cm.stick_half_width();
            t.tangential = tangential;
            let s = tangential.signum();
            t.shear.push(Strip { half_width: a, peak: s * f * n.p0 });
            if t.c_stick > 0.0 {
                t.shear.push(Strip { half_width: t.c_stick, peak: -s * f * n.p0 * t.c_stick / a });
            }
            t.cattaneo = Some(cm);
        }
        Some(LineFriction::GradedPartialSlip { friction: f, tangential }) => {
            let ratio = (tangential.abs() / (f * n.load)).min(1.0);
            t.c_stick = stickslip_graded::partial_slip::stick_half_width(a, n.k, ratio);
            t.tangential = tangential;
            t.mu = f * tangential.signum();
            t.graded_stick = (t.c_stick > 0.0).then_some(t.c_stick);
        }
    }
    Ok(t)
}

impl LineTraction {
    /// The shear traction at `x` (0 without a friction stage).
    pub fn q(&self, x: f64, n: &LineContact) -> f64 {
        match self.kind {
            None => 0.0,
            Some(LineFriction::Cattaneo { .. }) => self.cattaneo.map_or(0.0, |c| c.traction(x)),
            Some(LineFriction::GradedPartialSlip { .. }) => {
                stickslip_graded::partial_slip::traction(
                    x,
                    n.a,
                    self.graded_stick,
                    n.p0,
                    n.k,
                    self.mu,
                )
            }
            Some(LineFriction::Sliding { .. }) => self.mu * n.pressure(x),
        }
    }

    /// The surface load the graded integrators see (pressure and shear).
    pub fn surface_load(&self, n: &LineContact) -> Result<SurfaceLoad, SceneError> {
        let (a, p0, k) = (n.a, n.p0, n.k);
        if n.punch {
            let patch = LoadPatch::new(0.0, a, -0.5, Profile::Uniform { p: p0, q: self.mu * p0 })
                .map_err(|e| solver_err("punch load", e))?;
            return Ok(SurfaceLoad::new().with_patch(patch));
        }
        let (mu, c) = match self.kind {
            Some(LineFriction::Cattaneo { friction, tangential }) => {
                (friction * tangential.signum(), (self.c_stick > 0.0).then_some(self.c_stick))
            }
            _ => (self.mu, self.graded_stick),
        };
        let sliding = matches!(self.kind, Some(LineFriction::Sliding { .. }));
        match c {
            Some(c) if c < a => SurfaceLoad::partial_slip(a, c, p0, k, mu),
            _ if self.kind.is_some() && !sliding && self.c_stick >= a => {
                SurfaceLoad::cylinder(a, p0, k, 0.0)
            }
            _ => SurfaceLoad::cylinder(a, p0, k, mu),
        }
        .map_err(|e| solver_err("surface load", e))
    }

    /// The stick and slip intervals along x.
    pub fn zones(&self, a: f64, friction_stage: bool, friction_possible: bool) -> Zones {
        let z = |stick: Vec<[f64; 2]>, slip: Vec<[f64; 2]>| Zones {
            stick,
            slip,
            coordinate: "x",
            grid: None,
        };
        let c = self.c_stick;
        if !friction_stage {
            if friction_possible {
                z(vec![[-a, a]], vec![])
            } else {
                z(vec![], vec![[-a, a]])
            }
        } else if c <= 0.0 {
            z(vec![], vec![[-a, a]])
        } else if c >= a {
            z(vec![[-a, a]], vec![])
        } else {
            z(vec![[-c, c]], vec![[-a, -c], [c, a]])
        }
    }
}

// ---------------------------------------------------------------------------------------
// 3D

/// What a 3D tangential stage produces.
pub(crate) struct TangentialOut {
    /// Tangential force (N, signed along the load direction).
    pub tangential: f64,
    /// Twisting moment (N m).
    pub moment: f64,
    /// Rigid-body motion of the stick zone.
    pub rigid: RigidOut,
    /// Stick and slip zones.
    pub zones: Zones,
    /// 3D rolling: the creep forces and spin moment (fx, fy, mz).
    pub creep: Option<[f64; 3]>,
}

/// No tangential stage: every contact cell sticks when friction can act, slips otherwise.
pub(crate) fn none(lat: &mut Lattice, friction: f64) -> TangentialOut {
    if friction == 0.0 {
        for row in &mut lat.stick {
            for s in row.iter_mut().filter(|s| **s == 1) {
                *s = 0;
            }
        }
    }
    TangentialOut {
        creep: None,
        tangential: 0.0,
        moment: 0.0,
        rigid: RigidOut { tangential: None, rotation: None, per_body: None },
        zones: Zones { stick: vec![], slip: vec![], coordinate: "grid", grid: None },
    }
}

/// Full sliding along `angle`: q = f p on every contact cell.
pub(crate) fn sliding(
    lat: &mut Lattice,
    f: f64,
    load: f64,
    angle: f64,
    cx: &mut Ctx<'_>,
) -> TangentialOut {
    let (c, s) = (angle.cos(), angle.sin());
    for i in 0..lat.x.len() {
        for j in 0..lat.y.len() {
            if lat.stick[i][j] >= 0 {
                let q = f * lat.p[i][j];
                lat.qx[i][j] = q * c;
                lat.qy[i][j] = q * s;
                lat.stick[i][j] = 0;
                cx.ev.friction += 1;
            }
        }
    }
    TangentialOut {
        creep: None,
        tangential: f * load,
        moment: 0.0,
        rigid: RigidOut { tangential: None, rotation: None, per_body: None },
        zones: Zones {
            stick: vec![],
            slip: vec![[0.0, 1.0]],
            coordinate: "fraction of the contact (all slips)",
            grid: None,
        },
    }
}

/// Show a closed-form partial-slip traction on the lattice consistently with the lattice's
/// pressure: one discrete rule for p and q, so that the written arrays satisfy Coulomb's
/// law and equilibrium exactly, as a grid solution does.
///
/// In each contact cell the closed form's ratio $\rho = q/p \in [0, f]$ (at the cell
/// centre) splits the full-slip traction $f p_k$ into the part carried and a stick
/// correction $c_k = (f - \rho)\,p_k \ge 0$ (zero in the slip zone). The cell traction is
/// $q_k = f p_k - \lambda c_k$ with the one factor
/// $\lambda = (\sum_k f p_k w_k - L)/\sum_k c_k w_k$ that makes the lattice resultant equal
/// the applied load $L$ ($w_k = 1$ for a force, $w_k = r_k$ for a moment about the centre).
/// $\lambda - 1$ is the sampling error of the lattice; $|q_k| \le f p_k$ holds while
/// $0 \le \lambda \le 2$. Returns $\lambda$.
pub(crate) fn sample_consistently(
    lat: &mut Lattice,
    f: f64,
    area: f64,
    load: f64,
    cell: impl Fn(f64, f64) -> (f64, f64, (f64, f64)),
) -> f64 {
    // (i, j, p, c, w, direction)
    let mut cells = Vec::new();
    let (mut full, mut corr) = (0.0, 0.0);
    for i in 0..lat.x.len() {
        for j in 0..lat.y.len() {
            if lat.stick[i][j] >= 0 {
                let p = lat.p[i][j];
                let (ratio, w, dir) = cell(lat.x[i], lat.y[j]);
                let c = (f - ratio) * p;
                full += f * p * w * area;
                corr += c * w * area;
                cells.push((i, j, p, c, dir));
            }
        }
    }
    let lambda = if corr > 0.0 { (full - load) / corr } else { 1.0 };
    for (i, j, p, c, dir) in cells {
        let q = f * p - lambda * c;
        lat.qx[i][j] = q * dir.0;
        lat.qy[i][j] = q * dir.1;
    }
    lambda
}

/// Mindlin's partial slip of a Hertz circle.
pub(crate) fn mindlin(
    lat: &mut Lattice,
    r: &ContactRecipe,
    n: &ContactSolution,
    force: Force,
    cx: &mut Ctx<'_>,
) -> Result<TangentialOut, SceneError> {
    let m = Mindlin::new(n.ax, n.load, r.friction, force.magnitude)
        .map_err(|e| solver_err("Mindlin", e))?;
    cx.ev.friction += 1;
    let astar = m.stick_radius();
    let e = (force.direction.cos(), force.direction.sin());
    let (a, p0, f) = (n.ax, n.p0, r.friction);
    cx.sampling =
        Some(sample_consistently(lat, f, n.grid.element_area(), force.magnitude, |x, y| {
            let rr = x.hypot(y);
            let p = p0 * ((1.0 - rr / a) * (1.0 + rr / a)).max(0.0).sqrt();
            let ratio = if p > 0.0 { m.traction(rr) / p } else { f };
            (ratio, 1.0, e)
        }));
    for i in 0..lat.x.len() {
        for j in 0..lat.y.len() {
            if lat.stick[i][j] >= 0 {
                cx.ev.friction += 1;
                lat.stick[i][j] = i8::from(lat.x[i].hypot(lat.y[j]) < astar);
            }
        }
    }
    let d = [m.compliance_per_body(&r.bodies.substrate), m.compliance_per_body(&r.bodies.indenter)];
    Ok(TangentialOut {
        creep: None,
        zones: Zones {
            stick: vec![[0.0, astar]],
            slip: vec![[astar, n.ax]],
            coordinate: "radius",
            grid: None,
        },
        ..shifted(force, d)
    })
}

/// Cattaneo's partial slip of a Hertz ellipse, the load along an axis.
pub(crate) fn cattaneo(
    lat: &mut Lattice,
    r: &ContactRecipe,
    n: &ContactSolution,
    force: Force,
    along_x: bool,
    cx: &mut Ctx<'_>,
) -> Result<TangentialOut, SceneError> {
    // a is the semi-axis along the load
    let (al, ac) = if along_x { (n.ax, n.ay) } else { (n.ay, n.ax) };
    let m = Cattaneo::new(al, ac, n.load, r.friction, force.magnitude)
        .map_err(|e| solver_err("Cattaneo", e))?;
    cx.ev.friction += 1;
    let sc = m.stick_scale();
    let e = (force.direction.cos(), force.direction.sin());
    let (p0, f) = (m.peak_pressure(), r.friction);
    let local = move |x: f64, y: f64| if along_x { (x, y) } else { (y, x) };
    cx.sampling =
        Some(sample_consistently(lat, f, n.grid.element_area(), force.magnitude, |x, y| {
            let (u, v) = local(x, y);
            let p = p0 * (1.0 - (u / al).powi(2) - (v / ac).powi(2)).max(0.0).sqrt();
            let ratio = if p > 0.0 { m.traction(u, v) / p } else { f };
            (ratio, 1.0, e)
        }));
    for i in 0..lat.x.len() {
        for j in 0..lat.y.len() {
            if lat.stick[i][j] >= 0 {
                let (u, v) = local(lat.x[i], lat.y[j]);
                cx.ev.friction += 1;
                lat.stick[i][j] = i8::from((u / (sc * al)).powi(2) + (v / (sc * ac)).powi(2) < 1.0);
            }
        }
    }
    let d = [m.compliance_per_body(&r.bodies.substrate), m.compliance_per_body(&r.bodies.indenter)];
    Ok(TangentialOut {
        creep: None,
        zones: Zones {
            stick: vec![[-sc * al, sc * al]],
            slip: vec![[-al, -sc * al], [sc * al, al]],
            coordinate: "x along the load",
            grid: None,
        },
        ..shifted(force, d)
    })
}

/// The outcome of a closed-form force on a circle or ellipse: the force, no moment, and the
/// rigid shift `d` per body (their sum relative), zones to be filled in.
fn shifted(force: Force, d: [f64; 2]) -> TangentialOut {
    TangentialOut {
        creep: None,
        tangential: force.signed,
        moment: 0.0,
        rigid: RigidOut { tangential: Some(d[0] + d[1]), rotation: None, per_body: Some(d) },
        zones: Zones { stick: vec![], slip: vec![], coordinate: "", grid: None },
    }
}
