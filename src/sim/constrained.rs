//! The wall phase in full coordinates: the free rod (x, y, θ) held on the wall and the floor by
//! two constraints with Lagrange multipliers, instead of the note's single coordinate θ
//! (sec. 2.1). The multipliers are the contact forces, so this is also an independent route to
//! eqs. (14), (15) and the separation of footnote 4.
//!
//! # Formulation
//! Units of l, g, m as in [`super::penalty`]. Constraints (top on the wall, foot on the floor):
//! g₁ = x_C = x − sin θ = 0 and g₂ = y_D = y − cos θ = 0, with Jacobian
//! G = [[1, 0, −cos θ], [0, 1, sin θ]]. With M = diag(1, 1, 1/3) and gravity f = (0, −1, 0):
//!
//! M q̈ = f + Gᵀλ,  G q̈ = −(sin θ θ̇², cos θ θ̇²) − 2α ġ − β² g.
//!
//! The second line is the constraint differentiated twice (index 3 → index 1), plus Baumgarte's
//! stabilisation terms (α = β = 0: none). The 2×2 system for λ = (F_w, F_f) has
//! G M⁻¹ Gᵀ = [[1 + 3cos²θ, −3 sin θ cos θ], [−3 sin θ cos θ, 1 + 3 sin²θ]] with determinant 4
//! for every θ, so it is solved in closed form, never singular.
//!
//! # Drift
//! The index-1 form keeps g̈ = 0 only: the integrator's errors in g and ġ are not corrected and
//! the constraints drift (linearly to quadratically in t). Baumgarte's terms turn the drift
//! into a damped oscillator, g̈ + 2α ġ + β² g = 0, bounding it. [`drift`] measures max |g|
//! over time for any integrator; `ladder stability` tabulates it. The constraints are held
//! two-sided here (no separation): the rod then swings through θ = π/2 and back, a long test
//! run for the drift.

use super::event::{Direction, Event};
use super::integrators::AnyStepper;
use super::integrators::{Control, Ode, Stats, Stepper};
use super::rigid::event_safe_step;
use super::run::{integrate_phase, Observer, RunError};
use num_dual::DualNum;

/// Ω = √(3/4), eq. (5) with l = g = 1.
const OMEGA: f64 = 0.866_025_403_784_438_6;

/// The constrained rod: y = [x, y, θ, ẋ, ẏ, θ̇], Baumgarte's α and β (0, 0: unstabilised).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Constrained {
    /// α, damping rate of the constraint error, units of √(g/l).
    pub alpha: f64,
    /// β, its natural frequency, units of √(g/l).
    pub beta: f64,
}

/// The constraint values (g₁, g₂) = (x_C, y_D): zero on the wall and the floor.
pub fn constraints<D: DualNum<Primitive = f64> + Copy>(y: &[D; 6]) -> (D, D) {
    (y[0] - y[2].sin(), y[1] - y[2].cos())
}

/// The multipliers λ = (F_w, F_f) in units of m g: the contact forces (eqs. (14), (15) when the
/// constraints hold).
pub fn multipliers<D: DualNum<Primitive = f64> + Copy>(c: &Constrained, y: &[D; 6]) -> (D, D) {
    let (s, co) = y[2].sin_cos();
    let w2 = y[5] * y[5];
    let (g1, g2) = constraints(y);
    let (gd1, gd2) = (y[3] - co * y[5], y[4] + s * y[5]);
    // b = −G M⁻¹ f − (sin θ θ̇², cos θ θ̇²) − 2α ġ − β² g, with G M⁻¹ f = (0, −1).
    let b1 = -(s * w2) - gd1 * (2.0 * c.alpha) - g1 * (c.beta * c.beta);
    let b2 = -(co * w2) - gd2 * (2.0 * c.alpha) - g2 * (c.beta * c.beta) + 1.0;
    // (G M⁻¹ Gᵀ)⁻¹ = ¼ [[1 + 3 sin²θ, 3 sin θ cos θ], [3 sin θ cos θ, 1 + 3 cos²θ]].
    let sc3 = s * co * 3.0;
    (
        ((s * s * 3.0 + 1.0) * b1 + sc3 * b2) * 0.25,
        (sc3 * b1 + (co * co * 3.0 + 1.0) * b2) * 0.25,
    )
}

impl Ode<6> for Constrained {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 6]) -> [D; 6] {
        let (fw, ff) = multipliers(self, y);
        let (s, c) = y[2].sin_cos();
        // q̈ = M⁻¹ (f + Gᵀλ): Gᵀλ = (F_w, F_f, −cos θ F_w + sin θ F_f).
        [y[3], y[4], y[5], fw, ff - 1.0, (s * ff - c * fw) * 3.0]
    }
    fn max_step(&self, y: &[f64; 6]) -> f64 {
        event_safe_step(OMEGA, y[5])
    }
    /// Absolute control in units of l and √(g l) (the constraint values are differences).
    fn scale(&self, _y: &[f64; 6]) -> [f64; 6] {
        [1.0, 1.0, 1.0, OMEGA, OMEGA, OMEGA]
    }
}

/// The consistent start at (θ0, θ̇0): both constraints and their rates zero.
pub fn start(theta0: f64, rate0: f64) -> [f64; 6] {
    let (s, c) = theta0.sin_cos();
    [s, c, theta0, c * rate0, -s * rate0, rate0]
}

/// Max |g| over [0, t] at each checkpoint t.
#[derive(Clone, Debug, PartialEq)]
pub struct Drift {
    /// (checkpoint time, max(|x_C|, |y_D|) up to it), units of √(l/g) and l.
    pub points: Vec<(f64, f64)>,
    /// Integrator counters.
    pub stats: Stats,
    /// Why the run stopped early, if it did.
    pub error: Option<RunError>,
}

struct DriftObserver<'a> {
    checkpoints: &'a [f64],
    next: usize,
    max: f64,
    points: Vec<(f64, f64)>,
}

impl Observer<6> for DriftObserver<'_> {
    fn observe(&mut self, t: f64, y: &[f64; 6]) {
        let (g1, g2) = constraints(y);
        // Record before this state when it lies past a checkpoint: the maximum up to it.
        while self.next < self.checkpoints.len() && t > self.checkpoints[self.next] {
            self.points.push((self.checkpoints[self.next], self.max));
            self.next += 1;
        }
        self.max = self.max.max(g1.abs()).max(g2.abs());
        if self.next < self.checkpoints.len() && t == self.checkpoints[self.next] {
            self.points.push((t, self.max));
            self.next += 1;
        }
    }
}

/// Integrate the two-sided constrained rod from (θ0, θ̇0) with `method` at `control` to the
/// last checkpoint, recording the constraint drift (increasing checkpoints, dimensionless).
pub fn drift(
    model: &Constrained,
    theta0: f64,
    rate0: f64,
    method: &str,
    control: Control,
    checkpoints: &[f64],
    max_steps: u64,
) -> Drift {
    let t_end = checkpoints.last().copied().unwrap_or(0.0);
    let Some(mut stepper) = AnyStepper::new(method, control, 0.0, start(theta0, rate0)) else {
        return Drift {
            points: Vec::new(),
            stats: Stats::default(),
            error: Some(RunError::Start(format!(
                "method {method} does not take {control:?}"
            ))),
        };
    };
    let mut obs = DriftObserver {
        checkpoints,
        next: 0,
        max: 0.0,
        points: Vec::new(),
    };
    let end = integrate_phase(model, &mut stepper, &[], t_end, max_steps, &mut obs);
    Drift {
        points: obs.points,
        stats: stepper.stats(),
        error: end.err(),
    }
}

/// Separation: the wall's multiplier falls through zero.
struct WallMultiplier(Constrained);
impl Event<6> for WallMultiplier {
    fn value(&self, _t: f64, y: &[f64; 6]) -> f64 {
        multipliers(&self.0, y).0
    }
    fn direction(&self) -> Direction {
        Direction::Falling
    }
}

/// The separation angle of the constrained formulation: θ where λ₁ = F_w falls through zero.
pub fn separation_angle(
    model: &Constrained,
    theta0: f64,
    rate0: f64,
    method: &str,
    control: Control,
    max_steps: u64,
) -> Result<f64, RunError> {
    let mut stepper = AnyStepper::new(method, control, 0.0, start(theta0, rate0))
        .ok_or_else(|| RunError::Start(format!("method {method} does not take {control:?}")))?;
    let ev = WallMultiplier(*model);
    let end = integrate_phase(model, &mut stepper, &[&ev], 1e4, max_steps, &mut ())?;
    end.event
        .map(|_| end.y[2])
        .ok_or_else(|| RunError::Start("the wall force did not reach zero".into()))
}
