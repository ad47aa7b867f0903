//! The Manchester contact benchmark, case A-2.2: the 21 positions of the left wheel (S1002
//! on UIC60, 10 kN, 2 m/s, friction 0.3, 0.2 mm cells), solved with the exact steady-rolling
//! theory and with FASTSIM, each position a whole solve (placement, contact search, normal
//! contact under the vertical load, creepages, tangential contact), with per-position
//! results, wall times, and CONTACT's published output beside them.
//!
//! ```sh
//! cargo run --release -p stickslip-wheelrail --example manchester -- \
//!     [left|right] [--exact|--fastsim] [--normal] [--forget] [--repeat N] [--smoothing MM]
//! ```
//!
//! `--normal` presses the wheel with the issue's load definition (the normal forces'
//! vertical components carry it) instead of CONTACT's (the total vertical force);
//! `--forget` makes each position start from its own estimates, as the points of a sweep do
//! (by default the [`Cache`] hands each position's frames, height and pressure to the next);
//! `--smoothing` sets the profiles' smoothing length in millimetres (default 0: the
//! interpolating spline).
//!
//! ```text
//! ```
//!
//! The profiles are the project's copy in `crates/wheelrail/data/` (see its README for the
//! attribution). Planned operators are kept from one position to the next ([`Cache`]).

use std::time::Instant;
use stickslip_halfspace::Material;
use stickslip_wheelrail::{
    Cache, Format, Motion, Position, Profile, ProfileOptions, Role, Side, Solution, Tangential,
    Track, VerticalLoad, WheelRail, Wheelset,
};

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data");

struct Case {
    lateral: f64,
    yaw: f64,
    roll: f64,
    load: f64,
    speed: f64,
    pitch_rate: f64,
}

fn cases(side: &str) -> Vec<Case> {
    let text = std::fs::read_to_string(format!("{DATA}/manchester_a22_cases.csv")).expect("cases");
    text.lines()
        .skip(1)
        .filter(|l| l.starts_with(side))
        .map(|l| {
            let v: Vec<f64> = l.split(',').skip(2).map(|x| x.parse().expect("number")).collect();
            Case {
                lateral: v[0] * 1e-3,
                yaw: v[1] * 1e-3,
                roll: v[2] * 1e-3,
                load: v[3],
                speed: v[4] * 1e-3,
                pitch_rate: v[5],
            }
        })
        .collect()
}

/// CONTACT's reference output per case (its first patch): (fn, fx, fs, y_cp_tr, pmax,
/// z_ws, delta, patches).
fn contact_reference(side: &str) -> Vec<[f64; 8]> {
    let text = std::fs::read_to_string(format!("{DATA}/contact_a22_{side}_reference.csv"))
        .expect("reference");
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = lines.next().expect("header").split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).expect("column");
    let (cfn, cfx, cfs, cy, cp) =
        (col("fn_N"), col("fx_N"), col("fs_N"), col("ycp_tr_mm"), col("pmax_MPa"));
    let (cz, cd, cn) = (col("z_ws_mm"), col("deltcp_rad"), col("patches"));
    lines
        .filter(|l| l.split(',').nth(1) == Some("1"))
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.trim().parse().unwrap_or(f64::NAN)).collect();
            [v[cfn], v[cfx], v[cfs], v[cy], v[cp], v[cz], v[cd], v[cn]]
        })
        .collect()
}

fn problem(side: Side, smoothing: f64) -> WheelRail {
    let o = ProfileOptions { smoothing, ..ProfileOptions::default() };
    let read = |file: &str, role| {
        let text = std::fs::read_to_string(format!("{DATA}/{file}")).expect("profile");
        Profile::read(&text, file, Format::from_name(file), role, &o).expect("profile reads")
    };
    let rail = read("MBench_UIC60_v3.prr", Role::Rail);
    let wheel = read("MBench_S1002_v3.prw", Role::Wheel);
    let track = Track::new(rail, 1.435, 14e-3, 0.0).expect("track");
    let wheelset = Wheelset::new(wheel, 1.360, -70e-3, 0.460).expect("wheelset");
    let g = 82e9;
    let nu = 0.28;
    let steel = Material::new(2.0 * g * (1.0 + nu), nu).expect("steel");
    WheelRail::new(side, track, wheelset, steel, steel, 0.3, (2e-4, 2e-4)).expect("problem")
}

fn run(
    pb: &WheelRail,
    cases: &[Case],
    method: Tangential,
    load: fn(f64) -> VerticalLoad,
    cache: &mut Cache,
    forget: bool,
) -> (Vec<Solution>, f64) {
    let t0 = Instant::now();
    let out = cases
        .iter()
        .map(|c| {
            let pos = Position { lateral: c.lateral, yaw: c.yaw, roll: c.roll };
            let motion = Motion::rolling(c.speed, c.pitch_rate);
            if forget {
                cache.forget();
            }
            pb.solve(&pos, &motion, load(c.load), method, cache)
                .unwrap_or_else(|e| panic!("position y = {} mm: {e}", c.lateral * 1e3))
        })
        .collect();
    (out, t0.elapsed().as_secs_f64())
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let side_name = if args.iter().any(|a| a == "right") { "right" } else { "left" };
    let side = if side_name == "right" { Side::Right } else { Side::Left };
    let repeat: usize = args
        .iter()
        .position(|a| a == "--repeat")
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(1);
    // --smoothing L: the profiles' smoothing length in mm (0: the interpolating spline).
    let smoothing: f64 = args
        .iter()
        .position(|a| a == "--smoothing")
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse::<f64>().ok())
        .unwrap_or(0.0)
        * 1e-3;
    // --forget: each position starts from its own estimates (as a sweep's points do).
    let forget = args.iter().any(|a| a == "--forget");
    let pb = problem(side, smoothing);
    let cases = cases(side_name);
    let reference = contact_reference(side_name);
    // CONTACT's force control counts the creep forces' vertical components; `--normal`
    // counts the normal forces only.
    let load: fn(f64) -> VerticalLoad = if args.iter().any(|a| a == "--normal") {
        VerticalLoad::Force
    } else {
        VerticalLoad::TotalForce
    };
    let mut summary = Vec::new();
    let methods: Vec<(&str, Tangential)> =
        [("exact", Tangential::Exact { tolerance: 1e-6 }), ("FASTSIM", Tangential::Fastsim)]
            .into_iter()
            .filter(|(n, _)| {
                !(args.iter().any(|a| a == "--exact") && *n != "exact"
                    || args.iter().any(|a| a == "--fastsim") && *n != "FASTSIM")
            })
            .collect();
    for (name, method) in methods {
        let mut cache = Cache::new();
        let mut best = f64::INFINITY;
        let mut sols = vec![];
        for _ in 0..repeat {
            let (s, t) = run(&pb, &cases, method, load, &mut cache, forget);
            best = best.min(t);
            sols = s;
        }
        println!("\n== {side_name} wheel, {name}: 21 positions in {best:.4} s (best of {repeat}; {:.2} ms per position); operators planned {}, reused {}", 1e3 * best / cases.len() as f64, cache.misses, cache.hits);
        println!(
            "{:>4} {:>6} {:>9} {:>3} {:>9} {:>8} {:>10} {:>10} {:>10} {:>9} {:>9} {:>8} {:>6} {:>6} | {:>8} {:>8} {:>8} {:>9}",
            "case", "y mm", "z_ws mm", "np", "y_cp mm", "delta", "xi", "eta", "phi 1/m", "Fn N", "Fx N", "Fs N", "pmax", "ms",
            "C:Fn", "C:Fx", "C:Fs", "C:y_cp"
        );
        let verbose = std::env::var("WR_VERBOSE").is_ok();
        // Largest differences from CONTACT over the positions where both find one patch:
        // z_ws (mm), Fn (relative), Fx and Fs (of f Fn), y_cp (mm), delta (rad); and where.
        let mut worst = [(0.0f64, 0usize); 6];
        for (k, s) in sols.iter().enumerate() {
            let Some(r) = reference.get(k) else { continue };
            if s.patches.len() != 1 || r[7] != 1.0 {
                continue;
            }
            let p = &s.patches[0];
            let fmax = 0.3 * r[0];
            let d = [
                (s.z_wheelset * 1e3 - r[5]).abs(),
                (p.normal_force / r[0] - 1.0).abs(),
                (p.fx - r[1]).abs() / fmax,
                (p.fs - r[2]).abs() / fmax,
                (p.reference[1] * 1e3 - r[3]).abs(),
                (p.contact_angle - r[6]).abs(),
            ];
            for (w, v) in worst.iter_mut().zip(d) {
                if v > w.0 {
                    *w = (v, k + 1);
                }
            }
        }
        let sum = |f: &dyn Fn(&Solution) -> f64| sols.iter().map(f).sum::<f64>();
        summary.push(format!(
            "{side_name} {name}: last run's wall times summed: geometry {:.1} ms, normal {:.1} ms ({} solves, {} CG iterations), tangential {:.1} ms, all {:.1} ms",
            1e3 * sum(&|s| s.info.geometry_seconds),
            1e3 * sum(&|s| s.info.normal_seconds),
            sum(&|s| s.info.normal_solves as f64),
            sum(&|s| s.info.normal_iterations as f64),
            1e3 * sum(&|s| s.info.tangential_seconds),
            1e3 * sum(&|s| s.info.total_seconds),
        ));
        summary.push(format!("{side_name} {name}: largest differences from CONTACT (single-patch positions): z_ws {:.2e} mm (pos {}), Fn {:.2e} (pos {}), Fx {:.2e} fFn (pos {}), Fs {:.2e} fFn (pos {}), y_cp {:.3} mm (pos {}), delta {:.2e} rad (pos {})",
            worst[0].0, worst[0].1, worst[1].0, worst[1].1, worst[2].0, worst[2].1, worst[3].0, worst[3].1, worst[4].0, worst[4].1, worst[5].0, worst[5].1));
        for (k, (c, s)) in cases.iter().zip(&sols).enumerate() {
            for (ip, p) in s.patches.iter().enumerate() {
                let r = reference.get(k).copied().unwrap_or([f64::NAN; 8]);
                println!(
                    "{:>4} {:>6.2} {:>9.5} {:>3} {:>9.3} {:>8.4} {:>10.3e} {:>10.3e} {:>10.3e} {:>9.1} {:>9.1} {:>8.1} {:>6.1} {:>6.2} | {:>8.0} {:>8.1} {:>8.1} {:>9.3}",
                    if ip == 0 { (k + 1).to_string() } else { String::new() },
                    c.lateral * 1e3,
                    s.z_wheelset * 1e3,
                    s.patches.len(),
                    p.reference[1] * 1e3,
                    p.contact_angle,
                    p.creepage.longitudinal,
                    p.creepage.lateral,
                    p.creepage.spin,
                    p.normal_force,
                    p.fx,
                    p.fs,
                    p.pmax * 1e-6,
                    s.info.total_seconds * 1e3,
                    r[0],
                    r[1],
                    r[2],
                    r[3],
                );
                if verbose {
                    eprintln!(
                        "      wheel point {:?}, rail point {:?}, reference {:?}",
                        p.wheel_point, p.rail_point, p.reference
                    );
                    let i = &s.info;
                    eprintln!("      geo {:.2} ms, normal {:.2} ms ({} solves, {} it, {} products, {} trials, {} layouts, {} moved), tangential {:.2} ms; lattice {}x{}, contact {} cells; rolling {:?}",
                        i.geometry_seconds * 1e3, i.normal_seconds * 1e3, i.normal_solves, i.normal_iterations, i.normal_products, i.load_iterations, i.layouts, i.frames_moved, i.tangential_seconds * 1e3,
                        p.lattice.nx, p.lattice.ns, p.contact_cells, p.rolling.as_ref().map(|r| (r.info.iterations, r.info.products)));
                }
            }
        }
    }
    for line in summary {
        println!("{line}");
    }
}
