//! The `ladder` command: parse the arguments, call the library.

use clap::{Parser, Subcommand};
use sliding_ladder::sim::command;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "ladder",
    version,
    about = "The sliding ladder: equations checked, the fall simulated"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
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
    /// Error against run time for every integrator (CSV + SVG with --out).
    WorkPrecision {
        /// The scene (default: the from-rest scene θ0 = 0.3).
        scene: Option<PathBuf>,
        /// Print JSON (runs[]) instead of a table.
        #[arg(long)]
        json: bool,
        /// Write runs.csv and work_precision.svg here.
        #[arg(long)]
        out: Option<PathBuf>,
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
        Command::Simulate { scene, json, out } => command::simulate(&scene, json, out.as_deref()),
        Command::WorkPrecision { scene, json, out } => {
            command::work_precision(scene.as_deref(), json, out.as_deref())
        }
    }
}
