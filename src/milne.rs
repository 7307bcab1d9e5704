//! Appendix B: chap. 8 of Milne's *Vectorial Mechanics* (1948), in Milne's own notation.
//!
//! Every function here computes one of Milne's quantities from Milne's own definition, so that
//! the registry can hold it against ours (from [`crate::system`]) without borrowing our formula.
//! The dictionary (note, App. B):
//!
//! | Milne            | ours                         | where              |
//! |------------------|------------------------------|--------------------|
//! | Σ m, M           | m                            | (64), (72)         |
//! | **L**            | **P** (momentum)             | (65), (73)         |
//! | **H**(O)         | **L**, **L**_P               | (66), (76), (77)   |
//! | **P**, **R**     | **F**_i, **F** (forces)      | (67)               |
//! | **Γ**(O)         | **τ**                        | (68)               |
//! | r̄                | x_cm, later x_cm − x_P       | (72), (80)         |
//! | O', O            | origin, moving point P       | (75)               |
//! | **r**', **r**_0, **r** | x_i, x_P, x_i − x_P    | (75)               |
//! | **V**, **v**'    | v_P, v_i − v_P               | (81), (82)         |
//! | **H**_r(O)       | **L**'_P                     | (83)               |
//! | G (C in sec. 300), G' | the centre of mass, a fixed point on it | (79), (84), (87) |
//! | ∧                | ×                            |                    |
//!
//! Milne's O is his reference point: the fixed origin in secs. 295-299, a moving point from
//! sec. 300 on (the note's P), and his O' is then the fixed origin. Positions relative to O are
//! `r = x_i − x_O`; every dot (ṙ, r̈, r̄̇, **V** = ṙ_0) is a rate of change along the motion,
//! taken here by automatic differentiation ([`System::along_motion`], [`Point::along_motion`])
//! rather than written out, so no velocity or acceleration of ours enters Milne's quantities
//! except through the motion itself. The force **P** on a particle is the one datum that is not
//! kinematic: in this particle model it is m_i a_i (eq. 29), [`Particle::force`].

use crate::scalar::Scalar;
use crate::system::{rate_vec, Particle, Point, System};
use crate::vector::{sum, Vec3};

/// Milne's fixed origin: O of secs. 295-299, O' from sec. 300 on; our origin, at rest.
pub fn origin<S: Scalar>() -> Point<S> {
    Point::fixed(Vec3::zero())
}

/// Eq. (75): Milne's **r**, the position of a particle relative to his point O (ours
/// x_i − x_P; with O at the origin, x_i).
pub fn r<S: Scalar>(q: &Particle<S>, o: &Point<S>) -> Vec3<S> {
    q.x.clone() - o.x.clone()
}

/// Eq. (75): Milne's **r**', the position of a particle relative to the fixed origin O' (ours
/// x_i).
pub fn r_prime<S: Scalar>(q: &Particle<S>) -> Vec3<S> {
    r(q, &origin())
}

/// Eq. (75): Milne's **r**_0, the position of his point O relative to the origin O' (ours x_P).
pub fn r_0<S: Scalar>(o: &Point<S>) -> Vec3<S> {
    o.x.clone() - origin::<S>().x
}

/// Milne's ṙ = d**r**/dt, by automatic differentiation of **r** along the motion of the particle
/// and of O (ours v_i for a fixed O; v_i − v_P for a moving one).
pub fn r_dot<S: Scalar>(q: &Particle<S>, o: &Point<S>) -> Vec3<S> {
    rate_vec::<S>(&r(&q.along_motion(), &o.along_motion()))
}

/// Milne's r̈ = dṙ/dt, by automatic differentiation of ṙ (ours a_i for a fixed O).
pub fn r_ddot<S: Scalar>(q: &Particle<S>, o: &Point<S>) -> Vec3<S> {
    rate_vec::<S>(&r_dot(&q.along_motion(), &o.along_motion()))
}

/// Eqs. (76), (82): Milne's **v** = ṙ', the velocity of a particle in the frame of the fixed
/// origin (ours v_i).
pub fn v<S: Scalar>(q: &Particle<S>) -> Vec3<S> {
    r_dot(q, &origin())
}

/// Eq. (82): Milne's **v**' = ṙ, the velocity of a particle relative to his moving point O
/// (ours v_i − v_P).
pub fn v_rel<S: Scalar>(q: &Particle<S>, o: &Point<S>) -> Vec3<S> {
    r_dot(q, o)
}

/// Eq. (81): Milne's **V** = ṙ_0, the velocity of his moving point O (ours v_P).
pub fn big_v<S: Scalar>(o: &Point<S>) -> Vec3<S> {
    rate_vec::<S>(&r_0(&o.along_motion()))
}

/// Eq. (89): Milne's d**V**/dt, by automatic differentiation of **V** (ours a_P).
pub fn big_v_dot<S: Scalar>(o: &Point<S>) -> Vec3<S> {
    rate_vec::<S>(&big_v(&o.along_motion()))
}

/// Eqs. (64), (72): Milne's Σ m, written M from sec. 298 on (ours m).
pub fn big_m<S: Scalar>(sys: &System<S>) -> S {
    sys.particles
        .iter()
        .fold(S::int(0), |acc, q| acc + q.m.clone())
}

/// Eqs. (65), (73): Milne's **L** = Σ m ṙ, the total momentum, ṙ about the fixed origin (ours
/// **P**).
pub fn l<S: Scalar>(sys: &System<S>) -> Vec3<S> {
    let o = origin();
    sum(sys.particles.iter().map(|q| r_dot(q, &o).scale(&q.m)))
}

/// Eq. (66): Milne's **H**(O) = Σ **r** ∧ m ṙ of sec. 295, O the fixed origin (ours **L**).
pub fn h_of_o<S: Scalar>(sys: &System<S>) -> Vec3<S> {
    let o = origin();
    sum(sys
        .particles
        .iter()
        .map(|q| r(q, &o).cross(&r_dot(q, &o).scale(&q.m))))
}

/// Eq. (67): Milne's **R** = Σ **P**, the total force; **P** is the force on one particle (ours
/// **F**).
pub fn big_r<S: Scalar>(sys: &System<S>) -> Vec3<S> {
    sum(sys.particles.iter().map(Particle::force))
}

/// Eq. (67): Milne's Σ m r̈, r̈ about the fixed origin (ours Σ m_i a_i).
pub fn sum_m_r_ddot<S: Scalar>(sys: &System<S>) -> Vec3<S> {
    let o = origin();
    sum(sys.particles.iter().map(|q| r_ddot(q, &o).scale(&q.m)))
}

/// Eqs. (68), (69): Milne's **Γ**(O) = Σ **r** ∧ **P**, the moment about O of the forces (ours
/// **τ** for O the origin, **τ**_P for O = P).
pub fn gamma<S: Scalar>(sys: &System<S>, o: &Point<S>) -> Vec3<S> {
    sum(sys.particles.iter().map(|q| r(q, o).cross(&q.force())))
}

/// Eq. (68) as printed: Σ **r** ∧ r̈ about the fixed origin, with no mass (not a torque; kept to
/// show that it fails).
pub fn gamma_as_printed<S: Scalar>(sys: &System<S>) -> Vec3<S> {
    let o = origin();
    sum(sys.particles.iter().map(|q| r(q, &o).cross(&r_ddot(q, &o))))
}

/// Eq. (68) corrected: **Γ**(O) = Σ **r** ∧ m r̈ about the fixed origin, which is Σ **r** ∧ **P**
/// by Newton's law m r̈ = **P**.
pub fn gamma_corrected<S: Scalar>(sys: &System<S>) -> Vec3<S> {
    let o = origin();
    sum(sys
        .particles
        .iter()
        .map(|q| r(q, &o).cross(&r_ddot(q, &o).scale(&q.m))))
}

/// Eq. (72): Milne's Σ m **r**, the first moment of the masses about O.
pub fn sum_m_r<S: Scalar>(sys: &System<S>, o: &Point<S>) -> Vec3<S> {
    sum(sys.particles.iter().map(|q| r(q, o).scale(&q.m)))
}

/// Eqs. (72), (80): Milne's r̄ from M r̄ = Σ m **r**, the centre of mass relative to O (ours x_cm
/// for O the origin, sec. 298; x_cm − x_P for O = P, sec. 301).
pub fn r_bar<S: Scalar>(sys: &System<S>, o: &Point<S>) -> Vec3<S> {
    sum_m_r(sys, o).div(&big_m(sys))
}

/// Eq. (73): Milne's dr̄/dt, r̄ about the fixed origin, by automatic differentiation (ours v_cm).
pub fn r_bar_dot<S: Scalar>(sys: &System<S>) -> Vec3<S> {
    rate_vec::<S>(&r_bar(&sys.along_motion(), &origin()))
}

/// Eq. (74): Milne's d²r̄/dt², by automatic differentiation of dr̄/dt (ours a_cm).
pub fn r_bar_ddot<S: Scalar>(sys: &System<S>) -> Vec3<S> {
    rate_vec::<S>(&r_bar_dot(&sys.along_motion()))
}

/// Eqs. (76), (77), (79), (83): Milne's **H**(O) = Σ **r** ∧ m **v** of sec. 300, the moment of
/// the momenta about a point O that may move, **v** the velocity in the fixed frame (ours
/// **L**_P; **L** for O the origin, where it is also his **H**(O')).
pub fn h<S: Scalar>(sys: &System<S>, o: &Point<S>) -> Vec3<S> {
    sum(sys
        .particles
        .iter()
        .map(|q| r(q, o).cross(&v(q).scale(&q.m))))
}

/// Eq. (83): Milne's **H**_r(O) = Σ **r** ∧ m **v**', the angular momentum relative to the
/// moving point O, **v**' = ṙ (ours **L**'_P, eq. 39).
pub fn h_r<S: Scalar>(sys: &System<S>, o: &Point<S>) -> Vec3<S> {
    sum(sys
        .particles
        .iter()
        .map(|q| r(q, o).cross(&v_rel(q, o).scale(&q.m))))
}

/// Eqs. (79), (84), (87): Milne's G (his C in sec. 300), the centre of mass as a moving point:
/// at r̄ about the origin, with velocity, acceleration and jerk the rates of r̄ by automatic
/// differentiation.
pub fn g<S: Scalar>(sys: &System<S>) -> Point<S> {
    let lifted = sys.along_motion();
    Point {
        x: r_bar(sys, &origin()),
        v: r_bar_dot(sys),
        a: r_bar_ddot(sys),
        j: rate_vec::<S>(&r_bar_ddot(&lifted)),
    }
}

/// Eqs. (87), (88): Milne's G', the fixed point that G passes through at this instant.
pub fn g_prime<S: Scalar>(sys: &System<S>) -> Point<S> {
    Point::fixed(r_bar(sys, &origin()))
}
