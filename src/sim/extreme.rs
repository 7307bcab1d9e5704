//! The wall phase at the edges of its domain: any m, l, g in 1e-30..1e30, starts from almost
//! upright to almost flat, pushes from 1e-15 rad/s to past the speed at which the top leaves
//! the wall at once, and the equilibrium. Every start gets an answer, never a hang:
//!
//! * θ0 = θ̇0 = 0 is an equilibrium (the wall force m l sin θ (Ω² cos θ − θ̇²) is zero for all
//!   time): the ladder never leaves the wall; said so without integrating.
//! * When Ω² cos θ0 − θ̇0² ≤ 0 (for θ0 = 0: θ̇0 ≥ Ω, i.e. cos θ_s = 2/3 + θ̇0²/(3Ω²) ≥ 1) the
//!   wall would have to pull from the first instant: the top leaves at once, t_s = 0, θ_s = θ0.
//!   Near that push the factor is formed exactly and the phase runs in the deviation from the
//!   start (`super::near_release`).
//! * Otherwise the wall phase (5) is integrated *in the ladder's own units as given*, with the
//!   end time scaled by the time unit √(l/g), so that the integrators' scale invariance is put to
//!   the test rather than assumed. The separation angle must not depend on m, l, g; times scale
//!   as √(l/g) and forces as m g (the forces are products m l Ω² ..., each within f64's range
//!   for factors in 1e-30..1e30).

use super::complement;
use super::event::{Direction, Event};
use super::integrators::AnyStepper;
use super::integrators::{Control, Stats, Stepper};
pub use super::lead_in::{linear_lead_in, LINEAR_AMPLITUDE};
use super::near_release::{self, NearRelease};
use super::outcome::SeparationState;
use super::rigid::{separation_factor, WallPhase};

use super::run::{integrate_phase, Observer, RunError};
use super::scene::MAX_END_TIME;
use super::start_margin::Lean;
use crate::ladder::Ladder;

/// How the wall phase from a start ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WallRelease {
    /// The wall force reached zero at this state.
    Separated(SeparationState),
    /// The wall would have to pull at t = 0: the top leaves at once (θ_s = θ0, t_s = 0).
    AtOnce,
    /// θ0 = θ̇0 = 0: equilibrium, the ladder never leaves the wall.
    Equilibrium,
}

/// Separation: the factor Ω² cos θ − θ̇² of the wall force falls through zero.
struct Factor(f64);
impl Event<2> for Factor {
    fn value(&self, _t: f64, y: &[f64; 2]) -> f64 {
        separation_factor(self.0, y[0], y[1])
    }
    fn direction(&self) -> Direction {
        Direction::Falling
    }
}

/// The wall phase of `ladder` from (θ0, θ̇0) with `method` at `control` (in the ladder's own
/// seconds), at most `max_steps` steps. Returns how it ends and the integrator's counters.
pub fn wall_release(
    ladder: &Ladder<f64>,
    theta0: f64,
    rate0: f64,
    method: &str,
    control: Control,
    max_steps: u64,
) -> Result<(WallRelease, Stats), RunError> {
    let big_omega2 = ladder.big_omega2();
    if !(big_omega2.is_finite() && big_omega2 > 0.0 && theta0.is_finite() && rate0.is_finite()) {
        return Err(RunError::Start(format!(
            "no wall phase for Ω² = {big_omega2}, θ0 = {theta0}, θ̇0 = {rate0}"
        )));
    }
    if theta0 == 0.0 && rate0 == 0.0 {
        return Ok((WallRelease::Equilibrium, Stats::default()));
    }
    // Near the release push the factor at the start is formed exactly (`super::start_margin`)
    // and the phase runs in the deviation from the start (`super::near_release`).
    let margin = near_release::near_margin(ladder, Lean::Theta(theta0), rate0);
    if margin.map_or(separation_factor(big_omega2, theta0, rate0), |d| d) <= 0.0 {
        return Ok((WallRelease::AtOnce, Stats::default()));
    }
    // The longest fall the scenes allow (1e4 s at l = g = 1 m, s⁻²), in this ladder's units.
    let t_end = MAX_END_TIME * (ladder.l / ladder.g).sqrt();
    if let Some(d) = margin {
        let model = NearRelease::new(big_omega2, Lean::Theta(theta0), rate0, d);
        let mut stepper = AnyStepper::new(method, control, 0.0, [0.0, 0.0])
            .ok_or_else(|| RunError::Start(format!("method {method} does not take {control:?}")))?;
        let end = near_release::integrate(&model, &mut stepper, t_end, max_steps, &mut ());
        let stats = stepper.stats();
        let end = end?;
        let (u, rate) = model.travel_and_rate(&end.y);
        return separated(end.event, end.t, theta0 + u, rate, stats, t_end);
    }
    let wall = WallPhase::new(ladder);
    let (t0, y0) = linear_lead_in(big_omega2, theta0, rate0)
        .map_or((0.0, [theta0, rate0]), |(t, th, w)| (t, [th, w]));
    // Near the floor, in φ = π/2 − θ (see `super::complement`).
    let in_complement = complement::applies(y0[0]);
    let start = match in_complement {
        true => [complement::complement(y0[0]), -y0[1]],
        false => y0,
    };
    let mut stepper = AnyStepper::new(method, control, 0.0, start)
        .ok_or_else(|| RunError::Start(format!("method {method} does not take {control:?}")))?;
    // In time since the lead-in (the steppers' step floor is relative to |t|).
    let end = if in_complement {
        let sys = complement::ComplementWall::new(ladder);
        let event = complement::ComplementSeparation(big_omega2);
        integrate_phase(
            &sys,
            &mut stepper,
            &[&event],
            t_end - t0,
            max_steps,
            &mut (),
        )
        .map(|mut e| {
            e.y = complement::to_theta(&e.y);
            e
        })
    } else {
        integrate_phase(
            &wall,
            &mut stepper,
            &[&Factor(big_omega2)],
            t_end - t0,
            max_steps,
            &mut (),
        )
    }
    .map(|mut e| {
        e.t += t0;
        e
    });
    let stats = stepper.stats();
    let end = end?;
    separated(end.event, end.t, end.y[0], end.y[1], stats, t_end)
}

/// The separation at (t, θ, θ̇) when the phase ended on its event, else the error of a wall
/// force that never reached zero by `t_end`.
fn separated(
    event: Option<usize>,
    time: f64,
    angle: f64,
    rate: f64,
    stats: Stats,
    t_end: f64,
) -> Result<(WallRelease, Stats), RunError> {
    match event {
        Some(_) => Ok((
            WallRelease::Separated(SeparationState { time, angle, rate }),
            stats,
        )),
        None => Err(RunError::Start(format!(
            "the wall force did not reach zero by t = {t_end:e} s"
        ))),
    }
}

/// An observer that sees times shifted by `.1` (a phase integrated in time since a lead-in).
pub struct Shifted<'a, O>(pub &'a mut O, pub f64);

impl<const N: usize, O: Observer<N>> Observer<N> for Shifted<'_, O> {
    fn samples_per_step(&self) -> usize {
        self.0.samples_per_step()
    }
    fn observe(&mut self, t: f64, y: &[f64; N]) {
        self.0.observe(t + self.1, y);
    }
    fn wants_steps(&self) -> bool {
        self.0.wants_steps()
    }
    fn step(&mut self, t0: f64, t1: f64, dense: &dyn Fn(f64) -> [f64; N]) {
        let shift = self.1;
        self.0.step(t0 + shift, t1 + shift, &|t| dense(t - shift));
    }
}
