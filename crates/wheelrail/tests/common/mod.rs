//! Shared set-ups of the tests: the analytic cone-on-crown pair and the Manchester profiles.
#![allow(dead_code)]

use stickslip_halfspace::Material;
use stickslip_wheelrail::{
    Format, Profile, ProfileOptions, Role, Side, Track, WheelRail, Wheelset,
};

pub const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data");

/// Steel of the Manchester benchmark: G = 82 GPa, nu = 0.28.
pub fn steel() -> Material {
    let (g, nu) = (82e9, 0.28);
    Material::new(2.0 * g * (1.0 + nu), nu).unwrap()
}

/// The analytic pair: a rail head crowned with radius `r_rail` (|y| <= 30 mm), a wheel that
/// is a cone of conicity `gamma` (z_w = -gamma y, -40 mm <= y <= 60 mm), gauge measured 1 mm
/// below the top, and the wheel's profile origin straight above the rail's crown (flange
/// back position chosen so) on a radius of 0.46 m.
pub struct Cone {
    pub r_rail: f64,
    pub gamma: f64,
    pub r0: f64,
    pub gauge: f64,
    pub gauge_height: f64,
}

impl Cone {
    pub fn new(r_rail: f64, gamma: f64) -> Self {
        Self { r_rail, gamma, r0: 0.46, gauge: 1.435, gauge_height: 1e-3 }
    }

    /// Track y of the crown's top: the gauge point lies at depth h on the circle,
    /// y_r = -sqrt(2 R h - h^2), and is placed at G/2.
    pub fn crown_y(&self) -> f64 {
        let h = self.gauge_height;
        0.5 * self.gauge + (2.0 * self.r_rail * h - h * h).sqrt()
    }

    /// The rail point where the crown's slope equals the cone's, -gamma (first touch of the
    /// centred wheelset), in the rail's own y.
    pub fn touch_y(&self) -> f64 {
        -self.gamma * self.r_rail / (1.0 + self.gamma * self.gamma).sqrt()
    }

    /// Rolling radius at first touch: r0 - gamma y_w with y_w the touch point in the wheel's
    /// own y (equal to the rail's, the origins being above each other).
    pub fn rolling_radius(&self) -> f64 {
        self.r0 - self.gamma * self.touch_y()
    }

    pub fn problem(&self, side: Side, cell: f64) -> WheelRail {
        let o = ProfileOptions::default();
        let r = self.r_rail;
        let rail: Vec<(f64, f64)> = (-300..=300)
            .map(|i| {
                let y = f64::from(i) * 1e-4;
                (y, r - (r * r - y * y).sqrt())
            })
            .collect();
        let wheel: Vec<(f64, f64)> =
            (-40..=60).map(|i| (f64::from(i) * 1e-3, -self.gamma * f64::from(i) * 1e-3)).collect();
        let rail = Profile::from_points("crown", Role::Rail, &rail, &o).unwrap();
        let wheel = Profile::from_points("cone", Role::Wheel, &wheel, &o).unwrap();
        let track = Track::new(rail, self.gauge, self.gauge_height, 0.0).unwrap();
        let fb_distance = 1.36;
        let wheelset =
            Wheelset::new(wheel, fb_distance, 0.5 * fb_distance - self.crown_y(), self.r0).unwrap();
        WheelRail::new(side, track, wheelset, steel(), steel(), 0.3, (cell, cell)).unwrap()
    }
}

pub fn read_profile(file: &str, role: Role) -> Profile {
    let text = std::fs::read_to_string(format!("{DATA}/{file}")).unwrap();
    Profile::read(&text, file, Format::from_name(file), role, &ProfileOptions::default()).unwrap()
}

/// The Manchester benchmark's wheelset on its track (data README).
pub fn manchester(side: Side) -> WheelRail {
    let rail = read_profile("MBench_UIC60_v3.prr", Role::Rail);
    let wheel = read_profile("MBench_S1002_v3.prw", Role::Wheel);
    let track = Track::new(rail, 1.435, 14e-3, 0.0).unwrap();
    let wheelset = Wheelset::new(wheel, 1.360, -70e-3, 0.460).unwrap();
    WheelRail::new(side, track, wheelset, steel(), steel(), 0.3, (2e-4, 2e-4)).unwrap()
}

/// One Manchester position: (lateral m, yaw rad, roll rad, load N, speed m/s, pitch
/// rate rad/s), `case` 1..=21.
pub fn a22_case(side: &str, case: usize) -> (f64, f64, f64, f64, f64, f64) {
    let text = std::fs::read_to_string(format!("{DATA}/manchester_a22_cases.csv")).unwrap();
    let line = text.lines().skip(1).find(|l| l.starts_with(&format!("{side},{case},"))).unwrap();
    let v: Vec<f64> = line.split(',').skip(2).map(|x| x.parse().unwrap()).collect();
    (v[0] * 1e-3, v[1] * 1e-3, v[2] * 1e-3, v[3], v[4] * 1e-3, v[5])
}

/// CONTACT's reference rows for a side: per row (case, patch, column -> value).
pub fn contact_reference(side: &str) -> Vec<std::collections::HashMap<String, f64>> {
    let text = std::fs::read_to_string(format!("{DATA}/contact_a22_{side}_reference.csv")).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    lines
        .map(|l| {
            header
                .iter()
                .cloned()
                .zip(l.split(',').map(|v| v.trim().parse::<f64>().unwrap()))
                .collect()
        })
        .collect()
}
