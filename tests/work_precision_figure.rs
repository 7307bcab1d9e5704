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
