//! Registry entries for Appendix A's general identities, eqs. (29)-(42), (56)-(58).
use super::Equation;
pub(super) fn equations() -> Vec<Equation> {
    vec![]
}
