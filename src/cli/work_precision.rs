//! `ladder work-precision [SCENE]`: error against run time for every integrator, as a table,
//! JSON, or CSV + SVG with `--out`.

use crate::report::files::{write_all, OutFile};
use crate::report::work_precision::{
    csv, default_scene, measure, observed_order, pareto, plot, sweep,
};
use crate::sim::integrators::{order, RIGID_METHODS as METHODS};
use crate::sim::scene;
use clap::Args;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// The options of `ladder work-precision`.
#[derive(Args)]
pub struct WorkPrecisionArgs {
    /// The scene (default: the built-in from-rest scene θ0 = 0.3).
    scene: Option<PathBuf>,
    /// Print JSON (runs[]) instead of a table.
    #[arg(long)]
    json: bool,
    /// Write runs.csv and work_precision.svg here.
    #[arg(long)]
    out: Option<PathBuf>,
}

/// Run `ladder work-precision` with its options.
pub fn run(a: WorkPrecisionArgs) -> ExitCode {
    work_precision(a.scene.as_deref(), a.json, a.out.as_deref())
}

/// `ladder work-precision [SCENE] [--json] [--out DIR]`.
pub fn work_precision(scene_path: Option<&Path>, json: bool, out: Option<&Path>) -> ExitCode {
    let base = match scene_path.map(scene::load) {
        None => default_scene(),
        Some(Ok(s)) => s,
        Some(Err(e)) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let total: usize = METHODS.iter().map(|m| sweep(m).len()).sum();
    let bar = indicatif::ProgressBar::new(total as u64);
    let runs = measure(&base, |m| {
        bar.set_message(m.to_string());
        bar.inc(1);
    });
    bar.finish_and_clear();
    let runs = match runs {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: {}: {e}", base.file);
            return ExitCode::from(2);
        }
    };
    if let Some(dir) = out {
        if let Err(e) = write_all(
            dir,
            &[
                OutFile::text("runs.csv", csv(&runs)),
                plot(&runs, &base.file),
            ],
        ) {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    }
    let orders: Vec<serde_json::Value> = METHODS
        .iter()
        .map(|m| serde_json::json!({"method": m, "theoretical": order(m), "observed": observed_order(&runs, m)}))
        .collect();
    if json {
        let v = serde_json::json!({ "scene": base.file, "runs": runs, "orders": orders, "pareto": pareto(&runs) });
        println!("{}", serde_json::to_string_pretty(&v).unwrap_or_default());
        return ExitCode::SUCCESS;
    }
    println!(
        "work-precision for {} (θ0 = {}, θ̇0 = {})",
        base.file, base.theta0, base.rate0
    );
    println!(
        "{:<17} {:>9} {:>10} {:>10} {:>10} {:>9} {:>11}",
        "method", "tol/step", "angle err", "time err", "energy err", "rhs", "µs/solve"
    );
    for r in &runs {
        println!(
            "{:<17} {:>9.1e} {:>10.2e} {:>10.2e} {:>10.2e} {:>9} {:>11.3}",
            r.method,
            r.tolerance,
            r.angle_error,
            r.time_error,
            r.energy_error,
            r.rhs_evals,
            r.seconds * 1e6
        );
    }
    println!("\nobserved order (slope of error against rhs evaluations):");
    for m in METHODS {
        let obs = observed_order(&runs, m).map_or("n/a".to_string(), |o| format!("{o:.2}"));
        println!(
            "  {m:<17} theoretical {}  observed {obs}",
            order(m).unwrap_or(0)
        );
    }
    println!("\nPareto front (run time against the worse of angle and time error):");
    for r in pareto(&runs) {
        println!(
            "  {:<17} {:>9.1e}  error {:.2e}  {:.3} µs",
            r.method,
            r.tolerance,
            r.angle_error.max(r.time_error),
            r.seconds * 1e6
        );
    }
    ExitCode::SUCCESS
}
