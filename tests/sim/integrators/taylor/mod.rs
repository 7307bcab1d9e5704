//! `sim::integrators::taylor` and its series: the Taylor method.

mod coefficients;
mod f64_paths;
mod models;
mod order;
mod poly;
mod scaled;
mod step;
