//! `sim::constrained`: the wall phase as a constrained (Lagrange multiplier) system.

mod baumgarte;
mod drift;
