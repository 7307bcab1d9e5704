//! Running the penalty model ([`crate::sim::penalty`]) to its separation: the release events, the
//! pre-loaded start after a tiny start's linear lead-in, the separation believed only within
//! its bound of the rigid one (`crate::sim::penalty::confirm`), and one retry at a tenth of the
//! tolerance. Kept apart from the model so each file has one job.

use crate::sim::event::{Direction, Event};
use crate::sim::integrators::AnyStepper;
use crate::sim::integrators::{order, Control, Ode, Stats, Stepper};
use crate::sim::lead_in::linear_lead_in;
use crate::sim::penalty::confirm::{confirm_separation, retry_control};
use crate::sim::penalty::{
    contact_forces, energy, preloaded_start, Contact, Law, PenaltyModel, OMEGA2, T_END,
};
use crate::sim::rigid::separation_factor;
use crate::sim::run::{integrate_phase, RunError};

/// A contact force falling through zero: the wall's (separation) or the floor's (lift-off).
/// The value is the spring-dashpot's force κ p + γ ṗ *before* clipping under either law: the
/// clipped force max(0, ·) is identically zero past its root, and a root finder on it may stop
/// anywhere in that flat stretch (up to a step late: 3e-5 rad at κ = 1e4 once radau5's steps
/// grew with the index-2 weights, `PenaltyModel::index2`).
struct Release {
    model: PenaltyModel,
    floor: bool,
}
impl Event<6> for Release {
    fn value(&self, _t: f64, y: &[f64; 6]) -> f64 {
        let (fw, ff) = contact_forces(&self.model.contact, Law::Switched, y);
        if self.floor {
            ff
        } else {
            fw
        }
    }
    fn direction(&self) -> Direction {
        Direction::Falling
    }
}

/// Where the penalty ladder leaves the wall (dimensionless time).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PenaltySeparation {
    /// θ_s, rad.
    pub angle: f64,
    /// t_s in units of √(l/g).
    pub time: f64,
    /// θ̇ at t_s in units of √(g/l).
    pub rate: f64,
    /// |E(t_s) − E(0)| in units of m g l.
    pub energy_change: f64,
}

/// A penalty run: its result and the work done (also when it failed).
#[derive(Clone, Debug, PartialEq)]
pub struct PenaltyRun {
    /// The separation, or why the run stopped.
    pub result: Result<PenaltySeparation, RunError>,
    /// Integrator counters.
    pub stats: Stats,
}

/// Integrate the penalty model from the pre-loaded start at (θ0, θ̇0) with `stepper` until the
/// wall force falls through zero, at most `max_steps` steps.
pub fn separate_with<St: Stepper<6>>(
    model: &PenaltyModel,
    stepper: &mut St,
    max_steps: u64,
) -> PenaltyRun {
    separate_with_ode(model, model, stepper, max_steps)
}

/// As [`separate_with`], integrating `ode` (the model, or a wrapper of it that changes only how
/// its Jacobian is formed) while the events and the energy are those of `model`.
pub fn separate_with_ode<S: Ode<6>, St: Stepper<6>>(
    model: &PenaltyModel,
    ode: &S,
    stepper: &mut St,
    max_steps: u64,
) -> PenaltyRun {
    let e0 = energy(&model.contact, &stepper.y());
    let wall = Release {
        model: *model,
        floor: false,
    };
    let floor = Release {
        model: *model,
        floor: true,
    };
    let end = integrate_phase(ode, stepper, &[&wall, &floor], T_END, max_steps, &mut ());
    let stats = stepper.stats();
    let result = end.and_then(|e| match e.event {
        Some(0) => Ok(PenaltySeparation {
            angle: e.y[0],
            time: e.t,
            rate: e.y[3],
            energy_change: (energy(&model.contact, &e.y) - e0).abs(),
        }),
        Some(_) => Err(RunError::LiftOff {
            t: e.t,
            theta: e.y[0],
        }),
        None => Err(RunError::Start(format!(
            "the wall force did not reach zero by t = {T_END} √(l/g)"
        ))),
    });
    PenaltyRun { result, stats }
}

/// The separation of the penalty ladder started at (θ0, θ̇0) (θ̇0 in units of √(g/l)) with
/// the method `method` at `control` (dimensionless step or tolerance).
pub fn separation(
    contact: Contact,
    law: Law,
    theta0: f64,
    rate0: f64,
    method: &str,
    control: Control,
    max_steps: u64,
) -> PenaltyRun {
    let fail = |m: String| PenaltyRun {
        result: Err(RunError::Start(m)),
        stats: Stats::default(),
    };
    if !(contact.kappa.is_finite() && contact.kappa > 0.0) {
        return fail(format!("stiffness κ = {} is not usable", contact.kappa));
    }
    if theta0 == 0.0 && rate0 == 0.0 {
        return fail("θ0 = θ̇0 = 0 is the equilibrium: the ladder never leaves the wall".into());
    }
    // The wall would have to pull at once: the ladder leaves it at t = 0. Judged by the factor
    // of F_w = sin θ (Ω² cos θ − θ̇²) (14), as the rigid phases do (`extreme::wall_release`):
    // the product underflows to 0 at a subnormal θ0, and a push short of the limit then "left
    // at once" (the campaign's F9: θ0 = 2e-323 pushed to θ̇0 = 0.82, θ_s = θ0, 0.24 rad from
    // the rigid separation, exit 0).
    if separation_factor(OMEGA2, theta0, rate0) <= 0.0 {
        return PenaltyRun {
            result: Ok(PenaltySeparation {
                angle: theta0,
                time: 0.0,
                rate: rate0,
                energy_change: 0.0,
            }),
            stats: Stats::default(),
        };
    }
    let first = attempt(contact, law, (theta0, rate0), method, control, max_steps);
    // Not believed (a zero outside the bound, or the foot lifting, which the rigid ladder's
    // floor force ≥ m g/4 rules out for κ ≥ 5): tried once more at τ/10 (the campaign's F11,
    // F12; `penalty::confirm::retry_control`), the work of both runs counted.
    let (Some(retry), true) = (retry_control(control), first.1) else {
        return first.0;
    };
    let mut again = attempt(contact, law, (theta0, rate0), method, retry, max_steps).0;
    let (a, b) = (first.0.stats, again.stats);
    again.stats = Stats {
        rhs_evals: a.rhs_evals + b.rhs_evals,
        jacobians: a.jacobians + b.jacobians,
        steps: a.steps + b.steps,
        rejected: a.rejected + b.rejected,
    };
    if let Err(RunError::Start(m)) = &mut again.result {
        m.push_str(" (tried at the scene's tolerance and again at a tenth of it)");
    }
    again
}

/// One run of [`separation`] at `control` after the early answers, and whether its end is
/// not believed (a zero outside the stated bound, or a lift-off).
fn attempt(
    contact: Contact,
    law: Law,
    (theta0, rate0): (f64, f64),
    method: &str,
    control: Control,
    max_steps: u64,
) -> (PenaltyRun, bool) {
    // A tiny start first grows along the linearised motion (as the rigid phases do,
    // `extreme::linear_lead_in`): from a subnormal θ0 the forces ~θ m g have a few bits and no
    // tolerance measures them (the campaign's F4: radau5 from 2.5e-315 left at θ = 0.69). The
    // springs follow the rigid motion there to O(1/κ), the model's own error.
    let (lead, theta_i, rate_i) =
        linear_lead_in(OMEGA2, theta0, rate0).unwrap_or((0.0, theta0, rate0));
    let model = PenaltyModel::new(contact, law);
    let y0 = preloaded_start(&contact, theta_i, rate_i);
    let Some(mut stepper) = AnyStepper::new(method, control, 0.0, y0) else {
        let m = format!("method {method} does not take {control:?}");
        let stats = Stats::default();
        let result = Err(RunError::Start(m));
        return (PenaltyRun { result, stats }, false);
    };
    let mut run = separate_with(&model, &mut stepper, max_steps);
    // A zero of the force is the separation only within the stated bound of the rigid one.
    let tau = match control {
        Control::Tolerance(t) => t,
        Control::Fixed(h) => h.powi(order(method).map_or(2, |p| p as i32 + 1)),
    };
    let mut unbelieved = matches!(run.result, Err(RunError::LiftOff { .. }));
    if let Ok(s) = &mut run.result {
        s.time += lead;
        let start = (theta0, rate0);
        if let Err(m) = confirm_separation(contact.kappa, start, s.angle, run.stats.steps, tau) {
            run.result = Err(RunError::Start(m));
            unbelieved = true;
        }
    }
    (run, unbelieved)
}
