//! `sliding_ladder::ladder`: the torque analyses about A-E and any point, Jensen's terms.

mod analysis;
mod energy;
mod jensen;
mod particles;
mod torque_analyses;
