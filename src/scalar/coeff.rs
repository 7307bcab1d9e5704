//! [`Coeff`]: the rational coefficients of the symbolic polynomials ([`super::poly`]), held in
//! machine words while they fit and as `BigRational` beyond.
//!
//! Profiling `ladder verify` showed the symbolic proofs spending about half their time in
//! num-bigint (allocating, dividing, taking gcds) on coefficients that are nearly all small: the
//! note's identities have coefficients like 1/3, −3/2 or 9/4, and even after the denominators of a
//! centre of mass are cleared they stay far below 2⁶³. A coefficient is therefore either
//! `Small(n, d)`, n/d in lowest terms with d > 0 and |n|, d < 2⁶³, or `Big(q)` for everything
//! else. `Small` operands are combined in i128, where no sum or product of two such fractions can
//! overflow (|n₁d₂ + n₂d₁| ≤ 2(2⁶³ − 1)² < 2¹²⁷), reduced by a binary gcd, and demoted back to
//! `Small` when the reduced result fits; otherwise, and whenever an operand is `Big`, the
//! operation is done in `BigRational` and its result demoted when it fits. So the representation
//! is canonical (a value is `Small` exactly when it fits), and derived equality and hashing are
//! those of the values; the order is the numeric one, as `BigRational`'s. `coeff_tests.rs` holds
//! every operation to the `BigRational` one on random and overflow-edge values.
//!
//! Written by hand because num-rational, the project's exact type, has no small-value path
//! (`Ratio<i64>` overflows, `BigRational` always allocates), and the crates whose rationals do
//! have one (malachite-q) would replace num-bigint throughout the crate for one hot loop.

use super::gcd::gcd_words;
use super::{Int, Rational};
use num_bigint::BigInt;
use num_traits::{One, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub, SubAssign};

/// 2⁶³: `Small` parts are below this in magnitude.
const LIMIT: u128 = 1 << 63;

/// An exact rational coefficient: `Small(n, d)` (lowest terms, d > 0, |n|, d < 2⁶³) or `Big`.
#[derive(Clone, PartialEq, Eq, Hash)]
pub enum Coeff {
    /// n/d in lowest terms, d > 0, |n| < 2⁶³, d < 2⁶³.
    Small(i64, i64),
    /// A value that does not fit `Small`.
    Big(Rational),
}

impl Coeff {
    /// The integer `n`.
    pub fn int(n: i64) -> Coeff {
        Coeff::from_i128(i128::from(n), 1)
    }
    /// The fraction `n/d` (`d` nonzero).
    pub fn ratio(n: i64, d: i64) -> Coeff {
        Coeff::from_i128(i128::from(n), i128::from(d))
    }
    /// `n/d` in canonical form (`d` nonzero).
    fn from_i128(n: i128, d: i128) -> Coeff {
        assert!(d != 0, "coefficient with a zero denominator");
        if n == 0 {
            return Coeff::Small(0, 1);
        }
        let negative = (n < 0) != (d < 0);
        let (mut un, mut ud) = (n.unsigned_abs(), d.unsigned_abs());
        if ud != 1 {
            let g = gcd_words(un, ud);
            un /= g;
            ud /= g;
        }
        if un < LIMIT && ud < LIMIT {
            let n = un as i64;
            return Coeff::Small(if negative { -n } else { n }, ud as i64);
        }
        let sign = if negative {
            num_bigint::Sign::Minus
        } else {
            num_bigint::Sign::Plus
        };
        Coeff::Big(Rational::new_raw(
            BigInt::from_biguint(sign, un.into()).into(),
            Int::from(ud),
        ))
    }
    /// A `BigRational` (in lowest terms, as num-rational keeps them) in canonical form.
    fn from_big(q: Rational) -> Coeff {
        match (q.numer().to_i64(), q.denom().to_i64()) {
            (Some(n), Some(d)) if n != i64::MIN => Coeff::Small(n, d),
            _ => Coeff::Big(q),
        }
    }
    /// The value as a `BigRational`.
    pub fn to_big(&self) -> Rational {
        match self {
            Coeff::Small(n, d) => Rational::new_raw(Int::from(*n), Int::from(*d)),
            Coeff::Big(q) => q.clone(),
        }
    }
    /// The numerator (lowest terms, carrying the sign).
    pub fn numer(&self) -> BigInt {
        match self {
            Coeff::Small(n, _) => BigInt::from(*n),
            Coeff::Big(q) => q.numer().0.clone(),
        }
    }
    /// The denominator (lowest terms, positive).
    pub fn denom(&self) -> BigInt {
        match self {
            Coeff::Small(_, d) => BigInt::from(*d),
            Coeff::Big(q) => q.denom().0.clone(),
        }
    }
    /// True for an integer.
    pub fn is_integer(&self) -> bool {
        match self {
            Coeff::Small(_, d) => *d == 1,
            Coeff::Big(q) => q.is_integer(),
        }
    }
    /// True below zero.
    pub fn is_negative(&self) -> bool {
        match self {
            Coeff::Small(n, _) => *n < 0,
            Coeff::Big(q) => q.numer().sign() == num_bigint::Sign::Minus,
        }
    }
    /// |self|.
    pub fn abs(&self) -> Coeff {
        if self.is_negative() {
            -self
        } else {
            self.clone()
        }
    }
    /// The nearest float.
    pub fn to_f64(&self) -> f64 {
        self.to_big().to_f64().unwrap_or(f64::NAN)
    }
}

impl From<Rational> for Coeff {
    fn from(q: Rational) -> Coeff {
        Coeff::from_big(q)
    }
}

impl From<&Rational> for Coeff {
    fn from(q: &Rational) -> Coeff {
        Coeff::from_big(q.clone())
    }
}

impl From<i64> for Coeff {
    fn from(n: i64) -> Coeff {
        Coeff::int(n)
    }
}

impl std::fmt::Debug for Coeff {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Coeff::Small(n, 1) => write!(f, "{n}"),
            Coeff::Small(n, d) => write!(f, "{n}/{d}"),
            Coeff::Big(q) => write!(f, "{q}"),
        }
    }
}

impl Ord for Coeff {
    fn cmp(&self, o: &Coeff) -> Ordering {
        match (self, o) {
            (Coeff::Small(a, b), Coeff::Small(c, d)) => {
                (i128::from(*a) * i128::from(*d)).cmp(&(i128::from(*c) * i128::from(*b)))
            }
            _ => self.to_big().cmp(&o.to_big()),
        }
    }
}

impl PartialOrd for Coeff {
    fn partial_cmp(&self, o: &Coeff) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl Add for &Coeff {
    type Output = Coeff;
    fn add(self, o: &Coeff) -> Coeff {
        match (self, o) {
            (Coeff::Small(a, 1), Coeff::Small(c, 1)) => {
                Coeff::from_i128(i128::from(*a) + i128::from(*c), 1)
            }
            (Coeff::Small(a, b), Coeff::Small(c, d)) if b == d => {
                Coeff::from_i128(i128::from(*a) + i128::from(*c), i128::from(*b))
            }
            (Coeff::Small(a, b), Coeff::Small(c, d)) => {
                let (a, b, c, d) = (
                    i128::from(*a),
                    i128::from(*b),
                    i128::from(*c),
                    i128::from(*d),
                );
                Coeff::from_i128(a * d + c * b, b * d)
            }
            _ => Coeff::from_big(self.to_big() + o.to_big()),
        }
    }
}

impl Neg for &Coeff {
    type Output = Coeff;
    fn neg(self) -> Coeff {
        match self {
            // |n| < 2⁶³, so −n cannot overflow, and the result is still canonical.
            Coeff::Small(n, d) => Coeff::Small(-n, *d),
            Coeff::Big(q) => Coeff::Big(-q),
        }
    }
}

impl Sub for &Coeff {
    type Output = Coeff;
    fn sub(self, o: &Coeff) -> Coeff {
        self + &-o
    }
}

impl Mul for &Coeff {
    type Output = Coeff;
    fn mul(self, o: &Coeff) -> Coeff {
        match (self, o) {
            (Coeff::Small(a, b), Coeff::Small(c, d)) => Coeff::from_i128(
                i128::from(*a) * i128::from(*c),
                i128::from(*b) * i128::from(*d),
            ),
            _ => Coeff::from_big(self.to_big() * o.to_big()),
        }
    }
}

impl Div for &Coeff {
    type Output = Coeff;
    fn div(self, o: &Coeff) -> Coeff {
        match (self, o) {
            (Coeff::Small(a, b), Coeff::Small(c, d)) => Coeff::from_i128(
                i128::from(*a) * i128::from(*d),
                i128::from(*b) * i128::from(*c),
            ),
            _ => {
                assert!(!o.is_zero(), "coefficient divided by zero");
                Coeff::from_big(self.to_big() / o.to_big())
            }
        }
    }
}

macro_rules! by_value {
    ($($tr:ident $f:ident),*) => {$(
        impl $tr for Coeff {
            type Output = Coeff;
            fn $f(self, o: Coeff) -> Coeff {
                (&self).$f(&o)
            }
        }
        impl $tr<&Coeff> for Coeff {
            type Output = Coeff;
            fn $f(self, o: &Coeff) -> Coeff {
                (&self).$f(o)
            }
        }
    )*};
}
by_value!(Add add, Sub sub, Mul mul, Div div);

impl Neg for Coeff {
    type Output = Coeff;
    fn neg(self) -> Coeff {
        -&self
    }
}

impl AddAssign for Coeff {
    fn add_assign(&mut self, o: Coeff) {
        *self = &*self + &o;
    }
}

impl SubAssign for Coeff {
    fn sub_assign(&mut self, o: Coeff) {
        *self = &*self - &o;
    }
}

impl Zero for Coeff {
    fn zero() -> Coeff {
        Coeff::Small(0, 1)
    }
    fn is_zero(&self) -> bool {
        matches!(self, Coeff::Small(0, _))
    }
}

impl One for Coeff {
    fn one() -> Coeff {
        Coeff::Small(1, 1)
    }
    fn is_one(&self) -> bool {
        matches!(self, Coeff::Small(1, 1))
    }
}
