//! The whole fall of a scene: wall phase to separation, then (if the outputs need it) the floor
//! phase to flat. A [`Plan`] made from the outputs decides what is built, evaluated and stored;
//! [`Work`] counts it so that tests can check that nothing else was done.

use super::event::{Direction, Event};
use super::exact::PhaseOne;
use super::floor::{self, FloorPhase};
use super::integrators::any::AnyStepper;
use super::integrators::{Stats, Stepper};
use super::output::Output;
use super::rigid::{self, Ladder, WallPhase};
use super::run::{integrate_phase, Observer, RunError};
use super::scaled::Units;
use super::scene::{ContactModel, End, Scene, MAX_END_TIME};
use std::cell::Cell;
use std::f64::consts::FRAC_PI_2;

/// Default hard limit on steps per phase.
pub const MAX_STEPS: u64 = 10_000_000;
/// Dense samples per step kept for plots and monitors.
const SAMPLES_PER_STEP: usize = 4;

/// What a run must compute, decided by the scene's outputs alone.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Plan {
    /// Build and integrate the floor phase.
    pub floor_phase: bool,
    /// Keep the trajectory (θ, θ̇ against t).
    pub trace: bool,
    /// Evaluate contact forces along the trace.
    pub forces: bool,
    /// Track the floor force and the top's clearance over the floor phase.
    pub floor_monitor: bool,
    /// Evaluate the energy at the ends.
    pub energy: bool,
}

impl Plan {
    /// The plan for `scene`.
    pub fn of(scene: &Scene) -> Plan {
        let wants = |o: Output| scene.outputs.contains(&o);
        Plan {
            floor_phase: scene.end != End::Separation && scene.method != "exact",
            trace: wants(Output::Trajectory) || wants(Output::Forces),
            forces: wants(Output::Forces),
            floor_monitor: wants(Output::FloorForceMin) || wants(Output::TopClearanceMin),
            energy: wants(Output::EnergyError),
        }
    }
}

/// One stored point of the motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// 1 (wall phase) or 2 (floor phase).
    pub phase: u8,
    /// t, s.
    pub t: f64,
    /// θ, rad.
    pub theta: f64,
    /// θ̇, rad/s.
    pub rate: f64,
    /// (F_w, F_f), N, when the forces were asked for.
    pub forces: Option<(f64, f64)>,
}

/// Counters of the work done, for the summary and for tests.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Work {
    /// Integrator statistics, wall phase.
    pub wall: Stats,
    /// Integrator statistics, floor phase (None if it was never built).
    pub floor: Option<Stats>,
    /// Contact-force evaluations (traces, monitors, the lift-off watch).
    pub force_evals: u64,
    /// Samples kept in memory.
    pub stored_samples: usize,
}

/// The state at separation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeparationState {
    /// t_s.
    pub time: f64,
    /// θ_s.
    pub angle: f64,
    /// θ̇ at t_s.
    pub rate: f64,
}

/// The state when the ladder lies flat (θ = π/2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlatState {
    /// Time.
    pub time: f64,
    /// θ̇.
    pub rate: f64,
    /// Centre's abscissa X.
    pub centre_x: f64,
    /// Ẋ.
    pub centre_velocity_x: f64,
    /// ẏ of the centre (= −l sin θ θ̇), its impact speed on the floor.
    pub centre_velocity_y: f64,
}

/// What the floor-phase monitors saw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FloorReport {
    /// Smallest floor force seen (step ends and dense samples).
    pub floor_force_min: f64,
    /// Smallest abscissa of the top after the start of the phase (> 0: clear of the wall).
    pub top_clearance_min: f64,
}

/// Everything a run produced.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// The plan that was followed.
    pub plan: Plan,
    /// Separation, if reached.
    pub separation: Option<SeparationState>,
    /// Flat, if reached.
    pub flat: Option<FlatState>,
    /// (t, θ, θ̇) at the end.
    pub last: (f64, f64, f64),
    /// |E_end − E_0| / (m g l), if asked.
    pub energy_error: Option<f64>,
    /// |Ẋ_end − Ẋ_s| / |Ẋ_s| over the floor phase, if it ran.
    pub momentum_error: Option<f64>,
    /// Floor-phase monitors, if asked.
    pub floor_report: Option<FloorReport>,
    /// The trace, if asked.
    pub trace: Option<Vec<Sample>>,
    /// Work counters.
    pub work: Work,
}

struct TraceObserver<'a> {
    ladder: Ladder,
    phase: u8,
    forces: bool,
    trace: Option<&'a mut Vec<Sample>>,
    monitor: Option<FloorReport>,
    force_evals: u64,
}

impl TraceObserver<'_> {
    fn record(&mut self, t: f64, theta: f64, rate: f64, centre_x: f64) {
        let forces = (self.forces && self.trace.is_some()).then(|| {
            self.force_evals += 2;
            if self.phase == 1 {
                (
                    rigid::wall_force(&self.ladder, theta, rate),
                    rigid::floor_force(&self.ladder, theta, rate),
                )
            } else {
                (0.0, floor::floor_force(&self.ladder, theta, rate))
            }
        });
        if let Some(tr) = self.trace.as_deref_mut() {
            tr.push(Sample {
                phase: self.phase,
                t,
                theta,
                rate,
                forces,
            });
        }
        if let Some(m) = self.monitor.as_mut() {
            self.force_evals += 1;
            m.floor_force_min =
                m.floor_force_min
                    .min(floor::floor_force(&self.ladder, theta, rate));
            m.top_clearance_min =
                m.top_clearance_min
                    .min(floor::top_x(&self.ladder, theta, centre_x));
        }
    }
}

impl Observer<2> for TraceObserver<'_> {
    fn samples_per_step(&self) -> usize {
        if self.trace.is_some() {
            SAMPLES_PER_STEP
        } else {
            0
        }
    }
    fn observe(&mut self, t: f64, y: &[f64; 2]) {
        self.record(t, y[0], y[1], 0.0);
    }
}

impl Observer<4> for TraceObserver<'_> {
    fn samples_per_step(&self) -> usize {
        if self.trace.is_some() || self.monitor.is_some() {
            SAMPLES_PER_STEP
        } else {
            0
        }
    }
    fn observe(&mut self, t: f64, y: &[f64; 4]) {
        self.record(t, y[0], y[2], y[1]);
    }
}

/// Separation: the factor g = Ω² cos θ − θ̇² of the wall force falls through zero.
struct SeparationEvent(f64);
impl Event<2> for SeparationEvent {
    fn value(&self, _t: f64, y: &[f64; 2]) -> f64 {
        rigid::separation_factor(self.0, y[0], y[1])
    }
    fn direction(&self) -> Direction {
        Direction::Falling
    }
    /// d/dt (ω² cos θ − θ̇²) = −ω² sin θ θ̇ − 2 θ̇ θ̈.
    fn rate(&self, _t: f64, y: &[f64; 2], dy: &[f64; 2]) -> Option<f64> {
        Some(-self.0 * y[0].sin() * dy[0] - 2.0 * y[1] * dy[1])
    }
}

/// Flat: θ − π/2 rises through zero.
struct FlatEvent;
impl Event<4> for FlatEvent {
    fn value(&self, _t: f64, y: &[f64; 4]) -> f64 {
        y[0] - FRAC_PI_2
    }
    fn direction(&self) -> Direction {
        Direction::Rising
    }
    fn rate(&self, _t: f64, _y: &[f64; 4], dy: &[f64; 4]) -> Option<f64> {
        Some(dy[0])
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
        floor::floor_force(&self.ladder, y[0], y[2])
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
    let lead = super::extreme::linear_lead_in(scene.ladder.omega2(), scene.theta0, scene.rate0)
        .map(|(t, theta, rate)| (t / units.time, theta, rate * units.time));
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
    let mut trace = plan.trace.then(Vec::new);
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
        .filter(|(t, _, _)| *t < t_end)
        .map_or((0.0, [scene.theta0, scene.rate0]), |(t, th, w)| {
            (t, [th, w])
        });
    let Some(control) = scene.control else {
        // The exact reference (wall phase only; the scene validation guarantees end = separation).
        let p = PhaseOne::new(y_lead[0], y_lead[1], ladder.omega2()).map_err(RunError::Start)?;
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
    // The stepper runs in time since the lead-in (its step floor is relative to |t|).
    let mut stepper = AnyStepper::new(&scene.method, control, 0.0, y_lead).ok_or_else(|| {
        RunError::Start(format!("method {} does not take {control:?}", scene.method))
    })?;
    let mut obs = TraceObserver {
        ladder,
        phase: 1,
        forces: plan.forces,
        trace: trace.as_mut(),
        monitor: None,
        force_evals: 0,
    };
    obs.observe(0.0, &y0);
    if t0 > 0.0 {
        obs.observe(t0, &y_lead);
    }
    let sep_event = SeparationEvent(wall.omega2);
    let mut end1 = integrate_phase(
        &wall,
        &mut stepper,
        &[&sep_event],
        t_end - t0,
        max_steps,
        &mut super::extreme::Shifted(&mut obs, t0),
    )?;
    end1.t += t0;
    work.wall = stepper.stats();
    work.force_evals += obs.force_evals;
    let mut last = (end1.t, end1.y[0], end1.y[1]);
    let mut energy_end = e0.map(|_| rigid::energy(&ladder, end1.y[0], end1.y[1]));
    let separation = end1.event.map(|_| SeparationState {
        time: end1.t,
        angle: end1.y[0],
        rate: end1.y[1],
    });
    let (mut flat, mut momentum_error, mut floor_report) = (None, None, None);

    if let (true, Some(sep)) = (plan.floor_phase, separation) {
        let floor_sys = FloorPhase::new(&ladder);
        let y_s = floor::state_at_separation(&ladder, sep.angle, sep.rate);
        let mut stepper2 =
            AnyStepper::new(&scene.method, control, sep.time, y_s).ok_or_else(|| {
                RunError::Start(format!("method {} does not take {control:?}", scene.method))
            })?;
        let monitor = plan.floor_monitor.then_some(FloorReport {
            floor_force_min: f64::INFINITY,
            top_clearance_min: f64::INFINITY,
        });
        let mut obs2 = TraceObserver {
            ladder,
            phase: 2,
            forces: plan.forces,
            trace: trace.as_mut(),
            monitor,
            force_evals: 0,
        };
        let lift = LiftOffEvent {
            ladder,
            evals: Cell::new(0),
        };
        let end2 = integrate_phase(
            &floor_sys,
            &mut stepper2,
            &[&FlatEvent, &lift],
            t_end,
            max_steps,
            &mut obs2,
        );
        work.floor = Some(stepper2.stats());
        work.force_evals += obs2.force_evals + lift.evals.get();
        floor_report = obs2.monitor;
        let end2 = end2?;
        if end2.event == Some(1) {
            return Err(RunError::LiftOff {
                t: end2.t,
                theta: end2.y[0],
            });
        }
        let y = end2.y;
        last = (end2.t, y[0], y[2]);
        momentum_error = Some((y[3] - y_s[3]).abs() / y_s[3].abs().max(f64::MIN_POSITIVE));
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
    work.stored_samples = trace.as_ref().map_or(0, Vec::len);
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
