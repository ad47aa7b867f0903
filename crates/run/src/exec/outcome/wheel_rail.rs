//! The wheel–rail part of result.json (`wheel_rail`): the wheel, its patches and their
//! creep forces.

use serde::Serialize;

/// `wheel_rail` in result.json: one wheel on its rail (track coordinates: x rolling, y to
/// the right, z down; SI).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WheelRailOut {
    /// "left" or "right".
    pub side: &'static str,
    /// The wheelset's vertical position (m, z down; 0 where the undeformed profiles first
    /// touch at the nominal height).
    pub z_wheelset: f64,
    /// The wheelset's approach beyond first touch (m).
    pub approach: f64,
    /// The force of the wheel on the rail in track coordinates (N).
    pub total_on_rail: TrackForce,
    /// The given vertical wheel load (N), when force-controlled.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vertical_load: Option<f64>,
    /// What carries `vertical_load` (`load.vertical`): "normal" (the normal forces'
    /// vertical components, `normal_vertical`) or "total" (the total vertical force,
    /// `total_on_rail.fz`, creep forces included).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vertical: Option<&'static str>,
    /// The sum over the patches of the normal forces' vertical components (N).
    pub normal_vertical: f64,
    /// The contact patches, in the library's order.
    pub patches: Vec<WheelRailPatchOut>,
    /// The rail and wheel profiles at the solved position as polylines in track
    /// coordinates (y, z), m; the wheel's section through its lowest points (for drawing;
    /// not in result.json).
    #[serde(skip)]
    pub profiles: [Vec<[f64; 2]>; 2],
}

/// A force in track coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TrackForce {
    /// Along x (rolling direction), N.
    pub fx: f64,
    /// Along y (to the right), N.
    pub fy: f64,
    /// Along z (down), N.
    pub fz: f64,
}

/// The creepages of one patch.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CreepageOut {
    /// Longitudinal creepage (dimensionless).
    pub longitudinal: f64,
    /// Lateral creepage (dimensionless).
    pub lateral: f64,
    /// Spin creepage (1/m).
    pub spin: f64,
}

/// One contact patch of a wheel on its rail.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WheelRailPatchOut {
    /// The contact reference point's y in the rail profile's coordinates (m).
    pub y_rail: f64,
    /// The contact reference point's z in the rail profile's coordinates (m).
    pub z_rail: f64,
    /// The wheel point's y in the wheel profile's coordinates (m).
    pub y_wheel: f64,
    /// The wheel point's z in the wheel profile's coordinates (m).
    pub z_wheel: f64,
    /// The reference point in track coordinates (x, y, z), m.
    pub reference: [f64; 3],
    /// Contact angle (rad): rotation about x from the track z axis to the patch normal.
    pub contact_angle: f64,
    /// Rolling radius (m).
    pub rolling_radius: f64,
    /// Creepages at the reference point.
    pub creepage: CreepageOut,
    /// Normal force on the rail (N).
    #[serde(rename = "fn")]
    pub fn_: f64,
    /// Longitudinal creep force on the rail (N, patch plane).
    pub fx: f64,
    /// Lateral creep force on the rail (N, patch plane).
    pub fs: f64,
    /// Spin moment on the rail about the reference point (N m).
    pub mn: f64,
    /// Peak pressure (Pa).
    pub pmax: f64,
    /// Contact area (m^2).
    pub area: f64,
    /// Fraction of the contact cells that stick (absent without creep forces).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stick_fraction: Option<f64>,
    /// The force of this patch on the rail in track coordinates (N).
    pub force_on_rail: TrackForce,
    /// Contact cells.
    pub contact_cells: usize,
    /// The patch lattice: cells along x and across (s), their sides and lower corner (m).
    pub lattice: PatchLatticeOut,
    /// The tangential solver's iterations and residual, when it ran.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tangential: Option<TangentialSolveOut>,
    /// The Coulomb check of this patch: max over its contact cells of (|q| - f p)/(f pmax).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub coulomb: Option<f64>,
    /// The patch's maps on its lattice (written as `patch{k}_*.npy`, drawn in report.html;
    /// not in result.json).
    #[serde(skip)]
    pub maps: PatchMaps,
}

/// One wheel-rail patch's maps on its lattice, row-major `(ns, nx)`: row `j` across the
/// patch (s), column `i` along x; patch coordinates (m), forces on the rail.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PatchMaps {
    /// Cell centres along x (m), `nx` of them.
    pub x: Vec<f64>,
    /// Cell centres across the patch, s (m), `ns` of them.
    pub s: Vec<f64>,
    /// Pressure (Pa).
    pub pressure: Vec<f64>,
    /// The undeformed gap at the final wheelset height (m; negative where the profiles
    /// interpenetrate).
    pub gap: Vec<f64>,
    /// Traction on the rail along x (Pa), with a tangential solution.
    pub qx: Option<Vec<f64>>,
    /// Traction on the rail along s (Pa), with a tangential solution.
    pub qs: Option<Vec<f64>>,
    /// 1 stick, 0 slip, -1 outside the contact, with a tangential solution (else 0 in the
    /// contact).
    pub stick: Vec<i8>,
}

/// A patch lattice as reported.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PatchLatticeOut {
    /// Cells along x.
    pub nx: usize,
    /// Cells across the patch.
    pub ns: usize,
    /// Cell side along x (m).
    pub hx: f64,
    /// Cell side across (m).
    pub hs: f64,
    /// Lower corner (x, s), m.
    pub origin: [f64; 2],
}

/// The tangential solve of one patch.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TangentialSolveOut {
    /// Iterations.
    pub iterations: usize,
    /// Final relative residual.
    pub residual: f64,
}
