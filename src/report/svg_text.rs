//! Text helpers shared by the hand-written SVG of the charts and the force diagrams: escaping,
//! numbers with a true minus sign, and the diagrams' palette.

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
