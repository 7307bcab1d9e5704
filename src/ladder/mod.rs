//! The ladder of the note: a uniform rod of mass m and length 2l, its top C on a frictionless
//! wall and its foot D on a frictionless floor, at angle θ to the wall (see `equations/FIGURE.md`).
//!
//! The state carries sin θ and cos θ rather than θ, so that every equation is a rational
//! function of the state and can be evaluated exactly at rational points of the unit circle.
//!
//! * [`geometry`]: the points A-E and the note's printed kinematics, eqs. (7), (8), (20), (23),
//!   (26), (43)-(48);
//! * [`particles`]: an independent model of the ladder as three particles, the reference the
//!   note's formulas are checked against;
//! * [`energy`]: Lagrange's method, eqs. (1)-(5), (9), (10);
//! * [`forces`]: the contact forces, eqs. (6), (14), (15);
//! * [`torque`]: the torque analyses about A-E as printed, eqs. (11)-(28);
//! * [`analysis`]: one generic torque analysis about any reference point;
//! * [`jensen`]: Jensen's five methods applied at C, eqs. (42)-(63);
//! * [`floor_phase`]: after the wall, on the floor alone, (P1)-(P5) (beyond the note).

pub mod analysis;
pub mod energy;
pub mod floor_phase;
pub mod forces;
pub mod geometry;
pub mod jensen;
pub mod particles;
pub mod torque;

use crate::scalar::Scalar;

/// The ladder's parameters: in f64 for the simulator, in any [`Scalar`] for the checks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ladder<T> {
    /// Mass m.
    pub m: T,
    /// Half-length l (the ladder is 2l long).
    pub l: T,
    /// Gravitational acceleration g.
    pub g: T,
}

impl<T: Scalar> Ladder<T> {
    /// The same ladder in the dual numbers (parameters do not change in time).
    pub fn constant(&self) -> Ladder<T::Dual> {
        Ladder {
            m: T::constant(self.m.clone()),
            l: T::constant(self.l.clone()),
            g: T::constant(self.g.clone()),
        }
    }
    /// Ω² = 3g/(4l), the rate constant of the equation of motion (5), formed as 3g/(4l) (in f64
    /// the simulator's rounding).
    pub fn big_omega2(&self) -> T {
        T::int(3) * self.g.clone() / (T::int(4) * self.l.clone())
    }
}

/// The ladder's instantaneous state: angle (as sin θ, cos θ) and its time derivatives.
#[derive(Clone, Debug)]
pub struct State<T> {
    /// sin θ.
    pub sin: T,
    /// cos θ.
    pub cos: T,
    /// θ̇.
    pub rate: T,
    /// θ̈.
    pub accel: T,
    /// d³θ/dt³ (only needed to differentiate quantities that contain θ̈).
    pub jerk: T,
}

impl<T: Scalar> State<T> {
    /// Lift along the motion: sin θ → sin θ + cos θ θ̇ ε, cos θ → cos θ − sin θ θ̇ ε,
    /// θ̇ → θ̇ + θ̈ ε, θ̈ → θ̈ + θ⃛ ε. The ε part of any function of the result is its d/dt.
    pub fn along_motion(&self) -> State<T::Dual> {
        State {
            sin: T::lift(self.sin.clone(), self.cos.clone() * self.rate.clone()),
            cos: T::lift(self.cos.clone(), -(self.sin.clone() * self.rate.clone())),
            rate: T::lift(self.rate.clone(), self.accel.clone()),
            accel: T::lift(self.accel.clone(), self.jerk.clone()),
            jerk: T::constant(self.jerk.clone()),
        }
    }
    /// Lift for ∂/∂θ at fixed θ̇, θ̈ (Lagrange's partial derivative).
    pub fn vary_angle(&self) -> State<T::Dual> {
        State {
            sin: T::lift(self.sin.clone(), self.cos.clone()),
            cos: T::lift(self.cos.clone(), -self.sin.clone()),
            rate: T::constant(self.rate.clone()),
            accel: T::constant(self.accel.clone()),
            jerk: T::constant(self.jerk.clone()),
        }
    }
    /// Lift for ∂/∂θ̇ at fixed θ (Lagrange's partial derivative).
    pub fn vary_rate(&self) -> State<T::Dual> {
        State {
            sin: T::constant(self.sin.clone()),
            cos: T::constant(self.cos.clone()),
            rate: T::lift(self.rate.clone(), T::int(1)),
            accel: T::constant(self.accel.clone()),
            jerk: T::constant(self.jerk.clone()),
        }
    }
    /// The same state with zero derivative part (for a partial derivative in another variable).
    pub fn constant_state(&self) -> State<T::Dual> {
        State {
            sin: T::constant(self.sin.clone()),
            cos: T::constant(self.cos.clone()),
            rate: T::constant(self.rate.clone()),
            accel: T::constant(self.accel.clone()),
            jerk: T::constant(self.jerk.clone()),
        }
    }
    /// The same state with a different θ̈ (to solve an equation that is affine in θ̈).
    pub fn with_accel(&self, accel: T) -> Self {
        State {
            accel,
            ..self.clone()
        }
    }
}

/// Solve `r(θ̈) = 0` for θ̈, where `r` is affine in θ̈ (every torque analysis and Lagrange's
/// equation are): θ̈ = −a·r(0) / (r(a) − r(0)). The second point is the ladder's own scale
/// a = g/l, so that r(a) − r(0) does not cancel whatever the units.
pub fn solve_for_accel<T: Scalar>(
    ladder: &Ladder<T>,
    state: &State<T>,
    r: impl Fn(&State<T>) -> T,
) -> T {
    let a = ladder.g.clone() / ladder.l.clone();
    let r0 = r(&state.with_accel(T::int(0)));
    let r1 = r(&state.with_accel(a.clone()));
    -(a * r0.clone()) / (r1 - r0)
}
