//! After the wall: the ladder on the floor alone. **An extension beyond the note**, which stops
//! where the wall force vanishes; equations (P1)-(P5) of `equations/phase2.md`.
//!
//! Once the top has left the wall the ladder has two degrees of freedom: θ, and the abscissa X of
//! its centre B. The foot D stays on the frictionless floor, so B is at (X, l cos θ). The functions
//! here are generic over the scalar type like the note's own, and are checked the same way against
//! a three-particle model of the free ladder ([`as_system`]) and by automatic differentiation.

use super::{Ladder, State};
use crate::scalar::{sq, Scalar};
use crate::system::{Particle, System};
use crate::vector::Vec3;

/// The centre's horizontal motion: X and its time derivatives.
#[derive(Clone, Debug)]
pub struct Slide<T> {
    /// X, the abscissa of the centre B.
    pub x: T,
    /// Ẋ.
    pub rate: T,
    /// Ẍ.
    pub accel: T,
    /// d³X/dt³.
    pub jerk: T,
}

impl<T: Scalar> Slide<T> {
    /// Lift along the motion (X → X + Ẋ ε, ...), as [`State::along_motion`] does for θ.
    pub fn along_motion(&self) -> Slide<T::Dual> {
        Slide {
            x: T::lift(self.x.clone(), self.rate.clone()),
            rate: T::lift(self.rate.clone(), self.accel.clone()),
            accel: T::lift(self.accel.clone(), self.jerk.clone()),
            jerk: T::constant(self.jerk.clone()),
        }
    }
    /// Lift for ∂/∂X at fixed Ẋ.
    pub fn vary_position(&self) -> Slide<T::Dual> {
        Slide {
            x: T::lift(self.x.clone(), T::int(1)),
            ..self.constant()
        }
    }
    /// Lift for ∂/∂Ẋ at fixed X.
    pub fn vary_rate(&self) -> Slide<T::Dual> {
        Slide {
            rate: T::lift(self.rate.clone(), T::int(1)),
            ..self.constant()
        }
    }
    /// The same motion with zero derivative part.
    pub fn constant(&self) -> Slide<T::Dual> {
        Slide {
            x: T::constant(self.x.clone()),
            rate: T::constant(self.rate.clone()),
            accel: T::constant(self.accel.clone()),
            jerk: T::constant(self.jerk.clone()),
        }
    }
}

/// (P1): T = ½ m Ẋ² + ½ m l² (sin²θ + 1/3) θ̇².
pub fn kinetic_energy<T: Scalar>(l: &Ladder<T>, s: &State<T>, x: &Slide<T>) -> T {
    let half = T::ratio(1, 2);
    half.clone() * l.m.clone() * sq(&x.rate)
        + half * l.m.clone() * sq(&l.l) * (sq(&s.sin) + T::ratio(1, 3)) * sq(&s.rate)
}

/// (P2): the centre's horizontal acceleration, Ẍ = 0 (no horizontal force).
pub fn centre_acceleration<T: Scalar>() -> T {
    T::int(0)
}

/// (P3): the equation of motion, θ̈ = sin θ (g/l − cos θ θ̇²)/(sin²θ + 1/3).
pub fn angular_acceleration<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> T {
    s.sin.clone() * (l.g.clone() / l.l.clone() - s.cos.clone() * sq(&s.rate))
        / (sq(&s.sin) + T::ratio(1, 3))
}

/// (P4): the floor force, F_f = m (g − l sin θ θ̈ − l cos θ θ̇²).
pub fn floor_force<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> T {
    l.m.clone()
        * (l.g.clone()
            - l.l.clone() * s.sin.clone() * s.accel.clone()
            - l.l.clone() * s.cos.clone() * sq(&s.rate))
}

/// (P5): the abscissa of the top, x_C = X − l sin θ (clear of the wall while positive).
pub fn top_abscissa<T: Scalar>(l: &Ladder<T>, s: &State<T>, x: &Slide<T>) -> T {
    x.x.clone() - l.l.clone() * s.sin.clone()
}

fn positions<T: Scalar>(l: &Ladder<T>, s: &State<T>, x: &Slide<T>) -> [Vec3<T>; 3] {
    let b = Vec3::planar(x.x.clone(), l.l.clone() * s.cos.clone());
    let half = Vec3::planar(-(l.l.clone() * s.sin.clone()), l.l.clone() * s.cos.clone());
    [b.clone() + half.clone(), b.clone(), b - half]
}

/// The free ladder as three particles (Simpson's weights at C, B, D), with velocities,
/// accelerations and jerks by automatic differentiation: the reference for (P1)-(P5).
pub fn as_system<T: Scalar>(l: &Ladder<T>, s: &State<T>, x: &Slide<T>) -> System<T> {
    let l1 = l.constant();
    let (s1, x1) = (s.along_motion(), x.along_motion());
    let p1 = positions(&l1, &s1, &x1);
    let p2 = positions(&l1.constant(), &s1.along_motion(), &x1.along_motion());
    let p3 = positions(
        &l1.constant().constant(),
        &s1.along_motion().along_motion(),
        &x1.along_motion().along_motion(),
    );
    let p0 = positions(l, s, x);
    let m = [T::ratio(1, 6), T::ratio(2, 3), T::ratio(1, 6)].map(|w| w * l.m.clone());
    let particles = (0..3)
        .map(|i| {
            let j3 = Vec3::<<T::Dual as Scalar>::Dual>::derivative_of(&p3[i]);
            Particle {
                m: m[i].clone(),
                x: p0[i].clone(),
                v: Vec3::<T>::derivative_of(&p1[i]),
                a: Vec3::<T>::derivative_of(&Vec3::<T::Dual>::derivative_of(&p2[i])),
                j: Vec3::<T>::derivative_of(&Vec3::<T::Dual>::derivative_of(&j3)),
            }
        })
        .collect();
    System {
        particles,
        spin: None,
    }
}

/// ℒ = Σ ½ m_i v_i² − Σ m_i g y_i of the free three-particle ladder.
pub fn particle_lagrangian<T: Scalar>(l: &Ladder<T>, s: &State<T>, x: &Slide<T>) -> T {
    as_system(l, s, x)
        .particles
        .iter()
        .fold(T::int(0), |acc, p| {
            acc + p.m.clone() * p.v.dot(&p.v) / T::int(2)
                - p.m.clone() * l.g.clone() * p.x.y.clone()
        })
}

/// Lagrange's equations of the free ladder by automatic differentiation, as residuals
/// (θ equation, X equation): d/dt ∂ℒ/∂q̇ − ∂ℒ/∂q.
pub fn lagrange_residuals<T: Scalar>(l: &Ladder<T>, s: &State<T>, x: &Slide<T>) -> (T, T) {
    let (l1, l2) = (l.constant(), l.constant().constant());
    let d_theta = T::split(particle_lagrangian(&l1, &s.vary_angle(), &x.constant())).1;
    let d_x = T::split(particle_lagrangian(
        &l1,
        &s.constant_state(),
        &x.vary_position(),
    ))
    .1;
    let (sm, xm) = (s.along_motion(), x.along_motion());
    let p_theta =
        <T::Dual as Scalar>::split(particle_lagrangian(&l2, &sm.vary_rate(), &xm.constant())).1;
    let p_x = <T::Dual as Scalar>::split(particle_lagrangian(
        &l2,
        &sm.constant_state(),
        &xm.vary_rate(),
    ))
    .1;
    (T::split(p_theta).1 - d_theta, T::split(p_x).1 - d_x)
}
