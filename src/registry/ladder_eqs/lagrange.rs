//! Checks of sec. 2.1, eqs. (1)-(10).

use crate::ladder::energy::*;
use crate::ladder::forces::*;
use crate::ladder::geometry::{cm_acceleration, cm_position};
use crate::ladder::particles::{as_system, wall_force_from_motion};
use crate::ladder::{solve_for_accel, Ladder, State};
use crate::registry::{printed, reference, vector_chains, Chain};
use crate::scalar::{sq, Scalar};
use crate::system::{rate, rate_vec};

pub(super) fn eq1<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let sys = as_system(l, s);
    vec![vec![
        printed("I_cm = ml²/3", moment_of_inertia_cm(l)),
        reference(
            "particles: Σ m_i |x_i − x_cm|²",
            sys.moment_of_inertia_about(&sys.centre_of_mass()),
        ),
    ]]
}

pub(super) fn eq2<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
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

pub(super) fn eq3<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let sys = as_system(l, s);
    let v = sys.particles.iter().fold(S::int(0), |a, p| {
        a + p.m.clone() * l.g.clone() * p.x.y.clone()
    });
    vec![vec![
        printed("V = mgl cos θ", potential_energy(l, s)),
        reference("particles: Σ m_i g y_i", v),
    ]]
}

pub(super) fn eq4<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
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

pub(super) fn eq5_from_lagrange<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
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

pub(super) fn eq5_on_shell<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vec![vec![
        reference("θ̈ of the state", s.accel.clone()),
        printed("(3g/4l) sin θ", angular_acceleration(l, s)),
    ]]
}

pub(super) fn eq6<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
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

pub(super) fn eq7<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed("(l sin θ, l cos θ)", cm_position(l, s)),
        reference("particles: Σ m_i x_i / m", as_system(l, s).centre_of_mass()),
    ])
}

pub(super) fn eq8<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
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

pub(super) fn particle_energy<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> S {
    let sys = as_system(l, s);
    sys.particles.iter().fold(S::int(0), |a, p| {
        a + p.m.clone() * p.v.dot(&p.v) / S::int(2) + p.m.clone() * l.g.clone() * p.x.y.clone()
    })
}

pub(super) fn eq9<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vec![vec![
        printed("E_0 = mgl", initial_energy(l)),
        printed("E = T + V", energy(l, s)),
        reference("particles: Σ m_i v_i²/2 + m_i g y_i", particle_energy(l, s)),
    ]]
}

pub(super) fn eq9_conserved<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vec![vec![
        printed("d(T + V)/dt (AD)", d_dt!(energy, l, s)),
        reference("0", S::int(0)),
    ]]
}

pub(super) fn eq10_rate<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    // Footnote 3: differentiating (10) along the motion gives back (5).
    vec![vec![
        reference(
            "d(θ̇²)/dt (AD)",
            d_dt!(|_: &Ladder<S::Dual>, x: &State<S::Dual>| sq(&x.rate), l, s),
        ),
        printed("d/dt (3g/2l)(1 − cos θ) (AD)", d_dt!(rate_squared, l, s)),
    ]]
}

pub(super) fn eq10_value<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vec![vec![
        reference("θ̇² of the state", sq(&s.rate)),
        printed("(3g/2l)(1 − cos θ)", rate_squared(l, s)),
    ]]
}
