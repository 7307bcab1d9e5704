//! `sim::integrators::verlet`: Störmer-Verlet.

mod step;
mod velocity_dependent;
