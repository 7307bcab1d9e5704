//! Registry entries and checks for sec. 2, eqs. (1)-(28).

/// d/dt of a ladder quantity, by lifting the state along the motion.
macro_rules! d_dt {
    ($f:expr, $l:expr, $s:expr) => {
        rate::<S>($f(&$l.constant(), &$s.along_motion()))
    };
}

mod analyses;
mod lagrange;
use analyses::*;
use lagrange::*;

/// The chain functions of this module, by the names the sections' `*Rust:*` lists use.
pub(super) const FNS: &[(&str, crate::registry::Fns)] = &[
    crate::named_fns!(Ladder<f64>, eq28),
    crate::named_fns!(Ladder<f64>, eq1),
    crate::named_fns!(Ladder<f64>, eq2),
    crate::named_fns!(Ladder<f64>, eq3),
    crate::named_fns!(Ladder<f64>, eq4),
    crate::named_fns!(Ladder<f64>, eq5_from_lagrange),
    crate::named_fns!(Ladder<f64>, eq5_on_shell),
    crate::named_fns!(Ladder<f64>, eq6),
    crate::named_fns!(Ladder<f64>, eq7),
    crate::named_fns!(Ladder<f64>, eq8),
    crate::named_fns!(Ladder<f64>, eq9),
    crate::named_fns!(Ladder<f64>, eq9_conserved),
    crate::named_fns!(Ladder<f64>, eq10_rate),
    crate::named_fns!(Ladder<f64>, eq10_value),
    crate::named_fns!(Ladder<f64>, eq11),
    crate::named_fns!(Ladder<f64>, eq11_forces_from_motion),
    crate::named_fns!(Ladder<f64>, eq12),
    crate::named_fns!(Ladder<f64>, eq13),
    crate::named_fns!(Ladder<f64>, eq14),
    crate::named_fns!(Ladder<f64>, eq15),
    crate::named_fns!(Ladder<f64>, eq16),
    crate::named_fns!(Particles, eq17),
    crate::named_fns!(Ladder<f64>, eq18),
    crate::named_fns!(Ladder<f64>, eq19),
    crate::named_fns!(Ladder<f64>, eq20),
    crate::named_fns!(Ladder<f64>, eq21),
    crate::named_fns!(Ladder<f64>, eq22),
    crate::named_fns!(Ladder<f64>, eq23),
    crate::named_fns!(Ladder<f64>, eq24),
    crate::named_fns!(Ladder<f64>, eq25),
    crate::named_fns!(Ladder<f64>, eq26),
    crate::named_fns!(Ladder<f64>, eq27),
];
