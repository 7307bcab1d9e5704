//! Line charts as SVG: the file writers; the data types ([`PlotSpec`], [`Series`], [`Chart`])
//! live in [`super::chart`] (re-exported here) so that the drawing, [`super::svg_chart`] (which
//! says why it is not plotters), can use them without importing this module back.
//!
//! A [`PlotSpec`] alone draws linear axes with plain lines, as before; a [`Chart`] adds real
//! logarithmic axes, markers on measured points, dashed reference lines and labelled events.

pub use super::chart::{Chart, Mark, PlotSpec, Series};
use super::svg_chart::document;
use std::path::Path;

/// Where `points` cross y = 0 (linear interpolation between the samples that straddle it).
pub fn zero_crossings(points: &[(f64, f64)]) -> Vec<f64> {
    points
        .windows(2)
        .filter(|w| (w[0].1 > 0.0 && w[1].1 <= 0.0) || (w[0].1 < 0.0 && w[1].1 >= 0.0))
        .filter(|w| w[1].1 != 0.0 || w[0].1 != 0.0)
        .map(|w| {
            let (a, b) = (w[0], w[1]);
            a.0 + (b.0 - a.0) * a.1 / (a.1 - b.1)
        })
        .collect()
}

fn write(path: &Path, svg: String) -> Result<(), String> {
    std::fs::write(path, svg).map_err(|e| format!("cannot draw {}: {e}", path.display()))
}

/// Draw `series` into the SVG file `path`.
pub fn line_plot(path: &Path, spec: &PlotSpec, series: &[Series]) -> Result<(), String> {
    chart_plot(path, &spec.clone().into(), series)
}

/// Draw a [`Chart`] into the SVG file `path`.
pub fn chart_plot(path: &Path, chart: &Chart, series: &[Series]) -> Result<(), String> {
    write(
        path,
        document(&[(chart.clone(), series.to_vec())], 960.0, 600.0),
    )
}

/// Draw one chart per panel into the SVG file `path`, in a grid two panels wide.
pub fn panel_plot<C: Clone + Into<Chart>>(
    path: &Path,
    panels: &[(C, Vec<Series>)],
) -> Result<(), String> {
    let charts: Vec<(Chart, Vec<Series>)> = panels
        .iter()
        .map(|(c, s)| (c.clone().into(), s.clone()))
        .collect();
    write(path, document(&charts, 760.0, 500.0))
}
