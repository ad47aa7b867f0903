//! Property: mutating a valid scene file (scenes/*.toml) — deleting, duplicating or
//! truncating lines, replacing a value with a random string, number, boolean, array or
//! table — never panics, and every refusal has a key or a position, a hint, no serde or
//! Rust type name, and exit code 2 (refused before solving).
//!
//! 256 cases by default; more with `PROPTEST_CASES=N`.

// SceneError carries file, position, key and hint; tests return it as is.
#![allow(clippy::result_large_err)]

use proptest::prelude::*;
use stickslip_run::Plan;
use stickslip_scene::Scene;

const INTERNAL: &[&str] =
    &["Qty", "Raw", "untagged", "struct", "f64", "i64", "enum", "variant", "Spanned", "serde"];

fn scenes() -> Vec<(String, String)> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes");
    let mut v: Vec<(String, String)> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .map(|p| {
            // The whole path, so that files a scene names (a load path, heights) resolve.
            (p.to_string_lossy().into_owned(), std::fs::read_to_string(&p).unwrap())
        })
        .collect();
    v.sort();
    assert!(!v.is_empty());
    v
}

/// A TOML value of any kind (strings from a charset that cannot spell an internal name).
fn value() -> impl Strategy<Value = String> {
    let leaf = prop_oneof![
        "[0-9 .eE+-]{0,8}".prop_map(|s| format!("\"{s}\"")),
        ("[0-9]{1,4}", "(mm|N|Pa|psi|kN/m|GPa|s|cm/s|xyz| )")
            .prop_map(|(n, u)| format!("\"{n} {u}\"")),
        "(sphere|cylinder|fast|auto|homogeneous|graded|same|rolling|a|m)"
            .prop_map(|s| format!("\"{s}\"")),
        any::<i64>().prop_map(|i| i.to_string()),
        (-1e6..1e6f64).prop_map(|x| format!("{x:e}")),
        prop_oneof![Just("nan"), Just("-inf"), Just("0"), Just("1e400"), Just("0.5"), Just("-3")]
            .prop_map(str::to_string),
        any::<bool>().prop_map(|b| b.to_string()),
        Just("1979-05-27".to_string()),
    ];
    leaf.prop_recursive(2, 8, 4, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..4).prop_map(|v| format!("[{}]", v.join(", "))),
            inner.prop_map(|v| format!("{{ x = {v} }}")),
        ]
    })
}

#[derive(Debug, Clone)]
enum Mutation {
    Delete(usize),
    Duplicate(usize),
    Replace(usize, String),
    Truncate(usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        any::<usize>().prop_map(Mutation::Delete),
        any::<usize>().prop_map(Mutation::Duplicate),
        (any::<usize>(), value()).prop_map(|(i, v)| Mutation::Replace(i, v)),
        any::<usize>().prop_map(Mutation::Truncate),
    ]
}

fn apply(src: &str, m: &Mutation) -> String {
    let mut lines: Vec<String> = src.lines().map(str::to_string).collect();
    let n = lines.len().max(1);
    match m {
        Mutation::Delete(i) => {
            if !lines.is_empty() {
                lines.remove(i % n);
            }
        }
        Mutation::Duplicate(i) => {
            if !lines.is_empty() {
                let l = lines[i % n].clone();
                lines.insert(i % n, l);
            }
        }
        Mutation::Replace(i, v) => {
            let with_value: Vec<usize> = (0..lines.len())
                .filter(|&k| {
                    !lines[k].trim_start().starts_with(['#', '[']) && lines[k].contains('=')
                })
                .collect();
            if !with_value.is_empty() {
                let k = with_value[i % with_value.len()];
                let key = lines[k].split('=').next().unwrap_or("").to_string();
                lines[k] = format!("{key}= {v}");
            }
        }
        Mutation::Truncate(i) => {
            let mut at = i % (src.len() + 1);
            while !src.is_char_boundary(at) {
                at -= 1;
            }
            return src[..at].to_string();
        }
    }
    lines.join("\n") + "\n"
}

fn cases() -> u32 {
    std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(256)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), ..ProptestConfig::default() })]

    #[test]
    fn mutated_scenes_are_refused_in_plain_words(pick in any::<usize>(), muts in prop::collection::vec(mutation(), 1..3)) {
        let all = scenes();
        let (name, text) = &all[pick % all.len()];
        let mut src = text.clone();
        for m in &muts {
            src = apply(&src, m);
        }
        let result = Scene::from_toml_str(&src, Some(name.into())).and_then(|s| Plan::new(&s).map(|_| ()));
        if let Err(e) = result {
            let msg = e.to_string();
            prop_assert!(e.key.is_some() || e.position.is_some(), "no key and no position: {msg}\n--- scene:\n{src}");
            prop_assert!(e.hint.as_deref().is_some_and(|h| !h.trim().is_empty()), "no hint: {msg}\n--- scene:\n{src}");
            for w in INTERNAL {
                prop_assert!(!msg.contains(w), "internal word {w:?}: {msg}\n--- scene:\n{src}");
            }
            prop_assert_eq!(e.exit_code(), 2, "{}", msg);
        }
    }
}
