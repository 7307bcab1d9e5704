//! `sim::exact`: the exact phase-one solution against mpmath and quadrature references.

mod carlson;
mod mpmath;
mod ode;
mod quadrature;
mod reference;
mod robust;
mod ulps;
