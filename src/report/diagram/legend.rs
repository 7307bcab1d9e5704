//! The legend column of a force diagram's SVG ([`crate::report::diagram::svg`]): the state, each force
//! with its components, point, lever arm and torque about P, and the total torque. Kept apart
//! from the drawing so that each file has one job.

use crate::report::diagram::{arm_symbol, component_torques, length_symbol, Diagram};
use crate::report::svg_text::{n3, subscript, FORCE_COLOURS};
use std::fmt::Write;

/// The legend's column of lines: where the next one goes.
struct Column {
    x: f64,
    y: f64,
}

impl Column {
    /// A line of `text` at `size` px, then `dy` px down to the next.
    fn put(&mut self, out: &mut String, text: &str, colour: &str, size: u32, dy: f64) {
        let (x, y) = (self.x, self.y);
        let _ = writeln!(
            out,
            "<text x=\"{x:.1}\" y=\"{y:.1}\" font-size=\"{size}\" fill=\"{colour}\" xml:space=\"preserve\">{}</text>",
            subscript(text, size)
        );
        self.y += dy;
    }
}

/// The legend column: the state, each force with its arm and torque about P, the total.
pub(in crate::report) fn legend(out: &mut String, d: &Diagram, left: f64) {
    let mut col = Column {
        x: left + 10.0,
        y: 28.0,
    };
    state_lines(&mut col, out, d);
    force_lines(&mut col, out, d);
    totals_and_key(&mut col, out, d);
}

/// The heading, the state θ, θ̇, θ̈, m and l, and where P is when it is not a corner.
fn state_lines(col: &mut Column, out: &mut String, d: &Diagram) {
    let (th, rate, acc) = d.state;
    col.put(
        out,
        &format!("Torque analysis about {} (red ring)", d.point),
        "black",
        18,
        26.0,
    );
    col.put(
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
    col.put(
        out,
        &format!("m = {} kg, l = {} m", d.mass_length.0, d.mass_length.1),
        "black",
        15,
        if d.description.is_some() { 20.0 } else { 30.0 },
    );
    if let Some(what) = &d.description {
        col.put(out, what, "#D00", 15, 20.0);
        col.put(
            out,
            &format!("at ({}, {}) m", n3(d.p.0), n3(d.p.1)),
            "#D00",
            15,
            30.0,
        );
    }
}

/// Each force: its components and point, its arm and torque about P (by components when it is
/// slanted), and for the coordinate force the acceleration it stands for.
fn force_lines(col: &mut Column, out: &mut String, d: &Diagram) {
    for (i, a) in d.arrows.iter().enumerate() {
        let colour = FORCE_COLOURS[i % FORCE_COLOURS.len()];
        col.put(
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
        let split = component_torques(d, a);
        col.put(
            out,
            &format!(
                "    arm {arm} m, torque about {} {} N·m",
                d.point,
                n3(a.torque)
            ),
            colour,
            15,
            if split.is_some() { 20.0 } else { 28.0 },
        );
        if let Some(terms) = split {
            col.put(out, &by_components(d, &terms), colour, 15, 28.0);
        }
        if a.symbol == format!("F_{}", d.point) {
            if let Some(words) = super::marks::acceleration_words(d) {
                col.put(out, &format!("    {words}"), colour, 14, 24.0);
            }
        }
    }
}

/// The total torque, the model's dL/dt, and the key to the drawing.
fn totals_and_key(col: &mut Column, out: &mut String, d: &Diagram) {
    col.put(
        out,
        &format!(
            "total torque about {}: {} N·m",
            d.point,
            n4(d.arrows.iter().map(|a| a.torque).sum::<f64>())
        ),
        "black",
        15,
        20.0,
    );
    col.put(
        out,
        &format!(
            "dL{}_{}/dt of the model (AD): {} N·m",
            // About the fixed corner the two angular momenta of (37) and (39) are one, L_A.
            if d.point == "A" { "" } else { "′" },
            d.point,
            n4(d.angular_momentum_rate)
        ),
        "black",
        15,
        30.0,
    );
    col.put(
        out,
        "arrows: forces to scale; dashed: lever arm from P,",
        "#444",
        14,
        18.0,
    );
    col.put(
        out,
        "perpendicular to the dotted line of action;",
        "#444",
        14,
        18.0,
    );
    col.put(
        out,
        "torque > 0 turns counter-clockwise (+ẑ);",
        "#444",
        14,
        18.0,
    );
    col.put(
        out,
        "the law of motion: total torque = dL/dt, on the motion only",
        "#444",
        14,
        18.0,
    );
}

/// A slanted force's torque by components, as (28) writes the coordinate force's about E:
/// "= F_E,x·l cos θ − F_E,y·l sin θ = −3.811 − 3.547".
fn by_components(d: &Diagram, terms: &[(f64, String, f64, f64); 2]) -> String {
    let mut symbols = String::from("    =");
    let mut values = String::from(" =");
    for (i, (value, component, sign, arm)) in terms.iter().enumerate() {
        let arm = length_symbol(d, *arm).map_or_else(|| format!("{} m", n3(*arm)), str::to_string);
        let op = match (i, *sign < 0.0) {
            (0, true) => " −",
            (0, false) => "",
            (_, true) => " −",
            (_, false) => " +",
        };
        symbols.push_str(&format!("{op} {component}·{arm}"));
        values.push_str(&format!(
            "{} {}",
            if i == 0 {
                ""
            } else if *value < 0.0 {
                " −"
            } else {
                " +"
            },
            n3(if i == 0 { *value } else { value.abs() })
        ));
    }
    symbols + &values
}

/// Four decimals with a true minus sign (the book's worked examples print the same sums so:
/// −2ml²θ̈/3 = −2.4525 at their state, which three decimals round to a tie).
fn n4(x: f64) -> String {
    let s = format!("{x:.4}");
    if s == "-0.0000" {
        "0.0000".into()
    } else {
        s.replace('-', "−")
    }
}
