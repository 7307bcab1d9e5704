//! Sec. 2.1, Lagrange's method: eqs. (1)-(5), (9), (10).
//!
//! Lagrange's equation (4) is applied by automatic differentiation: ∂ℒ/∂θ by lifting θ
//! (sin θ → sin θ + cos θ ε), ∂ℒ/∂θ̇ by lifting θ̇, and d/dt of the latter by lifting the result
//! once more along the motion (a nested dual number). Nothing is differentiated by hand.

use super::particles::as_system;
use super::{Ladder, State};
use crate::scalar::{sq, Scalar};

/// Eq. (1): the moment of inertia about the centre of mass, I_cm = m l²/3.
pub fn moment_of_inertia_cm<T: Scalar>(ladder: &Ladder<T>) -> T {
    ladder.m.clone() * sq(&ladder.l) / T::int(3)
}

/// Eq. (2), first form: T = m v_cm²/2 + I_cm θ̇²/2, for a given centre-of-mass speed squared.
pub fn kinetic_energy_split<T: Scalar>(ladder: &Ladder<T>, v_cm_squared: T, rate: &T) -> T {
    ladder.m.clone() * v_cm_squared / T::int(2)
        + moment_of_inertia_cm(ladder) * sq(rate) / T::int(2)
}

/// Eq. (2), middle form: T = m (l θ̇)²/2 + m l² θ̇²/6.
pub fn kinetic_energy_middle<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> T {
    let m = ladder.m.clone();
    m.clone() * sq(&(ladder.l.clone() * st.rate.clone())) / T::int(2)
        + m * sq(&ladder.l) * sq(&st.rate) / T::int(6)
}

/// Eq. (2), last form: T = 2 m l² θ̇²/3.
pub fn kinetic_energy<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> T {
    T::int(2) * ladder.m.clone() * sq(&ladder.l) * sq(&st.rate) / T::int(3)
}

/// Eq. (3): the potential energy relative to the floor, V = m g l cos θ.
pub fn potential_energy<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> T {
    ladder.m.clone() * ladder.g.clone() * ladder.l.clone() * st.cos.clone()
}

/// Eq. (9): the energy E = T + V.
pub fn energy<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> T {
    kinetic_energy(ladder, st) + potential_energy(ladder, st)
}

/// Eq. (9): the energy of the start at rest upright, E_0 = m g l.
pub fn initial_energy<T: Scalar>(ladder: &Ladder<T>) -> T {
    ladder.m.clone() * ladder.g.clone() * ladder.l.clone()
}

/// Eq. (5): the equation of motion, θ̈ = (3g/4l) sin θ.
pub fn angular_acceleration<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> T {
    T::int(3) * ladder.g.clone() / (T::int(4) * ladder.l.clone()) * st.sin.clone()
}

/// Eq. (10): θ̇² = (3g/2l)(1 − cos θ), from rest at θ = 0.
pub fn rate_squared<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> T {
    T::int(3) * ladder.g.clone() / (T::int(2) * ladder.l.clone()) * (T::int(1) - st.cos.clone())
}

/// A Lagrangian ℒ(θ, θ̇) of the ladder, evaluable in any scalar type.
pub trait Lagrangian {
    /// ℒ at the given state.
    fn value<T: Scalar>(&self, ladder: &Ladder<T>, st: &State<T>) -> T;
}

/// The note's Lagrangian ℒ = T − V with T from eq. (2) and V from eq. (3).
pub struct NoteLagrangian;

impl Lagrangian for NoteLagrangian {
    fn value<T: Scalar>(&self, ladder: &Ladder<T>, st: &State<T>) -> T {
        kinetic_energy(ladder, st) - potential_energy(ladder, st)
    }
}

/// ℒ = Σ ½ m_i v_i² − Σ m_i g y_i of the three-particle model: no formula of the note used.
pub struct ParticleLagrangian;

impl Lagrangian for ParticleLagrangian {
    fn value<T: Scalar>(&self, ladder: &Ladder<T>, st: &State<T>) -> T {
        let sys = as_system(ladder, st);
        sys.particles.iter().fold(T::int(0), |acc, p| {
            acc + p.m.clone() * p.v.dot(&p.v) / T::int(2)
                - p.m.clone() * ladder.g.clone() * p.x.y.clone()
        })
    }
}

/// Eq. (4), both sides by automatic differentiation: (d/dt ∂ℒ/∂θ̇, ∂ℒ/∂θ).
pub fn lagrange_sides<T: Scalar, L: Lagrangian>(
    lag: &L,
    ladder: &Ladder<T>,
    st: &State<T>,
) -> (T, T) {
    let d_angle = T::split(lag.value(&ladder.constant(), &st.vary_angle())).1;
    // Lift along the motion first, then vary θ̇: the ε₂ part is ∂ℒ/∂θ̇ as a dual number along
    // the motion, whose ε₁ part is its time derivative (mixed partials commute).
    let moving = st.along_motion().vary_rate();
    let dl_drate = <T::Dual as Scalar>::split(lag.value(&ladder.constant().constant(), &moving)).1;
    (T::split(dl_drate).1, d_angle)
}

/// Eq. (4) as a residual, d/dt ∂ℒ/∂θ̇ − ∂ℒ/∂θ; zero exactly on the equation of motion.
pub fn lagrange_residual<T: Scalar, L: Lagrangian>(
    lag: &L,
    ladder: &Ladder<T>,
    st: &State<T>,
) -> T {
    let (lhs, rhs) = lagrange_sides(lag, ladder, st);
    lhs - rhs
}
