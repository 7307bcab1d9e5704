//! Integrators side by side, in the same run: every method of this crate on the same scenes,
//! and the peer crate ode_solvers 0.6 (Dop853, Dopri5) at equal error.
//!
//! Equal error: for each solver the largest tolerance (from 1e-4 down to 1e-16, by decades)
//! whose error is at most the target is chosen before timing (printed on stderr). The common task
//! is "θ at the exact separation time t_s" (ode_solvers has no event location); this crate's
//! separation with event location is timed too, beside one closed-form evaluation, and the whole
//! fall to flat (reference: the closed-form separation time plus the floor phase's duration
//! by quadrature of its energy integral, `exact::flat`; the Taylor method at 1e-16 is compared
//! with it on stderr). Run: `cargo bench --features bench --bench integrators`; only the Taylor
//! comparisons of issue 13: `cargo bench --features bench --bench integrators -- at-1e-12`, which ends with a
//! table of the medians of that run and their ratios to the Taylor method (with the load
//! average: on a shared machine only ratios within one run are comparable).

use criterion::{criterion_group, Criterion};
use ode_solvers::{OutputType, System, Vector2};
use sliding_ladder::report::campaign::judge::reference_separation_time;
use sliding_ladder::report::work_precision::scene_at;
use sliding_ladder::sim::exact::flat::floor_duration;
use sliding_ladder::sim::exact::{separation_cos, PhaseOne};
use sliding_ladder::sim::fall;
use sliding_ladder::sim::integrators::dop853::Dop853;
use sliding_ladder::sim::integrators::dopri5::Dopri5;
use sliding_ladder::sim::integrators::taylor::Taylor;
use sliding_ladder::sim::integrators::{Control, Stepper};
use sliding_ladder::sim::rigid::WallPhase;

use sliding_ladder::ladder::Ladder;
use sliding_ladder::sim::scene::{End, Scene};
use sliding_ladder::sim::units::Units;
use std::hint::black_box;
use std::time::Duration;

const LADDER: Ladder<f64> = Ladder {
    m: 1.0,
    l: 1.0,
    g: 9.81,
};
/// (name, θ0, θ̇0)
const SCENES: [(&str, f64, f64); 3] = [
    ("from-rest-0.1", 0.1, 0.0),
    ("from-rest-0.3", 0.3, 0.0),
    ("classic", 0.0, 1e-6),
];

struct Peer(f64);
impl System<f64, Vector2<f64>> for Peer {
    fn system(&self, _t: f64, y: &Vector2<f64>, dy: &mut Vector2<f64>) {
        dy[0] = y[1];
        dy[1] = self.0 * y[0].sin();
    }
}

fn peer_theta(dop853: bool, tol: f64, theta0: f64, rate0: f64, t: f64) -> f64 {
    let y0 = Vector2::new(theta0, rate0);
    let sys = Peer(LADDER.big_omega2());
    let last = if dop853 {
        let mut s = ode_solvers::Dop853::new(sys, 0.0, t, t, y0, tol, tol);
        s.set_output(OutputType::Sparse);
        let _ = s.integrate();
        s.y_out().last().copied()
    } else {
        let mut s = ode_solvers::Dopri5::new(sys, 0.0, t, t, y0, tol, tol);
        s.set_output(OutputType::Sparse);
        let _ = s.integrate();
        s.y_out().last().copied()
    };
    last.map_or(f64::NAN, |y| y[0])
}

/// θ(t) by one of this crate's steppers, stepping to `t` exactly.
fn run_to<St: Stepper<2>>(mut s: St, t: f64) -> f64 {
    let sys = WallPhase::new(&LADDER);
    while s.t() < t {
        if s.step(&sys, t).is_err() {
            return f64::NAN;
        }
    }
    s.y()[0]
}

fn our_theta(method: &str, tol: f64, theta0: f64, rate0: f64, t: f64) -> f64 {
    let y0 = [theta0, rate0];
    match method {
        "dop853" => run_to(Dop853::new(0.0, y0, tol), t),
        "dopri5" => run_to(Dopri5::new(0.0, y0, tol), t),
        _ => run_to(Taylor::new(0.0, y0, tol), t),
    }
}

/// Largest decade tolerance whose relative error `err(tol)` is at most `target`.
fn pick(err: &dyn Fn(f64) -> f64, target: f64) -> Option<(f64, f64)> {
    (4..=16).map(|k| 10f64.powi(-k)).find_map(|tol| {
        let e = err(tol);
        (e <= target).then_some((tol, e))
    })
}

fn configure() -> Criterion {
    Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .sample_size(30)
}

fn bench_peers(c: &mut Criterion) {
    for (name, theta0, rate0) in SCENES {
        let sep = PhaseOne::new(theta0, rate0, LADDER.big_omega2())
            .unwrap()
            .separation()
            .unwrap();
        for target in [1e-8, 1e-12] {
            let mut g = c.benchmark_group(format!("{name}/theta-at-ts/error<={target:e}"));
            for label in [
                "ours-taylor",
                "ours-dop853",
                "ode_solvers-dop853",
                "ours-dopri5",
                "ode_solvers-dopri5",
            ] {
                let f = |tol: f64| match label {
                    "ode_solvers-dop853" => peer_theta(true, tol, theta0, rate0, sep.time),
                    "ode_solvers-dopri5" => peer_theta(false, tol, theta0, rate0, sep.time),
                    _ => our_theta(&label[5..], tol, theta0, rate0, sep.time),
                };
                let Some((tol, err)) = pick(&|tol| (f(tol) - sep.angle).abs() / sep.angle, target)
                else {
                    eprintln!("{name}: {label} never reaches {target:e}");
                    continue;
                };
                eprintln!(
                    "{name}: {label} tolerance {tol:e} gives error {err:.2e} (target {target:e})"
                );
                g.bench_function(label, |b| b.iter(|| f(black_box(tol))));
            }
            g.finish();
        }
    }
}

fn scene_with(theta0: f64, rate0: f64, method: &str, ctl: Control, end: End) -> Scene {
    let mut sc = scene_at(theta0, rate0);
    sc.method = method.into();
    sc.control = Some(ctl);
    sc.end = end;
    sc
}

/// Issue 13's targets: separation (with event location) at angle error ≤ 1e-12 beside one
/// closed-form evaluation, and the whole fall to flat at flat-time error ≤ 1e-12.
fn bench_at_1e12(c: &mut Criterion) {
    let target = 1e-12;
    for (name, theta0, rate0) in &SCENES[..2] {
        let (theta0, rate0) = (*theta0, *rate0);
        let exact = PhaseOne::new(theta0, rate0, LADDER.big_omega2())
            .unwrap()
            .separation()
            .unwrap();
        let mut g = c.benchmark_group(format!("{name}/separation-at-1e-12"));
        g.bench_function("closed-form", |b| {
            b.iter(|| {
                PhaseOne::new(black_box(theta0), black_box(rate0), LADDER.big_omega2())
                    .ok()
                    .and_then(|p| p.separation())
            })
        });
        // The peer has no event location: it is handed the exact separation time and timed
        // for θ there, an easier task than ours (which finds t_s too).
        let peer_err = |tol| {
            (peer_theta(true, tol, theta0, rate0, exact.time) - exact.angle).abs() / exact.angle
        };
        match pick(&peer_err, target) {
            Some((tol, e)) => {
                eprintln!("{name}: ode_solvers-dop853 θ(t_s), tolerance {tol:e} gives angle error {e:.2e}");
                g.bench_function("ode_solvers-dop853", |b| {
                    b.iter(|| peer_theta(true, black_box(tol), theta0, rate0, exact.time))
                });
            }
            None => eprintln!("{name}: ode_solvers-dop853 never reaches {target:e}"),
        }
        for m in ["taylor", "dop853"] {
            let sc = |tol| scene_with(theta0, rate0, m, Control::Tolerance(tol), End::Separation);
            let err = |tol| {
                fall::run(&sc(tol), fall::MAX_STEPS)
                    .ok()
                    .and_then(|o| o.separation)
                    .map_or(f64::INFINITY, |s| {
                        (s.angle - exact.angle).abs() / exact.angle
                    })
            };
            let Some((tol, e)) = pick(&err, target) else {
                eprintln!("{name}: {m} never reaches {target:e}");
                continue;
            };
            eprintln!("{name}: {m} separation, tolerance {tol:e} gives angle error {e:.2e}");
            let sc = sc(tol);
            g.bench_function(m, |b| {
                b.iter(|| fall::run(black_box(&sc), fall::MAX_STEPS).ok())
            });
        }
        g.finish();
    }
    // The whole fall to flat from θ0 = 0.3: reference flat time from the closed forms (the
    // wall phase's separation time plus the floor phase's duration by quadrature of its energy
    // integral, `exact::flat`), independent of every integrator here.
    let flat = |m: &str, tol: f64| {
        fall::run(
            &scene_with(0.3, 0.0, m, Control::Tolerance(tol), End::Flat),
            fall::MAX_STEPS,
        )
        .ok()
        .and_then(|o| o.flat)
    };
    let whole = scene_at(0.3, 0.0);
    let cos_s = separation_cos(0.3, 0.0, LADDER.big_omega2());
    let reference = (reference_separation_time(&whole).expect("closed form").0
        + floor_duration(cos_s))
        * Units::of(&LADDER).time;
    if let Some(t) = flat("taylor", 1e-16) {
        eprintln!(
            "full fall: reference flat time {reference} (taylor at 1e-16 differs by {:.1e})",
            (t.time - reference).abs() / reference
        );
    }
    let mut g = c.benchmark_group("full-fall-0.3/flat-at-1e-12");
    for m in ["taylor", "dop853"] {
        let err =
            |tol| flat(m, tol).map_or(f64::INFINITY, |f| (f.time - reference).abs() / reference);
        let Some((tol, e)) = pick(&err, target) else {
            eprintln!("full fall: {m} never reaches {target:e}");
            continue;
        };
        eprintln!("full fall: {m} tolerance {tol:e} gives flat-time error {e:.2e}");
        let sc = scene_with(0.3, 0.0, m, Control::Tolerance(tol), End::Flat);
        g.bench_function(m, |b| {
            b.iter(|| fall::run(black_box(&sc), fall::MAX_STEPS).ok())
        });
    }
    g.finish();
}

fn bench_methods(c: &mut Criterion) {
    let settings = [
        ("euler", Control::Fixed(1e-5)),
        ("symplectic-euler", Control::Fixed(1e-5)),
        ("verlet", Control::Fixed(1e-3)),
        ("rk4", Control::Fixed(1e-2)),
        ("dopri5", Control::Tolerance(1e-8)),
        ("dop853", Control::Tolerance(1e-8)),
        ("dop853", Control::Tolerance(1e-12)),
        ("radau5", Control::Tolerance(1e-8)),
        ("taylor", Control::Tolerance(1e-8)),
        ("taylor", Control::Tolerance(1e-12)),
    ];
    for (name, theta0, rate0) in SCENES {
        let mut g = c.benchmark_group(format!("{name}/separation-with-event"));
        let exact = PhaseOne::new(theta0, rate0, LADDER.big_omega2())
            .unwrap()
            .separation()
            .unwrap();
        for (m, ctl) in settings {
            let sc = scene_with(theta0, rate0, m, ctl, End::Separation);
            let s = fall::run(&sc, fall::MAX_STEPS).unwrap().separation.unwrap();
            let label = match ctl {
                Control::Fixed(h) => format!("{m}/h={h:e}"),
                Control::Tolerance(t) => format!("{m}/tol={t:e}"),
            };
            eprintln!(
                "{name}: {label} angle error {:.2e}",
                (s.angle - exact.angle).abs() / exact.angle
            );
            g.bench_function(label, |b| {
                b.iter(|| fall::run(black_box(&sc), fall::MAX_STEPS).ok())
            });
        }
        g.finish();
    }
}

criterion_group! { name = benches; config = configure(); targets = bench_at_1e12, bench_peers, bench_methods }

/// The groups of issue 13 whose medians are summarised after the run, with their members.
const SUMMARY: [(&str, &[&str]); 3] = [
    (
        "from-rest-0.1/separation-at-1e-12",
        &["taylor", "dop853", "ode_solvers-dop853", "closed-form"],
    ),
    (
        "from-rest-0.3/separation-at-1e-12",
        &["taylor", "dop853", "ode_solvers-dop853", "closed-form"],
    ),
    ("full-fall-0.3/flat-at-1e-12", &["taylor", "dop853"]),
];

/// Criterion's median (ns per solve) of `group`/`name`, if this run wrote it (files from an
/// earlier run, or from a run filtered to other groups, are left out: ratios are only quoted
/// between benches of one run).
fn median_ns(group: &str, name: &str, since: std::time::SystemTime) -> Option<f64> {
    let target = std::env::var("CARGO_TARGET_DIR").unwrap_or_else(|_| "target".into());
    let dir = format!(
        "{target}/criterion/{}/{name}/new/estimates.json",
        group.replace('/', "_")
    );
    let meta = std::fs::metadata(&dir).ok()?;
    if meta.modified().ok()? < since {
        return None;
    }
    let v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&dir).ok()?).ok()?;
    v["median"]["point_estimate"].as_f64()
}

/// Medians of the issue-13 groups and their ratios to the Taylor method, for README's table.
fn summary(since: std::time::SystemTime) {
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    let load = load
        .split_whitespace()
        .take(3)
        .collect::<Vec<_>>()
        .join(" ");
    eprintln!("\nmedians per solve of this run (load average at the end: {load})");
    for (group, names) in SUMMARY {
        let Some(taylor) = median_ns(group, "taylor", since) else {
            continue;
        };
        for name in names.iter() {
            if let Some(m) = median_ns(group, name, since) {
                eprintln!(
                    "{group:38} {name:20} {:8.3} µs   {:5.2}x taylor's",
                    m / 1e3,
                    m / taylor
                );
            }
        }
    }
}

fn main() {
    let since = std::time::SystemTime::now();
    benches();
    Criterion::default().configure_from_args().final_summary();
    summary(since);
}
