//! One insta snapshot per VERIFICATION.md id (published, computed and relative difference side
//! by side, our number formatting), the assertions FORMULAS.md makes true, and the check that
//! the committed pages in `docs/verification/` are what the generator writes now.
//!
//! All tests run in one process, so each check is computed once (see
//! `stickslip_verification::check`) and shared with the page test.

mod common;
use common::tol;
use stickslip_verification::{check, record::divergences, Check, Reference, Status};

/// Snapshot a check, print it, and assert what holds for every check: every divergence is
/// attributed, every claim on which FORMULAS.md speaks comes out as FORMULAS.md says, and
/// no computed value is NaN unless it is the point of the row (a non-finite published
/// formula).
fn snap(id: &str, name: &str) -> &'static Check {
    let t0 = std::time::Instant::now();
    let c = check(id).unwrap_or_else(|e| panic!("{id}: {e}"));
    let text = c.render();
    println!("{text}(built in {:.3} s)", t0.elapsed().as_secs_f64());
    insta::assert_snapshot!(name, text);
    for d in divergences(c) {
        assert!(d.cause.is_some(), "{id}: unattributed divergence in {:?}", d.quantity);
    }
    for cl in &c.claims {
        if let Some(e) = cl.expected {
            assert_eq!(cl.holds, e, "{id}: claim {:?} ({})", cl.claim, cl.deciding);
        }
    }
    for r in &c.rows {
        if r.computed.is_nan() {
            assert!(r.quantity.contains("as printed"), "{id}: NaN in {:?}", r.quantity);
        }
        // Closed-form references without a cause must agree.
        if matches!(r.reference, Reference::Closed { .. }) && r.cause.is_none() {
            assert_eq!(
                r.status(),
                Status::Agrees,
                "{id}: {:?} {} vs {:?}",
                r.quantity,
                r.computed,
                r.reference
            );
        }
    }
    c
}

fn row<'a>(c: &'a Check, starts: &str) -> &'a stickslip_verification::Row {
    c.rows
        .iter()
        .find(|r| r.quantity.starts_with(starts))
        .unwrap_or_else(|| panic!("no row {starts:?}"))
}

#[test]
fn seed000_t1() {
    let c = snap("T1", "seed000_T1");
    // FORMULAS.md A1/A4 values.
    for (q, want) in [
        ("I_k (eq 12)", 0.760992),
        ("J_k (eq 14)", 0.709859),
        ("P implied by a: corrected", 986.39),
    ] {
        let got = row(c, q).computed;
        assert!((got / want - 1.0).abs() < tol::FORMULAS_DIGITS * 2.0, "{q}: {got} vs {want}");
    }
    assert_eq!(row(c, "I_k, eq 12 with every Gamma = 1").status(), Status::Diverges);
    assert_eq!(row(c, "beta").status(), Status::Agrees);
    assert_eq!(row(c, "h = ").status(), Status::Agrees);
}

#[test]
fn seed000_f4() {
    snap("F4", "seed000_F4");
}

#[test]
fn seed000_f5() {
    snap("F5", "seed000_F5");
}

#[test]
fn seed000_f6() {
    snap("F6", "seed000_F6");
}

#[test]
fn seed000_f7_t2() {
    snap("F7/T2", "seed000_F7_T2");
}

#[test]
fn seed000_f8() {
    snap("F8", "seed000_F8");
}

#[test]
fn seed000_f9() {
    snap("F9", "seed000_F9");
}

#[test]
fn seed000_f10_f11_t3() {
    let c = snap("F10/F11/T3", "seed000_F10_F11_T3");
    // G&P column reproduced by eq 32 (FORMULAS.md A5); the paper's column is not, and eq 29
    // as printed is not finite.
    for r in &c.rows {
        if r.quantity.contains("eq 32 with") {
            assert_eq!(r.status(), Status::Agrees, "{}", r.quantity);
        }
        if r.quantity.contains("eq 29 as printed") {
            assert!(!r.computed.is_finite(), "{}", r.quantity);
        }
        if r.quantity.contains("from q = mu p") {
            assert!(r.relative().abs() < tol::IDENTITY, "{}", r.quantity);
        }
    }
}

#[test]
fn seed000_two_term() {
    let c = snap("TT", "seed000_TT");
    // The as-published forms are far from full integration everywhere (FORMULAS.md A2).
    assert!(row(c, "smallest median divergence").computed > 0.1);
}

#[test]
fn seed001_g_w() {
    snap("G-W", "seed001_G-W");
}

#[test]
fn seed001_g_e() {
    snap("G-E", "seed001_G-E");
}

#[test]
fn seed001_g_l() {
    snap("G-L", "seed001_G-L");
}

#[test]
fn seed001_g_s() {
    let c = snap("G-S", "seed001_G-S");
    for r in c.rows.iter().filter(|r| r.quantity.ends_with("(<= 1)")) {
        assert!(r.computed.is_finite() && r.computed <= 1.0 + 1e-12, "{}", r.quantity);
    }
}

#[test]
fn seed002_f3_2() {
    snap("F3.2", "seed002_F3.2");
}

#[test]
fn seed002_f3_3_f3_4_eq3_5() {
    snap("F3.3/F3.4/Eq3.5", "seed002_F3.3_F3.4_Eq3.5");
}

#[test]
fn seed002_ex1() {
    let c = snap("Ex1/F3.6", "seed002_Ex1_F3.6");
    let dev = row(c, "deviation below Mindlin, exact rectangle").computed / 100.0;
    println!("Example 1 exact-rectangle LP vs Mindlin: -{:.4} %", dev * 100.0);
    assert!(dev.abs() < tol::EX1_COARSE);
    assert_eq!(row(c, "Mindlin per-body delta").status(), Status::Agrees);
}

#[test]
fn seed002_ex2() {
    let c = snap("Ex2/F3.7", "seed002_Ex2_F3.7");
    assert_eq!(row(c, "ratio rubber/steel").status(), Status::Agrees);
}

#[test]
fn seed002_ex3() {
    let c = snap("Ex3/T3.1/F3.8-F3.11", "seed002_Ex3_T3.1_F3.8-F3.11");
    for r in c.rows.iter().filter(|r| r.quantity.contains("elements")) {
        assert_eq!(r.status(), Status::Agrees, "{}", r.quantity);
    }
}

#[test]
fn seed002_ex4() {
    let c = snap("Ex4/F3.12-F3.15", "seed002_Ex4_F3.12-F3.15");
    assert_eq!(row(c, "gross slip load").status(), Status::Agrees);
}

#[test]
fn seed002_ex5() {
    let c = snap("Ex5/F3.16-F3.21", "seed002_Ex5_F3.16-F3.21");
    assert_eq!(row(c, "gross slip of the whole contact").status(), Status::Agrees);
}

#[test]
fn seed002_twist() {
    let c = snap("Tw", "seed002_Tw");
    for r in c.rows.iter().filter(|r| r.quantity.contains("rotation")) {
        assert!(r.relative().abs() < tol::TWIST, "{}: {}", r.quantity, r.relative());
    }
}

/// Every VERIFICATION.md id has a test above.
#[test]
fn every_id_is_tested() {
    let src = include_str!("verification.rs");
    for (id, _) in stickslip_verification::IDS {
        assert!(src.contains(&format!("snap(\"{id}\"")), "no snapshot test for {id}");
    }
}

/// The committed pages are what the generator writes now (CI fails when they are stale).
#[test]
fn committed_pages_are_current() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/verification");
    let tmp = std::env::temp_dir().join(format!("stickslip-verification-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&tmp);
    let files = stickslip_verification::generate(&tmp).expect("generate");
    let mut committed: Vec<String> = std::fs::read_dir(&root)
        .expect("docs/verification exists")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    committed.sort();
    let mut fresh: Vec<String> =
        files.iter().map(|f| f.file_name().unwrap().to_string_lossy().into_owned()).collect();
    fresh.sort();
    assert_eq!(committed, fresh, "file list of docs/verification is stale: run `cargo run --release -p stickslip-verification --bin reproduce`");
    for f in &files {
        let name = f.file_name().unwrap();
        let want = std::fs::read(root.join(name)).expect("committed page");
        let got = std::fs::read(f).expect("generated page");
        assert!(want == got, "docs/verification/{} is stale: run `cargo run --release -p stickslip-verification --bin reproduce`", name.to_string_lossy());
    }
    println!("{} pages and plots identical to the committed ones", files.len());
    let _ = std::fs::remove_dir_all(&tmp);
}
