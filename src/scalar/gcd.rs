//! Greatest common divisors: of machine words by Stein's binary algorithm, of big integers by
//! Lehmer's.
//!
//! Every operation on an exact [`super::Rational`] ends in a gcd (num-rational keeps fractions in
//! lowest terms), and `ladder verify` takes millions of them, of operands up to about a thousand
//! bits (most under 512). num-bigint 0.4 computes a gcd by Stein's algorithm on the whole number:
//! one full-width shift and subtraction per bit, each a pass over the digits. That was half the
//! CPU time of `ladder verify` (docs/build-time.md). Lehmer's algorithm runs Euclid's quotients on
//! the leading 62 bits in one machine word, as long as they are provably the true quotients, and
//! then applies the accumulated 2×2 matrix to the whole numbers in a single pass: about 30 bits of
//! progress per pass instead of one. Operands that fit in 128 bits never reach it.
//!
//! Written by hand because no crate offers a faster gcd for num-bigint's integers (upstream,
//! rust-num/num-bigint#296 is open), and the crates that have one (dashu, malachite) would replace
//! num-bigint and num-rational throughout the crate. `tests/note/scalar/gcd.rs` holds it to
//! num-bigint's gcd on random, Fibonacci (the worst case) and edge operands.

use num_bigint::BigUint;
use num_traits::ToPrimitive;

/// Stein's binary gcd of two nonzero integers of one width: no division, which u128 lacks in
/// hardware. One body for both widths: the u64 loop, the common case, runs on cheaper words.
macro_rules! binary_gcd {
    ($a:expr, $b:expr) => {{
        let (mut a, mut b) = ($a, $b);
        let shift = (a | b).trailing_zeros();
        a >>= a.trailing_zeros();
        loop {
            b >>= b.trailing_zeros();
            if a > b {
                std::mem::swap(&mut a, &mut b);
            }
            b -= a;
            if b == 0 {
                break a << shift;
            }
        }
    }};
}

/// The gcd of two unsigned integers (0 when both are 0), by Stein's binary algorithm in u64 when
/// both fit.
pub fn gcd_words(a: u128, b: u128) -> u128 {
    if a == 0 || b == 0 {
        return a | b;
    }
    if a <= u128::from(u64::MAX) && b <= u128::from(u64::MAX) {
        return u128::from(binary_gcd!(a as u64, b as u64));
    }
    binary_gcd!(a, b)
}

/// The gcd of two magnitudes (0 when both are 0): in machine words when both fit in 128 bits,
/// by Lehmer's algorithm otherwise.
pub fn gcd_big(a: &BigUint, b: &BigUint) -> BigUint {
    if let (Some(x), Some(y)) = (a.to_u128(), b.to_u128()) {
        return BigUint::from(gcd_words(x, y));
    }
    let (a, b) = if a >= b { (a, b) } else { (b, a) };
    lehmer(a.to_u64_digits(), b.to_u64_digits())
}

/// Bits of the leading window: the cofactors stay below 2⁶², so `A·aᵢ + B·bᵢ` fits an i128.
const WINDOW: u64 = 62;

/// Knuth's Algorithm L (TAOCP vol. 2, sec. 4.5.2) on little-endian 64-bit digits, `a ≥ b`.
/// Euclid's quotients are taken on the leading 62 bits while Collins' test proves them the true
/// ones; a window that proves none falls back to one full division.
fn lehmer(mut a: Vec<u64>, mut b: Vec<u64>) -> BigUint {
    while b.len() > 2 {
        let k = bits(&a) - WINDOW;
        let (mut x, mut y) = (window(&a, k) as i64, window(&b, k) as i64);
        let (mut ma, mut mb, mut mc, mut md) = (1i64, 0i64, 0i64, 1i64);
        while y + mc != 0 && y + md != 0 {
            let q = (x + ma) / (y + mc);
            if q != (x + mb) / (y + md) {
                break;
            }
            (ma, mc) = (mc, ma - q * mc);
            (mb, md) = (md, mb - q * md);
            (x, y) = (y, x - q * y);
        }
        if mb == 0 {
            let r = from_words(&a) % from_words(&b);
            a = std::mem::replace(&mut b, r.to_u64_digits());
        } else {
            combine(&mut a, &mut b, [ma, mb, mc, md]);
        }
    }
    let (a, b) = (from_words(&a), from_words(&b));
    match b.to_u128() {
        Some(0) | None => a,
        Some(b128) => {
            let r = (a % &b).to_u128().unwrap_or(0);
            BigUint::from(gcd_words(b128, r))
        }
    }
}

/// The magnitude of little-endian 64-bit digits.
fn from_words(w: &[u64]) -> BigUint {
    BigUint::from_slice(
        &w.iter()
            .flat_map(|&x| [x as u32, (x >> 32) as u32])
            .collect::<Vec<u32>>(),
    )
}

/// The bit length of little-endian digits without leading zero digits.
fn bits(w: &[u64]) -> u64 {
    match w.last() {
        None => 0,
        Some(&top) => 64 * w.len() as u64 - u64::from(top.leading_zeros()),
    }
}

/// `⌊w / 2^k⌋`, known to be below 2⁶⁴ (the window of the longer operand at `k`).
fn window(w: &[u64], k: u64) -> u64 {
    let (i, s) = ((k / 64) as usize, k % 64);
    let lo = w.get(i).copied().unwrap_or(0) >> s;
    let hi = if s == 0 {
        0
    } else {
        w.get(i + 1).copied().unwrap_or(0) << (64 - s)
    };
    lo | hi
}

/// `(a, b) ← (A a + B b, C a + D b)` in one pass with signed carries; Lehmer's step makes both
/// results non-negative, so the final carries are zero.
fn combine(a: &mut Vec<u64>, b: &mut Vec<u64>, m: [i64; 4]) {
    let (mut ca, mut cb) = (0i128, 0i128);
    b.resize(a.len(), 0);
    for (x, y) in a.iter_mut().zip(b.iter_mut()) {
        let (xi, yi) = (i128::from(*x), i128::from(*y));
        let s = i128::from(m[0]) * xi + i128::from(m[1]) * yi + ca;
        let t = i128::from(m[2]) * xi + i128::from(m[3]) * yi + cb;
        (*x, *y) = (s as u64, t as u64);
        (ca, cb) = (s >> 64, t >> 64);
    }
    debug_assert!(ca == 0 && cb == 0, "Lehmer step left a carry");
    for w in [a, b] {
        while w.last() == Some(&0) {
            w.pop();
        }
    }
}
