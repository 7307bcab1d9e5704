//! A scene with `contact.model = "penalty"`: the penalty model of [`crate::sim::penalty`] run to
//! separation in its dimensionless units and scaled back to the scene's seconds. Only the
//! wall phase exists for this model, and only the separation outputs (the scene checks see to
//! that); nothing else is built or stored.

use crate::sim::integrators::Control;
use crate::sim::outcome::{Outcome, Plan, SeparationState, Work};
use crate::sim::penalty::run::separation;
use crate::sim::penalty::{Contact, Law};
use crate::sim::run::RunError;
use crate::sim::scene::Scene;

/// Run the penalty `scene` (stiffness k in N/m, damping c in N·s/m) with at most `max_steps`.
pub fn run(scene: &Scene, k: f64, c: f64, max_steps: u64) -> Result<Outcome, RunError> {
    let ladder = scene.ladder;
    let contact = Contact::from_dimensional(&ladder, k, c);
    // The time unit √(l/g): dimensionless t' = t / unit, θ̇' = θ̇ · unit.
    let unit = (ladder.l / ladder.g).sqrt();
    let control = match scene.control {
        Some(Control::Fixed(h)) => Control::Fixed(h / unit),
        Some(tol) => tol,
        None => {
            return Err(RunError::Start(
                "the penalty model needs an integrator".into(),
            ))
        }
    };
    let run = separation(
        contact,
        Law::Switched,
        scene.theta0,
        scene.rate0 * unit,
        &scene.method,
        control,
        max_steps,
    );
    let s = run.result?;
    let sep = SeparationState {
        time: s.time * unit,
        angle: s.angle,
        rate: s.rate / unit,
    };
    Ok(Outcome {
        plan: Plan::of(scene),
        separation: Some(sep),
        flat: None,
        slide: None,
        last: (sep.time, sep.angle, sep.rate),
        energy_error: None,
        momentum_error: None,
        floor_report: None,
        trace: None,
        work: Work {
            wall: run.stats,
            ..Work::default()
        },
    })
}
