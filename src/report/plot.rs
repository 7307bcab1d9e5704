//! Line plots as SVG with plotters (SVG backend only: text is emitted as SVG `<text>` with a
//! generic family, no system font is read). Logarithmic axes are drawn by plotting log10 of the
//! data and saying so in the axis label, which keeps one code path for all plots.

use plotters::prelude::*;
use std::path::Path;

/// One named line.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Legend text.
    pub name: String,
    /// (x, y) points in drawing order; non-finite points are dropped.
    pub points: Vec<(f64, f64)>,
}

/// Titles, labels and markers of a plot.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PlotSpec {
    /// Caption.
    pub title: String,
    /// x-axis label.
    pub x_label: String,
    /// y-axis label.
    pub y_label: String,
    /// Vertical marker lines at these x values.
    pub vlines: Vec<f64>,
    /// Horizontal marker lines at these y values.
    pub hlines: Vec<f64>,
}

const COLORS: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];

fn range(vals: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = vals.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let pad = if hi > lo {
        0.05 * (hi - lo)
    } else {
        0.5 * lo.abs().max(1.0)
    };
    (lo - pad, hi + pad)
}

/// Draw `series` into the SVG file `path`.
pub fn line_plot(path: &Path, spec: &PlotSpec, series: &[Series]) -> Result<(), String> {
    let e = |e: &dyn std::fmt::Display| format!("cannot draw {}: {e}", path.display());
    let root = SVGBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    draw_chart(&root, spec, series, 22).map_err(|x| e(&x))?;
    root.present().map_err(|x| e(&x))?;
    Ok(())
}

/// Draw one chart per panel into the SVG file `path`, in a grid two panels wide.
pub fn panel_plot(path: &Path, panels: &[(PlotSpec, Vec<Series>)]) -> Result<(), String> {
    let e = |e: &dyn std::fmt::Display| format!("cannot draw {}: {e}", path.display());
    let cols = panels.len().clamp(1, 2);
    let rows = panels.len().div_ceil(cols).max(1);
    let root = SVGBackend::new(path, (700 * cols as u32, 480 * rows as u32)).into_drawing_area();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    for (area, (spec, series)) in root.split_evenly((rows, cols)).iter().zip(panels) {
        draw_chart(area, spec, series, 18).map_err(|x| e(&x))?;
    }
    root.present().map_err(|x| e(&x))?;
    Ok(())
}

fn draw_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    spec: &PlotSpec,
    series: &[Series],
    caption_size: u32,
) -> Result<(), String> {
    let e = |x: &dyn std::fmt::Display| x.to_string();
    let clean: Vec<Vec<(f64, f64)>> = series
        .iter()
        .map(|s| {
            s.points
                .iter()
                .copied()
                .filter(|(x, y)| x.is_finite() && y.is_finite())
                .collect()
        })
        .collect();
    let all = || clean.iter().flatten();
    let (x0, x1) = range(all().map(|p| p.0).chain(spec.vlines.iter().copied()));
    let (y0, y1) = range(all().map(|p| p.1).chain(spec.hlines.iter().copied()));
    let mut chart = ChartBuilder::on(area)
        .caption(&spec.title, ("sans-serif", caption_size))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|x| e(&x))?;
    chart
        .configure_mesh()
        .x_desc(&spec.x_label)
        .y_desc(&spec.y_label)
        .draw()
        .map_err(|x| e(&x))?;
    for &v in &spec.vlines {
        chart
            .draw_series(LineSeries::new([(v, y0), (v, y1)], BLACK.mix(0.4)))
            .map_err(|x| e(&x))?;
    }
    for &h in &spec.hlines {
        chart
            .draw_series(LineSeries::new([(x0, h), (x1, h)], BLACK.mix(0.4)))
            .map_err(|x| e(&x))?;
    }
    for (i, (s, pts)) in series.iter().zip(&clean).enumerate() {
        let color = COLORS[i % COLORS.len()];
        chart
            .draw_series(LineSeries::new(pts.iter().copied(), color.stroke_width(2)))
            .map_err(|x| e(&x))?
            .label(s.name.clone())
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(|x| e(&x))?;
    Ok(())
}
