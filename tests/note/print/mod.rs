//! `sliding_ladder::registry::print_check` and `sliding_ladder::print`: the printed LaTeX parsed,
//! evaluated, proved and unit-checked.

mod check;
mod inject;
mod prove;
mod units;
