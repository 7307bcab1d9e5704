//! Tests of `sliding_ladder::sim::scene::shape` (src/sim/scene/shape.rs).

use sliding_ladder::sim::scene::errors::SECTIONS;
use sliding_ladder::sim::scene::parts::{Raw, RawLadder};
use sliding_ladder::sim::scene::shape::{fields_of, home_of};

#[test]
fn the_schema_is_read_off_the_structs() {
    assert_eq!(fields_of::<Raw>(), SECTIONS);
    assert_eq!(fields_of::<RawLadder>(), ["mass", "half_length", "gravity"]);
    assert_eq!(home_of("scaled_time"), Some("end"));
    assert_eq!(home_of("colour"), None);
}
