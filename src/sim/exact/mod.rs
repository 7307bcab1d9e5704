//! Exact phase one (docs to come).
mod carlson;
mod jacobi;
mod phase_one;
mod twofold;

pub use carlson::carlson_rf;
pub use jacobi::{Agm, Arg, Jacobi};
pub use phase_one::{separation_cos, PhaseOne, Separation};
