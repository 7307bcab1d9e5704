//! The SVG text of one line chart: float coordinates (two decimals, so curves are smooth at any
//! zoom), linear or real logarithmic axes (ticks at whole decades, labelled 10⁻¹², 10⁻⁸, …),
//! markers on measured points, dashed lines for references, labelled event lines, one title,
//! and the legend in its own column right of the plot area, so it never hides data.
//!
//! Written by hand rather than with plotters (which still draws the force diagrams): plotters'
//! SVG backend rounds every coordinate to a whole pixel, which makes curves jagged, and its log
//! axes label mantissas (1, 2, 5) rather than decades. A chart is a few hundred lines of SVG
//! text, and owning it keeps the palette and layout the same in every figure.

pub use super::axis::{decade_label, Axis};
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
/// The right margin of a panel whose legend is the figure's shared one.
const SHARED_RIGHT: f64 = 28.0;

/// Draw `chart` with `series` as an SVG group of size `w` × `h`; `id` makes clip ids unique.
pub fn chart_svg(chart: &Chart, series: &[Series], w: f64, h: f64, id: &str) -> String {
    panel_svg(chart, series, w, h, id, None)
}

/// (colour and marker index, dashed, markers) of `ser` in `chart`: a peer borrows its partner's
/// colour. `shared` is the figure's legend order when several panels share one legend, so a
/// method keeps its colour in every panel; otherwise a series' colour is its place in `series`.
fn style(
    chart: &Chart,
    series: &[Series],
    shared: Option<&[String]>,
    i: usize,
    ser: &Series,
) -> (usize, &'static str, bool) {
    let slot = |name: &str| match shared {
        Some(names) => names.iter().position(|n| n == name),
        None => series.iter().position(|s| s.name == name),
    };
    let partner = chart
        .peers
        .iter()
        .find(|(p, _)| *p == ser.name)
        .and_then(|(_, of)| slot(of));
    let own = shared.and_then(|_| slot(&ser.name)).unwrap_or(i);
    match partner {
        Some(j) => (j, " stroke-dasharray=\"7 4\"", chart.markers),
        None if chart.dashed.contains(&ser.name) => (own, " stroke-dasharray=\"7 4\"", false),
        None => (own, "", chart.markers),
    }
}

/// The chart as [`chart_svg`] draws it; with `shared` (see [`style`]) it leaves out its own
/// legend column, since the figure draws one legend for all its panels.
fn panel_svg(
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
        let pts: Vec<(f64, f64)> = ser
            .points
            .iter()
            .filter_map(|&(a, b)| Some((px(x.map(a)?), py(y.map(b)?))))
            .collect();
        let line: Vec<String> = thin(&pts)
            .iter()
            .map(|(a, b)| format!("{a:.2},{b:.2}"))
            .collect();
        let _ = write!(o, "<polyline fill=\"none\" stroke=\"{FRONT}\" stroke-width=\"9\" stroke-linejoin=\"round\" stroke-linecap=\"round\" points=\"{}\"/>", line.join(" "));
    }
    for (i, ser) in series.iter().enumerate().filter(|(_, s)| !front(s)) {
        let (k, dash, markers) = style(chart, series, shared, i, ser);
        let color = PALETTE[k % PALETTE.len()];
        let pts: Vec<(f64, f64)> = ser
            .points
            .iter()
            .filter_map(|&(a, b)| Some((px(x.map(a)?), py(y.map(b)?))))
            .collect();
        let line: Vec<String> = thin(&pts)
            .iter()
            .map(|(a, b)| format!("{a:.2},{b:.2}"))
            .collect();
        let _ = write!(o, "<polyline fill=\"none\" stroke=\"{color}\" stroke-width=\"2\"{dash} stroke-linejoin=\"round\" points=\"{}\"/>", line.join(" "));
        if markers {
            for (a, b) in &pts {
                o.push_str(&marker(k, *a, *b, color));
            }
        }
    }
    o.push_str("</g>");
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

/// One legend entry at (`lx`, `ly`): a short stretch of the series' line (or the front's band)
/// with its marker, then its name.
fn legend_entry(
    o: &mut String,
    lx: f64,
    ly: f64,
    ser: &Series,
    front: bool,
    st: (usize, &str, bool),
) {
    let (k, dash, markers) = st;
    let color = PALETTE[k % PALETTE.len()];
    if front {
        let _ = write!(o, "<line x1=\"{lx:.1}\" y1=\"{ly:.1}\" x2=\"{:.1}\" y2=\"{ly:.1}\" stroke=\"{FRONT}\" stroke-width=\"9\" stroke-linecap=\"round\"/>", lx + 26.0);
    } else {
        let _ = write!(o, "<line x1=\"{lx:.1}\" y1=\"{ly:.1}\" x2=\"{:.1}\" y2=\"{ly:.1}\" stroke=\"{color}\" stroke-width=\"2\"{dash}/>", lx + 26.0);
        if markers {
            o.push_str(&marker(k, lx + 13.0, ly, color));
        }
    }
    let _ = write!(
        o,
        "<text x=\"{:.1}\" y=\"{:.1}\" font-size=\"13\">{}</text>",
        lx + 32.0,
        ly + 4.0,
        esc(&ser.name)
    );
}

/// The points of a polyline (pixels) worth drawing: of each run of consecutive points in one
/// half-pixel column, the first, the lowest, the highest and the last, in their order. The line
/// looks the same at this resolution, and a trace of 1e5 steps stays a few thousand points
/// (one point per step made 20 MB files).
pub fn thin(pts: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(pts.len().min(4096));
    let mut i = 0;
    while i < pts.len() {
        let col = (2.0 * pts[i].0).floor();
        let mut j = i;
        while j + 1 < pts.len() && (2.0 * pts[j + 1].0).floor() == col {
            j += 1;
        }
        let run = &pts[i..=j];
        let by_y = |a: &&(f64, f64), b: &&(f64, f64)| a.1.total_cmp(&b.1);
        let lo = run
            .iter()
            .enumerate()
            .min_by(|a, b| by_y(&a.1, &b.1))
            .map_or(0, |m| m.0);
        let hi = run
            .iter()
            .enumerate()
            .max_by(|a, b| by_y(&a.1, &b.1))
            .map_or(0, |m| m.0);
        let mut keep = [0, lo, hi, run.len() - 1];
        keep.sort_unstable();
        let mut last = usize::MAX;
        for k in keep {
            if k != last {
                out.push(run[k]);
                last = k;
            }
        }
        i = j + 1;
    }
    out
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

/// Width of one entry of a figure's shared legend, px.
const ENTRY: f64 = 210.0;

/// A whole SVG document of `panels` in a grid two wide, each `pw` × `ph`. Several panels share
/// one legend, in rows under the grid, rather than each giving a quarter of its width to a copy.
pub fn document(panels: &[(Chart, Vec<Series>)], pw: f64, ph: f64) -> String {
    let cols = panels.len().clamp(1, 2);
    let rows = panels.len().div_ceil(cols).max(1);
    // The figure's series in first-seen order, each with the panel that styles its entry.
    let mut names: Vec<String> = Vec::new();
    let mut owner: Vec<(usize, usize)> = Vec::new();
    for (k, (_, series)) in panels.iter().enumerate() {
        for (i, ser) in series.iter().enumerate() {
            if !names.contains(&ser.name) {
                names.push(ser.name.clone());
                owner.push((k, i));
            }
        }
    }
    let shared = (panels.len() > 1).then_some(names.as_slice());
    let w = pw * cols as f64;
    let per_row = ((w - 2.0 * LEFT) / ENTRY).floor().max(1.0) as usize;
    let strip = match shared {
        Some(n) => 20.0 + 22.0 * n.len().div_ceil(per_row) as f64,
        None => 0.0,
    };
    let h = ph * rows as f64 + strip;
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
            panel_svg(chart, series, pw, ph, &format!("p{k}"), shared)
        );
    }
    if let Some(n) = shared {
        let top = ph * rows as f64;
        let _ = write!(
            o,
            "<rect x=\"0\" y=\"{top}\" width=\"{w}\" height=\"{strip}\" fill=\"white\"/>"
        );
        for (e, &(k, i)) in owner.iter().enumerate() {
            let (chart, series) = &panels[k];
            let ser = &series[i];
            let front = chart.front.as_deref() == Some(ser.name.as_str());
            let (lx, ly) = (
                LEFT + ENTRY * (e % per_row) as f64,
                top + 14.0 + 22.0 * (e / per_row) as f64,
            );
            legend_entry(
                &mut o,
                lx,
                ly,
                ser,
                front,
                style(chart, series, Some(n), i, ser),
            );
        }
    }
    o.push_str("</svg>\n");
    o
}
