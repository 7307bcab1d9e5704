//! `sim::integrators`: every method against known solutions, its step rules and counters.

mod any;
mod card;
mod convergence;
mod error_norm;
mod fixed;
mod overflow;
mod radau5;
mod rhs_counts;
mod step_time;
mod taylor;
mod unit_free_steps;
mod verlet;
