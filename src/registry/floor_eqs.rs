//! Registry entries for the extension beyond the note: the ladder on the floor alone after it
//! leaves the wall, (P1)-(P5) of `equations/phase2.md`, whose sections name the chain functions below. Checked like the note's own: against the
//! free three-particle model, with Lagrange's equations by automatic differentiation.

use super::{printed, reference, Chain};
use crate::ladder::energy::potential_energy;
use crate::ladder::floor_phase::*;
use crate::ladder::{solve_for_accel, Ladder, State};
use crate::scalar::Scalar;

type Chains<S> = Vec<Chain<S>>;

fn p1<S: Scalar>(l: &Ladder<S>, s: &State<S>, x: &Slide<S>) -> Chains<S> {
    let sys = as_system(l, s, x);
    let (t, v) = sys
        .particles
        .iter()
        .fold((S::int(0), S::int(0)), |(t, v), p| {
            (
                t + p.m.clone() * p.v.dot(&p.v) / S::int(2),
                v + p.m.clone() * l.g.clone() * p.x.y.clone(),
            )
        });
    vec![
        vec![
            printed("½mẊ² + ½ml²(sin²θ + 1/3)θ̇²", kinetic_energy(l, s, x)),
            reference("particles: Σ m_i v_i²/2", t),
        ],
        vec![
            printed("mgl cos θ", potential_energy(l, s)),
            reference("particles: Σ m_i g y_i", v),
        ],
    ]
}

fn p2<S: Scalar>(l: &Ladder<S>, s: &State<S>, x: &Slide<S>) -> Chains<S> {
    let (_, x_eq) = lagrange_residuals(l, s, x);
    let sys = as_system(l, s, x);
    vec![
        vec![
            printed("Ẍ = 0", centre_acceleration::<S>()),
            reference("Ẍ of the motion", x.accel.clone()),
        ],
        vec![
            reference("Lagrange's X equation (particle ℒ; AD)", x_eq),
            printed("0", S::int(0)),
        ],
        vec![
            reference("d p_x/dt = Σ m_i a_i,x (particles)", sys.total_force().x),
            printed("0", S::int(0)),
        ],
    ]
}

fn p2_kinematic<S: Scalar>(l: &Ladder<S>, s: &State<S>, x: &Slide<S>) -> Chains<S> {
    let (_, x_eq) = lagrange_residuals(l, s, x);
    vec![vec![
        reference("Lagrange's X equation (particle ℒ; AD)", x_eq),
        printed("m Ẍ", l.m.clone() * x.accel.clone()),
    ]]
}

fn p3<S: Scalar>(l: &Ladder<S>, s: &State<S>, x: &Slide<S>) -> Chains<S> {
    let (theta_eq, _) = lagrange_residuals(l, s, x);
    let lhs = (s.sin.clone() * s.sin.clone() + S::ratio(1, 3)) * s.accel.clone()
        + s.sin.clone() * s.cos.clone() * s.rate.clone() * s.rate.clone();
    vec![
        vec![
            printed("(sin²θ + 1/3)θ̈ + sin θ cos θ θ̇²", lhs),
            printed("(g/l) sin θ", l.g.clone() / l.l.clone() * s.sin.clone()),
        ],
        vec![
            reference("Lagrange's θ equation (particle ℒ; AD)", theta_eq),
            printed("0", S::int(0)),
        ],
    ]
}

fn p3_solved<S: Scalar>(l: &Ladder<S>, s: &State<S>, x: &Slide<S>) -> Chains<S> {
    let solved = solve_for_accel(l, s, |st| lagrange_residuals(l, st, x).0);
    vec![vec![
        printed("θ̈ of (P3)", angular_acceleration(l, s)),
        reference("θ̈ solved from Lagrange's θ equation (AD)", solved),
    ]]
}

fn p4<S: Scalar>(l: &Ladder<S>, s: &State<S>, x: &Slide<S>) -> Chains<S> {
    let sys = as_system(l, s, x);
    vec![vec![
        printed("m(g − l sin θ θ̈ − l cos θ θ̇²)", floor_force(l, s)),
        reference(
            "particles: m g + Σ m_i a_i,y",
            sys.total_force().y + l.m.clone() * l.g.clone(),
        ),
    ]]
}

fn p5<S: Scalar>(l: &Ladder<S>, s: &State<S>, x: &Slide<S>) -> Chains<S> {
    vec![vec![
        printed("X − l sin θ", top_abscissa(l, s, x)),
        reference(
            "particles: the top's x",
            as_system(l, s, x).particles[0].x.x.clone(),
        ),
    ]]
}

/// The chain functions of this module, by the names the sections' `*Rust:*` lists use.
pub(super) const FNS: &[(&str, crate::registry::Fns)] = &[
    crate::named_fns!(Floor, p1),
    crate::named_fns!(Floor, p2),
    crate::named_fns!(Floor, p2_kinematic),
    crate::named_fns!(Floor, p3),
    crate::named_fns!(Floor, p3_solved),
    crate::named_fns!(Floor, p4),
    crate::named_fns!(Floor, p5),
];
