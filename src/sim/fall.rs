//! The whole fall of a scene: wall phase to separation, then (if the outputs need it) the floor
//! phase to flat. A [`Plan`] made from the outputs decides what is built, evaluated and stored;
//! [`Work`] counts it so that tests can check that nothing else was done.

use super::complement;
use super::event::{Direction, Event};
use super::exact::PhaseOne;
pub use super::fall_observer::momentum_balance;
use super::fall_observer::{rigid_momentum_x, TraceObserver, SAMPLES_PER_STEP};
use super::floor;
use super::integrators::taylor;
use super::integrators::AnyStepper;
use super::integrators::Stepper;
use super::lead_in::linear_state_at;
pub use super::outcome::{FlatState, FloorReport, Outcome, Plan, Sample, SeparationState, Work};
use super::rigid::{self, Ladder, WallPhase};
use super::run::{integrate_phase, Observer, RunError};
use super::scene::{ContactModel, End, Scene, MAX_END_TIME};
use super::trace::Kept;
use super::units::Units;
use std::cell::Cell;

/// Default hard limit on steps per phase (the scene checks refuse a scene that needs more).
pub use super::scene_parts::MAX_STEPS;
/// Separation: the factor g = Ω² cos θ − θ̇² of the wall force falls through zero.
struct SeparationEvent(f64);
impl Event<2> for SeparationEvent {
    fn value(&self, _t: f64, y: &[f64; 2]) -> f64 {
        rigid::separation_factor(self.0, y[0], y[1])
    }
    fn direction(&self) -> Direction {
        Direction::Falling
    }
    /// d/dt (Ω² cos θ − θ̇²) = −Ω² sin θ θ̇ − 2 θ̇ θ̈.
    fn rate(&self, _t: f64, y: &[f64; 2], dy: &[f64; 2]) -> Option<f64> {
        Some(-self.0 * y[0].sin() * dy[0] - 2.0 * y[1] * dy[1])
    }
    /// Ω² cos θ − θ̇² and its rate on the step's polynomials of cos θ and θ̇.
    fn on_series(&self, s: &taylor::Series<2>, tau: f64) -> Option<(f64, f64)> {
        Some(taylor::separation_factor_on(
            self.0,
            &s.cos,
            &s.y[1],
            s.order,
            s.inv_unit(),
            tau,
        ))
    }
    /// Ω² cos θ − θ̇² with the carried cos θ.
    fn value_with_trig(&self, _t: f64, y: &[f64; 2], trig: (f64, f64)) -> f64 {
        self.0 * trig.1 - y[1] * y[1]
    }
}

/// Lift-off: the floor force falls through zero (checked inside steps too: it could dip and
/// recover within one step).
struct LiftOffEvent {
    ladder: Ladder,
    evals: Cell<u64>,
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

/// Run `scene` with at most `max_steps` steps per phase. Rigid scenes run in the scene's own
/// units (see [`super::scaled`]), penalty scenes in the penalty model's; results are in SI.
pub fn run(scene: &Scene, max_steps: u64) -> Result<Outcome, RunError> {
    if let ContactModel::Penalty { stiffness, damping } = scene.contact {
        return super::penalty_scene::run(scene, stiffness, damping, max_steps);
    }
    let units = Units::of(&scene.ladder);
    // Tiny starts take their linear lead-in in SI, before scaling: θ̇0 T underflows (5e-324 T
    // = 0 for T < 1), and a subnormal product keeps only part of θ̇0's digits. The lead-in ends
    // at an amplitude (~1e-9) where the conversion is exact to rounding.
    let big_omega2 = scene.ladder.big_omega2();
    let lead = super::extreme::linear_lead_in(big_omega2, scene.theta0, scene.rate0).map(
        |(t, theta, rate)| match scene.end {
            // An end before the hand-over: the whole run is the linear motion (closed form).
            End::Time(t_end) if t >= t_end => {
                let (theta, rate) = linear_state_at(big_omega2, scene.theta0, scene.rate0, t_end);
                (t_end, theta, rate)
            }
            _ => (t, theta, rate),
        },
    );
    let lead = lead.map(|(t, theta, rate)| (t / units.time, theta, rate * units.time));
    let mut out = run_rigid(&units.scale_scene(scene), lead, max_steps)
        .map(|o| units.outcome_to_si(o))
        .map_err(|e| units.error_to_si(e))?;
    // The trace's first point is the start as given (its rate may not survive the scaling).
    if let Some(first) = out.trace.as_mut().and_then(|t| t.first_mut()) {
        (first.theta, first.rate) = (scene.theta0, scene.rate0);
    }
    Ok(out)
}

/// A rigid `scene` already in its own units (m = l = g = 1), with the linear lead-in of a tiny
/// start (t0, θ, θ̇) in those units when it has one ([`super::extreme::linear_lead_in`]).
fn run_rigid(
    scene: &Scene,
    lead: Option<(f64, f64, f64)>,
    max_steps: u64,
) -> Result<Outcome, RunError> {
    let plan = Plan::of(scene);
    let ladder = scene.ladder;
    let (m, l, g) = (ladder.mass, ladder.half_length, ladder.gravity);
    let mut trace = plan.trace.then(Kept::default);
    let mut work = Work::default();
    let t_end = match scene.end {
        End::Time(t) => t,
        _ => MAX_END_TIME,
    };
    let e0 = plan
        .energy
        .then(|| rigid::energy(&ladder, scene.theta0, scene.rate0));

    // Tiny and subnormal starts: the exact linear motion up to where f64 can follow it.
    let (t0, y_lead) = lead
        .filter(|(t, _, _)| *t <= t_end)
        .map_or((0.0, [scene.theta0, scene.rate0]), |(t, th, w)| {
            (t, [th, w])
        });
    let Some(control) = scene.control else {
        // The exact reference (wall phase only; the scene validation guarantees end = separation).
        let p =
            PhaseOne::new(y_lead[0], y_lead[1], ladder.big_omega2()).map_err(RunError::Start)?;
        let s = p
            .separation()
            .ok_or_else(|| RunError::Start("the ladder never leaves the wall".into()))?;
        let sep = SeparationState {
            time: t0 + s.time,
            angle: s.angle,
            rate: s.rate,
        };
        return Ok(Outcome {
            plan,
            separation: Some(sep),
            flat: None,
            last: (t0 + s.time, s.angle, s.rate),
            energy_error: None,
            momentum_error: None,
            floor_report: None,
            trace: None,
            work,
        });
    };
    let wall = WallPhase::new(&ladder);
    let y0 = [scene.theta0, scene.rate0];
    // Near the floor the wall phase runs in φ = π/2 − θ (see `super::complement`).
    let in_complement = complement::applies(y_lead[0]);
    // A start given as its complement φ0 (`angle_from_floor`) enters exactly (θ0 cannot hold it).
    let phi0 = scene.phi0.filter(|_| t0 == 0.0);
    let start = match in_complement {
        true => [
            phi0.unwrap_or_else(|| complement::complement(y_lead[0])),
            -y_lead[1],
        ],
        false => y_lead,
    };
    // The stepper runs in time since the lead-in (its step floor is relative to |t|).
    let mut stepper = AnyStepper::with_order(&scene.method, control, scene.order, 0.0, start)
        .ok_or_else(|| {
            RunError::Start(format!("method {} does not take {control:?}", scene.method))
        })?;
    let mut obs = TraceObserver {
        ladder,
        phase: 1,
        trace: trace.as_mut(),
        monitor: None,
        force_evals: 0,
        phase_start: 0.0,
        // The linear lead-in's impulse is exact: m l Δ(cos θ θ̇) over it (eq. (7)).
        impulse: plan.momentum.then(|| {
            rigid_momentum_x(y_lead[0], y_lead[1]) - rigid_momentum_x(scene.theta0, scene.rate0)
        }),
    };
    obs.observe(0.0, &y0);
    if t0 > 0.0 {
        obs.observe(t0, &y_lead);
    }
    if t0 > 0.0 && t0 >= t_end {
        // The end came within the linear lead-in (`run` gave its state there): nothing to step.
        work.force_evals = obs.force_evals;
        let trace = finished(trace, &ladder, plan.forces, &mut work);
        let energy = rigid::energy(&ladder, y_lead[0], y_lead[1]);
        return Ok(Outcome {
            plan,
            separation: None,
            flat: None,
            last: (t0, y_lead[0], y_lead[1]),
            energy_error: e0.map(|e| (energy - e).abs() / (m * g * l)),
            momentum_error: None,
            floor_report: None,
            trace,
            work,
        });
    }
    let mut shifted = super::extreme::Shifted(&mut obs, t0);
    let mut phi_s = None;
    let mut end1 = if in_complement {
        let sys = complement::ComplementWall::new(&ladder);
        let sep_event = complement::ComplementSeparation(sys.big_omega2);
        let mut e = integrate_phase(
            &sys,
            &mut stepper,
            &[&sep_event],
            t_end - t0,
            max_steps,
            &mut complement::InTheta(&mut shifted),
        )?;
        phi_s = Some(e.y[0]);
        e.y = complement::to_theta(&e.y);
        e
    } else {
        let sep_event = SeparationEvent(wall.big_omega2);
        integrate_phase(
            &wall,
            &mut stepper,
            &[&sep_event],
            t_end - t0,
            max_steps,
            &mut shifted,
        )?
    };
    end1.t += t0;
    work.wall = stepper.stats();
    work.force_evals += obs.force_evals;
    let impulse = obs.impulse;
    let mut last = (end1.t, end1.y[0], end1.y[1]);
    let mut energy_end = e0.map(|_| rigid::energy(&ladder, end1.y[0], end1.y[1]));
    let separation = end1.event.map(|_| SeparationState {
        time: end1.t,
        angle: end1.y[0],
        rate: end1.y[1],
    });
    let (mut flat, mut momentum_error, mut floor_report) = (None, None, None);

    if let (true, Some(sep)) = (plan.floor_phase, separation) {
        // The floor phase runs in φ = π/2 − θ (see `super::complement`).
        let floor_sys = complement::ComplementFloor::new(&ladder);
        let phi_s = phi_s.unwrap_or_else(|| complement::complement(sep.angle));
        // The factor's zero has sin φ_s = φ̇_s²/Ω² ≥ 0; a φ_s ≤ 0 (rounding at subnormal sizes)
        // would leave the floor phase no flat to cross: say so, never run on past flat.
        if phi_s <= 0.0 {
            return Err(RunError::Start(format!(
                "the separation was located at or past flat (π/2 − θ = {phi_s:e} rad): the start is too close to the floor for f64"
            )));
        }
        let y_s = complement::floor_state_at_separation(&ladder, phi_s, sep.rate);
        let mut stepper2 =
            AnyStepper::with_order(&scene.method, control, scene.order, sep.time, y_s).ok_or_else(
                || RunError::Start(format!("method {} does not take {control:?}", scene.method)),
            )?;
        let monitor = plan.floor_monitor.then_some(FloorReport {
            floor_force_min: f64::INFINITY,
            top_clearance_min: f64::INFINITY,
        });
        let mut obs2 = TraceObserver {
            ladder,
            phase: 2,
            trace: trace.as_mut(),
            monitor,
            force_evals: 0,
            phase_start: sep.time,
            impulse: None,
        };
        let lift = LiftOffEvent {
            ladder,
            evals: Cell::new(0),
        };
        let end2 = integrate_phase(
            &floor_sys,
            &mut stepper2,
            &[&complement::Flat, &lift],
            t_end,
            max_steps,
            &mut complement::InTheta(&mut obs2),
        );
        work.floor = Some(stepper2.stats());
        work.force_evals += obs2.force_evals + lift.evals.get();
        floor_report = obs2.monitor;
        let mut end2 = end2?;
        end2.y = complement::floor_to_theta(&end2.y);
        if end2.event == Some(1) {
            return Err(RunError::LiftOff {
                t: end2.t,
                theta: end2.y[0],
            });
        }
        let y = end2.y;
        last = (end2.t, y[0], y[2]);
        momentum_error =
            impulse.map(|j| momentum_balance(y[3], rigid_momentum_x(scene.theta0, scene.rate0), j));
        energy_end = e0.map(|_| floor::energy(&ladder, y[0], y[2], y[3]));
        if end2.event == Some(0) {
            flat = Some(FlatState {
                time: end2.t,
                rate: y[2],
                centre_x: y[1],
                centre_velocity_x: y[3],
                centre_velocity_y: -l * y[0].sin() * y[2],
            });
        }
    }
    let trace = finished(trace, &ladder, plan.forces, &mut work);
    let energy_error = e0.zip(energy_end).map(|(a, b)| (b - a).abs() / (m * g * l));
    Ok(Outcome {
        plan,
        separation,
        flat,
        last,
        energy_error,
        momentum_error,
        floor_report,
        trace,
        work,
    })
}

/// The kept samples of a trace with their forces when asked, counted in `work`.
fn finished(
    trace: Option<Kept>,
    ladder: &Ladder,
    forces: bool,
    work: &mut Work,
) -> Option<Vec<Sample>> {
    let (samples, evals) = trace?.finish(ladder, forces);
    work.force_evals += evals;
    work.stored_samples = samples.len();
    Some(samples)
}

#[cfg(test)]
mod tests;
