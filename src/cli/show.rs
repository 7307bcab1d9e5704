//! `ladder show N`: one display in depth (issue 15); the work is done by [`crate::show`]; this file only prints and chooses the exit code.

use crate::registry::check::Config;
use crate::show::{self, text, Answer};
use clap::Args;
use std::process::ExitCode;

/// The options of `ladder show`.
#[derive(Args)]
pub struct ShowArgs {
    /// A display number (25), a list or range (23-25,28), or words to search for ("about D").
    query: String,
    /// The state: "m=2, l=1.5, g=9.81, theta=40deg, theta0=10deg" (θ̇ from the energy and
    /// θ̈ from (5) unless given as theta_dot, theta_ddot; sin_theta=3/5 for an exact angle).
    #[arg(long)]
    at: Option<String>,
    /// Print JSON.
    #[arg(long)]
    json: bool,
    /// Random float states per check.
    #[arg(long, default_value_t = Config::default().float_cases)]
    cases: usize,
    /// Only the forms' values (no check, proof or print check is run: fast).
    #[arg(long)]
    values_only: bool,
}

/// Run `ladder show` with its options.
pub fn run(a: ShowArgs) -> ExitCode {
    let cfg = Config {
        float_cases: a.cases,
        ..Config::default()
    };
    let shown = match show::answer(&a.query, a.at.as_deref(), a.values_only, &cfg) {
        Ok(Answer::Shown(s)) => s,
        Ok(Answer::Matches { words, hits }) => {
            if a.json {
                print_json(&serde_json::json!({ "query": words, "matches": hits }));
            } else {
                print!("{}", text::hits(&words, &hits));
            }
            return ExitCode::SUCCESS;
        }
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(2);
        }
    };
    if a.json && shown.len() == 1 {
        print_json(&shown[0]);
    } else if a.json {
        print_json(&shown);
    } else {
        for (k, s) in shown.iter().enumerate() {
            if k > 0 {
                println!();
            }
            print!("{}", text::render(s));
        }
    }
    let failed: Vec<String> = shown
        .iter()
        .filter(|s| s.failed())
        .map(|s| format!("({})", s.number))
        .collect();
    if failed.is_empty() {
        return ExitCode::SUCCESS;
    }
    eprintln!("ladder show: exit 1: failed: {}", failed.join(", "));
    ExitCode::from(1)
}

/// Print plain data as pretty JSON (it always serialises).
fn print_json(v: &impl serde::Serialize) {
    println!(
        "{}",
        serde_json::to_string_pretty(v).expect("JSON of plain data")
    );
}
