//! Registry entries for Appendix B (Milne), eqs. (64)-(90).
use super::Equation;
pub(super) fn equations() -> Vec<Equation> {
    vec![]
}
