//! Registry entries for Jensen's methods applied to the ladder, eqs. (43)-(55), (59)-(63).
use super::Equation;
pub(super) fn equations() -> Vec<Equation> {
    vec![]
}
