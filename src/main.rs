//! The `ladder` command: a thin shell over [`sliding_ladder::cli`], where every subcommand lives.

use std::process::ExitCode;

fn main() -> ExitCode {
    sliding_ladder::cli::run()
}
