//! `report::stability`: the stability report's cases.

mod long;
