//! Registry entries and checks for sec. 2, eqs. (1)-(28).

use super::sample::LadderSample;
use super::{
    eq, misprint, on_ladder, printed, reference, vector_chains, Chain, Equation, Erratum, Kind,
};
use crate::ladder::analysis::{AngularMomentum, Reference, ReferencePoint};
use crate::ladder::energy::*;
use crate::ladder::forces::*;
use crate::ladder::geometry::{cm_acceleration, cm_position, Corner};
use crate::ladder::particles::{
    as_system, external_torque_about, floor_force_from_motion, wall_force_from_motion,
};
use crate::ladder::torque::*;
use crate::ladder::{solve_for_accel, Ladder, State};
use crate::ladder_fns;
use crate::scalar::{sq, Scalar};
use crate::system::{rate, rate_vec};
use crate::vector::Vec3;

/// d/dt of a ladder quantity, by lifting the state along the motion.
macro_rules! d_dt {
    ($f:expr, $l:expr, $s:expr) => {
        rate::<S>($f(&$l.constant(), &$s.along_motion()))
    };
}

fn eq1<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let sys = as_system(l, s);
    vec![vec![
        printed("I_cm = ml²/3", moment_of_inertia_cm(l)),
        reference(
            "particles: Σ m_i |x_i − x_cm|²",
            sys.moment_of_inertia_about(&sys.centre_of_mass()),
        ),
    ]]
}

fn eq2<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let v_cm = rate_vec::<S>(&cm_position(&l.constant(), &s.along_motion()));
    let sys = as_system(l, s);
    let t_particles = sys.particles.iter().fold(S::int(0), |a, p| {
        a + p.m.clone() * p.v.dot(&p.v) / S::int(2)
    });
    vec![vec![
        printed(
            "m v_cm²/2 + I_cm θ̇²/2 (v_cm by AD of (7))",
            kinetic_energy_split(l, v_cm.dot(&v_cm), &s.rate),
        ),
        printed("m(lθ̇)²/2 + ml²θ̇²/6", kinetic_energy_middle(l, s)),
        printed("2ml²θ̇²/3", kinetic_energy(l, s)),
        reference("particles: Σ m_i v_i²/2", t_particles),
    ]]
}

fn eq3<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let sys = as_system(l, s);
    let v = sys.particles.iter().fold(S::int(0), |a, p| {
        a + p.m.clone() * l.g.clone() * p.x.y.clone()
    });
    vec![vec![
        printed("V = mgl cos θ", potential_energy(l, s)),
        reference("particles: Σ m_i g y_i", v),
    ]]
}

fn eq4<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let (lhs, rhs) = lagrange_sides(&NoteLagrangian, l, s);
    let (plhs, prhs) = lagrange_sides(&ParticleLagrangian, l, s);
    vec![
        vec![
            printed("d/dt ∂ℒ/∂θ̇ (ℒ from (2), (3); AD)", lhs),
            printed("∂ℒ/∂θ (AD)", rhs),
        ],
        vec![
            reference("d/dt ∂ℒ/∂θ̇ (particle ℒ; AD)", plhs),
            reference("∂ℒ/∂θ (particle ℒ; AD)", prhs),
        ],
    ]
}

fn eq5_from_lagrange<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vec![vec![
        printed("(3g/4l) sin θ", angular_acceleration(l, s)),
        reference(
            "θ̈ solving (4) with the note's ℒ",
            solve_for_accel(l, s, |x| lagrange_residual(&NoteLagrangian, l, x)),
        ),
        reference(
            "θ̈ solving (4) with the particle ℒ",
            solve_for_accel(l, s, |x| lagrange_residual(&ParticleLagrangian, l, x)),
        ),
    ]]
}

fn eq5_on_shell<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vec![vec![
        reference("θ̈ of the state", s.accel.clone()),
        printed("(3g/4l) sin θ", angular_acceleration(l, s)),
    ]]
}

fn eq6<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let a_x = rate::<S>(
        rate_vec::<S::Dual>(&cm_position(
            &l.constant().constant(),
            &s.along_motion().along_motion(),
        ))
        .x,
    );
    vec![vec![
        printed(
            "m a_x (a_x by AD of (7))",
            wall_force_from_acceleration(l, a_x),
        ),
        reference(
            "particles: Σ m_i a_i,x",
            wall_force_from_motion(&as_system(l, s)),
        ),
    ]]
}

fn eq7<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed("(l sin θ, l cos θ)", cm_position(l, s)),
        reference("particles: Σ m_i x_i / m", as_system(l, s).centre_of_mass()),
    ])
}

fn eq8<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let ad = rate_vec::<S>(&rate_vec::<S::Dual>(&cm_position(
        &l.constant().constant(),
        &s.along_motion().along_motion(),
    )));
    vector_chains(vec![
        printed("(8)", cm_acceleration(l, s)),
        reference("AD² of (7)", ad),
        reference(
            "particles: Σ m_i a_i / m",
            as_system(l, s).cm_acceleration(),
        ),
    ])
}

fn particle_energy<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> S {
    let sys = as_system(l, s);
    sys.particles.iter().fold(S::int(0), |a, p| {
        a + p.m.clone() * p.v.dot(&p.v) / S::int(2) + p.m.clone() * l.g.clone() * p.x.y.clone()
    })
}

fn eq9<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vec![vec![
        printed("E_0 = mgl", initial_energy(l)),
        printed("E = T + V", energy(l, s)),
        reference("particles: Σ m_i v_i²/2 + m_i g y_i", particle_energy(l, s)),
    ]]
}

fn eq9_conserved<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vec![vec![
        printed("d(T + V)/dt (AD)", d_dt!(energy, l, s)),
        reference("0", S::int(0)),
    ]]
}

fn eq10_rate<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    // Footnote 3: differentiating (10) along the motion gives back (5).
    vec![vec![
        reference(
            "d(θ̇²)/dt (AD)",
            d_dt!(|_: &Ladder<S::Dual>, x: &State<S::Dual>| sq(&x.rate), l, s),
        ),
        printed("d/dt (3g/2l)(1 − cos θ) (AD)", d_dt!(rate_squared, l, s)),
    ]]
}

fn eq10_value<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vec![vec![
        reference("θ̇² of the state", sq(&s.rate)),
        printed("(3g/2l)(1 − cos θ)", rate_squared(l, s)),
    ]]
}

/// The particle model's torque about a corner plus, for a moving corner, the torque of the
/// coordinate force (17) on the centre of mass: the right side of eq. (40).
fn torque_with_coordinate_force<S: Scalar>(k: Corner, l: &Ladder<S>, s: &State<S>) -> S {
    let (_, rhs) = crate::ladder::analysis::torque_equation(
        &Reference::Corner(k),
        AngularMomentum::Relative,
        l,
        s,
    );
    rhs
}

fn eq11<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
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

fn eq11_forces_from_motion<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
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

fn eq12<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
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

fn eq13<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
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

fn eq14<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vec![vec![
        printed("m a_x with (8)", wall_force_via_acceleration(l, s)),
        printed("ml cos θ θ̈ − ml sin θ θ̇²", wall_force(l, s)),
        reference(
            "particles: Σ m_i a_i,x",
            wall_force_from_motion(&as_system(l, s)),
        ),
    ]]
}

fn eq15<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
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
fn analysis_chain<S: Scalar>(
    d_l: S,
    forms: Vec<super::Side<S>>,
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

fn eq16<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
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

fn eq17<S: Scalar>(sys: &crate::system::System<S>, p: &crate::system::Point<S>) -> Vec<Chain<S>> {
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

fn eq18<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vec![vec![
        printed("I_cm θ̇", angular_momentum_about_b(l, s)),
        reference(
            "particles: L_cm (34)",
            as_system(l, s).spin_angular_momentum().z,
        ),
    ]]
}

fn eq19<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
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

fn coordinate_force_of<S: Scalar>(k: Corner, l: &Ladder<S>, s: &State<S>) -> Vec3<S> {
    let a = Reference::Corner(k).motion(l, s).a;
    coordinate_force(&l.m, &a)
}

fn eq20<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [a, b] = eq20_coordinate_force_c(l, s);
    vector_chains(vec![
        printed("(0, −2m ÿ_cm)", a),
        printed("(0, 2ml sin θ θ̈ + 2ml cos θ θ̇²)", b),
        reference("−m a_C (AD of x_C)", coordinate_force_of(Corner::C, l, s)),
    ])
}

fn relative_l<S: Scalar>(k: Corner, l: &Ladder<S>, s: &State<S>) -> S {
    crate::ladder::analysis::angular_momentum_about(
        &Reference::Corner(k),
        AngularMomentum::Relative,
        l,
        s,
    )
}

fn eq21<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [a, b] = eq21_angular_momentum_about_c(l, s);
    vec![vec![
        printed("I_C θ̇", a),
        printed("4ml²θ̇/3", b),
        reference("particles: L'_C (39)", relative_l(Corner::C, l, s)),
    ]]
}

fn five_forms<S: Scalar>(labels: [&'static str; 5], f: [S; 5]) -> Vec<super::Side<S>> {
    labels.iter().zip(f).map(|(&n, v)| printed(n, v)).collect()
}

fn eq22<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
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

fn eq23<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [a, b] = eq23_coordinate_force_d(l, s);
    vector_chains(vec![
        printed("(−2m ẍ_cm, 0)", a),
        printed("(−2ml cos θ θ̈ + 2ml sin θ θ̇², 0)", b),
        reference("−m a_D (AD of x_D)", coordinate_force_of(Corner::D, l, s)),
    ])
}

fn eq24<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [a, b] = eq24_angular_momentum_about_d(l, s);
    vec![vec![
        printed("I_D θ̇", a),
        printed("4ml²θ̇/3", b),
        reference("particles: L'_D (39)", relative_l(Corner::D, l, s)),
    ]]
}

fn eq25<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
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

fn eq26<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [a, b] = eq26_coordinate_force_e(l, s);
    vector_chains(vec![
        printed("(−2m ẍ_cm, −2m ÿ_cm)", a),
        printed("expanded with (8)", b),
        reference("−m a_E (AD of x_E)", coordinate_force_of(Corner::E, l, s)),
    ])
}

fn eq27<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [a, b] = eq27_angular_momentum_about_e(l, s);
    vec![vec![
        printed("−ml²θ̇ + ml²θ̇/3", a),
        printed("−2ml²θ̇/3", b),
        reference("particles: L'_E (39)", relative_l(Corner::E, l, s)),
    ]]
}

fn eq28<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let [f0, f1, f2, f3, f4] = eq28_torque_analysis_e(l, s);
    let forms = vec![
        printed("−2ml²θ̈/3", f0),
        misprint("τ_E − F_E,y l sin θ (as printed)", f1),
        super::corrected(
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

/// The entries for sec. 2.
pub(super) fn equations() -> Vec<Equation> {
    use Kind::*;
    let k = |name, f| on_ladder(name, LadderSample::Kinematic, f);
    let on = |name, f| on_ladder(name, LadderSample::OnShell, f);
    let rest = |name, f| on_ladder(name, LadderSample::OnShellFromRest, f);
    let mut e28 = eq(
        28,
        "2.6",
        "Torque analysis about E",
        OnShell,
        &[
            "ladder::torque::eq28_torque_analysis_e",
            "ladder::torque::eq28_second_form_corrected",
            "ladder::torque::torque_about_e",
        ],
        vec![on(
            "AD of (27) = printed forms = particle torques",
            ladder_fns!(eq28),
        )],
    );
    e28.erratum = Some(Erratum {
        printed: r"\tau_E - F_{E,y} l \sin \theta",
        corrected: r"\tau_E + F_{E,x} l \cos \theta - F_{E,y} l \sin \theta",
        why: "the coordinate force F_E has an x component too; its torque F_E,x l cos θ is missing from the second form (the third form has it)",
    });
    vec![
        eq(
            1,
            "2.1",
            "Moment of inertia about the centre of mass",
            Definition,
            &["ladder::energy::moment_of_inertia_cm"],
            vec![k("I_cm against the particle model", ladder_fns!(eq1))],
        ),
        eq(
            2,
            "2.1",
            "Kinetic energy",
            Kinematic,
            &[
                "ladder::energy::kinetic_energy_split",
                "ladder::energy::kinetic_energy_middle",
                "ladder::energy::kinetic_energy",
            ],
            vec![k(
                "three printed forms against Σ m_i v_i²/2",
                ladder_fns!(eq2),
            )],
        ),
        eq(
            3,
            "2.1",
            "Potential energy",
            Definition,
            &["ladder::energy::potential_energy"],
            vec![k("V against Σ m_i g y_i", ladder_fns!(eq3))],
        ),
        eq(
            4,
            "2.1",
            "Lagrange's equation",
            OnShell,
            &[
                "ladder::energy::lagrange_sides",
                "ladder::energy::lagrange_residual",
            ],
            vec![on(
                "both sides by AD, note's and particle ℒ",
                ladder_fns!(eq4),
            )],
        ),
        eq(
            5,
            "2.1",
            "Equation of motion",
            OnShell,
            &["ladder::energy::angular_acceleration"],
            vec![
                k("θ̈ solved from (4) by AD", ladder_fns!(eq5_from_lagrange)),
                on("θ̈ of the motion", ladder_fns!(eq5_on_shell)),
            ],
        ),
        eq(
            6,
            "2.1",
            "Wall force from the horizontal acceleration",
            Definition,
            &["ladder::forces::wall_force_from_acceleration"],
            vec![k("m a_x against Σ m_i a_i,x", ladder_fns!(eq6))],
        ),
        eq(
            7,
            "2.1",
            "Centre-of-mass coordinates",
            Definition,
            &["ladder::geometry::cm_position"],
            vec![k("against the particle model", ladder_fns!(eq7))],
        ),
        eq(
            8,
            "2.1",
            "Centre-of-mass acceleration",
            Kinematic,
            &["ladder::geometry::cm_acceleration"],
            vec![k("against AD² of (7) and particles", ladder_fns!(eq8))],
        ),
        eq(
            9,
            "2.1",
            "Conservation of energy",
            OnShell,
            &["ladder::energy::energy", "ladder::energy::initial_energy"],
            vec![
                rest("E_0 = T + V from rest upright", ladder_fns!(eq9)),
                on("dE/dt = 0 on the motion (AD)", ladder_fns!(eq9_conserved)),
            ],
        ),
        eq(
            10,
            "2.1",
            "Angular velocity from the energy",
            OnShell,
            &["ladder::energy::rate_squared"],
            vec![
                on(
                    "d/dt of (10) gives (5) (footnote 3)",
                    ladder_fns!(eq10_rate),
                ),
                rest("θ̇² from the particle energy", ladder_fns!(eq10_value)),
            ],
        ),
        eq(
            11,
            "2.2",
            "Torque equation about A",
            OnShell,
            &["ladder::torque::torque_about_a"],
            vec![
                on("dL_A/dt = τ_A", ladder_fns!(eq11)),
                k(
                    "τ_A with the forces the motion requires",
                    ladder_fns!(eq11_forces_from_motion),
                ),
            ],
        ),
        eq(
            12,
            "2.2",
            "Angular momentum about A",
            Kinematic,
            &[
                "ladder::torque::eq12_angular_momentum_about_a",
                "ladder::torque::angular_momentum_about_a",
            ],
            vec![k("against Σ x_i × m_i v_i", ladder_fns!(eq12))],
        ),
        eq(
            13,
            "2.2",
            "Moment of inertia about A, C, D, E",
            Definition,
            &["ladder::torque::eq13_moment_of_inertia_about_corner"],
            vec![k(
                "against the particle model about each corner",
                ladder_fns!(eq13),
            )],
        ),
        eq(
            14,
            "2.2",
            "Wall force",
            Kinematic,
            &[
                "ladder::forces::wall_force_via_acceleration",
                "ladder::forces::wall_force",
            ],
            vec![k("against Newton for the particles", ladder_fns!(eq14))],
        ),
        eq(
            15,
            "2.2",
            "Floor force",
            Kinematic,
            &[
                "ladder::forces::floor_force_via_acceleration",
                "ladder::forces::floor_force",
            ],
            vec![k("against Newton for the particles", ladder_fns!(eq15))],
        ),
        eq(
            16,
            "2.2",
            "Torque analysis about A",
            OnShell,
            &["ladder::torque::eq16_torque_analysis_a"],
            vec![on(
                "AD of (12) = printed forms = particle torques",
                ladder_fns!(eq16),
            )],
        ),
        eq(
            17,
            "2.3",
            "Coordinate force of an accelerating point",
            General,
            &["ladder::torque::coordinate_force"],
            vec![super::on_particles(
                "−m a_P against Newton in P's frame",
                super::ParticleSample::General,
                crate::particle_fns!(eq17),
            )],
        ),
        eq(
            18,
            "2.3",
            "Angular momentum about B",
            Kinematic,
            &["ladder::torque::angular_momentum_about_b"],
            vec![k("against L_cm of the particles", ladder_fns!(eq18))],
        ),
        eq(
            19,
            "2.3",
            "Torque analysis about B",
            OnShell,
            &["ladder::torque::eq19_torque_analysis_b"],
            vec![on(
                "AD of (18) = printed forms = particle torques",
                ladder_fns!(eq19),
            )],
        ),
        eq(
            20,
            "2.4",
            "Coordinate force for C",
            Kinematic,
            &["ladder::torque::eq20_coordinate_force_c"],
            vec![k("against −m a_C by AD", ladder_fns!(eq20))],
        ),
        eq(
            21,
            "2.4",
            "Angular momentum about C",
            Kinematic,
            &["ladder::torque::eq21_angular_momentum_about_c"],
            vec![k("against L'_C of the particles", ladder_fns!(eq21))],
        ),
        eq(
            22,
            "2.4",
            "Torque analysis about C",
            OnShell,
            &["ladder::torque::eq22_torque_analysis_c"],
            vec![on(
                "AD of (21) = printed forms = particle torques",
                ladder_fns!(eq22),
            )],
        ),
        eq(
            23,
            "2.5",
            "Coordinate force for D",
            Kinematic,
            &["ladder::torque::eq23_coordinate_force_d"],
            vec![k("against −m a_D by AD", ladder_fns!(eq23))],
        ),
        eq(
            24,
            "2.5",
            "Angular momentum about D",
            Kinematic,
            &["ladder::torque::eq24_angular_momentum_about_d"],
            vec![k("against L'_D of the particles", ladder_fns!(eq24))],
        ),
        eq(
            25,
            "2.5",
            "Torque analysis about D",
            OnShell,
            &["ladder::torque::eq25_torque_analysis_d"],
            vec![on(
                "AD of (24) = printed forms = particle torques",
                ladder_fns!(eq25),
            )],
        ),
        eq(
            26,
            "2.6",
            "Coordinate force for E",
            Kinematic,
            &["ladder::torque::eq26_coordinate_force_e"],
            vec![k("against −m a_E by AD", ladder_fns!(eq26))],
        ),
        eq(
            27,
            "2.6",
            "Angular momentum about E",
            Kinematic,
            &["ladder::torque::eq27_angular_momentum_about_e"],
            vec![k("against L'_E of the particles", ladder_fns!(eq27))],
        ),
        e28,
    ]
}
