//! Work-precision: for every integrator a sweep of tolerances (adaptive) or steps (fixed), on a
//! list of scenes, the error against an independent reference, the run time (warm; median of
//! repeats with the interquartile spread), the right-hand-side evaluations, the observed order
//! on the asymptotic range and the Pareto front ([`super::work_precision::fit`]).
//! Modelled on DiffEqDevTools.jl (`WorkPrecisionSet`): a plain record per run, plotting apart.
//!
//! References, independent of every integrator: the separation from the exact closed form
//! (`sim::exact`, within 1.1 ulps in angle and 1.6 in time of mpmath, `tests/sim/exact/ulps.rs`);
//! the full fall's flat time as that separation time plus the floor phase's duration by
//! quadrature of its conservation laws (`sim::exact::flat`, within 16 ε of mpmath). An error
//! below a reference's accuracy ([`SEPARATION_ACCURACY`], [`FLAT_ACCURACY`]) is not measured:
//! a run's error is counted as at least that ([`Run::error`]), so no point of a fit or of the
//! Pareto front lies below it. (The flat reference was the Taylor method at order 40 and
//! tolerance 1e-16, one of the methods measured; the front ended on an error of 0.)

pub mod fit;
#[cfg(feature = "peers")]
pub mod peers;
pub mod report;

use super::work_precision::fit::Point;
use crate::ladder::Ladder;
use crate::sim::exact::flat::floor_duration;
use crate::sim::exact::{separation_cos, PhaseOne, Separation};
use crate::sim::fall;
use crate::sim::integrators::{card, is_adaptive, Control};
use crate::sim::scene::output::Output;
use crate::sim::scene::{End, Scene};
use serde::Serialize;
use std::time::Instant;

/// The peers' names and the method each compares with (`--features peers`, see
/// `report::work_precision::peers`): ode_solvers' DOP853 and Dopri5.
pub const PEERS_OF: [(&str, &str); 2] = [
    ("ode_solvers-dop853", "dop853"),
    ("ode_solvers-dopri5", "dopri5"),
];

/// One run of one method at one tolerance or step on one scene.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Run {
    /// The scene's label.
    pub scene: String,
    /// Method name.
    pub method: String,
    /// Tolerance (adaptive) or step in s (fixed).
    pub tolerance: f64,
    /// |θ_s − θ_s,exact| / θ_s,exact.
    pub angle_error: f64,
    /// |t_s − t_s,exact| / t_s,exact.
    pub time_error: f64,
    /// |t_flat − t_flat,ref| / t_flat,ref (full-fall scenes).
    pub flat_time_error: Option<f64>,
    /// |E(t_end) − E(0)| / (m g l).
    pub energy_error: f64,
    /// Right-hand-side evaluations (f64; the Taylor method counts one per order per step).
    pub rhs_evals: u64,
    /// Accepted steps, both phases of a full fall together.
    pub steps: u64,
    /// Accepted steps of the floor phase (a full fall; `steps` includes them).
    pub floor_steps: Option<u64>,
    /// Median wall-clock seconds per solve (warm).
    pub seconds: f64,
    /// First and third quartile of the repeats (the spread).
    pub seconds_iqr: (f64, f64),
    /// Timed repeats.
    pub repeats: usize,
    /// The relative accuracy of the references this run is judged against: errors below it
    /// are not measured ([`SEPARATION_ACCURACY`], [`FLAT_ACCURACY`]).
    pub reference_accuracy: f64,
}

/// Relative accuracy of the separation's reference (the closed form): 2 ulps, above the 1.1
/// and 1.6 ulps measured against mpmath (`tests/sim/exact/ulps.rs`).
pub const SEPARATION_ACCURACY: f64 = 2.0 * f64::EPSILON;

/// Relative accuracy of the flat time's reference: the separation time's and the floor
/// phase's quadrature's 16 ε (`sim::exact::flat`'s bound against mpmath), added.
pub const FLAT_ACCURACY: f64 = SEPARATION_ACCURACY + 16.0 * f64::EPSILON;

impl Point for Run {
    fn method(&self) -> &str {
        &self.method
    }
    fn rhs_evals(&self) -> u64 {
        self.rhs_evals
    }
    fn steps(&self) -> u64 {
        self.steps
    }
    fn shortest_phase_steps(&self) -> u64 {
        self.floor_steps
            .map_or(self.steps, |f| f.min(self.steps - f))
    }
    fn seconds(&self) -> f64 {
        self.seconds
    }
    /// The tolerance of an adaptive run; a fixed step's is NaN (it has none).
    fn tolerance(&self) -> f64 {
        match is_adaptive(&self.method) {
            true => self.tolerance,
            false => f64::NAN,
        }
    }
    /// The worse of the angle, time and (full fall) flat-time errors, at least the
    /// references' accuracy (below it nothing is measured).
    fn error(&self) -> f64 {
        self.angle_error
            .max(self.time_error)
            .max(self.flat_time_error.unwrap_or(0.0))
            .max(self.reference_accuracy)
    }
}

/// The sweep of each method, tolerances or steps, from its card (`Card::sweep`); empty for a
/// name the table does not know.
pub fn sweep(method: &str) -> Vec<f64> {
    card(method).map_or_else(Vec::new, |c| {
        c.sweep
            .controls()
            .into_iter()
            .map(|c| match c {
                Control::Fixed(v) | Control::Tolerance(v) => v,
            })
            .collect()
    })
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
            m: 1.0,
            l: 1.0,
            g: 9.81,
        },
        theta0,
        phi0: None,
        rate0,
        method: "dop853".into(),
        control: Some(Control::Tolerance(1e-12)),
        order: None,
        end: End::Separation,
        outputs: vec![
            Output::SeparationAngle,
            Output::SeparationTime,
            Output::EnergyError,
        ],
        contact: crate::sim::scene::ContactModel::Rigid,
    }
}

/// The built-in list: upright with a push of 1e-6 rad/s, from rest at 0.1, 0.3, 1.0 and 1.5,
/// and the full fall to flat from 0.3.
pub fn default_scenes() -> Vec<Scene> {
    let mut v: Vec<Scene> = [(0.0, 1e-6), (0.1, 0.0), (0.3, 0.0), (1.0, 0.0), (1.5, 0.0)]
        .into_iter()
        .map(|(a, r)| scene_at(a, r))
        .collect();
    let mut flat = scene_at(0.3, 0.0);
    flat.end = End::Flat;
    flat.file = "(built in: θ0 = 0.3, θ̇0 = 0, to flat)".into();
    v.push(flat);
    v
}

/// Timing of each run: repeats until `budget` seconds or `max` repeats, at least `min`.
#[derive(Clone, Copy, Debug)]
pub struct Timing {
    /// Seconds to spend per run (after one warm-up).
    pub budget: f64,
    /// Fewest repeats.
    pub min: usize,
    /// Most repeats.
    pub max: usize,
}

/// The command's timing: ~20 ms per run, 5 to 51 repeats.
pub const TIMING: Timing = Timing {
    budget: 0.02,
    min: 5,
    max: 51,
};

/// Median, quartiles and number of repeats of `f`'s wall time, after one warm-up.
pub fn time_it(timing: Timing, mut f: impl FnMut()) -> (f64, (f64, f64), usize) {
    let t = Instant::now();
    f();
    let once = t.elapsed().as_secs_f64().max(1e-9);
    let reps = ((timing.budget / once).ceil() as usize).clamp(timing.min, timing.max);
    let mut v: Vec<f64> = (0..reps)
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64()
        })
        .collect();
    v.sort_by(f64::total_cmp);
    let q = |p: f64| v[((v.len() - 1) as f64 * p).round() as usize];
    (q(0.5), (q(0.25), q(0.75)), reps)
}

/// Median of `f`'s wall time (the command's timing).
pub fn median_seconds(f: impl FnMut()) -> f64 {
    time_it(TIMING, f).0
}

/// The reference flat time, independent of every integrator: the exact separation time `sep`
/// (closed form) plus the floor phase's duration by quadrature of its conservation laws
/// (`sim::exact::flat::floor_duration`, in √(l/g)), from cos θ_s of footnote 4
/// ([`separation_cos`], a sum of positive terms: near the floor it keeps φ_s = arcsin(cos θ_s)
/// to its relative precision, where θ_s itself is an ulp of π/2 off). Within [`FLAT_ACCURACY`].
pub fn flat_reference(base: &Scene, sep: &Separation) -> Result<f64, String> {
    let ladder = base.ladder;
    let cos_s = separation_cos(base.theta0, base.rate0, ladder.big_omega2());
    if !(cos_s > 0.0 && cos_s <= 1.0) {
        return Err(format!("no floor phase from cos θ_s = {cos_s}"));
    }
    let unit = (ladder.l / ladder.g).sqrt();
    Ok(sep.time + floor_duration(cos_s) * unit)
}

/// All runs of `methods` for `base` (its ladder, start and end; method and outputs are
/// replaced), calling `tick` after each run. Runs that fail (e.g. the step limit) are skipped.
pub fn measure(
    base: &Scene,
    methods: &[&str],
    timing: Timing,
    mut tick: impl FnMut(&str),
) -> Result<Vec<Run>, String> {
    let exact = PhaseOne::new(base.theta0, base.rate0, base.ladder.big_omega2())?
        .separation()
        .ok_or("the start is the equilibrium: no separation")?;
    let flat_ref = match base.end {
        End::Flat => Some(flat_reference(base, &exact)?),
        _ => None,
    };
    let mut runs = Vec::new();
    for &method in methods {
        for tol in sweep(method) {
            let mut sc = base.clone();
            sc.method = method.into();
            sc.control = Some(if is_adaptive(method) {
                Control::Tolerance(tol)
            } else {
                Control::Fixed(tol)
            });
            sc.end = if flat_ref.is_some() {
                End::Flat
            } else {
                End::Separation
            };
            sc.outputs = vec![
                Output::SeparationAngle,
                Output::SeparationTime,
                Output::EnergyError,
            ];
            tick(method);
            let Ok(o) = fall::run(&sc, fall::MAX_STEPS) else {
                continue;
            };
            let Some(s) = o.separation else { continue };
            let flat_time_error = match (flat_ref, o.flat) {
                (None, _) => None,
                (Some(r), Some(f)) => Some((f.time - r).abs() / r),
                (Some(_), None) => continue,
            };
            let (seconds, seconds_iqr, repeats) = time_it(timing, || {
                std::hint::black_box(fall::run(std::hint::black_box(&sc), fall::MAX_STEPS).ok());
            });
            runs.push(Run {
                scene: base.file.clone(),
                method: method.into(),
                tolerance: tol,
                angle_error: (s.angle - exact.angle).abs() / exact.angle,
                time_error: (s.time - exact.time).abs() / exact.time,
                flat_time_error,
                energy_error: o.energy_error.unwrap_or(f64::NAN),
                rhs_evals: o.work.wall.rhs_evals + o.work.floor.map_or(0, |f| f.rhs_evals),
                steps: o.work.wall.steps + o.work.floor.map_or(0, |f| f.steps),
                floor_steps: o.work.floor.map(|f| f.steps),
                seconds,
                seconds_iqr,
                repeats,
                reference_accuracy: match flat_ref {
                    Some(_) => FLAT_ACCURACY,
                    None => SEPARATION_ACCURACY,
                },
            });
        }
    }
    Ok(runs)
}
