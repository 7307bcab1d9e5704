//! Text helpers shared by the hand-written SVG of the charts and the force diagrams: escaping,
//! numbers with a true minus sign, the diagrams' palette, and symbols typeset with subscripts.

use std::fmt::Write;

/// Colours of the forces in order (F_w, F_f, m g, the coordinate force): Okabe–Ito.
pub const FORCE_COLOURS: [&str; 4] = ["#0072B2", "#009E73", "#000000", "#D55E00"];

/// Three decimals with a true minus sign, and never "−0.000".
pub fn n3(x: f64) -> String {
    let s = format!("{x:.3}");
    if s == "-0.000" {
        "0.000".into()
    } else {
        s.replace('-', "−")
    }
}

/// Escape text for SVG content (`&`, `<`, `>`).
pub fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// Text with its symbols typeset: in `F_w` or `F_E,x` the part after `_` (letters, digits and
/// commas) is lowered and smaller (an SVG `tspan`), and the text after it is raised back to the
/// baseline; text without `_` is only escaped.
pub fn subscript(text: &str, size: u32) -> String {
    let drop = 0.3 * f64::from(size);
    let mut out = String::new();
    let mut rest = text;
    let mut lowered = false;
    while let Some(i) = rest.find('_') {
        let sub_len = rest[i + 1..]
            .find(|c: char| !(c.is_alphanumeric() || c == ','))
            .unwrap_or(rest.len() - i - 1);
        let (before, sub) = (&rest[..i], &rest[i + 1..i + 1 + sub_len]);
        out.push_str(&raised(before, lowered, drop));
        let _ = write!(
            out,
            "<tspan dy=\"{drop:.1}\" font-size=\"{}\">{}</tspan>",
            size * 3 / 4,
            esc(sub)
        );
        lowered = true;
        rest = &rest[i + 1 + sub_len..];
    }
    out.push_str(&raised(rest, lowered, drop));
    out
}

/// The SVG's text as a reader reads it (for tests of what a figure says), the subscripts written back with `_`: the `tspan`
/// that lowers a subscript becomes `_`, every other `tspan` tag goes.
pub fn plain(svg: &str) -> String {
    let mut out = String::new();
    let mut rest = svg;
    while let Some(j) = [rest.find("<tspan"), rest.find("</tspan>")]
        .into_iter()
        .flatten()
        .min()
    {
        out.push_str(&rest[..j]);
        let end = j + rest[j..].find('>').unwrap() + 1;
        if rest[j..end].starts_with("<tspan dy=\"") && !rest[j..end].contains("dy=\"-") {
            out.push('_');
        }
        rest = &rest[end..];
    }
    out + rest
}

/// `text` escaped, raised back to the baseline when it follows a subscript.
fn raised(text: &str, after_subscript: bool, drop: f64) -> String {
    if after_subscript && !text.is_empty() {
        format!("<tspan dy=\"{:.1}\">{}</tspan>", -drop, esc(text))
    } else {
        esc(text)
    }
}
