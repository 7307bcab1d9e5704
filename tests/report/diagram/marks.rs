//! The diagrams' marks that explain (issue 39): the acceleration a_P drawn at P, opposite to the
//! coordinate force −m a_P and as long, where P accelerates (not about A, which is at rest); the
//! sense of θ̇ round B, counter-clockwise while θ grows; and no lever arm drawn on the floor, the
//! wall or a force's line of action (about D the floor force and two arms shared one line, and
//! gravity's arm lay on the floor). Shown able to fail: the arms moved back to their true places
//! (the drawing before this change) are caught about A, C and D. The direction of a_P is also
//! held to each corner's acceleration differentiated by hand from its position, and a wrong
//! reference (another corner's, or its own reversed) is caught.

use sliding_ladder::ladder::analysis::Reference;
use sliding_ladder::ladder::geometry::Corner;
use sliding_ladder::ladder::{Ladder, State};
use sliding_ladder::report::diagram::svg::draw_svg;
use sliding_ladder::report::diagram::{diagram, to_px, Diagram};

/// The worked example's state: θ = 30° from rest upright, m = l = 1, g = 9.81.
fn about(k: Corner) -> Diagram {
    let (m, l, g, th) = (1.0f64, 1.0f64, 9.81f64, 30f64.to_radians());
    let w2 = 0.75 * g / l;
    let rate = (2.0 * w2 * (1.0 - th.cos())).sqrt();
    let st = State {
        sin: th.sin(),
        cos: th.cos(),
        rate,
        accel: w2 * th.sin(),
        jerk: w2 * th.cos() * rate,
    };
    diagram(k.name(), &Reference::Corner(k), &Ladder { m, l, g }, &st)
}

/// A line's ends (x1, y1, x2, y2), px.
type Ends = (f64, f64, f64, f64);

/// Every `<line class="{class}">` with its `data-offset` (0, 0 if none).
fn lines(svg: &str, class: &str) -> Vec<(Ends, (f64, f64))> {
    svg.split("<line")
        .skip(1)
        .filter(|el| el.contains(&format!("class=\"{class}\"")))
        .map(|el| {
            let get = |n: &str| -> Option<String> {
                el.split(&format!(" {n}=\""))
                    .nth(1)?
                    .split('"')
                    .next()
                    .map(str::to_string)
            };
            let f = |n: &str| get(n).and_then(|v| v.parse::<f64>().ok()).unwrap();
            let o = get("data-offset").map_or((0.0, 0.0), |o| {
                let (a, b) = o.split_once(',').unwrap();
                (a.parse().unwrap(), b.parse().unwrap())
            });
            ((f("x1"), f("y1"), f("x2"), f("y2")), o)
        })
        .collect()
}

/// Arms (as drawn) lying on the floor, the wall or a force's line of action, as messages.
fn arms_on_lines(d: &Diagram, arms: &[Ends]) -> Vec<String> {
    let floor = to_px(d, (0.0, 0.0));
    let mut lines: Vec<((f64, f64), (f64, f64))> = vec![(floor, (1.0, 0.0)), (floor, (0.0, 1.0))];
    for a in d.arrows.iter().filter(|a| a.force != (0.0, 0.0)) {
        let n = a.force.0.hypot(a.force.1);
        lines.push((to_px(d, a.at), (a.force.0 / n, -a.force.1 / n)));
    }
    let mut out = Vec::new();
    for (i, &(x1, y1, x2, y2)) in arms.iter().enumerate() {
        for (k, (q, u)) in lines.iter().enumerate() {
            let off = |x: f64, y: f64| ((x - q.0) * u.1 - (y - q.1) * u.0).abs();
            if off(x1, y1) < 0.5 && off(x2, y2) < 0.5 {
                out.push(format!("arm {i} lies on line {k}"));
            }
        }
    }
    out
}

#[test]
fn no_arm_lies_on_the_floor_the_wall_or_a_line_of_action_and_the_old_drawing_is_caught() {
    let mut caught = 0;
    for k in Corner::ALL {
        let d = about(k);
        let drawn = lines(&draw_svg(&d), "arm");
        let as_drawn: Vec<_> = drawn.iter().map(|x| x.0).collect();
        let p = arms_on_lines(&d, &as_drawn);
        assert!(p.is_empty(), "about {k:?}: {p:?}");
        // The arms put back where they were before (no offset): about A, C and D they lay on
        // the floor, the wall or a line of action.
        let back: Vec<_> = drawn
            .iter()
            .map(|((x1, y1, x2, y2), o)| (x1 - o.0, y1 - o.1, x2 - o.0, y2 - o.1))
            .collect();
        if !arms_on_lines(&d, &back).is_empty() {
            caught += 1;
        }
    }
    assert!(
        caught >= 3,
        "the old drawing was caught about {caught} points only"
    );
}

#[test]
fn a_p_is_drawn_at_p_opposite_to_the_coordinate_force_and_theta_dot_turns_counter_clockwise() {
    for k in Corner::ALL {
        let d = about(k);
        let svg = draw_svg(&d);
        let acc = lines(&svg, "acceleration");
        let own = d
            .arrows
            .iter()
            .find(|a| a.symbol == format!("F_{}", k.name()));
        match own {
            None => assert!(acc.is_empty(), "about {k:?}: a_P drawn for a point at rest"),
            Some(f) => {
                assert_eq!(acc.len(), 1, "about {k:?}");
                let ((x1, y1, x2, y2), _) = acc[0];
                let p = to_px(&d, d.p);
                assert!(
                    (x1 - p.0).abs() < 0.01 && (y1 - p.1).abs() < 0.01,
                    "about {k:?}"
                );
                // a_P in px (y down) against F_P = −m a_P: opposite, and m a_P as long.
                let s = sliding_ladder::report::diagram::arrow_scale(&d);
                let px = to_px(&d, (d.p.0 - s * f.force.0, d.p.1 - s * f.force.1));
                assert!(
                    (x2 - px.0).abs() < 0.01 && (y2 - px.1).abs() < 0.01,
                    "about {k:?}: a_P tip at ({x2}, {y2}), −F_P/m at {px:?}"
                );
            }
        }
        // θ̇ > 0 at this state: counter-clockwise.
        assert!(
            svg.contains("class=\"rotation\" data-sense=\"counter-clockwise\""),
            "about {k:?}"
        );
    }
}

/// The acceleration of a corner at the worked example's state, from its position (B = (l sin θ,
/// l cos θ), C = (0, 2l cos θ), D = (2l sin θ, 0), E = (2l sin θ, 2l cos θ)) differentiated twice
/// by hand: independent of the model the diagram draws from.
fn closed_form_acceleration(k: Corner) -> (f64, f64) {
    let (l, g, th) = (1.0f64, 9.81f64, 30f64.to_radians());
    let w2 = 0.75 * g / l;
    let rate2 = 2.0 * w2 * (1.0 - th.cos());
    let accel = w2 * th.sin();
    let (s, c) = (th.sin(), th.cos());
    // d²/dt² (l sin θ) and d²/dt² (l cos θ).
    let (ax, ay) = (l * (c * accel - s * rate2), -l * (s * accel + c * rate2));
    match k {
        Corner::A => (0.0, 0.0),
        Corner::B => (ax, ay),
        Corner::C => (0.0, 2.0 * ay),
        Corner::D => (2.0 * ax, 0.0),
        Corner::E => (2.0 * ax, 2.0 * ay),
    }
}

/// Whether the drawn arrow `(x1, y1, x2, y2)` (px, y down) points along `a`: the ends are printed
/// to 0.01 px, so the sine of the angle between them is at most 2 · 0.005 √2 / length (doubled).
fn points_along(arrow: Ends, a: (f64, f64)) -> bool {
    let (x1, y1, x2, y2) = arrow;
    let (dx, dy) = (x2 - x1, y1 - y2);
    let (len, norm) = (dx.hypot(dy), a.0.hypot(a.1));
    let (cos, sin) = (
        (dx * a.0 + dy * a.1) / (len * norm),
        (dx * a.1 - dy * a.0) / (len * norm),
    );
    cos > 0.0 && sin.abs() <= 4.0 * 0.005 * std::f64::consts::SQRT_2 / len
}

#[test]
fn a_p_points_along_the_closed_form_acceleration_of_each_corner() {
    for k in [Corner::B, Corner::C, Corner::D, Corner::E] {
        let svg = draw_svg(&about(k));
        let acc = lines(&svg, "acceleration");
        assert_eq!(acc.len(), 1, "about {k:?}");
        assert!(
            points_along(acc[0].0, closed_form_acceleration(k)),
            "about {k:?}: a_P drawn along {:?}, the closed form is {:?}",
            acc[0].0,
            closed_form_acceleration(k)
        );
    }
    // A wrong reference fails: D's arrow against C's acceleration, and against its own reversed.
    let d = lines(&draw_svg(&about(Corner::D)), "acceleration")[0].0;
    assert!(!points_along(d, closed_form_acceleration(Corner::C)));
    let (ax, ay) = closed_form_acceleration(Corner::D);
    assert!(!points_along(d, (-ax, -ay)));
}
