//! Registry entries for Appendix B (Milne's *Vectorial Mechanics*, chap. 8), eqs. (64)-(90).
//!
//! Each display prints our form and Milne's; both lines are sides of one chain, Milne's computed
//! by [`crate::milne`] from his own definitions. Statements restricted to a special instant or
//! system ((70), (71), (84), (86)-(89)) are checked on samples of that sort only, and the tests
//! show that they fail on general samples.

mod momentum;
mod moving;
mod rates;

pub(super) use momentum::FNS as MOMENTUM_FNS;
pub(super) use moving::FNS as MOVING_FNS;
pub(super) use rates::FNS as RATES_FNS;

use crate::scalar::Scalar;
use crate::system::{rate_vec, Point, System};
use crate::vector::Vec3;

/// d/dt along the motion of a vector function of the system and a point, by lifting both.
pub(super) fn d_dt<S: Scalar>(
    sys: &System<S>,
    p: &Point<S>,
    f: impl Fn(&System<S::Dual>, &Point<S::Dual>) -> Vec3<S::Dual>,
) -> Vec3<S> {
    rate_vec::<S>(&f(&sys.along_motion(), &p.along_motion()))
}

/// The zero vector, the conclusion of (70), (71).
pub(super) fn zero<S: Scalar>() -> Vec3<S> {
    Vec3::zero()
}
