//! `Modp`: exact arithmetic modulo the Mersenne prime p = 2⁶¹ − 1, the fast path of the exact
//! checks.
//!
//! Why: every operation on an exact [`super::Rational`] reduces its fraction by a gcd of numbers
//! that reach a thousand bits (most of an exact check's time, even with the Lehmer gcd of
//! [`super::gcd`]). Evaluating the same generic code modulo p costs a few machine multiplications
//! per operation.
//!
//! What a modular point proves. Evaluating at integers x and reducing modulo p is a ring
//! homomorphism from the rationals whose denominators p does not divide, so a residual that is
//! zero in the rationals is zero modulo p, and a residual that is nonzero modulo p is nonzero in
//! the rationals: a *failure* mod p is a certain failure. A *pass* mod p is probabilistic: if the
//! residual is a nonzero rational function N/D (N, D integer polynomials, N of total degree ≤ d),
//! and p does not divide every coefficient of N, then N mod p is a nonzero polynomial over the
//! field F_p and, by the Schwartz-Zippel lemma over F_p, vanishes at a point whose coordinates are
//! drawn independently and uniformly from sets of at least S distinct residues with probability at
//! most d/S. The sample sets of [`crate::registry::check`] lie in an interval shorter than p, so
//! their residues are distinct. The one case this leaves, p dividing every coefficient of N, is
//! why each check also evaluates its first point in exact rationals (a bound that holds for any
//! p).
//!
//! A division by zero mod p (a denominator that is a multiple of p at the point, or a true zero)
//! gives [`Modp::UNDEFINED`], which every later operation keeps; the checks then evaluate that
//! point in rationals instead. Hand-written: the arithmetic is a dozen lines, and no well-kept
//! crate offers a field element that implements this crate's [`Scalar`] (with its `Jet` dual).

use super::{Jet, Scalar};
use num_traits::Zero;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// The modulus, the Mersenne prime 2⁶¹ − 1.
pub const MODULUS: u64 = (1 << 61) - 1;

/// A residue modulo [`MODULUS`], or undefined after a division by zero.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Modp(u64);

impl Modp {
    /// The value of a division by zero (and of anything computed from it).
    pub const UNDEFINED: Modp = Modp(u64::MAX);

    /// The residue of an integer.
    pub fn of(n: i64) -> Self {
        Modp(i128::from(n).rem_euclid(i128::from(MODULUS)) as u64)
    }

    /// The residue of an exact rational n/d: n · d⁻¹ mod p (undefined when p divides d).
    pub fn of_rational(q: &super::Rational) -> Self {
        let p = num_bigint::BigInt::from(MODULUS);
        let r = |b: &num_bigint::BigInt| {
            let v = num_integer::Integer::mod_floor(b, &p);
            Modp(num_traits::ToPrimitive::to_u64(&v).unwrap_or(u64::MAX))
        };
        r(q.numer()) / r(q.denom())
    }

    /// False after a division by zero.
    pub fn is_defined(self) -> bool {
        self.0 < MODULUS
    }

    /// The residue in [0, p), `None` when undefined.
    pub fn residue(self) -> Option<u64> {
        self.is_defined().then_some(self.0)
    }

    fn either_undefined(self, o: Self) -> bool {
        !(self.is_defined() && o.is_defined())
    }

    /// a^e by squaring.
    pub fn pow(self, mut e: u64) -> Self {
        let (mut base, mut acc) = (self, Modp(1));
        while e > 0 {
            if e & 1 == 1 {
                acc = acc * base;
            }
            base = base * base;
            e >>= 1;
        }
        acc
    }
}

impl Add for Modp {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        if self.either_undefined(o) {
            return Modp::UNDEFINED;
        }
        let s = self.0 + o.0;
        Modp(if s >= MODULUS { s - MODULUS } else { s })
    }
}

impl Sub for Modp {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        self + (-o)
    }
}

impl Neg for Modp {
    type Output = Self;
    fn neg(self) -> Self {
        match self.0 {
            0 => self,
            v if v < MODULUS => Modp(MODULUS - v),
            _ => Modp::UNDEFINED,
        }
    }
}

impl Mul for Modp {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        if self.either_undefined(o) {
            return Modp::UNDEFINED;
        }
        // x < p² < 2¹²²; x ≡ (x mod 2⁶¹) + (x div 2⁶¹) since 2⁶¹ ≡ 1, and that sum is < 2p.
        let x = u128::from(self.0) * u128::from(o.0);
        let s = (x as u64 & MODULUS) + (x >> 61) as u64;
        Modp(if s >= MODULUS { s - MODULUS } else { s })
    }
}

impl Div for Modp {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        if self.either_undefined(o) || o.0 == 0 {
            return Modp::UNDEFINED;
        }
        // Fermat: o^(p−2) is the inverse of o ≠ 0 in the field F_p.
        self * o.pow(MODULUS - 2)
    }
}

impl Zero for Modp {
    fn zero() -> Self {
        Modp(0)
    }
    fn is_zero(&self) -> bool {
        self.0 == 0
    }
}

impl Scalar for Modp {
    type Dual = Jet<Modp>;
    fn int(n: i64) -> Self {
        Modp::of(n)
    }
    fn lift(re: Self, eps: Self) -> Jet<Modp> {
        Jet::new(re, eps)
    }
    fn split(d: Jet<Modp>) -> (Self, Self) {
        (d.re, d.eps)
    }
    /// A residue has no real value.
    fn to_f64(&self) -> f64 {
        f64::NAN
    }
}
