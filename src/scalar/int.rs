//! [`Int`]: the integers of the exact [`super::Rational`], num-bigint's `BigInt` with a faster gcd.
//!
//! num-rational reduces every result to lowest terms by `Integer::gcd` of its integer type, and
//! num-bigint's is Stein's bit-by-bit algorithm (see [`super::gcd`]). A newtype is the one way to
//! give `Ratio` another gcd without replacing num-bigint and num-rational: every other operation
//! is `BigInt`'s, forwarded, and `Int` dereferences to its `BigInt` for reading (bits, sign,
//! digits). Measured on `ladder verify` (test profile): 9.9 s of CPU with num-bigint's gcd, 4.8 s
//! with [`super::gcd::gcd_big`] (docs/build-time.md).

use super::gcd::gcd_big;
use num_bigint::{BigInt, ParseBigIntError, Sign, ToBigInt};
use num_integer::Integer;
use num_traits::{FromPrimitive, Num, One, Signed, ToPrimitive, Zero};
use std::fmt;
use std::ops::{Add, AddAssign, Deref, Div, DivAssign, Mul, MulAssign, Neg, Rem, RemAssign};
use std::ops::{Sub, SubAssign};
use std::str::FromStr;

/// An arbitrary-precision integer: `BigInt` whose gcd is Lehmer's ([`gcd_big`]).
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct Int(pub BigInt);

impl Deref for Int {
    type Target = BigInt;
    fn deref(&self) -> &BigInt {
        &self.0
    }
}

impl fmt::Debug for Int {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(&self.0, f)
    }
}

impl fmt::Display for Int {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

impl From<BigInt> for Int {
    fn from(n: BigInt) -> Int {
        Int(n)
    }
}

impl From<Int> for BigInt {
    fn from(n: Int) -> BigInt {
        n.0
    }
}

/// `Int::from` for the machine integers the crate builds from.
macro_rules! from_primitive {
    ($($t:ty),*) => {$(
        impl From<$t> for Int {
            fn from(n: $t) -> Int {
                Int(BigInt::from(n))
            }
        }
    )*};
}
from_primitive!(i32, i64, i128, u32, u64, u128, usize);

/// The four ways to combine two owned or borrowed `Int`s, and the compound assignments, by
/// `BigInt`'s operator.
macro_rules! forward_binop {
    ($($op:ident $f:ident $assign:ident $fa:ident),*) => {$(
        impl $op for Int {
            type Output = Int;
            fn $f(self, o: Int) -> Int {
                Int(self.0.$f(o.0))
            }
        }
        impl $op<&Int> for Int {
            type Output = Int;
            fn $f(self, o: &Int) -> Int {
                Int(self.0.$f(&o.0))
            }
        }
        impl $op<Int> for &Int {
            type Output = Int;
            fn $f(self, o: Int) -> Int {
                Int((&self.0).$f(o.0))
            }
        }
        impl $op<&Int> for &Int {
            type Output = Int;
            fn $f(self, o: &Int) -> Int {
                Int((&self.0).$f(&o.0))
            }
        }
        impl $assign for Int {
            fn $fa(&mut self, o: Int) {
                self.0.$fa(o.0)
            }
        }
        impl $assign<&Int> for Int {
            fn $fa(&mut self, o: &Int) {
                self.0.$fa(&o.0)
            }
        }
    )*};
}
forward_binop!(
    Add add AddAssign add_assign,
    Sub sub SubAssign sub_assign,
    Mul mul MulAssign mul_assign,
    Div div DivAssign div_assign,
    Rem rem RemAssign rem_assign
);

impl Neg for Int {
    type Output = Int;
    fn neg(self) -> Int {
        Int(-self.0)
    }
}

impl Neg for &Int {
    type Output = Int;
    fn neg(self) -> Int {
        Int(-&self.0)
    }
}

impl Zero for Int {
    fn zero() -> Int {
        Int(BigInt::zero())
    }
    fn is_zero(&self) -> bool {
        self.0.is_zero()
    }
}

impl One for Int {
    fn one() -> Int {
        Int(BigInt::one())
    }
}

impl Num for Int {
    type FromStrRadixErr = ParseBigIntError;
    fn from_str_radix(s: &str, radix: u32) -> Result<Int, ParseBigIntError> {
        BigInt::from_str_radix(s, radix).map(Int)
    }
}

impl FromStr for Int {
    type Err = ParseBigIntError;
    fn from_str(s: &str) -> Result<Int, ParseBigIntError> {
        s.parse().map(Int)
    }
}

impl Signed for Int {
    fn abs(&self) -> Int {
        Int(self.0.abs())
    }
    fn abs_sub(&self, o: &Int) -> Int {
        Int(self.0.abs_sub(&o.0))
    }
    fn signum(&self) -> Int {
        Int(self.0.signum())
    }
    fn is_positive(&self) -> bool {
        self.0.is_positive()
    }
    fn is_negative(&self) -> bool {
        self.0.is_negative()
    }
}

/// `BigInt`'s division and parity; the gcd (and with it the lcm) by Lehmer's algorithm.
impl Integer for Int {
    fn gcd(&self, o: &Int) -> Int {
        Int(BigInt::from_biguint(
            Sign::Plus,
            gcd_big(self.0.magnitude(), o.0.magnitude()),
        ))
    }
    fn lcm(&self, o: &Int) -> Int {
        if self.is_zero() && o.is_zero() {
            return Int::zero();
        }
        Int((&self.0 / &self.gcd(o).0 * &o.0).abs())
    }
    fn div_floor(&self, o: &Int) -> Int {
        Int(self.0.div_floor(&o.0))
    }
    fn mod_floor(&self, o: &Int) -> Int {
        Int(self.0.mod_floor(&o.0))
    }
    fn is_multiple_of(&self, o: &Int) -> bool {
        self.0.is_multiple_of(&o.0)
    }
    fn is_even(&self) -> bool {
        self.0.is_even()
    }
    fn is_odd(&self) -> bool {
        self.0.is_odd()
    }
    fn div_rem(&self, o: &Int) -> (Int, Int) {
        let (q, r) = self.0.div_rem(&o.0);
        (Int(q), Int(r))
    }
}

impl ToPrimitive for Int {
    fn to_i64(&self) -> Option<i64> {
        self.0.to_i64()
    }
    fn to_u64(&self) -> Option<u64> {
        self.0.to_u64()
    }
    fn to_i128(&self) -> Option<i128> {
        self.0.to_i128()
    }
    fn to_u128(&self) -> Option<u128> {
        self.0.to_u128()
    }
    fn to_f64(&self) -> Option<f64> {
        self.0.to_f64()
    }
}

impl FromPrimitive for Int {
    fn from_i64(n: i64) -> Option<Int> {
        Some(Int::from(n))
    }
    fn from_u64(n: u64) -> Option<Int> {
        Some(Int::from(n))
    }
    fn from_f64(x: f64) -> Option<Int> {
        BigInt::from_f64(x).map(Int)
    }
}

/// For num-rational's `to_f64` of a fraction whose parts do not fit an i64.
impl ToBigInt for Int {
    fn to_bigint(&self) -> Option<BigInt> {
        Some(self.0.clone())
    }
}

/// For `Rational::pow`.
impl num_traits::Pow<u32> for &Int {
    type Output = Int;
    fn pow(self, e: u32) -> Int {
        Int(num_traits::Pow::pow(&self.0, e))
    }
}

/// The exact value of a finite float as a [`super::Rational`] (`None` for NaN and ±∞): num-rational's
/// `from_float`, which exists for `BigInt` parts only.
pub fn rational_from_float(x: f64) -> Option<super::Rational> {
    let q = num_rational::BigRational::from_float(x)?;
    let (n, d) = q.into_raw();
    Some(super::Rational::new_raw(Int(n), Int(d)))
}
