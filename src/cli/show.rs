//! `ladder show N`: one display in depth (issue 15); the work is done by [`crate::show`].

use crate::registry::check::Config;
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
    crate::show::command(
        &a.query,
        a.at.as_deref(),
        a.json,
        a.values_only,
        &Config {
            float_cases: a.cases,
            ..Config::default()
        },
    )
}
