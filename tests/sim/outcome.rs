//! Tests of `sliding_ladder::sim::outcome` (src/sim/outcome.rs).

use sliding_ladder::sim::outcome::{top_inside_wall, FloorReport, TOP_CLEARANCE_ROUNDING};

fn report(c: f64) -> FloorReport {
    FloorReport {
        floor_force_min: 1.0,
        top_clearance_min: c,
    }
}

/// The flag fires just below the rounding bound and not at or above it, at any length;
/// the bound is the four roundings of the constant's docs, 4 u with u = 2^-53.
#[test]
fn top_inside_wall_fires_only_below_the_rounding() {
    assert_eq!(TOP_CLEARANCE_ROUNDING, 4.0 * 2f64.powi(-53));
    for l in [1e-20, 1.0, 1e20] {
        let b = TOP_CLEARANCE_ROUNDING * l;
        assert!(top_inside_wall(&report(-3.6e-7 * l), l).is_some());
        assert!(top_inside_wall(&report(-2.0 * b), l).is_some());
        assert!(top_inside_wall(&report(-b), l).is_none());
        assert!(top_inside_wall(&report(0.0), l).is_none());
        assert!(top_inside_wall(&report(1e-9 * l), l).is_none());
    }
}
