//! The whole fall of a scene: wall phase to separation, then (if the outputs need it) the floor
//! phase to flat, and, for a run to a later time, the ladder lying flat after its top struck
//! the floor ([`super::impact`]). A [`Plan`] made from the outputs decides what is built,
//! evaluated and stored; [`Work`] counts it so that tests can check that nothing else was done.
//! The phases themselves are in `sim::fall::wall_phase` and `sim::fall::floor_phase`.

pub mod floor_phase;
pub mod observer;
pub mod penalty;
pub mod wall_phase;

use self::floor_phase::{floor_phase, FloorEnd};
use self::observer::{rigid_momentum_x, TraceObserver};
use self::wall_phase::{wall_phase, WallStart};
use super::exact::PhaseOne;
pub use super::fall::observer::momentum_balance;
use super::floor;
use super::impact;
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
    // The margin belongs to the start as given (a lead-in never meets the release push).
    let margin = margin.filter(|_| t0 == 0.0);
    if scene.control.is_none() {
        return exact_outcome(plan, &ladder, t0, y_lead, margin);
    }
    let y0 = [scene.theta0, scene.rate0];
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
            slide: None,
            last: (t0, y_lead[0], y_lead[1]),
            energy_error: e0.map(|e| (energy - e).abs() / (m * g * l)),
            momentum_error: None,
            floor_report: None,
            trace,
            work,
        });
    }
    let start = WallStart {
        y: y_lead,
        // A start given as its complement φ0 (`angle_from_floor`) enters exactly.
        phi0: scene.phi0.filter(|_| t0 == 0.0),
        margin,
    };
    // The stepper runs in time since the lead-in (its step floor is relative to |t|).
    let mut shifted = super::extreme::Shifted(&mut obs, t0);
    let wall = wall_phase(scene, &start, t_end - t0, max_steps, &mut shifted)?;
    let mut end1 = wall.end;
    end1.t += t0;
    work.wall = wall.stats;
    work.force_evals += obs.force_evals;
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
        let run = Beyond::run(scene, &plan, trace.as_mut(), sep, phi_s, t_end, max_steps)?;
        beyond = run.0;
        work.floor = Some(run.1.stats);
        work.force_evals += run.1.force_evals;
        last = beyond.last;
        beyond.momentum_error = impulse.map(|j| {
            momentum_balance(
                run.1.end.y[3],
                rigid_momentum_x(scene.theta0, scene.rate0),
                j,
            )
        });
        let y = run.1.end.y;
        // Over the integrated phases: up to flat (the impact's loss is the slide's own figure).
        energy_end = e0.map(|_| floor::energy(&ladder, y[0], y[2], y[3]));
    }
    let trace = finished(trace, &ladder, plan.forces, &mut work);
    let energy_error = e0.zip(energy_end).map(|(a, b)| (b - a).abs() / (m * g * l));
    Ok(Outcome {
        plan,
        separation,
        flat: beyond.flat,
        slide: beyond.slide,
        last,
        energy_error,
        momentum_error: beyond.momentum_error,
        floor_report: beyond.floor_report,
        trace,
        work,
    })
}

/// What a run finds past the separation: the floor phase's report, the flat state and, for a
/// run to a later time, the slide lying flat after the top's impact (`super::impact`).
#[derive(Default)]
struct Beyond {
    flat: Option<FlatState>,
    slide: Option<Slide>,
    momentum_error: Option<f64>,
    floor_report: Option<FloorReport>,
    /// The last state (t, θ, θ̇).
    last: (f64, f64, f64),
}

impl Beyond {
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
