//! The law and the algebra told apart: which `=` of a display is the law of motion.
//!
//! A torque analysis such as (25) is a chain of forms joined by `=`. Exactly one of those `=` is
//! physics, the torque law (dL/dt = τ about a fixed point, or with the coordinate force's torque
//! (40), or with m v_cm × v_P (38)); the others are algebra and kinematics, and since the contact
//! forces are whatever the motion requires ((14), (15)), they hold for any θ̈. So off the motion
//! (θ̈ left free) the chain breaks at the law's `=` and nowhere else. [`breaks`] finds where a
//! chain breaks at one exact point; the checker runs it at every off-motion point
//! ([`super::check::CheckReport::off_motion_breaks`]) and `ladder verify` holds the result against
//! the step the registry marks ([`Law`]). Nothing here is asserted by hand: the registry's mark is
//! a claim that the computation confirms or refutes.

use super::{Chain, Role};
use crate::scalar::Scalar;
use num_traits::Zero;
use serde::Serialize;

/// Where in a display the law of motion is used.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Law {
    /// The `=` of the display, counted from 1 left to right, that is the law; every other `=` is
    /// algebra or kinematics and holds for any θ̈.
    pub step: u32,
    /// The law, in words.
    pub statement: &'static str,
}

/// The display forms of a chain, in order: every side up to the last printed or corrected one,
/// misprints left out. A reference before that point stands for a form of the display that the
/// code computes independently (the left side dL/dt of (11), (53), (59), by automatic
/// differentiation); references after it (the particle model's torque) are not forms.
fn forms<S>(chain: &Chain<S>) -> Vec<&S> {
    let last = chain
        .iter()
        .rposition(|s| matches!(s.role, Role::Printed | Role::Corrected))
        .map_or(0, |k| k + 1);
    chain[..last]
        .iter()
        .filter(|s| s.role != Role::Misprint)
        .map(|s| &s.value)
        .collect()
}

/// The `=` (counted from 1) between consecutive display forms whose values differ, over every
/// chain of a check (a chain of vector components is one display, so the breaks are merged).
pub fn breaks<S: Scalar + Zero>(chains: &[Chain<S>]) -> Vec<u32> {
    let mut out: Vec<u32> = Vec::new();
    for c in chains {
        let f = forms(c);
        for (k, w) in f.windows(2).enumerate() {
            let step = k as u32 + 1;
            if !(w[1].clone() - w[0].clone()).is_zero() && !out.contains(&step) {
                out.push(step);
            }
        }
    }
    out.sort_unstable();
    out
}

/// Count the `=` of a display's LaTeX that join its forms: those outside braces (an `=` in a
/// subscript such as `\Big|_{\mathbf{x}_P=0}` joins nothing).
pub fn equals_signs(latex: &str) -> u32 {
    let mut depth = 0i32;
    let mut n = 0;
    for c in latex.chars() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            '=' if depth == 0 => n += 1,
            _ => {}
        }
    }
    n
}

/// The law steps of the note's displays: (equation, the `=` that is the law, the law in words).
/// Each is confirmed at every `ladder verify` by [`breaks`] off the motion; an on-shell display
/// not listed here is a consequence of the law rather than a use of it ((9): the energy, whose
/// checks compare more than the display's forms).
const LAWS: &[(u32, u32, &str)] = &[
    (4, 1, "Lagrange's equation for ℒ = T − V: the law of motion in Lagrange's form"),
    (5, 1, "the equation of motion itself, solved from Lagrange's equation (4)"),
    (10, 1, "conservation of energy (9) for the start at rest upright, a first integral of the law"),
    (11, 1, "dL_A/dt = τ_A, the torque law (35) about the fixed point A"),
    (16, 2, "dL_A/dt = τ_A, the torque law (35) about the fixed point A"),
    (19, 2, "dL_cm/dt = τ_cm, the torque law (41) about the centre of mass"),
    (22, 2, "dL'_C/dt = τ_C + (x_cm − x_C) × (−m a_C), the torque law (40) about the moving point C, with the torque of the coordinate force (20)"),
    (25, 2, "dL'_D/dt = τ_D + (x_cm − x_D) × (−m a_D), the torque law (40) about the moving point D, with the torque of the coordinate force (23)"),
    (28, 2, "dL'_E/dt = τ_E + (x_cm − x_E) × (−m a_E), the torque law (40) about the moving point E, with the torque of the coordinate force (26)"),
    (53, 2, "dL_C/dt = τ_C + m v_cm × v_C, the torque law (38) for L_C about the moving point C"),
    (54, 1, "the torque law (38) of (53) with its common terms cancelled: the equation of motion times 4ml²/3"),
    (59, 2, "Hu's (56), dL_P/dt = τ_P for P held fixed where C is now; equivalently dL_A/dt = τ_A about the fixed corner"),
    (60, 1, "Hu's (56) about C, as in (59), in components"),
    (61, 1, "Hu's (56) about C, as in (59), with F_f from (15)"),
    (62, 1, "Hu's (56) about C, as in (59), multiplied out"),
    (63, 1, "the equation of motion (5) times 4ml²/3, what (62) reduces to"),
];

/// The law step the registry marks for equation `number`.
pub fn law_of(number: u32) -> Option<Law> {
    LAWS.iter()
        .find(|(n, _, _)| *n == number)
        .map(|&(_, step, statement)| Law { step, statement })
}
