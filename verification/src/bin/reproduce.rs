//! Regenerate `docs/verification/` (run from the workspace root).

fn main() {
    let out = std::path::Path::new("docs/verification");
    match stickslip_verification::generate(out) {
        Ok(files) => {
            for f in files {
                println!("{}", f.display());
            }
        }
        Err(e) => {
            eprintln!("reproduce: {e}");
            std::process::exit(1);
        }
    }
}
