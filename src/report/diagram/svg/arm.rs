//! The lever arms of a force diagram: each a dashed perpendicular from P to a force's line of
//! action (dotted), with a right-angle mark at its foot and its symbol or length beside it.

use super::{label, line};
use crate::report::diagram::{arm_symbol, to_px, Arrow, Diagram};
use crate::report::svg_text::{esc, n3, FORCE_COLOURS};
use std::fmt::Write;

/// The lever arm of a force about P: dashed from P to the foot of the perpendicular on the
/// line of action, the line of action dotted from the point of the force to the foot, and the
/// arm's symbol and length beside it (on alternate sides, `side` = ±1, so that arms along the
/// same line keep their labels apart). An arm that would lie on the floor, the wall, a line of
/// action or another arm is drawn as a dimension line `shift` px beside its true place
/// (`data-offset` gives the shift), with thin extension lines from P and from the foot.
fn lever_arm(out: &mut String, d: &Diagram, a: &Arrow, colour: &str, side: f64, shift: f64) {
    let Some(foot) = foot(d, a) else {
        return;
    };
    let (p0, f0, q) = (to_px(d, d.p), to_px(d, foot), to_px(d, a.at));
    line(
        out,
        q,
        f0,
        &format!("stroke=\"{colour}\" stroke-opacity=\"0.45\" stroke-width=\"1.2\" stroke-dasharray=\"2 3\""),
    );
    let n = arm_normal(p0, f0);
    let o = (shift * n.0, shift * n.1);
    let (p, f) = ((p0.0 + o.0, p0.1 + o.1), (f0.0 + o.0, f0.1 + o.1));
    if shift != 0.0 {
        for (from, to) in [(p0, p), (f0, f)] {
            line(
                out,
                from,
                to,
                &format!("stroke=\"{colour}\" stroke-width=\"0.8\""),
            );
        }
    }
    let side = if shift != 0.0 { shift.signum() } else { side };
    let _ = writeln!(
        out,
        "<line class=\"arm\" data-symbol=\"{}\" data-offset=\"{:.2},{:.2}\" x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" stroke=\"{colour}\" stroke-width=\"1.6\" stroke-dasharray=\"7 4\"/>",
        esc(&a.symbol),
        o.0,
        o.1,
        p.0,
        p.1,
        f.0,
        f.1
    );
    // A small square at the foot marks the right angle.
    let (vx, vy) = (
        (f.0 - p.0) / (f.0 - p.0).hypot(f.1 - p.1),
        (f.1 - p.1) / (f.0 - p.0).hypot(f.1 - p.1),
    );
    right_angle(out, f, (vx, vy), colour);
    let text = match arm_symbol(d, a) {
        Some(sym) => sym.to_string(),
        None => format!("{} m", n3(a.arm)),
    };
    let (at, anchor) = label_place(d, (p, f), (vx, vy), (side, shift), &text);
    label(out, at, anchor, colour, 14, &text);
}

/// The small square at the foot `f` of an arm along the unit vector `v` that marks the right
/// angle.
fn right_angle(out: &mut String, f: (f64, f64), (vx, vy): (f64, f64), colour: &str) {
    let k = 7.0;
    let c1 = (f.0 - k * vx, f.1 - k * vy);
    let c2 = (c1.0 + k * vy, c1.1 - k * vx);
    let c3 = (f.0 + k * vy, f.1 - k * vx);
    let _ = writeln!(
        out,
        "<polyline points=\"{:.2},{:.2} {:.2},{:.2} {:.2},{:.2}\" fill=\"none\" stroke=\"{colour}\" stroke-width=\"1\"/>",
        c1.0, c1.1, c2.0, c2.1, c3.0, c3.1
    );
}

/// Where the label `text` of the arm from `p` to `f` (px, unit vector `v`) goes, and its
/// anchor, for an arm on `side` shifted by `shift` px.
fn label_place(
    d: &Diagram,
    (p, f): ((f64, f64), (f64, f64)),
    (vx, vy): (f64, f64),
    (side, shift): (f64, f64),
    text: &str,
) -> ((f64, f64), &'static str) {
    // Along the arm: at 60 % of it on one side, 40 % on the other, so that labels of arms on
    // one line from P, and a line of action that crosses an arm's middle, stay clear; where
    // that place would put the label on the ladder, the next of a few others that does not.
    let place = |w: f64, side: f64| {
        let mid = (p.0 + w * (f.0 - p.0), p.1 + w * (f.1 - p.1));
        let normal = (-vy * side, vx * side);
        // Beside a mostly vertical arm the label starts (or ends) a little off the line;
        // elsewhere it is centred above or below it.
        if normal.0.abs() > 0.7 {
            (
                (mid.0 + 8.0 * normal.0.signum(), mid.1 + 5.0),
                if normal.0 > 0.0 { "start" } else { "end" },
            )
        } else {
            (
                (mid.0 + 14.0 * normal.0, mid.1 + 14.0 * normal.1 + 4.0),
                "middle",
            )
        }
    };
    // Arms stacked beside one line (levels 1, 2, ...) take their labels at different places.
    let level = (shift.abs() / 11.0).round() as usize;
    let w = match (level, side > 0.0) {
        (0, true) => 0.6,
        (0, false) => 0.4,
        (l, _) if l % 2 == 1 => 0.75,
        _ => 0.3,
    };
    let tries = [
        (w, side),
        (0.25, side),
        (0.8, side),
        (w, -side),
        (0.25, -side),
    ];
    tries
        .iter()
        .map(|&(w, s)| place(w, s))
        .find(|(at, anchor)| clear_of_ladder(d, *at, anchor, text))
        .unwrap_or_else(|| place(w, side))
}

/// True when a label of `text` (14 px type, about 8 px a character) at `at` with `anchor`
/// keeps 6 px from the ladder C–D.
fn clear_of_ladder(d: &Diagram, at: (f64, f64), anchor: &str, text: &str) -> bool {
    let corner = |n: &str| d.corners.iter().find(|c| c.0 == n).map(|c| to_px(d, c.1));
    let (Some(c), Some(dd)) = (corner("C"), corner("D")) else {
        return true;
    };
    let w = 8.0 * text.chars().count() as f64;
    let x0 = match anchor {
        "end" => at.0 - w,
        "middle" => at.0 - w / 2.0,
        _ => at.0,
    };
    let (seg, len2) = (
        (dd.0 - c.0, dd.1 - c.1),
        (dd.0 - c.0).powi(2) + (dd.1 - c.1).powi(2),
    );
    let dist = |q: (f64, f64)| {
        let t = (((q.0 - c.0) * seg.0 + (q.1 - c.1) * seg.1) / len2).clamp(0.0, 1.0);
        (q.0 - c.0 - t * seg.0).hypot(q.1 - c.1 - t * seg.1)
    };
    // The box's corners and the middles of its long sides, 14 px high above the baseline.
    let pts = [0.0, 0.5, 1.0]
        .iter()
        .flat_map(|k| [(x0 + k * w, at.1 + 3.0), (x0 + k * w, at.1 - 12.0)]);
    pts.map(dist).fold(f64::INFINITY, f64::min) > 6.0 + 4.0
}
/// The unit normal (−v_y, v_x) of the arm from `p` to `f`, px.
fn arm_normal(p: (f64, f64), f: (f64, f64)) -> (f64, f64) {
    let len = (f.0 - p.0).hypot(f.1 - p.1);
    (-(f.1 - p.1) / len, (f.0 - p.0) / len)
}

/// The shift (px along [`arm_normal`]) of the arm of `a` to its foot `f`, the `along`-th arm on
/// its ray from P: none for an arm in the clear; 11 px per level for one that lies on the floor
/// or the wall (into the room), on a force's line of action, or on an earlier arm's ray.
fn arm_shift(d: &Diagram, a: &Arrow, f: (f64, f64), along: usize) -> f64 {
    let tiny = 1e-9 * (d.mass_length.1 + d.p.0.abs() + d.p.1.abs());
    let on_floor = d.p.1.abs() < tiny && f.1.abs() < tiny;
    let on_wall = d.p.0.abs() < tiny && f.0.abs() < tiny;
    let through = |b: &Arrow, q: (f64, f64)| {
        let r = (q.0 - b.at.0, q.1 - b.at.1);
        (r.0 * b.force.1 - r.1 * b.force.0).abs() <= tiny * b.force.0.hypot(b.force.1)
    };
    let on_force = d
        .arrows
        .iter()
        .any(|b| b.symbol != a.symbol && b.force != (0.0, 0.0) && through(b, d.p) && through(b, f));
    let level = along + usize::from(on_floor || on_wall || on_force);
    if level == 0 {
        return 0.0;
    }
    let n = arm_normal(to_px(d, d.p), to_px(d, f));
    let sign = if on_floor {
        -n.1.signum()
    } else if on_wall {
        n.0.signum()
    } else if along % 2 == 0 {
        1.0
    } else {
        -1.0
    };
    11.0 * level as f64 * sign
}

/// The foot of the perpendicular from P on the line of action of `a` (m); `None` when the arm
/// is zero (the line passes through P) or the force is.
pub fn foot(d: &Diagram, a: &Arrow) -> Option<(f64, f64)> {
    let size = a.force.0.hypot(a.force.1);
    if size == 0.0 || a.arm <= 1e-12 {
        return None;
    }
    let u = (a.force.0 / size, a.force.1 / size);
    let t = (d.p.0 - a.at.0) * u.0 + (d.p.1 - a.at.1) * u.1;
    Some((a.at.0 + t * u.0, a.at.1 + t * u.1))
}

/// Every lever arm, under the arrows. Two forces with the same foot share one arm (drawn
/// once); arms along one line from P take alternate sides for their labels.
pub(super) fn lever_arms(out: &mut String, d: &Diagram) {
    let mut drawn: Vec<(f64, f64)> = Vec::new();
    let mut directions: Vec<(f64, f64)> = Vec::new();
    for (i, a) in d.arrows.iter().enumerate() {
        let Some(f) = foot(d, a) else { continue };
        if drawn
            .iter()
            .any(|g| (g.0 - f.0).abs() + (g.1 - f.1).abs() < 1e-9)
        {
            continue;
        }
        let dir = ((f.0 - d.p.0) / a.arm, (f.1 - d.p.1) / a.arm);
        let along = directions
            .iter()
            .filter(|g| (g.0 - dir.0).abs() + (g.1 - dir.1).abs() < 1e-9)
            .count();
        lever_arm(
            out,
            d,
            a,
            FORCE_COLOURS[i % FORCE_COLOURS.len()],
            if along % 2 == 0 { 1.0 } else { -1.0 },
            arm_shift(d, a, f, along),
        );
        drawn.push(f);
        directions.push(dir);
    }
}
