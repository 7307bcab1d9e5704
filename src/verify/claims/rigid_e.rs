//! Secs. 2.2 and 2.7: "the rotation of the ladder is not rigid body rotation about [A and E]", so
//! the angular momentum about them is not I θ̇; and sec. 2.2's test for when I θ̇ is right (the
//! centre of mass circling the point with the body's own sense and rate).
//!
//! About E the sentence depends on which angular momentum is meant. E is the ladder's
//! instantaneous centre of rotation: every particle moves as v_i = θ̇ ẑ × (x_i − x_E), so in the
//! lab frame L_E = Σ (x_i − x_E) × m_i v_i = I_E θ̇ exactly (4ml²θ̇/3), rigid rotation about E.
//! Relative to E's own motion (v_E ≠ 0), L′_E = Σ (x_i − x_E) × m_i (v_i − v_E) = −2ml²θ̇/3, the
//! (27) of the note, which is not I_E θ̇. So the sentence is true of L′_E, the quantity sec. 2.6
//! uses, and false of L_E in the lab frame.

use super::{all, Claim};
use crate::ladder::analysis::{angular_momentum_about, AngularMomentum, Reference};
use crate::ladder::geometry::Corner;
use crate::ladder::particles::as_system;
use crate::ladder::torque::eq13_moment_of_inertia_about_corner;
use crate::ladder::{Ladder, State};
use crate::registry::sample::LadderSample::Kinematic;
use crate::scalar::{Rational, Scalar};
use crate::system::Point;
use crate::vector::Vec3;

type Q = Rational;

/// Whether the ladder's angular momentum about corner `k` (as defined by `def`) is I_k θ̇, at
/// every exact state.
pub fn rigid_about(k: Corner, def: AngularMomentum) -> bool {
    all(Kinematic, |l, s| {
        angular_momentum_about(&Reference::Corner(k), def, l, s)
            == eq13_moment_of_inertia_about_corner(l)[1].clone() * s.rate.clone()
    })
}

/// The angular rate at which the centre of mass circles corner `k` (relative to the corner's
/// motion for `Relative`, in the lab for `Absolute`): (r × u)/|r|², r = x_cm − x_k, u = v_cm
/// (− v_k).
fn orbital_rate(k: Corner, def: AngularMomentum, l: &Ladder<Q>, s: &State<Q>) -> Q {
    let sys = as_system(l, s);
    let p: Point<Q> = crate::ladder::analysis::ReferencePoint::motion(&Reference::Corner(k), l, s);
    let r = sys.centre_of_mass() - p.x;
    let u = match def {
        AngularMomentum::Absolute => sys.cm_velocity(),
        AngularMomentum::Relative => sys.cm_velocity() - p.v,
    };
    r.cross(&u).z / r.dot(&r)
}

/// Sec. 2.2's test: I_k θ̇ is the angular momentum exactly when the centre of mass circles k
/// at the body's rate θ̇ (same magnitude and sense). Checked as an equivalence at every exact
/// state, for every corner and both definitions; `sense` is ±1, the printed test's being +1
/// (the same sense).
pub fn orbital_test_decides(sense: i64) -> bool {
    let defs = [AngularMomentum::Absolute, AngularMomentum::Relative];
    [Corner::A, Corner::C, Corner::D, Corner::E]
        .into_iter()
        .all(|k| {
            defs.into_iter().all(|def| {
                all(Kinematic, |l, s| {
                    let same_rate = orbital_rate(k, def, l, s) == Q::int(sense) * s.rate.clone();
                    let rigid = angular_momentum_about(&Reference::Corner(k), def, l, s)
                        == eq13_moment_of_inertia_about_corner(l)[1].clone() * s.rate.clone();
                    same_rate == rigid
                })
            })
        })
}

/// Whether corner `k` is the instantaneous centre: the velocity field of the ladder (from its
/// particles) is θ̇ ẑ × (x − x_k) at each particle. The figure says so of E.
pub fn is_instant_centre_of_particles(k: Corner) -> bool {
    all(Kinematic, |l, s| {
        let x_e = crate::ladder::geometry::corner_position(k, l, s);
        let w = Vec3::along_z(s.rate.clone());
        as_system(l, s)
            .particles
            .iter()
            .all(|q| q.v == w.cross(&(q.x.clone() - x_e.clone())))
    })
}

/// The claims of this module.
pub fn claims() -> Vec<Claim> {
    use AngularMomentum::{Absolute, Relative};
    let relative_not = !rigid_about(Corner::E, Relative);
    let lab_rigid = rigid_about(Corner::E, Absolute) && is_instant_centre_of_particles(Corner::E);
    vec![
        Claim::erratum(
            "sec. 2.2, 2.7",
            "'the ladder is not in rigid-body rotation about E, so L_E is not I_E θ̇': true of L'_E (relative to E's motion, the L_E of (27)), false of L_E in the lab frame, where E is the instantaneous centre and L_E = I_E θ̇",
            (
                "not in rigid-body rotation about E",
                "not rigid for L'_E (relative to moving E); in the lab frame L_E = I_E θ̇ (E is the instantaneous centre)",
            ),
            relative_not && lab_rigid,
            lab_rigid,
        )
        .imprecise(),
        Claim::checked(
            "sec. 2.2",
            "I_P θ̇ is the angular momentum about P exactly when the centre of mass circles P at the body's rate θ̇ (same magnitude and sense): so for C and D (L'), not A and E (L'); in the lab frame (L) for E, not A, C, D",
            orbital_test_decides(1)
                && rigid_about(Corner::C, Relative)
                && rigid_about(Corner::D, Relative)
                && !rigid_about(Corner::C, Absolute)
                && !rigid_about(Corner::A, Absolute),
        ),
    ]
}
