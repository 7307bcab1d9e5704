//! Force diagrams: the ladder at a stated state with every force the torque analysis about a
//! reference point P uses, and the lever arm of each about P (the note's lost figure, sec. 2).
//!
//! [`diagram`] computes the arrows from the model: the wall force F_w (14) at C along +x, the
//! floor force F_f (15) at D along +y, gravity −mg ŷ at B, and, where P accelerates, the
//! coordinate force F_P = −m a_P (17) at the centre of mass, with a_P by automatic
//! differentiation of P's position. For each arrow it gives the lever arm about P (the distance
//! from P to the line of action) and the torque (x_Q − x_P) × F about P. [`draw_svg`] draws it
//! with plotters' SVG backend (text as SVG `<text>`, no system font is read): wall, floor, the
//! ladder C–D, the rectangle A–D–E–C, the points, each arrow with its symbol and value, and
//! each lever arm as a dashed perpendicular from P with its length.

use crate::ladder::analysis::ReferencePoint;
use crate::ladder::forces::{floor_force, wall_force};
use crate::ladder::geometry::{corner_position, Corner};
use crate::ladder::torque::coordinate_force;
use crate::ladder::{Ladder, State};
use plotters::prelude::*;

/// One force of the diagram.
#[derive(Clone, Debug, PartialEq)]
pub struct Arrow {
    /// The note's symbol: "F_w", "F_f", "m g", "F_C".
    pub symbol: String,
    /// Where it acts (x, y), m.
    pub at: (f64, f64),
    /// The force (x, y), N.
    pub force: (f64, f64),
    /// Distance from P to the line of action, m.
    pub arm: f64,
    /// Torque about P, z component (positive counter-clockwise), N·m.
    pub torque: f64,
}

/// A force diagram about one reference point.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagram {
    /// The point's name ("A", ..., or a description).
    pub point: String,
    /// Where P is (x, y), m.
    pub p: (f64, f64),
    /// The points A-E, for the drawing.
    pub corners: Vec<(&'static str, (f64, f64))>,
    /// The forces.
    pub arrows: Vec<Arrow>,
    /// The state, for the caption: θ (rad), θ̇ (1/s), θ̈ (1/s²).
    pub state: (f64, f64, f64),
    /// m (kg) and l (m), for the caption.
    pub mass_length: (f64, f64),
}

/// Three decimals with a true minus sign, and never "−0.000".
fn n3(x: f64) -> String {
    let s = format!("{x:.3}");
    if s == "-0.000" {
        "0.000".into()
    } else {
        s.replace('-', "−")
    }
}

fn xy(v: &crate::vector::Vec3<f64>) -> (f64, f64) {
    (v.x, v.y)
}

fn arrow(symbol: &str, at: (f64, f64), force: (f64, f64), p: (f64, f64)) -> Arrow {
    let r = (at.0 - p.0, at.1 - p.1);
    let torque = r.0 * force.1 - r.1 * force.0;
    let size = force.0.hypot(force.1);
    Arrow {
        symbol: symbol.into(),
        at,
        force,
        arm: if size > 0.0 { torque.abs() / size } else { 0.0 },
        torque,
    }
}

/// The forces of a torque analysis about `point` (named `name`) at the state `st`.
pub fn diagram(
    name: &str,
    point: &impl ReferencePoint,
    ladder: &Ladder<f64>,
    st: &State<f64>,
) -> Diagram {
    let motion = point.motion(ladder, st);
    let p = xy(&motion.x);
    let pos = |k| xy(&corner_position(k, ladder, st));
    let mut arrows = vec![
        arrow("F_w", pos(Corner::C), (wall_force(ladder, st), 0.0), p),
        arrow("F_f", pos(Corner::D), (0.0, floor_force(ladder, st)), p),
        arrow("m g", pos(Corner::B), (0.0, -ladder.m * ladder.g), p),
    ];
    let f_p = xy(&coordinate_force(&ladder.m, &motion.a));
    // Only where P accelerates: a point at rest has no coordinate force (exactly zero by AD).
    if f_p != (0.0, 0.0) {
        arrows.push(arrow(&format!("F_{name}"), pos(Corner::B), f_p, p));
    }
    Diagram {
        point: name.into(),
        p,
        corners: Corner::ALL.iter().map(|&k| (k.name(), pos(k))).collect(),
        arrows,
        state: (st.sin.atan2(st.cos), st.rate, st.accel),
        mass_length: (ladder.m, ladder.l),
    }
}

/// Metres of arrow per newton in the drawing.
pub fn arrow_scale(d: &Diagram) -> f64 {
    let biggest = d
        .arrows
        .iter()
        .map(|a| a.force.0.hypot(a.force.1))
        .fold(0.0, f64::max);
    if biggest > 0.0 {
        1.0 / biggest
    } else {
        1.0
    }
}

/// The drawing's window in metres: (x0, x1, y0, y1).
pub fn window(d: &Diagram) -> (f64, f64, f64, f64) {
    let s = arrow_scale(d);
    let mut pts: Vec<(f64, f64)> = d.corners.iter().map(|c| c.1).collect();
    for a in &d.arrows {
        pts.push(a.at);
        pts.push((a.at.0 + s * a.force.0, a.at.1 + s * a.force.1));
    }
    pts.push(d.p);
    let (mut x0, mut x1, mut y0, mut y1) = (-0.3f64, 0.3f64, -0.3f64, 0.3f64);
    for (x, y) in pts {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    let pad = 0.25 * (x1 - x0).max(y1 - y0);
    // Equal scales on both axes: a square window.
    let half = 0.5 * (x1 - x0).max(y1 - y0) + pad;
    let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    (cx - half, cx + half, cy - half, cy + half)
}

/// Pixel size of the square drawing (the legend is to its right).
pub const SIDE: u32 = 600;

/// Where a point (m) lands in pixels of the drawing area (plotters' own mapping, 0-based).
pub fn to_px(d: &Diagram, q: (f64, f64)) -> (i32, i32) {
    let (x0, x1, y0, y1) = window(d);
    let side = f64::from(SIDE);
    (
        ((q.0 - x0) / (x1 - x0) * side).round() as i32,
        ((y1 - q.1) / (y1 - y0) * side).round() as i32,
    )
}

/// Draw the diagram as SVG text.
pub fn draw_svg(d: &Diagram) -> Result<String, String> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (SIDE + 420, SIDE)).into_drawing_area();
        let e =
            |x: &dyn std::fmt::Display| format!("cannot draw the diagram about {}: {x}", d.point);
        root.fill(&WHITE).map_err(|x| e(&x))?;
        let (left, right) = root.split_horizontally(SIDE);
        let (x0, x1, y0, y1) = window(d);
        let mut chart = ChartBuilder::on(&left)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(|x| e(&x))?;
        let grey = RGBColor(120, 120, 120);
        let line = |pts: Vec<(f64, f64)>, style: ShapeStyle| PathElement::new(pts, style);
        // Wall and floor.
        chart
            .draw_series([
                line(vec![(0.0, 0.0), (0.0, y1)], BLACK.stroke_width(3)),
                line(vec![(0.0, 0.0), (x1, 0.0)], BLACK.stroke_width(3)),
            ])
            .map_err(|x| e(&x))?;
        let at = |n: &str| {
            d.corners
                .iter()
                .find(|c| c.0 == n)
                .map_or((0.0, 0.0), |c| c.1)
        };
        // The rectangle A-D-E-C, thin, and the ladder C-D, thick.
        chart
            .draw_series([line(vec![at("D"), at("E"), at("C")], grey.stroke_width(1))])
            .map_err(|x| e(&x))?;
        chart
            .draw_series([line(
                vec![at("C"), at("D")],
                RGBColor(140, 86, 75).stroke_width(6),
            )])
            .map_err(|x| e(&x))?;
        for (n, q) in &d.corners {
            chart
                .draw_series([Circle::new(*q, 4, BLACK.filled())])
                .map_err(|x| e(&x))?;
            chart
                .draw_series([Text::new(
                    n.to_string(),
                    (q.0 - 0.12, q.1 + 0.04),
                    ("sans-serif", 20),
                )])
                .map_err(|x| e(&x))?;
        }
        chart
            .draw_series([Circle::new(d.p, 7, RED.stroke_width(2))])
            .map_err(|x| e(&x))?;
        let s = arrow_scale(d);
        let colors = [
            RGBColor(31, 119, 180),
            RGBColor(44, 160, 44),
            RGBColor(0, 0, 0),
            RGBColor(214, 39, 40),
        ];
        for (i, a) in d.arrows.iter().enumerate() {
            let c = colors[i % colors.len()];
            let tip = (a.at.0 + s * a.force.0, a.at.1 + s * a.force.1);
            // Shaft, then a head of two short strokes at ±25° back from the tip.
            chart
                .draw_series([line(vec![a.at, tip], c.stroke_width(3))])
                .map_err(|x| e(&x))?;
            let (dx, dy) = (tip.0 - a.at.0, tip.1 - a.at.1);
            let len = dx.hypot(dy);
            if len > 0.0 {
                let h = 0.08 * (x1 - x0) / 3.0;
                for ang in [0.44f64, -0.44] {
                    let (ca, sa) = (ang.cos(), ang.sin());
                    let back = (
                        -(dx * ca - dy * sa) / len * h,
                        -(dx * sa + dy * ca) / len * h,
                    );
                    chart
                        .draw_series([line(
                            vec![tip, (tip.0 + back.0, tip.1 + back.1)],
                            c.stroke_width(3),
                        )])
                        .map_err(|x| e(&x))?;
                }
            }
            chart
                .draw_series([Text::new(
                    format!("{} = {:.2} N", a.symbol, a.force.0.hypot(a.force.1)),
                    // Left-pointing arrows get their label below the tip, clear of the ladder.
                    if a.force.0 < 0.0 {
                        (tip.0 - 0.05, tip.1 - 0.08)
                    } else {
                        (tip.0 + 0.04, tip.1 + 0.04)
                    },
                    ("sans-serif", 16).into_font().color(&c),
                )])
                .map_err(|x| e(&x))?;
            // Lever arm: dashed from P to the foot of the perpendicular on the line of action.
            if len > 0.0 && a.arm > 1e-12 {
                let u = (a.force.0 / len * s, a.force.1 / len * s);
                let t = (d.p.0 - a.at.0) * u.0 + (d.p.1 - a.at.1) * u.1;
                let foot = (a.at.0 + t * u.0, a.at.1 + t * u.1);
                let dashes = 14;
                let seg: Vec<_> = (0..dashes)
                    .filter(|k| k % 2 == 0)
                    .map(|k| {
                        let f = |j: usize| {
                            let w = j as f64 / dashes as f64;
                            (d.p.0 + w * (foot.0 - d.p.0), d.p.1 + w * (foot.1 - d.p.1))
                        };
                        line(vec![f(k), f(k + 1)], c.mix(0.7).stroke_width(1))
                    })
                    .collect();
                chart.draw_series(seg).map_err(|x| e(&x))?;
                // The line of action itself, faint, through the foot.
                chart
                    .draw_series([line(vec![a.at, foot], c.mix(0.3).stroke_width(1))])
                    .map_err(|x| e(&x))?;
            }
        }
        // Legend: the state and, per force, its value, arm and torque about P.
        let (th, rate, acc) = d.state;
        let mut lines = vec![
            format!("Torque analysis about {}", d.point),
            format!(
                "θ = {:.1}°, θ̇ = {} s⁻¹, θ̈ = {} s⁻² (m = {} kg, l = {} m)",
                th.to_degrees(),
                n3(rate),
                n3(acc),
                d.mass_length.0,
                d.mass_length.1
            ),
            String::new(),
        ];
        for a in &d.arrows {
            lines.push(format!(
                "{}: ({}, {}) N at ({}, {}) m",
                a.symbol,
                n3(a.force.0),
                n3(a.force.1),
                n3(a.at.0),
                n3(a.at.1)
            ));
            lines.push(format!(
                "      arm about {} {} m, torque {} N·m",
                d.point,
                n3(a.arm),
                n3(a.torque)
            ));
        }
        lines.push(String::new());
        lines.push(format!(
            "total torque about {}: {} N·m",
            d.point,
            n3(d.arrows.iter().map(|a| a.torque).sum::<f64>())
        ));
        lines.push("dashed: lever arm from the red circle (P)".into());
        for (k, t) in lines.iter().enumerate() {
            right
                .draw(&Text::new(
                    t.clone(),
                    (10, 20 + 24 * k as i32),
                    ("sans-serif", 17),
                ))
                .map_err(|x| e(&x))?;
        }
        root.present().map_err(|x| e(&x))?;
    }
    Ok(svg)
}
