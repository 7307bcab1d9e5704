//! The points of the figure and the note's printed kinematics.
//!
//! The only geometric input is where the ends are while both contacts hold: the top C on the
//! wall at (0, 2l cos θ) and the foot D on the floor at (2l sin θ, 0) (equations/FIGURE.md). The centre of
//! mass B is the midpoint of C and D, E completes the rectangle A-D-E-C, A is the origin. The
//! note's printed formulas for these points, their velocities and accelerations, are separate
//! functions checked against the ones here (velocities by automatic differentiation).

use super::{Ladder, State};
use crate::scalar::Scalar;
use crate::vector::Vec3;

/// The five reference points of the note.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Corner {
    /// The corner of wall and floor, fixed in the lab: the origin.
    A,
    /// The centre of mass of the ladder.
    B,
    /// The top of the ladder, touching the wall.
    C,
    /// The foot of the ladder, touching the floor.
    D,
    /// The fourth corner of the rectangle A-D-E-C: the instantaneous centre of rotation.
    E,
}

impl Corner {
    /// All five, in the note's order.
    pub const ALL: [Corner; 5] = [Corner::A, Corner::B, Corner::C, Corner::D, Corner::E];
    /// The point's letter.
    pub fn name(self) -> &'static str {
        match self {
            Corner::A => "A",
            Corner::B => "B",
            Corner::C => "C",
            Corner::D => "D",
            Corner::E => "E",
        }
    }
}

/// The top of the ladder, on the wall: C = (0, 2l cos θ).
pub fn wall_contact<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
    Vec3::planar(T::int(0), T::int(2) * ladder.l.clone() * st.cos.clone())
}

/// The foot of the ladder, on the floor: D = (2l sin θ, 0).
pub fn floor_contact<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
    Vec3::planar(T::int(2) * ladder.l.clone() * st.sin.clone(), T::int(0))
}

/// The position of one of the points A-E, built from the two contacts alone.
pub fn corner_position<T: Scalar>(corner: Corner, ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
    let (c, d) = (wall_contact(ladder, st), floor_contact(ladder, st));
    match corner {
        Corner::A => Vec3::zero(),
        Corner::B => (c + d).scale(&T::ratio(1, 2)),
        Corner::C => c,
        Corner::D => d,
        Corner::E => c + d,
    }
}

/// Eq. (7), (43): the centre of mass as printed, x_cm = l sin θ, y_cm = l cos θ.
pub fn cm_position<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
    Vec3::planar(
        ladder.l.clone() * st.sin.clone(),
        ladder.l.clone() * st.cos.clone(),
    )
}

/// Eq. (8): the centre-of-mass acceleration as printed,
/// a_x = l cos θ θ̈ − l sin θ θ̇², a_y = −l sin θ θ̈ − l cos θ θ̇².
pub fn cm_acceleration<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
    let (l, s, c) = (ladder.l.clone(), st.sin.clone(), st.cos.clone());
    let (w, wd) = (st.rate.clone(), st.accel.clone());
    Vec3::planar(
        l.clone() * c.clone() * wd.clone() - l.clone() * s.clone() * w.clone() * w.clone(),
        -(l.clone() * s * wd) - l * c * w.clone() * w,
    )
}

/// Eq. (43): the centre-of-mass velocity as printed, v_cm = (l θ̇ cos θ, −l θ̇ sin θ).
pub fn cm_velocity<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
    let lw = ladder.l.clone() * st.rate.clone();
    Vec3::planar(lw.clone() * st.cos.clone(), -(lw * st.sin.clone()))
}

/// Eq. (44): the top as printed, x_C = (0, 2l cos θ).
pub fn top_position<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
    Vec3::planar(T::int(0), T::int(2) * ladder.l.clone() * st.cos.clone())
}

/// Eq. (44): the top's velocity as printed, v_C = (0, −2l θ̇ sin θ).
pub fn top_velocity<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
    Vec3::planar(
        T::int(0),
        -(T::int(2) * ladder.l.clone() * st.rate.clone() * st.sin.clone()),
    )
}

/// Eq. (45): x_cm − x_C = (l sin θ, −l cos θ) as printed.
pub fn cm_from_top<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
    Vec3::planar(
        ladder.l.clone() * st.sin.clone(),
        -(ladder.l.clone() * st.cos.clone()),
    )
}

/// Eq. (45): v_cm − v_C = (l θ̇ cos θ, l θ̇ sin θ) as printed.
pub fn cm_velocity_from_top<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
    let lw = ladder.l.clone() * st.rate.clone();
    Vec3::planar(lw.clone() * st.cos.clone(), lw * st.sin.clone())
}

/// Eq. (46): (x_cm − x_C) × v_cm = l² θ̇ (cos²θ − sin²θ) ẑ as printed.
pub fn eq46_cross<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
    let (s, c) = (st.sin.clone(), st.cos.clone());
    Vec3::along_z(
        ladder.l.clone() * ladder.l.clone() * st.rate.clone() * (c.clone() * c - s.clone() * s),
    )
}

/// Eq. (47): (x_cm − x_C) × (v_cm − v_C) = l² θ̇ ẑ as printed.
pub fn eq47_cross<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
    Vec3::along_z(ladder.l.clone() * ladder.l.clone() * st.rate.clone())
}

/// Eq. (48): v_cm × v_C = −2 l² θ̇² cos θ sin θ ẑ as printed.
pub fn eq48_cross<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
    let l2 = ladder.l.clone() * ladder.l.clone();
    Vec3::along_z(
        -(T::int(2) * l2 * st.rate.clone() * st.rate.clone() * st.cos.clone() * st.sin.clone()),
    )
}
