//! Tests of `sliding_ladder::scalar::si_unit` (src/scalar/si_unit.rs).

use sliding_ladder::scalar::Dimension;

#[test]
fn units_spell_their_dimensions() {
    let d = |s| Dimension::from_si(s).unwrap();
    assert_eq!(d("N"), d("kg m/s^2"));
    assert_eq!(d("J s"), d("kg m^2/s"));
    assert_eq!(d("rad/s^2"), Dimension::new(0, 0, -2));
    assert_ne!(d("N"), d("J"));
    assert_ne!(d("kg m^2/s"), d("kg m^2/s^2"));
    assert!(Dimension::from_si("lb").is_err());
    assert!(Dimension::from_si("m^x").is_err());
}
