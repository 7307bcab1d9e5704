//! The wall phase of a fall ([`crate::sim::fall`]) in the form that keeps its digits: near the
//! release push in the deviation from the start ([`crate::sim::near_release`]), near the floor in
//! φ = π/2 − θ ([`crate::sim::complement`]), in θ elsewhere; no phase at all when the wall would
//! have to pull at the start (the top leaves at once, t_s = 0).

use crate::sim::complement;
use crate::sim::event::{Direction, Event};
use crate::sim::integrators::AnyStepper;
use crate::sim::integrators::{taylor, Stats, Stepper};
use crate::sim::near_release::{self, NearRelease};
use crate::sim::rigid::{self, WallPhase};
use crate::sim::run::{integrate_phase, Observer, PhaseEnd, RunError};
use crate::sim::scene::Scene;
use crate::sim::start_margin::Lean;

/// Separation: the factor g = Ω² cos θ − θ̇² of the wall force falls through zero.
pub struct SeparationEvent(pub f64);
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

/// Where the wall phase starts: (θ, θ̇) after a tiny start's lead-in (`y`), the scene's φ0
/// when it still holds (no lead-in), and the start's margin D0 near the release push.
pub struct WallStart {
    /// (θ, θ̇) where the integration starts.
    pub y: [f64; 2],
    /// φ0 = π/2 − θ0 exactly, when the scene gave it and no lead-in moved the start.
    pub phi0: Option<f64>,
    /// D0 = Ω² cos θ0 − θ̇0² from the inputs (`sim::start_margin`), near the release push.
    pub margin: Option<f64>,
}

/// How the wall phase ended: its end in θ (time since the lead-in; `event` Some at the
/// separation), φ_s when the run carries it better than π/2 − θ_s, the integrator's counters.
pub struct WallEnd {
    pub end: PhaseEnd<2>,
    pub phi_s: Option<f64>,
    pub stats: Stats,
}

/// The wall phase of `scene` (in its own units) from `start` until the separation or `t_end`
/// (time since the lead-in), at most `max_steps` steps, feeding `observer` with (θ, θ̇).
pub fn wall_phase<O: Observer<2>>(
    scene: &Scene,
    start: &WallStart,
    t_end: f64,
    max_steps: u64,
    observer: &mut O,
) -> Result<WallEnd, RunError> {
    let ladder = scene.ladder;
    let [theta0, rate0] = start.y;
    let phi0 = start.phi0.unwrap_or_else(|| complement::complement(theta0));
    let stepper = |y0: [f64; 2]| {
        let control = scene
            .control
            .ok_or_else(|| RunError::Start("no integrator".into()))?;
        AnyStepper::with_order(&scene.method, control, scene.order, 0.0, y0).ok_or_else(|| {
            RunError::Start(format!("method {} does not take {control:?}", scene.method))
        })
    };
    match start.margin {
        // The wall would have to pull at once: the top leaves at t = 0 (the floor phase goes on).
        Some(d) if d <= 0.0 => Ok(WallEnd {
            end: PhaseEnd {
                t: 0.0,
                y: start.y,
                event: Some(0),
            },
            phi_s: Some(phi0),
            stats: Stats::default(),
        }),
        Some(d) => {
            let lean = match start.phi0 {
                Some(p) => Lean::Phi(p),
                None => Lean::Theta(theta0),
            };
            let model = NearRelease::new(ladder.big_omega2(), lean, rate0, d);
            let mut st = stepper([0.0, 0.0])?;
            let mut obs = near_release::InTheta {
                model: &model,
                theta0,
                inner: observer,
            };
            let mut e = near_release::integrate(&model, &mut st, t_end, max_steps, &mut obs)?;
            let (u, rate) = model.travel_and_rate(&e.y);
            e.y = [theta0 + u, rate];
            // φ_s = φ0 − u: no rounding of θ near π/2 enters.
            let phi_s = Some(phi0 - u);
            Ok(WallEnd {
                end: e,
                phi_s,
                stats: st.stats(),
            })
        }
        None if complement::applies(theta0) => {
            let sys = complement::ComplementWall::new(&ladder);
            let event = complement::ComplementSeparation(sys.big_omega2);
            let mut st = stepper([phi0, -rate0])?;
            let mut obs = complement::InTheta(observer);
            let mut e = integrate_phase(&sys, &mut st, &[&event], t_end, max_steps, &mut obs)?;
            let phi_s = Some(e.y[0]);
            e.y = complement::to_theta(&e.y);
            Ok(WallEnd {
                end: e,
                phi_s,
                stats: st.stats(),
            })
        }
        None => {
            let wall = WallPhase::new(&ladder);
            let event = SeparationEvent(wall.big_omega2);
            let mut st = stepper(start.y)?;
            let e = integrate_phase(&wall, &mut st, &[&event], t_end, max_steps, observer)?;
            Ok(WallEnd {
                end: e,
                phi_s: None,
                stats: st.stats(),
            })
        }
    }
}
