//! Criterion benches for stickslip live in `benches/`; this library is empty on purpose.
//!
//! Every bench measures time *and* prints the accuracy it buys (against the same independent
//! references the tests use), because a fast wrong answer is not a result. Run with
//! `cargo bench -p stickslip-benches`.
