//! The SVG text of a force diagram ([`crate::report::diagram::Diagram`]): wall and floor (hatched), the
//! rectangle A–D–E–C, the ladder C–D, the angle θ at C, the points, P ringed in red, every force
//! as an arrow with its symbol and value, and every lever arm as a dashed perpendicular from P to
//! the force's line of action (dotted), labelled with the note's symbol and its length. The
//! legend column on the right gives the state and, per force, its components, point, arm and
//! torque about P, and their sum.
//!
//! Written by hand like [`crate::report::svg_chart`], for the same reason: plotters' SVG backend rounds
//! every coordinate to a whole pixel, so an arrow's direction and a lever arm's right angle came
//! out slightly wrong; here every coordinate is a float with two decimals.

use crate::report::diagram::{arrow_scale, drawing_width, to_px, window, Arrow, Diagram, SIDE};
use crate::report::svg_text::{esc, subscript, FORCE_COLOURS};
use std::fmt::Write;

mod arm;

pub use arm::foot;

/// Width of the legend column right of the drawing, px.
pub const LEGEND: f64 = 460.0;

fn line(out: &mut String, a: (f64, f64), b: (f64, f64), style: &str) {
    let _ = writeln!(
        out,
        "<line x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" {style}/>",
        a.0, a.1, b.0, b.1
    );
}

/// Text with a white halo, so that it stays legible over lines.
fn label(out: &mut String, at: (f64, f64), anchor: &str, colour: &str, size: u32, text: &str) {
    let _ = writeln!(
        out,
        "<text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"{anchor}\" font-size=\"{size}\" fill=\"{colour}\" \
stroke=\"white\" stroke-width=\"4\" stroke-linejoin=\"round\" paint-order=\"stroke\" xml:space=\"preserve\">{}</text>",
        at.0,
        at.1,
        subscript(text, size)
    );
}

/// The arrow of one force: a shaft from where it acts to its tip (the force times the scale),
/// a filled head at the tip, and its symbol and value beyond the tip.
fn arrow(out: &mut String, d: &Diagram, a: &Arrow, colour: &str) {
    let s = arrow_scale(d);
    let from = to_px(d, a.at);
    let to = to_px(d, (a.at.0 + s * a.force.0, a.at.1 + s * a.force.1));
    let (dx, dy) = (to.0 - from.0, to.1 - from.1);
    let len = dx.hypot(dy);
    let _ = writeln!(
        out,
        "<line class=\"force\" data-symbol=\"{}\" x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" stroke=\"{colour}\" stroke-width=\"3\"/>",
        esc(&a.symbol),
        from.0,
        from.1,
        to.0,
        to.1
    );
    if len == 0.0 {
        return;
    }
    let (ux, uy) = (dx / len, dy / len);
    let (h, w) = (14.0, 5.5);
    let base = (to.0 - h * ux, to.1 - h * uy);
    let _ = writeln!(
        out,
        "<polygon points=\"{:.2},{:.2} {:.2},{:.2} {:.2},{:.2}\" fill=\"{colour}\"/>",
        to.0,
        to.1,
        base.0 - w * uy,
        base.1 + w * ux,
        base.0 + w * uy,
        base.1 - w * ux
    );
    // The symbol (the value is in the legend): a mostly horizontal arrow's just under its tip
    // (its line may carry lever arms), a mostly vertical one's beside its tip, right of the
    // shaft (its line of action, dotted, runs on through the tip), any other beyond its tip.
    let (at, anchor) = if ux.abs() > 0.85 {
        (
            (to.0 - 4.0 * ux.signum(), to.1 + 20.0),
            if ux > 0.0 { "end" } else { "start" },
        )
    } else if uy.abs() > 0.85 {
        ((to.0 + 10.0, to.1 - 6.0 * uy.signum() + 5.0), "start")
    } else {
        let anchor = if ux < -0.3 {
            "end"
        } else if ux > 0.3 {
            "start"
        } else {
            "middle"
        };
        (
            (
                to.0 + 10.0 * ux,
                to.1 + 10.0 * uy + if uy > 0.0 { 12.0 } else { -2.0 },
            ),
            anchor,
        )
    };
    let text = a.symbol.clone();
    label(out, at, anchor, colour, 15, &text);
}

/// The wall and the floor, hatched on the side of the solid.
fn walls(out: &mut String, d: &Diagram) {
    let (_, x1, _, y1) = window(d);
    let origin = to_px(d, (0.0, 0.0));
    let (top, right) = (to_px(d, (0.0, y1)), to_px(d, (x1, 0.0)));
    let mut y = origin.1;
    while y > top.1 + 10.0 {
        line(
            out,
            (origin.0, y),
            (origin.0 - 9.0, y + 9.0),
            "stroke=\"#777\" stroke-width=\"1\"",
        );
        y -= 14.0;
    }
    let mut x = origin.0;
    while x < right.0 - 10.0 {
        line(
            out,
            (x, origin.1),
            (x - 9.0, origin.1 + 9.0),
            "stroke=\"#777\" stroke-width=\"1\"",
        );
        x += 14.0;
    }
    line(out, origin, top, "stroke=\"black\" stroke-width=\"3\"");
    line(out, origin, right, "stroke=\"black\" stroke-width=\"3\"");
}

/// The rectangle A–D–E–C (E is not on the ladder), thin, the ladder C–D, thick, and the
/// angle θ at C between the wall (downwards) and the ladder.
fn ladder_and_angle(out: &mut String, d: &Diagram) {
    let at = |n: &str| {
        d.corners
            .iter()
            .find(|c| c.0 == n)
            .map_or((0.0, 0.0), |c| c.1)
    };
    // The rectangle A–D–E–C (E is not on the ladder), thin, and the ladder C–D, thick.
    let (c, dd, e) = (to_px(d, at("C")), to_px(d, at("D")), to_px(d, at("E")));
    let _ = writeln!(
        out,
        "<polyline points=\"{:.2},{:.2} {:.2},{:.2} {:.2},{:.2}\" fill=\"none\" stroke=\"#999\" stroke-width=\"1\" stroke-dasharray=\"4 3\"/>",
        dd.0, dd.1, e.0, e.1, c.0, c.1
    );
    line(
        out,
        c,
        dd,
        "stroke=\"#D2B98B\" stroke-width=\"8\" stroke-linecap=\"round\"",
    );
    // θ at C, between the wall (downwards) and the ladder.
    let r = 42.0;
    let (ux, uy) = (
        (dd.0 - c.0) / (dd.0 - c.0).hypot(dd.1 - c.1),
        (dd.1 - c.1) / (dd.0 - c.0).hypot(dd.1 - c.1),
    );
    let _ = writeln!(
        out,
        "<path d=\"M {:.2} {:.2} A {r} {r} 0 0 0 {:.2} {:.2}\" fill=\"none\" stroke=\"#555\" stroke-width=\"1.2\"/>",
        c.0,
        c.1 + r,
        c.0 + r * ux,
        c.1 + r * uy
    );
    let half = (0.5 * ux, 0.5 * (1.0 + uy));
    let n = half.0.hypot(half.1);
    label(
        out,
        (
            c.0 + (r + 12.0) * half.0 / n,
            c.1 + (r + 12.0) * half.1 / n + 5.0,
        ),
        "middle",
        "#555",
        15,
        "θ",
    );
}

/// The points A–E, and P ringed in red.
fn points(out: &mut String, d: &Diagram) {
    for (name, q) in &d.corners {
        let p = to_px(d, *q);
        let _ = writeln!(
            out,
            "<circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"4\" fill=\"black\"/>",
            p.0, p.1
        );
        label(out, (p.0 - 12.0, p.1 - 8.0), "end", "black", 18, name);
    }
    let p = to_px(d, d.p);
    let _ = writeln!(
        out,
        "<circle class=\"reference\" cx=\"{:.2}\" cy=\"{:.2}\" r=\"9\" fill=\"none\" stroke=\"#D00\" stroke-width=\"2\"/>",
        p.0, p.1
    );
}

/// Draw the diagram as SVG text.
pub fn draw_svg(d: &Diagram) -> String {
    let left = drawing_width(d);
    let (w, h) = (left + LEGEND, SIDE);
    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" \
font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n<rect width=\"{w}\" height=\"{h}\" fill=\"white\"/>\n"
    );
    walls(&mut out, d);
    ladder_and_angle(&mut out, d);
    arm::lever_arms(&mut out, d);
    points(&mut out, d);
    for (i, a) in d.arrows.iter().enumerate() {
        arrow(&mut out, d, a, FORCE_COLOURS[i % FORCE_COLOURS.len()]);
    }
    // a_P at P in the coordinate force's colour, and the sense of θ̇ round B.
    let own = d
        .arrows
        .iter()
        .position(|a| a.symbol == format!("F_{}", d.point));
    if let Some(i) = own {
        crate::report::diagram::marks::acceleration_arrow(
            &mut out,
            d,
            FORCE_COLOURS[i % FORCE_COLOURS.len()],
        );
    }
    crate::report::diagram::marks::rotation_arrow(&mut out, d);
    crate::report::diagram::legend::legend(&mut out, d, left);
    out.push_str("</svg>\n");
    out
}
