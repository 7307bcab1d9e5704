//! Registry entries for the extension beyond the note: the ladder on the floor alone after it
//! leaves the wall, (P1)-(P5) of `equations/phase2.md`. Checked like the note's own: against the
//! free three-particle model, with Lagrange's equations by automatic differentiation.

use super::sample::LadderSample;
use super::{printed, reference, Chain, Check, Equation, Eval, Kind, EXTENSION_BASE};
use crate::floor_fns;
use crate::ladder::energy::potential_energy;
use crate::ladder::floor_phase::*;
use crate::ladder::{solve_for_accel, Ladder, State};
use crate::scalar::Scalar;

type Chains<S> = Vec<Chain<S>>;

/// The LaTeX of (P1)-(P5), as displayed in `equations/phase2.md`.
pub fn latex(k: u32) -> &'static str {
    match k {
        1 => {
            r"T = \tfrac12 m \dot X^2 + \tfrac12 m l^2 \left(\sin^2\theta + \tfrac13\right)\dot\theta^2, \qquad V = m g l \cos\theta"
        }
        2 => r"\ddot X = 0, \qquad p_x = m \dot X = \text{const}",
        3 => {
            r"\left(\sin^2\theta + \tfrac13\right)\ddot\theta + \sin\theta\cos\theta\,\dot\theta^2 = \frac{g}{l}\sin\theta"
        }
        4 => r"F_f = m\left(g - l\sin\theta\,\ddot\theta - l\cos\theta\,\dot\theta^2\right)",
        5 => r"x_C = X - l\sin\theta",
        _ => "",
    }
}

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

fn check(name: &'static str, sort: LadderSample, f: super::FloorFns) -> Check {
    Check {
        name,
        eval: Eval::Floor(sort, f),
    }
}

/// The entries (P1)-(P5), numbered 1001-1005.
pub(super) fn equations() -> Vec<Equation> {
    use Kind::*;
    let e = |k: u32, title, kind, functions, checks| {
        super::eq(EXTENSION_BASE + k, "ext.", title, kind, functions, checks)
    };
    vec![
        e(
            1,
            "Floor phase: energies",
            Kinematic,
            &[
                "ladder::floor_phase::kinetic_energy",
                "ladder::energy::potential_energy",
            ],
            vec![check(
                "against the free particle model",
                LadderSample::Kinematic,
                floor_fns!(p1),
            )],
        ),
        e(
            2,
            "Floor phase: the centre keeps its horizontal velocity",
            OnShell,
            &["ladder::floor_phase::centre_acceleration"],
            vec![
                check(
                    "Lagrange's X equation (AD) and Newton for the particles",
                    LadderSample::OnShell,
                    floor_fns!(p2),
                ),
                check(
                    "Lagrange's X equation is m Ẍ at any state",
                    LadderSample::Kinematic,
                    floor_fns!(p2_kinematic),
                ),
            ],
        ),
        e(
            3,
            "Floor phase: equation of motion",
            OnShell,
            &[
                "ladder::floor_phase::angular_acceleration",
                "ladder::floor_phase::lagrange_residuals",
            ],
            vec![
                check(
                    "printed form and Lagrange's θ equation (AD)",
                    LadderSample::OnShell,
                    floor_fns!(p3),
                ),
                check(
                    "θ̈ solved from Lagrange (AD)",
                    LadderSample::Kinematic,
                    floor_fns!(p3_solved),
                ),
            ],
        ),
        e(
            4,
            "Floor phase: floor force",
            Newton,
            &["ladder::floor_phase::floor_force"],
            vec![check(
                "against Newton for the particles",
                LadderSample::Kinematic,
                floor_fns!(p4),
            )],
        ),
        e(
            5,
            "Floor phase: where the top is",
            Definition,
            &["ladder::floor_phase::top_abscissa"],
            vec![check(
                "against the particle model",
                LadderSample::Kinematic,
                floor_fns!(p5),
            )],
        ),
    ]
}
