//! The stickslip scene format: a contact problem as a TOML file or built in code, read,
//! converted to SI and validated, with errors naming file, line, column, key and what is
//! allowed.
//!
//! A scene describes one contact problem (bodies, materials, loads, motion, requested
//! outputs); its reference is the repository's `docs/SCENES.md`. This crate knows the format
//! only: it solves nothing and decides nothing about methods. The run (planner, stages,
//! audit) is `stickslip-run`, the result files are `stickslip-report`, sweeps are
//! `stickslip-sweep`. The one routine it takes from a physics crate is the synthesis of a
//! random rough surface (`stickslip_lattice::roughness`), which the reader calls for
//! `[geometry.roughness]` without a file: the heights are part of the scene as read, and a
//! parameter the synthesis refuses is located in the file like any other value.
//!
//! - [`Scene`]: the typed scene (every quantity in SI); [`Scene::from_toml_str`] and
//!   [`Scene::from_file`] read and validate it, [`SceneBuilder`] builds it in code and
//!   validates it the same way;
//! - [`units`]: quantities with units to SI; [`materials`]: named materials (`material =
//!   "steel"`);
//! - [`SceneError`] and [`ErrorKind`]: the error of a scene, also used for what the run
//!   refuses (an [`Issue`] located by [`Scene::locate`]) and for a failed audit (its
//!   [`Check`]s), and the exit status of each kind;
//! - [`json_schema`]: the JSON Schema of the format, for editors; [`templates`]: the
//!   commented starting scenes of `stickslip new`.
//!
//! ```
//! use stickslip_scene::{Geometry, Scene};
//! let scene = Scene::from_toml_str(
//!     r#"
//! [geometry]
//! kind = "cylinder"
//! radius = "20 mm"
//! [substrate]
//! model = "homogeneous"
//! e = "210 GPa"
//! nu = 0.3
//! [indenter]
//! model = "same"
//! [load]
//! normal = "100 kN/m"
//! tangential = "15 kN/m"
//! friction = 0.3
//! "#,
//!     None,
//! )
//! .unwrap();
//! assert_eq!(scene.geometry, Geometry::Cylinder { radius: 0.02 });
//! assert_eq!(scene.load.friction, 0.3);
//! // A refusal names the key, and the line and column of its value.
//! let text = "[geometry]\nkind = \"cylinder\"\nradius = \"-1 mm\"\n[substrate]\nmodel = \"homogeneous\"\ne = \"210 GPa\"\nnu = 0.3\n[load]\nnormal = \"1 kN/m\"\n";
//! let e = Scene::from_toml_str(text, None).unwrap_err();
//! assert_eq!(e.key.as_deref(), Some("geometry.radius"));
//! assert_eq!(e.position, Some((3, 10)));
//! ```

pub mod eng;
mod error;
pub mod json_schema;
pub mod materials;
mod raw;
mod scene;
pub mod templates;
pub mod units;

pub use error::{Check, ErrorKind, Issue, SceneError};
pub use scene::ranges;
pub use scene::{
    patch_bounds, AdhesionKeys, ApproachPath, Cycle, Elastic, Ellipse, FieldGrid, FieldScale,
    Geometry, HeightStep, History, HistoryControl, Indenter, Interface, Load, Method, Motion,
    NormalLoad, NormalSweep, Outputs, Patch, PatchShape, PathSource, Profile, ProfileFile,
    RailSide, Scene, SceneBuilder, SolverOptions, Source, Substrate, Surface, SurfaceBoundary,
    Transient, TransientStart, WheelLoadDefinition, WheelRail, WheelsetPosition, DEFAULT_SCENE,
    MAX_GRID,
};
pub use units::{parse_quantity, Dim, UnitError};
