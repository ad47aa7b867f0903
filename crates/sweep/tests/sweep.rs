//! Sweeps: shards merge to the full sweep exactly (also through the CSV files), a failing
//! point is a row with its reason, bad specifications and mismatched shards are refused, and
//! a row holds the numbers of a direct run of the same scene.

use stickslip_run::{run, RunOptions};
use stickslip_scene::{ErrorKind, Scene};
use stickslip_sweep::{merge, Cell, Shard, Sweep, Table, Vary};

const SCENE: &str = include_str!("../../../scenes/hertz_cylinder_cattaneo.toml");

fn sweep() -> Sweep {
    let vary = [
        Vary::parse("load.friction=0.2,0.3").unwrap(),
        Vary::parse("load.tangential=0 kN/m:40 kN/m:5").unwrap(),
    ];
    Sweep::new(SCENE, Some("hertz.toml".into()), &vary).unwrap()
}

fn cell<'a>(t: &'a Table, row: usize, col: &str) -> &'a Cell {
    &t.rows[row][t.column(col).unwrap()]
}

#[test]
fn shards_merge_to_the_full_sweep() {
    let s = sweep();
    assert_eq!(s.len(), 10);
    let full = s.run(Shard::ALL, 600.0, |_| {});
    assert_eq!(full.rows.len(), 10);
    let shards: Vec<Table> =
        (1..=3).map(|i| s.run(Shard { index: i, count: 3 }, 600.0, |_| {})).collect();
    assert_eq!(shards.iter().map(|t| t.rows.len()).collect::<Vec<_>>(), [4, 3, 3]);
    let names: Vec<String> = (1..=3).map(|i| format!("shard {i}")).collect();
    let merged = merge(shards.clone(), &names).unwrap();
    assert_eq!(merged, full);

    // Through the CSV files, in another order: the same text.
    let dir = std::env::temp_dir().join(format!("stickslip-sweep-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut read = Vec::new();
    for (i, t) in shards.iter().enumerate().rev() {
        let p = dir.join(format!("shard{i}.csv"));
        std::fs::write(&p, t.to_csv().unwrap()).unwrap();
        read.push(Table::read_csv(&p).unwrap());
    }
    let merged = merge(read, &names).unwrap();
    assert_eq!(merged.to_csv().unwrap(), full.to_csv().unwrap());
    assert_eq!(merged, full);
    full.write_parquet(&dir.join("full.parquet")).unwrap();
    let bytes = std::fs::read(dir.join("full.parquet")).unwrap();
    assert_eq!(&bytes[..4], b"PAR1");
    assert_eq!(&bytes[bytes.len() - 4..], b"PAR1");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_row_holds_the_numbers_of_a_direct_run() {
    let s = sweep();
    // Point 7: friction 0.3 (second value), tangential 20 kN/m (third value).
    let row = s.run_point(7, 600.0);
    let t = Table { columns: s.columns(), rows: vec![row] };
    assert_eq!(cell(&t, 0, "load.friction"), &Cell::Float(Some(0.3)));
    assert_eq!(cell(&t, 0, "load.tangential"), &Cell::Text(Some("20 kN/m".into())));
    assert_eq!(cell(&t, 0, "status"), &Cell::Text(Some("ok".into())));
    let text = SCENE.replace("tangential = \"15 kN/m\"", "tangential = \"20 kN/m\"");
    assert_ne!(text, SCENE);
    let out = run(&Scene::from_toml_str(&text, None).unwrap(), &RunOptions::default()).unwrap();
    assert_eq!(cell(&t, 0, "tangential"), &Cell::Float(Some(out.forces.tangential)));
    assert_eq!(cell(&t, 0, "a"), &Cell::Float(Some(out.contact.a)));
    assert_eq!(cell(&t, 0, "p0"), &Cell::Float(Some(out.contact.p0)));
    assert_eq!(out.forces.tangential, 20e3);
    // Cattaneo: the stick zone is c = a sqrt(1 - Q/(fP)) wide, centred.
    let c_over_a = (1.0f64 - 20e3 / (0.3 * 100e3)).sqrt();
    let Cell::Float(Some(stick)) = cell(&t, 0, "stick_fraction") else {
        panic!("no stick fraction")
    };
    assert!((stick - c_over_a).abs() < 1e-9, "{stick} vs {c_over_a}");
}

#[test]
fn a_failing_point_is_a_row_with_its_reason() {
    let s = sweep();
    // Point 4: friction 0.2, tangential 40 kN/m > f P = 20 kN/m.
    let t = Table { columns: s.columns(), rows: vec![s.run_point(4, 600.0)] };
    assert_eq!(cell(&t, 0, "status"), &Cell::Text(Some("failed".into())));
    assert_eq!(cell(&t, 0, "exit_code"), &Cell::Int(i64::from(ErrorKind::Impossible.exit_code())));
    assert_eq!(cell(&t, 0, "error_kind"), &Cell::Text(Some("impossible".into())));
    let Cell::Text(Some(reason)) = cell(&t, 0, "reason") else { panic!("no reason") };
    assert!(reason.starts_with("hertz.toml:"), "{reason}");
    assert!(reason.contains("load.tangential"), "{reason}");
    assert!(reason.contains("hint:"), "{reason}");
    assert_eq!(cell(&t, 0, "tangential"), &Cell::Float(None));
    // The CSV keeps the failure and an empty cell for results.
    let csv = t.to_csv().unwrap();
    assert!(csv.contains(",failed,2,impossible,\"hertz.toml:"), "{csv}");
}

#[test]
fn bad_sweeps_are_refused_with_the_key() {
    let bad = |spec: &str| {
        Sweep::new(SCENE, Some("hertz.toml".into()), &[Vary::parse(spec).unwrap()]).unwrap_err()
    };
    let e = bad("load.frction=0.1,0.2");
    assert_eq!(e.kind, ErrorKind::Schema);
    assert!(e.to_string().contains("frction"), "{e}");
    assert!(e.position.is_some(), "{e}");
    let e = bad("load.friction.x=1");
    assert_eq!(e.key.as_deref(), Some("load.friction.x"));
    assert!(e.message.contains("holds a value"), "{e}");
    let e = bad("load=1");
    assert!(e.message.contains("is a table"), "{e}");
    let twice =
        [Vary::parse("load.friction=0.1").unwrap(), Vary::parse("load.friction=0.2").unwrap()];
    let e = Sweep::new(SCENE, None, &twice).unwrap_err();
    assert!(e.message.contains("varied twice"), "{e}");
    for bad in ["0/2", "3/2", "1", "a/b", "1/0"] {
        let e = Shard::parse(bad).unwrap_err();
        assert!(e.contains("I/N"), "{e}");
    }
}

#[test]
fn the_sweep_may_fix_what_the_scene_lacks_or_refuses() {
    // The base asks for T = 50 kN/m > f P = 30 kN/m and is refused; the sweep replaces
    // the load, and each point is checked on its own.
    let base = SCENE.replace("tangential = \"15 kN/m\"", "tangential = \"50 kN/m\"");
    assert_eq!(
        Scene::from_toml_str(&base, None).unwrap_err().kind,
        ErrorKind::Impossible,
        "the base scene is refused (T > f P)"
    );
    let vary = [Vary::parse("load.tangential=10 kN/m,20 kN/m").unwrap()];
    let t = Sweep::new(&base, None, &vary).unwrap().run(Shard::ALL, 600.0, |_| {});
    for r in 0..2 {
        assert_eq!(cell(&t, r, "status"), &Cell::Text(Some("ok".into())));
    }
    assert_eq!(cell(&t, 1, "tangential"), &Cell::Float(Some(20e3)));
    // A key added by the sweep: [outputs] has no `plots` in this text.
    let no_outputs = &SCENE[..SCENE.find("[outputs]").unwrap()];
    let vary = [Vary::parse("outputs.plots=false").unwrap()];
    let s = Sweep::new(no_outputs, None, &vary).unwrap();
    assert!(
        s.point_text(0).unwrap().contains("[outputs]\nplots = false"),
        "{}",
        s.point_text(0).unwrap()
    );
    // Not TOML: the reader's located syntax error.
    let e = Sweep::new("[load\n", Some("x.toml".into()), &vary).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Syntax);
    assert!(e.position.is_some(), "{e}");
}

#[test]
fn mismatched_or_incomplete_shards_are_refused() {
    let s = sweep();
    let a = s.run(Shard { index: 1, count: 2 }, 600.0, |_| {});
    let b = s.run(Shard { index: 2, count: 2 }, 600.0, |_| {});
    let names = ["a.csv".to_string(), "b.csv".to_string()];
    let e = merge(vec![a.clone()], &names[..1]).unwrap_err();
    assert!(e.0.contains("points missing: 1, 3, 5, 7, 9"), "{e}");
    let e = merge(vec![a.clone(), a.clone()], &names).unwrap_err();
    assert!(e.0.contains("more than once: 0, 2, 4, 6, 8"), "{e}");
    let other = Sweep::new(
        SCENE,
        None,
        &[
            Vary::parse("load.friction=0.2,0.3").unwrap(),
            Vary::parse("load.tangential=0 kN/m:40 kN/m:6").unwrap(),
        ],
    )
    .unwrap();
    let c = other.run(Shard { index: 2, count: 2 }, 600.0, |_| {});
    let e = merge(vec![a.clone(), c], &names).unwrap_err();
    assert!(e.0.contains("scene or the --vary differ"), "{e}");
    assert_eq!(merge(vec![b.clone(), a.clone()], &names).unwrap().rows.len(), 10);
    // A shard without points (12 shards of 10 points) merges: it adds nothing.
    let empty = s.run(Shard { index: 12, count: 12 }, 600.0, |_| {});
    assert!(empty.rows.is_empty());
    let three = ["a".to_string(), "empty".to_string(), "b".to_string()];
    assert_eq!(merge(vec![a, empty.clone(), b], &three).unwrap(), s.run(Shard::ALL, 600.0, |_| {}));
    let e = merge(vec![empty], &names[..1]).unwrap_err();
    assert!(e.0.contains("no rows"), "{e}");
}

#[test]
fn column_kinds_survive_the_csv() {
    use stickslip_sweep::Kind;
    let vary = [
        Vary::parse("solver.grid=16,32").unwrap(),
        Vary::parse("load.friction=1,0.5").unwrap(),
        Vary::parse("load.normal=100 kN/m,200 kN/m").unwrap(),
    ];
    let s = Sweep::new(SCENE, None, &vary).unwrap();
    let kinds: Vec<Kind> = s.columns()[3..6].iter().map(|c| c.1).collect();
    assert_eq!(kinds, [Kind::Int, Kind::Float, Kind::Text]);
    let t = s.run(Shard::ALL, 600.0, |_| {});
    assert_eq!(cell(&t, 0, "solver.grid"), &Cell::Int(16));
    assert_eq!(cell(&t, 0, "load.friction"), &Cell::Float(Some(1.0)));
    let p = std::env::temp_dir().join(format!("stickslip-kinds-{}.csv", std::process::id()));
    std::fs::write(&p, t.to_csv().unwrap()).unwrap();
    let back = Table::read_csv(&p).unwrap();
    std::fs::remove_file(&p).unwrap();
    assert_eq!(back, t);
}

/// Points run in parallel (issue 30, item 5) give the serial table, row for row and bit for
/// bit: a surface (the nested normal solver, then the fast partial-slip solver) over loads
/// and friction coefficients, with one failing point among them, on two and three threads.
#[test]
fn parallel_points_give_the_serial_table() {
    let scene = include_str!("../../../scenes/sphere_as_surface.toml");
    let vary = [
        Vary::parse("load.normal=5 N:20 N:3").unwrap(),
        Vary::parse("load.friction=0.05,0.2").unwrap(),
    ];
    let s = Sweep::new(scene, Some("sphere_as_surface.toml".into()), &vary).unwrap();
    let serial = s.run_serial(Shard::ALL, 600.0, |_| {});
    assert_eq!(serial.rows.len(), 6);
    for threads in [2, 3] {
        let done = std::sync::atomic::AtomicUsize::new(0);
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        let parallel = pool.install(|| {
            s.run(Shard::ALL, 600.0, |_| {
                done.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            })
        });
        assert_eq!(done.into_inner(), 6, "progress once per point");
        assert_eq!(parallel.columns, serial.columns);
        for (a, b) in parallel.rows.iter().zip(&serial.rows) {
            assert_eq!(a, b, "{threads} threads");
        }
    }
    // One point (T = 1 N > f P at f = 0.05, P = 5 N) fails and is a row with its reason.
    let status = serial.column("status").unwrap();
    assert!(serial.rows.iter().any(|r| r[status] == Cell::Text(Some("failed".into()))));
    // `--jobs`: one at a time, two, and more than the points give the same table.
    for jobs in [1, 2, 9] {
        let t = s.clone().with_jobs(jobs).run(Shard::ALL, 600.0, |_| {});
        assert_eq!(t, serial, "jobs {jobs}");
    }
}

/// A journal written by parallel points holds its rows in the order they finished; resuming
/// from one with rows out of point order and a torn last record (a kill during a write)
/// solves exactly the points it lacks and gives the serial table (issue 30, item 5).
#[test]
fn resume_from_an_out_of_order_torn_journal_gives_the_serial_table() {
    let s = sweep().with_jobs(2);
    let serial = s.run_serial(Shard::ALL, 600.0, |_| {});
    let dir = std::env::temp_dir().join(format!("stickslip-sweep-resume-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let journal = stickslip_sweep::journal_path(&dir, "sweep");
    // A whole journaled run: its table is the serial one; the journal holds every point.
    let whole = s.run_journaled(Shard::ALL, 600.0, &journal, false, |_| {}).unwrap();
    assert_eq!(whole.table, serial);
    assert_eq!((whole.resumed, whole.solved), (0, 10));
    // Each record by its point, as the bytes it spans (a failed point's reason holds
    // line breaks inside quotes).
    let text = std::fs::read_to_string(&journal).unwrap();
    let mut r = csv::ReaderBuilder::new().has_headers(false).from_reader(text.as_bytes());
    let mut spans = Vec::new();
    let mut rec = csv::StringRecord::new();
    let mut start = 0;
    while r.read_record(&mut rec).unwrap() {
        let end = r.position().byte() as usize;
        spans.push((rec[0].parse::<usize>().ok(), &text[start..end]));
        start = end;
    }
    assert_eq!(spans.len(), 11, "the header and one record per point");
    let pick = |i: usize| spans.iter().find(|(p, _)| *p == Some(i)).unwrap().1;
    // Keep points 7, 2, 9, 0 in that order, then half of point 4's record.
    let mut partial = spans[0].1.to_string();
    for i in [7, 2, 9, 0] {
        partial += pick(i);
    }
    let torn = pick(4);
    partial += &torn[..torn.len() / 2];
    std::fs::write(&journal, &partial).unwrap();
    let solved = std::sync::Mutex::new(Vec::new());
    let again = s
        .run_journaled(Shard::ALL, 600.0, &journal, true, |i| solved.lock().unwrap().push(i))
        .unwrap();
    let mut solved = solved.into_inner().unwrap();
    solved.sort_unstable();
    assert_eq!(solved, [1, 3, 4, 5, 6, 8], "the points the journal lacks, once each");
    assert_eq!((again.resumed, again.solved), (4, 6));
    assert_eq!(again.table, serial);
    // The journal is whole again: the torn record was cut, the new ones appended.
    let text = std::fs::read_to_string(&journal).unwrap();
    let mut r = csv::ReaderBuilder::new().has_headers(false).from_reader(text.as_bytes());
    assert_eq!(r.records().map(Result::unwrap).count(), 11);
    assert!(text.ends_with('\n'));
    std::fs::remove_dir_all(&dir).unwrap();
}
