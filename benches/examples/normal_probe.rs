//! Probe of the normal-contact solver on issue 30's two problems, one solve per run:
//!
//! ```sh
//! cargo run --release -p stickslip-benches --example normal_probe -- rough 1024
//! cargo run --release -p stickslip-benches --example normal_probe -- hertz 1024
//! ```
//!
//! `rough N`: the periodic band-limited self-affine surface of
//! `stickslip_benches::surfaces` (H = 0.8, 4 to 64 cycles per period, the same continuous
//! surface on every lattice) pressed by a rigid body on steel, about 5 % of the period in
//! contact. `hertz N`: a rigid sphere on steel, free boundary, the Hertz contact radius 0.3
//! of the lattice side. Tolerance 1e-8 unless `tol=`; options `cold` (no nesting),
//! `identity` (no preconditioner), `write=FILE` (the initial gap as little-endian f64, for
//! `scripts/compare_aspher.py`, then exit), `pressure=FILE` (write the pressure after the
//! solve), `hardness=H` (cap the pressure at H Pa, issue 32; the line then also gives the
//! plastic share of the contact and the peak pressure), `approach=D` (approach control at D m
//! instead of the force). Prints one line: the levels with their iterations, the fine iterations and FFT
//! products, the residuals, the contact fraction, the times (set-up, coarse levels, whole
//! solve), one product's time, and the peak resident memory in doubles per cell.

use std::io::Write;
use std::time::Instant;
use stickslip_benches::process::{cpu_seconds, peak_rss};
use stickslip_benches::surfaces::{hertz_gap, rough_problem, PERIOD};
use stickslip_halfspace::material::composite_modulus;
use stickslip_halfspace::Material;
use stickslip_normal::{Boundary, Nesting, NormalLoad, NormalProblem, Preconditioner};
use stickslip_quad::Tolerance;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let case = args.first().map_or("rough", String::as_str).to_string();
    let n: usize = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(512);
    let opt = |k: &str| args.iter().find_map(|a| a.strip_prefix(k).map(str::to_string));
    let flag = |k: &str| args.iter().any(|a| a == k);
    let tol: f64 = opt("tol=").and_then(|v| v.parse().ok()).unwrap_or(1e-8);
    let steel = Material::new(210e9, 0.3).expect("steel");
    let rigid = Material::rigid();
    let (gap, boundary, load, side) = match case.as_str() {
        "rough" => {
            let (gap, pm) = rough_problem(n);
            let pm = opt("pm=").and_then(|v| v.parse().ok()).unwrap_or(pm);
            (gap, Boundary::Periodic, pm * PERIOD * PERIOD, PERIOD)
        }
        "hertz" => {
            let side = 1e-3;
            let (a, r) = (0.3 * side, 0.01);
            let es = composite_modulus(&steel, &rigid);
            (hertz_gap(n, side, r), Boundary::Free, 4.0 * es * a * a * a / (3.0 * r), side)
        }
        other => panic!("unknown case {other}: rough or hertz"),
    };
    if let Some(file) = opt("write=") {
        let mut f = std::fs::File::create(&file).expect("create");
        for v in &gap {
            f.write_all(&v.to_le_bytes()).expect("write");
        }
        println!("{case} {n}: gap written to {file}; load {load:e} N, side {side:e} m");
        return;
    }
    let h = side / n as f64;
    let mut problem = NormalProblem::new(n, n, (h, h), &gap, [steel, rigid], boundary)
        .expect("problem")
        .with_tolerance(Tolerance::relative(tol).expect("tolerance"))
        .with_min_contact_cells(1);
    if flag("cold") {
        problem = problem.with_nesting(Nesting::Cold);
    }
    if flag("identity") {
        problem = problem.with_preconditioner(Preconditioner::Identity);
    }
    if let Some(h) = opt("hardness=").and_then(|v| v.parse().ok()) {
        problem = problem.with_hardness(h);
    }
    let (c0, t0) = (cpu_seconds(), Instant::now());
    let control = match opt("approach=").and_then(|v| v.parse().ok()) {
        Some(d) => NormalLoad::Approach(d),
        None => NormalLoad::Force(load),
    };
    let s = problem.solve(control).expect("solve");
    let (wall, cpu) = (t0.elapsed().as_secs_f64(), cpu_seconds() - c0);
    let peak = peak_rss() as f64 / (8.0 * (n * n) as f64);
    let levels: Vec<String> = s
        .levels
        .iter()
        .map(|l| format!("{}:{}+{}", l.lattice.0, l.iterations, l.products))
        .collect();
    println!(
        "{case} {n}x{n} tol {tol:e}: levels [{}] fine {} iterations ({} approach steps), {} products + {} preconditioner; \
         residuals gap {:.1e} compl {:.1e} force {:.1e}; contact {:.4} ({} cells, plastic {:.4}, peak {:.3e} Pa, force {:.4e} N, approach {:.6e} m); \
         setup {:.3} s, coarse {:.3} s, solve {:.3} s (wall {wall:.3} s, CPU {cpu:.2} s); peak {peak:.2} doubles/cell",
        levels.join(" "),
        s.info.iterations,
        s.info.approach_steps,
        s.info.products,
        s.info.preconditioner_products,
        s.info.gap_residual,
        s.info.complementarity_residual,
        s.info.force_residual,
        s.fraction,
        s.contact_cells,
        s.plastic_fraction,
        s.peak_pressure,
        s.force,
        s.approach,
        s.info.setup_seconds,
        s.info.coarse_seconds,
        s.info.solve_seconds,
    );
    if let Some(file) = opt("pressure=") {
        let mut f = std::fs::File::create(&file).expect("create");
        for v in &s.pressure {
            f.write_all(&v.to_le_bytes()).expect("write");
        }
    }
}
