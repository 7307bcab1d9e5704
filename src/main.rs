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
    /// One display in depth: print, symbols, every form's value at a state, its checks.
    Show {
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
        Some(Command::Show {
            query,
            at,
            json,
            cases,
            values_only,
        }) => sliding_ladder::show::command(
            &query,
            at.as_deref(),
            json,
            values_only,
            &Config {
                float_cases: cases,
                ..Config::default()
            },
        ),
        Some(Command::Errata { json }) => verify::errata_command(json, &Config::default()),
        Some(Command::Simulate { scene, json, out }) => sim::simulate(&scene, json, out.as_deref()),
        Some(Command::WorkPrecision { scenes, json, out }) => {
            sim::work_precision(&scenes, json, out.as_deref())
        }
        Some(Command::Stability { json }) => sliding_ladder::report::stability::command(json),
    }
}
