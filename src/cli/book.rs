//! `ladder book --out DIR`: the note as verified, as a static HTML book (issue 12); the work is
//! done by [`crate::book`]; this file only prints and chooses the exit code.

use crate::book;
use crate::registry::check::Config;
use crate::verify::Status;
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

/// Run `ladder book` with its options: 0 when the book is written and every check passed, 1
/// when it is written but some check failed or some display did not typeset, 2 when it cannot
/// be written (nothing is left behind).
pub fn run(a: BookArgs) -> ExitCode {
    let cfg = Config {
        float_cases: a.cases,
        ..Config::default()
    };
    let (built, data) = match book::write_book(&a.out, &cfg) {
        Ok(b) => b,
        Err(e) => {
            eprintln!("ladder book: {e}");
            return ExitCode::from(2);
        }
    };
    let pages = built
        .files
        .iter()
        .filter(|(n, _)| n.ends_with(".html"))
        .count();
    println!(
        "book: {} files ({pages} pages) written to {}; open {}",
        built.files.len(),
        a.out.display(),
        a.out.join("index.html").display()
    );
    println!("{}", data.summary);
    for p in built.problems.iter().chain(&data.docs_problems) {
        println!("  ! {p}");
    }
    if built.problems.is_empty() && data.all_good() {
        return ExitCode::SUCCESS;
    }
    let failed: Vec<&str> = data
        .results
        .iter()
        .chain(&data.extensions)
        .filter(|r| r.status == Status::Failed)
        .map(|r| r.label.as_str())
        .collect();
    eprintln!(
        "ladder book: written, exit 1: {} failed displays{}; {} problems of the book, {} of its files; {} methods failed",
        failed.len(),
        if failed.is_empty() { String::new() } else { format!(" ({})", failed.join(", ")) },
        built.problems.len(),
        data.docs_problems.len(),
        data.methods.iter().filter(|m| !m.passed).count()
    );
    ExitCode::from(1)
}
