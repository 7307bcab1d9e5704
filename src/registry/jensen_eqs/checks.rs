//! Checks of eqs. (43)-(55), (59)-(63).

use crate::ladder::analysis::{
    angular_momentum_about, torque_equation, AngularMomentum, Reference, ReferencePoint,
};
use crate::ladder::geometry::*;
use crate::ladder::jensen::*;
use crate::ladder::particles::{as_system, external_torque_about};
use crate::ladder::{Ladder, State};
use crate::registry::{corrected, misprint, printed, reference, vector_chains, Chain};
use crate::scalar::Scalar;
use crate::system::{rate, rate_vec, Point};

pub(super) type Chains<S> = Vec<Chain<S>>;

pub(super) const C: Reference = Reference::Corner(Corner::C);

pub(super) fn top<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Point<S> {
    C.motion(l, s)
}

pub(super) fn eq43<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let sys = as_system(l, s);
    let mut c = vector_chains(vec![
        printed("x_cm", cm_position(l, s)),
        reference("particles: x_cm", sys.centre_of_mass()),
    ]);
    c.extend(vector_chains(vec![
        printed("v_cm", cm_velocity(l, s)),
        reference(
            "AD of printed x_cm",
            rate_vec::<S>(&cm_position(&l.constant(), &s.along_motion())),
        ),
        reference("particles: v_cm", sys.cm_velocity()),
    ]));
    c
}

pub(super) fn eq44<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let p = top(l, s);
    let mut c = vector_chains(vec![
        printed("x_C", top_position(l, s)),
        reference("geometry: the top", p.x),
    ]);
    c.extend(vector_chains(vec![
        printed("v_C", top_velocity(l, s)),
        reference("AD of the top", p.v),
    ]));
    c
}

pub(super) fn eq45<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let (sys, p) = (as_system(l, s), top(l, s));
    let mut c = vector_chains(vec![
        printed("x_cm − x_C", cm_from_top(l, s)),
        reference("particles − geometry", sys.centre_of_mass() - p.x),
    ]);
    c.extend(vector_chains(vec![
        printed("v_cm − v_C", cm_velocity_from_top(l, s)),
        reference("AD", sys.cm_velocity() - p.v),
    ]));
    c
}

pub(super) fn eq46<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let (sys, p) = (as_system(l, s), top(l, s));
    vector_chains(vec![
        printed("l²θ̇(cos²θ − sin²θ) ẑ", eq46_cross(l, s)),
        reference(
            "(x_cm − x_C) × v_cm, references",
            (sys.centre_of_mass() - p.x).cross(&sys.cm_velocity()),
        ),
    ])
}

pub(super) fn eq47<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let (sys, p) = (as_system(l, s), top(l, s));
    vector_chains(vec![
        printed("l²θ̇ ẑ", eq47_cross(l, s)),
        reference(
            "(x_cm − x_C) × (v_cm − v_C), references",
            (sys.centre_of_mass() - p.x).cross(&(sys.cm_velocity() - p.v)),
        ),
    ])
}

pub(super) fn eq48<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let (sys, p) = (as_system(l, s), top(l, s));
    vector_chains(vec![
        printed("−2l²θ̇² cos θ sin θ ẑ", eq48_cross(l, s)),
        reference("v_cm × v_C, references", sys.cm_velocity().cross(&p.v)),
    ])
}

pub(super) fn eq49<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq49_angular_momentum_about_c(l, s);
    vec![vec![
        reference(
            "particles: L_C (37)",
            angular_momentum_about(&C, AngularMomentum::Absolute, l, s),
        ),
        printed("L_cm + (x_cm − x_P) × m v_cm with (46)", a),
        misprint("ml²θ̇/3 + l²θ̇(cos²θ − sin²θ) (as printed)", b),
        corrected("ml²θ̇/3 + ml²θ̇(cos²θ − sin²θ)", eq49_corrected(l, s)),
    ]]
}

pub(super) fn eq50<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq50_rigid_angular_momentum_c(l, s);
    let sys = as_system(l, s);
    vec![vec![
        printed("I_C θ̇", a),
        printed("4ml²θ̇/3", b),
        reference(
            "particles: I about C times θ̇",
            sys.moment_of_inertia_about(&top(l, s).x) * s.rate.clone(),
        ),
    ]]
}

pub(super) fn eq51<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq51_torque_about_c(l, s);
    let sys = as_system(l, s);
    vec![vec![
        printed("−mgl sin θ + 2F_f l sin θ", a),
        printed("expanded", b),
        reference(
            "particles: τ_C",
            external_torque_about(l, &sys, &top(l, s).x).z,
        ),
    ]]
}

pub(super) fn eq52<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq52_modified_torque_c(l, s);
    let (_, rhs38) = torque_equation(&C, AngularMomentum::Absolute, l, s);
    vec![vec![
        printed("τ_C − 2ml² cos θ sin θ θ̇²", a),
        printed("expanded", b),
        reference("particles: τ_C + m (v_cm × v_C)_z", rhs38),
    ]]
}

pub(super) fn eq53<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq53_method_one_c(l, s);
    let (d_l, _) = torque_equation(&C, AngularMomentum::Absolute, l, s);
    vec![vec![
        reference("dL_C/dt (particles; AD)", d_l),
        printed("ml²θ̈/3 + ml²θ̈(cos²θ − sin²θ) − 4ml²θ̇² cos θ sin θ", a),
        printed("mgl sin θ − 2ml²θ̈ sin²θ − 4ml²θ̇² cos θ sin θ", b),
    ]]
}

pub(super) fn eq53_first_form<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let d = rate::<S>(eq49_corrected(&l.constant(), &s.along_motion()));
    vec![vec![
        reference("d/dt of corrected (49) (AD)", d),
        printed("first form of (53)", eq53_method_one_c(l, s)[0].clone()),
    ]]
}

/// (54): besides the Rust copy of the print, the independent value its correct side states:
/// τ′_C of (40), the torque about C of gravity, the wall and the floor (the forces the motion
/// requires, on the particle model) and of the coordinate force −m a_C at the cm, which is
/// mgl sin θ at every state (sec. 2.4, (22)); the print check holds the printed correct side to it.
pub(super) fn eq54<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [lhs, rhs] = eq54_printed(l, s);
    vec![vec![
        printed("mgl sin θ", rhs),
        misprint("4ml²θ̇²/3 (as printed)", lhs),
        corrected("4ml²θ̈/3", eq54_corrected(l, s)),
        reference(
            EQ54_TORQUE,
            torque_equation(&C, AngularMomentum::Relative, l, s).1,
        ),
    ]]
}

/// The independent value of (54)'s correct side.
const EQ54_TORQUE: &str =
    "torque τ′_C about C of gravity, wall, floor and the coordinate force −m a_C (particles)";

/// The independent value of (62)'s correct (left) side.
const EQ62_RATE: &str = "rate dL_C/dt about the fixed lab point where C is now (particles; AD)";

/// Hu's dL_C/dt of (56) about C: the rate of the particles' angular momentum about the lab point
/// where C is now, held fixed (automatic differentiation along the motion).
fn rate_about_frozen_c<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> S {
    let frozen = Point::fixed(top(l, s).x.constant());
    rate::<S>(
        as_system(&l.constant(), &s.along_motion())
            .angular_momentum_about(&frozen)
            .z,
    )
}

pub(super) fn eq55<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let f = eq55_relative_angular_momentum_c(l, s);
    let labels = [
        "L_cm + (x_cm − x_P) × m(v_cm − v_P) with (47)",
        "ml²θ̇/3 + ml²θ̇",
        "4ml²θ̇/3",
        "I_C θ̇",
    ];
    let mut c = vec![reference(
        "particles: L'_C (39)",
        angular_momentum_about(&C, AngularMomentum::Relative, l, s),
    )];
    c.extend(labels.iter().zip(f).map(|(&n, v)| printed(n, v)));
    vec![c]
}

pub(super) fn eq59<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq59_hu_method_c(l, s);
    let sys = as_system(l, s);
    let x_c = top(l, s).x;
    // Hu's L_C: about the lab point where C is now, held fixed while the ladder moves.
    vec![vec![
        reference(
            "dL_P/dt about the fixed point at C (particles; AD)",
            rate_about_frozen_c(l, s),
        ),
        printed("dL_A/dt − x_C × m a_cm", a),
        printed("τ_C", b),
        reference("particles: τ_C", external_torque_about(l, &sys, &x_c).z),
    ]]
}

pub(super) fn eq60<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq60_hu_components(l, s);
    vec![vec![
        printed("left side", a),
        printed("2l sin θ F_f − mgl sin θ", b),
    ]]
}

pub(super) fn eq61<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq61_hu_expanded(l, s);
    vec![
        vec![printed("left side", a), printed("right side", b)],
        vec![
            reference("left side of (60)", eq60_hu_components(l, s)[0].clone()),
            printed("left side of (61)", eq61_hu_expanded(l, s)[0].clone()),
        ],
    ]
}

/// (62): besides the Rust copy of the print, the independent value its correct (left) side
/// states: Hu's dL_C/dt = dL_A/dt − x_C × m a_cm of (59)-(60), by automatic differentiation of the
/// particles' angular momentum about the fixed point where C is now, at every state.
pub(super) fn eq62<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq62_printed(l, s);
    vec![vec![
        printed("left side", a),
        misprint("mlg sin θ − ml sin²θ θ̈ − ml cos θ sin θ θ̇² (as printed)", b),
        corrected(
            "mlg sin θ − 2ml² sin²θ θ̈ − 2ml² cos θ sin θ θ̇²",
            eq62_corrected(l, s),
        ),
        reference(EQ62_RATE, rate_about_frozen_c(l, s)),
    ]]
}

pub(super) fn eq63<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq63_equation_of_motion(l, s);
    vec![vec![printed("4ml²θ̈/3", a), printed("mlg sin θ", b)]]
}
