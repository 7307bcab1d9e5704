//! `ladder work-precision [SCENE...]`: error against run time for every integrator on each
//! scene, as tables, JSON, or CSV + SVG with `--out`.

use crate::report::files::{write_all, OutFile};
use crate::report::work_precision::fit::Point;
use crate::report::work_precision::report::{csv, panel, report, OrderRow, SceneReport};
use crate::report::work_precision::{default_scenes, sweep, TIMING};
use crate::sim::integrators::names;
use crate::sim::scene;
use clap::Args;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// The options of `ladder work-precision`.
#[derive(Args)]
pub struct WorkPrecisionArgs {
    /// The scenes (default: upright with a tiny push, from rest at 0.1, 0.3, 1.0, 1.5, and
    /// the full fall to flat from 0.3).
    scenes: Vec<PathBuf>,
    /// Print JSON (runs[]) instead of a table.
    #[arg(long)]
    json: bool,
    /// Write runs.csv and work_precision.svg here.
    #[arg(long)]
    out: Option<PathBuf>,
}

/// Run `ladder work-precision` with its options.
pub fn run(a: WorkPrecisionArgs) -> ExitCode {
    work_precision(&a.scenes, a.json, a.out.as_deref())
}

/// `ladder work-precision [SCENE...] [--json] [--out DIR]`: every scene given, or the built-in
/// list ([`default_scenes`]).
pub fn work_precision(scene_paths: &[PathBuf], json: bool, out: Option<&Path>) -> ExitCode {
    let mut scenes = Vec::new();
    for p in scene_paths {
        match scene::load(p) {
            Ok(s) => scenes.push(s),
            Err(e) => {
                eprintln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    }
    if scenes.is_empty() {
        scenes = default_scenes();
    }
    let per_scene: usize = names().map(|m| sweep(m).len()).sum();
    let bar = indicatif::ProgressBar::new((per_scene * scenes.len()) as u64);
    let mut reports = Vec::new();
    for sc in &scenes {
        let rep = report(sc, TIMING, |m| {
            bar.set_message(format!("{} {m}", sc.file));
            bar.inc(1);
        });
        match rep {
            Ok(r) => reports.push(r),
            Err(e) => {
                bar.finish_and_clear();
                eprintln!("error: {}: {e}", sc.file);
                return ExitCode::from(2);
            }
        }
    }
    bar.finish_and_clear();
    if let Some(dir) = out {
        let panels = reports.iter().map(panel).collect();
        if let Err(e) = write_all(
            dir,
            &[
                OutFile::text("runs.csv", csv(&reports)),
                OutFile::panels("work_precision.svg", panels),
            ],
        ) {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    }
    if json {
        let v = serde_json::json!({ "scenes": reports });
        println!("{}", serde_json::to_string_pretty(&v).unwrap_or_default());
        return ExitCode::SUCCESS;
    }
    for r in &reports {
        print_report(r);
    }
    ExitCode::SUCCESS
}

/// One method's observed order (or why not), note and tolerance slope.
fn print_order_row(row: &OrderRow) {
    let name = match row.fixed_order {
        Some(p) => format!("{} order {p}", row.method),
        None => row.method.clone(),
    };
    let classical = row
        .classical
        .map_or("p(tol)".to_string(), |p| p.to_string());
    match (&row.observed, &row.not_fitted) {
        (Some(f), _) => println!(
            "  {name:<17} classical {classical:<6} observed {:.2} ± {:.2} over {} runs, steps {}..{}, rhs {}..{}, error {:.1e}..{:.1e} (floor {:.0e})",
            f.order, f.std_error, f.runs, f.steps_range.0, f.steps_range.1, f.rhs_range.0, f.rhs_range.1, f.error_range.0, f.error_range.1, f.floor
        ),
        (None, why) => println!(
            "  {name:<17} classical {classical:<6} observed: not fitted ({})",
            why.as_deref().unwrap_or("no runs")
        ),
    }
    if let Some(n) = &row.note {
        println!("  {:<17} note: {n}", "");
    }
    match (&row.tolerance_slope, &row.tolerance_not_fitted) {
        (Some(t), _) => println!(
            "  {:<17} tolerance slope {:.2} ± {:.2} over {} runs, tolerance {:.0e}..{:.0e}, error {:.1e}..{:.1e}, steps {}..{}",
            "", t.slope, t.std_error, t.runs, t.tolerance_range.0, t.tolerance_range.1, t.error_range.0, t.error_range.1, t.steps_range.0, t.steps_range.1
        ),
        (None, Some(why)) => println!("  {:<17} tolerance slope: not fitted ({why})", ""),
        (None, None) => {}
    }
}

/// The table of one scene on stdout.
fn print_report(rep: &SceneReport) {
    // A built-in scene's name is its start, which the line gives anyway.
    let name = if rep.scene.starts_with("(built in") {
        "a built-in scene"
    } else {
        rep.scene.as_str()
    };
    println!(
        "\nwork-precision for {} (θ0 = {}, θ̇0 = {}{})",
        name,
        rep.start.0,
        rep.start.1,
        if rep.to_flat {
            ", to flat; flat-time reference: the exact separation plus the floor phase's duration by quadrature of its conservation laws"
        } else {
            ""
        }
    );
    println!(
        "{:<17} {:>9} {:>10} {:>10} {:>10} {:>10} {:>9} {:>6} {:>11} {:>19}",
        "method",
        "tol/step",
        "angle err",
        "time err",
        "flat err",
        "energy err",
        "rhs",
        "steps",
        "µs median",
        "µs q1-q3"
    );
    for r in &rep.runs {
        println!(
            "{:<17} {:>9.1e} {:>10.2e} {:>10.2e} {:>10} {:>10.2e} {:>9} {:>6} {:>11.3} {:>19}",
            r.method,
            r.tolerance,
            r.angle_error,
            r.time_error,
            r.flat_time_error.map_or("-".into(), |e| format!("{e:.2e}")),
            r.energy_error,
            r.rhs_evals,
            r.steps,
            r.seconds * 1e6,
            format!("{:.3}-{:.3}", r.seconds_iqr.0 * 1e6, r.seconds_iqr.1 * 1e6),
        );
    }
    if rep.runs.iter().any(|r| r.method.starts_with("ode_solvers")) {
        println!("ode_solvers-*: the peers (--features peers), handed the exact t_s (no event location): θ there, time error 0 by construction, not on the Pareto front");
    }
    println!(
        "observed order: least-squares slope of −ln(error) against ln(steps) over at least {} runs spanning at least {} decades of error, each with error in [floor, {:.0e}], at least {} steps in each phase (a full fall has two), steps not tied with another run and growing, error falling (floor: min({:.0e}, {} × the sweep's rounding level); see work_precision::fit). tolerance slope: of ln(error) against ln(tolerance) over the runs above the floor (1: proportional)",
        crate::report::work_precision::fit::MIN_RUNS,
        crate::report::work_precision::fit::MIN_DECADES,
        crate::report::work_precision::fit::ASYMPTOTIC,
        crate::report::work_precision::fit::MIN_STEPS,
        crate::report::work_precision::fit::FLOOR,
        crate::report::work_precision::fit::ROUNDING_MARGIN,
    );
    for row in rep.orders.iter().chain(&rep.taylor_fixed) {
        print_order_row(row);
    }
    println!("Pareto front (median run time against the worse error; no listed run is dominated):");
    for r in &rep.pareto {
        println!(
            "  {:<17} {:>9.1e}  error {:.2e}  {:.3} µs",
            r.method,
            r.tolerance,
            r.error(),
            r.seconds * 1e6
        );
    }
}
