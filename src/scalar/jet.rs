//! `Jet<T>`: first-order dual numbers `re + eps ε` (ε² = 0) over any [`Scalar`].
//!
//! The operations follow num-dual's `Dual` step by step (same formulas, same order), so that a
//! `Jet<Bound>` evaluation is a running error bound of exactly the float operations a
//! `num_dual::Dual64` evaluation performs.
//!
//! Used for exact time derivatives (`Jet<Rational>`), for the error bound of a derivative
//! (`Jet<Bound>`), for the degree of a derivative (`Jet<Degree>`) and nested (`Jet<Jet<T>>`) for
//! second derivatives and Lagrange's equation.

use super::Scalar;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A first-order dual number over `T`.
#[derive(Clone, Debug, PartialEq)]
pub struct Jet<T> {
    /// The value.
    pub re: T,
    /// The derivative.
    pub eps: T,
}

impl<T> Jet<T> {
    /// `re + eps ε`.
    pub fn new(re: T, eps: T) -> Self {
        Jet { re, eps }
    }
}

impl<T: Scalar> Add for Jet<T> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Jet::new(self.re + o.re, self.eps + o.eps)
    }
}

impl<T: Scalar> Sub for Jet<T> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Jet::new(self.re - o.re, self.eps - o.eps)
    }
}

impl<T: Scalar> Mul for Jet<T> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        // (a + a'ε)(b + b'ε) = ab + (a' b + b' a) ε, in num-dual's operation order
        let eps = self.eps * o.re.clone() + o.eps * self.re.clone();
        Jet::new(self.re * o.re, eps)
    }
}

impl<T: Scalar> Div for Jet<T> {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        // (a + a'ε)/(b + b'ε) = a/b + (a' b − b' a)/b² ε, in num-dual's operation order
        // (through 1/b), so that a `Jet<Bound>` bounds exactly what `Dual64` computes.
        let inv = T::int(1) / o.re.clone();
        let re = self.re.clone() * inv.clone();
        let eps = (self.eps * o.re.clone() - o.eps * self.re) * inv.clone() * inv;
        Jet::new(re, eps)
    }
}

impl<T: Scalar> Neg for Jet<T> {
    type Output = Self;
    fn neg(self) -> Self {
        Jet::new(-self.re, -self.eps)
    }
}

impl<T: Scalar> Scalar for Jet<T> {
    type Dual = Jet<Jet<T>>;
    fn int(n: i64) -> Self {
        Jet::new(T::int(n), T::int(0))
    }
    fn ratio(n: i64, d: i64) -> Self {
        Jet::new(T::ratio(n, d), T::int(0))
    }
    fn lift(re: Self, eps: Self) -> Jet<Jet<T>> {
        Jet::new(re, eps)
    }
    fn split(d: Jet<Jet<T>>) -> (Self, Self) {
        (d.re, d.eps)
    }
    fn to_f64(&self) -> f64 {
        self.re.to_f64()
    }
}
