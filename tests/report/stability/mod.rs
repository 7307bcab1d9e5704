//! `report::stability`: the stability report's cases.

mod extreme;
mod long;
mod scale;
mod stiff;
