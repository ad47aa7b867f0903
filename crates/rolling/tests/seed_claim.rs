//! The seed's claim l ~ sqrt(8 K R P beta / alpha) over its whole stated grid, for a
//! rubber-like and a polymer-like material (timed, not asserted); the claim fails exactly where
//! FORMULAS.md section D says: where l is not small compared with 2 beta w (x1 not << 1).

mod common;

use stickslip_rolling::{claim_sweep, SweepMaterial};

/// Relative deviation counted as "the claim fails".
const CLAIM_TOL: f64 = 0.01;

#[test]
fn seed_claim_over_its_grid() {
    let per_decade = 4;
    let t0 = std::time::Instant::now();
    let rubber = claim_sweep(&SweepMaterial::RUBBER_LIKE, per_decade).unwrap();
    let polymer = claim_sweep(&SweepMaterial::POLYMER_LIKE, per_decade).unwrap();
    let secs = t0.elapsed().as_secs_f64();
    println!(
        "sweep: {} + {} solves of eqs 19/20 in {:.1} ms",
        rubber.len(),
        polymer.len(),
        secs * 1e3
    );
    for (mat, rows) in
        [(SweepMaterial::RUBBER_LIKE, &rubber), (SweepMaterial::POLYMER_LIKE, &polymer)]
    {
        let name = mat.name;
        assert_eq!(rows.len(), 3 * 29 * 28 / 2);
        let fails: Vec<_> = rows.iter().filter(|r| !r.claim_holds(CLAIM_TOL)).collect();
        let worst =
            rows.iter().max_by(|a, b| a.claim_error.abs().total_cmp(&b.claim_error.abs())).unwrap();
        let min_x1_fail = fails.iter().map(|r| r.x1).fold(f64::INFINITY, f64::min);
        let max_err_small =
            rows.iter().filter(|r| r.x1 <= 0.02).map(|r| r.claim_error.abs()).fold(0.0, f64::max);
        println!(
            "{name}: l_H = {:.3e} m; claim off by > {CLAIM_TOL}: {} of {} rows; smallest x1 among them = {min_x1_fail:.3e}; \
             max |l/l_claim - 1| over rows with x1 <= 0.02: {max_err_small:.2e}; worst row: alpha={:e} beta={:e} w={} l/l_claim={:.4} l/l_H={:.4} x1={:.3e}",
            mat.hertz_length(), fails.len(), rows.len(),
            worst.alpha, worst.beta, worst.speed, worst.claim_error + 1.0, worst.length_over_hertz, worst.x1
        );
        // every row: finite, forward shift, l between the fast asymptote and l_H
        for r in rows.iter() {
            assert!(r.length.is_finite() && r.shift.is_finite());
            assert!(r.shift > 0.0, "d > 0 (forward shift) fails at {r:?}");
            assert!(r.claim_error >= 0.0 && r.length_over_hertz < 1.0, "{r:?}");
        }
        // the claim fails only where l is not << 2 beta w ...
        assert!(fails.iter().all(|r| r.x1 > 0.05), "{name}: a failure at small x1");
        // ... and it holds where l << 2 beta w
        assert!(max_err_small < CLAIM_TOL);
    }
}
