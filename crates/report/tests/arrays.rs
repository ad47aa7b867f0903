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

/// The shipped wheel-on-rail scene (Manchester, position 5): each patch's maps are
/// written as `patch{k}_*.npy`, (ns, nx), and integrate to the patch's forces in
/// result.json; the stick map gives its stick fraction.
#[test]
fn a_wheel_on_rail_writes_each_patch_as_npy() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let file = root.join("scenes/wheel_rail_manchester_a22.toml");
    let text = std::fs::read_to_string(&file).unwrap();
    let out =
        run(&Scene::from_toml_str(&text, Some(file)).unwrap(), &RunOptions::default()).unwrap();
    let dir = std::env::temp_dir().join(format!("stickslip-wheel-rail-npy-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    write_outputs(&out, &dir, false).unwrap();
    let read = |name: &str| -> (Vec<usize>, Vec<f64>) {
        let b = std::fs::read(dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        let h = u16::from_le_bytes([b[8], b[9]]) as usize;
        let header = std::str::from_utf8(&b[10..10 + h]).unwrap();
        let shape = header.split("'shape': (").nth(1).unwrap().split(')').next().unwrap();
        let shape: Vec<usize> = shape
            .split(',')
            .filter(|t| !t.trim().is_empty())
            .map(|t| t.trim().parse().unwrap())
            .collect();
        let v = b[10 + h..]
            .chunks_exact(8)
            .map(|c| f64::from_le_bytes(c.try_into().unwrap()))
            .collect();
        (shape, v)
    };
    let w = out.wheel_rail.as_ref().unwrap();
    assert_eq!(w.patches.len(), 1);
    let p = &w.patches[0];
    let (_, x) = read("patch0_x.npy");
    let (_, s) = read("patch0_s.npy");
    assert_eq!((x.len(), s.len()), (p.lattice.nx, p.lattice.ns));
    assert!(
        (x[1] - x[0] - p.lattice.hx).abs() < 1e-15 && (s[1] - s[0] - p.lattice.hs).abs() < 1e-15
    );
    let (shape, pressure) = read("patch0_pressure.npy");
    assert_eq!(shape, [s.len(), x.len()]);
    let cell = p.lattice.hx * p.lattice.hs;
    let sum = |v: &[f64]| v.iter().sum::<f64>() * cell;
    assert!((sum(&pressure) / p.fn_ - 1.0).abs() < 1e-9, "{} vs {}", sum(&pressure), p.fn_);
    assert_eq!(pressure.iter().copied().fold(0.0, f64::max), p.pmax);
    let fmax = 0.3 * p.fn_;
    let (_, qx) = read("patch0_qx.npy");
    let (_, qs) = read("patch0_qs.npy");
    assert!((sum(&qx) - p.fx).abs() < 1e-9 * fmax, "{} vs {}", sum(&qx), p.fx);
    assert!((sum(&qs) - p.fs).abs() < 1e-9 * fmax, "{} vs {}", sum(&qs), p.fs);
    let (_, stick) = read("patch0_stick.npy");
    let contact = stick.iter().filter(|&&v| v >= 0.0).count();
    assert_eq!(contact, p.contact_cells);
    let sticking = stick.iter().filter(|&&v| v == 1.0).count() as f64 / contact as f64;
    assert!((sticking - p.stick_fraction.unwrap()).abs() < 1e-12);
    // Outside the contact no pressure and no traction.
    for k in 0..stick.len() {
        if stick[k] < 0.0 {
            assert!(pressure[k] == 0.0 && qx[k] == 0.0 && qs[k] == 0.0, "cell {k}");
        }
    }
    let (_, gap) = read("patch0_gap.npy");
    assert!(gap.iter().copied().fold(f64::INFINITY, f64::min) < 0.0, "the profiles interpenetrate");
    let _ = std::fs::remove_dir_all(&dir);
}
