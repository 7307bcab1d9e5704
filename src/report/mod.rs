//! Reports: the work-precision sweep, output files written all-or-nothing, SVG plots.

pub mod animation;
pub mod axis;
pub mod campaign;
pub mod chart;
pub mod diagram;
pub mod digits;
pub mod fall_figures;
pub mod files;
pub mod outcome;
pub mod plot;
pub mod stability;
pub mod svg_chart;
pub mod svg_text;
pub mod work_precision;
