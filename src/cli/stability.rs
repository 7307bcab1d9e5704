//! `ladder stability`: the stiff and extreme cases with their verdicts (see
//! [`crate::report::stability`]); exit 1 only when a verdict contradicts theory's expectation.

use crate::report::stability::case::Case;
use crate::report::stability::scale::SWEEP_CASES;
use crate::report::stability::stiff::EXPECTED_RUNS;
use crate::report::stability::{all_cases, table};
use clap::Args;
use indicatif::{ProgressBar, ProgressDrawTarget};
use std::io::{IsTerminal, Write};
use std::process::ExitCode;

/// The options of `ladder stability`.
#[derive(Args)]
pub struct StabilityArgs {
    /// Print JSON (cases[]) instead of tables.
    #[arg(long)]
    json: bool,
}

/// Run `ladder stability` with its options.
pub fn run(a: StabilityArgs) -> ExitCode {
    stability(a.json)
}

fn progress() -> ProgressBar {
    let target = if std::io::stdout().is_terminal() {
        ProgressDrawTarget::stderr()
    } else {
        ProgressDrawTarget::hidden()
    };
    ProgressBar::with_draw_target(Some(EXPECTED_RUNS + SWEEP_CASES as u64), target)
}

/// `ladder stability [--json]`.
pub fn stability(json: bool) -> ExitCode {
    let bar = progress();
    let (cases, conv) = all_cases(|label, n| {
        bar.set_message(label.to_string());
        bar.inc(n);
    });
    bar.finish_and_clear();
    let surprises = cases
        .iter()
        .filter(|c| c.expect.surprised_by(c.verdict))
        .count();
    let text = if json {
        let v = serde_json::json!({ "cases": cases, "convergence": conv, "surprises": surprises });
        serde_json::to_string_pretty(&v).unwrap_or_default() + "\n"
    } else {
        table(&cases, &conv)
    };
    // A closed pipe (e.g. `| head`) is not an error of the report.
    let _ = std::io::stdout().lock().write_all(text.as_bytes());
    match surprise_line(&cases) {
        None => ExitCode::SUCCESS,
        Some(why) => {
            eprintln!("{why}");
            ExitCode::from(1)
        }
    }
}

/// The stderr line of a report with cases not as theory expects (exit 1), naming each; `None`
/// when every verdict is the expected one.
pub fn surprise_line(cases: &[Case]) -> Option<String> {
    let names: Vec<String> = cases
        .iter()
        .filter(|c| c.expect.surprised_by(c.verdict))
        .map(|c| format!("{} {} ({})", c.group, c.case, c.method))
        .collect();
    (!names.is_empty()).then(|| {
        format!(
            "ladder stability: exit 1: {} cases not as expected: {}",
            names.len(),
            names.join(", ")
        )
    })
}
