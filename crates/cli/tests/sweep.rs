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

/// `--jobs 1` (one point at a time) and `--jobs 2` write the same files, byte for byte.
#[test]
fn any_number_of_jobs_writes_the_same_table() {
    let d = tmp("jobs");
    for j in ["1", "2", "3"] {
        let o = bin()
            .arg("sweep")
            .arg(scene())
            .args(VARY)
            .args(["--jobs", j, "--out"])
            .arg(d.join(j))
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    for f in ["sweep.csv", "sweep.parquet"] {
        let a = std::fs::read(d.join("1").join(f)).unwrap();
        for j in ["2", "3"] {
            assert!(a == std::fs::read(d.join(j).join(f)).unwrap(), "{f} differs at --jobs {j}");
        }
    }
    let mut zero = bin();
    zero.arg("sweep").arg(scene()).args(VARY).args(["-j", "0", "--out"]).arg(d.join("0"));
    let o = zero.output().unwrap();
    assert_eq!(o.status.code(), Some(2), "--jobs 0 is a usage error");
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

/// A sweep killed mid-way and continued with `--resume` gives the table of an
/// uninterrupted run, byte for byte: the points it finished are read from its partial table
/// (appended and flushed as each point finished), only the others are solved, and a torn
/// last record (a kill during a write) is dropped and its point solved again.
#[test]
fn a_killed_sweep_resumes_without_solving_a_point_twice_or_losing_one() {
    let d = tmp("resume");
    std::fs::create_dir_all(&d).unwrap();
    // Points slow enough to kill the sweep between them (a 256 x 256 surface each).
    let scene = d.join("slow.toml");
    std::fs::write(
        &scene,
        "[geometry]\nkind = \"surface\"\nsize = [\"0.6 mm\", \"0.6 mm\"]\ncells = [256, 256]\n[geometry.profile]\nshape = \"sphere\"\nradius = \"10 mm\"\n[substrate]\nmaterial = \"steel\"\n[indenter]\nmodel = \"same\"\n[load]\nnormal = \"5 N\"\n[solver]\ntolerance = 1e-10\n",
    )
    .unwrap();
    let vary = ["--vary", "load.normal=1:10:16"];
    let whole = bin()
        .arg("sweep")
        .arg(&scene)
        .args(vary)
        .arg("--out")
        .arg(d.join("whole"))
        .output()
        .unwrap();
    assert!(whole.status.success(), "{}", String::from_utf8_lossy(&whole.stderr));

    let out = d.join("killed");
    let journal = out.join("sweep.partial.csv");
    let mut child =
        bin().arg("sweep").arg(&scene).args(vary).arg("--out").arg(&out).spawn().unwrap();
    // Kill it once two points are in the partial table (and before it ends).
    let rows = |p: &Path| {
        std::fs::read_to_string(p).map_or(0, |t| {
            t.lines().filter(|l| l.starts_with(|c: char| c.is_ascii_digit())).count()
        })
    };
    let t0 = std::time::Instant::now();
    while rows(&journal) < 2 {
        assert!(t0.elapsed().as_secs() < 120, "no rows in the partial table");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.kill().unwrap();
    let status = child.wait().unwrap();
    let done_before = rows(&journal);
    assert!(!out.join("sweep.csv").exists(), "a killed sweep left a table");
    if status.success() {
        // The sweep ended before the kill: nothing to resume; the test proves nothing.
        panic!("the sweep finished before it was killed ({done_before} rows); use slower points");
    }
    assert!(done_before < 16, "{done_before}");
    // A torn record, as a kill during a write leaves it.
    let mut f = std::fs::OpenOptions::new().append(true).open(&journal).unwrap();
    std::io::Write::write_all(&mut f, b"15,abc,16,9.").unwrap();
    drop(f);

    let o = bin()
        .arg("sweep")
        .arg(&scene)
        .args(vary)
        .arg("--out")
        .arg(&out)
        .arg("--resume")
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    let text = format!("{}{err}", String::from_utf8_lossy(&o.stdout));
    assert!(o.status.success(), "{text}");
    println!("{text}");
    let want = format!(
        "resumed: {done_before} points read from the partial table, {} solved now",
        16 - done_before
    );
    assert!(text.contains(&want), "{text}\nexpected: {want}");
    for f in ["sweep.csv", "sweep.parquet"] {
        assert_eq!(
            std::fs::read(out.join(f)).unwrap(),
            std::fs::read(d.join("whole").join(f)).unwrap(),
            "{f} differs from the uninterrupted sweep"
        );
    }
    assert!(!journal.exists(), "the partial table outlived the finished table");
    // --resume without a partial table, or with another sweep's, is refused (exit 2).
    let o = bin()
        .arg("sweep")
        .arg(&scene)
        .args(vary)
        .arg("--out")
        .arg(&out)
        .arg("--resume")
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    // ... and a refused --resume into a directory that does not exist leaves none behind.
    let fresh = d.join("never-made");
    let o = bin()
        .arg("sweep")
        .arg(&scene)
        .args(vary)
        .arg("--out")
        .arg(&fresh)
        .arg("--resume")
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(!fresh.exists(), "a refused --resume created {}", fresh.display());
    std::fs::write(&journal, "point,sweep\n").unwrap();
    let o = bin()
        .arg("sweep")
        .arg(&scene)
        .args(vary)
        .arg("--out")
        .arg(&out)
        .arg("--resume")
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", String::from_utf8_lossy(&o.stderr));
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn zipped_and_points_sweeps_take_the_keys_in_step() {
    let d = tmp("zip");
    let o = bin()
        .arg("sweep")
        .arg(scene())
        .args(["--zip", "--vary", "load.tangential=0 kN/m,10 kN/m", "--vary"])
        .args(["load.friction=0.2,0.3", "--out"])
        .arg(d.join("zip"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("2 points: 2 ok"));
    // The same points from a table.
    let points = d.join("points.csv");
    std::fs::write(
        &points,
        "# two points\nload.tangential,load.friction\n0 kN/m,0.2\n10 kN/m,0.3\n",
    )
    .unwrap();
    let o = bin()
        .arg("sweep")
        .arg(scene())
        .arg("--points")
        .arg(&points)
        .arg("--out")
        .arg(d.join("points"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let a = std::fs::read_to_string(d.join("zip/sweep.csv")).unwrap();
    let b = std::fs::read_to_string(d.join("points/sweep.csv")).unwrap();
    assert_eq!(a, b);
    assert_eq!(a.lines().count(), 3, "{a}");
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn zipped_lists_of_unequal_length_and_bad_points_tables_exit_2() {
    let d = tmp("zip-bad");
    let o = bin()
        .arg("sweep")
        .arg(scene())
        .args(["--zip", "--vary", "load.tangential=0 kN/m,10 kN/m", "--vary"])
        .args(["load.friction=0.2,0.3,0.4", "--out"])
        .arg(d.join("out"))
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("load.friction") && err.contains("3 values"), "{err}");
    assert!(!d.join("out").exists());
    std::fs::create_dir_all(&d).unwrap();
    let points = d.join("points.csv");
    std::fs::write(&points, "load.tangential,load.friction\n0 kN/m,0.2\n10 kN/m\n").unwrap();
    let o = bin()
        .arg("sweep")
        .arg(scene())
        .arg("--points")
        .arg(&points)
        .arg("--out")
        .arg(d.join("out"))
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("points.csv:3: 1 values for 2 keys") && err.contains("hint:"), "{err}");
    assert!(!d.join("out").exists());
    let _ = std::fs::remove_dir_all(&d);
}
