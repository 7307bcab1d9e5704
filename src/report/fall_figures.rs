//! The files `ladder simulate --out` writes for a fall: the trajectory and the contact forces,
//! as CSV and as charts that mark the events: the separation from the wall (where F_w reaches
//! zero: past it the wall would have to pull), the flat landing, and F_w crossing zero.

use super::files::OutFile;
use super::plot::{zero_crossings, Chart, Mark, PlotSpec, Series};
use crate::sim::fall::{Outcome, Sample};
use crate::sim::rigid::separation_cosine;
use crate::sim::scene::output::Output;
use crate::sim::scene::Scene;

fn csv_rows(trace: &[Sample], forces: bool) -> String {
    let mut s = String::from(if forces {
        "phase,t,theta,rate,wall_force,floor_force\n"
    } else {
        "phase,t,theta,rate\n"
    });
    for p in trace {
        s += &format!("{},{:e},{:e},{:e}", p.phase, p.t, p.theta, p.rate);
        if let (true, Some((fw, ff))) = (forces, p.forces) {
            s += &format!(",{fw:e},{ff:e}");
        }
        s.push('\n');
    }
    s
}

/// The events of a fall on the time axis: separation and flat, when they happened.
pub fn time_marks(o: &Outcome) -> Vec<Mark> {
    let mut m = Vec::new();
    if let Some(s) = &o.separation {
        m.push(Mark {
            x: s.time,
            label: format!("separation, t = {:.4} s", s.time),
        });
    }
    if let Some(f) = &o.flat {
        m.push(Mark {
            x: f.time,
            label: format!("flat, t = {:.4} s", f.time),
        });
    }
    m
}

/// Where the wall force of the wall phase crosses zero (None when it stays on one side); the
/// wall phase ends there, so it lies at the separation within the trace's sampling.
fn wall_force_zero(points: &[(f64, f64)]) -> Option<Mark> {
    zero_crossings(points).first().map(|&x| Mark {
        x,
        label: "F_w = 0".into(),
    })
}

/// "from rest at θ0 = 0.300 rad (17.19°)", or with θ̇0 when the start is not at rest.
pub fn start_words(scene: &Scene) -> String {
    let at = format!(
        "θ0 = {:.3} rad ({:.2}°)",
        scene.theta0,
        scene.theta0.to_degrees()
    );
    if scene.rate0 == 0.0 {
        format!("from rest at {at}")
    } else {
        format!("from {at}, θ̇0 = {} rad/s", scene.rate0)
    }
}

/// The CSV and SVG files of a scene's trace (what its `[outputs]` ask for), each title saying
/// where the fall starts ([`start_words`]).
pub fn files(scene: &Scene, o: &Outcome) -> Vec<OutFile> {
    let mut v = Vec::new();
    let Some(trace) = &o.trace else { return v };
    // Every title says where the fall starts: the figures differ by θ0 (and θ̇0) alone.
    let start = start_words(scene);
    if scene.outputs.contains(&Output::Trajectory) {
        trajectory_files(&mut v, trace, o, &start);
    }
    if scene.outputs.contains(&Output::Forces) {
        force_files(&mut v, scene, (trace, o), &start);
    }
    v
}

/// One line of a chart: the samples of `trace` that `f` maps to a point.
fn series(trace: &[Sample], name: &str, f: &dyn Fn(&Sample) -> Option<(f64, f64)>) -> Series {
    Series {
        name: name.into(),
        points: trace.iter().filter_map(f).collect(),
    }
}

/// `trajectory.csv` and `trajectory.svg`: θ and θ̇ against t.
fn trajectory_files(v: &mut Vec<OutFile>, trace: &[Sample], o: &Outcome, start: &str) {
    v.push(OutFile::text("trajectory.csv", csv_rows(trace, false)));
    let chart = Chart {
        spec: PlotSpec {
            title: format!("The fall: θ and θ̇ against t, {start}"),
            x_label: "t (s)".into(),
            y_label: "θ (rad), θ̇ (rad/s)".into(),
            ..Default::default()
        },
        marks: time_marks(o),
        ..Default::default()
    };
    let lines = vec![
        series(trace, "θ (rad)", &|p| Some((p.t, p.theta))),
        series(trace, "θ̇ (rad/s)", &|p| Some((p.t, p.rate))),
    ];
    v.push(OutFile::chart("trajectory.svg", chart, lines));
}

/// `forces.csv`, `forces_t.svg` and `forces_theta.svg`: F_w and F_f against t and against θ,
/// with where the wall force reaches zero.
fn force_files(
    v: &mut Vec<OutFile>,
    scene: &Scene,
    (trace, o): (&[Sample], &Outcome),
    start: &str,
) {
    v.push(OutFile::text("forces.csv", csv_rows(trace, true)));
    let fw = |x: fn(&Sample) -> f64| move |p: &Sample| p.forces.map(|f| (x(p), f.0));
    let ff = |x: fn(&Sample) -> f64| move |p: &Sample| p.forces.map(|f| (x(p), f.1));
    let wall_phase = |x: fn(&Sample) -> f64| -> Vec<(f64, f64)> {
        trace
            .iter()
            .filter(|p| p.phase == 1)
            .filter_map(|p| p.forces.map(|f| (x(p), f.0)))
            .collect()
    };
    let mut t_marks = time_marks(o);
    t_marks.extend(wall_force_zero(&wall_phase(|p| p.t)));
    let t_chart = Chart {
        spec: PlotSpec {
            title: format!("Contact forces against t, {start}"),
            x_label: "t (s)".into(),
            y_label: "force (N)".into(),
            hlines: vec![0.0],
            ..Default::default()
        },
        marks: t_marks,
        ..Default::default()
    };
    let lines = vec![
        series(trace, "F_w, wall (N)", &fw(|p| p.t)),
        series(trace, "F_f, floor (N)", &ff(|p| p.t)),
    ];
    v.push(OutFile::chart("forces_t.svg", t_chart, lines));
    let cs = separation_cosine(scene.ladder.big_omega2(), scene.theta0, scene.rate0);
    let mut th_marks = vec![Mark {
        x: cs.acos(),
        label: "cos θ = (2 cos θ0 + θ̇0²/Ω²)/3".into(),
    }];
    th_marks.extend(wall_force_zero(&wall_phase(|p| p.theta)));
    let th_chart = Chart {
        spec: PlotSpec {
            title: format!("Contact forces against θ, {start}"),
            x_label: "θ (rad)".into(),
            y_label: "force (N)".into(),
            hlines: vec![0.0],
            ..Default::default()
        },
        marks: th_marks,
        ..Default::default()
    };
    let lines = vec![
        series(trace, "F_w, wall (N)", &fw(|p| p.theta)),
        series(trace, "F_f, floor (N)", &ff(|p| p.theta)),
    ];
    v.push(OutFile::chart("forces_theta.svg", th_chart, lines));
}
