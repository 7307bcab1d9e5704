//! `report::diagram*`: the force diagrams of the torque analyses.

mod figures;
mod legend;
mod marks;
