//! Simulation of the sliding ladder (the simulator proper lives on its own branch).
pub mod exact;
