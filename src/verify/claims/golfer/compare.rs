//! A run of the ball in the cylinder held to the closed form (sec. B.10, Milne sec. 421): what
//! is read off a run, how far that is from the closed form, and how far the integrator's error
//! lets it be.
//!
//! The error model is a Richardson-style comparison of tolerances. The run at rtol is repeated
//! at rtol/100 and rtol/10⁴; with r₀, r₁, r₂ their readings and R the closed form's, the errors
//! eᵢ = rᵢ − R satisfy e₀ = d + e₁ and e₁ = d′ + e₂, d = r₀ − r₁ and d′ = r₁ − r₂ being measured.
//! DOP853 aims at tolerance proportionality (error ∝ rtol; here it falls as rtol^1.1, a factor
//! 150-180 per factor 100, docs/golfers-nemesis.md). Each reading must therefore
//!
//! 1. converge: |d′| ≤ q |d| with q = 1/10 (an error falling at least as rtol^0.5, half the
//!    proportionality aimed at), else its difference is no error estimate (a lowest point
//!    located only to within a step, say, falls as the step, rtol^(1/8));
//! 2. deviate from the closed form by at most |d| + |d′|/(1 − q): from |e₀| ≤ |d| + |e₁| and,
//!    if the contraction shown in 1 holds one level further (|e₂| ≤ q |e₁|), |e₁| ≤ |d′|/(1 − q).
//!
//! Both up to a rounding floor of 8 ε per step (of the three runs) times the reading's scale.
//!
//! The simpler a-priori bound, (accepted steps) × √N rtol × scale, was tried first and is
//! exceeded 1.2-23 times (larger at looser tolerances): an early error in the orbit rate
//! changes ω_z and so turns into a phase error of the height that grows with time, which a sum
//! of local errors does not see. The comparison of tolerances measures that growth.

use super::closed_form::ClosedForm;
use super::model::{parts, Contact, Perturbation};
use super::run::Trace;
use super::Setup;

/// The names of the readings, in the order of [`Readings::groups`].
pub const READINGS: [&str; 8] = [
    "height z(t) at the samples",
    "height back at each period",
    "vertical velocity back at each period",
    "period between lowest points",
    "lowest height",
    "orbit rate",
    "rolling constraint (slip)",
    "distance from the axis",
];

/// What is read off a run, each a list over the run, to be compared with the closed form's
/// values or with another run's.
#[derive(Clone, Debug, Default)]
pub struct Readings {
    /// z at every sample time.
    pub height: Vec<f64>,
    /// z at each multiple of the closed form's period.
    pub returns: Vec<f64>,
    /// ż there.
    pub return_rate: Vec<f64>,
    /// The times between successive lowest points (ż = 0 going up).
    pub periods: Vec<f64>,
    /// z at the lowest points.
    pub lows: Vec<f64>,
    /// φ̇ = (x v_y − y v_x)/(x² + y²) at the samples.
    pub orbit_rate: Vec<f64>,
    /// The components of v + ω × (a n) at the samples.
    pub slip: Vec<f64>,
    /// √(x² + y²) at the samples.
    pub radius: Vec<f64>,
}

impl Readings {
    /// The lists in the order of [`READINGS`].
    pub fn groups(&self) -> [&Vec<f64>; 8] {
        [
            &self.height,
            &self.returns,
            &self.return_rate,
            &self.periods,
            &self.lows,
            &self.orbit_rate,
            &self.slip,
            &self.radius,
        ]
    }

    /// The readings of `trace`, sampled every 1/`per_period` of a period.
    pub fn of(setup: &Setup, trace: &Trace, per_period: usize) -> Readings {
        let rolling = setup.model(Contact::Rolling, Perturbation::None);
        let samples = &trace.at_samples;
        let at_periods = || samples.iter().skip(per_period - 1).step_by(per_period);
        Readings {
            height: samples.iter().map(|y| y[2]).collect(),
            returns: at_periods().map(|y| y[2]).collect(),
            return_rate: at_periods().map(|y| y[5]).collect(),
            periods: trace.lows.windows(2).map(|w| w[1].0 - w[0].0).collect(),
            lows: trace.lows.iter().map(|(_, z)| *z).collect(),
            orbit_rate: samples
                .iter()
                .map(|y| {
                    let [x, v, _] = parts(y);
                    (x[0] * v[1] - x[1] * v[0]) / (x[0] * x[0] + x[1] * x[1])
                })
                .collect(),
            slip: samples.iter().flat_map(|y| rolling.residual(y)).collect(),
            radius: samples.iter().map(|y| y[0].hypot(y[1])).collect(),
        }
    }

    /// The closed form's values at the same places: `periods` periods sampled `per_period`
    /// times each, one lowest point per period, no slip, the distance b − a.
    pub fn closed_form(setup: &Setup, cf: &ClosedForm, periods: usize, per_period: usize) -> Self {
        let n = periods * per_period;
        let dt = cf.period() / per_period as f64;
        Readings {
            height: (1..=n).map(|j| cf.height(j as f64 * dt)).collect(),
            returns: vec![cf.z0; periods],
            return_rate: vec![cf.w0; periods],
            periods: vec![cf.period(); periods.saturating_sub(1)],
            lows: vec![cf.lowest(); periods],
            orbit_rate: vec![cf.orbit_rate; n],
            slip: vec![0.0; 3 * n],
            radius: vec![setup.b - setup.ball.a; n],
        }
    }

    /// The largest difference from `other`, reading by reading (infinite where the lists differ
    /// in length, e.g. a lowest point missing; a NaN counts as infinite).
    pub fn gaps(&self, other: &Readings) -> [f64; 8] {
        let (a, b) = (self.groups(), other.groups());
        std::array::from_fn(|i| {
            if a[i].len() != b[i].len() {
                return f64::INFINITY;
            }
            a[i].iter().zip(b[i]).fold(0.0, |m: f64, (p, q)| {
                let d = (p - q).abs();
                if d.is_nan() {
                    f64::INFINITY
                } else {
                    m.max(d)
                }
            })
        })
    }
}

/// The rounding floor of each reading after `steps` accepted steps: 8 ε per step times the
/// reading's scale (ℓ for lengths, ℓ Ω for velocities, the run's length for times, Ω for the
/// orbit rate).
pub fn rounding_floor(setup: &Setup, steps: u64, run_time: f64) -> [f64; 8] {
    let (l, o) = (setup.length(), setup.orbit_rate);
    let per = steps as f64 * 8.0 * f64::EPSILON;
    [l, l, l * o, run_time, l, o, l * o, l].map(|s| per * s)
}

/// The contraction q each reading's error estimate must show per factor 100 of tolerance.
pub const CONTRACTION: f64 = 0.1;

/// A run's judgement: for each reading its deviation from the closed form, the error estimates
/// (its difference from the run at rtol/100, and that run's from the run at rtol/10⁴) and the
/// rounding floor.
#[derive(Clone, Debug)]
pub struct Judgement {
    /// Largest |r₀ − R|, per reading.
    pub deviation: [f64; 8],
    /// Largest |r₀ − r₁|, per reading.
    pub estimate: [f64; 8],
    /// Largest |r₁ − r₂|, per reading.
    pub next_estimate: [f64; 8],
    /// The rounding floor, per reading.
    pub floor: [f64; 8],
    /// The readings of the run.
    pub readings: Readings,
    /// Accepted steps of the run (at rtol).
    pub steps: u64,
}

impl Judgement {
    /// The allowance of each reading: |d| + |d′|/(1 − q) + floor (see the module docs).
    pub fn allowed(&self) -> [f64; 8] {
        std::array::from_fn(|i| {
            self.estimate[i] + self.next_estimate[i] / (1.0 - CONTRACTION) + self.floor[i]
        })
    }

    /// Whether reading `i`'s estimate converges: |d′| ≤ q |d| + floor, both finite (two runs
    /// that do not find the same number of lowest points estimate nothing).
    pub fn converges(&self, i: usize) -> bool {
        self.estimate[i].is_finite()
            && self.next_estimate[i] <= CONTRACTION * self.estimate[i] + self.floor[i]
    }

    /// Whether every reading converges and is within its allowance.
    pub fn agrees(&self) -> bool {
        let allowed = self.allowed();
        (0..8).all(|i| self.converges(i) && self.deviation[i] <= allowed[i])
    }
}
