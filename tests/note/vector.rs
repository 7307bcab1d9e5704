//! Tests of `sliding_ladder::vector` (src/vector.rs).

use sliding_ladder::vector::Vec3;

#[test]
fn right_handed_cross_product() {
    let x = Vec3::new(1.0, 0.0, 0.0);
    let y = Vec3::new(0.0, 1.0, 0.0);
    assert_eq!(x.cross(&y), Vec3::new(0.0, 0.0, 1.0));
    assert_eq!(y.cross(&x), Vec3::new(0.0, 0.0, -1.0));
}
