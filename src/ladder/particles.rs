//! An independent model of the ladder: three particles.
//!
//! A uniform rod is replaced by masses m/6, 2m/3, m/6 at its top C, middle B and foot D. These
//! are Simpson's weights, so the three particles have the rod's mass, centre of mass and second
//! moments exactly (Simpson's rule integrates polynomials of degree ≤ 3 without error), and every
//! quantity the note uses — momentum, angular momentum about any point, kinetic and potential
//! energy, moment of inertia, gravitational torque — is quadratic or lower in position along the
//! rod, hence the same for the particles as for the rod.
//!
//! Nothing here uses the note's formulas: positions come from the two contacts (equations/FIGURE.md),
//! velocities, accelerations and jerks from automatic differentiation along the motion, and the
//! contact forces from Newton's second law for the whole ladder. This is the reference that the
//! note's printed equations are checked against.

use super::geometry::{floor_contact, wall_contact};
use super::{Ladder, State};
use crate::scalar::Scalar;
use crate::system::{Particle, System};
use crate::vector::{sum, Vec3};

/// Positions of the three particles C, B, D.
fn positions<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> [Vec3<T>; 3] {
    let (c, d) = (wall_contact(ladder, st), floor_contact(ladder, st));
    let b = (c.clone() + d.clone()).scale(&T::ratio(1, 2));
    [c, b, d]
}

/// Simpson's masses m/6, 2m/3, m/6.
fn masses<T: Scalar>(m: &T) -> [T; 3] {
    [
        m.clone() * T::ratio(1, 6),
        m.clone() * T::ratio(2, 3),
        m.clone() * T::ratio(1, 6),
    ]
}

/// The ladder as a system of three particles, with velocities, accelerations and jerks obtained
/// by differentiating the positions along the motion (once, twice, three times).
pub fn as_system<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> System<T> {
    let x = positions(ladder, st);
    let l1 = ladder.constant();
    let s1 = st.along_motion();
    let x1 = positions(&l1, &s1);
    let x2 = positions(&l1.constant(), &s1.along_motion());
    let x3 = positions(&l1.constant().constant(), &s1.along_motion().along_motion());
    let m = masses(&ladder.m);
    let particles = (0..3)
        .map(|i| {
            let v = Vec3::<T>::derivative_of(&x1[i]);
            let a = Vec3::<T>::derivative_of(&Vec3::<T::Dual>::derivative_of(&x2[i]));
            let j3 = Vec3::<<T::Dual as Scalar>::Dual>::derivative_of(&x3[i]);
            let j = Vec3::<T>::derivative_of(&Vec3::<T::Dual>::derivative_of(&j3));
            Particle {
                m: m[i].clone(),
                x: x[i].clone(),
                v,
                a,
                j,
            }
        })
        .collect();
    System {
        particles,
        spin: None,
    }
}

/// The wall force the motion requires: the only horizontal external force, so by Newton's
/// second law for the whole ladder it equals Σ m_i a_i,x.
pub fn wall_force_from_motion<T: Scalar>(sys: &System<T>) -> T {
    sys.total_force().x
}

/// The floor force the motion requires: F_f − m g = Σ m_i a_i,y.
pub fn floor_force_from_motion<T: Scalar>(ladder: &Ladder<T>, sys: &System<T>) -> T {
    sys.total_force().y + ladder.m.clone() * ladder.g.clone()
}

/// The torque of the external forces (gravity on each particle, F_w x̂ at C, F_f ŷ at D) about
/// the point `x_p`, with the contact forces the motion requires.
pub fn external_torque_about<T: Scalar>(
    ladder: &Ladder<T>,
    sys: &System<T>,
    x_p: &Vec3<T>,
) -> Vec3<T> {
    let gravity = sum(sys.particles.iter().map(|q| {
        let w = Vec3::planar(T::int(0), -(q.m.clone() * ladder.g.clone()));
        (q.x.clone() - x_p.clone()).cross(&w)
    }));
    let (c, d) = (&sys.particles[0].x, &sys.particles[2].x);
    let wall =
        (c.clone() - x_p.clone()).cross(&Vec3::planar(wall_force_from_motion(sys), T::int(0)));
    let floor = (d.clone() - x_p.clone()).cross(&Vec3::planar(
        T::int(0),
        floor_force_from_motion(ladder, sys),
    ));
    gravity + wall + floor
}
