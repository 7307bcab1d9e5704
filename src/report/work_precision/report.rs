//! The reporting half of work-precision: per scene the runs, the observed orders with their
//! fitted range and the Pareto front, for JSON, `runs.csv` and one SVG panel per scene (the
//! table is printed by `ladder work-precision`, in `crate::cli::work_precision`).

use crate::report::plot::{Chart, PlotSpec, Series};
use crate::report::svg_chart::decade_label;
use crate::report::work_precision::fit::{
    order_fit, pareto, tolerance_slope, OrderFit, Point, ToleranceSlope,
};
use crate::report::work_precision::{measure, Run, Timing, PEERS_OF};
use crate::sim::integrators::{is_adaptive, names, order};
use crate::sim::scene::{End, Scene};
use serde::Serialize;

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
    /// Per method: its classical order, the observed one or why not, and for the adaptive
    /// methods how the error follows the tolerance.
    pub orders: Vec<OrderRow>,
    /// The Taylor method at fixed orders ([`TAYLOR_ORDERS`]): the observed order of each.
    pub taylor_fixed: Vec<OrderRow>,
    /// The Pareto front.
    pub pareto: Vec<Run>,
}

/// One method's orders on one scene.
#[derive(Clone, Debug, Serialize)]
pub struct OrderRow {
    /// Method name.
    pub method: String,
    /// The Taylor method's fixed order (`[integrator] order`), for [`SceneReport::taylor_fixed`].
    pub fixed_order: Option<usize>,
    /// The classical order (None: the Taylor method's follows its tolerance).
    pub classical: Option<u32>,
    /// The observed order ([`order_fit`]), when fitted.
    pub observed: Option<OrderFit>,
    /// Why no order was fitted.
    pub not_fitted: Option<String>,
    /// Why the observed order differs from the classical one, where that is known.
    pub note: Option<String>,
    /// The error against the tolerance (adaptive methods), when fitted.
    pub tolerance_slope: Option<ToleranceSlope>,
    /// Why no tolerance slope was fitted (adaptive methods).
    pub tolerance_not_fitted: Option<String>,
}

/// The fixed orders at which the Taylor method's observed order is measured: its order is p
/// (the truncation of the series), not one number.
pub const TAYLOR_ORDERS: [usize; 3] = [4, 8, 12];

/// Why radau5's observed order is below its classical 5 (`tests/report/work_precision/radau5_order.rs` measures
/// it): its error estimate is of order 3, so its steps grow as τ^(−1/4), while its error
/// follows the tolerance: the error falls as steps⁻⁴.
pub const RADAU5_NOTE: &str = "classical 5, but its error estimate (radau5.f's) is of order 3: its steps grow as tol^(-1/4) while its error follows tol (slope ≈ 1), so the error falls as steps^-4";

fn order_row(runs: &[Run], method: &str, fixed_order: Option<usize>) -> OrderRow {
    let fit = order_fit(runs, method);
    let slope = is_adaptive(method).then(|| tolerance_slope(runs, method));
    OrderRow {
        method: method.into(),
        fixed_order,
        classical: fixed_order.map(|p| p as u32).or(order(method)),
        observed: fit.as_ref().ok().cloned(),
        not_fitted: fit.err(),
        note: (method == "radau5").then(|| RADAU5_NOTE.to_string()),
        tolerance_slope: slope.as_ref().and_then(|s| s.as_ref().ok().cloned()),
        tolerance_not_fitted: slope.and_then(|s| s.err()),
    }
}

/// Measure `scene` and judge it.
pub fn report(
    scene: &Scene,
    timing: Timing,
    tick: impl FnMut(&str),
) -> Result<SceneReport, String> {
    let methods: Vec<&str> = names().collect();
    #[allow(unused_mut)]
    let mut runs = measure(scene, &methods, timing, tick)?;
    // ode_solvers' DOP853 and Dopri5 in the same run (`--features peers`; see the module).
    #[cfg(feature = "peers")]
    runs.extend(crate::report::work_precision::peers::measure_peers(
        scene, timing,
    )?);
    let orders = methods.iter().map(|m| order_row(&runs, m, None)).collect();
    // The Taylor method at fixed orders: one timed repeat each (only the errors count here).
    let once = Timing {
        budget: 0.0,
        min: 1,
        max: 1,
    };
    let mut taylor_fixed = Vec::new();
    for p in TAYLOR_ORDERS {
        let mut sc = scene.clone();
        sc.order = Some(p);
        let fixed = measure(&sc, &["taylor"], once, |_| {})?;
        taylor_fixed.push(order_row(&fixed, "taylor", Some(p)));
    }
    // The front of this crate's runs: the peers were handed t_s (see `work_precision::peers`).
    let ours: Vec<Run> = runs
        .iter()
        .filter(|r| PEERS_OF.iter().all(|(p, _)| r.method != *p))
        .cloned()
        .collect();
    let pareto = pareto(&ours).into_iter().cloned().collect();
    Ok(SceneReport {
        scene: scene.file.clone(),
        start: (scene.theta0, scene.rate0),
        to_flat: scene.end == End::Flat,
        runs,
        orders,
        taylor_fixed,
        pareto,
    })
}

/// Every run of every scene as CSV (`runs.csv`).
pub fn csv(reports: &[SceneReport]) -> String {
    let mut s = String::from(
        "scene,method,tolerance,angle_error,time_error,flat_time_error,energy_error,rhs_evals,steps,floor_steps,seconds_median,seconds_q1,seconds_q3,repeats\n",
    );
    for r in reports.iter().flat_map(|p| &p.runs) {
        s += &format!(
            "\"{}\",{},{:e},{:e},{:e},{},{:e},{},{},{},{:e},{:e},{:e},{}\n",
            r.scene,
            r.method,
            r.tolerance,
            r.angle_error,
            r.time_error,
            r.flat_time_error
                .map_or(String::new(), |e| format!("{e:e}")),
            r.energy_error,
            r.rhs_evals,
            r.steps,
            r.floor_steps.map_or(String::new(), |f| f.to_string()),
            r.seconds,
            r.seconds_iqr.0,
            r.seconds_iqr.1,
            r.repeats
        );
    }
    s
}

/// One scene's panel of `work_precision.svg`: error against run time per method.
pub fn panel(rep: &SceneReport) -> (Chart, Vec<Series>) {
    // Real log axes (the chart draws decades); an error is at least the reference's accuracy.
    let point = |r: &Run| (r.seconds, r.error());
    let mut series: Vec<Series> = names()
        .map(|m| Series {
            name: m.into(),
            points: rep
                .runs
                .iter()
                .filter(|r| r.method == *m)
                .map(point)
                .collect(),
        })
        .collect();
    // The peers measured (`--features peers`), each beside the method it compares with.
    let mut peers = Vec::new();
    for (peer, of) in PEERS_OF {
        let points: Vec<(f64, f64)> = rep
            .runs
            .iter()
            .filter(|r| r.method == peer)
            .map(point)
            .collect();
        if !points.is_empty() {
            series.push(Series {
                name: peer.into(),
                points,
            });
            peers.push((peer.to_string(), of.to_string()));
        }
    }
    series.push(Series {
        name: "Pareto front".into(),
        points: staircase(rep.pareto.iter().map(point).collect()),
    });
    let what = if rep.to_flat {
        "θₛ, tₛ, flat time"
    } else {
        "θₛ and tₛ"
    };
    // The peers have no events, so a scene that runs to flat has none (`work_precision::peers`).
    let no_peers = if rep.to_flat && cfg!(feature = "peers") {
        " (no peers: no floor phase)"
    } else {
        ""
    };
    let spec = PlotSpec {
        title: format!(
            "θ0 = {} rad, θ̇0 = {} rad/s{}{no_peers}",
            number(rep.start.0),
            number(rep.start.1),
            if rep.to_flat { ", to flat" } else { "" }
        ),
        x_label: "median run time per solve (s)".into(),
        y_label: format!("worse rel. error of {what} (at least the reference's accuracy)"),
        ..Default::default()
    };
    let chart = Chart {
        spec,
        log_x: true,
        log_y: true,
        markers: true,
        peers,
        front: Some("Pareto front".into()),
        ..Default::default()
    };
    (chart, series)
}

/// The Pareto front as the boundary of the region it dominates: from each run across to the
/// next one's time, then down to its error (points sorted by time; their errors then fall).
pub fn staircase(mut front: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    front.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut out = Vec::with_capacity(2 * front.len());
    for (i, &p) in front.iter().enumerate() {
        if i > 0 {
            out.push((p.0, front[i - 1].1));
        }
        out.push(p);
    }
    out
}

/// A start value for a title: a power of ten as 10⁻⁶, otherwise as Rust prints it.
fn number(v: f64) -> String {
    let k = v.abs().log10().round();
    if v > 0.0 && k.abs() >= 3.0 && 10f64.powi(k as i32) == v {
        decade_label(k as i32)
    } else {
        v.to_string()
    }
}
