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
//! instead of the force), `adhesion=W,R` (a Maugis–Dugdale interface of work W J/m² and
//! range R m, issue 32; needs `approach=`; the line then also gives the zone cells and the
//! zone updates, and `iterations`/`products` are summed over the contact solves),
//! `gap=FILE` (`rough` only: the initial gap of the N x N period read from FILE as
//! little-endian f64 instead of the built-in surface), `young=E` and `poisson=NU` (the body
//! instead of steel), `gapout=FILE` (write the gap after the solve). Prints one line: the levels with their iterations, the fine iterations and FFT
//! products, the residuals, the contact fraction, the times (set-up, coarse levels, whole
//! solve), one product's time, and the peak resident memory in doubles per cell.

use std::io::Write;
use std::time::Instant;
use stickslip_benches::process::{cpu_seconds, peak_rss};
use stickslip_benches::surfaces::{hertz_gap, rough_problem, PERIOD};
use stickslip_halfspace::material::composite_modulus;
use stickslip_halfspace::Material;
use stickslip_normal::solver::DEFAULT_MAX_ZONE_UPDATES;
use stickslip_normal::{Adhesion, Boundary, Nesting, NormalLoad, NormalProblem, Preconditioner};
use stickslip_quad::Tolerance;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let case = args.first().map_or("rough", String::as_str).to_string();
    let n: usize = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(512);
    let opt = |k: &str| args.iter().find_map(|a| a.strip_prefix(k).map(str::to_string));
    let flag = |k: &str| args.iter().any(|a| a == k);
    let tol: f64 = opt("tol=").and_then(|v| v.parse().ok()).unwrap_or(1e-8);
    let young: f64 = opt("young=").and_then(|v| v.parse().ok()).unwrap_or(210e9);
    let poisson: f64 = opt("poisson=").and_then(|v| v.parse().ok()).unwrap_or(0.3);
    let steel = Material::new(young, poisson).expect("body");
    let rigid = Material::rigid();
    let (gap, boundary, load, side) = match case.as_str() {
        "rough" => {
            let (mut gap, pm) = rough_problem(n);
            if let Some(file) = opt("gap=") {
                let bytes = std::fs::read(&file).expect("read gap=");
                assert_eq!(bytes.len(), 8 * n * n, "gap= holds N x N little-endian f64");
                gap = bytes
                    .chunks_exact(8)
                    .map(|b| f64::from_le_bytes(b.try_into().expect("8 bytes")))
                    .collect();
            }
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
    let adhesion = opt("adhesion=").map(|v| {
        let (w, r) = v.split_once(',').expect("adhesion=W,R");
        Adhesion::new(w.parse().expect("W"), r.parse().expect("R")).expect("adhesion")
    });
    let s = match (adhesion, control) {
        (Some(adh), NormalLoad::Approach(d)) => {
            let op = problem.operator();
            let a = problem
                .solve_adhesive(&op, adh, d, None, DEFAULT_MAX_ZONE_UPDATES)
                .expect("adhesive solve");
            println!(
                "adhesion w {:e} J/m^2 range {:e} m: zone {} cells ({} outside the contact), {} zone updates, zone residual {:e}",
                adh.work(),
                adh.range(),
                a.zone_cells,
                a.cohesive_only_cells(),
                a.zone_updates,
                a.zone_residual
            );
            a.normal
        }
        (Some(_), NormalLoad::Force(_)) => panic!("adhesion= needs approach="),
        (None, control) => problem.solve(control).expect("solve"),
    };
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
    if let Some(file) = opt("gapout=") {
        let mut f = std::fs::File::create(&file).expect("create");
        for v in &s.gap {
            f.write_all(&v.to_le_bytes()).expect("write");
        }
    }
    if let Some(file) = opt("pressure=") {
        let mut f = std::fs::File::create(&file).expect("create");
        for v in &s.pressure {
            f.write_all(&v.to_le_bytes()).expect("write");
        }
    }
}
