//! Tests of `sliding_ladder::print::point` (src/print/point.rs).

use sliding_ladder::ladder::analysis::Reference;
use sliding_ladder::print::point::{fraction, parse_point};

#[test]
fn fractions_and_points_are_read_exactly() {
    assert_eq!(fraction("3"), Some((3, 1)));
    assert_eq!(fraction("-1/4"), Some((-1, 4)));
    assert_eq!(fraction("0.25"), Some((25, 100)));
    assert_eq!(fraction("-0.5"), Some((-5, 10)));
    assert_eq!(fraction("1/0"), None);
    assert_eq!(fraction("x"), None);
    assert!(matches!(
        parse_point("ladder:1/4"),
        Some(Reference::OnLadder(1, 4))
    ));
    assert!(parse_point("ladder:5/4").is_none() && parse_point("ladder:-1/4").is_none());
    assert!(matches!(
        parse_point("lab:1/2,3/2"),
        Some(Reference::Lab(2, 6, 4))
    ));
    assert!(parse_point("lab:1/2").is_none() && parse_point("moon").is_none());
}
