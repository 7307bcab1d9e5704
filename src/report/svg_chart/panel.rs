//! One panel of a chart: the frame, its grid and labels, the guide lines, the series and
//! (alone) its legend column.

use super::{legend_entry, marker, style, thin, Axis, FRONT, LEFT, PALETTE, RIGHT, SHARED_RIGHT};
use super::{BOTTOM, TOP};
use crate::report::chart::{Chart, Series};
use crate::report::svg_text::esc;
use std::fmt::Write;

/// The plot area of a panel: its axes and its box (x0..x1, y0..y1 px).
struct Frame {
    x: Axis,
    y: Axis,
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
}

impl Frame {
    /// The pixel column of `v` (plotted units).
    fn px(&self, v: f64) -> f64 {
        let (x, x0, x1) = (&self.x, self.x0, self.x1);
        x0 + (v - x.lo) / (x.hi - x.lo) * (x1 - x0)
    }
    /// The pixel row of `v` (plotted units).
    fn py(&self, v: f64) -> f64 {
        let (y, y0, y1) = (&self.y, self.y0, self.y1);
        y1 - (v - y.lo) / (y.hi - y.lo) * (y1 - y0)
    }
}

/// The chart as [`super::chart_svg`] draws it; with `shared` (see [`style`]) it leaves out its
/// own legend column, since the figure draws one legend for all its panels.
pub(super) fn panel_svg(
    chart: &Chart,
    series: &[Series],
    w: f64,
    h: f64,
    id: &str,
    shared: Option<&[String]>,
) -> String {
    let s = &chart.spec;
    let xs = series.iter().flat_map(|p| p.points.iter().map(|q| q.0));
    let marks = chart.marks.iter().map(|m| m.x);
    let x = Axis::fit(xs.chain(s.vlines.iter().copied()).chain(marks), chart.log_x);
    let ys = series.iter().flat_map(|p| p.points.iter().map(|q| q.1));
    let y = Axis::fit(ys.chain(s.hlines.iter().copied()), chart.log_y);
    let right = if shared.is_some() {
        SHARED_RIGHT
    } else {
        RIGHT
    };
    let (x0, x1, y0, y1) = (LEFT, w - right, TOP, h - BOTTOM);
    let f = Frame {
        x,
        y,
        x0,
        x1,
        y0,
        y1,
    };
    let mut o = String::new();
    title_and_clip(&mut o, &f, chart, (w, h), id);
    grid(&mut o, &f);
    box_and_labels(&mut o, &f, chart, h);
    let _ = write!(o, "<g clip-path=\"url(#clip-{id})\">");
    guides(&mut o, &f, chart);
    lines(&mut o, &f, chart, series, shared);
    o.push_str("</g>");
    let front = |ser: &&Series| chart.front.as_deref() == Some(ser.name.as_str());
    if shared.is_none() {
        // The legend, in its own column.
        for (i, ser) in series.iter().enumerate() {
            let ly = y0 + 10.0 + 20.0 * i as f64;
            legend_entry(
                &mut o,
                x1 + 14.0,
                ly,
                ser,
                front(&ser),
                style(chart, series, None, i, ser),
            );
        }
    }
    o
}

/// The white ground, the title, and the clip path of the plot area.
fn title_and_clip(o: &mut String, f: &Frame, chart: &Chart, (w, h): (f64, f64), id: &str) {
    let s = &chart.spec;
    let (x0, x1, y0, y1) = (f.x0, f.x1, f.y0, f.y1);
    let _ = write!(
        *o,
        "<rect x=\"0\" y=\"0\" width=\"{w}\" height=\"{h}\" fill=\"white\"/>\
<text x=\"{:.1}\" y=\"26\" text-anchor=\"middle\" font-size=\"17\" font-weight=\"bold\">{}</text>\
<clipPath id=\"clip-{id}\"><rect x=\"{x0}\" y=\"{y0}\" width=\"{:.1}\" height=\"{:.1}\"/></clipPath>",
        (x0 + x1) / 2.0,
        esc(&s.title),
        x1 - x0,
        y1 - y0
    );
}

/// Grid, ticks and tick labels.
fn grid(o: &mut String, f: &Frame) {
    let (x, y) = (&f.x, &f.y);
    let (x0, x1, y0, y1) = (f.x0, f.x1, f.y0, f.y1);
    for (v, label) in &x.ticks {
        let p = f.px(*v);
        let _ = write!(
            *o,
            "<line x1=\"{p:.2}\" y1=\"{y0}\" x2=\"{p:.2}\" y2=\"{y1}\" stroke=\"#e3e3e3\"/>\
<text x=\"{p:.2}\" y=\"{:.1}\" text-anchor=\"middle\" font-size=\"13\">{}</text>",
            y1 + 18.0,
            esc(label)
        );
    }
    for (v, label) in &y.ticks {
        let p = f.py(*v);
        let _ = write!(
            *o,
            "<line x1=\"{x0}\" y1=\"{p:.2}\" x2=\"{x1}\" y2=\"{p:.2}\" stroke=\"#e3e3e3\"/>\
<text x=\"{:.1}\" y=\"{:.2}\" text-anchor=\"end\" font-size=\"13\">{}</text>",
            x0 - 6.0,
            p + 4.0,
            esc(label)
        );
    }
}

/// The box of the plot area and the axes' labels.
fn box_and_labels(o: &mut String, f: &Frame, chart: &Chart, h: f64) {
    let s = &chart.spec;
    let (x0, x1, y0, y1) = (f.x0, f.x1, f.y0, f.y1);
    let _ = write!(
        *o,
        "<rect x=\"{x0}\" y=\"{y0}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"none\" stroke=\"#444\"/>\
<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\" font-size=\"14\">{}</text>\
<text transform=\"translate({:.1},{:.1}) rotate(-90)\" text-anchor=\"middle\" font-size=\"14\">{}</text>",
        x1 - x0,
        y1 - y0,
        (x0 + x1) / 2.0,
        h - 14.0,
        esc(&s.x_label),
        22.0,
        (y0 + y1) / 2.0,
        esc(&s.y_label)
    );
}

/// The reference lines (vertical and horizontal) and the labelled event marks.
fn guides(o: &mut String, f: &Frame, chart: &Chart) {
    let s = &chart.spec;
    let (x, y) = (&f.x, &f.y);
    let (x0, x1, y0, y1) = (f.x0, f.x1, f.y0, f.y1);
    for v in s.vlines.iter().filter_map(|v| x.map(*v)) {
        let _ = write!(
            *o,
            "<line x1=\"{0:.2}\" y1=\"{y0}\" x2=\"{0:.2}\" y2=\"{y1}\" stroke=\"#777\"/>",
            f.px(v)
        );
    }
    for v in s.hlines.iter().filter_map(|v| y.map(*v)) {
        let _ = write!(
            *o,
            "<line x1=\"{x0}\" y1=\"{0:.2}\" x2=\"{x1}\" y2=\"{0:.2}\" stroke=\"#777\"/>",
            f.py(v)
        );
    }
    for (i, m) in chart.marks.iter().enumerate() {
        if let Some(v) = x.map(m.x) {
            let p = f.px(v);
            // A label in the right half reads leftwards from its line, so it stays inside.
            let right = p > (x0 + x1) / 2.0;
            let _ = write!(*o, "<line x1=\"{p:.2}\" y1=\"{y0}\" x2=\"{p:.2}\" y2=\"{y1}\" stroke=\"#555\" stroke-dasharray=\"3 3\"/>\
<text x=\"{:.2}\" y=\"{:.1}\" font-size=\"12\" fill=\"#333\"{}>{}</text>", if right { p - 4.0 } else { p + 4.0 }, y0 + 15.0 + 15.0 * (i % 3) as f64, if right { " text-anchor=\"end\"" } else { "" }, esc(&m.label));
        }
    }
}

/// A series' points in the panel's pixels, and its polyline's `points` attribute (thinned).
fn plotted(f: &Frame, ser: &Series) -> (Vec<(f64, f64)>, String) {
    let pts: Vec<(f64, f64)> = ser
        .points
        .iter()
        .filter_map(|&(a, b)| Some((f.px(f.x.map(a)?), f.py(f.y.map(b)?))))
        .collect();
    let line: Vec<String> = thin(&pts)
        .iter()
        .map(|(a, b)| format!("{a:.2},{b:.2}"))
        .collect();
    (pts, line.join(" "))
}

/// The series: the front first, under every method's line, then each method's line with its
/// markers.
fn lines(o: &mut String, f: &Frame, chart: &Chart, series: &[Series], shared: Option<&[String]>) {
    // The front first, under every method's line.
    let front = |ser: &&Series| chart.front.as_deref() == Some(ser.name.as_str());
    for ser in series.iter().filter(front) {
        let (_, line) = plotted(f, ser);
        let _ = write!(*o, "<polyline fill=\"none\" stroke=\"{FRONT}\" stroke-width=\"9\" stroke-linejoin=\"round\" stroke-linecap=\"round\" points=\"{line}\"/>");
    }
    for (i, ser) in series.iter().enumerate().filter(|(_, s)| !front(s)) {
        let (k, dash, markers) = style(chart, series, shared, i, ser);
        let color = PALETTE[k % PALETTE.len()];
        let (pts, line) = plotted(f, ser);
        let _ = write!(*o, "<polyline fill=\"none\" stroke=\"{color}\" stroke-width=\"2\"{dash} stroke-linejoin=\"round\" points=\"{line}\"/>");
        if markers {
            for (a, b) in &pts {
                o.push_str(&marker(k, *a, *b, color));
            }
        }
    }
}
