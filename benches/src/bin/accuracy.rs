//! Produce the accuracy-versus-time report: `accuracy [--quick] [--out DIR]`.
//!
//! Full mode (the default) writes `docs/accuracy.md` and `docs/accuracy/*.svg` of the
//! workspace; `--quick` measures the CI subset.

use std::path::PathBuf;
use stickslip_benches::accuracy::{run, write, Mode};

fn main() -> std::process::ExitCode {
    let mut mode = Mode::Full;
    let mut out = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs"));
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--quick" => mode = Mode::Quick,
            "--full" => mode = Mode::Full,
            "--out" => match args.next() {
                Some(d) => out = PathBuf::from(d),
                None => {
                    eprintln!("--out needs a directory");
                    return std::process::ExitCode::FAILURE;
                }
            },
            _ => {
                eprintln!("usage: accuracy [--quick|--full] [--out DIR]");
                return std::process::ExitCode::FAILURE;
            }
        }
    }
    let report = run(mode);
    for m in &report.methods {
        println!("{:<16} {}", m.slug, m.reading);
        for s in &m.settings {
            println!(
                "    {:<12} error {:>10.3e}  claim {:>9}  {:>10}  {}",
                s.label,
                s.error,
                s.claim.map_or("-".to_string(), |c| format!("{c:.0e}")),
                stickslip_benches::accuracy::fmt_time(s.seconds),
                s.work
            );
        }
    }
    println!("total {:.1} s", report.seconds);
    match write(&report, &out) {
        Ok(paths) => {
            for p in paths {
                println!("wrote {}", p.display());
            }
        }
        Err(e) => {
            eprintln!("cannot write the report: {e}");
            return std::process::ExitCode::FAILURE;
        }
    }
    let bad = report.violations();
    for v in &bad {
        eprintln!("claim not met: {v}");
    }
    if bad.is_empty() {
        std::process::ExitCode::SUCCESS
    } else {
        std::process::ExitCode::FAILURE
    }
}
