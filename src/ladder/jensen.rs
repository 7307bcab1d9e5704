//! Appendix A.1-A.5: Jensen's methods applied to the ladder about C, eqs. (43)-(63), as printed.
//!
//! The kinematics (43)-(48) live in [`super::geometry`]; here are the angular momenta, torques
//! and analyses. Each `eqNN_*` function returns the printed forms of its display in order.
//! Two displays are misprinted in the note (see `equations/ERRATA.md`): the last form of (49)
//! drops the mass from the orbital term, and (62) drops factors 2l on its right side; (54)
//! prints θ̇² where (53) implies θ̈. The corrected forms are separate functions.

use super::energy::moment_of_inertia_cm;
use super::forces::floor_force;
use super::geometry::{cm_acceleration, eq46_cross, eq47_cross, eq48_cross, top_position};
use super::torque::{angular_momentum_about_a, eq13_moment_of_inertia_about_corner};
use super::{Ladder, State};
use crate::scalar::{sq, Scalar};
use crate::system::rate;

fn n<T: Scalar>(k: i64) -> T {
    T::int(k)
}

/// m l²
fn ml2<T: Scalar>(l: &Ladder<T>) -> T {
    l.m.clone() * sq(&l.l)
}

/// m g l sin θ
fn mgls<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> T {
    l.m.clone() * l.g.clone() * l.l.clone() * s.sin.clone()
}

/// Eq. (49): L_C (Jensen's L_P of eq. 37, about C) as printed, z components:
/// [L_cm + (x_cm − x_C) × m v_cm with (1) and (46), m l² θ̇/3 + l² θ̇ (cos²θ − sin²θ)].
/// The second form is misprinted (the mass is missing from the orbital term).
pub fn eq49_angular_momentum_about_c<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> [T; 2] {
    let spin = moment_of_inertia_cm(l) * s.rate.clone();
    let orbital = eq46_cross(l, s).z;
    [spin.clone() + l.m.clone() * orbital.clone(), spin + orbital]
}

/// Eq. (49) corrected: L_C = m l² θ̇/3 + m l² θ̇ (cos²θ − sin²θ).
pub fn eq49_corrected<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> T {
    let w = s.rate.clone();
    ml2(l) * w.clone() / n(3) + ml2(l) * w * (sq(&s.cos) - sq(&s.sin))
}

/// Eq. (50): I_C ω as printed, z components: [I_C θ̇ with (13), 4 m l² θ̇/3].
pub fn eq50_rigid_angular_momentum_c<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> [T; 2] {
    let i_c = eq13_moment_of_inertia_about_corner(l)[1].clone();
    [
        i_c * s.rate.clone(),
        n::<T>(4) * ml2(l) * s.rate.clone() / n(3),
    ]
}

/// Eq. (51): the torque about C as printed: [−mgl sin θ + 2 F_f l sin θ with (15),
/// mgl sin θ − 2ml²θ̈ sin²θ − 2ml²θ̇² cos θ sin θ].
pub fn eq51_torque_about_c<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> [T; 2] {
    let (sn, c, w, wd) = (
        s.sin.clone(),
        s.cos.clone(),
        s.rate.clone(),
        s.accel.clone(),
    );
    [
        -mgls(l, s) + n::<T>(2) * floor_force(l, s) * l.l.clone() * sn.clone(),
        mgls(l, s) - n::<T>(2) * ml2(l) * wd * sq(&sn) - n::<T>(2) * ml2(l) * sq(&w) * c * sn,
    ]
}

/// Eq. (52): the torque side of eq. (38) about C, τ̃_C = τ_C + m (v_cm × v_C)_z, as printed:
/// [τ_C − 2ml² cos θ sin θ θ̇² with (51), mgl sin θ − 2ml²θ̈ sin²θ − 4ml²θ̇² cos θ sin θ].
pub fn eq52_modified_torque_c<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> [T; 2] {
    let (sn, c, w, wd) = (
        s.sin.clone(),
        s.cos.clone(),
        s.rate.clone(),
        s.accel.clone(),
    );
    let tau_c = eq51_torque_about_c(l, s)[1].clone();
    [
        tau_c - n::<T>(2) * ml2(l) * c.clone() * sn.clone() * sq(&w),
        mgls(l, s) - n::<T>(2) * ml2(l) * wd * sq(&sn) - n::<T>(4) * ml2(l) * sq(&w) * c * sn,
    ]
}

/// Eq. (53): method 1 about C as printed: [ml²θ̈/3 + ml²θ̈(cos²θ − sin²θ) − 4ml²θ̇² cos θ sin θ,
/// mgl sin θ − 2ml²θ̈ sin²θ − 4ml²θ̇² cos θ sin θ].
pub fn eq53_method_one_c<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> [T; 2] {
    let (sn, c, w, wd) = (
        s.sin.clone(),
        s.cos.clone(),
        s.rate.clone(),
        s.accel.clone(),
    );
    [
        ml2(l) * wd.clone() / n(3) + ml2(l) * wd * (sq(&c) - sq(&sn))
            - n::<T>(4) * ml2(l) * sq(&w) * c * sn,
        eq52_modified_torque_c(l, s)[1].clone(),
    ]
}

/// Eq. (54) as printed: [4 m l² θ̇²/3, m g l sin θ] (misprinted: θ̇² for θ̈).
pub fn eq54_printed<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> [T; 2] {
    [n::<T>(4) * ml2(l) * sq(&s.rate) / n(3), mgls(l, s)]
}

/// Eq. (54) corrected, left side: 4 m l² θ̈/3 (what (53) reduces to with sin²θ + cos²θ = 1).
pub fn eq54_corrected<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> T {
    n::<T>(4) * ml2(l) * s.accel.clone() / n(3)
}

/// Eq. (55): method 3 about C as printed, z components: [L_cm + (x_cm − x_P) × m(v_cm − v_P)
/// with (1) and (47), ml²θ̇/3 + ml²θ̇, 4ml²θ̇/3, I_C θ̇].
pub fn eq55_relative_angular_momentum_c<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> [T; 4] {
    let w = s.rate.clone();
    [
        moment_of_inertia_cm(l) * w.clone() + l.m.clone() * eq47_cross(l, s).z,
        ml2(l) * w.clone() / n(3) + ml2(l) * w.clone(),
        n::<T>(4) * ml2(l) * w / n(3),
        eq50_rigid_angular_momentum_c(l, s)[0].clone(),
    ]
}

/// Eq. (59): Hu's method about C as printed, z components: [dL_A/dt − (x_C × m a_cm)_z with
/// (12) differentiated along the motion, (44) and (8), τ_C of (51)].
pub fn eq59_hu_method_c<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> [T; 2] {
    let d_la = rate::<T>(angular_momentum_about_a(&l.constant(), &s.along_motion()));
    let moment = top_position(l, s)
        .cross(&cm_acceleration(l, s).scale(&l.m))
        .z;
    [d_la - moment, eq51_torque_about_c(l, s)[0].clone()]
}

/// Eq. (60) as printed: [−2ml²θ̈/3 − ((0, 2l cos θ, 0) × (m a_x, m a_y, 0))_z,
/// 2 l sin θ F_f − mgl sin θ], with a from (8) and F_f from (15).
pub fn eq60_hu_components<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> [T; 2] {
    let moment = top_position(l, s)
        .cross(&cm_acceleration(l, s).scale(&l.m))
        .z;
    [
        -(n::<T>(2) * ml2(l) * s.accel.clone()) / n(3) - moment,
        n::<T>(2) * l.l.clone() * s.sin.clone() * floor_force(l, s) - mgls(l, s),
    ]
}

/// Eq. (61) as printed: [−2ml²θ̈/3 + 2ml a_x cos θ, 2ml sin θ (g − l sin θ θ̈ − l cos θ θ̇²) − mgl sin θ].
pub fn eq61_hu_expanded<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> [T; 2] {
    let ml = l.m.clone() * l.l.clone();
    let a_x = cm_acceleration(l, s).x;
    let (sn, c, w, wd) = (
        s.sin.clone(),
        s.cos.clone(),
        s.rate.clone(),
        s.accel.clone(),
    );
    let bracket =
        l.g.clone() - l.l.clone() * sn.clone() * wd.clone() - l.l.clone() * c.clone() * sq(&w);
    [
        -(n::<T>(2) * ml2(l) * wd) / n(3) + n::<T>(2) * ml.clone() * a_x * c,
        n::<T>(2) * ml * sn * bracket - mgls(l, s),
    ]
}

/// Eq. (62) as printed: [−2ml²θ̈/3 + 2ml²cos²θ θ̈ − 2ml² cos θ sin θ θ̇²,
/// mlg sin θ − ml sin²θ θ̈ − ml cos θ sin θ θ̇²] (the right side is misprinted).
pub fn eq62_printed<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> [T; 2] {
    let ml = l.m.clone() * l.l.clone();
    let (sn, c, w, wd) = (
        s.sin.clone(),
        s.cos.clone(),
        s.rate.clone(),
        s.accel.clone(),
    );
    [
        -(n::<T>(2) * ml2(l) * wd.clone()) / n(3) + n::<T>(2) * ml2(l) * sq(&c) * wd.clone()
            - n::<T>(2) * ml2(l) * c.clone() * sn.clone() * sq(&w),
        ml.clone() * l.g.clone() * sn.clone() - ml.clone() * sq(&sn) * wd - ml * c * sn * sq(&w),
    ]
}

/// Eq. (62) corrected, right side: mlg sin θ − 2ml² sin²θ θ̈ − 2ml² cos θ sin θ θ̇².
pub fn eq62_corrected<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> T {
    let (sn, c, w, wd) = (
        s.sin.clone(),
        s.cos.clone(),
        s.rate.clone(),
        s.accel.clone(),
    );
    mgls(l, s) - n::<T>(2) * ml2(l) * sq(&sn) * wd - n::<T>(2) * ml2(l) * c * sn * sq(&w)
}

/// Eq. (63) as printed: [4ml²θ̈/3, mlg sin θ].
pub fn eq63_equation_of_motion<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> [T; 2] {
    [eq54_corrected(l, s), mgls(l, s)]
}

/// Eq. (48) times m: the extra term of eq. (38) about C, m (v_cm × v_C)_z.
pub fn velocity_term_c<T: Scalar>(l: &Ladder<T>, s: &State<T>) -> T {
    l.m.clone() * eq48_cross(l, s).z
}
