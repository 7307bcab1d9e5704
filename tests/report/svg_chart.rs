//! Two properties of the figures' SVG (issue 12, item 3): a figure of several panels draws one
//! legend for all of them, with each method in the same colour in every panel; and a dense trace
//! is thinned to what its pixels can show without losing an extreme.

use sliding_ladder::report::chart::{Chart, Series};
use sliding_ladder::report::svg_chart::{document, thin, PALETTE};

fn series(name: &str, k: f64) -> Series {
    Series {
        name: name.into(),
        points: vec![(1e-6 * k, 1e-4), (2e-6 * k, 1e-8), (4e-6 * k, 1e-12)],
    }
}

/// The stroke colour of each data polyline, in drawing order.
fn strokes(svg: &str) -> Vec<String> {
    svg.split("<polyline")
        .skip(1)
        .map(|p| p.split("stroke=\"").nth(1).unwrap()[..7].to_string())
        .collect()
}

#[test]
fn panels_share_one_legend_and_keep_each_methods_colour() {
    let chart = Chart {
        log_x: true,
        log_y: true,
        markers: true,
        ..Default::default()
    };
    let a = vec![series("dopri5", 1.0), series("dop853", 2.0)];
    // The second panel lists the methods the other way round and adds one.
    let b = vec![
        series("dop853", 2.0),
        series("dopri5", 1.0),
        series("taylor", 0.5),
    ];
    let svg = document(
        &[(chart.clone(), a.clone()), (chart.clone(), b)],
        700.0,
        460.0,
    );
    for name in ["dopri5", "dop853", "taylor"] {
        let n = svg.matches(&format!(">{name}</text>")).count();
        assert_eq!(n, 1, "{name} has {n} legend entries");
    }
    let s = strokes(&svg);
    assert_eq!(
        s,
        [PALETTE[0], PALETTE[1], PALETTE[1], PALETTE[0], PALETTE[2]]
    );
    // The legend lies below both panels (it would otherwise hide a panel's data).
    let at = svg.find(">taylor</text>").unwrap();
    let y: f64 = svg[..at]
        .rsplit("y=\"")
        .next()
        .unwrap()
        .split('"')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(y > 460.0, "legend entry at y = {y}");
    // One panel alone keeps its legend column beside the plot.
    let one = document(&[(chart, a)], 960.0, 600.0);
    assert_eq!(one.matches(">dop853</text>").count(), 1);
    assert!(one.contains("height=\"600\""));
}

#[test]
fn a_dense_trace_is_thinned_without_losing_its_extremes() {
    // 1e5 samples of a fast oscillation across 800 px, with one spike a single sample wide.
    let n = 100_000;
    let mut pts: Vec<(f64, f64)> = (0..n)
        .map(|i| {
            let x = 800.0 * i as f64 / (n - 1) as f64;
            (x, 200.0 + 50.0 * (0.37 * i as f64).sin())
        })
        .collect();
    pts[61_234].1 = 3.0;
    let t = thin(&pts);
    assert!(t.len() <= 4 * 1601, "{} points left", t.len());
    assert_eq!((t[0], *t.last().unwrap()), (pts[0], pts[n - 1]));
    assert!(t.contains(&pts[61_234]), "the spike was lost");
    let max = |v: &[(f64, f64)]| v.iter().map(|p| p.1).fold(f64::MIN, f64::max);
    assert_eq!(max(&t), max(&pts));
    // Order is kept: x never goes back.
    assert!(t.windows(2).all(|w| w[0].0 <= w[1].0));
    // A sparse line (one point per 3 px) is left as it is.
    let sparse: Vec<(f64, f64)> = (0..100).map(|i| (3.0 * i as f64, (i * i) as f64)).collect();
    assert_eq!(thin(&sparse), sparse);
}
