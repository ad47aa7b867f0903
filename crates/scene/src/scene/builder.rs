//! Building a [`Scene`] in code: the second way in beside TOML (the Python package uses it).
//! Values are SI; [`SceneBuilder::build`] runs the same validation as the TOML reader.
//!
//! ```
//! use stickslip_scene::{Elastic, Geometry, Indenter, Scene, Substrate};
//! let steel = Elastic { e: 210e9, nu: 0.3 };
//! let scene = Scene::builder(Geometry::Sphere { radius: 0.0254 }, Substrate::Homogeneous(steel))
//!     .title("steel ball on steel")
//!     .indenter(Indenter::Same)
//!     .normal_force(9608.0)
//!     .tangential(640.5, 0.0)
//!     .friction(0.1)
//!     .build()
//!     .unwrap();
//! assert_eq!(scene.load.friction, 0.1);
//! ```

use super::{
    FieldGrid, Geometry, Indenter, Load, Method, Motion, NormalLoad, Outputs, Patch, Scene,
    SolverOptions, Substrate,
};
use crate::error::SceneError;

/// A scene under construction; see the module docs.
#[derive(Debug, Clone)]
#[must_use]
pub struct SceneBuilder {
    scene: Scene,
}

impl SceneBuilder {
    /// A static scene of `geometry` on `substrate` with a rigid indenter, no load yet
    /// (patches carry their own), no friction, surface output on, default solver options.
    pub fn new(geometry: Geometry, substrate: Substrate) -> Self {
        let normal = match &geometry {
            Geometry::Patches(ps) => NormalLoad::FromPatches(ps.iter().map(Patch::force).sum()),
            _ => NormalLoad::Force(0.0),
        };
        SceneBuilder {
            scene: Scene {
                title: "untitled scene".to_string(),
                file: None,
                geometry,
                substrate,
                indenter: Indenter::Rigid,
                load: Load {
                    normal,
                    tangential: 0.0,
                    direction_deg: 0.0,
                    friction: 0.0,
                    sliding: false,
                    moment: 0.0,
                    normal_sweep: None,
                    approach_path: None,
                    history: None,
                },
                motion: Motion::Static,
                outputs: Outputs { surface: true, field: None, cycle: None, plots: true },
                solver: SolverOptions::default(),
                interface: super::Interface::default(),
                source: None,
            },
        }
    }

    /// The title.
    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.scene.title = title.into();
        self
    }

    /// The body above.
    pub fn indenter(mut self, indenter: Indenter) -> Self {
        self.scene.indenter = indenter;
        self
    }

    /// The normal force P (N/m in 2D, N in 3D).
    pub fn normal_force(mut self, p: f64) -> Self {
        self.scene.load.normal = NormalLoad::Force(p);
        self
    }

    /// The contact half-width a (m) instead of the force.
    pub fn half_width(mut self, a: f64) -> Self {
        self.scene.load.normal = NormalLoad::HalfWidth(a);
        self
    }

    /// A tangential force T along `direction_deg` (degrees from +x).
    pub fn tangential(mut self, t: f64, direction_deg: f64) -> Self {
        self.scene.load.tangential = t;
        self.scene.load.direction_deg = direction_deg;
        self
    }

    /// The Coulomb friction coefficient.
    pub fn friction(mut self, f: f64) -> Self {
        self.scene.load.friction = f;
        self
    }

    /// Full sliding, q = f p.
    pub fn sliding(mut self, sliding: bool) -> Self {
        self.scene.load.sliding = sliding;
        self
    }

    /// A twisting moment about the contact normal (N m, 3D).
    pub fn moment(mut self, m: f64) -> Self {
        self.scene.load.moment = m;
        self
    }

    /// Steady rolling at `speed` (m/s) with `creep`.
    pub fn rolling(mut self, speed: f64, creep: f64) -> Self {
        self.scene.motion = Motion::Rolling { speed, creep };
        self
    }

    /// Surface arrays on or off.
    pub fn surface(mut self, on: bool) -> Self {
        self.scene.outputs.surface = on;
        self
    }

    /// Subsurface stresses on a grid.
    pub fn field(mut self, grid: FieldGrid) -> Self {
        self.scene.outputs.field = Some(grid);
        self
    }

    /// A load path (`[load.history]`), solved step by step.
    pub fn history(mut self, history: super::History) -> Self {
        self.scene.load.history = Some(history);
        self
    }

    /// A Mindlin–Deresiewicz cycle at amplitude T*/(fP) with `points` points.
    pub fn cycle(mut self, amplitude: f64, points: usize) -> Self {
        self.scene.outputs.cycle = Some(super::Cycle { amplitude, points });
        self
    }

    /// SVG plots beside the JSON and in report.html (on by default).
    pub fn plots(mut self, on: bool) -> Self {
        self.scene.outputs.plots = on;
        self
    }

    /// The method, grid side and relative tolerance.
    pub fn solver(mut self, method: Method, grid: usize, tolerance: f64) -> Self {
        self.scene.solver = SolverOptions { method, grid, tolerance, cell: None };
        self
    }

    /// The scene, validated exactly as a TOML file is.
    ///
    /// # Errors
    /// The first refusal, with the key to change and a hint.
    #[allow(clippy::result_large_err)]
    pub fn build(self) -> Result<Scene, SceneError> {
        self.scene.validate()?;
        Ok(self.scene)
    }
}
