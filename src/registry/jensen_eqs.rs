//! Registry entries and checks for Jensen's methods applied to the ladder about C,
//! eqs. (43)-(55), (59)-(63).

use super::sample::LadderSample;
use super::{
    corrected, eq, misprint, on_ladder, printed, reference, vector_chains, Chain, Equation,
    Erratum, Kind,
};
use crate::ladder::analysis::{
    angular_momentum_about, torque_equation, AngularMomentum, Reference, ReferencePoint,
};
use crate::ladder::geometry::*;
use crate::ladder::jensen::*;
use crate::ladder::particles::{as_system, external_torque_about};
use crate::ladder::{Ladder, State};
use crate::ladder_fns;
use crate::scalar::Scalar;
use crate::system::{rate, rate_vec, Point};

type Chains<S> = Vec<Chain<S>>;

const C: Reference = Reference::Corner(Corner::C);

fn top<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Point<S> {
    C.motion(l, s)
}

fn eq43<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
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

fn eq44<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
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

fn eq45<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
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

fn eq46<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let (sys, p) = (as_system(l, s), top(l, s));
    vector_chains(vec![
        printed("l²θ̇(cos²θ − sin²θ) ẑ", eq46_cross(l, s)),
        reference(
            "(x_cm − x_C) × v_cm, references",
            (sys.centre_of_mass() - p.x).cross(&sys.cm_velocity()),
        ),
    ])
}

fn eq47<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let (sys, p) = (as_system(l, s), top(l, s));
    vector_chains(vec![
        printed("l²θ̇ ẑ", eq47_cross(l, s)),
        reference(
            "(x_cm − x_C) × (v_cm − v_C), references",
            (sys.centre_of_mass() - p.x).cross(&(sys.cm_velocity() - p.v)),
        ),
    ])
}

fn eq48<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let (sys, p) = (as_system(l, s), top(l, s));
    vector_chains(vec![
        printed("−2l²θ̇² cos θ sin θ ẑ", eq48_cross(l, s)),
        reference("v_cm × v_C, references", sys.cm_velocity().cross(&p.v)),
    ])
}

fn eq49<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
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

fn eq50<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
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

fn eq51<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
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

fn eq52<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq52_modified_torque_c(l, s);
    let (_, rhs38) = torque_equation(&C, AngularMomentum::Absolute, l, s);
    vec![vec![
        printed("τ_C − 2ml² cos θ sin θ θ̇²", a),
        printed("expanded", b),
        reference("particles: τ_C + m (v_cm × v_C)_z", rhs38),
    ]]
}

fn eq53<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq53_method_one_c(l, s);
    let (d_l, _) = torque_equation(&C, AngularMomentum::Absolute, l, s);
    vec![vec![
        reference("dL_C/dt (particles; AD)", d_l),
        printed("ml²θ̈/3 + ml²θ̈(cos²θ − sin²θ) − 4ml²θ̇² cos θ sin θ", a),
        printed("mgl sin θ − 2ml²θ̈ sin²θ − 4ml²θ̇² cos θ sin θ", b),
    ]]
}

fn eq53_first_form<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let d = rate::<S>(eq49_corrected(&l.constant(), &s.along_motion()));
    vec![vec![
        reference("d/dt of corrected (49) (AD)", d),
        printed("first form of (53)", eq53_method_one_c(l, s)[0].clone()),
    ]]
}

fn eq54<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [lhs, rhs] = eq54_printed(l, s);
    vec![vec![
        printed("mgl sin θ", rhs),
        misprint("4ml²θ̇²/3 (as printed)", lhs),
        corrected("4ml²θ̈/3", eq54_corrected(l, s)),
    ]]
}

fn eq55<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
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

fn eq59<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq59_hu_method_c(l, s);
    let sys = as_system(l, s);
    let x_c = top(l, s).x;
    // Hu's L_C: about the lab point where C is now, held fixed while the ladder moves.
    let frozen = Point::fixed(x_c.constant());
    let d_frozen = rate::<S>(
        as_system(&l.constant(), &s.along_motion())
            .angular_momentum_about(&frozen)
            .z,
    );
    vec![vec![
        reference(
            "dL_P/dt about the fixed point at C (particles; AD)",
            d_frozen,
        ),
        printed("dL_A/dt − x_C × m a_cm", a),
        printed("τ_C", b),
        reference("particles: τ_C", external_torque_about(l, &sys, &x_c).z),
    ]]
}

fn eq60<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq60_hu_components(l, s);
    vec![vec![
        printed("left side", a),
        printed("2l sin θ F_f − mgl sin θ", b),
    ]]
}

fn eq61<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq61_hu_expanded(l, s);
    vec![
        vec![printed("left side", a), printed("right side", b)],
        vec![
            reference("left side of (60)", eq60_hu_components(l, s)[0].clone()),
            printed("left side of (61)", eq61_hu_expanded(l, s)[0].clone()),
        ],
    ]
}

fn eq62<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq62_printed(l, s);
    vec![vec![
        printed("left side", a),
        misprint("mlg sin θ − ml sin²θ θ̈ − ml cos θ sin θ θ̇² (as printed)", b),
        corrected(
            "mlg sin θ − 2ml² sin²θ θ̈ − 2ml² cos θ sin θ θ̇²",
            eq62_corrected(l, s),
        ),
    ]]
}

fn eq63<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Chains<S> {
    let [a, b] = eq63_equation_of_motion(l, s);
    vec![vec![printed("4ml²θ̈/3", a), printed("mlg sin θ", b)]]
}

/// The entries for Jensen's methods on the ladder.
pub(super) fn equations() -> Vec<Equation> {
    use Kind::*;
    let k = |name, f| on_ladder(name, LadderSample::Kinematic, f);
    let on = |name, f| on_ladder(name, LadderSample::OnShell, f);
    let mut e49 = eq(
        49,
        "A.1",
        "Method 1: L_C about the contact point",
        Kinematic,
        &[
            "ladder::jensen::eq49_angular_momentum_about_c",
            "ladder::jensen::eq49_corrected",
        ],
        vec![k("against L_C (37) of the particles", ladder_fns!(eq49))],
    );
    e49.erratum = Some(Erratum {
        printed: r"\frac{m l^2 \dot{\theta}}{3} \hat{\mathbf{z}} + l^2 \dot{\theta} (\cos^2 \theta - \sin^2 \theta) \hat{\mathbf{z}}",
        corrected: r"\frac{m l^2 \dot{\theta}}{3} \hat{\mathbf{z}} + m l^2 \dot{\theta} (\cos^2 \theta - \sin^2 \theta) \hat{\mathbf{z}}",
        why: "the orbital term is (x_cm − x_C) × m v_cm; the mass m is missing (the term has the wrong dimensions); (53) differentiates the corrected form",
    });
    let mut e54 = eq(
        54,
        "A.1",
        "Method 1 reduced",
        OnShell,
        &[
            "ladder::jensen::eq54_printed",
            "ladder::jensen::eq54_corrected",
        ],
        vec![on("(53) reduced, on the motion", ladder_fns!(eq54))],
    );
    e54.erratum = Some(Erratum {
        printed: r"\frac{4m l^2 \dot{\theta}^2}{3} = m g l \sin \theta",
        corrected: r"\frac{4m l^2 \ddot{\theta}}{3} = m g l \sin \theta",
        why: "cancelling −2ml²θ̈ sin²θ and −4ml²θ̇² cos θ sin θ between the two sides of (53) leaves θ̈, not θ̇²; the printed form is the energy-like θ̇², which is wrong",
    });
    let mut e62 = eq(
        62,
        "A.5",
        "Hu's method about C, expanded",
        OnShell,
        &[
            "ladder::jensen::eq62_printed",
            "ladder::jensen::eq62_corrected",
        ],
        vec![on(
            "left side against printed and corrected right side",
            ladder_fns!(eq62),
        )],
    );
    e62.erratum = Some(Erratum {
        printed: r"m l g \sin \theta - m l \sin^2 \theta \ddot{\theta} - m l \cos \theta \sin \theta \dot{\theta}^2",
        corrected: r"m l g \sin \theta - 2m l^2 \sin^2 \theta \ddot{\theta} - 2m l^2 \cos \theta \sin \theta \dot{\theta}^2",
        why: "expanding the right side of (61) gives 2ml² on the θ̈ and θ̇² terms; the printed ml lacks a factor 2l (wrong dimensions)",
    });
    vec![
        eq(
            43,
            "A.1",
            "Centre of mass: position and velocity",
            Kinematic,
            &[
                "ladder::geometry::cm_position",
                "ladder::geometry::cm_velocity",
            ],
            vec![k("against particles and AD", ladder_fns!(eq43))],
        ),
        eq(
            44,
            "A.1",
            "The top C: position and velocity",
            Kinematic,
            &[
                "ladder::geometry::top_position",
                "ladder::geometry::top_velocity",
            ],
            vec![k("against geometry and AD", ladder_fns!(eq44))],
        ),
        eq(
            45,
            "A.1",
            "Centre of mass relative to C",
            Kinematic,
            &[
                "ladder::geometry::cm_from_top",
                "ladder::geometry::cm_velocity_from_top",
            ],
            vec![k("against references", ladder_fns!(eq45))],
        ),
        eq(
            46,
            "A.1",
            "(x_cm − x_C) × v_cm",
            Kinematic,
            &["ladder::geometry::eq46_cross"],
            vec![k(
                "against the cross product of references",
                ladder_fns!(eq46),
            )],
        ),
        eq(
            47,
            "A.1",
            "(x_cm − x_C) × (v_cm − v_C)",
            Kinematic,
            &["ladder::geometry::eq47_cross"],
            vec![k(
                "against the cross product of references",
                ladder_fns!(eq47),
            )],
        ),
        eq(
            48,
            "A.1",
            "v_cm × v_C",
            Kinematic,
            &[
                "ladder::geometry::eq48_cross",
                "ladder::jensen::velocity_term_c",
            ],
            vec![k(
                "against the cross product of references",
                ladder_fns!(eq48),
            )],
        ),
        e49,
        eq(
            50,
            "A.1",
            "I_C ω",
            Kinematic,
            &["ladder::jensen::eq50_rigid_angular_momentum_c"],
            vec![k("against the particles' I about C", ladder_fns!(eq50))],
        ),
        eq(
            51,
            "A.1",
            "Torque about C",
            Kinematic,
            &["ladder::jensen::eq51_torque_about_c"],
            vec![k("against τ_C of the particles", ladder_fns!(eq51))],
        ),
        eq(
            52,
            "A.1",
            "Torque side of (38) about C",
            Kinematic,
            &["ladder::jensen::eq52_modified_torque_c"],
            vec![k(
                "against τ_C + m v_cm × v_C of the particles",
                ladder_fns!(eq52),
            )],
        ),
        eq(
            53,
            "A.1",
            "Method 1 about C",
            OnShell,
            &["ladder::jensen::eq53_method_one_c"],
            vec![
                on("dL_C/dt by AD = both printed forms", ladder_fns!(eq53)),
                k(
                    "first form is d/dt of the corrected (49)",
                    ladder_fns!(eq53_first_form),
                ),
            ],
        ),
        e54,
        eq(
            55,
            "A.3",
            "Method 3: L'_C about the contact point",
            Kinematic,
            &["ladder::jensen::eq55_relative_angular_momentum_c"],
            vec![k("against L'_C (39) of the particles", ladder_fns!(eq55))],
        ),
        eq(
            59,
            "A.5",
            "Hu's method about C",
            OnShell,
            &["ladder::jensen::eq59_hu_method_c"],
            vec![on("dL_P/dt with P frozen at C = τ_C", ladder_fns!(eq59))],
        ),
        eq(
            60,
            "A.5",
            "Hu's method about C, in components",
            OnShell,
            &["ladder::jensen::eq60_hu_components"],
            vec![on("both sides on the motion", ladder_fns!(eq60))],
        ),
        eq(
            61,
            "A.5",
            "Hu's method about C, forces substituted",
            OnShell,
            &["ladder::jensen::eq61_hu_expanded"],
            vec![on("both sides on the motion", ladder_fns!(eq61))],
        ),
        e62,
        eq(
            63,
            "A.5",
            "Hu's method about C: the equation of motion",
            OnShell,
            &["ladder::jensen::eq63_equation_of_motion"],
            vec![on("both sides on the motion", ladder_fns!(eq63))],
        ),
    ]
}
