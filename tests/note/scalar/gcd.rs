//! Tests of `sliding_ladder::scalar::gcd` (src/scalar/gcd.rs): Lehmer's gcd held to num-bigint's
//! own (Stein's algorithm, an independent method) on operands of every size the checks meet and
//! on the cases that steer Lehmer's algorithm into its rare branches.

use num_bigint::{BigUint, RandBigInt};
use num_integer::Integer;
use num_traits::{One, Zero};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use sliding_ladder::scalar::gcd::{gcd_big, gcd_words};

/// `gcd_big(a, b)` and `gcd_big(b, a)` against num-bigint's gcd.
fn agrees(a: &BigUint, b: &BigUint) {
    let want = a.gcd(b);
    assert_eq!(gcd_big(a, b), want, "gcd({a}, {b})");
    assert_eq!(gcd_big(b, a), want, "gcd({b}, {a})");
}

#[test]
fn gcd_big_agrees_with_num_bigint_on_random_operands_with_a_common_factor() {
    let mut rng = ChaCha8Rng::seed_from_u64(35);
    let mut beyond_words = 0;
    for _ in 0..20_000 {
        let bits = rng.gen_range(0..300);
        let g = rng.gen_biguint(bits) + 1u32;
        let (ba, bb) = (rng.gen_range(0..1200), rng.gen_range(0..1200));
        let (a, b) = (rng.gen_biguint(ba) * &g, rng.gen_biguint(bb) * &g);
        beyond_words += usize::from(a.bits() > 128 && b.bits() > 128);
        agrees(&a, &b);
        // A multiple of the common factor: the gcd is at least it, so a gcd of 1 cannot pass.
        assert!(gcd_big(&a, &b).is_multiple_of(&g) || a.is_zero() && b.is_zero());
    }
    assert!(
        beyond_words > 10_000,
        "{beyond_words} pairs reached Lehmer's loop"
    );
}

#[test]
fn gcd_big_agrees_on_consecutive_fibonacci_numbers_the_longest_remainder_sequence() {
    let (mut f0, mut f1) = (BigUint::one(), BigUint::one());
    for _ in 0..2000 {
        let f2 = &f0 + &f1;
        f0 = std::mem::replace(&mut f1, f2);
        agrees(&f0, &f1);
        agrees(&(&f0 * 6u32), &(&f1 * 10u32));
    }
}

#[test]
fn gcd_big_agrees_on_edge_operands() {
    let two = BigUint::from(2u32);
    let big = |e: u32| two.pow(e);
    let cases = [
        (BigUint::zero(), BigUint::zero()),
        (BigUint::zero(), big(700) + 1u32),
        (big(700), big(300)),
        (big(700), big(700) - 1u32),
        (big(700) + 1u32, BigUint::from(3u32).pow(100)),
        (big(128), big(128) - 1u32),
        (big(128) - 1u32, (big(128) - 1u32) * 5u32),
        (big(64), big(64) + 2u32),
        (big(1000) * 7u32, big(1000) * 7u32),
        (
            BigUint::from(u128::MAX),
            BigUint::from(u128::MAX) * BigUint::from(u128::MAX),
        ),
        (
            BigUint::from(u64::MAX) * 3u32,
            BigUint::from(u64::MAX) * 5u32,
        ),
    ];
    for (a, b) in &cases {
        agrees(a, b);
    }
    // Operands that differ by many orders: the window proves no quotient, a full division.
    let mut rng = ChaCha8Rng::seed_from_u64(62);
    for _ in 0..2000 {
        let (ba, bb) = (rng.gen_range(500..2000), rng.gen_range(129..400));
        agrees(&rng.gen_biguint(ba), &rng.gen_biguint(bb));
    }
}

#[test]
fn gcd_words_agrees_with_num_integer_on_both_widths() {
    let mut rng = ChaCha8Rng::seed_from_u64(64);
    for i in 0..50_000 {
        let shift = [0, 64, 100, 127][i % 4];
        let g = u128::from(rng.gen::<u16>()) + 1;
        let (a, b) = (rng.gen::<u128>() >> shift, rng.gen::<u128>() >> shift);
        let (a, b) = (a / g * g, b / g * g);
        assert_eq!(gcd_words(a, b), a.gcd(&b), "gcd({a}, {b})");
    }
    assert_eq!(gcd_words(0, 0), 0);
    assert_eq!(gcd_words(0, 12), 12);
    assert_eq!(gcd_words(u128::MAX, u128::MAX - 1), 1);
}
