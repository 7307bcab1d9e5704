//! The reporting half of work-precision: per scene the runs, the observed orders with their
//! fitted range and the Pareto front, as a table, JSON, `runs.csv` and one SVG panel per scene.

use super::files::{write_all, OutFile};
use super::plot::{Chart, PlotSpec, Series};
use super::work_precision::{default_scenes, measure, sweep, Run, Timing, TIMING};
use super::work_precision_fit::{observed_order, pareto, OrderFit, Point};
use crate::sim::integrators::{order, RIGID_METHODS as METHODS};
use crate::sim::scene::{self, End, Scene};
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// The results of one scene.
#[derive(Clone, Debug, Serialize)]
pub struct SceneReport {
    /// The scene's label.
    pub scene: String,
    /// θ0, θ̇0.
    pub start: (f64, f64),
    /// Whether the error includes the flat time (full fall).
    pub to_flat: bool,
    /// Every run.
    pub runs: Vec<Run>,
    /// Per method: theoretical order (None: varies, the Taylor method) and the fit.
    pub orders: Vec<(String, Option<u32>, Option<OrderFit>)>,
    /// The Pareto front.
    pub pareto: Vec<Run>,
}

/// Measure `scene` and judge it.
pub fn report(
    scene: &Scene,
    timing: Timing,
    tick: impl FnMut(&str),
) -> Result<SceneReport, String> {
    let runs = measure(scene, &METHODS, timing, tick)?;
    let orders = METHODS
        .iter()
        .map(|m| ((*m).to_string(), order(m), observed_order(&runs, m)))
        .collect();
    let pareto = pareto(&runs).into_iter().cloned().collect();
    Ok(SceneReport {
        scene: scene.file.clone(),
        start: (scene.theta0, scene.rate0),
        to_flat: scene.end == End::Flat,
        runs,
        orders,
        pareto,
    })
}

fn csv(reports: &[SceneReport]) -> String {
    let mut s = String::from(
        "scene,method,tolerance,angle_error,time_error,flat_time_error,energy_error,rhs_evals,seconds_median,seconds_q1,seconds_q3,repeats\n",
    );
    for r in reports.iter().flat_map(|p| &p.runs) {
        s += &format!(
            "\"{}\",{},{:e},{:e},{:e},{},{:e},{},{:e},{:e},{:e},{}\n",
            r.scene,
            r.method,
            r.tolerance,
            r.angle_error,
            r.time_error,
            r.flat_time_error
                .map_or(String::new(), |e| format!("{e:e}")),
            r.energy_error,
            r.rhs_evals,
            r.seconds,
            r.seconds_iqr.0,
            r.seconds_iqr.1,
            r.repeats
        );
    }
    s
}

fn panel(rep: &SceneReport) -> (Chart, Vec<Series>) {
    // Real log axes (the chart draws decades); an error below 1e-17 is shown at 1e-17.
    let point = |r: &Run| (r.seconds, r.error().max(1e-17));
    let mut series: Vec<Series> = METHODS
        .iter()
        .map(|m| Series {
            name: (*m).into(),
            points: rep
                .runs
                .iter()
                .filter(|r| r.method == *m)
                .map(point)
                .collect(),
        })
        .collect();
    let mut front: Vec<(f64, f64)> = rep.pareto.iter().map(point).collect();
    front.sort_by(|a, b| a.0.total_cmp(&b.0));
    series.push(Series {
        name: "Pareto front".into(),
        points: front,
    });
    let what = if rep.to_flat {
        "separation and flat"
    } else {
        "separation angle and time"
    };
    let spec = PlotSpec {
        title: format!(
            "θ0 = {}, θ̇0 = {}{}",
            rep.start.0,
            rep.start.1,
            if rep.to_flat { ", to flat" } else { "" }
        ),
        x_label: "median run time per solve (s)".into(),
        y_label: format!("worse relative error ({what})"),
        ..Default::default()
    };
    let chart = Chart {
        spec,
        log_x: true,
        log_y: true,
        markers: true,
        dashed: vec!["Pareto front".into()],
        ..Default::default()
    };
    (chart, series)
}

fn print_report(rep: &SceneReport) {
    println!(
        "\nwork-precision for {} (θ0 = {}, θ̇0 = {}{})",
        rep.scene,
        rep.start.0,
        rep.start.1,
        if rep.to_flat {
            ", to flat; flat-time reference: Taylor order 40 at 1e-16 from the exact separation"
        } else {
            ""
        }
    );
    println!(
        "{:<17} {:>9} {:>10} {:>10} {:>10} {:>10} {:>9} {:>11} {:>19}",
        "method",
        "tol/step",
        "angle err",
        "time err",
        "flat err",
        "energy err",
        "rhs",
        "µs median",
        "µs q1-q3"
    );
    for r in &rep.runs {
        println!(
            "{:<17} {:>9.1e} {:>10.2e} {:>10.2e} {:>10} {:>10.2e} {:>9} {:>11.3} {:>19}",
            r.method,
            r.tolerance,
            r.angle_error,
            r.time_error,
            r.flat_time_error.map_or("-".into(), |e| format!("{e:.2e}")),
            r.energy_error,
            r.rhs_evals,
            r.seconds * 1e6,
            format!("{:.3}-{:.3}", r.seconds_iqr.0 * 1e6, r.seconds_iqr.1 * 1e6),
        );
    }
    println!(
        "observed order: slope of −ln(error) against ln(rhs evaluations) over runs with error in [floor, {:.0e}] whose work grows and is not tied (floor: min({:.0e}, {} × the sweep's rounding level); see work_precision_fit)",
        super::work_precision_fit::ASYMPTOTIC,
        super::work_precision_fit::FLOOR,
        super::work_precision_fit::ROUNDING_MARGIN,
    );
    for (m, theory, fit) in &rep.orders {
        let theory = theory.map_or("p(tol)".to_string(), |p| p.to_string());
        match fit {
            Some(f) => println!(
                "  {m:<17} theoretical {theory:<6} observed {:.2} over {} runs, rhs {}..{}, error {:.1e}..{:.1e} (floor {:.0e})",
                f.order, f.runs, f.rhs_range.0, f.rhs_range.1, f.error_range.0, f.error_range.1, f.floor
            ),
            None => println!("  {m:<17} theoretical {theory:<6} observed n/a (fewer than 3 runs in range)"),
        }
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

/// `ladder work-precision [SCENE...] [--json] [--out DIR]`: every scene given, or the built-in
/// list ([`default_scenes`]).
pub fn command(scene_paths: &[PathBuf], json: bool, out: Option<&Path>) -> ExitCode {
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
    let per_scene: usize = METHODS.iter().map(|m| sweep(m).len()).sum();
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
