//! One cache of FFT plans for the whole process: a transform of a given length and precision
//! is planned once and shared by every operator that needs it (the points of a sweep on equal
//! lattices, the levels of repeated nested solves, the load steps of a run). Planning is
//! cheap next to a solve, but not free at large sizes, and a sweep repeats it per point.

use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftNum, FftPlanner};
use std::any::{Any, TypeId};
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

type Key = (TypeId, u8, usize);
type Cache = Mutex<HashMap<Key, Box<dyn Any + Send + Sync>>>;

static CACHE: OnceLock<Cache> = OnceLock::new();

/// The plan under `key`, made by `make` the first time.
fn cached<P: Any + Send + Sync + Clone>(key: Key, make: impl FnOnce() -> P) -> P {
    // A panic while planning cannot leave the map half-written: use it as it is.
    let mut map = CACHE.get_or_init(Cache::default).lock().unwrap_or_else(|e| e.into_inner());
    if let Some(p) = map.get(&key).and_then(|b| b.downcast_ref::<P>()) {
        return p.clone();
    }
    let p = make();
    map.insert(key, Box::new(p.clone()));
    p
}

/// The forward real transform of length `n`.
pub(crate) fn r2c<T: FftNum>(n: usize) -> Arc<dyn RealToComplex<T>> {
    cached((TypeId::of::<T>(), 0, n), || RealFftPlanner::<T>::new().plan_fft_forward(n))
}

/// The inverse real transform of length `n`.
pub(crate) fn c2r<T: FftNum>(n: usize) -> Arc<dyn ComplexToReal<T>> {
    cached((TypeId::of::<T>(), 1, n), || RealFftPlanner::<T>::new().plan_fft_inverse(n))
}

/// The forward complex transform of length `n`.
pub(crate) fn forward<T: FftNum>(n: usize) -> Arc<dyn Fft<T>> {
    cached((TypeId::of::<T>(), 2, n), || FftPlanner::<T>::new().plan_fft_forward(n))
}

/// The inverse complex transform of length `n`.
pub(crate) fn inverse<T: FftNum>(n: usize) -> Arc<dyn Fft<T>> {
    cached((TypeId::of::<T>(), 3, n), || FftPlanner::<T>::new().plan_fft_inverse(n))
}

#[cfg(test)]
mod tests {
    #[test]
    fn plans_are_shared() {
        let (a, b) = (super::r2c::<f64>(96), super::r2c::<f64>(96));
        assert!(std::sync::Arc::ptr_eq(&a, &b));
        let (c, d) = (super::forward::<f32>(96), super::forward::<f64>(96));
        assert_eq!(c.len(), d.len());
    }
}
