//! The builder is a second way into the same validated scene: it must give exactly the
//! scene (and so the result) the TOML reader gives, and refuse what the reader refuses with
//! the same key and hint; refusals found after reading are located in the file.

use stickslip_run::{check, read_scene, run, RunOptions};
use stickslip_scene::{Elastic, ErrorKind, Geometry, Indenter, Method, Scene, Substrate};

const IN: f64 = 0.0254;
const LBF: f64 = 4.4482216152605;
const PSI: f64 = LBF / (IN * IN);

fn ex1_builder() -> stickslip_scene::SceneBuilder {
    Scene::builder(
        Geometry::Sphere { radius: 1.0 * IN },
        Substrate::Homogeneous(Elastic { e: 30e6 * PSI, nu: 0.3 }),
    )
    .indenter(Indenter::Same)
    .normal_force(2160.0 * LBF)
    .tangential(144.0 * LBF, 0.0)
    .friction(0.1)
}

#[test]
fn builder_and_toml_give_the_same_result() {
    let toml = Scene::from_file(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../scenes/seed002_ex1_mindlin.toml"
    )))
    .unwrap();
    let built =
        ex1_builder().title(toml.title.clone()).solver(Method::Auto, 20, 1e-10).build().unwrap();
    assert_eq!(built.geometry, toml.geometry);
    assert_eq!(built.substrate, toml.substrate);
    assert_eq!(built.load, toml.load);
    let a = run(&built, &RunOptions::default()).unwrap();
    let b = run(&toml, &RunOptions::default()).unwrap();
    assert_eq!(a.contact, b.contact);
    assert_eq!(a.forces, b.forces);
    assert_eq!(a.zones, b.zones);
    assert_eq!(a.rigid_displacement, b.rigid_displacement);
    assert_eq!(a.surface, b.surface);
}

#[test]
fn builder_refuses_what_the_reader_refuses() {
    let e = Scene::builder(
        Geometry::Sphere { radius: -1.0 },
        Substrate::Homogeneous(Elastic { e: 2e11, nu: 0.3 }),
    )
    .normal_force(10.0)
    .build()
    .unwrap_err();
    assert_eq!(e.kind, ErrorKind::OutOfRange);
    assert_eq!(e.key.as_deref(), Some("geometry.radius"));
    assert!(e.hint.is_some());
    assert_eq!(e.position, None, "a scene built in code has no position");

    let e = ex1_builder().tangential(0.0, f64::NAN).build().unwrap_err();
    assert_eq!(e.key.as_deref(), Some("load.direction_deg"), "{e}");

    let e = ex1_builder().tangential(400.0 * LBF, 0.0).build().unwrap_err();
    assert_eq!((e.kind, e.key.as_deref()), (ErrorKind::Impossible, Some("load.tangential")));

    // The planner's refusals of a built scene, as a run gives them before solving.
    let e = check(&ex1_builder().solver(Method::Fast, 32, 0.5).build().unwrap()).unwrap_err();
    assert_eq!(e.key.as_deref(), Some("solver.tolerance"), "{e}");
    assert!(e.hint.as_deref().unwrap_or("").contains("1e-14"), "{e}");
}

fn err(src: &str) -> stickslip_scene::SceneError {
    read_scene(src, Some("s.toml".into())).unwrap_err()
}

const BASE: &str = "[geometry]\nkind = \"sphere\"\nradius = 0.01\n[substrate]\nmodel = \"homogeneous\"\ne = 2e11\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = 100.0\ntangential = 10.0\nfriction = 0.2\n";

#[test]
fn non_finite_values_are_refused_at_their_position() {
    let e = err(&format!("{BASE}direction_deg = nan\n"));
    assert_eq!(e.key.as_deref(), Some("load.direction_deg"), "{e}");
    assert_eq!(e.position, Some((14, 17)), "{e}");
    let e = err(&BASE.replace("radius = 0.01", "radius = inf"));
    assert_eq!(e.key.as_deref(), Some("geometry.radius"), "{e}");
    assert_eq!(e.position.map(|p| p.0), Some(3), "{e}");
}

#[test]
fn planner_refusals_are_located_at_the_key_or_its_table() {
    // A tolerance the fast solver does not support: at the value.
    let e = err(&format!("{BASE}[solver]\nmethod = \"fast\"\ntolerance = 0.5\n"));
    assert_eq!(e.key.as_deref(), Some("solver.tolerance"), "{e}");
    assert_eq!(e.position.map(|p| p.0), Some(16), "{e}");
    // A key the file does not hold (the viscoelastic model is refused at substrate.model).
    let visco = "[geometry]\nkind = \"sphere\"\nradius = 0.01\n[substrate]\nmodel = \"viscoelastic\"\ne = 1e7\nnu = 0.45\nalpha = 2.0\nbeta = 1.0\n[load]\nnormal = 1.0\n";
    let e = err(visco);
    assert_eq!(e.key.as_deref(), Some("substrate.model"), "{e}");
    assert_eq!(e.position.map(|p| p.0), Some(5), "{e}");
}
