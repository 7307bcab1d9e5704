//! Tests of `sliding_ladder::scalar::coeff` (src/scalar/coeff.rs).

//! The machine-word path of [`Coeff`] against `BigRational` on random and overflow-edge values.
use num_bigint::BigInt;
use num_traits::{ToPrimitive, Zero};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use sliding_ladder::scalar::coeff::Coeff;
use sliding_ladder::scalar::gcd::gcd_words;
use sliding_ladder::scalar::{Int, Rational};

/// The canonical form: `Small` exactly when numerator and denominator fit below 2⁶³.
fn canonical(c: &Coeff) -> bool {
    match c {
        Coeff::Small(n, d) => {
            *d > 0 && *n != i64::MIN && gcd_words(n.unsigned_abs().into(), (*d as u64).into()) == 1
        }
        Coeff::Big(q) => !matches!(
            (q.numer().to_i64(), q.denom().to_i64()),
            (Some(n), Some(_)) if n != i64::MIN
        ),
    }
}

/// Values near every boundary: 0, ±1, small fractions, ±(2⁶³ − 1), 2⁶³ and beyond, and big
/// rationals whose reduced form is small.
fn edges() -> Vec<Rational> {
    let r = |n: i128, d: i128| Rational::new(BigInt::from(n).into(), BigInt::from(d).into());
    let max = i128::from(i64::MAX);
    let mut v = vec![
        r(0, 1),
        r(1, 1),
        r(-1, 1),
        r(1, 3),
        r(-9, 4),
        r(max, 1),
        r(-max, 1),
        r(max + 1, 1),
        r(-max - 1, 1),
        r(1, max),
        r(-1, max),
        r(1, max + 1),
        r(max, max - 1),
        r(max + 1, 3),
        r(3 * (max + 1), 3 * max),
        r(max * max, max),
        r(i128::MAX, 7),
    ];
    v.push(Rational::new(
        Int(BigInt::from(1) << 200),
        Int((BigInt::from(1) << 199) * 3),
    ));
    v
}

fn random(rng: &mut ChaCha8Rng) -> Rational {
    let bits = [4u32, 31, 62, 63, 64, 100][rng.gen_range(0..6)];
    let mut part = |nonzero: bool| loop {
        let x = BigInt::from(rng.gen::<u128>() >> (128 - bits));
        let x = if rng.gen() { -x } else { x };
        if !nonzero || x != BigInt::zero() {
            return x;
        }
    };
    let n = part(false);
    Rational::new(n.into(), part(true).into())
}

fn check_pair(a: &Rational, b: &Rational) {
    let (ca, cb) = (Coeff::from(a), Coeff::from(b));
    assert!(canonical(&ca) && canonical(&cb), "{ca:?} {cb:?}");
    assert_eq!(ca.to_big(), *a);
    let mut results = vec![
        ("+", &ca + &cb, Some(a + b)),
        ("-", &ca - &cb, Some(a - b)),
        ("*", &ca * &cb, Some(a * b)),
        ("neg", -&ca, Some(-a)),
    ];
    if !b.is_zero() {
        results.push(("/", &ca / &cb, Some(a / b)));
    }
    for (op, fast, big) in results {
        let big = big.expect("an expected value");
        assert!(canonical(&fast), "{a} {op} {b} = {fast:?} not canonical");
        assert_eq!(fast.to_big(), big, "{a} {op} {b}");
        assert_eq!(
            fast,
            Coeff::from(big),
            "{a} {op} {b}: representations differ"
        );
    }
    assert_eq!(ca.cmp(&cb), a.cmp(b), "{a} cmp {b}");
    assert_eq!(ca.partial_cmp(&cb), Some(a.cmp(b)), "{a} partial_cmp {b}");
    assert_eq!((-ca.clone()).to_big(), -a, "owned neg of {a}");
    assert_eq!(format!("{ca:?}"), a.to_string(), "Debug of {a}");
    assert_eq!(ca.is_negative(), a < &Rational::zero());
    assert_eq!(ca.is_integer(), a.is_integer());
    assert_eq!(
        (ca.numer(), ca.denom()),
        (a.numer().0.clone(), a.denom().0.clone())
    );
}

#[test]
fn every_operation_equals_the_big_rational_one_at_the_edges() {
    let e = edges();
    for a in &e {
        for b in &e {
            check_pair(a, b);
        }
    }
}

#[test]
fn every_operation_equals_the_big_rational_one_at_random_values() {
    let mut rng = ChaCha8Rng::seed_from_u64(10);
    for _ in 0..20_000 {
        let (a, b) = (random(&mut rng), random(&mut rng));
        check_pair(&a, &b);
    }
}

#[test]
fn overflow_leaves_the_machine_word_and_comes_back() {
    let max = Coeff::from(i64::MAX);
    assert_eq!(max.to_big(), Rational::from_integer(Int::from(i64::MAX)));
    let over = &max + &Coeff::int(1);
    assert!(matches!(over, Coeff::Big(_)), "{over:?}");
    assert_eq!(
        over.to_big(),
        Rational::from_integer(Int::from(BigInt::from(1) << 63))
    );
    let back = &over - &Coeff::int(1);
    assert_eq!(back, max);
    assert!(matches!(back, Coeff::Small(..)));
    // −2⁶³ fits an i64 but not `Small` (its negation would overflow).
    let min = -&over;
    assert!(matches!(min, Coeff::Big(_)));
    assert_eq!(-&min, over);
    // A product of two big values that is small again.
    let big = &over * &over;
    assert_eq!(
        &big / &(&over * &Coeff::int(2)),
        Coeff::ratio(1, 2) * over.clone()
    );
    assert_eq!(&(&big / &big) + &Coeff::ratio(-1, 2), Coeff::ratio(1, 2));
}

#[test]
fn a_wrong_fast_result_would_be_caught() {
    // The comparison the tests rest on can fail: a value off by one part in 2⁶² differs.
    let a = Coeff::ratio(i64::MAX, 3);
    let b = Coeff::ratio(i64::MAX - 1, 3);
    assert_ne!(a, b);
    assert_ne!(a.to_big(), b.to_big());
    assert!(!canonical(&Coeff::Small(2, 4)));
    assert!(!canonical(&Coeff::Big(Rational::from_integer(
        BigInt::from(5).into()
    ))));
}
