//! Force diagrams (issue 16, item 2): one per reference point A-E, drawn from the model at the
//! worked example's state, committed under equations/figures/ and embedded in each section.
//! The arrows must be the forces of an independent model (the three particles' Newton's law and
//! −m a_P by automatic differentiation of P's position), the SVG must draw them where they are,
//! and the committed files must be exactly what the code draws
//! (`LADDER_BLESS_DOCS=1 cargo test --test report diagram::figures` redraws them).

use sliding_ladder::docs::default_dir;
use sliding_ladder::docs::worked::example_state;
use sliding_ladder::ladder::analysis::{Reference, ReferencePoint};
use sliding_ladder::ladder::geometry::{corner_position, Corner};
use sliding_ladder::ladder::particles::{
    as_system, floor_force_from_motion, wall_force_from_motion,
};
use sliding_ladder::report::diagram::svg::draw_svg;
use sliding_ladder::report::diagram::{arm_symbol, arrow_scale, diagram, to_px, window, Diagram};
use sliding_ladder::report::svg_text::n3;
use sliding_ladder::report::svg_text::plain;

fn about(k: Corner) -> Diagram {
    let (ladder, st) = example_state(true);
    diagram(k.name(), &Reference::Corner(k), &ladder, &st)
}

/// A line of the SVG: its `data-symbol` and its two ends in px.
type Line = (String, (f64, f64), (f64, f64));

/// Every `<line class="{class}" data-symbol="S" x1 y1 x2 y2>` of the SVG.
fn lines(svg: &str, class: &str) -> Vec<Line> {
    let attr = |el: &str, name: &str| -> Option<String> {
        Some(
            el.split(&format!(" {name}=\""))
                .nth(1)?
                .split('"')
                .next()?
                .to_string(),
        )
    };
    svg.split("<line")
        .skip(1)
        .filter(|el| attr(el, "class").as_deref() == Some(class))
        .filter_map(|el| {
            let f = |n: &str| attr(el, n)?.parse::<f64>().ok();
            Some((
                attr(el, "data-symbol")?,
                (f("x1")?, f("y1")?),
                (f("x2")?, f("y2")?),
            ))
        })
        .collect()
}

/// The `data-offset` (px) of the arm labelled `symbol` that starts at `from`.
fn offset(svg: &str, symbol: &str, from: (f64, f64)) -> (f64, f64) {
    for el in svg.split("<line").skip(1) {
        let get = |n: &str| {
            el.split(&format!(" {n}=\""))
                .nth(1)
                .and_then(|r| r.split('"').next())
                .map(str::to_string)
        };
        let x1: Option<f64> = get("x1").and_then(|v| v.parse().ok());
        let y1: Option<f64> = get("y1").and_then(|v| v.parse().ok());
        if get("class").as_deref() == Some("arm")
            && get("data-symbol").as_deref() == Some(symbol)
            && x1.zip(y1).is_some_and(|q| same(q, from))
        {
            let o = get("data-offset").expect("an arm says its offset");
            let (a, b) = o.split_once(',').expect("x,y");
            return (a.parse().unwrap(), b.parse().unwrap());
        }
    }
    (0.0, 0.0)
}

/// Two points in px agree to the SVG's two decimals.
fn same(p: (f64, f64), q: (f64, f64)) -> bool {
    (p.0 - q.0).abs() <= 0.006 && (p.1 - q.1).abs() <= 0.006
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
        let svg = draw_svg(&d);
        let shafts = lines(&svg, "force");
        let s = arrow_scale(&d);
        for a in &d.arrows {
            let (from, to) = (
                to_px(&d, a.at),
                to_px(&d, (a.at.0 + s * a.force.0, a.at.1 + s * a.force.1)),
            );
            assert!(
                shafts
                    .iter()
                    .any(|(sym, p, q)| sym == &a.symbol && same(*p, from) && same(*q, to)),
                "about {k:?}: no shaft for {} from {from:?} to {to:?}",
                a.symbol
            );
            // The legend states the force's components as the model has them.
            let row = format!("{} = ({}, {}) N", a.symbol, n3(a.force.0), n3(a.force.1));
            assert!(
                plain(&svg).contains(&row),
                "about {k:?}: no legend row '{row}'"
            );
        }
        // A wrong force would not be found: lengthen F_w by 1 % and look for its shaft.
        let f = &d.arrows[0];
        let wrong = to_px(&d, (f.at.0 + 1.01 * s * f.force.0, f.at.1));
        assert!(!shafts
            .iter()
            .any(|(_, p, q)| same(*p, to_px(&d, f.at)) && same(*q, wrong)));
    }
}

#[test]
fn each_lever_arm_is_drawn_from_p_at_right_angles_to_its_force_with_its_length() {
    for k in Corner::ALL {
        let d = about(k);
        let svg = draw_svg(&d);
        let arms = lines(&svg, "arm");
        let p = to_px(&d, d.p);
        let (x0, _, y0, y1) = window(&d);
        let px_per_m = to_px(&d, (x0 + 1.0, y0)).0 - to_px(&d, (x0, y1)).0;
        for a in d.arrows.iter().filter(|a| a.arm > 1e-12) {
            // Some dashed arm from P is perpendicular to this force and as long as its arm.
            // An arm drawn beside its true place (a dimension line) says by how much: the
            // shift is at right angles to the arm and at most 3 levels of 11 px.
            let found = arms.iter().any(|(sym, from, to)| {
                let v = (to.0 - from.0, to.1 - from.1);
                let len = v.0.hypot(v.1);
                // The force in px: y flips.
                let (fx, fy) = (a.force.0, -a.force.1);
                let cos = (v.0 * fx + v.1 * fy) / (len * fx.hypot(fy));
                let o = offset(&svg, sym, *from);
                let along = (o.0 * v.0 + o.1 * v.1).abs() / len;
                same((from.0 - o.0, from.1 - o.1), p)
                    && along < 0.01
                    && o.0.hypot(o.1) <= 33.01
                    && cos.abs() < 1e-4
                    && (len / px_per_m - a.arm).abs() < 1e-4
            });
            assert!(
                found,
                "about {k:?}: no lever arm for {} ({} m)",
                a.symbol, a.arm
            );
        }
        // A zero arm is not drawn: about its own point of action a force has none.
        assert!(d.arrows.iter().all(|a| a.arm > 1e-12) || arms.len() < d.arrows.len());
    }
}

#[test]
fn the_arms_carry_the_notes_symbols() {
    // The arms the note's text names in each analysis (sec. 2.2-2.6; the book's sections say
    // the same): gravity l sin θ about A, D and E; the wall force 2l cos θ about A and D,
    // l cos θ about B; the floor force 2l sin θ about A and C, l sin θ about B; the coordinate
    // force l sin θ about C, l cos θ about D (about E it is neither horizontal nor vertical).
    let expected: &[(Corner, &str, Option<&str>)] = &[
        (Corner::A, "m g", Some("l sin θ")),
        (Corner::A, "F_w", Some("2l cos θ")),
        (Corner::A, "F_f", Some("2l sin θ")),
        (Corner::B, "F_w", Some("l cos θ")),
        (Corner::B, "F_f", Some("l sin θ")),
        (Corner::B, "m g", Some("0")),
        (Corner::C, "F_f", Some("2l sin θ")),
        (Corner::C, "m g", Some("l sin θ")),
        (Corner::C, "F_C", Some("l sin θ")),
        (Corner::C, "F_w", Some("0")),
        (Corner::D, "F_w", Some("2l cos θ")),
        (Corner::D, "m g", Some("l sin θ")),
        (Corner::D, "F_D", Some("l cos θ")),
        (Corner::D, "F_f", Some("0")),
        (Corner::E, "m g", Some("l sin θ")),
        (Corner::E, "F_w", Some("0")),
        (Corner::E, "F_f", Some("0")),
        (Corner::E, "F_E", None),
    ];
    for &(k, sym, want) in expected {
        let d = about(k);
        let a = d.arrows.iter().find(|a| a.symbol == sym).unwrap();
        assert_eq!(arm_symbol(&d, a), want, "arm of {sym} about {k:?}");
        if let Some(w) = want.filter(|w| *w != "0") {
            assert!(
                draw_svg(&d).contains(&format!(">{w}</text>")),
                "about {k:?}: the arm {w} is not labelled"
            );
        }
    }
    // A wrong arm gets no symbol: 10 % longer than l sin θ.
    let mut d = about(Corner::A);
    d.arrows[2].arm *= 1.1;
    assert_eq!(arm_symbol(&d, &d.arrows[2]), None);
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
        let svg = draw_svg(&about(k));
        if std::env::var_os("LADDER_BLESS_DOCS").is_some() {
            std::fs::write(&path, &svg).expect("write figure");
        }
        let committed = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(
            committed == svg,
            "{}: redraw with LADDER_BLESS_DOCS=1 cargo test --test report diagram::figures",
            path.display()
        );
        let page = std::fs::read_to_string(dir.join(file)).expect("section");
        assert!(
            page.contains(&format!("(figures/{name})")),
            "{file} does not embed {name}"
        );
    }
}

#[test]
fn ladder_diagram_draws_the_books_figures_and_any_point() {
    let run = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
            .arg("diagram")
            .args(args)
            .output()
            .expect("runs")
    };
    // At the default state (the worked example) the command draws the book's figure.
    let a = run(&["--about", "A"]);
    assert_eq!(a.status.code(), Some(0));
    let committed = std::fs::read_to_string(default_dir().join("figures/forces-a.svg")).unwrap();
    assert_eq!(String::from_utf8_lossy(&a.stdout), committed);
    // A point of the ladder a quarter of the way from C: its coordinate force is −m a_P with
    // a_P = (3/4) a_C + (1/4) a_D, from the corners' own motions.
    let p = run(&["--about", "ladder:1/4", "--at", "m=2, theta=40deg"]);
    assert_eq!(p.status.code(), Some(0));
    let svg = String::from_utf8_lossy(&p.stdout);
    let (ladder, st) = {
        let at = sliding_ladder::show::at::parse_at("m=2, theta=40deg").unwrap();
        sliding_ladder::show::state::build(&at).float
    };
    let acc = |k| Reference::Corner(k).motion(&ladder, &st).a;
    let (ac, ad) = (acc(Corner::C), acc(Corner::D));
    let f = (
        -ladder.m * (0.75 * ac.x + 0.25 * ad.x),
        -ladder.m * (0.75 * ac.y + 0.25 * ad.y),
    );
    let row = format!("F_P = ({}, {}) N", n3(f.0), n3(f.1));
    assert!(
        plain(&svg).contains(&row),
        "no '{row}' in the diagram about ladder:1/4"
    );
    assert!(svg.contains("the point of the ladder 1/4 of the way from C to D"));
    // A point fixed in the lab has no coordinate force.
    let lab = run(&["--about", "lab:1/2,1"]);
    assert_eq!(lab.status.code(), Some(0));
    assert!(!String::from_utf8_lossy(&lab.stdout).contains("F_P"));
    // Bad input: exit 2 and one line on stderr, nothing on stdout.
    for bad in [
        &["--about", "Z"][..],
        &["--about", "ladder:3/2"],
        &["--at", "m=-1"],
    ] {
        let out = run(bad);
        assert_eq!(out.status.code(), Some(2), "{bad:?}");
        assert_eq!(
            String::from_utf8_lossy(&out.stderr).lines().count(),
            1,
            "{bad:?}"
        );
        assert!(out.stdout.is_empty(), "{bad:?}");
    }
}
