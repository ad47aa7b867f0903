//! What accuracy costs in time, for every numerical method of stickslip.
//!
//! - [`accuracy`]: the accuracy-versus-time report (library form, no criterion): for each method
//!   and each setting of its accuracy knob, the error against an *independent* reference and the
//!   time, measured in the same run, written as `accuracy.md` with one log-log Pareto plot per
//!   method. The command `stickslip accuracy` and the binary `accuracy` of this package call it.
//! - [`data`]: the reference tables the report measures against (mpmath tables committed by the
//!   physics crates), embedded at compile time so the report runs from any directory.
//! - The criterion benches in `benches/` measure time by problem size and print the accuracy
//!   each setting buys beside it, because a fast wrong answer is not a result
//!   (`cargo bench -p stickslip-benches`).
//! - [`fast_sweep`]: the fast solver's robustness sweep (issue 20), run by
//!   `tests/stability_fast.rs` in CI and by the example `fast_large` at 512 and 1024 across.
//! - [`history_bench`]: the sphere, lattice and arguments the load-history examples share.
//! - The hard-case stability suite is `tests/stability.rs`; its case list is
//!   `docs/hard-cases.md`.

pub mod accuracy;
pub mod data;
pub mod fast_sweep;
pub mod history_bench;
pub mod process;
pub mod surfaces;
