//! Any text given as a scene: the reader, validation and the planner never panic; every
//! refusal names a key or a position and gives a hint, in plain words; a scene the planner
//! accepts and estimates as cheap is executed, and its result is audited or refused.

#![no_main]

use libfuzzer_sys::fuzz_target;
use stickslip_run::{Execute, Plan, RunOptions};
use stickslip_scene::Scene;

/// Words of the implementation that must never reach a user.
const INTERNAL: [&str; 6] = ["Qty", "Raw", "untagged", "struct ", "f64", "i64"];

fn check(e: &stickslip_scene::SceneError) {
    assert!(e.key.is_some() || e.position.is_some(), "no key or position: {e}");
    assert!(e.hint.is_some(), "no hint: {e}");
    let text = e.to_string();
    for w in INTERNAL {
        assert!(!text.contains(w), "internal word {w:?} in: {text}");
    }
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let scene = match Scene::from_toml_str(text, Some("fuzz.toml".into())) {
        Ok(s) => s,
        Err(e) => return check(&e),
    };
    let plan = match Plan::new(&scene) {
        Ok(p) => p,
        Err(e) => return check(&e),
    };
    let _ = plan.explain();
    if plan.cost.seconds < 0.02 && plan.cost.memory_bytes < 64 << 20 {
        match plan.execute(&RunOptions::default()) {
            Ok(out) => assert!(out.audit.passed),
            Err(e) => assert!(e.hint.is_some(), "no hint: {e}"),
        }
    }
});
