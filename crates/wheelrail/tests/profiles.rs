//! Profile files: the formats read as their documentation says, and bad input is refused
//! before any solving, naming the file, the line and what to do.

mod common;

use common::{read_profile, DATA};
use stickslip_wheelrail::{
    Cache, Error, Format, Motion, Position, Profile, ProfileOptions, Role, Side, Tangential, Track,
    VerticalLoad, WheelRail, Wheelset,
};

fn text(file: &str) -> String {
    std::fs::read_to_string(format!("{DATA}/{file}")).unwrap()
}

fn extremes(p: &Profile) -> ((f64, f64), (f64, f64)) {
    let (y, z) = p.points();
    let kmin = (0..z.len()).min_by(|&a, &b| z[a].total_cmp(&z[b])).unwrap();
    let kmax = (0..z.len()).max_by(|&a, &b| z[a].total_cmp(&z[b])).unwrap();
    ((y[kmin], z[kmin]), (y[kmax], z[kmax]))
}

#[test]
fn simpack_profiles_read_in_the_canonical_orientation() {
    let rail = read_profile("MBench_UIC60_v3.prr", Role::Rail);
    let wheel = read_profile("MBench_S1002_v3.prw", Role::Wheel);
    // The rail: 495 points in the file, a few closer than 1 um dropped; the top near y = 0,
    // the gauge face at y = -43.7 mm reaching 38.5 mm deep.
    let (y, z) = rail.points();
    assert!(y.len() > 480 && y.len() <= 495, "{}", y.len());
    assert!((y[0] + 43.7049e-3).abs() < 1e-6 && (z[0] - 38.5107e-3).abs() < 1e-6);
    let ((yt, zt), _) = extremes(&rail);
    assert!(yt.abs() < 1e-3 && zt.abs() < 1e-6, "top ({yt}, {zt})");
    // The wheel: mirror.y = 1 in the file puts the flange (28 mm below the tread, at 55 mm
    // from the origin) on the track-centre side, y < 0; the first point is a comment.
    let (y, _) = wheel.points();
    assert_eq!(y.len(), 399);
    assert!((y[0] + 69.612628e-3).abs() < 1e-9, "{}", y[0]);
    let (_, (yf, zf)) = extremes(&wheel);
    assert!((yf + 54.9e-3).abs() < 0.3e-3 && (zf - 28.0e-3).abs() < 0.05e-3, "flange ({yf}, {zf})");
    assert_eq!(wheel.lines()[0], 44, "first point on line 44 (line 43 is commented out)");
}

#[test]
fn miniprof_profiles_read_in_the_canonical_orientation() {
    let rail = read_profile("miniprof_rail_avg_HR.ban", Role::Rail);
    let wheel = read_profile("miniprof_wheel_avg.whl", Role::Wheel);
    // Rail: X, Y in the file; canonical (y, z) = (-X, -Y): the gauge face (X = 46.6 mm,
    // Y = -25.4 mm) at y = -46.6 mm, 25.4 mm deep.
    let (y, z) = rail.points();
    assert!(
        (y[0] + 46.59e-3).abs() < 1e-9 && (z[0] - 25.42e-3).abs() < 1e-9,
        "({}, {})",
        y[0],
        z[0]
    );
    let ((_, zt), _) = extremes(&rail);
    assert!((zt - 0.21e-3).abs() < 0.02e-3, "top {zt}");
    // Wheel: (y, z) = (X, Y): flange at X = 15.5 mm, 28 mm below the tread, the field face
    // at X = 139.7 mm rising to -31.8 mm.
    let (y, z) = wheel.points();
    assert!((y[0] - 1.55e-3).abs() < 1e-9 && (z[0] - 15.34e-3).abs() < 1e-9);
    let (_, (yf, zf)) = extremes(&wheel);
    assert!((yf - 15.5e-3).abs() < 0.3e-3 && (zf - 28.0e-3).abs() < 0.1e-3, "flange ({yf}, {zf})");
    // The measured pair in contact: 10 kN carried, contact on the tread.
    let track = Track::new(rail, 1.435, 14e-3, 0.0).unwrap();
    let wheelset = Wheelset::new(wheel, 1.360, 0.0, 0.46).unwrap();
    let steel = common::steel();
    let pb = WheelRail::new(Side::Right, track, wheelset, steel, steel, 0.3, (2e-4, 2e-4)).unwrap();
    let s = pb
        .solve(
            &Position::default(),
            &Motion::free_rolling(2.0, 0.46),
            VerticalLoad::Force(1e4),
            Tangential::Fastsim,
            &mut Cache::new(),
        )
        .unwrap();
    let fz: f64 = s.patches.iter().map(|p| p.normal_force * p.contact_angle.cos()).sum();
    assert!((fz - 1e4).abs() < 1e-6 * 1e4);
    assert!(s.patches.iter().all(|p| p.contact_angle.abs() < 0.2), "tread contact");
}

fn refusal(r: Result<Profile, Error>) -> (Option<usize>, String) {
    match r {
        Err(Error::ProfileCheck { line, problem, hint, .. }) => {
            (line, format!("{problem} ({hint})"))
        }
        Err(Error::ProfileFormat { line, message, .. }) => (line, message),
        Err(e) => panic!("unexpected error {e}"),
        Ok(_) => panic!("accepted"),
    }
}

fn rail_table() -> String {
    // The Manchester rail as plain text in mm.
    let rail = read_profile("MBench_UIC60_v3.prr", Role::Rail);
    let (y, z) = rail.points();
    y.iter().zip(z).map(|(y, z)| format!("{} {}\n", y * 1e3, z * 1e3)).collect()
}

#[test]
fn bad_profiles_are_refused_with_the_line() {
    let o = ProfileOptions::default();
    let rd = |t: &str, role| Profile::read(t, "p.txt", Format::Table, role, &o);
    // NaN on line 5.
    let mut lines: Vec<String> = rail_table().lines().map(String::from).collect();
    lines[4] = "-40.0 nan".to_string();
    let (line, msg) = refusal(rd(&lines.join("\n"), Role::Rail));
    assert_eq!(line, Some(5), "{msg}");
    assert!(msg.contains("finite"), "{msg}");
    // Too few points.
    let (_, msg) = refusal(rd("0 1\n1 0\n2 1\n", Role::Rail));
    assert!(msg.contains("at least 10"), "{msg}");
    // A word among the numbers.
    let (line, _) = refusal(rd("y z\n0 1\n1 0\nx 1\n", Role::Rail));
    assert_eq!(line, Some(4));
    // The rail in the wrong unit: millimetre numbers read as metres make a rail 38 m deep.
    let metres = ProfileOptions { unit: 1.0, ..o };
    let (_, msg) =
        refusal(Profile::read(&rail_table(), "rail.txt", Format::Table, Role::Rail, &metres));
    assert!(msg.contains("profile_unit") && msg.contains("long"), "{msg}");
    // ... and a SIMPACK file that states its unit.
    let (_, msg) = refusal(Profile::read(
        &text("MBench_UIC60_v3.prr"),
        "MBench_UIC60_v3.prr",
        Format::Simpack,
        Role::Rail,
        &metres,
    ));
    assert!(msg.contains("units.len.f") && msg.contains("profile_unit"), "{msg}");
    // A wheel profile given as the rail: by its SIMPACK type, its extension, its shape.
    let (_, msg) = refusal(Profile::read(
        &text("MBench_S1002_v3.prw"),
        "MBench_S1002_v3.prw",
        Format::Simpack,
        Role::Rail,
        &o,
    ));
    assert!(msg.contains("wheel profile") && msg.contains("given as the rail"), "{msg}");
    let (_, msg) = refusal(Profile::read(
        &text("miniprof_wheel_avg.whl"),
        "w.whl",
        Format::MiniProf,
        Role::Rail,
        &o,
    ));
    assert!(msg.contains("extension"), "{msg}");
    let wheel = read_profile("MBench_S1002_v3.prw", Role::Wheel);
    let (wy, wz) = wheel.points();
    let wheel_text: String =
        wy.iter().zip(wz).map(|(y, z)| format!("{} {}\n", y * 1e3, z * 1e3)).collect();
    let (_, msg) = refusal(rd(&wheel_text, Role::Rail));
    assert!(msg.contains("does not look like a rail head"), "{msg}");
    // ... and a rail given as the wheel.
    let (_, msg) = refusal(rd(&rail_table(), Role::Wheel));
    assert!(msg.contains("does not look like a wheel"), "{msg}");
    // A loop: the points cross back over earlier ones.
    let looped = "-30 5\n-20 1\n-10 0.2\n0 0\n10 0.2\n20 1\n0 0.5\n-5 -1\n25 2\n30 5\n35 8\n";
    let (line, msg) = refusal(rd(looped, Role::Rail));
    assert!(msg.contains("crosses itself") && line.is_some(), "{msg}");
    // A back-step on the crown (not a near-vertical face).
    let back = "-30 5\n-20 1\n-10 0.2\n0 0\n10 0.2\n9.5 0.25\n20 1\n25 2\n30 5\n35 8\n";
    let (line, msg) = refusal(rd(back, Role::Rail));
    assert_eq!(line, Some(6), "{msg}");
    assert!(msg.contains("steps back"), "{msg}");
    // A SIMPACK rotation is refused (its sense is not in the file).
    let rotated = text("MBench_UIC60_v3.prr")
        .replace("rotate         = +0.000000000000000e+00", "rotate = 0.025");
    let (line, msg) = refusal(Profile::read(&rotated, "r.prr", Format::Simpack, Role::Rail, &o));
    assert!(msg.contains("rotate") && line.is_some(), "{msg}");
}

#[test]
fn a_leaning_gauge_face_is_accepted() {
    // The gauge face leans back by 0.3 mm over its lowest 10 mm: accepted.
    let o = ProfileOptions::default();
    let t = "-30.3 25\n-30.1 20\n-30 15\n-29 8\n-25 3\n-20 1\n-10 0.2\n0 0\n10 0.2\n20 1\n25 3\n29 8\n30 15\n";
    let p = Profile::read(t, "lean.txt", Format::Table, Role::Rail, &o);
    assert!(p.is_ok(), "{:?}", p.err());
}

#[test]
fn impossible_placements_are_refused() {
    let o = ProfileOptions::default();
    // A rail head cut 5 mm below its top has no gauge face 14 mm down.
    let rail = read_profile("MBench_UIC60_v3.prr", Role::Rail);
    let (y, z) = rail.points();
    let cut: Vec<(f64, f64)> =
        y.iter().zip(z).filter(|(_, z)| **z < 5e-3).map(|(y, z)| (*y, *z)).collect();
    let short = Profile::from_points("short", Role::Rail, &cut, &o).unwrap();
    match Track::new(short, 1.435, 14e-3, 0.0).and_then(|t| {
        let w = Wheelset::new(read_profile("MBench_S1002_v3.prw", Role::Wheel), 1.36, -0.07, 0.46)?;
        WheelRail::new(Side::Right, t, w, common::steel(), common::steel(), 0.3, (2e-4, 2e-4))
    }) {
        Err(Error::Placement { what, hint }) => {
            assert!(what.contains("gauge face") && hint.contains("gauge_height"), "{what} {hint}")
        }
        other => panic!("expected a placement refusal, got {other:?}"),
    }
}

#[test]
fn profiles_that_never_meet_are_refused() {
    let motion = Motion::free_rolling(2.0, 0.46);
    let steel = common::steel();
    let wheel = read_profile("MBench_S1002_v3.prw", Role::Wheel);
    let rail = read_profile("MBench_UIC60_v3.prr", Role::Rail);
    // Flange backs 2 m apart: the wheel misses the rail sideways.
    let track = Track::new(rail.clone(), 1.435, 14e-3, 0.0).unwrap();
    let ws = Wheelset::new(wheel.clone(), 2.0, -0.07, 0.46).unwrap();
    let pb =
        WheelRail::new(Side::Right, track.clone(), ws, steel, steel, 0.3, (2e-4, 2e-4)).unwrap();
    match pb.solve(
        &Position::default(),
        &motion,
        VerticalLoad::Force(1e4),
        Tangential::None,
        &mut Cache::new(),
    ) {
        Err(e @ Error::NoContact { overlap: false, .. }) => {
            // No gap is measured, so none is printed (it was "inf m").
            let m = e.to_string();
            assert!(m.contains("do not even overlap") && !m.contains("inf"), "{m}");
        }
        other => panic!("expected no lateral overlap, got {other:?}"),
    }
    // The wheel profile 30 mm above its origin: it hovers over the rail.
    let (y, z) = wheel.points();
    let up: Vec<(f64, f64)> = y.iter().zip(z).map(|(y, z)| (*y, z - 0.03)).collect();
    let high = Profile::from_points("high", Role::Wheel, &up, &ProfileOptions::default()).unwrap();
    let ws = Wheelset::new(high, 1.36, -0.07, 0.46).unwrap();
    let pb = WheelRail::new(Side::Right, track, ws, steel, steel, 0.3, (2e-4, 2e-4)).unwrap();
    match pb.solve(
        &Position::default(),
        &motion,
        VerticalLoad::Force(1e4),
        Tangential::None,
        &mut Cache::new(),
    ) {
        Err(e @ Error::NoContact { min_gap, y, overlap: true }) => {
            assert!((min_gap - 0.03).abs() < 1e-3, "{e}");
            assert!(y > 0.7 && y < 0.8, "{e}");
        }
        other => panic!("expected a gap of 30 mm, got {other:?}"),
    }
}

#[test]
fn a_lateral_shift_past_flange_climb_is_refused() {
    let pb = common::manchester(Side::Right);
    let motion = Motion::free_rolling(2.0, 0.46);
    for lateral in [0.02, 0.035] {
        match pb.solve(
            &Position { lateral, yaw: 0.0, roll: 0.0 },
            &motion,
            VerticalLoad::Force(1e4),
            Tangential::None,
            &mut Cache::new(),
        ) {
            Err(e @ Error::FlangeClimb { .. }) => eprintln!("{lateral}: {e}"),
            other => panic!(
                "lateral {lateral}: expected flange climb, got {:?}",
                other.map(|s| s
                    .patches
                    .iter()
                    .map(|p| (p.wheel_point, p.contact_angle))
                    .collect::<Vec<_>>())
            ),
        }
    }
}

#[test]
fn bad_numbers_are_refused() {
    let pb = common::manchester(Side::Left);
    let m = Motion::free_rolling(2.0, 0.46);
    let solve = |pos: Position, m: Motion, l: VerticalLoad| {
        pb.solve(&pos, &m, l, Tangential::Fastsim, &mut Cache::new())
    };
    for (pos, motion, load, name) in [
        (
            Position { lateral: f64::NAN, ..Default::default() },
            m,
            VerticalLoad::Force(1e4),
            "position.lateral",
        ),
        (Position { yaw: 0.5, ..Default::default() }, m, VerticalLoad::Force(1e4), "position.yaw"),
        (
            Position::default(),
            Motion { speed: -1.0, ..m },
            VerticalLoad::Force(1e4),
            "motion.speed",
        ),
        (Position::default(), m, VerticalLoad::Force(-1.0), "load.normal"),
        (Position::default(), m, VerticalLoad::Approach(0.0), "load.approach"),
    ] {
        match solve(pos, motion, load) {
            Err(Error::OutOfDomain { name: n, .. }) => assert_eq!(n, name),
            other => panic!("{name}: {other:?}"),
        }
    }
}
