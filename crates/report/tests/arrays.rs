//! The array files of a result: field.csv with its fixed columns, the `.npy` arrays of a
//! large field box and of a surface's maps, each read back and compared with the outcome.

use stickslip_report::write_outputs;
use stickslip_run::{run, Outcome, RunOptions};
use stickslip_scene::Scene;

const FIELD_SPHERE: &str = "[geometry]\nkind = \"sphere\"\nradius = \"10 mm\"\n[substrate]\nmodel = \"homogeneous\"\ne = \"210 GPa\"\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = \"100 N\"\nLOAD\n[outputs]\nfield = FIELD\n[solver]\nSOLVER\n";

#[allow(clippy::result_large_err)]
fn field(load: &str, field: &str, solver: &str) -> Result<Outcome, stickslip_scene::SceneError> {
    let src = FIELD_SPHERE.replace("LOAD", load).replace("FIELD", field).replace("SOLVER", solver);
    run(&Scene::from_toml_str(&src, Some("f.toml".into()))?, &RunOptions::default())
}

const SURFACE: &str = "[geometry]\nkind = \"surface\"\nBOUNDARY\nsize = [\"0.8 mm\", \"0.8 mm\"]\ncells = [128, 128]\n[geometry.profile]\nPROFILE\nROUGH\n[substrate]\nmodel = \"homogeneous\"\ne = \"210 GPa\"\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nLOAD\n";

const SPHERE: &str = "shape = \"sphere\"\nradius = \"10 mm\"";

#[allow(clippy::result_large_err)]
fn surface(
    boundary: &str,
    profile: &str,
    rough: &str,
    load: &str,
) -> Result<Outcome, stickslip_scene::SceneError> {
    let src = SURFACE
        .replace("BOUNDARY", boundary)
        .replace("PROFILE", profile)
        .replace("ROUGH", rough)
        .replace("LOAD", load);
    let dir = std::env::temp_dir();
    run(&Scene::from_toml_str(&src, Some(dir.join("s.toml")))?, &RunOptions::default())
}

#[test]
fn field_csv_has_the_fixed_columns_and_large_boxes_write_npy() {
    let out = field(
        "",
        "{ x = [-1.5, 1.5, 201], y = [-1, 1, 101], z = [0.1, 1.0, 2], scale = \"a\" }",
        "grid = 16",
    )
    .unwrap();
    let v = out.field.volume().unwrap();
    assert!(v.values.is_none(), "40,602 points are not inlined");
    let dir = std::env::temp_dir().join(format!("stickslip-field3d-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    write_outputs(&out, &dir, false).unwrap();
    let csv = std::fs::read_to_string(dir.join("field.csv")).unwrap();
    assert_eq!(
        csv.lines().next().unwrap(),
        "x,y,z,sxx,syy,szz,sxy,syz,sxz,von_mises,tresca,max_principal"
    );
    assert_eq!(csv.lines().count(), 1 + 201 * 101 * 2);
    let npy = std::fs::read(dir.join("field_szz.npy")).unwrap();
    assert_eq!(&npy[..8], b"\x93NUMPY\x01\x00");
    let hlen = u16::from_le_bytes([npy[8], npy[9]]) as usize;
    assert_eq!((10 + hlen) % 64, 0, "header padded to 64 bytes");
    let header = std::str::from_utf8(&npy[10..10 + hlen]).unwrap();
    assert!(
        header.contains("'descr': '<f8'") && header.contains("'shape': (2, 101, 201)"),
        "{header}"
    );
    assert_eq!(npy.len(), 10 + hlen + 8 * 201 * 101 * 2);
    // the first value is the first szz of the result
    let first = f64::from_le_bytes(npy[10 + hlen..18 + hlen].try_into().unwrap());
    assert_eq!(first, v.arrays.szz[0]);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_surface_writes_its_maps_as_npy_with_the_gap_closed_under_pressure() {
    let out = surface("", SPHERE, "", "normal = \"10 N\"").unwrap();
    let dir = std::env::temp_dir().join(format!("stickslip-surface-npy-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    write_outputs(&out, &dir, false).unwrap();
    let read = |name: &str| -> Vec<f64> {
        let b = std::fs::read(dir.join(name)).unwrap();
        let h = u16::from_le_bytes([b[8], b[9]]) as usize;
        let header = std::str::from_utf8(&b[10..10 + h]).unwrap();
        assert!(header.contains("'shape': (128, 128)"), "{name}: {header}");
        b[10 + h..].chunks_exact(8).map(|c| f64::from_le_bytes(c.try_into().unwrap())).collect()
    };
    let (p, gap) = (read("surface_p.npy"), read("surface_gap.npy"));
    let delta = out.contact.indentation.unwrap();
    let mut in_contact = 0;
    for (p, g) in p.iter().zip(&gap) {
        if *p > 0.0 {
            in_contact += 1;
            assert!(g.abs() <= 1e-8 * delta, "gap {g} under pressure {p}");
        } else {
            assert!(*g >= -1e-8 * delta, "penetration {g}");
        }
    }
    assert!(in_contact > 100);
    let _ = std::fs::remove_dir_all(&dir);
}
