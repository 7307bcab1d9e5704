//! The legend column of a force diagram's SVG ([`super::diagram_svg`]): the state, each force
//! with its components, point, lever arm and torque about P, and the total torque. Kept apart
//! from the drawing so that each file has one job.

use super::diagram::{arm_symbol, Diagram};
use super::svg_text::{esc, n3, FORCE_COLOURS};
use std::fmt::Write;

/// The legend column: the state, each force with its arm and torque about P, the total.
pub(super) fn legend(out: &mut String, d: &Diagram, left: f64) {
    let (th, rate, acc) = d.state;
    let x = left + 10.0;
    let mut y = 28.0;
    let mut put = |out: &mut String, text: &str, colour: &str, size: u32, dy: f64| {
        let _ = writeln!(
            out,
            "<text x=\"{x:.1}\" y=\"{y:.1}\" font-size=\"{size}\" fill=\"{colour}\">{}</text>",
            esc(text)
        );
        y += dy;
    };
    put(
        out,
        &format!("Torque analysis about {} (red ring)", d.point),
        "black",
        18,
        26.0,
    );
    put(
        out,
        &format!(
            "θ = {:.1}°, θ̇ = {} s⁻¹, θ̈ = {} s⁻²",
            th.to_degrees(),
            n3(rate),
            n3(acc)
        ),
        "black",
        15,
        20.0,
    );
    put(
        out,
        &format!("m = {} kg, l = {} m", d.mass_length.0, d.mass_length.1),
        "black",
        15,
        if d.description.is_some() { 20.0 } else { 30.0 },
    );
    if let Some(what) = &d.description {
        put(out, what, "#D00", 15, 20.0);
        put(
            out,
            &format!("at ({}, {}) m", n3(d.p.0), n3(d.p.1)),
            "#D00",
            15,
            30.0,
        );
    }
    for (i, a) in d.arrows.iter().enumerate() {
        let colour = FORCE_COLOURS[i % FORCE_COLOURS.len()];
        put(
            out,
            &format!(
                "{} = ({}, {}) N at ({}, {}) m",
                a.symbol,
                n3(a.force.0),
                n3(a.force.1),
                n3(a.at.0),
                n3(a.at.1)
            ),
            colour,
            15,
            20.0,
        );
        let arm = match arm_symbol(d, a) {
            Some(s) => format!("{s} = {}", n3(a.arm)),
            None => n3(a.arm),
        };
        put(
            out,
            &format!(
                "    arm {arm} m, torque about {} {} N·m",
                d.point,
                n3(a.torque)
            ),
            colour,
            15,
            28.0,
        );
    }
    put(
        out,
        &format!(
            "total torque about {}: {} N·m",
            d.point,
            n3(d.arrows.iter().map(|a| a.torque).sum::<f64>())
        ),
        "black",
        15,
        30.0,
    );
    put(
        out,
        "arrows: forces to scale; dashed: lever arm from P,",
        "#444",
        14,
        18.0,
    );
    put(
        out,
        "perpendicular to the dotted line of action;",
        "#444",
        14,
        18.0,
    );
    put(
        out,
        "torque > 0 turns counter-clockwise (+ẑ)",
        "#444",
        14,
        18.0,
    );
}
