//! The memory that the points running at once may hold: each point reserves its planned
//! memory before it executes and gives it back when done; a point that does not fit waits
//! for running points to finish, and a point that needs more than the whole budget runs
//! when no other point does (its own check against the machine refuses what cannot run at
//! all). So no point is read or planned twice, as a count of points fixed before the sweep
//! would need.

use std::sync::{Condvar, Mutex, PoisonError};

/// Memory free for points and the number of points holding some.
#[derive(Debug)]
pub(crate) struct Budget {
    total: u64,
    state: Mutex<(u64, usize)>,
    freed: Condvar,
}

/// A reservation, given back when dropped (also when the point panics).
pub(crate) struct Held<'a> {
    budget: &'a Budget,
    bytes: u64,
}

impl Budget {
    /// A budget of `total` bytes.
    pub(crate) fn new(total: u64) -> Budget {
        Budget { total, state: Mutex::new((total, 0)), freed: Condvar::new() }
    }

    /// Reserve `bytes` (at most the whole budget), waiting while other points hold too
    /// much of it.
    pub(crate) fn reserve(&self, bytes: u64) -> Held<'_> {
        let bytes = bytes.min(self.total);
        let mut s = self.state.lock().unwrap_or_else(PoisonError::into_inner);
        while s.1 > 0 && s.0 < bytes {
            s = self.freed.wait(s).unwrap_or_else(PoisonError::into_inner);
        }
        s.0 -= bytes;
        s.1 += 1;
        Held { budget: self, bytes }
    }

    /// Points holding a reservation now.
    #[cfg(test)]
    pub(crate) fn holders(&self) -> usize {
        self.state.lock().unwrap_or_else(PoisonError::into_inner).1
    }
}

impl Drop for Held<'_> {
    fn drop(&mut self) {
        let mut s = self.budget.state.lock().unwrap_or_else(PoisonError::into_inner);
        s.0 += self.bytes;
        s.1 -= 1;
        self.budget.freed.notify_all();
    }
}

#[cfg(test)]
mod tests {
    use super::Budget;
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// Points of 60 bytes under a budget of 100 run one at a time; points of 30 three at a
    /// time; a point of 500 (more than the budget) alone.
    #[test]
    fn points_wait_for_memory() {
        for (need, most) in [(60u64, 1usize), (30, 3), (500, 1)] {
            let b = Budget::new(100);
            let peak = AtomicUsize::new(0);
            std::thread::scope(|s| {
                for _ in 0..6 {
                    s.spawn(|| {
                        let _h = b.reserve(need);
                        peak.fetch_max(b.holders(), Ordering::SeqCst);
                        std::thread::sleep(std::time::Duration::from_millis(20));
                    });
                }
            });
            assert_eq!(b.holders(), 0);
            let p = peak.into_inner();
            assert!(p <= most, "{need} bytes: {p} at once, at most {most}");
            assert!(p >= 1);
        }
    }
}
