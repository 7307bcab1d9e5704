//! The floor phase of a fall ([`crate::sim::fall`]): from the separation to flat (or the end time),
//! in φ = π/2 − θ ([`crate::sim::complement`]), watching the floor force for a lift-off. Beyond the
//! note: its sec. 2.1 stops at the separation (footnote 4).

use crate::ladder::Ladder;
use crate::sim::complement;
use crate::sim::event::{Direction, Event};
use crate::sim::fall::observer::{TraceObserver, SAMPLES_PER_STEP};
use crate::sim::integrators::AnyStepper;
use crate::sim::integrators::{Stats, Stepper};
use crate::sim::outcome::{FloorReport, Plan, SeparationState};
use crate::sim::run::{integrate_phase, PhaseEnd, RunError};
use crate::sim::scene::Scene;
use crate::sim::trace::Kept;
use std::cell::Cell;

/// Lift-off: the floor force falls through zero (checked inside steps too: it could dip and
/// recover within one step).
pub struct LiftOffEvent {
    /// The ladder, for the floor force.
    pub ladder: Ladder<f64>,
    /// Force evaluations spent locating the event.
    pub evals: Cell<u64>,
}
impl Event<4> for LiftOffEvent {
    fn value(&self, _t: f64, y: &[f64; 4]) -> f64 {
        self.evals.set(self.evals.get() + 1);
        complement::floor_force(&self.ladder, y[0], y[2])
    }
    fn direction(&self) -> Direction {
        Direction::Falling
    }
    fn interior_samples(&self) -> usize {
        SAMPLES_PER_STEP
    }
}

/// How the floor phase ended: the end (θ, X, θ̇, Ẋ) with `event` Some(0) at flat, the
/// integrator's counters, the force evaluations and the monitors' report.
pub struct FloorEnd {
    pub end: PhaseEnd<4>,
    pub stats: Stats,
    pub force_evals: u64,
    pub report: Option<FloorReport>,
}

/// The floor phase of `scene` (in its own units) from the separation `sep` (with φ_s =
/// `phi_s`) until flat or `t_end`, at most `max_steps` steps; the trace (when kept) and the
/// monitors (when `plan` asks) are fed. A lift-off, also one at the phase's start (a start
/// pushed past Ω √cos θ0 so hard that the floor would have to pull at once), is an error.
#[allow(clippy::too_many_arguments)]
pub fn floor_phase(
    scene: &Scene,
    plan: &Plan,
    trace: Option<&mut Kept>,
    sep: SeparationState,
    phi_s: f64,
    t_end: f64,
    max_steps: u64,
) -> Result<FloorEnd, RunError> {
    let ladder = scene.ladder;
    let floor_sys = complement::ComplementFloor::new(&ladder);
    // The factor's zero has sin φ_s = φ̇_s²/Ω² ≥ 0; a φ_s ≤ 0 (rounding at subnormal sizes)
    // would leave the floor phase no flat to cross: say so, never run on past flat.
    if phi_s <= 0.0 {
        return Err(RunError::Start(format!(
            "the separation was located at or past flat (π/2 − θ = {phi_s:e} rad): the start is too close to the floor for f64"
        )));
    }
    let y_s = complement::floor_state_at_separation(&ladder, phi_s, sep.rate);
    let lift = LiftOffEvent {
        ladder,
        evals: Cell::new(0),
    };
    // At a separation the floor force is positive (m g/4 or more); only a start that left the
    // wall at once can begin with the foot pulled: it lifts off at t_s.
    if lift.value(sep.time, &y_s) <= 0.0 {
        return Err(RunError::LiftOff {
            t: sep.time,
            theta: sep.angle,
        });
    }
    let control = scene
        .control
        .ok_or_else(|| RunError::Start("no integrator".into()))?;
    let mut stepper = AnyStepper::with_order(&scene.method, control, scene.order, sep.time, y_s)
        .ok_or_else(|| {
            RunError::Start(format!("method {} does not take {control:?}", scene.method))
        })?;
    let monitor = plan.floor_monitor.then_some(FloorReport {
        floor_force_min: f64::INFINITY,
        top_clearance_min: f64::INFINITY,
    });
    let mut obs = TraceObserver {
        ladder,
        phase: 2,
        trace,
        monitor,
        force_evals: 0,
        phase_start: sep.time,
        impulse: None,
    };
    let end = integrate_phase(
        &floor_sys,
        &mut stepper,
        &[&complement::Flat, &lift],
        t_end,
        max_steps,
        &mut complement::InTheta(&mut obs),
    );
    let mut end = end?;
    end.y = complement::floor_to_theta(&end.y);
    if end.event == Some(1) {
        return Err(RunError::LiftOff {
            t: end.t,
            theta: end.y[0],
        });
    }
    Ok(FloorEnd {
        end,
        stats: stepper.stats(),
        force_evals: obs.force_evals + lift.evals.get(),
        report: obs.monitor,
    })
}
