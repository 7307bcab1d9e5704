//! The peers of work-precision (issue 12, item 3): ode_solvers' DOP853 and Dopri5 (Hairer's
//! codes as ported to Rust), measured in the same run as this crate's methods and drawn as
//! dashed lines in `work_precision.svg`.
//!
//! **Why a feature.** ode_solvers (with nalgebra beneath it) is only needed to compare, never to
//! simulate, so the `ladder` binary does not carry it by default: it is an optional dependency
//! behind the cargo feature `peers` (and a dev-dependency of the criterion bench). Run
//! `cargo run --release --features peers -- work-precision --out DIR`. CI lints this path
//! (`.ci/run`); its test, `cargo test --features peers --test report work_precision::peers`, runs there
//! with `LADDER_SLOW=1` only (it needs a second optimised build of the library).
//!
//! **The task.** ode_solvers stops only at the ends of its steps and has no event location, so a
//! peer is handed the exact separation time t_s and asked for θ there: its error is
//! |θ(t_s) − θ_s| / θ_s, with no time error (it did not have to find t_s, an easier task than
//! ours). Scenes that run to flat are not measured for the peers (no floor phase, no event).
//! Right-hand-side evaluations are ode_solvers' own count; rtol = atol = the tolerance.

use crate::report::work_precision::{sweep, time_it, Run, Timing, PEERS_OF, SEPARATION_ACCURACY};
use crate::sim::exact::PhaseOne;
use crate::sim::scene::{End, Scene};
use ode_solvers::{OutputType, System, Vector2};

/// Eq. (5), θ̈ = Ω² sin θ, as ode_solvers' system.
struct Wall(f64);
impl System<f64, Vector2<f64>> for Wall {
    fn system(&self, _t: f64, y: &Vector2<f64>, dy: &mut Vector2<f64>) {
        dy[0] = y[1];
        dy[1] = self.0 * y[0].sin();
    }
}

/// θ(t) from (θ0, θ̇0) by the peer `name` at tolerance `tol`, with its rhs evaluations and
/// accepted steps; None when the peer fails.
pub fn theta_at(name: &str, tol: f64, scene: &Scene, t: f64) -> Option<(f64, u64, u64)> {
    let y0 = Vector2::new(scene.theta0, scene.rate0);
    let sys = Wall(scene.ladder.big_omega2());
    let (stats, last) = if name == PEERS_OF[0].0 {
        let mut s = ode_solvers::Dop853::new(sys, 0.0, t, t, y0, tol, tol);
        s.set_output(OutputType::Sparse);
        (s.integrate().ok()?, s.y_out().last().copied()?)
    } else {
        let mut s = ode_solvers::Dopri5::new(sys, 0.0, t, t, y0, tol, tol);
        s.set_output(OutputType::Sparse);
        (s.integrate().ok()?, s.y_out().last().copied()?)
    };
    last[0].is_finite().then_some((
        last[0],
        u64::from(stats.num_eval),
        u64::from(stats.accepted_steps),
    ))
}

/// Every run of the peers on `scene` (none for a scene that runs to flat), timed like ours.
pub fn measure_peers(scene: &Scene, timing: Timing) -> Result<Vec<Run>, String> {
    if scene.end == End::Flat {
        return Ok(Vec::new());
    }
    let exact = PhaseOne::new(scene.theta0, scene.rate0, scene.ladder.big_omega2())?
        .separation()
        .ok_or("the start is the equilibrium: no separation")?;
    let mut runs = Vec::new();
    for (name, ours) in PEERS_OF {
        for tol in sweep(ours) {
            let Some((theta, rhs_evals, steps)) = theta_at(name, tol, scene, exact.time) else {
                continue;
            };
            let (seconds, seconds_iqr, repeats) = time_it(timing, || {
                std::hint::black_box(theta_at(name, std::hint::black_box(tol), scene, exact.time));
            });
            runs.push(Run {
                scene: scene.file.clone(),
                method: name.into(),
                tolerance: tol,
                angle_error: (theta - exact.angle).abs() / exact.angle,
                time_error: 0.0,
                flat_time_error: None,
                energy_error: f64::NAN,
                rhs_evals,
                steps,
                floor_steps: None,
                seconds,
                seconds_iqr,
                repeats,
                reference_accuracy: SEPARATION_ACCURACY,
            });
        }
    }
    Ok(runs)
}
