//! Stage 1, normal contact: the contact size, peak pressure and load, in 2D from the line
//! recipe, in 3D together with the lattice the later stages fill.

use std::f64::consts::PI;

use stickslip_graded::{GradedMaterial, RigidCylinder};
use stickslip_halfspace::hertz::{HertzEllipse, HertzLine, HertzSphere};
use stickslip_halfspace::material::composite_modulus;
use stickslip_traction::ContactGrid;

use super::lattice::{self, Lattice};
use super::{solver_err, Ctx};
use crate::error::SceneError;
use crate::plan::recipe::{ContactNormal, ContactRecipe, LineLoad, LineNormal};
use crate::scene::{patch_bounds, Patch};

/// The normal solution of a line contact.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LineContact {
    /// Half-width (m).
    pub a: f64,
    /// Peak pressure (Pa); for the punch, the pressure scale $P/(\pi a)$.
    pub p0: f64,
    /// Load per unit length (N/m).
    pub load: f64,
    /// Absolute indentation (graded only).
    pub indentation: Option<f64>,
    /// The graded material, on a graded substrate.
    pub graded: Option<GradedMaterial>,
    /// Pressure exponent: $p = p_0(1-x^2/a^2)^{(1+k)/2}$ (k = 0 for Hertz).
    pub k: f64,
    /// A flat punch: $p = p_0/\sqrt{1-x^2/a^2}$.
    pub punch: bool,
    /// Whether any friction acts (for the zones when no traction stage runs).
    pub friction_possible: bool,
}

impl LineContact {
    /// The pressure at $x$.
    pub fn pressure(&self, x: f64) -> f64 {
        let t = x / self.a;
        if t.abs() >= 1.0 {
            0.0
        } else if self.punch {
            self.p0 / ((1.0 - t) * (1.0 + t)).sqrt()
        } else {
            self.p0 * ((1.0 - t) * (1.0 + t)).powf(0.5 * (1.0 + self.k))
        }
    }
}

/// The normal contact of a line recipe.
pub(crate) fn line(
    normal: &LineNormal,
    friction: f64,
    cx: &mut Ctx<'_>,
) -> Result<LineContact, SceneError> {
    let friction_possible = friction > 0.0;
    let out = match *normal {
        LineNormal::Graded { radius, load, material } => {
            let cyl = match load {
                LineLoad::HalfWidth(a) => RigidCylinder::from_half_width(&material, radius, a),
                LineLoad::Force(p) => RigidCylinder::from_load(&material, radius, p),
            }
            .map_err(|e| solver_err("rigid cylinder (corrected eq 15)", e))?;
            let h = cyl.indentation().map_err(|e| solver_err("indentation (eq 16)", e))?;
            LineContact {
                a: cyl.half_width(),
                p0: cyl.p0(),
                load: cyl.load(),
                indentation: Some(h),
                graded: Some(material),
                k: material.k(),
                punch: false,
                friction_possible,
            }
        }
        LineNormal::Hertz { radius, load, substrate, indenter } => {
            let es = composite_modulus(&substrate, &indenter);
            let h = match load {
                LineLoad::HalfWidth(a) => HertzLine::from_half_width(a, radius, es),
                LineLoad::Force(p) => HertzLine::new(p, radius, es),
            }
            .map_err(|e| solver_err("2D Hertz", e))?;
            cx.notes.push(format!(
                "2D contact: no absolute indentation exists; the approach relative to the surface point at 10 a is {:.6e} m",
                h.approach_relative(10.0 * h.half_width())
            ));
            LineContact {
                a: h.half_width(),
                p0: h.max_pressure(),
                load: h.load(),
                indentation: None,
                graded: None,
                k: 0.0,
                punch: false,
                friction_possible,
            }
        }
        LineNormal::Punch { half_width, force } => LineContact {
            a: half_width,
            p0: force / (PI * half_width),
            load: force,
            indentation: None,
            graded: None,
            k: 0.0,
            punch: true,
            friction_possible,
        },
    };
    cx.ev.normal_contact += 1;
    Ok(out)
}

/// The normal solution of a 3D contact, with its grid and lattice.
#[derive(Debug, Clone)]
pub(crate) struct ContactSolution {
    /// Semi-axis along x (m).
    pub ax: f64,
    /// Semi-axis along y (m).
    pub ay: f64,
    /// Peak pressure (Pa).
    pub p0: f64,
    /// Normal force (N).
    pub load: f64,
    /// Approach of distant points (Hertz), when defined.
    pub indentation: Option<f64>,
    /// The contact elements with their pressure.
    pub grid: ContactGrid,
    /// The lattice over the contact, pressure filled, every contact element marked stick.
    pub lattice: Lattice,
}

/// The normal contact of a 3D recipe, and the lattice of `r.grid` elements per side.
pub(crate) fn contact(r: &ContactRecipe, cx: &mut Ctx<'_>) -> Result<ContactSolution, SceneError> {
    let n = r.grid;
    let (ax, ay, p0, load, indentation) = match &r.normal {
        ContactNormal::Sphere { radius, force, e_star } => {
            let h = HertzSphere::new(*force, *radius, *e_star)
                .map_err(|e| solver_err("Hertz sphere", e))?;
            (h.contact_radius(), h.contact_radius(), h.max_pressure(), *force, Some(h.approach()))
        }
        ContactNormal::Ellipse { rx, ry, force, e_star } => {
            let h = HertzEllipse::new(*rx, *ry, *force, *e_star)
                .map_err(|e| solver_err("Hertz ellipse", e))?;
            (h.semi_axis_x(), h.semi_axis_y(), h.max_pressure(), *force, Some(h.approach()))
        }
        ContactNormal::EllipseGiven { a, b, force } => {
            (*a, *b, 3.0 * force / (2.0 * PI * a * b), *force, None)
        }
        ContactNormal::Patches(ps) => {
            let (lo, hi) = patch_bounds(ps);
            let pmax = ps.iter().map(|p| p.pressure).fold(0.0, f64::max);
            let p: f64 = ps.iter().map(Patch::force).sum();
            (0.5 * (hi[0] - lo[0]), 0.5 * (hi[1] - lo[1]), pmax, p, None)
        }
    };
    cx.ev.normal_contact += 1;

    let (grid, x0, y0, nx, ny) = match &r.normal {
        ContactNormal::Sphere { .. } => (ContactGrid::hertz_circle(ax, load, n), -ax, -ay, n, n),
        ContactNormal::Ellipse { .. } | ContactNormal::EllipseGiven { .. } => {
            (ContactGrid::hertz_ellipse(ax, ay, load, n, n), -ax, -ay, n, n)
        }
        ContactNormal::Patches(ps) => {
            let (lo, hi) = patch_bounds(ps);
            let h = (hi[0] - lo[0]).max(hi[1] - lo[1]) / n as f64;
            let grid = ContactGrid::from_patches(h, h, (lo[0], lo[1]), &lattice::grid_patches(ps));
            let nx = ((hi[0] - lo[0]) / h).round() as usize;
            let ny = ((hi[1] - lo[1]) / h).round() as usize;
            (grid, lo[0], lo[1], nx, ny)
        }
    };
    let grid = grid.map_err(|e| solver_err("contact grid", e))?;
    let mut lat = Lattice::new(x0, y0, grid.hx, grid.hy, nx.max(1), ny.max(1));
    for kk in 0..grid.len() {
        if let Some((i, j)) = lat.index(grid.x[kk], grid.y[kk]) {
            lat.p[i][j] = grid.pressure[kk];
            lat.stick[i][j] = 1;
        }
    }
    cx.ev.normal_contact += grid.len() as u64;
    Ok(ContactSolution { ax, ay, p0, load, indentation, grid, lattice: lat })
}
