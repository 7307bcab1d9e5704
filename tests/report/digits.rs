//! Tests of `sliding_ladder::report::digits` (src/report/digits.rs).

use sliding_ladder::report::digits::sig;

#[test]
fn significant_digits_in_plain_and_scientific_notation() {
    assert_eq!(sig(0.5, 3), "0.500");
    assert_eq!(sig(123.456, 4), "123.5");
    assert_eq!(sig(-123.456, 4), "-123.5");
    assert_eq!(sig(9.9996, 4), "10.00");
    assert_eq!(sig(0.000123456, 3), "0.000123");
    assert_eq!(sig(1.234e-13, 4), "1.234e-13");
    assert_eq!(sig(-2.5e20, 2), "-2.5e20");
    assert_eq!(sig(12345.0, 3), "1.23e4");
    assert_eq!((sig(0.0, 5), sig(f64::NAN, 5)), ("0".into(), "NaN".into()));
    // Every significant digit survives a round trip; fixed decimals lose them all here.
    let slow = 3.141_592_653_589_793e-14;
    let back: f64 = sig(slow, 15).parse().unwrap();
    assert!((back - slow).abs() <= 1e-14 * slow);
    assert_eq!(format!("{slow:.12}"), "0.000000000000");
}
