//! The command line of `ladder`: the top layer (see ARCHITECTURE.md). One file per subcommand,
//! each with its clap options and a `run` that calls into verify, sim and report and turns
//! their results into printed output and an exit code. Nothing below this module imports it.

pub mod animate;
pub mod book;
pub mod diagram;
pub mod errata;
pub mod show;
pub mod simulate;
pub mod stability;
pub mod verify;
pub mod work_precision;

use crate::registry::check::Config;
use clap::{Parser, Subcommand};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "ladder",
    version,
    about = "The sliding ladder: the note's equations checked, the fall simulated"
)]
/// The command line: a global `--equations` folder and one subcommand.
pub struct Cli {
    /// Read the displays from this folder of markdown instead of the note built in: every
    /// `*.md` file, each display a section `### (N) Title`, its LaTeX between `$$` lines and a
    /// line `*Kind:* …` (see equations/README.md); for verify, show, errata and book.
    #[arg(long, global = true, value_name = "DIR")]
    pub equations: Option<std::path::PathBuf>,
    /// The subcommand; none verifies every display and simulates the note's fall.
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// The subcommands of `ladder`.
#[derive(Subcommand)]
pub enum Command {
    /// Check every numbered display of the note: one row per display.
    Verify(verify::VerifyArgs),
    /// One display in depth: print, symbols, every form's value at a state, its checks.
    Show(show::ShowArgs),
    /// The note's misprints: printed and corrected forms with their residuals.
    Errata(errata::ErrataArgs),
    /// Simulate a scene (TOML) and print the outputs it asks for.
    Simulate(simulate::SimulateArgs),
    /// Error against run time for every integrator on each scene (CSV + SVG with --out).
    WorkPrecision(work_precision::WorkPrecisionArgs),
    /// Stiff and extreme cases (penalty contact, Lagrange drift, edges of the domain, scales,
    /// long runs), with verdicts.
    Stability(stability::StabilityArgs),
    /// Write the note as verified as a static HTML book (MathML, no script, offline).
    Book(book::BookArgs),
    /// The force diagram of a torque analysis about a point (A-E or any point) at a state, SVG.
    Diagram(diagram::DiagramArgs),
    /// The fall of a scene from release to flat as an animated SVG, forces to scale.
    Animate(animate::AnimateArgs),
}

/// Parse the process arguments and run the subcommand; with none, verify every equation and
/// simulate the note's own fall. A usage error prints clap's message and exits 2.
pub fn run() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let code = if e.use_stderr() { 2 } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    if let Some(dir) = &cli.equations {
        if let Err(code) = use_folder(dir) {
            return code;
        }
    }
    if let Some(code) = reads_note(&cli.command).then(note_unreadable).flatten() {
        return code;
    }
    match cli.command {
        None => {
            let verified = verify::verify(
                false,
                &Config::default(),
                None,
                false,
                verify::columns(None),
            );
            println!();
            let simulated = simulate::simulate_builtin_classic();
            if verified == ExitCode::SUCCESS {
                simulated
            } else {
                verified
            }
        }
        Some(Command::Verify(a)) => verify::run(a),
        Some(Command::Diagram(a)) => diagram::run(a),
        Some(Command::Animate(a)) => animate::run(a),
        Some(Command::Errata(a)) => errata::run(a),
        Some(Command::Simulate(a)) => simulate::run(a),
        Some(Command::WorkPrecision(a)) => work_precision::run(a),
        Some(Command::Stability(a)) => stability::run(a),
        Some(Command::Show(a)) => show::run(a),
        Some(Command::Book(a)) => book::run(a),
    }
}

/// Whether `command` reads the note's displays. Only those commands pay for parsing the note at
/// start-up (about 8 ms; a scene, a stability or work-precision run needs none of it).
pub fn reads_note(command: &Option<Command>) -> bool {
    matches!(
        command,
        None | Some(Command::Verify(_) | Command::Show(_) | Command::Errata(_) | Command::Book(_))
    )
}

/// The note in use could not be read in full: every problem on stderr as `file:line: reason`,
/// exit 2. (The embedded note reads cleanly, a test shows; this catches a binary built from an
/// edited `equations/` whose section is malformed.)
fn note_unreadable() -> Option<ExitCode> {
    let errors = &crate::registry::source::current().errors;
    if errors.is_empty() {
        return None;
    }
    for e in errors {
        eprintln!("ladder: {e}");
    }
    Some(ExitCode::from(2))
}

/// Read the displays from `dir` for the rest of the run; a folder that cannot be read is one
/// line on stderr and exit 2 (a malformed section is reported by [`note_unreadable`]).
fn use_folder(dir: &std::path::Path) -> Result<(), ExitCode> {
    let note = crate::registry::source::Note::from_dir(dir).map_err(|e| {
        eprintln!("ladder: {e}");
        ExitCode::from(2)
    })?;
    crate::registry::source::use_note(note).map_err(|e| {
        eprintln!("ladder: {e}");
        ExitCode::from(2)
    })?;
    Ok(())
}
