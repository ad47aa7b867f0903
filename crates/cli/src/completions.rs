//! `stickslip completions SHELL` and `stickslip man`: shell completion scripts and the
//! manual page, both generated from the command-line definition (clap_complete,
//! clap_mangen), so they always match the program.

use clap::Args;
use clap_complete::Shell;

use crate::{emit, Failure};

/// The arguments of `completions`.
#[derive(Debug, Args)]
pub struct CompletionsArgs {
    /// The shell to complete for.
    shell: Shell,
}

/// `completions`: the script on standard output.
pub fn run(a: &CompletionsArgs, mut cmd: clap::Command) -> Result<(), Failure> {
    let mut out = Vec::new();
    clap_complete::generate(a.shell, &mut cmd, "stickslip", &mut out);
    emit(&String::from_utf8_lossy(&out))
}

/// `man`: the manual page (roff) on standard output.
pub fn man(cmd: clap::Command) -> Result<(), Failure> {
    let mut out = Vec::new();
    clap_mangen::Man::new(cmd)
        .render(&mut out)
        .map_err(|e| Failure::Other(format!("cannot render the manual page: {e}"), 1))?;
    emit(&String::from_utf8_lossy(&out))
}
