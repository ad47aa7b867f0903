//! The parallel passes over the lattice, in a fixed block order (bit-identical results for
//! any number of threads).

use rayon::prelude::*;

/// Cells per block of the parallel passes. Every sum over the lattice adds fixed blocks of
/// this many cells (each in index order) and then the block results in block order, so a
/// solve gives the same bits for any number of threads.
pub(super) const BLOCK: usize = 4096;

/// The results of a parallel pass over blocks, in block order (their sum, taken by the caller
/// in this order, does not depend on how rayon split the work).
pub(super) fn in_order<T: Send>(blocks: impl IndexedParallelIterator<Item = T>) -> Vec<T> {
    let mut out = Vec::with_capacity(blocks.len());
    blocks.collect_into_vec(&mut out);
    out
}

/// Scale `p` to the sum `target`; false if its sum is zero.
pub(super) fn rescale(p: &mut [f64], target: f64) -> bool {
    let s = in_order(p.par_chunks(BLOCK).map(|b| b.iter().sum::<f64>())).iter().sum::<f64>();
    if s > 0.0 {
        let f = target / s;
        p.par_iter_mut().for_each(|p| *p *= f);
        true
    } else {
        false
    }
}

/// `q` clipped to at most $H$ (a negative value is a cell off the contact, at that
/// distance below it: what a gradient step would give it), then its Euclidean projection onto the pressures of the sum
/// `target` that keep the contact's active set: $p_k = \min(\max(q_k - \mu, 0), H)$ over
/// the free cells $0 < q_k < H$, the cells at 0 and at the cap $H$ unchanged (the
/// projection onto that face of the box $0 \le p \le H$). When the free cells cannot carry
/// the target between their bounds, the projection is over every pressed cell
/// ($q_k > 0$), and when those cannot, over all cells (the projection onto the whole box
/// with the sum). The scalar $\mu$ is the root of the non-increasing, piecewise-linear
/// $S(\mu) = \sum_k \min(\max(q_k - \mu, 0), H)$ over those cells, found piece by piece:
/// on the piece of the current $\mu$ (the same cells strictly between the bounds) $S$ is
/// linear and its root is solved for directly; when that root lies on the same piece it is
/// exact, otherwise the search moves there, kept inside the bracket of the values tried
/// (bisection when the piece's root leaves it). Negative values outside the projection
/// become 0. No product with $K$. Returns $\mu$, or `None` when the target is not positive
/// and finite or exceeds $H$ times the cells (`q` then only clipped to at most $H$).
pub(super) fn project_sum(q: &mut [f64], cap: f64, target: f64) -> Option<f64> {
    if !(target > 0.0 && target.is_finite()) {
        return None;
    }
    q.par_iter_mut().for_each(|q| *q = q.min(cap));
    // The counts of the sets: free (0 < q < cap), at the cap, pressed.
    let (free, at_cap) = in_order(q.par_chunks(BLOCK).map(|b| {
        b.iter().fold((0usize, 0usize), |a, &q| {
            if q >= cap {
                (a.0, a.1 + 1)
            } else if q > 0.0 {
                (a.0 + 1, a.1)
            } else {
                a
            }
        })
    }))
    .into_iter()
    .fold((0, 0), |a, b| (a.0 + b.0, a.1 + b.1));
    let fixed = cap * at_cap as f64;
    // 0: the free cells (the others fixed); 1: the pressed cells; 2: all cells.
    let tier = if free > 0 && target >= fixed && target <= fixed + cap * free as f64 {
        0
    } else if ((free + at_cap) as f64) * cap >= target && free + at_cap > 0 {
        1
    } else if (q.len() as f64) * cap >= target {
        2
    } else {
        return None;
    };
    let member = move |q: f64| match tier {
        0 => q > 0.0 && q < cap,
        1 => q > 0.0,
        _ => true,
    };
    let fixed = if tier == 0 { fixed } else { 0.0 };
    // On the piece of mu: the sum of q over the free cells, their count, the count at the
    // cap, and the count above mu (with the count at the cap, they identify the piece).
    let piece = |mu: f64, q: &[f64]| -> (f64, usize, usize, usize) {
        in_order(q.par_chunks(BLOCK).map(|b| {
            let mut acc = (0.0, 0usize, 0usize, 0usize);
            for &q in b {
                if !member(q) {
                    continue;
                }
                let v = q - mu;
                if v >= cap {
                    acc.2 += 1;
                    acc.3 += 1;
                } else if v > 0.0 {
                    acc = (acc.0 + q, acc.1 + 1, acc.2, acc.3 + 1);
                }
            }
            acc
        }))
        .into_iter()
        .fold((0.0, 0, 0, 0), |a, b| (a.0 + b.0, a.1 + b.1, a.2 + b.2, a.3 + b.3))
    };
    let value = |pc: (f64, usize, usize, usize), mu: f64| {
        fixed + pc.0 - pc.1 as f64 * mu + cap * pc.2 as f64
    };
    // The bracket: S(lo) >= target >= S(hi).
    let (qmin, qmax) = in_order(q.par_chunks(BLOCK).map(|b| {
        b.iter()
            .filter(|&&q| member(q))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |a, &q| (a.0.min(q), a.1.max(q)))
    }))
    .into_iter()
    .fold((f64::INFINITY, f64::NEG_INFINITY), |a, b| (a.0.min(b.0), a.1.max(b.1)));
    let (mut lo, mut hi) = (qmin - cap, qmax);
    let mut mu = 0.0f64.clamp(lo, hi);
    let mut found = None;
    let mut pc = piece(mu, q);
    for _ in 0..200 {
        let s = value(pc, mu);
        if s >= target {
            lo = lo.max(mu);
        }
        if s <= target {
            hi = hi.min(mu);
        }
        if s == target {
            found = Some(mu);
            break;
        }
        // The root of this piece's line, if it has free cells.
        let next = if pc.1 > 0 { (value(pc, 0.0) - target) / pc.1 as f64 } else { f64::NAN };
        let next = if next >= lo && next <= hi { next } else { 0.5 * (lo + hi) };
        let again = piece(next, q);
        if again.1 == pc.1 && again.2 == pc.2 && again.3 == pc.3 && pc.1 > 0 {
            // The same piece: its root is exact.
            found = Some(next);
            break;
        }
        if next == mu || hi <= lo {
            found = Some(next);
            break;
        }
        // The piece of the next value is the one just evaluated.
        (mu, pc) = (next, again);
    }
    let mu = found.unwrap_or(0.5 * (lo + hi));
    q.par_iter_mut().for_each(|q| {
        *q = if member(*q) { (*q - mu).clamp(0.0, cap) } else { q.max(0.0) };
    });
    Some(mu)
}

#[cfg(test)]
mod tests {
    use super::project_sum;

    /// A reference projection by brute force over the cells `member` selects (the others
    /// fixed, `fixed` their sum): every breakpoint of S(mu) (q and q - H over those cells),
    /// sorted; S evaluated at each by a plain loop; the root linearly interpolated between
    /// the two breakpoints that bracket the target (S is linear between them).
    fn brute(q: &[f64], cap: f64, target: f64, member: impl Fn(f64) -> bool, fixed: f64) -> f64 {
        let cells: Vec<f64> = q.iter().copied().filter(|&q| member(q)).collect();
        let s = |mu: f64| fixed + cells.iter().map(|q| (q - mu).clamp(0.0, cap)).sum::<f64>();
        let mut bp: Vec<f64> = cells.iter().flat_map(|&q| [q, q - cap]).collect();
        bp.sort_by(f64::total_cmp);
        for w in bp.windows(2) {
            let (a, b) = (w[0], w[1]);
            let (sa, sb) = (s(a), s(b));
            if sa >= target && sb <= target {
                if sa == sb {
                    return a;
                }
                return a + (sa - target) * (b - a) / (sa - sb);
            }
        }
        panic!("target outside the range of S");
    }

    /// A deterministic pseudo-random sequence in [0, 1) (a 64-bit LCG).
    fn uniform(seed: &mut u64) -> f64 {
        *seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (*seed >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Pressures up to the cap 1 with a share exactly at it, and negative values (cells off
    /// the contact, at a distance), as after a step.
    fn pressures(n: usize, seed: &mut u64) -> Vec<f64> {
        (0..n).map(|_| (2.0 * uniform(seed) - 0.6).min(1.0)).collect()
    }

    #[test]
    fn projection_matches_brute_force() {
        let cap = 1.0;
        let mut seed = 7u64;
        let mut tiers = [0usize; 3];
        for case in 0..60 {
            let n = 1 + case * 37 % 5000;
            let q = pressures(n, &mut seed);
            let free = q.iter().filter(|&&q| q > 0.0 && q < cap).count();
            let at_cap = q.iter().filter(|&&q| q >= cap).count() as f64;
            let pressed = q.iter().filter(|&&q| q > 0.0).count() as f64;
            // Targets the free cells can carry, ones only all pressed cells can, and ones
            // that need every cell.
            for share in [0.02, 0.3, 0.6, 0.95, 0.98] {
                let target = share * n as f64 * cap;
                let (tier, member, fixed): (usize, Box<dyn Fn(f64) -> bool>, f64) =
                    if free > 0 && target >= at_cap && target <= at_cap + free as f64 {
                        (0, Box::new(move |q| q > 0.0 && q < cap), at_cap)
                    } else if pressed > 0.0 && target <= pressed {
                        (1, Box::new(|q| q > 0.0), 0.0)
                    } else {
                        (2, Box::new(|_| true), 0.0)
                    };
                tiers[tier] += 1;
                let mut p = q.clone();
                let mu = project_sum(&mut p, cap, target).expect("feasible");
                let reference = brute(&q, cap, target, &member, fixed);
                let sum: f64 = p.iter().sum();
                assert!(
                    (mu - reference).abs() <= 1e-12 * (1.0 + reference.abs()),
                    "n {n} share {share} tier {tier}: mu {mu} against {reference}"
                );
                assert!((sum - target).abs() <= 1e-11 * target, "sum {sum} against {target}");
                for (p, q) in p.iter().zip(&q) {
                    assert!((0.0..=cap).contains(p));
                    if member(*q) {
                        assert_eq!(*p, (q - mu).clamp(0.0, cap));
                    } else {
                        assert_eq!(*p, q.max(0.0), "a cell outside the projection stays");
                    }
                }
            }
        }
        assert!(tiers.iter().all(|&t| t > 0), "every tier tried: {tiers:?}");
    }

    #[test]
    fn projection_is_the_nearest_point_of_its_face() {
        // Against moving pressure between two free cells (which keeps the sum and the
        // face): no feasible neighbour is nearer to q than the projection.
        let mut seed = 11u64;
        let q = pressures(400, &mut seed);
        let target = q.iter().sum::<f64>() * 0.9;
        let mut p = q.clone();
        project_sum(&mut p, 1.0, target).expect("feasible");
        let free: Vec<usize> = (0..q.len()).filter(|&k| q[k] > 0.0 && q[k] < 1.0).collect();
        let dist = |p: &[f64]| free.iter().map(|&k| (p[k] - q[k]).powi(2)).sum::<f64>();
        let d0 = dist(&p);
        let mut tried = 0;
        for (a, b) in free.iter().zip(free.iter().skip(1)) {
            for eps in [1e-3, -1e-3] {
                let mut r = p.clone();
                r[*a] += eps;
                r[*b] -= eps;
                if (0.0..=1.0).contains(&r[*a]) && (0.0..=1.0).contains(&r[*b]) {
                    tried += 1;
                    assert!(dist(&r) >= d0 - 1e-12, "a feasible move nearer to q");
                }
            }
        }
        assert!(tried > 100, "{tried} moves tried");
    }

    #[test]
    fn projection_refuses_what_no_pressure_carries() {
        let mut p = vec![0.5, 0.0, 1.5];
        assert!(project_sum(&mut p, 1.0, 3.5).is_none());
        assert_eq!(p, vec![0.5, 0.0, 1.0], "only clipped");
        assert!(project_sum(&mut p, 1.0, 0.0).is_none());
        let mut z = vec![0.0; 4];
        assert!(project_sum(&mut z, 1.0, 1.0).is_some(), "all cells when none is pressed");
        assert_eq!(z, vec![0.25; 4]);
        // Off-contact cells enter nearest first: the one at -0.1 before the one at -0.5.
        let mut w = vec![1.0, 1.0, -0.1, -0.5];
        let mu = project_sum(&mut w, 1.0, 2.3).expect("feasible");
        assert!((mu + 0.4).abs() < 1e-15, "mu {mu}");
        assert_eq!((w[0], w[1], w[3]), (1.0, 1.0, 0.0));
        assert!((w[2] - 0.3).abs() < 1e-15, "{}", w[2]);
    }
}
