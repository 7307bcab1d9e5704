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

mod panel;
use panel::panel_svg;

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
