//! The points of a sweep hand each other the wheel-rail library's cache (its operators,
//! issue 29 item 9) and the parsed profiles: a run's result must not depend on the runs
//! before it. The same position, run first in a fresh process, then after other positions
//! (of the same problem, and of another cell size), gives the same wheel_rail block, bit for
//! bit, with FASTSIM and with the exact theory.

mod common;
use common::scenes_dir;
use stickslip_run::{run, Outcome, RunOptions};
use stickslip_scene::Scene;

fn scene(method: &str, cell: &str, lateral: &str) -> Outcome {
    let path = scenes_dir().join("wheel_rail_manchester_a22.toml");
    let text = std::fs::read_to_string(&path)
        .unwrap()
        .replace("lateral = \"2 mm\"", &format!("lateral = \"{lateral}\""))
        .replace("cell = [\"0.2 mm\", \"0.2 mm\"]", &format!("cell = [\"{cell}\", \"{cell}\"]"))
        .replace("[solver]\n", &format!("[solver]\n{method}"));
    let s = Scene::from_toml_str(&text, Some(path)).unwrap_or_else(|e| panic!("{e}"));
    run(&s, &RunOptions::default()).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn a_position_gives_the_same_result_whatever_ran_before() {
    for method in ["method = \"fastsim\"\n", ""] {
        let first = scene(method, "0.2 mm", "2 mm");
        let w = first.wheel_rail.as_ref().unwrap();
        assert!(w.patches[0].fn_ > 9e3, "{method}: fn {}", w.patches[0].fn_);
        // Other positions of the same problem (their operators are kept), and another cell
        // size (another problem: its own cache).
        let _ = scene(method, "0.2 mm", "6 mm");
        let _ = scene(method, "0.2 mm", "0 mm");
        let _ = scene(method, "0.25 mm", "2 mm");
        let again = scene(method, "0.2 mm", "2 mm");
        assert_eq!(again.wheel_rail, first.wheel_rail, "{method}");
        assert_eq!(again.forces, first.forces, "{method}");
        assert_eq!(again.contact, first.contact, "{method}");
        assert_eq!(again.solver.iterations, first.solver.iterations, "{method}");
        assert_eq!(
            again.solver.normal.map(|n| n.iterations),
            first.solver.normal.map(|n| n.iterations)
        );
    }
}
