//! The scene's own units. A rigid scene is run with m = l = g = 1: lengths in units of l, times
//! in units of T = √(l/g), masses in m, hence forces in m g and energies in m g l. Only the
//! inputs (θ̇0, a fixed step, an end time) are converted on the way in and the results on the
//! way out, so every phase, event, step limit, tolerance and iteration cap sees the same numbers
//! whatever the scene's m, l, g (1e-30..1e30): the separation angle and flat time / T of any
//! scale equal those of m = l = 1, g = 9.81 up to the rounding of those conversions.
//!
//! Why not integrate in SI and rely on the integrators to be unit-free: their starting-step
//! heuristic (Hairer-Nørsett-Wanner's `hinit`) and the f64 resolution of t are not. A floor
//! phase that starts at t_s = 1e15 s with a first step of 1e-4 s cannot advance t at all, which
//! is how a third of the slow scenes failed before.

use super::integrators::{Control, StepError};
use super::outcome::{FlatState, FloorReport, Outcome, SeparationState, Slide};
use super::run::RunError;
use super::scene::{End, Scene};
pub use super::units::{Units, UNIT_LADDER};

impl Units {
    /// `scene` in its own units: the unit ladder, θ̇0 T, a fixed step / T, an end time / T.
    pub fn scale_scene(&self, scene: &Scene) -> Scene {
        let mut s = scene.clone();
        s.ladder = UNIT_LADDER;
        s.rate0 = scene.rate0 * self.time;
        s.control = scene.control.map(|c| match c {
            Control::Fixed(h) => Control::Fixed(h / self.time),
            tol => tol,
        });
        if let End::Time(t) = scene.end {
            s.end = End::Time(t / self.time);
        }
        s
    }

    /// An outcome in the scene's units, in SI.
    pub fn outcome_to_si(&self, mut o: Outcome) -> Outcome {
        let (t, l, f) = (self.time, self.length, self.force);
        o.separation = o.separation.map(|s| SeparationState {
            time: s.time * t,
            angle: s.angle,
            rate: s.rate / t,
        });
        o.flat = o.flat.map(|s| FlatState {
            time: s.time * t,
            rate: s.rate / t,
            centre_x: s.centre_x * l,
            centre_velocity_x: s.centre_velocity_x * (l / t),
            centre_velocity_y: s.centre_velocity_y * (l / t),
        });
        o.slide = o.slide.map(|s| Slide {
            impact_time: s.impact_time * t,
            centre_velocity_x: s.centre_velocity_x * (l / t),
            centre_x_end: s.centre_x_end * l,
            energy_lost: s.energy_lost,
        });
        o.last = (o.last.0 * t, o.last.1, o.last.2 / t);
        o.floor_report = o.floor_report.map(|r| FloorReport {
            floor_force_min: r.floor_force_min * f,
            top_clearance_min: r.top_clearance_min * l,
        });
        if let Some(trace) = o.trace.as_mut() {
            for p in trace {
                p.t *= t;
                p.rate /= t;
                p.forces = p.forces.map(|(w, fl)| (w * f, fl * f));
            }
        }
        // energy_error and energy_lost are over m g l, momentum_error over m √(g l): unit-free.
        o
    }

    /// A run error in the scene's units, in SI (times and steps in seconds).
    pub fn error_to_si(&self, e: RunError) -> RunError {
        let t = self.time;
        match e {
            RunError::Step(StepError::StepTooSmall { t: at, h }) => {
                RunError::Step(StepError::StepTooSmall {
                    t: at * t,
                    h: h * t,
                })
            }
            RunError::Step(StepError::NotFinite { t: at }) => {
                RunError::Step(StepError::NotFinite { t: at * t })
            }
            RunError::Step(StepError::NewtonFailed { t: at }) => {
                RunError::Step(StepError::NewtonFailed { t: at * t })
            }
            RunError::Step(StepError::NoTaylorSeries { t: at }) => {
                RunError::Step(StepError::NoTaylorSeries { t: at * t })
            }
            RunError::TooManySteps { limit, t: at } => RunError::TooManySteps { limit, t: at * t },
            RunError::LiftOff { t: at, theta } => RunError::LiftOff { t: at * t, theta },
            other @ RunError::Start(_) => other,
        }
    }
}
