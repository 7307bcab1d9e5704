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

#[cfg(test)]
mod tests {
    use super::super::svg_chart::{decade_label, Axis};
    use super::*;

    #[test]
    fn decades_are_labelled_as_powers_of_ten() {
        assert_eq!(decade_label(-12), "10⁻¹²");
        assert_eq!(decade_label(0), "10⁰");
        assert_eq!(decade_label(3), "10³");
        let a = Axis::fit([3e-13, 2e-4, -1.0, 0.0].into_iter(), true);
        assert_eq!((a.lo, a.hi), (-13.0, -3.0));
        let labels: Vec<&str> = a.ticks.iter().map(|t| t.1.as_str()).collect();
        assert_eq!(labels, ["10⁻¹²", "10⁻¹⁰", "10⁻⁸", "10⁻⁶", "10⁻⁴"]);
        assert_eq!(a.map(-1.0), None);
    }

    #[test]
    fn linear_ticks_are_round_and_cover_the_data() {
        let a = Axis::fit([0.13, 2.71].into_iter(), false);
        assert!(a.lo < 0.13 && a.hi > 2.71);
        let v: Vec<f64> = a.ticks.iter().map(|t| t.0).collect();
        assert_eq!(v, [0.5, 1.0, 1.5, 2.0, 2.5]);
        assert_eq!(a.ticks[0].1, "0.5");
    }

    #[test]
    fn coordinates_are_not_rounded_to_pixels_and_the_legend_sits_outside_the_data() {
        let s = vec![Series {
            name: "a".into(),
            points: vec![(0.0, 0.0), (1.0, 1.0 / 3.0), (2.0, 1.0)],
        }];
        let svg = document(&[(PlotSpec::default().into(), s)], 960.0, 600.0);
        let poly = svg.split("points=\"").nth(1).unwrap();
        assert!(
            poly.split(['"', ' ', ','])
                .take(6)
                .any(|c| c.contains('.') && !c.ends_with(".00")),
            "{poly}"
        );
        assert_eq!(svg.matches("font-weight=\"bold\"").count(), 1, "one title");
    }

    #[test]
    fn a_force_that_changes_sign_is_found_between_its_samples() {
        let z = zero_crossings(&[(0.0, 2.0), (1.0, 1.0), (2.0, -1.0), (3.0, -2.0)]);
        assert_eq!(z, vec![1.5]);
        assert!(zero_crossings(&[(0.0, 1.0), (1.0, 2.0)]).is_empty());
    }
}
