//! The figures of a fall (`ladder simulate --out`): the force chart marks the separation, the
//! flat landing and F_w crossing zero, and the crossing found in the plotted samples lies at
//! the separation the simulator located (within the trace's sampling); the curves are drawn
//! with float coordinates; the work-precision chart has real log axes with decade labels.

use sliding_ladder::report::fall_figures::files;
use sliding_ladder::report::files::Content;
use sliding_ladder::report::plot::{zero_crossings, Chart};
use sliding_ladder::report::svg_chart::document;
use sliding_ladder::sim::{fall, scene};
use std::path::Path;

fn chart_of(name: &str) -> (Chart, Vec<sliding_ladder::report::plot::Series>) {
    let sc = scene::load(Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/full-fall.toml"
    )))
    .unwrap();
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    let f = files(&sc, &o)
        .into_iter()
        .find(|f| f.name == name)
        .expect(name);
    match f.content {
        Content::Chart(c, s) => (c, s),
        _ => panic!("{name} is not a chart"),
    }
}

#[test]
fn the_force_chart_marks_separation_flat_and_the_wall_force_reaching_zero() {
    let (chart, series) = chart_of("forces_t.svg");
    let at = |what: &str| {
        chart
            .marks
            .iter()
            .find(|m| m.label.starts_with(what))
            .unwrap_or_else(|| panic!("no {what} mark: {:?}", chart.marks))
            .x
    };
    let (sep, flat, zero) = (at("separation"), at("flat"), at("F_w = 0"));
    assert!(sep < flat, "separation {sep} before flat {flat}");
    // The step between samples bounds how far the sampled crossing can be from the event.
    let fw = &series[0].points;
    let dt = fw.windows(2).map(|w| w[1].0 - w[0].0).fold(0.0, f64::max);
    assert!(
        (zero - sep).abs() <= dt,
        "F_w = 0 at {zero}, separation at {sep}, sampling {dt}"
    );
    // Before the separation the wall pushes (F_w > 0).
    assert!(fw.iter().filter(|p| p.0 < sep - dt).all(|p| p.1 > 0.0));
    let svg = document(&[(chart, series)], 960.0, 600.0);
    assert!(
        svg.contains("separation, t = ") && svg.contains("F_w = 0") && svg.contains("flat, t = ")
    );
}

#[test]
fn a_moved_event_or_a_force_that_never_changes_sign_is_seen() {
    let (chart, series) = chart_of("forces_t.svg");
    let sep = chart.marks[0].x;
    // Shift the wall force so that it stays positive: no crossing is found.
    let lifted: Vec<(f64, f64)> = series[0]
        .points
        .iter()
        .filter(|p| p.0 < sep)
        .map(|p| (p.0, p.1 + 1.0))
        .collect();
    assert!(zero_crossings(&lifted).is_empty());
    // Shifted by a quarter of the run, the crossing moves away from the separation.
    let shifted: Vec<(f64, f64)> = series[0]
        .points
        .iter()
        .map(|p| (p.0 - 0.25 * sep, p.1))
        .collect();
    let z = zero_crossings(&shifted)[0];
    assert!((z - sep).abs() > 0.2 * sep);
}

#[test]
fn the_trajectory_is_drawn_with_float_coordinates() {
    let (chart, series) = chart_of("trajectory.svg");
    assert!(chart.marks.len() == 2 && !chart.log_x && !chart.log_y);
    let svg = document(&[(chart, series)], 960.0, 600.0);
    let pts = svg
        .split("points=\"")
        .nth(1)
        .unwrap()
        .split('"')
        .next()
        .unwrap();
    let fractional = pts
        .split([' ', ','])
        .filter(|c| !c.ends_with(".00"))
        .count();
    assert!(
        fractional > pts.split([' ', ',']).count() / 2,
        "coordinates look rounded: {}",
        &pts[..80]
    );
}

/// Each chart of a fall says where it starts (issue 39: "the fall plots do not say θ0"): the
/// scene's θ0 = 0.3 rad, from rest; a chart of another start says its own θ0.
#[test]
fn every_fall_chart_says_its_theta0() {
    for name in ["trajectory.svg", "forces_t.svg", "forces_theta.svg"] {
        let (chart, _) = chart_of(name);
        assert!(
            chart
                .spec
                .title
                .contains("from rest at θ0 = 0.300 rad (17.19°)"),
            "{name}: {}",
            chart.spec.title
        );
    }
    let mut sc = scene::load(Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/full-fall.toml"
    )))
    .unwrap();
    sc.theta0 = 0.5;
    assert!(sliding_ladder::report::fall_figures::start_words(&sc).contains("θ0 = 0.500 rad"));
}
