//! Numbers in reports by significant digits, not fixed decimals: a slow ladder's θ̇ of 3e-14
//! rad/s printed with `{:.12}` reads 0.000000000000, a wrong answer on the page. Like C's `%.Ng`
//! without the stripping of trailing zeros (they state the precision shown): plain notation for
//! decimal exponents in [−4, N), scientific otherwise. Written by hand: Rust's formatter has no
//! significant-digit mode, and the few lines here are all it takes.

/// `x` with `digits` (≥ 1) significant digits.
pub fn sig(x: f64, digits: usize) -> String {
    if !x.is_finite() || x == 0.0 {
        return format!("{x}");
    }
    let digits = digits.max(1);
    // The exponent after rounding to `digits` (9.9996 to 4 digits is 1.000e1).
    let sci = format!("{:.*e}", digits - 1, x);
    let exp: i32 = sci[sci.find('e').map_or(sci.len(), |i| i + 1)..]
        .parse()
        .unwrap_or(0);
    if (-4..digits as i32).contains(&exp) {
        let decimals = (digits as i32 - 1 - exp).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        sci
    }
}

#[cfg(test)]
mod tests {
    use super::sig;

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
}
