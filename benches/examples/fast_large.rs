//! The fast solver at grids too large for CI (issue 20), run once by hand:
//!
//! ```sh
//! cargo run --release -p stickslip-benches --example fast_large -- sweep 512 1024
//! cargo run --release -p stickslip-benches --example fast_large -- cattaneo 256 1e-8 q.f64
//! ```
//!
//! `sweep N...` runs the robustness sweep of `stickslip_benches::fast_sweep` (the cases and
//! checks of `tests/stability_fast.rs`) at N cells across: at 512 every force and moment
//! fraction and one force-and-moment case; at 1024 (slow: tens of seconds a solve) the
//! fractions 0.5 and 0.999 only, unless `--full` is given. One line per case with Newton and
//! CG iterations, residual, solve time and the peak resident memory of the case.
//!
//! `cattaneo N TOL [FILE]` solves the Cattaneo sphere of `scripts/compare_tamaas_slip.py`: a
//! rigid sphere on an elastic half-space with nu = 0.5 (no coupling of normal and tangential
//! tractions, as in tamaas's PolonskyKeerTan), T = 0.5 f P, both traction components free,
//! relative residual TOL, N cells across the contact; prints one JSON line (times of the
//! operator set-up and of the solve apart, iterations, residual, and the errors against
//! Mindlin's closed form) and, with FILE, writes x, y, p, qx, qy of every element as
//! little-endian f64, five arrays one after the other.

use std::f64::consts::PI;
use std::io::Write;
use stickslip_benches::fast_sweep::{combined_case, force_case, moment_case, Outcome, F, RATIOS};
use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
use stickslip_quad::Tolerance;
use stickslip_traction::closed::Mindlin;
use stickslip_traction::{fast::FastConfig, fast::FastProblem, fast::TractionDirections};
use stickslip_traction::{ElementState, Load};

/// Peak resident memory since the last reset, MiB (Linux; `None` elsewhere).
fn peak_mib() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/self/status").ok()?;
    let kb: f64 =
        s.lines().find_map(|l| l.strip_prefix("VmHWM:"))?.trim().split(' ').next()?.parse().ok()?;
    Some(kb / 1024.0)
}

/// Reset the peak resident memory to the current one (Linux >= 4.0).
fn reset_peak() {
    let _ = std::fs::write("/proc/self/clear_refs", "5");
}

fn sweep(ns: &[usize], full: bool) {
    for &n in ns {
        let ratios: Vec<f64> = if n <= 512 || full { RATIOS.to_vec() } else { vec![0.5, 0.999] };
        let mut cases: Vec<(String, Box<dyn Fn() -> Outcome>)> = Vec::new();
        for &r in &ratios {
            cases.push((
                format!("force n={n} T/fP={r} parallel"),
                Box::new(move || force_case(n, 0.3, r, TractionDirections::ParallelToForce, true)),
            ));
            cases.push((
                format!("force n={n} T/fP={r} free nu=0.3"),
                Box::new(move || force_case(n, 0.3, r, TractionDirections::Free, false)),
            ));
            cases.push((format!("moment n={n} M/Mf={r}"), Box::new(move || moment_case(n, r))));
        }
        cases.push((
            format!("combined n={n} mix=0.5 at 0.999"),
            Box::new(move || combined_case(n, 0.5, 0.999)),
        ));
        for (id, case) in cases {
            reset_peak();
            let t0 = std::time::Instant::now();
            let out = case();
            let wall = t0.elapsed().as_secs_f64();
            let mem = peak_mib().map_or("?".to_string(), |m| format!("{m:.0} MiB"));
            match out {
                Ok(s) => println!("ok   {id:<34} {s}; case wall {wall:.1} s, peak {mem}"),
                Err(e) => println!("FAIL {id:<34} {e}; case wall {wall:.1} s, peak {mem}"),
            }
            std::io::stdout().flush().ok();
        }
    }
}

fn cattaneo(n: usize, tol: f64, out: Option<&str>) -> Result<(), String> {
    let e = |x: &dyn std::fmt::Display| x.to_string();
    let elastic = Material::new(1.0, 0.5).map_err(|x| e(&x))?;
    // Contact radius and load 1: the solution scales with f p0 and a.
    let a = 1.0;
    let load = 1.0;
    let g = ContactGrid::hertz_circle(a, load, n).map_err(|x| e(&x))?;
    let t = 0.5 * F * g.total_normal_force();
    let config =
        FastConfig::new(Tolerance::relative(tol).map_err(|x| e(&x))?, 100).map_err(|x| e(&x))?;
    let pr = FastProblem::new(&g, [Material::rigid(), elastic], F, Load::polar(t, 0.0).unwrap())
        .map_err(|x| e(&x))?
        .with_config(config);
    reset_peak();
    let s = pr.solve().map_err(|x| e(&x))?;
    let mem = peak_mib().unwrap_or(f64::NAN);
    let mi = Mindlin::new(a, load, F, t).map_err(|x| e(&x))?;
    let h = g.hx;
    let q0 = 3.0 * F * load / (2.0 * PI * a * a);
    let stick = s.state.iter().filter(|x| **x == ElementState::Stick).count();
    let c = (stick as f64 * h * h / PI).sqrt();
    let (mut emax, mut e2) = (0.0f64, 0.0);
    for (k, q) in s.traction.iter().enumerate() {
        let d = (q.0 - mi.traction(g.x[k].hypot(g.y[k]))).hypot(q.1) / q0;
        emax = emax.max(d);
        e2 += d * d;
    }
    println!(
        "{{\"code\": \"stickslip\", \"n\": {n}, \"elements\": {}, \"tol\": {tol:e}, \"setup_s\": {:.4}, \"solve_s\": {:.4}, \"newton\": {}, \"cg\": {}, \"residual\": {:e}, \"stick_radius\": {c:.6}, \"stick_radius_mindlin\": {:.6}, \"stick_err_cells\": {:.4}, \"traction_rms\": {:e}, \"traction_max\": {:e}, \"peak_mib\": {mem:.0}}}",
        g.len(),
        s.info.setup_seconds,
        s.info.solve_seconds,
        s.info.iterations,
        s.info.cg_iterations,
        s.info.residual,
        mi.stick_radius(),
        (c - mi.stick_radius()) / h,
        (e2 / g.len() as f64).sqrt(),
        emax,
    );
    if let Some(path) = out {
        let mut bytes = Vec::with_capacity(5 * 8 * g.len());
        let cols: [Vec<f64>; 5] = [
            g.x.clone(),
            g.y.clone(),
            g.pressure.clone(),
            s.traction.iter().map(|q| q.0).collect(),
            s.traction.iter().map(|q| q.1).collect(),
        ];
        for col in &cols {
            for v in col {
                bytes.extend_from_slice(&v.to_le_bytes());
            }
        }
        std::fs::write(path, bytes).map_err(|x| format!("{path}: {x}"))?;
    }
    Ok(())
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: fast_large sweep N... [--full] | fast_large cattaneo N TOL [FILE]";
    let result = match args.first().map(String::as_str) {
        Some("sweep") => {
            let full = args.iter().any(|a| a == "--full");
            let ns: Result<Vec<usize>, _> =
                args[1..].iter().filter(|a| *a != "--full").map(|a| a.parse()).collect();
            match ns {
                Ok(ns) if !ns.is_empty() => {
                    sweep(&ns, full);
                    Ok(())
                }
                _ => Err(usage.to_string()),
            }
        }
        Some("cattaneo") if args.len() >= 3 => {
            match (args[1].parse::<usize>(), args[2].parse::<f64>()) {
                (Ok(n), Ok(tol)) => cattaneo(n, tol, args.get(3).map(String::as_str)),
                _ => Err(usage.to_string()),
            }
        }
        _ => Err(usage.to_string()),
    };
    if let Err(e) = result {
        eprintln!("fast_large: {e}");
        std::process::exit(2);
    }
}
