//! Output directories that cannot be written: each error is an I/O error naming the
//! directory, and no file is left behind; a good directory receives every file.

use stickslip_report::write_outputs;
use stickslip_run::{run, RunOptions};
use stickslip_scene::{ErrorKind, Scene};

const SPHERE: &str = r#"[geometry]
kind = "sphere"
radius = "1 in"
[substrate]
model = "homogeneous"
e = "30e6 psi"
nu = 0.3
[indenter]
model = "same"
[load]
normal = "2160 lbf"
friction = 0.1
"#;

fn leftovers(dir: &std::path::Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .map(|r| {
            r.filter_map(|e| e.ok()).map(|e| e.file_name().to_string_lossy().into_owned()).collect()
        })
        .unwrap_or_default()
}

#[cfg(unix)]
#[test]
fn unwritable_outputs_leave_nothing_behind() {
    let out = run(&Scene::from_toml_str(SPHERE, None).unwrap(), &RunOptions::default()).unwrap();
    let base = std::env::temp_dir().join(format!("stickslip-bad-out-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&base);
    std::fs::create_dir_all(&base).unwrap();
    // 1. the parent is a regular file
    let file = base.join("a_file");
    std::fs::write(&file, "x").unwrap();
    let e = write_outputs(&out, &file.join("out"), true).unwrap_err();
    println!("{e}");
    assert_eq!(e.kind, ErrorKind::Io);
    assert!(e.to_string().contains("a_file"));
    // 2. the target is a file
    let e = write_outputs(&out, &file, false).unwrap_err();
    println!("{e}");
    assert_eq!(e.kind, ErrorKind::Io);
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "x");
    // 3. a read-only parent directory (not meaningful as root, who may write anywhere)
    let ro = base.join("ro");
    std::fs::create_dir(&ro).unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o555)).unwrap();
    let probe_ok = std::fs::write(ro.join("probe"), "").is_ok();
    if probe_ok {
        println!("running with permission to write read-only directories (root): case 3 skipped");
        let _ = std::fs::remove_file(ro.join("probe"));
    } else {
        let e = write_outputs(&out, &ro.join("out"), true).unwrap_err();
        println!("{e}");
        assert_eq!(e.kind, ErrorKind::Io);
        assert!(leftovers(&ro).is_empty(), "{:?}", leftovers(&ro));
    }
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o755)).unwrap();
    // Nothing but the file we made and the ro directory remains.
    let mut left = leftovers(&base);
    left.sort();
    assert_eq!(left, vec!["a_file".to_string(), "ro".to_string()]);
    // 4. a good directory receives every file, and nothing temporary stays beside it
    let good = base.join("good");
    let w = write_outputs(&out, &good, true).unwrap();
    println!("wrote {:?}", w.files);
    assert!(w.files.iter().all(|f| f.exists()));
    assert!(leftovers(&base).iter().all(|n| !n.contains("tmp")));
    // writing again into the existing directory replaces the files
    write_outputs(&out, &good, true).unwrap();
    assert!(leftovers(&base).iter().all(|n| !n.contains("tmp")));
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(good.join("result.json")).unwrap()).unwrap();
    for k in [
        "title",
        "effects",
        "contact",
        "zones",
        "forces",
        "rigid_displacement",
        "surface",
        "field",
        "solver",
    ] {
        assert!(json.get(k).is_some(), "result.json lacks {k}");
    }
    let _ = std::fs::remove_dir_all(&base);
}
