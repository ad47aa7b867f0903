//! The scale table of the normal solver (issue 30, item 2): one solve per lattice size, each
//! in a process of its own (so that its peak memory is its own), printed as a Markdown table
//! with the least-squares growth of time against cells.
//!
//! ```sh
//! cargo run --release -p stickslip-benches --example normal_scale -- rough 256 4096
//! cargo run --release -p stickslip-benches --example normal_scale -- hertz 256 2048
//! ```
//!
//! The problems are those of `normal_probe` (`stickslip_benches::surfaces`): `rough`, the
//! periodic band-limited self-affine surface (the same continuous surface on every lattice,
//! about 5 % contact); `hertz`, a rigid sphere on a free lattice, contact radius 0.3 of the
//! side. Tolerance 1e-8. Columns: the lattice; the solve's wall time with the operator
//! set-up (and apart, the coarse levels'); the iterations on the finest lattice and on each
//! coarser one (coarsest first); the FFT products with K and the preconditioner's on the
//! finest lattice; the certified residual; the peak resident memory of the whole process
//! (initial gap and program included) and the solver's own estimate
//! (`NormalProblem::memory_bytes`), in doubles per cell.

use std::process::Command;
use std::time::Instant;
use stickslip_benches::process::peak_rss;
use stickslip_benches::surfaces::{hertz_gap, rough_problem, PERIOD};
use stickslip_halfspace::material::composite_modulus;
use stickslip_halfspace::Material;
use stickslip_normal::{Boundary, NormalLoad, NormalProblem};
use stickslip_quad::Tolerance;

/// One solve: prints `seconds coarse_seconds fine coarse_list products pre residual peak est`.
fn one(case: &str, n: usize) {
    let steel = Material::new(210e9, 0.3).expect("steel");
    let rigid = Material::rigid();
    let (gap, boundary, load, side) = match case {
        "rough" => {
            let (g, pm) = rough_problem(n);
            (g, Boundary::Periodic, pm * PERIOD * PERIOD, PERIOD)
        }
        _ => {
            let (side, a, r) = (1e-3, 0.3e-3, 0.01);
            let es = composite_modulus(&steel, &rigid);
            (hertz_gap(n, side, r), Boundary::Free, 4.0 * es * a * a * a / (3.0 * r), side)
        }
    };
    let h = side / n as f64;
    let problem = NormalProblem::new(n, n, (h, h), &gap, [steel, rigid], boundary)
        .expect("problem")
        .with_tolerance(Tolerance::relative(1e-8).expect("tolerance"))
        .with_min_contact_cells(1);
    let t0 = Instant::now();
    let s = problem.solve(NormalLoad::Force(load)).expect("solve");
    let wall = t0.elapsed().as_secs_f64();
    let coarse: Vec<String> = s.levels.iter().map(|l| l.iterations.to_string()).collect();
    let cells = (n * n) as f64;
    println!(
        "{wall} {} {} {} {} {} {:e} {} {}",
        s.info.coarse_seconds,
        s.info.iterations,
        if coarse.is_empty() { "-".to_string() } else { coarse.join(",") },
        s.info.products,
        s.info.preconditioner_products,
        s.info.residual,
        peak_rss() as f64 / (8.0 * cells),
        NormalProblem::memory_bytes(n, n, boundary) as f64 / (8.0 * cells),
    );
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().is_some_and(|a| a == "--one") {
        one(&args[1], args[2].parse().expect("size"));
        return;
    }
    let case = args.first().map_or("rough", String::as_str).to_string();
    let lo: usize = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(256);
    let hi: usize = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(2048);
    let exe = std::env::current_exe().expect("this program");
    println!(
        "| lattice | solve (s) | coarse levels (s) | fine iterations | coarse iterations | \
         products + preconditioner | residual | peak memory | estimate |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    let mut fit = Vec::new();
    let mut n = lo;
    while n <= hi {
        let out = Command::new(&exe).args(["--one", &case, &n.to_string()]).output().expect("run");
        let line = String::from_utf8_lossy(&out.stdout);
        let f: Vec<&str> = line.split_whitespace().collect();
        if f.len() < 9 {
            println!("| {n}² | failed: {} |", String::from_utf8_lossy(&out.stderr).trim());
            n *= 2;
            continue;
        }
        let secs: f64 = f[0].parse().unwrap_or(f64::NAN);
        fit.push((((n * n) as f64).ln(), secs.ln()));
        println!(
            "| {n}² | {secs:.3} | {:.3} | {} | {} | {} + {} | {:.1e} | {:.1} | {:.1} |",
            f[1].parse::<f64>().unwrap_or(f64::NAN),
            f[2],
            f[3],
            f[4],
            f[5],
            f[6].parse::<f64>().unwrap_or(f64::NAN),
            f[7].parse::<f64>().unwrap_or(f64::NAN),
            f[8].parse::<f64>().unwrap_or(f64::NAN),
        );
        n *= 2;
    }
    // Least squares of ln t = c + e ln N.
    if fit.len() >= 2 {
        let m = fit.len() as f64;
        let (sx, sy) = fit.iter().fold((0.0, 0.0), |a, p| (a.0 + p.0, a.1 + p.1));
        let (mx, my) = (sx / m, sy / m);
        let (sxy, sxx) = fit
            .iter()
            .fold((0.0, 0.0), |a, p| (a.0 + (p.0 - mx) * (p.1 - my), a.1 + (p.0 - mx).powi(2)));
        println!("\ntime grows as cells^{:.2} (least squares over {} sizes)", sxy / sxx, fit.len());
    }
}
