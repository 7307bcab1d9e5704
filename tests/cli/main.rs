//! The `ladder` command as a user runs it: exit codes, stderr, files (`cargo test --test cli`).

mod animate;
mod broken_pipe;
#[path = "../common/mod.rs"]
mod common;
mod show;
mod simulate;
mod stability;
mod units;
mod work_precision;
