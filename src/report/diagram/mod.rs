//! Force diagrams: the ladder at a stated state with every force the torque analysis about a
//! reference point P uses, and the lever arm of each about P (the note's lost figure, sec. 2).
//!
//! [`diagram`] computes the arrows from the model: the wall force F_w (14) at C along +x, the
//! floor force F_f (15) at D along +y, gravity −mg ŷ at B, and, where P accelerates, the
//! coordinate force F_P = −m a_P (17) at the centre of mass, with a_P by automatic
//! differentiation of P's position. For each arrow it gives the lever arm about P (the distance
//! from P to the line of action), in the note's symbols where it is one of them
//! ([`arm_symbol`]), and the torque (x_Q − x_P) × F about P; and, beside their sum, the rate
//! dL'_P/dt of the model's angular momentum, so that the figure shows the law of motion holding
//! (or, off the motion, failing). [`super::diagram::svg`] draws it.

pub(super) mod legend;
pub mod marks;
pub mod svg;

use crate::ladder::analysis::{torque_equation, AngularMomentum, ReferencePoint};
use crate::ladder::forces::{floor_force, wall_force};
use crate::ladder::geometry::{corner_position, Corner};
use crate::ladder::torque::coordinate_force;
use crate::ladder::{Ladder, State};

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
    /// What P is, when it is not one of A-E (for the legend).
    pub description: Option<String>,
    /// dL'_P/dt of the particle model, by automatic differentiation (L'_P of (39), which is L_P
    /// when P is at rest), N·m: the left side of the torque law (40), which the total torque
    /// equals on the motion and not off it.
    pub angular_momentum_rate: f64,
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
        description: None,
        angular_momentum_rate: torque_equation(point, AngularMomentum::Relative, ladder, st).0,
    }
}

/// Metres of arrow per newton in the drawing: the largest force is drawn 0.75 l long.
pub fn arrow_scale(d: &Diagram) -> f64 {
    let biggest = d
        .arrows
        .iter()
        .map(|a| a.force.0.hypot(a.force.1))
        .fold(0.0, f64::max);
    if biggest > 0.0 {
        0.75 * d.mass_length.1 / biggest
    } else {
        1.0
    }
}

/// The drawing's window in metres, (x0, x1, y0, y1): the points, P, every arrow and the
/// acceleration of P, with a
/// margin for the labels (more on the left, where the point labels and the wall's hatching go).
pub fn window(d: &Diagram) -> (f64, f64, f64, f64) {
    let s = arrow_scale(d);
    let mut pts: Vec<(f64, f64)> = d.corners.iter().map(|c| c.1).collect();
    for a in &d.arrows {
        pts.push(a.at);
        pts.push((a.at.0 + s * a.force.0, a.at.1 + s * a.force.1));
        // The acceleration of P is drawn at P, m a_P long: the coordinate force turned round.
        if a.symbol == format!("F_{}", d.point) {
            pts.push((d.p.0 - s * a.force.0, d.p.1 - s * a.force.1));
        }
    }
    pts.push(d.p);
    let (mut x0, mut x1, mut y0, mut y1) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for (x, y) in pts {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    let pad = 0.12 * (x1 - x0).max(y1 - y0);
    (x0 - 1.6 * pad, x1 + 1.6 * pad, y0 - pad, y1 + pad)
}

/// Height of the drawing, px (its width follows at equal scales; the legend is to its right).
pub const SIDE: f64 = 600.0;

/// Width of the drawing, px, at the scale that makes its height [`SIDE`].
pub fn drawing_width(d: &Diagram) -> f64 {
    let (x0, x1, y0, y1) = window(d);
    (x1 - x0) / (y1 - y0) * SIDE
}

/// Where a point (m) lands in pixels of the drawing, as floats (y grows downwards; one scale
/// for both axes, so right angles stay right).
pub fn to_px(d: &Diagram, q: (f64, f64)) -> (f64, f64) {
    let (x0, _, y0, y1) = window(d);
    let k = SIDE / (y1 - y0);
    ((q.0 - x0) * k, (y1 - q.1) * k)
}

/// The lever arm of `a` about P in the note's symbols, when it is one of the arms the note
/// names (0, l sin θ, l cos θ, 2l sin θ, 2l cos θ): the symbol whose value at the diagram's
/// state equals the computed arm to rounding. `None` for another arm (the coordinate force
/// about E, which is neither horizontal nor vertical).
pub fn arm_symbol(d: &Diagram, a: &Arrow) -> Option<&'static str> {
    length_symbol(d, a.arm)
}

/// A length (m) in the note's symbols (0, l sin θ, l cos θ, 2l sin θ, 2l cos θ), when it is one
/// of them at the diagram's state, to rounding.
pub fn length_symbol(d: &Diagram, length: f64) -> Option<&'static str> {
    let (th, l) = (d.state.0, d.mass_length.1);
    let (s, c) = (th.sin(), th.cos());
    let candidates = [
        ("0", 0.0),
        ("l sin θ", l * s),
        ("l cos θ", l * c),
        ("2l sin θ", 2.0 * l * s),
        ("2l cos θ", 2.0 * l * c),
    ];
    candidates
        .iter()
        .find(|(_, v)| (length - v).abs() <= 1e-12 * (1.0 + l))
        .map(|(n, _)| *n)
}

/// The torque of a slanted force (both components nonzero, not through P) split by
/// components, as the note writes such torques ((28)): (x_Q − x_P) F_y − (y_Q − y_P) F_x, each
/// term as (its value, the component's symbol "F_E,x", the sign it carries, the arm's length).
/// `None` for a force along x or y, or through P, whose torque is one term already.
pub fn component_torques(d: &Diagram, a: &Arrow) -> Option<[(f64, String, f64, f64); 2]> {
    let r = (a.at.0 - d.p.0, a.at.1 - d.p.1);
    if a.force.0 == 0.0 || a.force.1 == 0.0 || a.arm <= 1e-12 || r.0 == 0.0 || r.1 == 0.0 {
        return None;
    }
    // The x component's torque is −(y_Q − y_P) F_x, the y component's (x_Q − x_P) F_y.
    Some([
        (
            -r.1 * a.force.0,
            format!("{},x", a.symbol),
            -r.1.signum(),
            r.1.abs(),
        ),
        (
            r.0 * a.force.1,
            format!("{},y", a.symbol),
            r.0.signum(),
            r.0.abs(),
        ),
    ])
}
