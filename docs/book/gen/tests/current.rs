//! The committed generated pages of the book (`docs/book/src/generated/*.md`) must be exactly
//! what the generator produces now: CI fails when a chapter's numbers are stale. Regenerate
//! with `cargo run --release -p stickslip-docs`.

use std::collections::BTreeSet;
use std::time::Instant;

#[test]
fn generated_pages_are_current() {
    let t0 = Instant::now();
    let pages = stickslip_docs::generate().expect("generation (a check may have failed)");
    println!("generated {} pages in {:.2} s", pages.len(), t0.elapsed().as_secs_f64());

    // Regenerate into a temporary directory through the same writer the binary uses.
    let tmp = std::env::temp_dir().join(format!("stickslip-docs-{}", std::process::id()));
    let written = stickslip_docs::write_all(&tmp).expect("write into a temporary directory");
    assert_eq!(written.len(), pages.len());

    let committed_dir = stickslip_docs::default_dir();
    let mut stale = Vec::new();
    for p in &pages {
        let fresh = std::fs::read(tmp.join(p.name)).expect("read regenerated page");
        assert_eq!(fresh, p.text.as_bytes(), "{}: generation is not deterministic", p.name);
        match std::fs::read(committed_dir.join(p.name)) {
            Ok(old) if old == fresh => {}
            Ok(_) => stale.push(format!("{} differs", p.name)),
            Err(e) => stale.push(format!("{} missing ({e})", p.name)),
        }
    }
    // No committed page that the generator no longer writes.
    let expected: BTreeSet<&str> = pages.iter().map(|p| p.name).collect();
    if let Ok(rd) = std::fs::read_dir(&committed_dir) {
        for e in rd.flatten() {
            let name = e.file_name().to_string_lossy().into_owned();
            if name.ends_with(".md") && !expected.contains(name.as_str()) {
                stale.push(format!("{name} is not generated any more"));
            }
        }
    }
    let _ = std::fs::remove_dir_all(&tmp);
    assert!(
        stale.is_empty(),
        "generated book pages are stale: {stale:?}; run `cargo run --release -p stickslip-docs`"
    );
    println!("all {} committed pages are current", pages.len());
}
