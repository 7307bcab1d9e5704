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
    crate::named_fns!(Ladder, eq28),
    crate::named_fns!(Ladder, eq1),
    crate::named_fns!(Ladder, eq2),
    crate::named_fns!(Ladder, eq3),
    crate::named_fns!(Ladder, eq4),
    crate::named_fns!(Ladder, eq5_from_lagrange),
    crate::named_fns!(Ladder, eq5_on_shell),
    crate::named_fns!(Ladder, eq6),
    crate::named_fns!(Ladder, eq7),
    crate::named_fns!(Ladder, eq8),
    crate::named_fns!(Ladder, eq9),
    crate::named_fns!(Ladder, eq9_conserved),
    crate::named_fns!(Ladder, eq10_rate),
    crate::named_fns!(Ladder, eq10_value),
    crate::named_fns!(Ladder, eq11),
    crate::named_fns!(Ladder, eq11_forces_from_motion),
    crate::named_fns!(Ladder, eq12),
    crate::named_fns!(Ladder, eq13),
    crate::named_fns!(Ladder, eq14),
    crate::named_fns!(Ladder, eq15),
    crate::named_fns!(Ladder, eq16),
    crate::named_fns!(Particles, eq17),
    crate::named_fns!(Ladder, eq18),
    crate::named_fns!(Ladder, eq19),
    crate::named_fns!(Ladder, eq20),
    crate::named_fns!(Ladder, eq21),
    crate::named_fns!(Ladder, eq22),
    crate::named_fns!(Ladder, eq23),
    crate::named_fns!(Ladder, eq24),
    crate::named_fns!(Ladder, eq25),
    crate::named_fns!(Ladder, eq26),
    crate::named_fns!(Ladder, eq27),
];
