//! `stickslip new`, `schema`, `completions` and `man` as a user meets them: every kind
//! written to a file runs as written; the schema lands beside a scene outside a checkout
//! and is found inside one; an existing file is kept unless --force; completions for every
//! shell and the manual page name the subcommands.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_stickslip"))
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("stickslip-new-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn out(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Standard error with the lines the program wrapped to 80 columns joined again (every run
/// of white space is one space), so that a phrase is found wherever the line broke.
fn err(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).split_whitespace().collect::<Vec<_>>().join(" ")
}

fn kinds() -> Vec<String> {
    let o = bin().args(["new", "--list"]).output().unwrap();
    assert!(o.status.success(), "{}", err(&o));
    out(&o).lines().map(|l| l.split_whitespace().next().unwrap().to_string()).collect()
}

#[test]
fn every_kind_is_written_and_runs() {
    let d = tmp("kinds");
    let kinds = kinds();
    assert_eq!(kinds.len(), 10, "{kinds:?}");
    for k in &kinds {
        let f = d.join(format!("{k}.toml"));
        let o = bin().args(["new", k]).arg(&f).output().unwrap();
        assert!(o.status.success(), "{k}: {}", err(&o));
        let text = std::fs::read_to_string(&f).unwrap();
        // Outside a checkout the schema is written beside the scene.
        assert!(text.starts_with("#:schema ./scene.schema.json\n"), "{k}");
        let o = bin().arg("run").arg(&f).output().unwrap();
        assert!(o.status.success(), "{k}: {}", err(&o));
    }
    let schema = std::fs::read_to_string(d.join("scene.schema.json")).unwrap();
    let printed = out(&bin().arg("schema").output().unwrap());
    assert_eq!(schema, printed);
    let v: serde_json::Value = serde_json::from_str(&schema).unwrap();
    assert_eq!(v["title"], "stickslip scene");
    // Standard output: the same scene, the same directive.
    let o = bin().args(["new", "sphere"]).output().unwrap();
    assert_eq!(out(&o), std::fs::read_to_string(d.join("sphere.toml")).unwrap());
    assert!(err(&o).contains("stickslip schema > scene.schema.json"), "{}", err(&o));
}

#[test]
fn inside_a_checkout_the_directive_points_at_docs() {
    let d = tmp("checkout");
    std::fs::create_dir_all(d.join("docs")).unwrap();
    std::fs::create_dir_all(d.join("work/a")).unwrap();
    let schema = out(&bin().arg("schema").output().unwrap());
    std::fs::write(d.join("docs/scene.schema.json"), &schema).unwrap();
    let f = d.join("work/a/s.toml");
    let o = bin().args(["new", "rolling"]).arg(&f).output().unwrap();
    assert!(o.status.success(), "{}", err(&o));
    let text = std::fs::read_to_string(&f).unwrap();
    assert!(text.starts_with("#:schema ../../docs/scene.schema.json\n"), "{text}");
    assert!(!Path::new(&d.join("work/a/scene.schema.json")).exists());
}

#[test]
fn an_existing_file_is_kept_unless_forced() {
    let d = tmp("exists");
    let f = d.join("mine.toml");
    std::fs::write(&f, "precious").unwrap();
    let o = bin().args(["new", "sphere"]).arg(&f).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(err(&o).contains("exists; use --force"), "{}", err(&o));
    assert_eq!(std::fs::read_to_string(&f).unwrap(), "precious");
    // A foreign scene.schema.json is left alone.
    std::fs::write(d.join("scene.schema.json"), "{}").unwrap();
    let o = bin().args(["new", "sphere", "--force"]).arg(&f).output().unwrap();
    assert!(o.status.success(), "{}", err(&o));
    assert!(std::fs::read_to_string(&f).unwrap().starts_with("#:schema"));
    assert_eq!(std::fs::read_to_string(d.join("scene.schema.json")).unwrap(), "{}");
    assert!(err(&o).contains("is not a stickslip schema"), "{}", err(&o));
    // An unknown kind is a usage error that names the kinds.
    let o = bin().args(["new", "spere"]).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(err(&o).contains("sphere") && err(&o).contains("viscoelastic-rolling"), "{}", err(&o));
}

#[test]
fn completions_and_man_name_the_subcommands() {
    for shell in ["bash", "zsh", "fish", "powershell", "elvish"] {
        let o = bin().args(["completions", shell]).output().unwrap();
        assert!(o.status.success(), "{shell}: {}", err(&o));
        let s = out(&o);
        for word in ["run", "explain", "new", "completions", "--list"] {
            assert!(s.contains(word), "{shell} lacks {word}");
        }
        // clap_complete completes the kinds of `new` (a positional's values) in bash and zsh
        // only; fish, PowerShell and elvish complete subcommands and options.
        if matches!(shell, "bash" | "zsh") {
            assert!(s.contains("viscoelastic-rolling"), "{shell} lacks the kinds");
        }
    }
    let o = bin().args(["completions", "tcsh"]).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    let o = bin().arg("man").output().unwrap();
    assert!(o.status.success());
    let s = out(&o);
    assert!(s.contains(".TH stickslip 1"), "{s}");
    for word in ["run", "explain", "new", "completions", "man"] {
        assert!(s.contains(word), "man lacks {word}");
    }
}
