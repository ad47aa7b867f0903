//! `stickslip sweep` and `stickslip merge`: shards merge to the file the whole sweep writes,
//! byte for byte; bad specifications and incomplete merges exit 2 with the reason.

use std::path::{Path, PathBuf};
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_stickslip"))
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("stickslip-cli-sweep-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn scene() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/hertz_cylinder_cattaneo.toml")
}

const VARY: [&str; 4] =
    ["--vary", "load.tangential=0 kN/m:40 kN/m:5", "--vary", "load.friction=0.2,0.3"];

#[test]
fn shards_merge_to_the_full_sweep_byte_for_byte() {
    let d = tmp("shards");
    let o = bin()
        .arg("sweep")
        .arg(scene())
        .args(VARY)
        .arg("--out")
        .arg(d.join("full"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("10 points: 7 ok, 3 failed"), "{out}");
    for i in 1..=4 {
        let o = bin()
            .arg("sweep")
            .arg(scene())
            .args(VARY)
            .args(["--shard", &format!("{i}/4"), "--out"])
            .arg(d.join("shards"))
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    assert!(d.join("shards/sweep-4of4.parquet").exists());
    let o = bin()
        .arg("merge")
        .arg(d.join("shards"))
        .arg("--out")
        .arg(d.join("merged"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in ["sweep.csv", "sweep.parquet"] {
        let a = std::fs::read(d.join("full").join(f)).unwrap();
        let b = std::fs::read(d.join("merged").join(f)).unwrap();
        assert!(a == b, "{f} differs");
    }
    // A missing shard is named.
    std::fs::remove_file(d.join("shards/sweep-2of4.csv")).unwrap();
    let o =
        bin().arg("merge").arg(d.join("shards")).arg("--out").arg(d.join("m2")).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("points missing: 1, 5, 9"), "{err}");
    assert!(!d.join("m2").exists());
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn bad_specs_exit_2_with_the_reason() {
    let d = tmp("bad");
    for (args, want) in [
        (vec!["--vary", "load.friction"], "no `=`"),
        (vec!["--vary", "load.friction=1:2"], "three parts"),
        (vec!["--vary", "load.friction=0.1", "--shard", "3/2"], "not a shard"),
        (vec!["--vary", "load.frction=0.1,0.2"], "frction"),
    ] {
        let o = bin().arg("sweep").arg(scene()).args(&args).arg("--out").arg(&d).output().unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(want), "{args:?}: {err}");
        assert!(!d.exists(), "{args:?} wrote output");
    }
}
