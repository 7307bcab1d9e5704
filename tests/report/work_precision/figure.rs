//! The work-precision figure's peers (issue 12, item 3): a peer series is drawn dashed, with
//! markers, in the colour of the method it compares with; without the pairing it would take a
//! colour of its own and no markers when dashed.

use sliding_ladder::report::chart::{Chart, Series};
use sliding_ladder::report::svg_chart::{chart_svg, PALETTE};

fn series(name: &str, k: f64) -> Series {
    Series {
        name: name.into(),
        points: vec![(1e-6 * k, 1e-4), (2e-6 * k, 1e-8), (4e-6 * k, 1e-12)],
    }
}

/// The polylines of the data: (stroke colour, dashed).
fn lines(svg: &str) -> Vec<(String, bool)> {
    svg.split("<polyline")
        .skip(1)
        .map(|p| {
            let tag = &p[..p.find("/>").unwrap()];
            let colour = tag.split("stroke=\"").nth(1).unwrap()[..7].to_string();
            (colour, tag.contains("stroke-dasharray"))
        })
        .collect()
}

#[test]
fn a_peer_is_dashed_in_its_partners_colour_with_markers() {
    let data = vec![
        series("dopri5", 1.0),
        series("dop853", 2.0),
        series("ode_solvers-dop853", 3.0),
    ];
    let base = Chart {
        log_x: true,
        log_y: true,
        markers: true,
        ..Default::default()
    };
    let paired = Chart {
        peers: vec![("ode_solvers-dop853".into(), "dop853".into())],
        ..base.clone()
    };
    let svg = chart_svg(&paired, &data, 640.0, 420.0, "t");
    let l = lines(&svg);
    assert_eq!(l.len(), 3);
    assert_eq!(l[2], (PALETTE[1].to_string(), true), "{l:?}");
    assert_eq!(l[1], (PALETTE[1].to_string(), false));
    // Markers: dop853's shape (index 1: squares) for its 3 points, the peer's 3 and the peer's
    // legend entry, plus dop853's legend entry.
    assert_eq!(svg.matches("width=\"6\" height=\"6\"").count(), 8);
    // Unpaired, the same series is solid in a colour of its own.
    let l = lines(&chart_svg(&base, &data, 640.0, 420.0, "t"));
    assert_eq!(l[2], (PALETTE[2].to_string(), false));
}

#[test]
fn the_pareto_front_is_a_grey_staircase_under_the_data_without_markers() {
    use sliding_ladder::report::svg_chart::FRONT;
    use sliding_ladder::report::work_precision::report::staircase;
    // Across to the next run's time, then down to its error: the boundary of what it dominates.
    let front = staircase(vec![(4e-6, 1e-12), (1e-6, 1e-4), (2e-6, 1e-8)]);
    assert_eq!(
        front,
        [
            (1e-6, 1e-4),
            (2e-6, 1e-4),
            (2e-6, 1e-8),
            (4e-6, 1e-8),
            (4e-6, 1e-12)
        ]
    );
    let data = vec![
        series("dop853", 1.0),
        Series {
            name: "Pareto front".into(),
            points: front,
        },
    ];
    let chart = Chart {
        log_x: true,
        log_y: true,
        markers: true,
        front: Some("Pareto front".into()),
        ..Default::default()
    };
    let svg = chart_svg(&chart, &data, 640.0, 420.0, "t");
    let l = lines(&svg);
    // Drawn first (under the methods), grey, solid; the method keeps the first colour.
    assert_eq!(
        l,
        [(FRONT.to_string(), false), (PALETTE[0].to_string(), false)]
    );
    // Markers: the method's 3 points and its legend entry only.
    assert_eq!(svg.matches("<circle").count(), 4);
    // Without the option the same series is one more method, with markers.
    let plain = Chart {
        front: None,
        ..chart
    };
    let svg = chart_svg(&plain, &data, 640.0, 420.0, "t");
    assert_eq!(lines(&svg)[1], (PALETTE[1].to_string(), false));
    assert_eq!(svg.matches("width=\"6\" height=\"6\"").count(), 6);
}
