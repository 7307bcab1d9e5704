//! `sim::scene*`: scene files, their errors and the plan's refusals.

mod errors;
mod shape;
mod work;
