//! `sim::integrators::radau5`: the implicit Radau IIA method.

mod domain;
mod step_reuse;
