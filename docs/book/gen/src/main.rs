//! Writes the generated pages of the derivations book.
//!
//! `cargo run --release -p stickslip-docs [DIR]`: DIR defaults to `docs/book/src/generated`.

use std::process::ExitCode;

fn main() -> ExitCode {
    let dir = std::env::args_os().nth(1).map_or_else(stickslip_docs::default_dir, Into::into);
    match stickslip_docs::write_all(&dir) {
        Ok(paths) => {
            for p in paths {
                println!("wrote {}", p.display());
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
