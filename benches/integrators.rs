//! Integrators side by side, in the same run: every method of this crate on the same scenes,
//! and the peer crate ode_solvers 0.6 (Dop853, Dopri5) at equal error.
//!
//! Equal error: for each solver the largest tolerance (from 1e-4 down to 1e-15, by decades)
//! whose error is at most the target is chosen before timing (printed on stderr). The common task
//! is "θ at the exact separation time t_s" (ode_solvers has no event location); this crate's
//! separation with event location is timed too. Run: `cargo bench --bench integrators`.

use criterion::{criterion_group, criterion_main, Criterion};
use ode_solvers::{OutputType, System, Vector2};
use sliding_ladder::report::work_precision::scene_at;
use sliding_ladder::sim::exact::PhaseOne;
use sliding_ladder::sim::fall;
use sliding_ladder::sim::integrators::dop853::Dop853;
use sliding_ladder::sim::integrators::dopri5::Dopri5;
use sliding_ladder::sim::integrators::{Control, Stepper};
use sliding_ladder::sim::rigid::{Ladder, WallPhase};
use std::hint::black_box;
use std::time::Duration;

const LADDER: Ladder = Ladder {
    mass: 1.0,
    half_length: 1.0,
    gravity: 9.81,
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
    let sys = Peer(LADDER.omega2());
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

fn our_theta(dop853: bool, tol: f64, theta0: f64, rate0: f64, t: f64) -> f64 {
    let sys = WallPhase::new(&LADDER);
    if dop853 {
        let mut s = Dop853::new(0.0, [theta0, rate0], tol);
        while s.t() < t {
            if s.step(&sys, t).is_err() {
                return f64::NAN;
            }
        }
        s.y()[0]
    } else {
        let mut s = Dopri5::new(0.0, [theta0, rate0], tol);
        while s.t() < t {
            if s.step(&sys, t).is_err() {
                return f64::NAN;
            }
        }
        s.y()[0]
    }
}

/// Largest decade tolerance with relative error of θ(t_s) at most `target`.
fn pick(f: &dyn Fn(f64) -> f64, exact: f64, target: f64) -> Option<(f64, f64)> {
    (4..=15).map(|k| 10f64.powi(-k)).find_map(|tol| {
        let e = (f(tol) - exact).abs() / exact;
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
        let sep = PhaseOne::new(theta0, rate0, LADDER.omega2())
            .unwrap()
            .separation()
            .unwrap();
        for target in [1e-8, 1e-12] {
            let mut g = c.benchmark_group(format!("{name}/theta-at-ts/error<={target:e}"));
            for (label, ours, dop853) in [
                ("ours-dop853", true, true),
                ("ode_solvers-dop853", false, true),
                ("ours-dopri5", true, false),
                ("ode_solvers-dopri5", false, false),
            ] {
                let f = |tol: f64| {
                    if ours {
                        our_theta(dop853, tol, theta0, rate0, sep.time)
                    } else {
                        peer_theta(dop853, tol, theta0, rate0, sep.time)
                    }
                };
                let Some((tol, err)) = pick(&f, sep.angle, target) else {
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
    ];
    for (name, theta0, rate0) in SCENES {
        let mut g = c.benchmark_group(format!("{name}/separation-with-event"));
        let exact = PhaseOne::new(theta0, rate0, LADDER.omega2())
            .unwrap()
            .separation()
            .unwrap();
        for (m, ctl) in settings {
            let mut sc = scene_at(theta0, rate0);
            sc.method = m.into();
            sc.control = Some(ctl);
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

criterion_group! { name = benches; config = configure(); targets = bench_peers, bench_methods }
criterion_main!(benches);
