//! Registry entries and checks for Jensen's methods applied to the ladder about C,
//! eqs. (43)-(55), (59)-(63).

mod checks;
use checks::*;

/// The chain functions of this module, by the names the sections' `*Rust:*` lists use.
pub(super) const FNS: &[(&str, crate::registry::Fns)] = &[
    crate::named_fns!(Ladder<f64>, eq49),
    crate::named_fns!(Ladder<f64>, eq54),
    crate::named_fns!(Ladder<f64>, eq62),
    crate::named_fns!(Ladder<f64>, eq43),
    crate::named_fns!(Ladder<f64>, eq44),
    crate::named_fns!(Ladder<f64>, eq45),
    crate::named_fns!(Ladder<f64>, eq46),
    crate::named_fns!(Ladder<f64>, eq47),
    crate::named_fns!(Ladder<f64>, eq48),
    crate::named_fns!(Ladder<f64>, eq50),
    crate::named_fns!(Ladder<f64>, eq51),
    crate::named_fns!(Ladder<f64>, eq52),
    crate::named_fns!(Ladder<f64>, eq53),
    crate::named_fns!(Ladder<f64>, eq53_first_form),
    crate::named_fns!(Ladder<f64>, eq55),
    crate::named_fns!(Ladder<f64>, eq59),
    crate::named_fns!(Ladder<f64>, eq60),
    crate::named_fns!(Ladder<f64>, eq61),
    crate::named_fns!(Ladder<f64>, eq63),
];
