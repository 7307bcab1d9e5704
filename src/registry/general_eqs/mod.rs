//! Registry entries and checks for Appendix A's general identities, eqs. (29)-(42), (56)-(58):
//! any number of particles, any reference point P, every time derivative by automatic
//! differentiation along the motion.

mod momentum;
use momentum::*;
mod points;
use points::*;

/// The chain functions of this module, by the names the sections' `*Rust:*` lists use.
pub(super) const FNS: &[(&str, crate::registry::Fns)] = &[
    crate::named_fns!(Particles, eq29),
    crate::named_fns!(Particles, eq30),
    crate::named_fns!(Particles, eq31),
    crate::named_fns!(Particles, eq32),
    crate::named_fns!(Particles, eq33),
    crate::named_fns!(Particles, eq34),
    crate::named_fns!(Particles, eq35),
    crate::named_fns!(Particles, eq36),
    crate::named_fns!(Particles, eq37),
    crate::named_fns!(Particles, eq38),
    crate::named_fns!(Particles, eq39),
    crate::named_fns!(Particles, eq40),
    crate::named_fns!(Particles, eq41),
    crate::named_fns!(Particles, eq42),
    crate::named_fns!(Particles, eq56),
    crate::named_fns!(Particles, eq57),
    crate::named_fns!(Particles, eq58),
];
