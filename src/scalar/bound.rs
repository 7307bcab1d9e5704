//! `Bound`: a float that carries a running bound on its own rounding error.
//!
//! Every arithmetic operation adds the rounding error it commits, `|result|·u`, to the error it
//! inherits from its operands (Higham, *Accuracy and Stability of Numerical Algorithms*, 2nd ed.,
//! sec. 3.3, "running error analysis"); `e` is kept in units of the unit roundoff u = 2⁻⁵³:
//!
//! | operation | bound on the error, in units of u           |
//! |-----------|---------------------------------------------|
//! | a ± b     | e_a + e_b + \|a ± b\|                        |
//! | a · b     | \|b\| e_a + \|a\| e_b + u e_a e_b + \|a b\|     |
//! | a / b     | (e_a + \|a/b\| e_b)/\|b\| + \|a/b\|           |
//!
//! These are first-order bounds (terms in u² are dropped, except in the product, where an operand that is exactly zero would otherwise hide its own error). Evaluating both sides of an identity
//! in `Bound` gives the size of the terms that cancel, which is what a float check's tolerance
//! must be made of. A hand-written type because no crate offers running error bounds over a
//! user-supplied expression.

use super::{Jet, Scalar};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// The unit roundoff of IEEE double precision, 2⁻⁵³.
pub const UNIT_ROUNDOFF: f64 = f64::EPSILON / 2.0;

/// A float value `v` with a bound `e·u` on the absolute error committed in computing it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bound {
    /// The computed value (the same as a plain f64 computation would give).
    pub v: f64,
    /// Bound on `|v - exact|`, in units of the unit roundoff.
    pub e: f64,
}

impl Bound {
    /// An input known exactly (error zero).
    pub fn exact(v: f64) -> Self {
        Bound { v, e: 0.0 }
    }
    /// An input already in error by at most `units` roundoffs relative to its size (for example
    /// a correctly rounded `sin θ` has `units = 1`; a libm result within one ulp has `units = 2`).
    pub fn inexact(v: f64, units: f64) -> Self {
        Bound {
            v,
            e: units * v.abs(),
        }
    }
    /// The absolute error bound, `e·u`.
    pub fn abs_error(&self) -> f64 {
        self.e * UNIT_ROUNDOFF
    }
}

impl Add for Bound {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        let v = self.v + o.v;
        Bound {
            v,
            e: self.e + o.e + v.abs(),
        }
    }
}

impl Sub for Bound {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        let v = self.v - o.v;
        Bound {
            v,
            e: self.e + o.e + v.abs(),
        }
    }
}

impl Mul for Bound {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        let v = self.v * o.v;
        Bound {
            v,
            e: o.v.abs() * self.e + self.v.abs() * o.e + v.abs(),
        }
    }
}

impl Div for Bound {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        let v = self.v / o.v;
        Bound {
            v,
            e: (self.e + v.abs() * o.e) / o.v.abs() + v.abs(),
        }
    }
}

impl Neg for Bound {
    type Output = Self;
    fn neg(self) -> Self {
        Bound {
            v: -self.v,
            e: self.e,
        }
    }
}

impl Scalar for Bound {
    type Dual = Jet<Bound>;
    fn int(n: i64) -> Self {
        let v = n as f64;
        // Integers up to 2⁵³ are exact in f64.
        let e = if n.unsigned_abs() <= 1 << 53 {
            0.0
        } else {
            v.abs()
        };
        Bound { v, e }
    }
    fn ratio(n: i64, d: i64) -> Self {
        Bound::int(n) / Bound::int(d)
    }
    fn lift(re: Self, eps: Self) -> Jet<Bound> {
        Jet::new(re, eps)
    }
    fn split(d: Jet<Bound>) -> (Self, Self) {
        (d.re, d.eps)
    }
    fn to_f64(&self) -> f64 {
        self.v
    }
}
