//! Tests of `sliding_ladder::scalar::int` (src/scalar/int.rs): a `Rational` of `Int` parts is
//! num-rational's `BigRational`, value for value, and every forwarded operation is `BigInt`'s.

use num_bigint::{BigInt, RandBigInt};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{Pow, Signed, ToPrimitive};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use sliding_ladder::scalar::{rational_from_float, Int, Rational};

fn parts(q: &Rational) -> (BigInt, BigInt) {
    (q.numer().0.clone(), q.denom().0.clone())
}

fn big_parts(q: &BigRational) -> (BigInt, BigInt) {
    (q.numer().clone(), q.denom().clone())
}

/// A random fraction of up to 400-bit parts, as both types.
fn pair(rng: &mut ChaCha8Rng) -> (Rational, BigRational) {
    let (bn, bd) = (rng.gen_range(1..400), rng.gen_range(1..400));
    let n = rng.gen_bigint(bn);
    let d: BigInt = rng.gen_bigint(bd) * 6u32 + 1u32;
    (
        Rational::new(n.clone().into(), d.clone().into()),
        BigRational::new(n, d),
    )
}

#[test]
fn rational_of_int_parts_is_big_rational_under_every_operation() {
    let mut rng = ChaCha8Rng::seed_from_u64(37);
    for _ in 0..3000 {
        let ((a, ba), (b, bb)) = (pair(&mut rng), pair(&mut rng));
        assert_eq!(parts(&a), big_parts(&ba), "lowest terms on construction");
        assert_eq!(parts(&(&a + &b)), big_parts(&(&ba + &bb)));
        assert_eq!(parts(&(&a - &b)), big_parts(&(&ba - &bb)));
        assert_eq!(parts(&(&a * &b)), big_parts(&(&ba * &bb)));
        if !b.numer().0.sign().eq(&num_bigint::Sign::NoSign) {
            assert_eq!(parts(&(&a / &b)), big_parts(&(&ba / &bb)));
        }
        assert_eq!(parts(&a.clone().pow(3)), big_parts(&ba.clone().pow(3)));
        assert_eq!(a.to_f64(), ba.to_f64());
        assert_eq!(a < b, ba < bb);
        assert_eq!(a.to_string(), ba.to_string());
    }
}

#[test]
fn int_forwards_bigint_division_parity_and_lcm() {
    let mut rng = ChaCha8Rng::seed_from_u64(38);
    for _ in 0..3000 {
        let (x, y): (BigInt, BigInt) = (rng.gen_bigint(300), rng.gen_bigint(200) + 1u32);
        let (a, b) = (Int(x.clone()), Int(y.clone()));
        assert_eq!(a.div_floor(&b).0, x.div_floor(&y));
        assert_eq!(a.mod_floor(&b).0, x.mod_floor(&y));
        let (q, r) = a.div_rem(&b);
        assert_eq!((q.0, r.0), x.div_rem(&y));
        assert_eq!(a.lcm(&b).0, x.lcm(&y));
        assert_eq!(a.gcd(&b).0, x.gcd(&y));
        assert_eq!((a.is_even(), a.is_odd()), (x.is_even(), x.is_odd()));
        assert_eq!(a.is_multiple_of(&b), x.is_multiple_of(&y));
        assert!(Int(&x * &y).is_multiple_of(&b));
        assert_eq!(a.abs().0, x.abs());
        assert_eq!((&a % &b).0, &x % &y);
        assert_eq!(a.to_string().parse::<Int>().map(|n| n.0), Ok(x));
    }
}

#[test]
fn rational_from_float_is_the_floats_exact_value() {
    let third = rational_from_float(1.0 / 3.0).expect("finite");
    // 1/3 rounded: a power-of-two denominator, within half an ulp of 1/3, not 1/3 itself.
    assert_eq!(third.denom().0, BigInt::from(1u64) << 54);
    assert_ne!(third, Rational::new(Int::from(1), Int::from(3)));
    assert_eq!(third.to_f64(), Some(1.0 / 3.0));
    assert_eq!(
        rational_from_float(-2.5),
        Some(Rational::new(Int::from(-5), Int::from(2)))
    );
    assert_eq!(rational_from_float(f64::NAN), None);
    assert_eq!(rational_from_float(f64::INFINITY), None);
}

/// Every method `Int` implements for the num traits, held to `BigInt`'s on random values of
/// up to 300 bits and on values at the edges of the machine types (0, ±1, ±2⁶³, 2⁶⁴, ±2¹²⁷,
/// 2¹²⁸), where the conversions change from `Some` to `None`.
#[test]
fn int_forwards_every_num_trait_method_to_bigint() {
    use num_traits::{FromPrimitive, Num, One, Zero};
    let mut rng = ChaCha8Rng::seed_from_u64(39);
    let one = BigInt::from(1);
    let mut values: Vec<BigInt> = [0, 1, -1, 63, 64, 127, 128]
        .iter()
        .flat_map(|&k: &i32| {
            let p = if k <= 1 { BigInt::from(k) } else { &one << k };
            [p.clone(), -p.clone(), &p - 1, -&p + 1]
        })
        .collect();
    for _ in 0..500 {
        let bits = rng.gen_range(1..300);
        values.push(rng.gen_bigint(bits));
    }
    for x in &values {
        let a = Int(x.clone());
        let y = rng.gen_bigint(90);
        let b = Int(y.clone());
        assert_eq!(format!("{a:?}"), format!("{x:?}"));
        assert_eq!(BigInt::from(a.clone()), *x);
        assert_eq!((-&a).0, -x);
        assert_eq!((-a.clone()).0, -x);
        assert_eq!(
            Int::from_str_radix(&x.to_str_radix(7), 7).map(|n| n.0),
            Ok(x.clone())
        );
        assert_eq!(a.abs_sub(&b).0, x.abs_sub(&y));
        assert_eq!(a.signum().0, x.signum());
        assert_eq!(
            (a.is_positive(), a.is_negative()),
            (x.is_positive(), x.is_negative())
        );
        assert_eq!(a.to_i64(), x.to_i64());
        assert_eq!(a.to_u64(), x.to_u64());
        assert_eq!(a.to_i128(), x.to_i128());
        assert_eq!(a.to_u128(), x.to_u128());
        assert_eq!(a.to_f64(), x.to_f64());
        if let Some(n) = x.to_i64() {
            assert_eq!(Int::from_i64(n).map(|n| n.0), Some(x.clone()));
        }
        if let Some(n) = x.to_u64() {
            assert_eq!(Int::from_u64(n).map(|n| n.0), Some(x.clone()));
        }
        let f = x.to_f64().expect("a finite float");
        assert_eq!(Int::from_f64(f).map(|n| n.0), BigInt::from_f64(f));
    }
    assert!(Int::zero().is_zero() && !Int::one().is_zero());
    assert_eq!(Int::from_f64(f64::NAN), None);
}
