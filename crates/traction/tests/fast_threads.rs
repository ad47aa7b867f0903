//! The fast solver and the load-history stepper split their per-cell passes over rayon's
//! threads, with every sum taken over fixed blocks of cells and the block sums added in
//! order: the result must be the same, bit for bit, whatever the number of threads. Checked
//! on lattices of more than one block (4096 cells), on a steady partial-slip solve with a
//! force and a moment (three rigid modes) and on a load path with a reversal, each solved
//! on pools of one, two and three threads.

use stickslip_halfspace::Material;
use stickslip_lattice::ContactGrid;
use stickslip_traction::history::{HistoryProblem, LoadPath, PathControl};
use stickslip_traction::{Error, FastConfig, FastProblem, Load, Tolerance};

const P: f64 = 2160.0;
const F: f64 = 0.1;

/// The Hertz circle of seed 002 Example 1's proportions, `across` cells in diameter.
fn sphere(across: usize) -> (ContactGrid, Material) {
    let s = Material::new(30e6, 0.3).unwrap();
    let a = (3.0 * P * 2.0 * s.normal_compliance() / 4.0).cbrt();
    (ContactGrid::hertz_circle(a, P, across).unwrap(), s)
}

fn on_threads<R: Send>(threads: usize, f: impl FnOnce() -> R + Send) -> R {
    rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap().install(f)
}

fn bits(v: &[(f64, f64)]) -> Vec<(u64, u64)> {
    v.iter().map(|q| (q.0.to_bits(), q.1.to_bits())).collect()
}

#[test]
fn steady_solve_is_the_same_on_any_number_of_threads() {
    let (grid, s) = sphere(128);
    assert!(grid.len() > 2 * 4096, "{} cells: fewer than three blocks", grid.len());
    let config = FastConfig::new(Tolerance::relative(1e-10).unwrap(), 100).unwrap();
    let load =
        Load::polar(0.5 * F * P, 0.3).unwrap().with_moment(0.05 * F * P * 0.01, None).unwrap();
    let solve =
        || FastProblem::new(&grid, [s, s], F, load).unwrap().with_config(config).solve().unwrap();
    let one = on_threads(1, solve);
    assert!(one.state.contains(&stickslip_traction::ElementState::Slip));
    for threads in [2, 3] {
        let other = on_threads(threads, solve);
        assert_eq!(bits(&one.traction), bits(&other.traction), "traction, {threads} threads");
        assert_eq!(bits(&one.slip), bits(&other.slip), "slip, {threads} threads");
        assert_eq!(one.state, other.state, "state, {threads} threads");
        assert_eq!(one.shift.0.to_bits(), other.shift.0.to_bits());
        assert_eq!(one.shift.1.to_bits(), other.shift.1.to_bits());
        assert_eq!(one.rotation.to_bits(), other.rotation.to_bits());
        assert_eq!(one.info.products, other.info.products);
        assert_eq!(one.info.cg_iterations, other.info.cg_iterations);
        assert_eq!(one.info.residual.to_bits(), other.info.residual.to_bits());
    }
}

#[test]
fn load_path_is_the_same_on_any_number_of_threads() {
    let (grid, s) = sphere(80);
    assert!(grid.len() > 4096, "{} cells: a single block", grid.len());
    let config = FastConfig::new(Tolerance::relative(1e-10).unwrap(), 100).unwrap();
    let ts = 0.5 * F * P;
    let path = LoadPath::new(PathControl::Force, vec![0.0, ts, -ts], vec![P], 4).unwrap();
    let run = || {
        let pressure = grid.pressure.clone();
        HistoryProblem::new(&grid, [s, s], F)
            .unwrap()
            .with_config(config)
            .run(&path, |_| Ok::<_, Error>(pressure.clone()))
            .unwrap()
    };
    let one = on_threads(1, run);
    assert!(one.dissipation.iter().any(|d| *d > 0.0));
    for threads in [2, 3] {
        let other = on_threads(threads, run);
        assert_eq!(bits(&one.traction), bits(&other.traction), "traction, {threads} threads");
        assert_eq!(bits(&one.slip), bits(&other.slip), "slip, {threads} threads");
        let d = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(d(&one.dissipation), d(&other.dissipation), "dissipation, {threads}");
        assert_eq!(d(&one.slip_range), d(&other.slip_range), "slip range, {threads}");
        assert_eq!(one.steps.len(), other.steps.len());
        for (a, b) in one.steps.iter().zip(&other.steps) {
            assert_eq!(a.products, b.products);
            assert_eq!(a.tangential.to_bits(), b.tangential.to_bits());
            assert_eq!(a.shift.to_bits(), b.shift.to_bits());
            assert_eq!(a.dissipated.to_bits(), b.dissipated.to_bits());
            assert_eq!(a.moment.to_bits(), b.moment.to_bits());
            assert_eq!(a.elastic_energy.to_bits(), b.elastic_energy.to_bits());
        }
    }
}
