//! Issue 29 item 4: creepages given directly (`motion.creepage`) for a wheel on a rail with
//! a single contact patch, instead of the wheelset's pitch rate. The patch's creepages in
//! result.json are in the patch frame of the scene's side, so giving back the creepages a
//! kinematic run reports must give the same creep forces (the steady solution depends on
//! the creepages only), on the mirrored (left) side as on the right; a position with two
//! patches refuses them with the key.

// SceneError carries file, position, key and hint; tests return it as is.
#![allow(clippy::result_large_err)]

use stickslip_run::{run, Outcome, RunOptions};
use stickslip_scene::{ErrorKind, Scene, SceneError};

fn scene(side: &str, position: (&str, &str, &str), motion: &str) -> String {
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/../wheelrail/data");
    format!(
        "[geometry]\nkind = \"wheel-rail\"\nside = \"{side}\"\nrail_profile = \"{data}/MBench_UIC60_v3.prr\"\nwheel_profile = \"{data}/MBench_S1002_v3.prw\"\nprofile_unit = \"mm\"\ngauge = \"1435 mm\"\ngauge_height = \"14 mm\"\nrail_cant = \"0 rad\"\nflange_back_distance = \"1360 mm\"\nflange_back_position = \"-70 mm\"\nwheel_radius = \"460 mm\"\n[position]\nlateral = \"{}\"\nyaw = \"{}\"\nroll = \"{}\"\n[substrate]\ne = \"209.92 GPa\"\nnu = 0.28\n[indenter]\nmodel = \"same\"\n[load]\nnormal = \"10 kN\"\nfriction = 0.3\n[motion]\nkind = \"rolling\"\nspeed = \"2 m/s\"\n{motion}\n[solver]\ncell = [\"0.4 mm\", \"0.4 mm\"]\ntolerance = 1e-8\n",
        position.0, position.1, position.2
    )
}

fn go(src: &str) -> Result<Outcome, SceneError> {
    let file = std::env::temp_dir().join("wheel_rail_creepage.toml");
    run(&Scene::from_toml_str(src, Some(file))?, &RunOptions::default())
}

const A22_5: (&str, &str, &str) = ("2 mm", "4.8 mrad", "-0.1128 mrad");

#[test]
fn given_creepages_reproduce_the_kinematic_creep_forces_on_both_sides() {
    for side in ["left", "right"] {
        let kin = go(&scene(side, A22_5, "pitch_rate = \"-4.3459197 rad/s\"")).unwrap();
        let w = kin.wheel_rail.as_ref().unwrap();
        assert_eq!(w.patches.len(), 1, "{side}: one patch at position 5");
        let p = &w.patches[0];
        let c = p.creepage;
        let given = format!(
            "creepage = {{ longitudinal = {:e}, lateral = {:e}, spin = \"{:e} 1/m\" }}",
            c.longitudinal, c.lateral, c.spin
        );
        let out = go(&scene(side, A22_5, &given)).unwrap();
        let q = &out.wheel_rail.as_ref().unwrap().patches[0];
        let scale = 0.3 * p.fn_;
        let err = [(q.fx - p.fx).abs(), (q.fs - p.fs).abs()].iter().fold(0.0f64, |m, v| m.max(*v))
            / scale;
        println!(
            "{side}: creepages {:.4e} {:.4e} {:.4e}; fx {:.3} / {:.3} N, fs {:.3} / {:.3} N: {err:.1e} f Fn",
            c.longitudinal, c.lateral, c.spin, p.fx, q.fx, p.fs, q.fs
        );
        assert_eq!(q.creepage.longitudinal, c.longitudinal);
        assert_eq!(q.creepage.lateral, c.lateral);
        assert_eq!(q.creepage.spin, c.spin);
        assert!(err < 1e-6, "{side}: {err:.2e}");
        assert!(out.audit.passed);
    }
}

#[test]
fn creepages_for_two_patches_or_with_a_pitch_rate_are_refused() {
    // A22 position 11, right wheel: tread and flange root touch (two patches).
    let two = scene(
        "right",
        ("5 mm", "12 mrad", "-0.3554 mrad"),
        "creepage = { longitudinal = 1e-3, lateral = 0, spin = \"0 1/m\" }",
    );
    let e = go(&two).unwrap_err();
    println!("{e}");
    assert_eq!(e.key.as_deref(), Some("motion.creepage"), "{e}");
    assert!(e.to_string().contains("one contact patch"), "{e}");
    let both =
        scene("left", A22_5, "pitch_rate = \"-4.3 rad/s\"\ncreepage = { longitudinal = 1e-3 }");
    let e = go(&both).unwrap_err();
    println!("{e}");
    assert_eq!(e.kind, ErrorKind::Schema);
    assert_eq!(e.key.as_deref(), Some("motion.creepage"), "{e}");
}
