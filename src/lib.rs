//! sliding-ladder: the equations of "Torque Analyses of a Sliding Ladder" as checked code.
pub mod sim;
