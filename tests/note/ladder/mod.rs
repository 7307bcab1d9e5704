//! `sliding_ladder::ladder`: the torque analyses about A-E and any point, Jensen's terms.

mod analysis;
mod jensen;
mod torque_analyses;
