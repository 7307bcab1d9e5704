//! What the print gives beyond its chains on the motion: the degree of its residuals (for the
//! Schwartz-Zippel bound) and, for an on-shell display, its chains off the motion (where it
//! must fail, and the `=` where it breaks: the law of motion, [`crate::registry::law`]).

use super::{evaluate_chains, Form, PrintReport};
use crate::print::quantity::Model;
use crate::registry::check::exact_residual;
use crate::registry::sample::{exact_ladder, particle_system, LadderSample, PrintSample};
use crate::registry::Equation;
use rand_chacha::ChaCha8Rng;

/// The largest degree of a residual of the chains, in the variables of the states (`Degree`).
pub(super) fn degree(e: &Equation, chains: &[Vec<Form>], sample: PrintSample) -> u32 {
    use crate::registry::check::residual_degree;
    use crate::registry::sample::{EXTRA, LADDER_DRAWS, PER_PARTICLE};
    use crate::scalar::Degree;
    let evaluated = match sample {
        PrintSample::Ladder(sort) => {
            let (l, s) = exact_ladder(sort, [Degree::variable(); LADDER_DRAWS]);
            evaluate_chains(e, chains, Model::ladder(l, s), None)
        }
        PrintSample::Particles(sort) => {
            // The degree grows with the particles: the most an exact point draws (8).
            let vars = vec![Degree::variable(); 8 * PER_PARTICLE + EXTRA];
            let (sys, p) = particle_system(sort, 8, &vars);
            super::premises::premised(e, sys, p).and_then(|m| evaluate_chains(e, chains, m, None))
        }
    };
    evaluated.map_or(0, |c| residual_degree(&c))
}

/// Exact points off the motion (θ̈ drawn freely) for an on-shell display: the print must fail
/// there, and where it breaks is where the law of motion enters ([`crate::registry::law`]).
pub(super) fn off_motion_pass(
    e: &Equation,
    chains: &[Vec<Form>],
    rng: &mut ChaCha8Rng,
    rep: &mut PrintReport,
) {
    let mut all_fail = true;
    let mut breaks: Option<Option<Vec<u32>>> = None;
    for _ in 0..OFF_MOTION_POINTS {
        let draw = crate::registry::check::exact_ladder_draw(rng);
        let (l, s) = exact_ladder(LadderSample::Kinematic, draw);
        let Ok(ch) = evaluate_chains(e, chains, Model::ladder(l, s), None) else {
            return;
        };
        all_fail &= !exact_residual(&ch).0;
        let here = crate::registry::law::breaks(&ch);
        breaks = Some(match breaks {
            None => Some(here),
            Some(Some(prev)) if prev == here => Some(prev),
            Some(_) => None,
        });
    }
    rep.off_shell_fails = Some(all_fail);
    rep.off_motion_breaks = breaks.flatten();
}

/// Exact points off the motion per on-shell print: one false identity survives a random point
/// with probability at most degree/2⁶⁰ (Schwartz-Zippel), three make where the chain breaks
/// the same at every point unless it truly is.
pub const OFF_MOTION_POINTS: usize = 3;
