//! Checks of secs. B.1-B.4 (Milne secs. 295-298): momentum, force, torque, centre of mass about
//! the fixed origin, eqs. (64)-(74).
//!
//! Each chain holds our printed forms and Milne's printed forms side by side; Milne's are
//! computed by [`crate::milne`] from his own definitions, and every d/dt is a rate along the
//! motion by automatic differentiation.

use super::{d_dt, zero};
use crate::milne;
use crate::registry::{corrected, misprint, printed, reference, vector_chains, Chain};
use crate::scalar::Scalar;
use crate::system::{rate_vec, Point, System};
use crate::vector::sum;

/// (64): our m = Σ_i m_i against Milne's Σ m.
pub(super) fn eq64<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Vec<Chain<S>> {
    vec![vec![
        printed("m = Σ_i m_i", sys.total_mass()),
        printed("Milne: Σ m", milne::big_m(sys)),
    ]]
}

/// (65): P = Σ m_i dx_i/dt = Σ m_i ẋ_i = Σ m_i v_i, Milne's L = Σ m ṙ.
pub(super) fn eq65<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Vec<Chain<S>> {
    let lifted = sys.along_motion();
    let by_system = sum(sys
        .particles
        .iter()
        .zip(&lifted.particles)
        .map(|(q, ql)| rate_vec::<S>(&ql.x).scale(&q.m)));
    let by_particle = sum(sys
        .particles
        .iter()
        .map(|q| rate_vec::<S>(&q.along_motion().x).scale(&q.m)));
    let first_moment = sum(lifted.particles.iter().map(|q| q.x.scale(&q.m)));
    vector_chains(vec![
        printed("P = Σ_i m_i dx_i/dt (AD of the lifted system)", by_system),
        printed("Σ_i m_i ẋ_i (AD of each particle)", by_particle),
        printed("Σ_i m_i v_i", sys.momentum()),
        printed("Milne: L = Σ m ṙ (AD)", milne::l(sys)),
        reference("d/dt Σ_i m_i x_i (AD)", rate_vec::<S>(&first_moment)),
    ])
}

/// (66): L = Σ x_i × m_i v_i against Milne's H(O) = Σ r ∧ m ṙ about the fixed origin.
pub(super) fn eq66<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed("L = Σ_i x_i × m_i v_i", sys.angular_momentum()),
        printed("Milne: H(O) = Σ r ∧ m ṙ (ṙ by AD)", milne::h_of_o(sys)),
    ])
}

/// (67): F = Σ F_i = dP/dt = Σ m_i ẍ_i = m a_cm, Milne's R = Σ P = dL/dt = Σ m r̈.
pub(super) fn eq67<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    let x_ddot = sum(sys.particles.iter().map(|q| {
        rate_vec::<S>(&rate_vec::<S::Dual>(&q.along_motion().along_motion().x)).scale(&q.m)
    }));
    vector_chains(vec![
        printed("F = Σ_i F_i", sys.total_force()),
        printed("dP/dt (AD)", d_dt(sys, p, |s, _| s.momentum())),
        printed("Σ_i m_i ẍ_i (AD²)", x_ddot),
        printed("m a_cm", sys.cm_acceleration().scale(&sys.total_mass())),
        printed("Milne: R = Σ P", milne::big_r(sys)),
        printed("Milne: dL/dt (AD)", d_dt(sys, p, |s, _| milne::l(s))),
        printed("Milne: Σ m r̈ (AD²)", milne::sum_m_r_ddot(sys)),
    ])
}

/// (68): τ = Σ x_i × F_i against Milne's Γ(O); the printed Σ r ∧ r̈ lacks the mass.
pub(super) fn eq68<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed("τ = Σ_i x_i × F_i", sys.torque()),
        misprint(
            "Milne: Γ(O) = Σ r ∧ r̈ (as printed)",
            milne::gamma_as_printed(sys),
        ),
        corrected("Milne: Γ(O) = Σ r ∧ m r̈", milne::gamma_corrected(sys)),
        reference(
            "Milne's definition Γ(O) = Σ r ∧ P",
            milne::gamma(sys, &milne::origin()),
        ),
    ])
}

/// (69): dL/dt = τ, Milne's dH(O)/dt = Γ(O).
pub(super) fn eq69<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed("dL/dt (AD)", d_dt(sys, p, |s, _| s.angular_momentum())),
        printed("τ", sys.torque()),
        printed(
            "Milne: dH(O)/dt (AD)",
            d_dt(sys, p, |s, _| milne::h_of_o(s)),
        ),
        printed("Milne: Γ(O) = Σ r ∧ P", milne::gamma(sys, &milne::origin())),
    ])
}

/// (70), hypothesis: the sample is force-free, F = 0, Milne's R = 0.
pub(super) fn eq70_hypothesis<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed("F", sys.total_force()),
        printed("Milne: R", milne::big_r(sys)),
        reference("0", zero()),
    ])
}

/// (70), conclusion: P is constant, Milne's L is constant (rates by AD).
pub(super) fn eq70<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed("dP/dt (AD)", d_dt(sys, p, |s, _| s.momentum())),
        printed("Milne: dL/dt (AD)", d_dt(sys, p, |s, _| milne::l(s))),
        reference("0", zero()),
    ])
}

/// (71), hypothesis: the sample is torque-free about the origin, τ = 0, Milne's Γ(O) = 0.
pub(super) fn eq71_hypothesis<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed("τ", sys.torque()),
        printed("Milne: Γ(O)", milne::gamma(sys, &milne::origin())),
        reference("0", zero()),
    ])
}

/// (71), conclusion: L is constant, Milne's H(O) is constant (rates by AD).
pub(super) fn eq71<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed("dL/dt (AD)", d_dt(sys, p, |s, _| s.angular_momentum())),
        printed(
            "Milne: dH(O)/dt (AD)",
            d_dt(sys, p, |s, _| milne::h_of_o(s)),
        ),
        reference("0", zero()),
    ])
}

/// (72): m x_cm = Σ m_i x_i, Milne's M r̄ = Σ m r, about the fixed origin.
pub(super) fn eq72<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Vec<Chain<S>> {
    let o = milne::origin();
    vector_chains(vec![
        printed("m x_cm", sys.centre_of_mass().scale(&sys.total_mass())),
        printed(
            "Σ_i m_i x_i",
            sum(sys.particles.iter().map(|q| q.x.scale(&q.m))),
        ),
        printed(
            "Milne: M r̄",
            milne::r_bar(sys, &o).scale(&milne::big_m(sys)),
        ),
        printed("Milne: Σ m r", milne::sum_m_r(sys, &o)),
    ])
}

/// (73): P = m ṙ_cm = m v_cm, Milne's L = M dr̄/dt. The note's ṙ_cm is its x_cm differentiated.
pub(super) fn eq73<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    let m = sys.total_mass();
    let x_cm_dot = d_dt(sys, p, |s, _| s.centre_of_mass());
    vector_chains(vec![
        printed("P", sys.momentum()),
        printed("m ṙ_cm (AD of x_cm)", x_cm_dot.scale(&m)),
        printed("m v_cm", sys.cm_velocity().scale(&m)),
        printed("Milne: L = Σ m ṙ", milne::l(sys)),
        printed(
            "Milne: M dr̄/dt (AD)",
            milne::r_bar_dot(sys).scale(&milne::big_m(sys)),
        ),
    ])
}

/// (74): F = m r̈_cm = m a_cm, Milne's R = M d²r̄/dt².
pub(super) fn eq74<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Vec<Chain<S>> {
    let m = sys.total_mass();
    let lifted = sys.along_motion().along_motion();
    let x_cm_ddot = rate_vec::<S>(&rate_vec::<S::Dual>(&lifted.centre_of_mass()));
    vector_chains(vec![
        printed("F", sys.total_force()),
        printed("m r̈_cm (AD² of x_cm)", x_cm_ddot.scale(&m)),
        printed("m a_cm", sys.cm_acceleration().scale(&m)),
        printed("Milne: R = Σ P", milne::big_r(sys)),
        printed(
            "Milne: M d²r̄/dt² (AD²)",
            milne::r_bar_ddot(sys).scale(&milne::big_m(sys)),
        ),
    ])
}

/// The chain functions of this module, by the names the sections' `*Rust:*` lists use.
pub(in crate::registry) const FNS: &[(&str, crate::registry::Fns)] = &[
    crate::named_fns!(Particles, eq68),
    crate::named_fns!(Particles, eq64),
    crate::named_fns!(Particles, eq65),
    crate::named_fns!(Particles, eq66),
    crate::named_fns!(Particles, eq67),
    crate::named_fns!(Particles, eq69),
    crate::named_fns!(Particles, eq70_hypothesis),
    crate::named_fns!(Particles, eq70),
    crate::named_fns!(Particles, eq71_hypothesis),
    crate::named_fns!(Particles, eq71),
    crate::named_fns!(Particles, eq72),
    crate::named_fns!(Particles, eq73),
    crate::named_fns!(Particles, eq74),
];
