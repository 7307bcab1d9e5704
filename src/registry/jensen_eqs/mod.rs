//! Registry entries and checks for Jensen's methods applied to the ladder about C,
//! eqs. (43)-(55), (59)-(63).

mod checks;
use checks::*;

/// The chain functions of this module, by the names the sections' `*Rust:*` lists use.
pub(super) const FNS: &[(&str, crate::registry::Fns)] = &[
    crate::named_fns!(Ladder, eq49),
    crate::named_fns!(Ladder, eq54),
    crate::named_fns!(Ladder, eq62),
    crate::named_fns!(Ladder, eq43),
    crate::named_fns!(Ladder, eq44),
    crate::named_fns!(Ladder, eq45),
    crate::named_fns!(Ladder, eq46),
    crate::named_fns!(Ladder, eq47),
    crate::named_fns!(Ladder, eq48),
    crate::named_fns!(Ladder, eq50),
    crate::named_fns!(Ladder, eq51),
    crate::named_fns!(Ladder, eq52),
    crate::named_fns!(Ladder, eq53),
    crate::named_fns!(Ladder, eq53_first_form),
    crate::named_fns!(Ladder, eq55),
    crate::named_fns!(Ladder, eq59),
    crate::named_fns!(Ladder, eq60),
    crate::named_fns!(Ladder, eq61),
    crate::named_fns!(Ladder, eq63),
];
