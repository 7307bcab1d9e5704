//! The law and the algebra told apart: which `=` of a display is the law of motion.
//!
//! A torque analysis such as (25) is a chain of forms joined by `=`. Exactly one of those `=` is
//! physics, the torque law (dL/dt = τ about a fixed point, or with the coordinate force's torque
//! (40), or with m v_cm × v_P (38)); the others are algebra and kinematics, and since the contact
//! forces are whatever the motion requires ((14), (15)), they hold for any θ̈. So off the motion
//! (θ̈ left free) the chain breaks at the law's `=` and nowhere else. [`breaks`] finds where a
//! chain breaks at one exact point; the checker runs it at every off-motion point
//! ([`super::check::CheckReport::off_motion_breaks`]) and `ladder verify` holds the result against
//! the step the display's `*Law:*` line marks ([`Law`]). Nothing here is asserted by hand: the registry's mark is
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
