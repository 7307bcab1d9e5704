//! Past the separation: the floor phase, the flat state and, for a run to a later time, the
//! slide lying flat after the top's impact (`super::super::impact`).

use super::floor_phase::{floor_phase, FloorEnd};
use super::observer::{momentum_balance, rigid_momentum_x};
use super::{FlatState, FloorReport, Outcome, Plan, Sample, SeparationState, Slide, Work};
use crate::sim::impact;
use crate::sim::run::RunError;
use crate::sim::scene::{End, Scene};
use crate::sim::trace::Kept;

/// The floor phase and what follows it ([`Beyond::run`]) from the separation `sep` at
/// φ_s, its counts added to `work`, with the fall's horizontal momentum balance when the wall
/// phase's `impulse` was kept; and the floor phase's end state (φ, x, φ̇, ẋ).
pub(super) fn beyond_separation(
    scene: &Scene,
    plan: &Plan,
    trace: Option<&mut Kept>,
    (sep, phi_s): (SeparationState, f64),
    (t_end, max_steps): (f64, u64),
    work: &mut Work,
    impulse: Option<f64>,
) -> Result<(Beyond, [f64; 4]), RunError> {
    let run = Beyond::run(scene, plan, trace, sep, phi_s, t_end, max_steps)?;
    let mut beyond = run.0;
    work.floor = Some(run.1.stats);
    work.force_evals += run.1.force_evals;
    beyond.momentum_error = impulse.map(|j| {
        momentum_balance(
            run.1.end.y[3],
            rigid_momentum_x(scene.theta0, scene.rate0),
            j,
        )
    });
    Ok((beyond, run.1.end.y))
}

/// What a run finds past the separation: the floor phase's report, the flat state and, for a
/// run to a later time, the slide lying flat after the top's impact (`super::impact`).
#[derive(Default)]
pub(super) struct Beyond {
    pub(super) flat: Option<FlatState>,
    pub(super) slide: Option<Slide>,
    pub(super) momentum_error: Option<f64>,
    pub(super) floor_report: Option<FloorReport>,
    /// The last state (t, θ, θ̇).
    pub(super) last: (f64, f64, f64),
}

impl Beyond {
    /// The run's outcome with what lies beyond the separation.
    pub(super) fn outcome(
        self,
        plan: Plan,
        separation: Option<SeparationState>,
        last: (f64, f64, f64),
        energy_error: Option<f64>,
        trace: Option<Vec<Sample>>,
        work: Work,
    ) -> Outcome {
        Outcome {
            plan,
            separation,
            flat: self.flat,
            slide: self.slide,
            last,
            energy_error,
            momentum_error: self.momentum_error,
            floor_report: self.floor_report,
            trace,
            work,
        }
    }

    /// The floor phase from the separation `sep` (φ_s = π/2 − θ_s), then lying flat to `t_end`;
    /// with the floor phase's own run for its counts and end state.
    #[allow(clippy::too_many_arguments)]
    fn run(
        scene: &Scene,
        plan: &Plan,
        mut trace: Option<&mut Kept>,
        sep: SeparationState,
        phi_s: f64,
        t_end: f64,
        max_steps: u64,
    ) -> Result<(Beyond, FloorEnd), RunError> {
        let floor = floor_phase(
            scene,
            plan,
            trace.as_deref_mut(),
            sep,
            phi_s,
            t_end,
            max_steps,
        )?;
        let (end2, y) = (floor.end, floor.end.y);
        let mut b = Beyond {
            floor_report: floor.report,
            last: (end2.t, y[0], y[2]),
            ..Beyond::default()
        };
        if end2.event != Some(0) {
            return Ok((b, floor));
        }
        let f = FlatState {
            time: end2.t,
            rate: y[2],
            centre_x: y[1],
            centre_velocity_x: y[3],
            centre_velocity_y: -scene.ladder.l * y[0].sin() * y[2],
        };
        b.flat = Some(f);
        // A run to a later time goes on lying flat (module docs of `super::impact`).
        if let (End::Time(_), true) = (scene.end, end2.t < t_end) {
            let s = impact::slide(&scene.ladder, &f, t_end);
            if let Some(tr) = trace {
                for (t, x) in [(f.time, f.centre_x), (t_end, s.centre_x_end)] {
                    tr.offer(impact::lying_flat_sample(t, x));
                }
            }
            b.slide = Some(s);
            b.last = (t_end, end2.y[0], 0.0);
        }
        Ok((b, floor))
    }
}
