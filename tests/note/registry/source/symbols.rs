//! Tests of `sliding_ladder::registry::source::symbols` (src/registry/source/symbols.rs).

use sliding_ladder::registry::source::symbols::{point_id, with_points};
use sliding_ladder::registry::source::PointSpec;

#[test]
fn a_named_point_becomes_its_id_in_a_quantity() {
    let q = [PointSpec {
        name: "Q".into(),
        point: "ladder:1/4".into(),
        line: 1,
    }];
    assert_eq!(with_points("torque:Q.z", &q), "torque:ladder:1/4.z");
    assert_eq!(with_points("position:Q", &q), "position:ladder:1/4");
    assert_eq!(with_points("torque:A.z", &q), "torque:A.z");
    assert_eq!(with_points("wall_force", &q), "wall_force");
    assert!(point_id("ladder:1/4").is_ok() && point_id("lab:0.5,1.5").is_ok());
    assert!(point_id("ladder:3/2").is_err() && point_id("moon").is_err());
}
