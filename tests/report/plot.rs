//! Tests of `sliding_ladder::report::plot` (src/report/plot.rs).

use sliding_ladder::report::plot::{zero_crossings, PlotSpec, Series};
use sliding_ladder::report::svg_chart::document;
use sliding_ladder::report::svg_chart::{decade_label, Axis};

#[test]
fn decades_are_labelled_as_powers_of_ten() {
    assert_eq!(decade_label(-12), "10⁻¹²");
    assert_eq!(decade_label(0), "10⁰");
    assert_eq!(decade_label(3), "10³");
    let a = Axis::fit([3e-13, 2e-4, -1.0, 0.0].into_iter(), true);
    assert_eq!((a.lo, a.hi), (-13.0, -3.0));
    let labels: Vec<&str> = a.ticks.iter().map(|t| t.1.as_str()).collect();
    assert_eq!(labels, ["10⁻¹²", "10⁻¹⁰", "10⁻⁸", "10⁻⁶", "10⁻⁴"]);
    assert_eq!(a.map(-1.0), None);
}

#[test]
fn linear_ticks_are_round_and_cover_the_data() {
    let a = Axis::fit([0.13, 2.71].into_iter(), false);
    assert!(a.lo < 0.13 && a.hi > 2.71);
    let v: Vec<f64> = a.ticks.iter().map(|t| t.0).collect();
    assert_eq!(v, [0.5, 1.0, 1.5, 2.0, 2.5]);
    assert_eq!(a.ticks[0].1, "0.5");
}

#[test]
fn coordinates_are_not_rounded_to_pixels_and_the_legend_sits_outside_the_data() {
    let s = vec![Series {
        name: "a".into(),
        points: vec![(0.0, 0.0), (1.0, 1.0 / 3.0), (2.0, 1.0)],
    }];
    let svg = document(&[(PlotSpec::default().into(), s)], 960.0, 600.0);
    let poly = svg.split("points=\"").nth(1).unwrap();
    assert!(
        poly.split(['"', ' ', ','])
            .take(6)
            .any(|c| c.contains('.') && !c.ends_with(".00")),
        "{poly}"
    );
    assert_eq!(svg.matches("font-weight=\"bold\"").count(), 1, "one title");
}

#[test]
fn a_force_that_changes_sign_is_found_between_its_samples() {
    let z = zero_crossings(&[(0.0, 2.0), (1.0, 1.0), (2.0, -1.0), (3.0, -2.0)]);
    assert_eq!(z, vec![1.5]);
    assert!(zero_crossings(&[(0.0, 1.0), (1.0, 2.0)]).is_empty());
}
