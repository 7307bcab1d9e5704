//! `sim::penalty*`: the penalty (one-sided spring) contact model, its plan, start and confirmation.

mod confirm;
mod convergence;
mod energy;
mod estimate_margin;
mod refusals;
mod retry;
mod start;
mod sweep;
mod verlet_start;
