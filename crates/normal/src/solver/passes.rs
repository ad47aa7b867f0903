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
