//! Tests of `sliding_ladder::sim::units` (src/sim/units.rs).

use sliding_ladder::ladder::Ladder;
use sliding_ladder::sim::units::Units;

#[test]
fn units_of_a_ladder() {
    let u = Units::of(&Ladder {
        m: 2.0,
        l: 4.0,
        g: 16.0,
    });
    assert_eq!(
        u,
        Units {
            time: 0.5,
            length: 4.0,
            force: 32.0
        }
    );
}

#[test]
fn extreme_units_stay_finite() {
    let u = Units::of(&Ladder {
        m: 1e30,
        l: 1e30,
        g: 1e-30,
    });
    assert!((u.time / 1e30 - 1.0).abs() < 1e-15, "{u:?}");
    assert_eq!(u.force, 1.0);
}
