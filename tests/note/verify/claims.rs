//! Tests of `sliding_ladder::verify::claims` (src/verify/claims.rs).

use sliding_ladder::ladder::geometry::Corner;
use sliding_ladder::scalar::{Rational, Scalar};
use sliding_ladder::verify::claims::{claims, contact_torques_vanish_about, separates_where};

/// Exact rationals, the number type of the claims.
type Q = Rational;

#[test]
fn claims_hold_and_wrong_versions_fail() {
    assert!(claims()
        .iter()
        .all(|c| c.holds && c.printed_fails != Some(false)));
    // A root at (1/3) or (3/3) cos θ0 instead of (2/3) fails; so do torques about D.
    assert!(separates_where(&Q::ratio(3, 5), 2) && !separates_where(&Q::ratio(3, 5), 1));
    assert!(!separates_where(&Q::int(1), 3));
    assert!(contact_torques_vanish_about(Corner::E) && !contact_torques_vanish_about(Corner::D));
}
