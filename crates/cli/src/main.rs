//! The `stickslip` command-line program (being written: issue 10).

fn main() {
    eprintln!("stickslip: the command-line program is not written yet (issue 10)");
    std::process::exit(2);
}
