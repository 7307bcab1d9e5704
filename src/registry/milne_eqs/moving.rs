//! Checks of secs. B.5-B.6 (Milne secs. 300-301): angular momentum about another point, then
//! about a moving point, eqs. (75)-(84).
//!
//! Here Milne's O is the note's point P (moving, in general) and his O' the fixed origin.

use super::check;
use crate::milne;
use crate::particle_fns;
use crate::registry::sample::ParticleSample::*;
use crate::registry::{eq, Equation, Kind};
use crate::registry::{printed, reference, vector_chains, Chain};
use crate::scalar::Scalar;
use crate::system::{Point, System};

/// (75): x_i = x_P + (x_i − x_P), Milne's r' = r_0 + r, for every particle.
pub(super) fn eq75<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    sys.particles
        .iter()
        .flat_map(|q| {
            vector_chains(vec![
                printed("x_i", q.x.clone()),
                printed(
                    "x_P + (x_i − x_P)",
                    p.x.clone() + (q.x.clone() - p.x.clone()),
                ),
                printed("Milne: r'", milne::r_prime(q)),
                printed("Milne: r_0 + r", milne::r_0(p) + milne::r(q, p)),
            ])
        })
        .collect()
}

/// (76): L = Σ x_i × m_i v_i against Milne's H(O') = Σ r' ∧ m v.
pub(super) fn eq76<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed("L = Σ_i x_i × m_i v_i", sys.angular_momentum()),
        printed(
            "Milne: H(O') = Σ r' ∧ m v (v by AD)",
            milne::h(sys, &milne::origin()),
        ),
    ])
}

/// (77): L_P = Σ (x_i − x_P) × m_i v_i against Milne's H(O) = Σ r ∧ m v, O = P moving.
pub(super) fn eq77<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed(
            "L_P = Σ_i (x_i − x_P) × m_i v_i",
            sys.angular_momentum_about(p),
        ),
        printed("Milne: H(O) = Σ r ∧ m v (v by AD)", milne::h(sys, p)),
    ])
}

/// (78): L = L_P + x_P × Σ m_i v_i = L_P + x_P × m v_cm, Milne's H(O') = H(O) + r_0 ∧ L.
pub(super) fn eq78<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    let l_p = sys.angular_momentum_about(p);
    let m = sys.total_mass();
    vector_chains(vec![
        printed("L", sys.angular_momentum()),
        printed(
            "L_P + x_P × Σ_i m_i v_i",
            l_p.clone() + p.x.cross(&sys.momentum()),
        ),
        printed(
            "L_P + x_P × m v_cm",
            l_p + p.x.cross(&sys.cm_velocity().scale(&m)),
        ),
        printed("Milne: H(O')", milne::h(sys, &milne::origin())),
        printed(
            "Milne: H(O) + r_0 ∧ L",
            milne::h(sys, p) + milne::r_0(p).cross(&milne::l(sys)),
        ),
    ])
}

/// (79): L = L_cm + x_cm × m v_cm, Milne's H(O') = H(C) + r̄ ∧ L, C the centre of mass.
pub(super) fn eq79<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Vec<Chain<S>> {
    let o = milne::origin();
    let m = sys.total_mass();
    vector_chains(vec![
        printed("L", sys.angular_momentum()),
        printed(
            "L_cm + x_cm × m v_cm",
            sys.spin_angular_momentum() + sys.centre_of_mass().cross(&sys.cm_velocity().scale(&m)),
        ),
        printed("Milne: H(O')", milne::h(sys, &o)),
        printed(
            "Milne: H(C) + r̄ ∧ L",
            milne::h(sys, &milne::g(sys)) + milne::r_bar(sys, &o).cross(&milne::l(sys)),
        ),
    ])
}

/// (80): x_cm − x_P against Milne's r̄ = Σ m r / M with r relative to O = P.
pub(super) fn eq80<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed("x_cm − x_P", sys.centre_of_mass() - p.x.clone()),
        printed("Milne: r̄ = Σ m r / M about O = P", milne::r_bar(sys, p)),
    ])
}

/// (81): v_P against Milne's V = ṙ_0 by AD of the position of O = P.
pub(super) fn eq81<S: Scalar>(_: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed("v_P", p.v.clone()),
        printed("Milne: V = ṙ_0 (AD)", milne::big_v(p)),
    ])
}

/// (82): v_i = v_P + (v_i − v_P), Milne's v = V + v', and v_i − v_P against v' = ṙ, for every
/// particle.
pub(super) fn eq82<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    sys.particles
        .iter()
        .flat_map(|q| {
            let mut chains = vector_chains(vec![
                printed("v_i", q.v.clone()),
                printed(
                    "v_P + (v_i − v_P)",
                    p.v.clone() + (q.v.clone() - p.v.clone()),
                ),
                printed("Milne: v = ṙ' (AD)", milne::v(q)),
                printed("Milne: V + v' (AD)", milne::big_v(p) + milne::v_rel(q, p)),
            ]);
            chains.extend(vector_chains(vec![
                printed("v_i − v_P", q.v.clone() - p.v.clone()),
                printed("Milne: v' = ṙ (AD of r = x_i − x_P)", milne::v_rel(q, p)),
            ]));
            chains
        })
        .collect()
}

/// (83): L_P = L'_P + (x_cm − x_P) × m v_P, Milne's H(O) = H_r(O) + r̄ ∧ M V.
pub(super) fn eq83<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    let m = sys.total_mass();
    vector_chains(vec![
        printed("L_P", sys.angular_momentum_about(p)),
        printed(
            "L'_P + (x_cm − x_P) × m v_P",
            sys.relative_angular_momentum_about(p)
                + (sys.centre_of_mass() - p.x.clone()).cross(&p.v.scale(&m)),
        ),
        printed("Milne: H(O)", milne::h(sys, p)),
        printed(
            "Milne: H_r(O) + r̄ ∧ M V",
            milne::h_r(sys, p)
                + milne::r_bar(sys, p).cross(&milne::big_v(p).scale(&milne::big_m(sys))),
        ),
    ])
}

/// (84): with P on the centre of mass, L_cm = L'_cm; Milne's H(G) = H_r(G), G his centre of
/// mass (from r̄ and its rates, not from the sample's P).
pub(super) fn eq84<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    let g = milne::g(sys);
    vector_chains(vec![
        printed(
            "L_cm (L_P, P at the centre of mass)",
            sys.angular_momentum_about(p),
        ),
        printed(
            "L'_cm (L'_P, P at the centre of mass)",
            sys.relative_angular_momentum_about(p),
        ),
        printed("Milne: H(G)", milne::h(sys, &g)),
        printed("Milne: H_r(G)", milne::h_r(sys, &g)),
        reference("L_cm of eq. (34)", sys.spin_angular_momentum()),
    ])
}

/// The entries of secs. B.5-B.6, eqs. (75)-(84).
pub(super) fn equations() -> Vec<Equation> {
    vec![
        eq(
            75,
            "B.5",
            "Position relative to a point P; Milne's r' = r_0 + r",
            Kind::General,
            &["milne::r", "milne::r_prime", "milne::r_0"],
            vec![check(
                "x_i = x_P + (x_i − x_P) = r' = r_0 + r",
                General,
                particle_fns!(eq75),
            )],
        ),
        eq(
            76,
            "B.5",
            "Angular momentum about the origin; Milne's H(O')",
            Kind::Notation,
            &["system::System::angular_momentum", "milne::h", "milne::v"],
            vec![check(
                "L against Milne's Σ r' ∧ m v",
                General,
                particle_fns!(eq76),
            )],
        ),
        eq(
            77,
            "B.5",
            "Angular momentum L_P about a moving point; Milne's H(O)",
            Kind::Notation,
            &["system::System::angular_momentum_about", "milne::h"],
            vec![check(
                "L_P against Milne's Σ r ∧ m v",
                General,
                particle_fns!(eq77),
            )],
        ),
        eq(
            78,
            "B.5",
            "L from L_P; Milne's H(O') = H(O) + r_0 ∧ L",
            Kind::General,
            &[
                "system::System::angular_momentum",
                "system::System::angular_momentum_about",
                "milne::h",
                "milne::r_0",
                "milne::l",
            ],
            vec![check("both lines, any P", General, particle_fns!(eq78))],
        ),
        eq(
            79,
            "B.5",
            "L from L_cm; Milne's H(O') = H(C) + r̄ ∧ L",
            Kind::General,
            &[
                "system::System::spin_angular_momentum",
                "milne::h",
                "milne::g",
                "milne::r_bar",
            ],
            vec![check("both lines", General, particle_fns!(eq79))],
        ),
        eq(
            80,
            "B.6",
            "Centre of mass relative to P; Milne's r̄ of sec. 301",
            Kind::Notation,
            &["system::System::centre_of_mass", "milne::r_bar"],
            vec![check(
                "x_cm − x_P against Milne's Σ m r / M about P",
                General,
                particle_fns!(eq80),
            )],
        ),
        eq(
            81,
            "B.6",
            "Velocity of P; Milne's V",
            Kind::Notation,
            &["milne::big_v"],
            vec![check(
                "v_P against dx_P/dt by AD",
                General,
                particle_fns!(eq81),
            )],
        ),
        eq(
            82,
            "B.6",
            "Velocity relative to P; Milne's v = V + v'",
            Kind::Notation,
            &["milne::v", "milne::v_rel", "milne::big_v"],
            vec![check(
                "v_i − v_P against d(x_i − x_P)/dt by AD, for each particle",
                General,
                particle_fns!(eq82),
            )],
        ),
        eq(
            83,
            "B.6",
            "L_P from L'_P; Milne's H(O) = H_r(O) + r̄ ∧ M V",
            Kind::General,
            &[
                "system::System::angular_momentum_about",
                "system::System::relative_angular_momentum_about",
                "milne::h",
                "milne::h_r",
                "milne::r_bar",
                "milne::big_v",
            ],
            vec![check(
                "both lines, any moving P",
                General,
                particle_fns!(eq83),
            )],
        ),
        eq(
            84,
            "B.6",
            "About the centre of mass the two angular momenta agree; Milne's H(G) = H_r(G)",
            Kind::General,
            &[
                "system::System::angular_momentum_about",
                "system::System::relative_angular_momentum_about",
                "milne::g",
                "milne::h",
                "milne::h_r",
            ],
            vec![check(
                "L_P = L'_P with P on the centre of mass, H(G) = H_r(G)",
                PAtCm,
                particle_fns!(eq84),
            )],
        ),
    ]
}
