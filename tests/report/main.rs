//! The reports (`sliding_ladder::report`): work-precision, the reliability campaign, figures,
//! force diagrams and long runs (`cargo test --test report`).

mod animation;
mod campaign;
mod diagram;
mod digits;
mod fall_figures;
mod plot;
mod stability;
mod svg_chart;
mod work_precision;
