//! Checks of secs. 2.2-2.6, eqs. (11)-(28).

use crate::ladder::analysis::{AngularMomentum, Reference, ReferencePoint};
use crate::ladder::forces::*;
use crate::ladder::geometry::Corner;
use crate::ladder::particles::{
    as_system, external_torque_about, floor_force_from_motion, wall_force_from_motion,
};
use crate::ladder::torque::*;
use crate::ladder::{Ladder, State};
use crate::registry::{misprint, printed, reference, vector_chains, Chain};
use crate::scalar::Scalar;
use crate::system::rate;
use crate::vector::Vec3;

/// The particle model's torque about a corner plus, for a moving corner, the torque of the
/// coordinate force (17) on the centre of mass: the right side of eq. (40).
pub(super) fn torque_with_coordinate_force<S: Scalar>(k: Corner, l: &Ladder<S>, s: &State<S>) -> S {
    let (_, rhs) = crate::ladder::analysis::torque_equation(
        &Reference::Corner(k),
        AngularMomentum::Relative,
        l,
        s,
    );
    rhs
}

pub(super) fn eq11<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let sys = as_system(l, s);
    let l_a = |l: &Ladder<S::Dual>, s: &State<S::Dual>| as_system(l, s).angular_momentum().z;
    vec![vec![
        reference("dL_A/dt (particles; AD)", d_dt!(l_a, l, s)),
        printed(
            "2F_f l sin θ − mgl sin θ − 2F_w l cos θ with (14), (15)",
            torque_about_a(l, s, wall_force(l, s), floor_force(l, s)),
        ),
        reference(
            "particles: τ_A of gravity and contact forces",
            external_torque_about(l, &sys, &Vec3::zero()).z,
        ),
    ]]
}

pub(super) fn eq11_forces_from_motion<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let sys = as_system(l, s);
    vec![vec![
        printed(
            "τ_A (11) with the forces the motion requires",
            torque_about_a(
                l,
                s,
                wall_force_from_motion(&sys),
                floor_force_from_motion(l, &sys),
            ),
        ),
        reference(
            "particles: τ_A",
            external_torque_about(l, &sys, &Vec3::zero()).z,
        ),
    ]]
}

pub(super) fn eq12<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [a, b] = eq12_angular_momentum_about_a(l, s);
    vec![vec![
        printed("−ml²θ̇ + ml²θ̇/3", a),
        printed("−2ml²θ̇/3", b),
        reference(
            "particles: Σ x_i × m_i v_i",
            as_system(l, s).angular_momentum().z,
        ),
    ]]
}

pub(super) fn eq13<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [a, b] = eq13_moment_of_inertia_about_corner(l);
    let sys = as_system(l, s);
    let about = |k| sys.moment_of_inertia_about(&crate::ladder::geometry::corner_position(k, l, s));
    vec![vec![
        printed("I_cm + ml²", a),
        printed("4ml²/3", b),
        reference("particles: I about A", about(Corner::A)),
        reference("particles: I about C", about(Corner::C)),
        reference("particles: I about D", about(Corner::D)),
        reference("particles: I about E", about(Corner::E)),
    ]]
}

pub(super) fn eq14<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vec![vec![
        printed("m a_x with (8)", wall_force_via_acceleration(l, s)),
        printed("ml cos θ θ̈ − ml sin θ θ̇²", wall_force(l, s)),
        reference(
            "particles: Σ m_i a_i,x",
            wall_force_from_motion(&as_system(l, s)),
        ),
    ]]
}

pub(super) fn eq15<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vec![vec![
        printed("mg + m a_y with (8)", floor_force_via_acceleration(l, s)),
        printed("mg − ml sin θ θ̈ − ml cos θ θ̇²", floor_force(l, s)),
        reference(
            "particles: mg + Σ m_i a_i,y",
            floor_force_from_motion(l, &as_system(l, s)),
        ),
    ]]
}

/// An analysis display: d/dt of the printed angular momentum, the printed forms, the reference.
pub(super) fn analysis_chain<S: Scalar>(
    d_l: S,
    forms: Vec<crate::registry::Side<S>>,
    reference_rhs: S,
) -> Vec<Chain<S>> {
    let mut c = vec![printed("dL/dt (AD of the printed L)", d_l)];
    c.extend(forms);
    c.push(reference(
        "particles: τ_P + (x_cm − x_P) × (−m a_P)",
        reference_rhs,
    ));
    vec![c]
}

pub(super) fn eq16<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let f = eq16_torque_analysis_a(l, s);
    let labels = [
        "−2ml²θ̈/3",
        "τ_A (11) with (14), (15)",
        "expanded",
        "mgl sin θ − 2ml²θ̈",
    ];
    let forms = labels.iter().zip(f).map(|(&n, v)| printed(n, v)).collect();
    analysis_chain(
        d_dt!(angular_momentum_about_a, l, s),
        forms,
        torque_with_coordinate_force(Corner::A, l, s),
    )
}

pub(super) fn eq17<S: Scalar>(
    sys: &crate::system::System<S>,
    p: &crate::system::Point<S>,
) -> Vec<Chain<S>> {
    // In P's frame each particle accelerates by a_i − a_P; Newton there needs the extra force
    // Σ m_i (a_i − a_P) − Σ F_i, which is the coordinate force on the whole mass.
    let apparent = crate::vector::sum(
        sys.particles
            .iter()
            .map(|q| (q.a.clone() - p.a.clone()).scale(&q.m)),
    ) - sys.total_force();
    vector_chains(vec![
        printed("F_P = −m a_P", coordinate_force(&sys.total_mass(), &p.a)),
        reference("Σ m_i (a_i − a_P) − F", apparent),
    ])
}

pub(super) fn eq18<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vec![vec![
        printed("I_cm θ̇", angular_momentum_about_b(l, s)),
        reference(
            "particles: L_cm (34)",
            as_system(l, s).spin_angular_momentum().z,
        ),
    ]]
}

pub(super) fn eq19<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let f = eq19_torque_analysis_b(l, s);
    let labels = [
        "ml²θ̈/3",
        "F_f l sin θ − F_w l cos θ",
        "expanded",
        "mgl sin θ − ml²θ̈",
    ];
    let forms = labels.iter().zip(f).map(|(&n, v)| printed(n, v)).collect();
    analysis_chain(
        d_dt!(angular_momentum_about_b, l, s),
        forms,
        torque_with_coordinate_force(Corner::B, l, s),
    )
}

pub(super) fn coordinate_force_of<S: Scalar>(k: Corner, l: &Ladder<S>, s: &State<S>) -> Vec3<S> {
    let a = Reference::Corner(k).motion(l, s).a;
    coordinate_force(&l.m, &a)
}

pub(super) fn eq20<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [a, b] = eq20_coordinate_force_c(l, s);
    vector_chains(vec![
        printed("(0, −2m ÿ_cm)", a),
        printed("(0, 2ml sin θ θ̈ + 2ml cos θ θ̇²)", b),
        reference("−m a_C (AD of x_C)", coordinate_force_of(Corner::C, l, s)),
    ])
}

pub(super) fn relative_l<S: Scalar>(k: Corner, l: &Ladder<S>, s: &State<S>) -> S {
    crate::ladder::analysis::angular_momentum_about(
        &Reference::Corner(k),
        AngularMomentum::Relative,
        l,
        s,
    )
}

pub(super) fn eq21<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [a, b] = eq21_angular_momentum_about_c(l, s);
    vec![vec![
        printed("I_C θ̇", a),
        printed("4ml²θ̇/3", b),
        reference("particles: L'_C (39)", relative_l(Corner::C, l, s)),
    ]]
}

pub(super) fn five_forms<S: Scalar>(
    labels: [&'static str; 5],
    f: [S; 5],
) -> Vec<crate::registry::Side<S>> {
    labels.iter().zip(f).map(|(&n, v)| printed(n, v)).collect()
}

pub(super) fn eq22<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let labels = [
        "4ml²θ̈/3",
        "τ_C + F_C,y l sin θ",
        "−mgl sin θ + 2F_f l sin θ + F_C,y l sin θ",
        "expanded",
        "mgl sin θ",
    ];
    let d_l = d_dt!(
        |l: &Ladder<S::Dual>, s: &State<S::Dual>| eq21_angular_momentum_about_c(l, s)[1].clone(),
        l,
        s
    );
    analysis_chain(
        d_l,
        five_forms(labels, eq22_torque_analysis_c(l, s)),
        torque_with_coordinate_force(Corner::C, l, s),
    )
}

pub(super) fn eq23<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [a, b] = eq23_coordinate_force_d(l, s);
    vector_chains(vec![
        printed("(−2m ẍ_cm, 0)", a),
        printed("(−2ml cos θ θ̈ + 2ml sin θ θ̇², 0)", b),
        reference("−m a_D (AD of x_D)", coordinate_force_of(Corner::D, l, s)),
    ])
}

pub(super) fn eq24<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [a, b] = eq24_angular_momentum_about_d(l, s);
    vec![vec![
        printed("I_D θ̇", a),
        printed("4ml²θ̇/3", b),
        reference("particles: L'_D (39)", relative_l(Corner::D, l, s)),
    ]]
}

pub(super) fn eq25<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let labels = [
        "4ml²θ̈/3",
        "τ_D − F_D,x l cos θ",
        "mgl sin θ − 2F_w l cos θ − F_D,x l cos θ",
        "expanded",
        "mgl sin θ",
    ];
    let d_l = d_dt!(
        |l: &Ladder<S::Dual>, s: &State<S::Dual>| eq24_angular_momentum_about_d(l, s)[1].clone(),
        l,
        s
    );
    analysis_chain(
        d_l,
        five_forms(labels, eq25_torque_analysis_d(l, s)),
        torque_with_coordinate_force(Corner::D, l, s),
    )
}

pub(super) fn eq26<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [a, b] = eq26_coordinate_force_e(l, s);
    vector_chains(vec![
        printed("(−2m ẍ_cm, −2m ÿ_cm)", a),
        printed("expanded with (8)", b),
        reference("−m a_E (AD of x_E)", coordinate_force_of(Corner::E, l, s)),
    ])
}

pub(super) fn eq27<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [a, b] = eq27_angular_momentum_about_e(l, s);
    vec![vec![
        printed("−ml²θ̇ + ml²θ̇/3", a),
        printed("−2ml²θ̇/3", b),
        reference("particles: L'_E (39)", relative_l(Corner::E, l, s)),
    ]]
}

pub(super) fn eq28<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [f0, f1, f2, f3, f4] = eq28_torque_analysis_e(l, s);
    let forms = vec![
        printed("−2ml²θ̈/3", f0),
        misprint("τ_E − F_E,y l sin θ (as printed)", f1),
        crate::registry::corrected(
            "τ_E + F_E,x l cos θ − F_E,y l sin θ",
            eq28_second_form_corrected(l, s),
        ),
        printed("mgl sin θ + F_E,x l cos θ − F_E,y l sin θ", f2),
        printed("expanded", f3),
        printed("mgl sin θ − 2ml²θ̈", f4),
    ];
    let d_l = d_dt!(
        |l: &Ladder<S::Dual>, s: &State<S::Dual>| eq27_angular_momentum_about_e(l, s)[1].clone(),
        l,
        s
    );
    analysis_chain(d_l, forms, torque_with_coordinate_force(Corner::E, l, s))
}
