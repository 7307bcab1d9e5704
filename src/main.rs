//! The `ladder` command: parse the arguments, call the library.

use clap::{Parser, Subcommand};
use sliding_ladder::registry::check::Config;
use sliding_ladder::sim::command as sim;
use sliding_ladder::verify::command as verify;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "ladder",
    version,
    about = "The sliding ladder: the note's equations checked, the fall simulated"
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
        /// Show only these displays: equation numbers or sections, e.g. `25,28` or `2.5`.
        #[arg(long)]
        only: Option<String>,
    },
    /// The note's misprints: printed and corrected forms with their residuals.
    Errata {
        /// Print JSON.
        #[arg(long)]
        json: bool,
    },
    /// Simulate a scene (TOML) and print the outputs it asks for.
    Simulate {
        /// The scene file.
        scene: PathBuf,
        /// Print JSON instead of a summary.
        #[arg(long)]
        json: bool,
        /// Write CSV and SVG files here (when the scene asks for a trajectory or forces).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Error against run time for every integrator on each scene (CSV + SVG with --out).
    WorkPrecision {
        /// The scenes (default: upright with a tiny push, from rest at 0.1, 0.3, 1.0, 1.5, and
        /// the full fall to flat from 0.3).
        scenes: Vec<PathBuf>,
        /// Print JSON (runs[]) instead of a table.
        #[arg(long)]
        json: bool,
        /// Write runs.csv and work_precision.svg here.
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Stiff and extreme cases (penalty contact, Lagrange drift, edges of the domain, scales,
    /// long runs), with verdicts.
    Stability {
        /// Print JSON (cases[]) instead of tables.
        #[arg(long)]
        json: bool,
    },
    /// Write the note as verified as a static HTML book (MathML, no script, offline).
    Book {
        /// The directory to write (replaced whole if it holds an earlier book).
        #[arg(long)]
        out: PathBuf,
        /// Random float states per check.
        #[arg(long, default_value_t = Config::default().float_cases)]
        cases: usize,
    },
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let code = if e.use_stderr() { 2 } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    match cli.command {
        None => {
            let verified = verify::verify(false, &Config::default(), None);
            println!();
            let simulated = sim::simulate_builtin_classic();
            if verified == ExitCode::SUCCESS {
                simulated
            } else {
                verified
            }
        }
        Some(Command::Verify {
            json,
            cases,
            exact_points,
            seed,
            only,
        }) => verify::verify(
            json,
            &Config {
                float_cases: cases,
                exact_points,
                seed,
            },
            only.as_deref(),
        ),
        Some(Command::Errata { json }) => verify::errata_command(json, &Config::default()),
        Some(Command::Simulate { scene, json, out }) => sim::simulate(&scene, json, out.as_deref()),
        Some(Command::WorkPrecision { scenes, json, out }) => {
            sim::work_precision(&scenes, json, out.as_deref())
        }
        Some(Command::Stability { json }) => sliding_ladder::report::stability::command(json),
        Some(Command::Book { out, cases }) => sliding_ladder::book::command(
            &out,
            &Config {
                float_cases: cases,
                ..Config::default()
            },
        ),
    }
}
