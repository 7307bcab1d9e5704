//! The contact forces, eqs. (6), (14), (15): Newton's second law for the centre of mass.

use super::geometry::cm_acceleration;
use super::{Ladder, State};
use crate::scalar::Scalar;

/// Eq. (6): the wall force is the only horizontal force, F_w = m a_x.
pub fn wall_force_from_acceleration<T: Scalar>(ladder: &Ladder<T>, a_x: T) -> T {
    ladder.m.clone() * a_x
}

/// Eq. (14): F_w = m a_x with a_x from eq. (8).
pub fn wall_force_via_acceleration<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> T {
    wall_force_from_acceleration(ladder, cm_acceleration(ladder, st).x)
}

/// Eq. (14), last form: F_w = m l cos θ θ̈ − m l sin θ θ̇².
pub fn wall_force<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> T {
    let ml = ladder.m.clone() * ladder.l.clone();
    ml.clone() * st.cos.clone() * st.accel.clone()
        - ml * st.sin.clone() * st.rate.clone() * st.rate.clone()
}

/// Eq. (15), middle form: F_f = m g + m a_y with a_y from eq. (8).
pub fn floor_force_via_acceleration<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> T {
    ladder.m.clone() * ladder.g.clone() + ladder.m.clone() * cm_acceleration(ladder, st).y
}

/// Eq. (15), last form: F_f = m g − m l sin θ θ̈ − m l cos θ θ̇².
pub fn floor_force<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> T {
    let ml = ladder.m.clone() * ladder.l.clone();
    ladder.m.clone() * ladder.g.clone()
        - ml.clone() * st.sin.clone() * st.accel.clone()
        - ml * st.cos.clone() * st.rate.clone() * st.rate.clone()
}
