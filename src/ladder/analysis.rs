//! One torque analysis about any reference point P, built from first principles.
//!
//! The point is given as a function of the ladder's state ([`Reference`]): a corner of the
//! figure, a point fixed on the ladder at a fraction λ from C to D, a point fixed in the lab, or
//! any combination of A, C, D, E. Its velocity and acceleration come from automatic
//! differentiation. The analysis forms, from the three-particle model,
//!
//! * [`AngularMomentum::Absolute`]: L_P of eq. (37), obeying eq. (38),
//!   dL_P/dt = τ_P + m v_cm × v_P;
//! * [`AngularMomentum::Relative`]: L'_P of eq. (39), obeying eq. (40),
//!   dL'_P/dt = τ_P + (x_cm − x_P) × (−m a_P), the torque of the coordinate force (17);
//!
//! with τ_P the torque of gravity and of the contact forces the motion requires. Both sides are
//! affine in θ̈, so the analysis can be solved for θ̈, which must give eq. (5) for every P.

use super::geometry::{corner_position, Corner};
use super::particles::{as_system, external_torque_about};
use super::{solve_for_accel, Ladder, State};
use crate::scalar::Scalar;
use crate::system::{rate, Point};
use crate::vector::Vec3;

/// A reference point, as a function of the ladder's state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reference {
    /// One of the note's points A-E.
    Corner(Corner),
    /// The point of the ladder at fraction `num/den` of the way from C (0) to D (1).
    OnLadder(i64, i64),
    /// A point fixed in the lab at (x, y) = (xn/den, yn/den) in units of l.
    Lab(i64, i64, i64),
    /// Σ w_k x_k over k = A, C, D, E, with weights given as (numerator, denominator).
    Combination([(i64, i64); 4]),
}

/// Anything that names a point as a function of the ladder's state. Implement `position`; the
/// motion (velocity, acceleration, jerk) follows by automatic differentiation.
pub trait ReferencePoint {
    /// The point's position.
    fn position<T: Scalar>(&self, ladder: &Ladder<T>, st: &State<T>) -> Vec3<T>;

    /// The point's motion: position, and velocity, acceleration, jerk by automatic differentiation.
    fn motion<T: Scalar>(&self, ladder: &Ladder<T>, st: &State<T>) -> Point<T> {
        let l1 = ladder.constant();
        let s1 = st.along_motion();
        let x1 = self.position(&l1, &s1);
        let x2 = self.position(&l1.constant(), &s1.along_motion());
        let x3 = self.position(&l1.constant().constant(), &s1.along_motion().along_motion());
        let j3 = Vec3::<<T::Dual as Scalar>::Dual>::derivative_of(&x3);
        Point {
            x: self.position(ladder, st),
            v: Vec3::<T>::derivative_of(&x1),
            a: Vec3::<T>::derivative_of(&Vec3::<T::Dual>::derivative_of(&x2)),
            j: Vec3::<T>::derivative_of(&Vec3::<T::Dual>::derivative_of(&j3)),
        }
    }
}

impl ReferencePoint for Reference {
    fn position<T: Scalar>(&self, ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
        match *self {
            Reference::Corner(k) => corner_position(k, ladder, st),
            Reference::OnLadder(n, d) => {
                let c = corner_position(Corner::C, ladder, st);
                let dd = corner_position(Corner::D, ladder, st);
                c.clone() + (dd - c).scale(&T::ratio(n, d))
            }
            Reference::Lab(x, y, d) => {
                Vec3::planar(T::ratio(x, d), T::ratio(y, d)).scale(&ladder.l)
            }
            Reference::Combination(w) => [Corner::A, Corner::C, Corner::D, Corner::E]
                .iter()
                .zip(w)
                .fold(Vec3::zero(), |acc, (&k, (n, d))| {
                    acc + corner_position(k, ladder, st).scale(&T::ratio(n, d))
                }),
        }
    }
}

/// Which of Jensen's two angular momenta about a moving point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AngularMomentum {
    /// L_P, eq. (37): ignores the motion of P.
    Absolute,
    /// L'_P, eq. (39): relative to the moving P.
    Relative,
}

/// The angular momentum of the ladder about P (z component), from the particle model.
pub fn angular_momentum_about<T: Scalar>(
    p: &impl ReferencePoint,
    def: AngularMomentum,
    ladder: &Ladder<T>,
    st: &State<T>,
) -> T {
    let sys = as_system(ladder, st);
    let point = p.motion(ladder, st);
    match def {
        AngularMomentum::Absolute => sys.angular_momentum_about(&point).z,
        AngularMomentum::Relative => sys.relative_angular_momentum_about(&point).z,
    }
}

/// Both sides of the torque equation about P: (dL/dt by automatic differentiation, the torque
/// side of eq. (38) or (40)).
pub fn torque_equation<T: Scalar>(
    p: &impl ReferencePoint,
    def: AngularMomentum,
    ladder: &Ladder<T>,
    st: &State<T>,
) -> (T, T) {
    let d_l = rate::<T>(angular_momentum_about(
        p,
        def,
        &ladder.constant(),
        &st.along_motion(),
    ));
    let sys = as_system(ladder, st);
    let point = p.motion(ladder, st);
    let tau_p = external_torque_about(ladder, &sys, &point.x).z;
    let m = sys.total_mass();
    let extra = match def {
        // eq. (38): + m v_cm × v_P
        AngularMomentum::Absolute => sys.cm_velocity().scale(&m).cross(&point.v).z,
        // eq. (40): + (x_cm − x_P) × (−m a_P)
        AngularMomentum::Relative => {
            (sys.centre_of_mass() - point.x.clone())
                .cross(&point.a.scale(&(-m)))
                .z
        }
    };
    (d_l, tau_p + extra)
}

/// The torque equation about P solved for θ̈ (it is affine in θ̈).
pub fn solve_angular_acceleration<T: Scalar>(
    p: &impl ReferencePoint,
    def: AngularMomentum,
    ladder: &Ladder<T>,
    st: &State<T>,
) -> T {
    solve_for_accel(ladder, st, |s| {
        let (lhs, rhs) = torque_equation(p, def, ladder, s);
        lhs - rhs
    })
}
