//! Two marks of a force diagram ([`crate::report::diagram::svg`]) that explain rather than measure:
//!
//! * the acceleration a_P of the reference point, an arrow at P (dashed shaft, the colour of the
//!   coordinate force), drawn m a_P long at the force scale: the coordinate force F_P = −m a_P at
//!   the centre of mass is the same arrow turned round, which is why it points where it does;
//! * the sense of θ̇, a curved arrow round the centre of mass B: counter-clockwise (+ẑ) when
//!   θ̇ > 0, as the ladder turns while θ grows.

use crate::report::diagram::{arrow_scale, to_px, Diagram};
use crate::report::svg_text::{n3, subscript};
use std::fmt::Write;

/// The acceleration of P, m/s², when P accelerates (from F_P = −m a_P of the diagram).
pub fn acceleration_of_p(d: &Diagram) -> Option<(f64, f64)> {
    let f = d
        .arrows
        .iter()
        .find(|a| a.symbol == format!("F_{}", d.point))?;
    let m = d.mass_length.0;
    Some((-f.force.0 / m, -f.force.1 / m))
}

fn head(out: &mut String, to: (f64, f64), u: (f64, f64), colour: &str) {
    let (h, w) = (12.0, 5.0);
    let base = (to.0 - h * u.0, to.1 - h * u.1);
    let _ = writeln!(
        out,
        "<polygon points=\"{:.2},{:.2} {:.2},{:.2} {:.2},{:.2}\" fill=\"{colour}\"/>",
        to.0,
        to.1,
        base.0 - w * u.1,
        base.1 + w * u.0,
        base.0 + w * u.1,
        base.1 - w * u.0
    );
}

fn text(out: &mut String, at: (f64, f64), anchor: &str, colour: &str, words: &str) {
    let _ = writeln!(
        out,
        "<text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"{anchor}\" font-size=\"14\" fill=\"{colour}\" \
stroke=\"white\" stroke-width=\"4\" stroke-linejoin=\"round\" paint-order=\"stroke\" xml:space=\"preserve\">{}</text>",
        at.0,
        at.1,
        subscript(words, 14)
    );
}

/// The arrow of a_P at P, m a_P long at the force scale (nothing when P is at rest).
pub fn acceleration_arrow(out: &mut String, d: &Diagram, colour: &str) {
    let Some(a) = acceleration_of_p(d) else {
        return;
    };
    let s = arrow_scale(d) * d.mass_length.0;
    let from = to_px(d, d.p);
    let to = to_px(d, (d.p.0 + s * a.0, d.p.1 + s * a.1));
    let len = (to.0 - from.0).hypot(to.1 - from.1);
    if len < 1.0 {
        return;
    }
    let u = ((to.0 - from.0) / len, (to.1 - from.1) / len);
    let _ = writeln!(
        out,
        "<line class=\"acceleration\" data-symbol=\"a_{p}\" x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" stroke=\"{colour}\" stroke-width=\"2.5\" stroke-dasharray=\"6 3\"/>",
        from.0,
        from.1,
        to.0,
        to.1,
        p = d.point
    );
    head(out, to, u, colour);
    let anchor = if u.0 < -0.3 { "end" } else { "start" };
    let at = (to.0 + 8.0 * u.0 + 6.0 * u.1.abs(), to.1 + 8.0 * u.1 + 16.0);
    text(out, at, anchor, colour, &format!("a_{}", d.point));
}

/// The legend's words for a_P: its value, and what it has to do with F_P.
pub fn acceleration_words(d: &Diagram) -> Option<String> {
    let a = acceleration_of_p(d)?;
    Some(format!(
        "a_{p} = ({}, {}) m/s², dashed at {p}: F_{p} = −m a_{p}",
        n3(a.0),
        n3(a.1),
        p = d.point
    ))
}

/// A curved arrow round the centre of mass B in the sense of θ̇ (nothing when θ̇ = 0).
pub fn rotation_arrow(out: &mut String, d: &Diagram) {
    let rate = d.state.1;
    let Some(b) = d.corners.iter().find(|c| c.0 == "B").map(|c| to_px(d, c.1)) else {
        return;
    };
    if rate == 0.0 {
        return;
    }
    let r = 30.0;
    // Angles as on paper (y up): counter-clockwise is an increasing angle, and on the screen
    // (y down) it is SVG's sweep flag 0. The arc sits in the widest gap between the lines that
    // leave B (the ladder both ways, each force acting there and its line of action), so that
    // it crosses none of them.
    let s = rate.signum();
    let mid = free_direction(d);
    let half = 50f64.to_radians();
    let (a0, a1) = (mid - s * half, mid + s * half);
    let at = |a: f64| (b.0 + r * a.cos(), b.1 - r * a.sin());
    let (p0, p1) = (at(a0), at(a1));
    let sweep = if s > 0.0 { 0 } else { 1 };
    let _ = writeln!(
        out,
        "<path class=\"rotation\" data-sense=\"{}\" d=\"M {:.2} {:.2} A {r} {r} 0 0 {sweep} {:.2} {:.2}\" fill=\"none\" stroke=\"#6a3d9a\" stroke-width=\"2\"/>",
        if s > 0.0 { "counter-clockwise" } else { "clockwise" },
        p0.0,
        p0.1,
        p1.0,
        p1.1
    );
    // The tangent at the end, in the sense of travel (screen coordinates).
    head(out, p1, (-s * a1.sin(), -s * a1.cos()), "#6a3d9a");
    let lab = (
        b.0 + (r + 16.0) * mid.cos(),
        b.1 - (r + 16.0) * mid.sin() + 5.0,
    );
    let anchor = if mid.cos() < -0.3 {
        "end"
    } else if mid.cos() > 0.3 {
        "start"
    } else {
        "middle"
    };
    text(
        out,
        lab,
        anchor,
        "#6a3d9a",
        &format!("θ̇ = {} s⁻¹", n3(rate)),
    );
}

/// The direction (angle on paper, rad) in the middle of the widest gap between the lines that
/// leave the centre of mass B: the ladder towards C and towards D, and every force acting at B
/// along its line of action both ways.
pub fn free_direction(d: &Diagram) -> f64 {
    use std::f64::consts::TAU;
    let at = |n: &str| d.corners.iter().find(|c| c.0 == n).map(|c| c.1);
    let (Some(b), Some(c), Some(dd)) = (at("B"), at("C"), at("D")) else {
        return 0.0;
    };
    let mut dirs = vec![(c.1 - b.1).atan2(c.0 - b.0), (dd.1 - b.1).atan2(dd.0 - b.0)];
    for a in d
        .arrows
        .iter()
        .filter(|a| a.at == b && a.force != (0.0, 0.0))
    {
        let t = a.force.1.atan2(a.force.0);
        dirs.extend([t, t + std::f64::consts::PI]);
    }
    let mut dirs: Vec<f64> = dirs.iter().map(|t| t.rem_euclid(TAU)).collect();
    dirs.sort_by(f64::total_cmp);
    let mut best = (0.0, 0.0);
    for (i, t) in dirs.iter().enumerate() {
        let next = if i + 1 < dirs.len() {
            dirs[i + 1]
        } else {
            dirs[0] + TAU
        };
        if next - t > best.0 {
            best = (next - t, t + (next - t) / 2.0);
        }
    }
    best.1
}
