//! `sim::event`: event functions and where a step samples them.

mod defaults;
mod interior_samples;
