//! The effect of the profile spline's smoothing length on a solution: the Manchester design
//! profiles (S1002 on UIC60) and the measured MiniProf pair of `data/`, centred and at
//! 3 mm / 7.2 mrad, 10 kN, free rolling at 2 m/s, the exact theory, for smoothing lengths
//! from 0 (the interpolating spline) to 5 mm.
//!
//! ```sh
//! cargo run --release -p stickslip-wheelrail --example smoothing
//! ```

use stickslip_halfspace::Material;
use stickslip_wheelrail::{
    Cache, Format, Motion, Position, Profile, ProfileOptions, Role, Side, Tangential, Track,
    VerticalLoad, WheelRail, Wheelset,
};

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data");

fn problem(rail: &str, wheel: &str, fb_position: f64, smoothing: f64) -> WheelRail {
    let o = ProfileOptions { smoothing, ..ProfileOptions::default() };
    let read = |file: &str, role| {
        let text = std::fs::read_to_string(format!("{DATA}/{file}")).expect("profile");
        Profile::read(&text, file, Format::from_name(file), role, &o).expect("profile reads")
    };
    let track = Track::new(read(rail, Role::Rail), 1.435, 14e-3, 0.0).expect("track");
    let wheelset =
        Wheelset::new(read(wheel, Role::Wheel), 1.360, fb_position, 0.460).expect("wheelset");
    let (g, nu) = (82e9, 0.28);
    let steel = Material::new(2.0 * g * (1.0 + nu), nu).expect("steel");
    WheelRail::new(Side::Left, track, wheelset, steel, steel, 0.3, (2e-4, 2e-4)).expect("problem")
}

fn main() {
    println!(
        "{:>22} {:>6} {:>6} | {:>9} {:>8} {:>9} {:>9} {:>8} {:>8} {:>8}",
        "pair",
        "y mm",
        "Lc mm",
        "y_cp mm",
        "delta",
        "z_ws um",
        "pmax MPa",
        "area mm2",
        "Fx N",
        "Fs N"
    );
    for (name, rail, wheel, fb) in [
        ("S1002/UIC60 (design)", "MBench_UIC60_v3.prr", "MBench_S1002_v3.prw", -70e-3),
        ("MiniProf (measured)", "miniprof_rail_avg_HR.ban", "miniprof_wheel_avg.whl", 0.0),
    ] {
        for (lateral, yaw) in [(0.0, 0.0), (3e-3, 7.2e-3)] {
            for lc in [0.0, 0.5e-3, 1e-3, 2e-3, 5e-3] {
                let pb = problem(rail, wheel, fb, lc);
                let s = pb
                    .solve(
                        &Position { lateral, yaw, roll: 0.0 },
                        &Motion::free_rolling(2.0, 0.46),
                        VerticalLoad::Force(1e4),
                        Tangential::Exact { tolerance: 1e-6 },
                        &mut Cache::new(),
                    )
                    .expect("solves");
                for p in &s.patches {
                    println!(
                        "{:>22} {:>6.1} {:>6.1} | {:>9.3} {:>8.4} {:>9.3} {:>9.1} {:>8.2} {:>8.1} {:>8.1}",
                        name,
                        lateral * 1e3,
                        lc * 1e3,
                        p.reference[1] * 1e3,
                        p.contact_angle,
                        s.z_wheelset * 1e6,
                        p.pmax * 1e-6,
                        p.area * 1e6,
                        p.fx,
                        p.fs
                    );
                }
            }
        }
    }
}
