//! The whole fall of a scene: wall phase to separation, then (if the outputs need it) the floor
//! phase to flat, and, for a run to a later time, the ladder lying flat after its top struck
//! the floor ([`super::impact`]). A [`Plan`] made from the outputs decides what is built,
//! evaluated and stored; [`Work`] counts it so that tests can check that nothing else was done.
//! The phases themselves are in `sim::fall::wall_phase` and `sim::fall::floor_phase`.

mod beyond;
pub mod floor_phase;
pub mod observer;
pub mod penalty;
pub mod wall_phase;

use self::beyond::{beyond_separation, Beyond};
use self::observer::{rigid_momentum_x, TraceObserver};
use self::wall_phase::{wall_phase, WallEnd, WallStart};
use super::exact::PhaseOne;
pub use super::fall::observer::momentum_balance;
use super::floor;
use super::lead_in::linear_state_at;
use super::near_release;
pub use super::outcome::{
    FlatState, FloorReport, Outcome, Plan, Sample, SeparationState, Slide, Work,
};
use super::rigid;

use super::run::{Observer, RunError};
use super::scene::{ContactModel, End, Scene, MAX_END_TIME};
use super::start_margin::Lean;
use super::trace::Kept;
use super::units::Units;
use crate::ladder::Ladder;

/// Default hard limit on steps per phase (the scene checks refuse a scene that needs more).
pub use super::scene::parts::MAX_STEPS;

/// Run `scene` with at most `max_steps` steps per phase. Rigid scenes run in the scene's own
/// units (see [`super::scaled`]), penalty scenes in the penalty model's; results are in SI.
pub fn run(scene: &Scene, max_steps: u64) -> Result<Outcome, RunError> {
    if let ContactModel::Penalty { stiffness, damping } = scene.contact {
        return penalty::run(scene, stiffness, damping, max_steps);
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
    // Near the release push the start's margin D0 = Ω² cos θ0 − θ̇0², formed exactly from the
    // SI inputs and scaled by T² (a relative rounding): θ̇0 T, rounded, would lose it
    // (`super::start_margin`).
    let lean = scene.phi0.map_or(Lean::Theta(scene.theta0), Lean::Phi);
    let margin = near_release::near_margin(&scene.ladder, lean, scene.rate0)
        .map(|d| d * (units.time * units.time));
    let mut out = run_rigid(&units.scale_scene(scene), lead, margin, max_steps)
        .map(|o| units.outcome_to_si(o))
        .map_err(|e| units.error_to_si(e))?;
    // The trace's first point is the start as given (its rate may not survive the scaling).
    if let Some(first) = out.trace.as_mut().and_then(|t| t.first_mut()) {
        (first.theta, first.rate) = (scene.theta0, scene.rate0);
    }
    Ok(out)
}

/// A rigid `scene` already in its own units (m = l = g = 1), with the linear lead-in of a tiny
/// start (t0, θ, θ̇) in those units when it has one ([`super::extreme::linear_lead_in`]) and
/// the start's margin D0 near the release push ([`super::near_release::near_margin`]).
fn run_rigid(
    scene: &Scene,
    lead: Option<(f64, f64, f64)>,
    margin: Option<f64>,
    max_steps: u64,
) -> Result<Outcome, RunError> {
    let plan = Plan::of(scene);
    let ladder = scene.ladder;
    let (m, l, g) = (ladder.m, ladder.l, ladder.g);
    let mut trace = plan.trace.then(Kept::default);
    let mut work = Work::default();
    let t_end = end_time(scene.end);
    let e0 = plan
        .energy
        .then(|| rigid::energy(&ladder, scene.theta0, scene.rate0));
    let (t0, y_lead) = lead_in_end(scene, lead, t_end);
    // The margin belongs to the start as given (a lead-in never meets the release push).
    let margin = margin.filter(|_| t0 == 0.0);
    if scene.control.is_none() {
        return exact_outcome(plan, &ladder, t0, y_lead, margin);
    }
    let y0 = [scene.theta0, scene.rate0];
    let mut obs = wall_observer(scene, &plan, trace.as_mut(), y_lead);
    obs.observe(0.0, &y0);
    if t0 > 0.0 {
        obs.observe(t0, &y_lead);
    }
    if t0 > 0.0 && t0 >= t_end {
        // The end came within the linear lead-in (`run` gave its state there): nothing to step.
        work.force_evals = obs.force_evals;
        return Ok(lead_in_outcome(
            plan,
            trace,
            &ladder,
            work,
            (t0, y_lead),
            e0,
        ));
    }
    let wall = stepped_wall_phase(
        scene,
        &mut obs,
        (t0, y_lead, margin),
        (t_end, max_steps),
        &mut work,
    )?;
    let end1 = wall.end;
    let impulse = obs.impulse;
    let mut last = (end1.t, end1.y[0], end1.y[1]);
    let mut energy_end = e0.map(|_| rigid::energy(&ladder, end1.y[0], end1.y[1]));
    let separation = end1.event.map(|_| SeparationState {
        time: end1.t,
        angle: end1.y[0],
        rate: end1.y[1],
    });
    let mut beyond = Beyond::default();
    if let (true, Some(sep)) = (plan.floor_phase, separation) {
        // The floor phase runs in φ = π/2 − θ (see `super::complement`).
        let phi_s = wall
            .phi_s
            .unwrap_or_else(|| super::complement::complement(sep.angle));
        let y;
        (beyond, y) = beyond_separation(
            scene,
            &plan,
            trace.as_mut(),
            (sep, phi_s),
            (t_end, max_steps),
            &mut work,
            impulse,
        )?;
        last = beyond.last;
        // Over the integrated phases: up to flat (the impact's loss is the slide's own figure).
        energy_end = e0.map(|_| floor::energy(&ladder, y[0], y[2], y[3]));
    }
    let trace = finished(trace, &ladder, plan.forces, &mut work);
    let energy_error = e0.zip(energy_end).map(|(a, b)| (b - a).abs() / (m * g * l));
    Ok(beyond.outcome(plan, separation, last, energy_error, trace, work))
}

/// The time a run ends at the latest: the scene's end time, else [`MAX_END_TIME`].
fn end_time(end: End) -> f64 {
    match end {
        End::Time(t) => t,
        _ => MAX_END_TIME,
    }
}

/// Tiny and subnormal starts: the exact linear motion up to where f64 can follow it, when
/// that is before `t_end`; (t0, [θ, θ̇]) where the stepping starts (the start itself, t0 = 0,
/// without a lead-in).
fn lead_in_end(scene: &Scene, lead: Option<(f64, f64, f64)>, t_end: f64) -> (f64, [f64; 2]) {
    lead.filter(|(t, _, _)| *t <= t_end)
        .map_or((0.0, [scene.theta0, scene.rate0]), |(t, th, w)| {
            (t, [th, w])
        })
}

/// The observer of the wall phase, keeping `trace`; with the momentum balance, the lead-in's
/// impulse up to `y_lead`.
fn wall_observer<'a>(
    scene: &Scene,
    plan: &Plan,
    trace: Option<&'a mut Kept>,
    y_lead: [f64; 2],
) -> TraceObserver<'a> {
    TraceObserver {
        ladder: scene.ladder,
        phase: 1,
        trace,
        monitor: None,
        force_evals: 0,
        phase_start: 0.0,
        // The linear lead-in's impulse is exact: m l Δ(cos θ θ̇) over it (eq. (7)).
        impulse: plan.momentum.then(|| {
            rigid_momentum_x(y_lead[0], y_lead[1]) - rigid_momentum_x(scene.theta0, scene.rate0)
        }),
    }
}

/// The wall phase stepped from the lead-in's end (t0, [θ, θ̇]) with the start's `margin`,
/// observed by `obs`; its end in the scene's time, its counts added to `work`.
fn stepped_wall_phase(
    scene: &Scene,
    obs: &mut TraceObserver,
    (t0, y_lead, margin): (f64, [f64; 2], Option<f64>),
    (t_end, max_steps): (f64, u64),
    work: &mut Work,
) -> Result<WallEnd, RunError> {
    let start = WallStart {
        y: y_lead,
        // A start given as its complement φ0 (`angle_from_floor`) enters exactly.
        phi0: scene.phi0.filter(|_| t0 == 0.0),
        margin,
    };
    // The stepper runs in time since the lead-in (its step floor is relative to |t|).
    let mut shifted = super::extreme::Shifted(&mut *obs, t0);
    let mut wall = wall_phase(scene, &start, t_end - t0, max_steps, &mut shifted)?;
    wall.end.t += t0;
    work.wall = wall.stats;
    work.force_evals += obs.force_evals;
    Ok(wall)
}

/// The outcome of a run whose end came within the linear lead-in: the lead-in's end state
/// (t0, θ, θ̇) = `lead` is the last, nothing was stepped.
fn lead_in_outcome(
    plan: Plan,
    trace: Option<Kept>,
    ladder: &Ladder<f64>,
    mut work: Work,
    (t0, y_lead): (f64, [f64; 2]),
    e0: Option<f64>,
) -> Outcome {
    let (m, l, g) = (ladder.m, ladder.l, ladder.g);
    let trace = finished(trace, ladder, plan.forces, &mut work);
    let energy = rigid::energy(ladder, y_lead[0], y_lead[1]);
    Outcome {
        plan,
        separation: None,
        flat: None,
        slide: None,
        last: (t0, y_lead[0], y_lead[1]),
        energy_error: e0.map(|e| (energy - e).abs() / (m * g * l)),
        momentum_error: None,
        floor_report: None,
        trace,
        work,
    }
}

/// The exact reference's outcome (wall phase only; the scene validation guarantees
/// end = separation), from (θ, θ̇) = `y` at `t0` after a lead-in, with the start's margin.
fn exact_outcome(
    plan: Plan,
    ladder: &Ladder<f64>,
    t0: f64,
    y: [f64; 2],
    margin: Option<f64>,
) -> Result<Outcome, RunError> {
    let big_omega2 = ladder.big_omega2();
    let mut p = PhaseOne::new(y[0], y[1], big_omega2).map_err(RunError::Start)?;
    if let Some(d) = margin {
        p = p.with_start_margin(d);
    }
    let s = p
        .separation()
        .ok_or_else(|| RunError::Start("the ladder never leaves the wall".into()))?;
    let sep = SeparationState {
        time: t0 + s.time,
        angle: s.angle,
        rate: s.rate,
    };
    Ok(Outcome {
        plan,
        separation: Some(sep),
        flat: None,
        slide: None,
        last: (t0 + s.time, s.angle, s.rate),
        energy_error: None,
        momentum_error: None,
        floor_report: None,
        trace: None,
        work: Work::default(),
    })
}

/// The kept samples of a trace with their forces when asked, counted in `work`.
fn finished(
    trace: Option<Kept>,
    ladder: &Ladder<f64>,
    forces: bool,
    work: &mut Work,
) -> Option<Vec<Sample>> {
    let (samples, evals) = trace?.finish(ladder, forces);
    work.force_evals += evals;
    work.stored_samples = samples.len();
    Some(samples)
}
