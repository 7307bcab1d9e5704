//! `Degree`: the degree of a rational function, carried through an evaluation instead of a value.
//!
//! An exact check evaluates both sides of an identity at a random point whose coordinates are
//! integers drawn from a set of size N. If the identity were false, the residual would be a
//! nonzero rational function `p/q`; by the Schwartz-Zippel lemma `p` vanishes at the random point
//! with probability at most `deg p / N`. Evaluating the same generic code in `Degree` bounds
//! `deg p` (total degree in all the random coordinates) with the rules
//!
//! | operation          | numerator degree          | denominator degree |
//! |--------------------|---------------------------|--------------------|
//! | a ± b              | max(n_a + d_b, n_b + d_a) | d_a + d_b          |
//! | a · b              | n_a + n_b                 | d_a + d_b          |
//! | a / b              | n_a + d_b                 | d_a + n_b          |
//!
//! which never underestimate (no cancellation is assumed). Hand-written: no crate tracks this.

use super::{Jet, Scalar};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Upper bounds on the degrees of the numerator and denominator of a rational function.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Degree {
    /// Degree bound of the numerator.
    pub num: u32,
    /// Degree bound of the denominator.
    pub den: u32,
}

impl Degree {
    /// One of the random coordinates: a polynomial of degree one.
    pub fn variable() -> Self {
        Degree { num: 1, den: 0 }
    }
}

impl Add for Degree {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Degree {
            num: (self.num + o.den).max(o.num + self.den),
            den: self.den + o.den,
        }
    }
}

impl Sub for Degree {
    type Output = Self;
    // A difference has the same degree bound as a sum.
    #[allow(clippy::suspicious_arithmetic_impl)]
    fn sub(self, o: Self) -> Self {
        self + o
    }
}

impl Mul for Degree {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Degree {
            num: self.num + o.num,
            den: self.den + o.den,
        }
    }
}

impl Div for Degree {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        Degree {
            num: self.num + o.den,
            den: self.den + o.num,
        }
    }
}

impl Neg for Degree {
    type Output = Self;
    fn neg(self) -> Self {
        self
    }
}

impl Scalar for Degree {
    type Dual = Jet<Degree>;
    fn int(_: i64) -> Self {
        Degree { num: 0, den: 0 }
    }
    fn lift(re: Self, eps: Self) -> Jet<Degree> {
        Jet::new(re, eps)
    }
    fn split(d: Jet<Degree>) -> (Self, Self) {
        (d.re, d.eps)
    }
    fn to_f64(&self) -> f64 {
        f64::NAN
    }
}
