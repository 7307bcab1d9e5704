//! Checks of secs. B.5-B.6 (Milne secs. 300-301): angular momentum about another point, then
//! about a moving point, eqs. (75)-(84).
//!
//! Here Milne's O is the note's point P (moving, in general) and his O' the fixed origin.

use crate::milne;
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

/// The chain functions of this module, by the names the sections' `*Rust:*` lists use.
pub(in crate::registry) const FNS: &[(&str, crate::registry::Fns)] = &[
    crate::named_fns!(Particles, eq75),
    crate::named_fns!(Particles, eq76),
    crate::named_fns!(Particles, eq77),
    crate::named_fns!(Particles, eq78),
    crate::named_fns!(Particles, eq79),
    crate::named_fns!(Particles, eq80),
    crate::named_fns!(Particles, eq81),
    crate::named_fns!(Particles, eq82),
    crate::named_fns!(Particles, eq83),
    crate::named_fns!(Particles, eq84),
];
