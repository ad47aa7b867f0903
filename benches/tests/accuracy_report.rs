//! CI check of the accuracy-versus-time report: quick mode runs, every measured error meets
//! its claim, the report is well-formed, and its errors agree with the committed full report
//! (`docs/accuracy.md`) where the two share settings.

use std::collections::BTreeMap;
use stickslip_benches::accuracy::{markdown, parse_errors, run, Mode};

/// Tolerances, each with its reason.
mod tol {
    /// Quick and full mode run the same code on the same inputs for a shared setting, so the
    /// errors are normally identical. A factor of 10 either way is allowed for rounding-level
    /// changes in the physics crates; a larger change means `docs/accuracy.md` is stale
    /// (regenerate it with `cargo run --release -p stickslip-benches --bin accuracy`).
    pub const SHARED_FACTOR: f64 = 10.0;
    /// Errors below this are rounding noise and are not compared by ratio.
    pub const NOISE: f64 = 1e-13;
}

#[test]
fn quick_report_meets_claims_and_matches_committed_full_report() {
    let report = run(Mode::Quick);
    println!("quick accuracy report: {:.2} s", report.seconds);
    // well-formed: every method has settings with finite errors and positive times, unique
    // labels, and a reading
    assert!(report.methods.len() >= 8);
    for m in &report.methods {
        assert!(!m.settings.is_empty(), "{}: no settings", m.slug);
        assert!(!m.reading.is_empty() && m.reading != "no data", "{}: no reading", m.slug);
        let mut labels: Vec<&str> = m.settings.iter().map(|s| s.label.as_str()).collect();
        labels.sort_unstable();
        labels.dedup();
        assert_eq!(labels.len(), m.settings.len(), "{}: duplicate labels", m.slug);
        for s in &m.settings {
            assert!(
                s.error.is_finite() && s.error >= 0.0,
                "{}/{}: error {}",
                m.slug,
                s.label,
                s.error
            );
            assert!(s.seconds > 0.0 && s.seconds.is_finite(), "{}/{}: time", m.slug, s.label);
            println!(
                "  {:<16} {:<10} error {:.3e} claim {:>9} time {:.3e} s  {}",
                m.slug,
                s.label,
                s.error,
                s.claim.map_or("-".into(), |c| format!("{c:.1e}")),
                s.seconds,
                s.work
            );
        }
        println!("  {:<16} reading: {}", m.slug, m.reading);
    }
    let bad = report.violations();
    assert!(bad.is_empty(), "claims not met: {bad:#?}");

    // the markdown round-trips its error column
    let md = markdown(&report);
    let parsed = parse_errors(&md);
    let n: usize = report.methods.iter().map(|m| m.settings.len()).sum();
    assert_eq!(parsed.len(), n, "markdown rows");
    for (slug, label, e) in &parsed {
        let m = report.methods.iter().find(|m| m.slug == slug).expect("slug");
        let s = m.settings.iter().find(|s| &s.label == label).expect("label");
        assert!(
            ((e - s.error) / s.error.max(1e-300)).abs() < 1e-3 || (*e == 0.0 && s.error == 0.0)
        );
    }

    // compare with the committed full report where settings are shared
    let doc_path = concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/accuracy.md");
    let doc = std::fs::read_to_string(doc_path).expect("docs/accuracy.md is committed");
    assert!(doc.contains("mode **full**"), "docs/accuracy.md must be a full-mode report");
    let full: BTreeMap<(String, String), f64> =
        parse_errors(&doc).into_iter().map(|(s, l, e)| ((s, l), e)).collect();
    let mut shared = 0;
    let mut worst: f64 = 1.0;
    for m in &report.methods {
        assert!(
            doc.contains(&format!("## {}:", m.slug)),
            "{} missing from docs/accuracy.md",
            m.slug
        );
        let svg = format!("{}/../docs/accuracy/{}.svg", env!("CARGO_MANIFEST_DIR"), m.slug);
        assert!(std::path::Path::new(&svg).exists(), "{svg} missing");
        for s in &m.settings {
            let Some(&e_full) = full.get(&(m.slug.to_string(), s.label.clone())) else { continue };
            shared += 1;
            if s.error <= tol::NOISE && e_full <= tol::NOISE {
                continue;
            }
            let ratio = (s.error.max(tol::NOISE) / e_full.max(tol::NOISE))
                .max(e_full.max(tol::NOISE) / s.error.max(tol::NOISE));
            worst = worst.max(ratio);
            assert!(
                ratio <= tol::SHARED_FACTOR,
                "{}/{}: quick {:e} vs committed full {:e}: regenerate docs/accuracy.md",
                m.slug,
                s.label,
                s.error,
                e_full
            );
        }
    }
    println!("{shared} settings shared with docs/accuracy.md; worst error ratio {worst:.3}");
    assert!(shared >= 15, "only {shared} shared settings");
}
