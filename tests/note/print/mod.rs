//! `sliding_ladder::registry::print_check` and `sliding_ladder::print`: the printed LaTeX parsed,
//! evaluated, proved and unit-checked.

mod check;
mod condition;
mod independent;
mod inject;
mod lexer;
mod own_point;
mod parser;
mod planted;
mod point;
mod premises;
mod prove;
mod quantity;
mod render;
mod shapes;
mod symbols;
mod unicode;
mod units;
