//! Work-precision: for every integrator a sweep of tolerances (adaptive) or steps (fixed), the
//! error of the separation angle, time and energy against the exact reference, the run time
//! (warm, median of repeats), the right-hand-side evaluations and the observed order.
//! Modelled on DiffEqDevTools.jl (`WorkPrecision`): a plain record per run, plotting apart.

use super::files::OutFile;
use super::plot::{PlotSpec, Series};
use crate::sim::exact::PhaseOne;
use crate::sim::fall;
use crate::sim::integrators::{is_adaptive, Control, RIGID_METHODS as METHODS};
use crate::sim::output::Output;
use crate::sim::rigid::Ladder;
use crate::sim::scene::{End, Scene};
use serde::Serialize;
use std::time::Instant;

/// One run of one method at one tolerance or step.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Run {
    /// Method name.
    pub method: String,
    /// Tolerance (adaptive) or step in s (fixed).
    pub tolerance: f64,
    /// |θ_s − θ_s,exact| / θ_s,exact.
    pub angle_error: f64,
    /// |t_s − t_s,exact| / t_s,exact.
    pub time_error: f64,
    /// |E(t_s) − E(0)| / (m g l).
    pub energy_error: f64,
    /// Right-hand-side evaluations (f64).
    pub rhs_evals: u64,
    /// Median wall-clock seconds per solve (warm).
    pub seconds: f64,
}

/// The sweep of each method: tolerances or steps.
pub fn sweep(method: &str) -> Vec<f64> {
    let decades = |a: i32, b: i32| (a..=b).map(|k| 10f64.powi(-k)).collect::<Vec<_>>();
    let halves = |h0: f64, n: i32| (0..n).map(|k| h0 / 2f64.powi(k)).collect::<Vec<_>>();
    match method {
        "dop853" => decades(3, 16),
        "taylor" => decades(3, 16),
        "dopri5" => decades(3, 15),
        "radau5" => decades(3, 13),
        "rk4" => halves(0.1, 10),
        "verlet" => halves(0.05, 10),
        _ => halves(0.01, 9),
    }
}

/// The default scene of the sweep: from rest at θ0 = 0.3 (scenes/from-rest.toml).
pub fn default_scene() -> Scene {
    scene_at(0.3, 0.0)
}

/// A from-rest style scene at (θ0, θ̇0), m = l = 1, g = 9.81, ending at separation.
pub fn scene_at(theta0: f64, rate0: f64) -> Scene {
    Scene {
        file: format!("(built in: θ0 = {theta0}, θ̇0 = {rate0})"),
        ladder: Ladder {
            mass: 1.0,
            half_length: 1.0,
            gravity: 9.81,
        },
        theta0,
        rate0,
        method: "dop853".into(),
        control: Some(Control::Tolerance(1e-12)),
        end: End::Separation,
        outputs: vec![
            Output::SeparationAngle,
            Output::SeparationTime,
            Output::EnergyError,
        ],
        contact: crate::sim::scene::ContactModel::Rigid,
    }
}

/// Median of `f`'s wall time after one warm-up, repeated until ~20 ms or 51 times (at least 3).
pub fn median_seconds(mut f: impl FnMut()) -> f64 {
    let t = Instant::now();
    f();
    let once = t.elapsed().as_secs_f64().max(1e-9);
    let reps = ((0.02 / once).ceil() as usize).clamp(3, 51);
    let mut v: Vec<f64> = (0..reps)
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64()
        })
        .collect();
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// All runs for `base` (its ladder and start; method, end and outputs are replaced), calling
/// `tick` after each run. Runs that fail (e.g. the step limit) are skipped.
pub fn measure(base: &Scene, mut tick: impl FnMut(&str)) -> Result<Vec<Run>, String> {
    let exact = PhaseOne::new(base.theta0, base.rate0, base.ladder.omega2())?
        .separation()
        .ok_or("the start is the equilibrium: no separation")?;
    let (m, l, g) = (
        base.ladder.mass,
        base.ladder.half_length,
        base.ladder.gravity,
    );
    let e0 = crate::sim::rigid::energy(&base.ladder, base.theta0, base.rate0);
    let mut runs = Vec::new();
    for method in METHODS {
        for tol in sweep(method) {
            let mut sc = base.clone();
            sc.method = method.into();
            sc.control = Some(if is_adaptive(method) {
                Control::Tolerance(tol)
            } else {
                Control::Fixed(tol)
            });
            sc.end = End::Separation;
            sc.outputs = vec![Output::SeparationAngle, Output::SeparationTime];
            tick(method);
            let Ok(o) = fall::run(&sc, fall::MAX_STEPS) else {
                continue;
            };
            let Some(s) = o.separation else { continue };
            let seconds = median_seconds(|| {
                std::hint::black_box(fall::run(std::hint::black_box(&sc), fall::MAX_STEPS).ok());
            });
            let e1 = crate::sim::rigid::energy(&base.ladder, s.angle, s.rate);
            runs.push(Run {
                method: method.into(),
                tolerance: tol,
                angle_error: (s.angle - exact.angle).abs() / exact.angle,
                time_error: (s.time - exact.time).abs() / exact.time,
                energy_error: (e1 - e0).abs() / (m * g * l),
                rhs_evals: o.work.wall.rhs_evals,
                seconds,
            });
        }
    }
    Ok(runs)
}

/// Observed order: least-squares slope of −log(angle error) against log(rhs evaluations), over
/// runs whose error lies in (1e-12, 1e-2) (above rounding, inside the asymptotic regime).
pub fn observed_order(runs: &[Run], method: &str) -> Option<f64> {
    let pts: Vec<(f64, f64)> = runs
        .iter()
        .filter(|r| r.method == method && r.angle_error > 1e-12 && r.angle_error < 1e-2)
        .map(|r| ((r.rhs_evals as f64).ln(), -r.angle_error.ln()))
        .collect();
    if pts.len() < 3 {
        return None;
    }
    let n = pts.len() as f64;
    let (mx, my) = (
        pts.iter().map(|p| p.0).sum::<f64>() / n,
        pts.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}

/// Runs not beaten by another run in both seconds and (worse of angle and time) error.
pub fn pareto(runs: &[Run]) -> Vec<&Run> {
    let err = |r: &Run| r.angle_error.max(r.time_error);
    let mut front: Vec<&Run> = runs
        .iter()
        .filter(|r| {
            !runs
                .iter()
                .any(|q| q.seconds < r.seconds && err(q) < err(r))
        })
        .collect();
    front.sort_by(|a, b| a.seconds.total_cmp(&b.seconds));
    front
}

/// The runs as CSV, one row per run (`runs.csv`).
pub fn csv(runs: &[Run]) -> String {
    let mut s =
        String::from("method,tolerance,angle_error,time_error,energy_error,rhs_evals,seconds\n");
    for r in runs {
        s += &format!(
            "{},{:e},{:e},{:e},{:e},{},{:e}\n",
            r.method,
            r.tolerance,
            r.angle_error,
            r.time_error,
            r.energy_error,
            r.rhs_evals,
            r.seconds
        );
    }
    s
}

/// The work-precision figure (`work_precision.svg`): error against run time per method.
pub fn plot(runs: &[Run], title: &str) -> OutFile {
    let series = METHODS
        .iter()
        .map(|m| Series {
            name: (*m).into(),
            points: runs
                .iter()
                .filter(|r| r.method == *m)
                .map(|r| (r.seconds.log10(), r.angle_error.max(1e-17).log10()))
                .collect(),
        })
        .collect();
    let spec = PlotSpec {
        title: format!("work-precision: {title}"),
        x_label: "log10 run time per solve (s)".into(),
        y_label: "log10 relative error of the separation angle".into(),
        ..Default::default()
    };
    OutFile::plot("work_precision.svg", spec, series)
}
