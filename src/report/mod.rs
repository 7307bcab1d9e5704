//! Reports: the work-precision sweep, output files written all-or-nothing, SVG plots.

pub mod animation;
pub mod axis;
pub mod campaign;
pub mod campaign_judge;
pub mod chart;
pub mod diagram;
mod diagram_legend;
pub mod diagram_marks;
pub mod diagram_svg;
pub mod digits;
pub mod fall_figures;
pub mod files;
pub mod plot;
pub mod stability;
pub mod stability_case;
pub mod stability_corners;
pub mod stability_extreme;
pub mod stability_long;
pub mod stability_scale;
pub mod stability_stiff;
pub mod svg_chart;
pub mod svg_text;
pub mod work_precision;
pub mod work_precision_fit;
#[cfg(feature = "peers")]
pub mod work_precision_peers;
pub mod work_precision_report;
