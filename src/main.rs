//! The `ladder` command: verify the note's equations, list its errata, simulate the fall.

use clap::{Parser, Subcommand};
use sliding_ladder::registry::check::Config;
use sliding_ladder::verify::command;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "ladder",
    version,
    about = "The equations of 'Torque Analyses of a Sliding Ladder', checked"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Check every numbered equation (1)-(90): one row per equation.
    Verify {
        /// Print JSON instead of a table.
        #[arg(long)]
        json: bool,
        /// Random float states per check.
        #[arg(long, default_value_t = Config::default().float_cases)]
        cases: usize,
        /// Random exact rational points per check.
        #[arg(long, default_value_t = Config::default().exact_points)]
        exact_points: usize,
        /// Seed of the random states.
        #[arg(long, default_value_t = Config::default().seed)]
        seed: u64,
    },
    /// The note's misprints: printed and corrected forms with their residuals.
    Errata {
        /// Print JSON.
        #[arg(long)]
        json: bool,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        None => command::verify(false, &Config::default()),
        Some(Command::Verify {
            json,
            cases,
            exact_points,
            seed,
        }) => command::verify(
            json,
            &Config {
                float_cases: cases,
                exact_points,
                seed,
            },
        ),
        Some(Command::Errata { json }) => command::errata_command(json, &Config::default()),
    }
}
