//! `sliding_ladder::verify`: the verdict table and the errata.

mod claims;
mod errata_difference;
mod errata_point;
mod errata_reading;
mod fill;
mod golfer;
mod judge;
mod methods;
mod print_alone;
mod proof;
mod rolling;
mod summary;
mod table;
