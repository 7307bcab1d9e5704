//! sliding-ladder: the equations of "Torque Analyses of a Sliding Ladder" as checked code.

pub mod docs;
pub mod ladder;
pub mod milne;
pub mod registry;
pub mod scalar;
pub mod system;
pub mod vector;
pub mod verify;
