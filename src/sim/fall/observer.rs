//! What a fall watches while it runs ([`crate::sim::fall`]): the samples a trace keeps (with the
//! forces when asked), the floor phase's monitors (least floor force and top clearance,
//! minimised on each step's dense output) and the wall's impulse for the momentum balance.

use crate::sim::floor;
use crate::sim::minimum::minimum_on;
use crate::sim::outcome::{FloorReport, Sample};
use crate::sim::rigid;

use crate::ladder::Ladder;
use crate::sim::run::Observer;
use crate::sim::trace::Kept;
use std::cell::Cell;

/// Dense samples per step kept for plots and monitors.
pub(in crate::sim) const SAMPLES_PER_STEP: usize = 4;

/// The observer of both phases: trace samples, floor monitors, the wall's impulse.
pub struct TraceObserver<'a> {
    /// The ladder observed.
    pub ladder: Ladder<f64>,
    /// The phase observed: 1 on the wall, 2 on the floor.
    pub phase: u8,
    /// The samples kept for the trace, when asked for.
    pub trace: Option<&'a mut Kept>,
    /// The floor-phase monitors (top clearance, floor force), once the floor phase has started.
    pub monitor: Option<FloorReport>,
    /// Force evaluations spent by the observer.
    pub force_evals: u64,
    /// Start of the phase: the top clearance is 0 there by construction (eq. (7)), so its
    /// minimum is searched after it.
    pub phase_start: f64,
    /// ∫F_w dt over the wall phase so far, when the momentum balance is asked for.
    pub impulse: Option<f64>,
}

impl TraceObserver<'_> {
    fn record(&mut self, t: f64, theta: f64, rate: f64, centre_x: f64) {
        // The forces of the kept samples are evaluated when the trace is finished.
        if let Some(tr) = self.trace.as_deref_mut() {
            tr.offer(Sample {
                phase: self.phase,
                t,
                theta,
                rate,
                centre_x,
                forces: None,
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
        // On the wall the centre is at x_cm = l sin θ (7).
        self.record(t, y[0], y[1], self.ladder.l * y[0].sin());
    }
    fn wants_steps(&self) -> bool {
        self.impulse.is_some()
    }
    /// The wall's impulse over the step, by 5-point Gauss-Legendre on the dense output, on
    /// [`impulse_pieces`] pieces of the step.
    fn step(&mut self, t0: f64, t1: f64, dense: &dyn Fn(f64) -> [f64; 2]) {
        let ladder = self.ladder;
        if let Some(j) = self.impulse.as_mut() {
            let force = |t: f64| {
                let y = dense(t);
                rigid::wall_force(&ladder, y[0], y[1])
            };
            // |θ̇| grows along the wall phase (θ̈ = Ω² sin θ ≥ 0): its larger end value.
            let rate = dense(t0)[1].abs().max(dense(t1)[1].abs());
            let n = impulse_pieces(ladder.big_omega2().sqrt(), rate, t1 - t0);
            let h = (t1 - t0) / n as f64;
            for i in 0..n {
                let a = t0 + i as f64 * h;
                let b = if i + 1 == n { t1 } else { a + h };
                *j += gauss_legendre_5(force, a, b);
            }
            self.force_evals += 5 * n as u64;
        }
    }
}

/// How many pieces the impulse's quadrature splits a wall-phase step of length `h` into: each
/// piece at most 0.25/(|θ̇| + Ω) long (|θ̇| the larger of the step's end rates), half the step
/// cap of every method but Taylor ([`rigid::event_safe_step`]). The quadrature is resolved by the
/// motion, not by the integrator's steps: its error grows as the 10th power of the piece's
/// length in units of the motion's time scale 1/(|θ̇| + Ω). On the exact motion (tests below)
/// one 5-point rule over 0.5/(|θ̇| + Ω) misses the impulse by up to 4e-12, over half that by
/// ≤ 1e-15 (4 ulps); a Taylor step, up to three times the cap
/// ([`rigid::taylor_event_safe_step`]), in one piece missed it by 2.9e-13 at tolerance 3.4e-16
/// (campaign seed 1, scene 995) where the judge's error model allows 2e-13.
pub fn impulse_pieces(big_omega: f64, rate: f64, h: f64) -> usize {
    // The 1e-9 slack keeps a piece of exactly the length (rounded up by an ulp) whole.
    let n = (h / (0.5 * rigid::event_safe_step(big_omega, rate)) - 1e-9).ceil();
    // Every method's step is capped ([`crate::sim::integrators::Ode::max_step`]): n ≤ 7 for
    // the Taylor method; the bound only guards against a runaway count.
    if n.is_finite() && n > 1.0 {
        n.min(64.0) as usize
    } else {
        1
    }
}

/// m Ẋ = m l cos θ θ̇ while the top touches the wall (eq. (7)), in the scene's units (m = l = 1).
pub fn rigid_momentum_x(theta: f64, rate: f64) -> f64 {
    theta.cos() * rate
}

/// ∫_a^b f by 5-point Gauss-Legendre (exact for polynomials of degree 9).
pub fn gauss_legendre_5(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    // Nodes √(5 ∓ 2√(10/7))/3, weights 128/225 and (322 ± 13√70)/900, rounded to f64 (with 15
    // digits the weights summed to 2 − 1e-15: a relative error of 5e-16 in every impulse).
    const X: [f64; 3] = [0.0, 0.538_469_310_105_683_1, 0.906_179_845_938_664];
    const W: [f64; 3] = [
        0.568_888_888_888_888_9,
        0.478_628_670_499_366_47,
        0.236_926_885_056_189_08,
    ];
    let (c, h) = (0.5 * (a + b), 0.5 * (b - a));
    let s = W[0] * f(c)
        + W[1] * (f(c - h * X[1]) + f(c + h * X[1]))
        + W[2] * (f(c - h * X[2]) + f(c + h * X[2]));
    s * h
}

/// The momentum balance of a fall (Newton's law for the centre, horizontally): the wall force is
/// the only horizontal force, so m Ẋ_end − m Ẋ_0 = ∫F_w dt, with Ẋ = l cos θ θ̇ (eq. (7)) while
/// the top touches the wall. Evaluated on the integrated motion (the impulse by quadrature of
/// (14) on the wall phase's dense output), its defect measures the integrator's error; over the
/// floor phase no horizontal force acts and Ẍ = 0 is integrated exactly, adding only rounding.
/// In units of m √(g l) (the scene's own units: m = l = g = 1).
pub fn momentum_balance(rate_x_end: f64, rate_x_start: f64, impulse: f64) -> f64 {
    (rate_x_end - rate_x_start - impulse).abs()
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
    fn wants_steps(&self) -> bool {
        self.monitor.is_some()
    }
    /// The monitors' minima between samples, searched on the step's dense output.
    fn step(&mut self, t0: f64, t1: f64, dense: &dyn Fn(f64) -> [f64; 4]) {
        let ladder = self.ladder;
        let Some(m) = self.monitor.as_mut() else {
            return;
        };
        let evals = Cell::new(0u64);
        let force = |t: f64| {
            evals.set(evals.get() + 1);
            let y = dense(t);
            floor::floor_force(&ladder, y[0], y[2])
        };
        let clearance = |t: f64| {
            let y = dense(t);
            floor::top_x(&ladder, y[0], y[1])
        };
        let f = minimum_on(force, t0, t1, SAMPLES_PER_STEP);
        m.floor_force_min = m.floor_force_min.min(f);
        let k = SAMPLES_PER_STEP;
        let c = if t0 == self.phase_start {
            minimum_on(clearance, t0 + (t1 - t0) / (k + 1) as f64, t1, k - 1)
        } else {
            minimum_on(clearance, t0, t1, k)
        };
        m.top_clearance_min = m.top_clearance_min.min(c);
        self.force_evals += evals.get();
    }
}
