//! `sim::fall`: whole falls, wall phase then floor phase, from every kind of start.

mod floor_minima;
mod floor_starts;
mod momentum_balance;
mod near_flat_starts;
mod plan;
mod scale;
mod tiny_starts;
mod top_clearance;
mod wall_phase;
