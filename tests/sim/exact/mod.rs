//! `sim::exact`: the exact phase-one solution against mpmath and quadrature references.

mod carlson;
mod flat;
mod mpmath;
mod near_flat;
mod ode;
mod quadrature;
mod reference;
mod robust;
mod twofold;
mod ulps;
