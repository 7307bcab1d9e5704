//! The `ladder` command: a thin shell over [`sliding_ladder::cli`], where every subcommand lives.

use std::process::ExitCode;

fn main() -> ExitCode {
    // Rust ignores SIGPIPE, so `ladder errata | head` would panic in `println!` once `head`
    // closes the pipe. Restore the default action: the command then ends quietly, as Unix
    // filters do.
    #[cfg(unix)]
    // SAFETY: called once at start-up, before any thread exists; SIG_DFL is a valid action.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    sliding_ladder::cli::run()
}
