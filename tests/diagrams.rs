//! Force diagrams (issue 16, item 2): one per reference point A-E, drawn from the model at the
//! worked example's state, committed under equations/figures/ and embedded in each section.
//! The arrows must be the forces of an independent model (the three particles' Newton's law and
//! −m a_P by automatic differentiation of P's position), the SVG must draw them where they are,
//! and the committed files must be exactly what the code draws
//! (`LADDER_BLESS_DOCS=1 cargo test --test diagrams` redraws them).

use sliding_ladder::docs::default_dir;
use sliding_ladder::docs::worked::example_state;
use sliding_ladder::ladder::analysis::{Reference, ReferencePoint};
use sliding_ladder::ladder::geometry::{corner_position, Corner};
use sliding_ladder::ladder::particles::{
    as_system, floor_force_from_motion, wall_force_from_motion,
};
use sliding_ladder::report::diagram::{diagram, draw_svg, to_px, Diagram};

fn about(k: Corner) -> Diagram {
    let (ladder, st) = example_state(true);
    diagram(k.name(), &Reference::Corner(k), &ladder, &st)
}

/// The endpoints of every `<polyline>` with two points in the SVG, in pixels.
fn segments(svg: &str) -> Vec<((i32, i32), (i32, i32))> {
    svg.split("<polyline")
        .skip(1)
        .filter_map(|el| {
            let pts = el.split("points=\"").nth(1)?.split('"').next()?;
            let p: Vec<(i32, i32)> = pts
                .split_whitespace()
                .filter_map(|xy| {
                    let (x, y) = xy.split_once(',')?;
                    Some((x.parse().ok()?, y.parse().ok()?))
                })
                .collect();
            (p.len() == 2).then(|| (p[0], p[1]))
        })
        .collect()
}

#[test]
fn the_arrows_are_the_models_forces_at_the_stated_state() {
    let (ladder, st) = example_state(true);
    let sys = as_system(&ladder, &st);
    let (f_w, f_f) = (
        wall_force_from_motion(&sys),
        floor_force_from_motion(&ladder, &sys),
    );
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * (1.0 + b.abs());
    for k in Corner::ALL {
        let d = about(k);
        let get = |s: &str| {
            d.arrows
                .iter()
                .find(|a| a.symbol == s)
                .unwrap_or_else(|| panic!("{s} about {k:?}"))
        };
        let pos = |c| {
            let v = corner_position(c, &ladder, &st);
            (v.x, v.y)
        };
        assert!(close(get("F_w").force.0, f_w) && get("F_w").force.1 == 0.0);
        assert_eq!(get("F_w").at, pos(Corner::C));
        assert!(close(get("F_f").force.1, f_f) && get("F_f").force.0 == 0.0);
        assert_eq!(get("F_f").at, pos(Corner::D));
        assert!(close(get("m g").force.1, -ladder.m * ladder.g));
        // The coordinate force −m a_P at the centre of mass exactly where P accelerates (not A).
        let a_p = Reference::Corner(k).motion(&ladder, &st).a;
        let coord = d
            .arrows
            .iter()
            .find(|a| a.symbol == format!("F_{}", k.name()));
        match k {
            Corner::A => assert!(coord.is_none() && a_p.x == 0.0 && a_p.y == 0.0),
            _ => {
                let c = coord.expect("a coordinate force");
                assert!(close(c.force.0, -ladder.m * a_p.x) && close(c.force.1, -ladder.m * a_p.y));
                assert_eq!(c.at, pos(Corner::B));
            }
        }
        // Torques about P add up to the right side of the torque law (40): τ_P + (x_cm − x_P) × (−m a_P).
        let total: f64 = d.arrows.iter().map(|a| a.torque).sum();
        let (_, rhs) = sliding_ladder::ladder::analysis::torque_equation(
            &Reference::Corner(k),
            sliding_ladder::ladder::analysis::AngularMomentum::Relative,
            &ladder,
            &st,
        );
        assert!(close(total, rhs), "about {k:?}: {total} against {rhs}");
        // Each arm is the distance from P to the line of action, |r × F|/|F|.
        for a in &d.arrows {
            let r = (a.at.0 - d.p.0, a.at.1 - d.p.1);
            let f = a.force.0.hypot(a.force.1);
            assert!(
                close(a.arm * f, (r.0 * a.force.1 - r.1 * a.force.0).abs()),
                "{}",
                a.symbol
            );
        }
    }
}

#[test]
fn the_svg_draws_each_arrow_where_the_model_puts_it() {
    for k in Corner::ALL {
        let d = about(k);
        let svg = draw_svg(&d).expect("draws");
        let segs = segments(&svg);
        let s = sliding_ladder::report::diagram::arrow_scale(&d);
        for a in &d.arrows {
            let (from, to) = (
                to_px(&d, a.at),
                to_px(&d, (a.at.0 + s * a.force.0, a.at.1 + s * a.force.1)),
            );
            let near =
                |p: (i32, i32), q: (i32, i32)| (p.0 - q.0).abs() <= 2 && (p.1 - q.1).abs() <= 2;
            assert!(
                segs.iter().any(|&(p, q)| near(p, from) && near(q, to)),
                "about {k:?}: no shaft for {} from {from:?} to {to:?}",
                a.symbol
            );
            assert!(svg.contains(&format!(
                "{} = {:.2} N",
                a.symbol,
                a.force.0.hypot(a.force.1)
            )));
        }
        // A wrong force would not be found: shift F_w by 10 % and look for its shaft.
        let f = &d.arrows[0];
        let wrong = to_px(&d, (f.at.0 + 1.1 * s * f.force.0, f.at.1));
        assert!(!segs
            .iter()
            .any(|&(p, q)| p == to_px(&d, f.at) && q == wrong));
    }
}

#[test]
fn the_committed_figures_are_what_the_code_draws_and_each_section_embeds_its_own() {
    let dir = default_dir();
    let sections = [
        (Corner::A, "02-point-a.md"),
        (Corner::B, "03-point-b.md"),
        (Corner::C, "04-point-c.md"),
        (Corner::D, "05-point-d.md"),
        (Corner::E, "06-point-e.md"),
    ];
    for (k, file) in sections {
        let name = format!("forces-{}.svg", k.name().to_lowercase());
        let path = dir.join("figures").join(&name);
        let svg = draw_svg(&about(k)).expect("draws");
        if std::env::var_os("LADDER_BLESS_DOCS").is_some() {
            std::fs::write(&path, &svg).expect("write figure");
        }
        let committed = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(
            committed == svg,
            "{}: redraw with LADDER_BLESS_DOCS=1 cargo test --test diagrams",
            path.display()
        );
        let page = std::fs::read_to_string(dir.join(file)).expect("section");
        assert!(
            page.contains(&format!("(figures/{name})")),
            "{file} does not embed {name}"
        );
    }
}
