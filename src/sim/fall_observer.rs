//! What a fall watches while it runs ([`super::fall`]): the samples a trace keeps (with the
//! forces when asked), the floor phase's monitors (least floor force and top clearance,
//! minimised on each step's dense output) and the wall's impulse for the momentum balance.

use super::floor;
use super::minimum::minimum_on;
use super::outcome::{FloorReport, Sample};
use super::rigid::{self, Ladder};
use super::run::Observer;
use std::cell::Cell;

/// Dense samples per step kept for plots and monitors.
pub(super) const SAMPLES_PER_STEP: usize = 4;

/// The observer of both phases: trace samples, floor monitors, the wall's impulse.
pub(super) struct TraceObserver<'a> {
    pub(super) ladder: Ladder,
    pub(super) phase: u8,
    pub(super) forces: bool,
    pub(super) trace: Option<&'a mut Vec<Sample>>,
    pub(super) monitor: Option<FloorReport>,
    pub(super) force_evals: u64,
    /// Start of the phase: the top clearance is 0 there by construction (eq. (7)), so its
    /// minimum is searched after it.
    pub(super) phase_start: f64,
    /// ∫F_w dt over the wall phase so far, when the momentum balance is asked for.
    pub(super) impulse: Option<f64>,
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
    fn wants_steps(&self) -> bool {
        self.impulse.is_some()
    }
    /// The wall's impulse over the step, by 5-point Gauss-Legendre on the dense output.
    fn step(&mut self, t0: f64, t1: f64, dense: &dyn Fn(f64) -> [f64; 2]) {
        let ladder = self.ladder;
        if let Some(j) = self.impulse.as_mut() {
            *j += gauss_legendre_5(
                |t| {
                    let y = dense(t);
                    rigid::wall_force(&ladder, y[0], y[1])
                },
                t0,
                t1,
            );
            self.force_evals += 5;
        }
    }
}

/// m Ẋ = m l cos θ θ̇ while the top touches the wall (eq. (7)), in the scene's units (m = l = 1).
pub(super) fn rigid_momentum_x(theta: f64, rate: f64) -> f64 {
    theta.cos() * rate
}

/// ∫_a^b f by 5-point Gauss-Legendre (exact for polynomials of degree 9).
fn gauss_legendre_5(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    const X: [f64; 3] = [0.0, 0.538_469_310_105_683, 0.906_179_845_938_664];
    const W: [f64; 3] = [
        0.568_888_888_888_889,
        0.478_628_670_499_366,
        0.236_926_885_056_189,
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
