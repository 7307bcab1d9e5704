//! The legend of the force diagrams as a teacher reads it (issue 16, item 2): the total torque
//! about P set beside the model's dL'_P/dt, equal on the motion and not off it (the law of
//! motion, shown), and a slanted force's torque split into the two terms the note writes ((28)).

use sliding_ladder::docs::worked::example_state;
use sliding_ladder::ladder::analysis::Reference;
use sliding_ladder::ladder::geometry::Corner;
use sliding_ladder::report::diagram::svg::draw_svg;
use sliding_ladder::report::diagram::{component_torques, diagram, Diagram};
use sliding_ladder::report::svg_text::n3;
use sliding_ladder::report::svg_text::plain;

fn about(k: Corner) -> Diagram {
    let (ladder, st) = example_state(true);
    diagram(k.name(), &Reference::Corner(k), &ladder, &st)
}

/// The size of the terms of the total torque about P, for its rounding bound: Σ |r| |F|.
fn torque_size(d: &Diagram) -> f64 {
    d.arrows
        .iter()
        .map(|a| (a.at.0 - d.p.0).hypot(a.at.1 - d.p.1) * a.force.0.hypot(a.force.1))
        .sum()
}

#[test]
fn the_legend_sets_the_total_torque_beside_the_rate_of_angular_momentum_on_the_motion_only() {
    let (_, off) = example_state(false);
    let (ladder, _) = example_state(true);
    for k in Corner::ALL {
        // On the motion the law holds: Σ torques = dL'_P/dt (by AD of the particle model), to
        // the rounding of the sum's terms (a few ulps of Σ |r| |F| and of the rate's size).
        let d = about(k);
        let total: f64 = d.arrows.iter().map(|a| a.torque).sum();
        let bound = 16.0 * f64::EPSILON * (torque_size(&d) + d.angular_momentum_rate.abs());
        assert!(
            (total - d.angular_momentum_rate).abs() <= bound,
            "about {k:?}: total {total} against dL/dt {}",
            d.angular_momentum_rate
        );
        let svg = draw_svg(&d);
        assert!(
            svg.contains(&format!("{:.4} N·m</text>", d.angular_momentum_rate).replace('-', "−")),
            "about {k:?}: the legend does not give dL/dt"
        );
        // Off the motion (θ̈ = 0, same θ, θ̇) the same figure shows the law failing: the rate
        // is I θ̈-like and the torques are not, so they differ by far more than rounding.
        let d = diagram(k.name(), &Reference::Corner(k), &ladder, &off);
        let total: f64 = d.arrows.iter().map(|a| a.torque).sum();
        assert!(
            (total - d.angular_momentum_rate).abs() > 1e6 * f64::EPSILON * torque_size(&d),
            "about {k:?} off the motion: total {total} equals dL/dt {}",
            d.angular_momentum_rate
        );
    }
}

#[test]
fn the_coordinate_force_about_e_is_split_into_the_two_terms_of_28() {
    // (28), corrected: the torque of F_E about E is F_E,x l cos θ − F_E,y l sin θ (the print's
    // form 3 drops the first). The legend gives both terms, and they add up to the torque.
    let d = about(Corner::E);
    let f_e = d.arrows.iter().find(|a| a.symbol == "F_E").unwrap();
    let [x, y] = component_torques(&d, f_e).expect("F_E is slanted");
    let (th, l) = (d.state.0, d.mass_length.1);
    assert_eq!(
        (x.1.as_str(), x.2, y.1.as_str(), y.2),
        ("F_E,x", 1.0, "F_E,y", -1.0)
    );
    let close = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * (a.abs() + b.abs());
    assert!(close(x.0, f_e.force.0 * l * th.cos()) && close(y.0, -f_e.force.1 * l * th.sin()));
    assert!(
        close(x.0 + y.0, f_e.torque),
        "{} + {} against {}",
        x.0,
        y.0,
        f_e.torque
    );
    let svg = draw_svg(&d);
    assert!(
        svg.contains("<tspan dy=\"4.5\" font-size=\"11\">E,x</tspan>"),
        "F_E,x is not typeset with its subscript"
    );
    let line = format!(
        "= F_E,x·l cos θ − F_E,y·l sin θ = {} − {}",
        n3(x.0),
        n3(-y.0)
    );
    assert!(plain(&svg).contains(&line), "no '{line}' in the legend");
    // A force along an axis, or through P, has one term and no split.
    for k in Corner::ALL {
        let d = about(k);
        for a in d
            .arrows
            .iter()
            .filter(|a| a.force.0 == 0.0 || a.force.1 == 0.0 || a.arm == 0.0)
        {
            assert!(
                component_torques(&d, a).is_none(),
                "{} about {k:?}",
                a.symbol
            );
        }
    }
}
