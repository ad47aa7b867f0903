//! Reference solvers and surfaces shared by the normal-contact tests: a dense LU and the
//! exact active-set solve of the discrete problem, independent of the FFT solver; the dense
//! matrix of an operator (its columns); a band-limited rough periodic surface.

#![allow(dead_code)]

use stickslip_lattice::roughness::{Rms, SelfAffine};
use stickslip_normal::NormalOperator;

/// The dense row-major matrix of `op` (n x n, n its cells), column by column from its own
/// products: checks the iteration, not the operator.
pub fn dense_matrix(op: &NormalOperator) -> Vec<f64> {
    let (nx, ny) = op.lattice();
    let n = nx * ny;
    let mut scratch = op.make_scratch();
    let mut k = vec![0.0; n * n];
    let (mut e_j, mut col) = (vec![0.0; n], vec![0.0; n]);
    for j in 0..n {
        e_j.fill(0.0);
        e_j[j] = 1.0;
        op.apply(&e_j, &mut col, &mut scratch);
        for i in 0..n {
            k[i * n + j] = col[i];
        }
    }
    k
}

/// The initial gap of a band-limited self-affine periodic surface (Hurst 0.8, wavenumbers 2 to
/// 32 over the period, rms height 1 um) on `n` x `n` cells of a square period `size` (m),
/// measured from its highest point; and the cell side.
pub fn rough_periodic_gap(n: usize, size: f64, seed: u64) -> (Vec<f64>, f64) {
    let h = SelfAffine {
        hurst: 0.8,
        k_low: 2.0,
        k_rolloff: 2.0,
        k_high: 32.0,
        rms: Rms::Height(1e-6),
        seed,
    }
    .heights(n, n, [size, size])
    .unwrap();
    let top = h.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    (h.iter().map(|v| top - v).collect(), size / n as f64)
}

/// Dense LU with partial pivoting: solves a x = b in place (a row-major n x n).
pub fn lu_solve(mut a: Vec<f64>, mut b: Vec<f64>) -> Vec<f64> {
    let n = b.len();
    for c in 0..n {
        let piv =
            (c..n).max_by(|&i, &j| a[i * n + c].abs().total_cmp(&a[j * n + c].abs())).unwrap();
        if piv != c {
            for k in 0..n {
                a.swap(c * n + k, piv * n + k);
            }
            b.swap(c, piv);
        }
        for i in c + 1..n {
            let f = a[i * n + c] / a[c * n + c];
            if f != 0.0 {
                for k in c..n {
                    a[i * n + k] -= f * a[c * n + k];
                }
                b[i] -= f * b[c];
            }
        }
    }
    let mut x = vec![0.0; n];
    for i in (0..n).rev() {
        let s: f64 = (i + 1..n).map(|k| a[i * n + k] * x[k]).sum();
        x[i] = (b[i] - s) / a[i * n + i];
    }
    x
}

/// Exact active-set solve of K p + g0 - delta >= 0, p >= 0, complementarity, with
/// h^2 sum p = load: the bordered system on the active set, one cell in or out per step.
pub fn dense_active_set(k: &[f64], g0: &[f64], area: f64, load: f64) -> (Vec<f64>, f64) {
    let n = g0.len();
    let first = (0..n).min_by(|&i, &j| g0[i].total_cmp(&g0[j])).unwrap();
    let mut set = vec![first];
    for _ in 0..10 * n {
        let m = set.len();
        let mut a = vec![0.0; (m + 1) * (m + 1)];
        let mut b = vec![0.0; m + 1];
        for (r, &i) in set.iter().enumerate() {
            for (c, &j) in set.iter().enumerate() {
                a[r * (m + 1) + c] = k[i * n + j];
            }
            a[r * (m + 1) + m] = -1.0;
            a[m * (m + 1) + r] = area;
            b[r] = -g0[i];
        }
        b[m] = load;
        let x = lu_solve(a, b);
        let delta = x[m];
        if let Some((r, _)) =
            x[..m].iter().enumerate().filter(|(_, v)| **v < 0.0).min_by(|a, b| a.1.total_cmp(b.1))
        {
            set.remove(r);
            continue;
        }
        let mut p = vec![0.0; n];
        for (r, &i) in set.iter().enumerate() {
            p[i] = x[r];
        }
        let gap: Vec<f64> = (0..n)
            .map(|i| (0..n).map(|j| k[i * n + j] * p[j]).sum::<f64>() + g0[i] - delta)
            .collect();
        let worst = (0..n).filter(|i| !set.contains(i)).min_by(|&i, &j| gap[i].total_cmp(&gap[j]));
        match worst {
            Some(i) if gap[i] < -1e-15 * delta.abs() => set.push(i),
            _ => return (p, delta),
        }
    }
    panic!("active set did not terminate");
}

/// Exact active-set solve of the box-constrained problem (a hardness cap) at the approach
/// `delta`: `p` with `0 <= p <= cap` and the gap `g = K p + g0 - delta` zero where
/// `0 < p < cap`, `>= 0` where `p = 0` and `<= 0` where `p = cap`. The system on the free set
/// by LU, one cell moved per step (the most violated condition), from the cells that the rigid
/// interference overlaps.
pub fn dense_box_approach(k: &[f64], g0: &[f64], delta: f64, cap: f64) -> Vec<f64> {
    let n = g0.len();
    // 0: off, 1: free, 2: at the cap.
    let mut state: Vec<u8> = g0.iter().map(|&g| u8::from(g < delta)).collect();
    let scale = delta - g0.iter().copied().fold(f64::INFINITY, f64::min);
    for _ in 0..20 * n {
        let free: Vec<usize> = (0..n).filter(|&i| state[i] == 1).collect();
        let m = free.len();
        let mut a = vec![0.0; m * m];
        let mut b = vec![0.0; m];
        for (r, &i) in free.iter().enumerate() {
            for (c, &j) in free.iter().enumerate() {
                a[r * m + c] = k[i * n + j];
            }
            let plastic: f64 = (0..n).filter(|&j| state[j] == 2).map(|j| k[i * n + j] * cap).sum();
            b[r] = delta - g0[i] - plastic;
        }
        let x = if m > 0 { lu_solve(a, b) } else { Vec::new() };
        let mut p: Vec<f64> = state.iter().map(|&s| if s == 2 { cap } else { 0.0 }).collect();
        for (r, &i) in free.iter().enumerate() {
            p[i] = x[r];
        }
        let worst_bound = free
            .iter()
            .map(|&i| (i, (-p[i]).max(p[i] - cap)))
            .filter(|(_, v)| *v > 0.0)
            .max_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((i, _)) = worst_bound {
            state[i] = if p[i] < 0.0 { 0 } else { 2 };
            continue;
        }
        let gap = |i: usize| (0..n).map(|j| k[i * n + j] * p[j]).sum::<f64>() + g0[i] - delta;
        let worst_gap = (0..n)
            .filter(|&i| state[i] != 1)
            .map(|i| (i, if state[i] == 0 { -gap(i) } else { gap(i) }))
            .filter(|(_, v)| *v > 1e-14 * scale)
            .max_by(|a, b| a.1.total_cmp(&b.1));
        match worst_gap {
            Some((i, _)) => state[i] = 1,
            None => return p,
        }
    }
    panic!("dense box active set did not finish");
}

/// [`dense_box_approach`] under the force `load` (`area` the cell area): the approach found
/// by bisection on the force, which grows monotonically with the approach, down to adjacent
/// doubles. Returns `p` and the approach.
pub fn dense_box_force(k: &[f64], g0: &[f64], area: f64, load: f64, cap: f64) -> (Vec<f64>, f64) {
    let force = |d: f64| dense_box_approach(k, g0, d, cap).iter().sum::<f64>() * area;
    let gmin = g0.iter().copied().fold(f64::INFINITY, f64::min);
    let (mut lo, mut hi) = (gmin, gmin + 1e-12);
    while force(hi) < load {
        hi = gmin + 2.0 * (hi - gmin);
    }
    loop {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if force(mid) < load {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (dense_box_approach(k, g0, hi, cap), hi)
}
