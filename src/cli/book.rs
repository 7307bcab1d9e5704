//! `ladder book --out DIR`: the note as verified, as a static HTML book (issue 12); the work is
//! done by [`crate::book`].

use crate::registry::check::Config;
use clap::Args;
use std::path::PathBuf;
use std::process::ExitCode;

/// The options of `ladder book`.
#[derive(Args)]
pub struct BookArgs {
    /// The directory to write (replaced whole if it holds an earlier book).
    #[arg(long)]
    out: PathBuf,
    /// Random float states per check.
    #[arg(long, default_value_t = Config::default().float_cases)]
    cases: usize,
}

/// Run `ladder book` with its options.
pub fn run(a: BookArgs) -> ExitCode {
    crate::book::command(
        &a.out,
        &Config {
            float_cases: a.cases,
            ..Config::default()
        },
    )
}
