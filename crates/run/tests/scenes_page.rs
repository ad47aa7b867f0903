//! `docs/scenes.md` is generated from `scenes/` by the planner ([`scenes_page`]) and must be
//! current: this test regenerates it and compares. With `STICKSLIP_UPDATE_DOCS=1` it writes
//! the page instead.

mod common;
use common::scenes_dir;
use std::path::PathBuf;
use stickslip_run::scenes_page;

#[test]
fn docs_scenes_md_is_current_and_deterministic() {
    let page = scenes_page(&scenes_dir(), "../scenes").unwrap_or_else(|e| panic!("{e}"));
    let again = scenes_page(&scenes_dir(), "../scenes").unwrap();
    assert_eq!(page, again, "the page is not deterministic");
    let n = std::fs::read_dir(scenes_dir())
        .unwrap()
        .filter_map(Result::ok)
        .filter(|e| e.file_name().to_string_lossy().ends_with(".toml"))
        .count();
    for e in std::fs::read_dir(scenes_dir()).unwrap().filter_map(Result::ok) {
        let name = e.file_name().to_string_lossy().into_owned();
        if let Some(stem) = name.strip_suffix(".toml") {
            assert!(page.contains(&format!("[`{stem}`]")), "{stem} missing from the page");
        }
    }
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../docs/scenes.md");
    if std::env::var("STICKSLIP_UPDATE_DOCS").is_ok_and(|v| v == "1") {
        std::fs::write(&path, &page).unwrap();
        println!("wrote {} ({n} scenes)", path.display());
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    println!("{n} scenes, {} lines", page.lines().count());
    assert!(
        committed == page,
        "docs/scenes.md is not current: run STICKSLIP_UPDATE_DOCS=1 cargo test --release -p stickslip-run --test scenes_page"
    );
}
