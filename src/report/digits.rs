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
