//! The shipped Manchester sweep (`scenes/wheel_rail_manchester_a22.toml` with the
//! points table `scenes/wheel_rail_manchester_a22_left.csv`, zipped): every fifth position
//! (positions 1, 6, 11, 16, 21; the whole sweep is in docs/sweeps.md) against
//!
//! - the library's own solve of the same position (`stickslip-wheelrail`, called directly
//!   with the benchmark's numbers from its case list, not from the sweep's table): the scene,
//!   the points table and the zipping must hand the solver the same problem;
//! - CONTACT's published output for the benchmark (`contact_a22_left_reference.csv`), to the
//!   tolerances of the wheel-rail crate's `tests/manchester.rs`.

use std::collections::HashMap;
use std::path::PathBuf;

use stickslip_halfspace::Material;
use stickslip_sweep::{read_points, Cell, Mode, Shard, Sweep, Table};
use stickslip_wheelrail::{
    Cache, Format, Motion, Position, Profile, ProfileOptions, Role, Side, Tangential, Track,
    VerticalLoad, WheelRail, Wheelset,
};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn data(file: &str) -> String {
    std::fs::read_to_string(root().join("crates/wheelrail/data").join(file)).unwrap()
}

/// The shipped sweep, as `stickslip sweep SCENE --points FILE` builds it.
fn shipped() -> Sweep {
    let scene = root().join("scenes/wheel_rail_manchester_a22.toml");
    let points = root().join("scenes/wheel_rail_manchester_a22_left.csv");
    let vary = read_points(
        &std::fs::read_to_string(&points).unwrap(),
        "wheel_rail_manchester_a22_left.csv",
    )
    .unwrap();
    let sweep =
        Sweep::zipped(&std::fs::read_to_string(&scene).unwrap(), Some(scene), &vary).unwrap();
    assert_eq!(sweep.mode(), Mode::Zip);
    sweep
}

fn get(t: &Table, row: usize, name: &str) -> f64 {
    let j = t.column(name).unwrap_or_else(|| panic!("no column {name}"));
    match &t.rows[row][j] {
        Cell::Float(Some(x)) => *x,
        Cell::Int(i) => *i as f64,
        c => panic!("{name}: {c:?}"),
    }
}

/// The library's problem, built from the benchmark's numbers (data README).
fn library() -> WheelRail {
    let o = ProfileOptions::default();
    let read = |file: &str, role| {
        Profile::read(&data(file), file, Format::from_name(file), role, &o).unwrap()
    };
    let rail = read("MBench_UIC60_v3.prr", Role::Rail);
    let wheel = read("MBench_S1002_v3.prw", Role::Wheel);
    let track = Track::new(rail, 1.435, 14e-3, 0.0).unwrap();
    let wheelset = Wheelset::new(wheel, 1.360, -70e-3, 0.460).unwrap();
    let (g, nu) = (82e9, 0.28);
    let steel = Material::new(2.0 * g * (1.0 + nu), nu).unwrap();
    WheelRail::new(Side::Left, track, wheelset, steel, steel, 0.3, (2e-4, 2e-4)).unwrap()
}

/// Position `case` of the left wheel from the case list: (lateral, yaw, roll, load, speed,
/// pitch rate), SI.
fn case(case: usize) -> [f64; 6] {
    let text = data("manchester_a22_cases.csv");
    let line = text.lines().find(|l| l.starts_with(&format!("left,{case},"))).unwrap();
    let v: Vec<f64> = line.split(',').skip(2).map(|x| x.parse().unwrap()).collect();
    [v[0] * 1e-3, v[1] * 1e-3, v[2] * 1e-3, v[3], v[4] * 1e-3, v[5]]
}

/// CONTACT's rows for the left wheel: column -> value.
fn contact() -> Vec<HashMap<String, f64>> {
    let text = data("contact_a22_left_reference.csv");
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    lines
        .map(|l| {
            header.iter().cloned().zip(l.split(',').map(|v| v.trim().parse().unwrap())).collect()
        })
        .collect()
}

#[test]
fn the_shipped_a22_sweep_is_the_library_solve_and_agrees_with_contact() {
    let sweep = shipped();
    assert_eq!(sweep.len(), 21);
    let shard = Shard { index: 1, count: 5 };
    let table = sweep.run(shard, 600.0, |_| {});
    let points: Vec<usize> = shard.points(21).collect();
    assert_eq!(points, [0, 5, 10, 15, 20]);
    let pb = library();
    let reference = contact();
    for (row, &i) in points.iter().enumerate() {
        let n = i + 1; // the benchmark numbers its positions from 1
        let status = table.column("status").unwrap();
        assert_eq!(table.rows[row][status], Cell::Text(Some("ok".into())), "position {n}");
        let [y, psi, phi, fz, v, wp] = case(n);
        // The table's lateral shift is the case list's.
        let j = table.column("position.lateral").unwrap();
        let Cell::Text(Some(lateral)) = &table.rows[row][j] else {
            panic!("{:?}", table.rows[row][j])
        };
        let mm: f64 = lateral.strip_suffix(" mm").unwrap().parse().unwrap();
        assert!((mm * 1e-3 - y).abs() < 1e-15, "position {n}: {lateral}");
        // The library, on its own, from the case list; a fresh cache, as each sweep point
        // starts afresh.
        let s = pb
            .solve(
                &Position { lateral: y, yaw: psi, roll: phi },
                &Motion::rolling(v, wp),
                VerticalLoad::Force(fz),
                Tangential::Exact { tolerance: 1e-6 },
                &mut Cache::new(),
            )
            .unwrap();
        assert_eq!(get(&table, row, "patches") as usize, s.patches.len(), "position {n}");
        assert_eq!(s.patches.len(), 1, "position {n}: the left wheel has one tread patch");
        let p = &s.patches[0];
        let fmax = 0.3 * p.normal_force;
        let same = |name: &str, lib: f64, scale: f64| {
            let got = get(&table, row, name);
            assert!(
                (got - lib).abs() <= 1e-9 * scale,
                "position {n}: {name} {got} from the sweep, {lib} from the library"
            );
        };
        same("z_wheelset", s.z_wheelset, 1e-3);
        same("fx_rail", s.total_on_rail[0], fmax);
        same("fy_rail", s.total_on_rail[1], fmax);
        same("fz_rail", s.total_on_rail[2], fz);
        same("patch0_fn", p.normal_force, p.normal_force);
        same("patch0_fx", p.fx, fmax);
        same("patch0_fs", p.fs, fmax);
        same("patch0_y_rail", p.rail_point[0], 1e-3);
        same("patch0_contact_angle", p.contact_angle, 1.0);
        same(
            "patch0_creepage_longitudinal",
            p.creepage.longitudinal,
            p.creepage.longitudinal.abs().max(1e-6),
        );
        same("patch0_creepage_lateral", p.creepage.lateral, p.creepage.lateral.abs().max(1e-6));
        same("patch0_creepage_spin", p.creepage.spin, p.creepage.spin.abs());
        same("patch0_pmax", p.pmax, p.pmax);
        // No second patch on the left wheel: its columns are empty.
        let j = table.column("patch1_fn").unwrap();
        assert_eq!(table.rows[row][j], Cell::Float(None), "position {n}");

        // CONTACT (tests/manchester.rs of the wheel-rail crate: wheelset height 2 um, normal
        // force 0.5 %, creep forces 1.5 % of f Fn, reference point 0.5 mm, contact angle
        // 5 mrad). CONTACT counts the creep forces' vertical components in the load; the
        // scene's `load.normal` does not (docs/SCENES.md), which moves Fn by well under
        // 0.5 % on the tread.
        let r = reference.iter().find(|r| r["case"] == n as f64).unwrap();
        let fmax = 0.3 * r["fn_N"];
        let near = |name: &str, want: f64, tol: f64| {
            let got = get(&table, row, name);
            assert!((got - want).abs() < tol, "position {n}: {name} {got} vs CONTACT {want}");
        };
        near("z_wheelset", r["z_ws_mm"] * 1e-3, 2e-6);
        near("patch0_fn", r["fn_N"], 5e-3 * r["fn_N"]);
        near("patch0_fx", r["fx_N"], 1.5e-2 * fmax);
        near("patch0_fs", r["fs_N"], 1.5e-2 * fmax);
        near("patch0_y_rail", r["ycp_r_mm"] * 1e-3, 0.5e-3);
        near("patch0_contact_angle", r["deltcp_rad"], 5e-3);
    }
}

#[test]
fn zipped_lists_of_unequal_length_are_refused_with_the_key() {
    let scene =
        std::fs::read_to_string(root().join("scenes/wheel_rail_manchester_a22.toml")).unwrap();
    let vary = [
        stickslip_sweep::Vary::parse("position.lateral=0 mm:10 mm:21").unwrap(),
        stickslip_sweep::Vary::parse("position.yaw=0 mrad:24 mrad:20").unwrap(),
    ];
    let e = Sweep::zipped(&scene, None, &vary).unwrap_err();
    assert_eq!(e.key.as_deref(), Some("position.yaw"));
    let text = e.to_string();
    assert!(text.contains("20 values") && text.contains("has 21"), "{text}");
    // The same lists make a cartesian sweep of 420 points.
    assert_eq!(Sweep::new(&scene, None, &vary).unwrap().len(), 420);
}
