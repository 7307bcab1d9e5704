//! A reader that closes the pipe early (`ladder show 1-30 | head -c1`: 100 kB, more than a pipe holds) must not make `ladder` panic.

use std::io::Read;
use std::process::{Command, Stdio};

#[test]
fn a_closed_pipe_ends_the_command_without_a_panic() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(["show", "1-30"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("ladder runs");
    // Read one byte, then close our end of the pipe while ladder is still writing.
    let mut first = [0u8; 1];
    child
        .stdout
        .take()
        .expect("piped stdout")
        .read_exact(&mut first)
        .expect("ladder writes to stdout");
    let mut err = String::new();
    child
        .stderr
        .take()
        .expect("piped stderr")
        .read_to_string(&mut err)
        .expect("stderr is UTF-8");
    child.wait().expect("ladder ends");
    assert!(
        !err.contains("panicked"),
        "ladder panicked on a closed pipe: {err}"
    );
}
