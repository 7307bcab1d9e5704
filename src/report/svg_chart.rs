//! The SVG text of one line chart: float coordinates (two decimals, so curves are smooth at any
//! zoom), linear or real logarithmic axes (ticks at whole decades, labelled 10⁻¹², 10⁻⁸, …),
//! markers on measured points, dashed lines for references, labelled event lines, one title,
//! and the legend in its own column right of the plot area, so it never hides data.
//!
//! Written by hand rather than with plotters (which still draws the force diagrams): plotters'
//! SVG backend rounds every coordinate to a whole pixel, which makes curves jagged, and its log
//! axes label mantissas (1, 2, 5) rather than decades. A chart is a few hundred lines of SVG
//! text, and owning it keeps the palette and layout the same in every figure.

use super::chart::{Chart, Series};
use super::svg_text::esc;
use std::fmt::Write;

/// The palette (Okabe–Ito, distinguishable with any colour vision), in series order.
pub const PALETTE: [&str; 9] = [
    "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#8C6D31",
    "#7F7F7F",
];

/// The colour of a front ([`Chart::front`]): a light grey band behind the data.
pub const FRONT: &str = "#D0D0D0";

const LEFT: f64 = 84.0;
const RIGHT: f64 = 200.0;
const TOP: f64 = 44.0;
const BOTTOM: f64 = 58.0;

/// `10` to the integer power `k`, as text with Unicode superscripts: 10⁻¹².
pub fn decade_label(k: i32) -> String {
    const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::from("10");
    if k < 0 {
        s.push('⁻');
    }
    for d in k.unsigned_abs().to_string().bytes() {
        s.push(SUP[(d - b'0') as usize]);
    }
    s
}

/// One axis: its range in plotted units (log10 of the data on a log axis) and its ticks.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    /// Lower end, plotted units.
    pub lo: f64,
    /// Upper end, plotted units.
    pub hi: f64,
    /// Ticks: (position in plotted units, label).
    pub ticks: Vec<(f64, String)>,
    /// Logarithmic.
    pub log: bool,
}

impl Axis {
    /// The axis through `values` (data units; non-positive values are left out on a log axis).
    pub fn fit(values: impl Iterator<Item = f64>, log: bool) -> Axis {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for v in values.filter(|v| v.is_finite() && (!log || *v > 0.0)) {
            let v = if log { v.log10() } else { v };
            lo = lo.min(v);
            hi = hi.max(v);
        }
        if !lo.is_finite() {
            (lo, hi) = (0.0, 1.0);
        }
        if log {
            let (a, b) = (lo.floor(), hi.ceil().max(lo.floor() + 1.0));
            let every = ((b - a) / 8.0).ceil().max(1.0);
            let first = (a / every).ceil() * every;
            let ticks = (0..)
                .map(|i| first + i as f64 * every)
                .take_while(|&k| k <= b + 1e-9)
                .map(|k| (k, decade_label(k as i32)))
                .collect();
            return Axis {
                lo: a,
                hi: b,
                ticks,
                log,
            };
        }
        if hi - lo < 1e-300 {
            let pad = 0.5 * lo.abs().max(1.0);
            (lo, hi) = (lo - pad, hi + pad);
        }
        let pad = 0.04 * (hi - lo);
        let (lo, hi) = (lo - pad, hi + pad);
        let raw = (hi - lo) / 6.0;
        let mag = 10f64.powf(raw.log10().floor());
        let step = [1.0, 2.0, 5.0, 10.0]
            .iter()
            .map(|m| m * mag)
            .find(|s| *s >= raw)
            .unwrap_or(10.0 * mag);
        let decimals = (-step.log10().floor()).max(0.0) as usize;
        let first = (lo / step).ceil();
        let ticks = (0..)
            .map(|i| (first + i as f64) * step)
            .take_while(|&v| v <= hi)
            .map(|v| {
                let v = if v.abs() < step * 1e-9 { 0.0 } else { v };
                (v, format!("{v:.decimals$}").replace('-', "−"))
            })
            .collect();
        Axis { lo, hi, ticks, log }
    }

    /// A data value in plotted units (None when it cannot be shown on this axis).
    pub fn map(&self, v: f64) -> Option<f64> {
        match (self.log, v.is_finite()) {
            (true, true) if v > 0.0 => Some(v.log10()),
            (false, true) => Some(v),
            _ => None,
        }
    }
}

/// Draw `chart` with `series` as an SVG group of size `w` × `h`; `id` makes clip ids unique.
pub fn chart_svg(chart: &Chart, series: &[Series], w: f64, h: f64, id: &str) -> String {
    let s = &chart.spec;
    let xs = series.iter().flat_map(|p| p.points.iter().map(|q| q.0));
    let marks = chart.marks.iter().map(|m| m.x);
    let x = Axis::fit(xs.chain(s.vlines.iter().copied()).chain(marks), chart.log_x);
    let ys = series.iter().flat_map(|p| p.points.iter().map(|q| q.1));
    let y = Axis::fit(ys.chain(s.hlines.iter().copied()), chart.log_y);
    let (x0, x1, y0, y1) = (LEFT, w - RIGHT, TOP, h - BOTTOM);
    let px = |v: f64| x0 + (v - x.lo) / (x.hi - x.lo) * (x1 - x0);
    let py = |v: f64| y1 - (v - y.lo) / (y.hi - y.lo) * (y1 - y0);
    let mut o = String::new();
    let _ = write!(
        o,
        "<rect x=\"0\" y=\"0\" width=\"{w}\" height=\"{h}\" fill=\"white\"/>\
<text x=\"{:.1}\" y=\"26\" text-anchor=\"middle\" font-size=\"17\" font-weight=\"bold\">{}</text>\
<clipPath id=\"clip-{id}\"><rect x=\"{x0}\" y=\"{y0}\" width=\"{:.1}\" height=\"{:.1}\"/></clipPath>",
        (x0 + x1) / 2.0,
        esc(&s.title),
        x1 - x0,
        y1 - y0
    );
    // Grid, ticks and tick labels.
    for (v, label) in &x.ticks {
        let p = px(*v);
        let _ = write!(
            o,
            "<line x1=\"{p:.2}\" y1=\"{y0}\" x2=\"{p:.2}\" y2=\"{y1}\" stroke=\"#e3e3e3\"/>\
<text x=\"{p:.2}\" y=\"{:.1}\" text-anchor=\"middle\" font-size=\"13\">{}</text>",
            y1 + 18.0,
            esc(label)
        );
    }
    for (v, label) in &y.ticks {
        let p = py(*v);
        let _ = write!(
            o,
            "<line x1=\"{x0}\" y1=\"{p:.2}\" x2=\"{x1}\" y2=\"{p:.2}\" stroke=\"#e3e3e3\"/>\
<text x=\"{:.1}\" y=\"{:.2}\" text-anchor=\"end\" font-size=\"13\">{}</text>",
            x0 - 6.0,
            p + 4.0,
            esc(label)
        );
    }
    let _ = write!(
        o,
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
    let _ = write!(o, "<g clip-path=\"url(#clip-{id})\">");
    for v in s.vlines.iter().filter_map(|v| x.map(*v)) {
        let _ = write!(
            o,
            "<line x1=\"{0:.2}\" y1=\"{y0}\" x2=\"{0:.2}\" y2=\"{y1}\" stroke=\"#777\"/>",
            px(v)
        );
    }
    for v in s.hlines.iter().filter_map(|v| y.map(*v)) {
        let _ = write!(
            o,
            "<line x1=\"{x0}\" y1=\"{0:.2}\" x2=\"{x1}\" y2=\"{0:.2}\" stroke=\"#777\"/>",
            py(v)
        );
    }
    for (i, m) in chart.marks.iter().enumerate() {
        if let Some(v) = x.map(m.x) {
            let p = px(v);
            // A label in the right half reads leftwards from its line, so it stays inside.
            let right = p > (x0 + x1) / 2.0;
            let _ = write!(o, "<line x1=\"{p:.2}\" y1=\"{y0}\" x2=\"{p:.2}\" y2=\"{y1}\" stroke=\"#555\" stroke-dasharray=\"3 3\"/>\
<text x=\"{:.2}\" y=\"{:.1}\" font-size=\"12\" fill=\"#333\"{}>{}</text>", if right { p - 4.0 } else { p + 4.0 }, y0 + 15.0 + 15.0 * (i % 3) as f64, if right { " text-anchor=\"end\"" } else { "" }, esc(&m.label));
        }
    }
    // The front first, under every method's line.
    let front = |ser: &&Series| chart.front.as_deref() == Some(ser.name.as_str());
    for ser in series.iter().filter(front) {
        let line: Vec<String> = ser
            .points
            .iter()
            .filter_map(|&(a, b)| Some((px(x.map(a)?), py(y.map(b)?))))
            .map(|(a, b)| format!("{a:.2},{b:.2}"))
            .collect();
        let _ = write!(o, "<polyline fill=\"none\" stroke=\"{FRONT}\" stroke-width=\"9\" stroke-linejoin=\"round\" stroke-linecap=\"round\" points=\"{}\"/>", line.join(" "));
    }
    // (colour and marker index, dashed, markers) of each series: a peer borrows its partner's.
    let style = |i: usize, ser: &Series| {
        let partner = chart
            .peers
            .iter()
            .find(|(p, _)| *p == ser.name)
            .and_then(|(_, of)| series.iter().position(|s| s.name == *of));
        match partner {
            Some(j) => (j, " stroke-dasharray=\"7 4\"", chart.markers),
            None if chart.dashed.contains(&ser.name) => (i, " stroke-dasharray=\"7 4\"", false),
            None => (i, "", chart.markers),
        }
    };
    for (i, ser) in series.iter().enumerate().filter(|(_, s)| !front(s)) {
        let (k, dash, markers) = style(i, ser);
        let color = PALETTE[k % PALETTE.len()];
        let pts: Vec<(f64, f64)> = ser
            .points
            .iter()
            .filter_map(|&(a, b)| Some((px(x.map(a)?), py(y.map(b)?))))
            .collect();
        let line: Vec<String> = pts.iter().map(|(a, b)| format!("{a:.2},{b:.2}")).collect();
        let _ = write!(o, "<polyline fill=\"none\" stroke=\"{color}\" stroke-width=\"2\"{dash} stroke-linejoin=\"round\" points=\"{}\"/>", line.join(" "));
        if markers {
            for (a, b) in &pts {
                o.push_str(&marker(k, *a, *b, color));
            }
        }
    }
    o.push_str("</g>");
    // The legend, in its own column.
    let lx = x1 + 14.0;
    for (i, ser) in series.iter().enumerate() {
        let (k, dash, markers) = style(i, ser);
        let color = PALETTE[k % PALETTE.len()];
        let ly = y0 + 10.0 + 20.0 * i as f64;
        if front(&ser) {
            let _ = write!(o, "<line x1=\"{lx:.1}\" y1=\"{ly:.1}\" x2=\"{:.1}\" y2=\"{ly:.1}\" stroke=\"{FRONT}\" stroke-width=\"9\" stroke-linecap=\"round\"/><text x=\"{:.1}\" y=\"{:.1}\" font-size=\"13\">{}</text>", lx + 26.0, lx + 32.0, ly + 4.0, esc(&ser.name));
            continue;
        }
        let _ = write!(o, "<line x1=\"{lx:.1}\" y1=\"{ly:.1}\" x2=\"{:.1}\" y2=\"{ly:.1}\" stroke=\"{color}\" stroke-width=\"2\"{dash}/>", lx + 26.0);
        if markers {
            o.push_str(&marker(k, lx + 13.0, ly, color));
        }
        let _ = write!(
            o,
            "<text x=\"{:.1}\" y=\"{:.1}\" font-size=\"13\">{}</text>",
            lx + 32.0,
            ly + 4.0,
            esc(&ser.name)
        );
    }
    o
}

/// A marker whose shape, like the colour, tells the series apart (also in grey print).
fn marker(i: usize, x: f64, y: f64, color: &str) -> String {
    match i % 4 {
        0 => format!("<circle cx=\"{x:.2}\" cy=\"{y:.2}\" r=\"3.2\" fill=\"{color}\"/>"),
        1 => format!("<rect x=\"{:.2}\" y=\"{:.2}\" width=\"6\" height=\"6\" fill=\"{color}\"/>", x - 3.0, y - 3.0),
        2 => format!("<path d=\"M{x:.2},{:.2} l3.6,6.2 h-7.2 z\" fill=\"{color}\"/>", y - 4.1),
        _ => format!("<path d=\"M{x:.2},{:.2} l3.8,3.8 l-3.8,3.8 l-3.8,-3.8 z\" fill=\"white\" stroke=\"{color}\" stroke-width=\"1.5\"/>", y - 3.8),
    }
}

/// A whole SVG document of `panels` in a grid two wide, each `pw` × `ph`.
pub fn document(panels: &[(Chart, Vec<Series>)], pw: f64, ph: f64) -> String {
    let cols = panels.len().clamp(1, 2);
    let rows = panels.len().div_ceil(cols).max(1);
    let (w, h) = (pw * cols as f64, ph * rows as f64);
    let mut o = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" \
font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n"
    );
    for (k, (chart, series)) in panels.iter().enumerate() {
        let (c, r) = (k % cols, k / cols);
        let _ = writeln!(
            o,
            "<g transform=\"translate({},{})\">{}</g>",
            pw * c as f64,
            ph * r as f64,
            chart_svg(chart, series, pw, ph, &format!("p{k}"))
        );
    }
    o.push_str("</svg>\n");
    o
}
