//! `sliding_ladder::verify`: the verdict table and the errata.

mod errata_difference;
mod errata_point;
mod table;
