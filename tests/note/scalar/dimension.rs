//! Tests of `sliding_ladder::scalar::dimension` (src/scalar/dimension.rs).

//! Tests of the dimension scalar: the rules of dimensional analysis, and that a clash is caught.

use num_rational::Ratio;
use sliding_ladder::scalar::dimension::{Clash, Dim, Dimension};
use sliding_ladder::scalar::Scalar;

fn m() -> Dim {
    Dim::Of(Dimension::MASS)
}
fn l() -> Dim {
    Dim::Of(Dimension::LENGTH)
}
fn rate() -> Dim {
    Dim::new(0, 0, -1)
}

#[test]
fn products_quotients_and_powers_move_exponents() {
    let ml2w = m() * l() * l() * rate();
    assert_eq!(ml2w, Dim::new(1, 2, -1));
    assert_eq!(ml2w.clone() / l(), Dim::new(1, 1, -1));
    assert_eq!(Dim::new(0, 2, -2).pow(Ratio::new(1, 2)), Dim::new(0, 1, -1));
    // Numbers are dimensionless: 2/3 m l² θ̇ has the dimension of m l² θ̇.
    assert_eq!(Dim::ratio(2, 3) * ml2w.clone(), ml2w);
    assert_ne!(ml2w, Dim::new(1, 1, -1));
}

#[test]
fn a_sum_of_unlike_dimensions_is_recorded_with_both() {
    // The last form of (49): m l² θ̇ added to l² θ̇.
    let bad = m() * l() * l() * rate() + l() * l() * rate();
    let i = bad.inconsistency().expect("recorded");
    assert_eq!(
        i.clash,
        Clash::Unlike {
            op: "+",
            left: Dimension::new(1, 2, -1),
            right: Dimension::new(0, 2, -1)
        }
    );
    assert_eq!(i.to_string(), "M L² T⁻¹ + L² T⁻¹");
    // It absorbs later operations and keeps the first clash and the first place given.
    let later = (bad * m() - l()).at("form 3").at("form 4");
    assert_eq!(
        later.inconsistency().unwrap().to_string(),
        "M L² T⁻¹ + L² T⁻¹ in form 3"
    );
    // Like dimensions add without complaint.
    assert_eq!(m() * rate() + m() * rate(), Dim::new(1, 0, -1));
    assert!((m() - l()).inconsistency().is_some());
}

#[test]
fn zero_has_every_dimension_and_division_by_it_is_recorded() {
    assert_eq!(Dim::int(0) + m(), m());
    assert_eq!(l() - Dim::int(0), l());
    assert_eq!(Dim::int(0) * m(), Dim::Zero);
    assert_eq!(
        (m() / Dim::int(0)).inconsistency().unwrap().clash,
        Clash::DivisionByZero
    );
    // A nonzero number is dimensionless, not a wildcard.
    assert!((Dim::int(1) + m()).inconsistency().is_some());
}

#[test]
fn time_derivatives_along_the_motion_divide_by_time() {
    // θ̇ → θ̇ + θ̈ ε; m, l constant: d/dt (m l² θ̇) = m l² θ̈, of dimension M L² T⁻².
    let w = Dim::lift(rate(), Dim::new(0, 0, -2));
    let (mm, ll) = (Dim::constant(m()), Dim::constant(l()));
    let (value, derivative) = Dim::split(mm * ll.clone() * ll * w);
    assert_eq!(value, Dim::new(1, 2, -1));
    assert_eq!(derivative, Dim::new(1, 2, -2));
    // sin θ → sin θ + cos θ θ̇ ε: d/dt sin θ has dimension T⁻¹.
    let s = Dim::lift(Dim::int(1), Dim::int(1) * rate());
    assert_eq!(Dim::split(s.clone() * s).1, rate());
}

#[test]
fn angles_must_be_pure_numbers() {
    assert_eq!(Dim::int(3).require_dimensionless("θ"), Dim::int(1));
    let e = l().require_dimensionless("θ");
    assert_eq!(
        e.inconsistency().unwrap().to_string(),
        "θ has dimension L, not a pure number"
    );
}

#[test]
fn dimensions_parse_and_print() {
    assert_eq!(Dimension::parse("M L^2 T^-1"), Ok(Dimension::new(1, 2, -1)));
    assert_eq!(Dimension::parse("M·L·T^{-2}"), Ok(Dimension::new(1, 1, -2)));
    assert_eq!(Dimension::parse("1"), Ok(Dimension::NONE));
    assert_eq!(
        Dimension::parse("L^1/2"),
        Ok(Dimension::LENGTH.pow(Ratio::new(1, 2)))
    );
    assert!(Dimension::parse("K").is_err());
    assert!(Dimension::parse("L^x").is_err());
    assert_eq!(Dimension::new(1, 1, -2).to_string(), "M L T⁻²");
    assert_eq!(Dimension::new(1, 1, -2).si_unit(), "kg m s^-2");
    assert_eq!(Dimension::NONE.to_string(), "1");
    assert_eq!(Dimension::LENGTH.pow(Ratio::new(1, 2)).to_string(), "L¹ᐟ²");
}

/// A dimension has no numerical value: `to_f64` is NaN.
#[test]
fn dimension_to_f64_is_not_a_number() {
    assert!(Dim::new(1, 2, -2).to_f64().is_nan());
    assert!(Dim::int(1).to_f64().is_nan());
}
