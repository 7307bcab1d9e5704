//! The number types every equation is evaluated in.
//!
//! One generic code path serves all of them: each equation of the note is written once as a
//! function over `S: Scalar` and then evaluated
//!
//! * in `f64` (the everyday check at random states; time derivatives by [`num_dual::Dual64`]),
//! * in [`Bound`], a running error bound (Higham, *Accuracy and Stability of Numerical
//!   Algorithms*, sec. 3.3) that gives every float check its tolerance,
//! * in [`Rational`] (exact, zero residual) with time derivatives by [`Jet`], a first-order dual
//!   number over any scalar,
//! * in [`Modp`], exact residues modulo the prime 2⁶¹ − 1 (the fast path of the exact checks),
//! * in [`Degree`], which carries no value at all but the degree of the rational function being
//!   built, so the Schwartz-Zippel bound of every exact check is computed, not guessed, and
//! * in [`Sym`], exact rational functions of the variables themselves (normal form modulo
//!   s² + c² = 1, see [`poly`]), so an identity is proved rather than sampled, and
//! * in [`Dim`], which carries the physical dimension of each value (dimensional analysis: a sum
//!   of unlike dimensions is recorded as an inconsistency).
//!
//! No equation ever takes sin or cos: the ladder state carries sin θ and cos θ, which is what
//! makes exact evaluation possible.
//!
//! `Jet` is written by hand because num-dual requires float parts (its `DualNum` is bounded by
//! `Float`-like traits), and exact rationals, error bounds and degrees are not floats.

pub mod bound;
pub mod coeff;
pub mod degree;
pub mod dimension;
pub mod gcd;
pub mod int;
pub mod jet;
pub mod modp;
pub mod poly;
mod si_unit;
pub mod sym_factor;
pub mod sym_print;
pub mod sym_reading;
pub mod symbolic;

pub use bound::{Bound, UNIT_ROUNDOFF};
pub use coeff::Coeff;
pub use degree::Degree;
pub use dimension::{Clash, Dim, Dimension, Exponent, Inconsistency};
pub use int::{rational_from_float, Int};
pub use jet::Jet;
pub use modp::{Modp, MODULUS};
pub use sym_factor::{factored_latex, factored_text, Factored};
pub use sym_print::{latex, text};
pub use sym_reading::{reading, Reading};
pub use symbolic::{Den, Sym};

use num_dual::{Dual, DualNum};
use num_rational::Ratio;
use std::fmt::Debug;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Exact rational numbers (arbitrary precision; [`Int`] parts, for their faster gcd).
pub type Rational = Ratio<Int>;

/// A field-like number type that the note's equations can be evaluated in.
///
/// `Dual` is the first-order dual number over `Self`; lifting a state "along the motion" turns
/// every quantity `q` into `q + q̇ ε`, and [`Scalar::split`] reads `q̇` back.
pub trait Scalar:
    Clone
    + Debug
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The first-order dual numbers over this type.
    type Dual: Scalar;
    /// The integer `n` in this type.
    fn int(n: i64) -> Self;
    /// The fraction `n/d`, exact where the type allows.
    fn ratio(n: i64, d: i64) -> Self {
        Self::int(n) / Self::int(d)
    }
    /// `re + eps ε`.
    fn lift(re: Self, eps: Self) -> Self::Dual;
    /// `(re, eps)` of a dual number.
    fn split(d: Self::Dual) -> (Self, Self);
    /// A constant (zero derivative) dual number.
    fn constant(re: Self) -> Self::Dual {
        Self::lift(re, Self::int(0))
    }
    /// The float nearest to this value (`NaN` for types without a value, like [`Degree`]).
    fn to_f64(&self) -> f64;
}

/// `a²`, written once so the equations read like the note.
pub fn sq<S: Scalar>(a: &S) -> S {
    a.clone() * a.clone()
}

impl Scalar for f64 {
    type Dual = Dual<f64>;
    fn int(n: i64) -> Self {
        n as f64
    }
    fn lift(re: Self, eps: Self) -> Dual<f64> {
        Dual::new(re, eps)
    }
    fn split(d: Dual<f64>) -> (Self, Self) {
        (d.re, d.eps)
    }
    fn to_f64(&self) -> f64 {
        *self
    }
}

/// num-dual's dual numbers over f64 (and over its own duals, for nested derivatives).
impl<T> Scalar for Dual<T>
where
    T: DualNum<Primitive = f64> + Scalar,
{
    type Dual = Dual<Dual<T>>;
    fn int(n: i64) -> Self {
        Dual::from_re(T::int(n))
    }
    fn ratio(n: i64, d: i64) -> Self {
        Dual::from_re(T::ratio(n, d))
    }
    fn lift(re: Self, eps: Self) -> Dual<Dual<T>> {
        Dual::new(re, eps)
    }
    fn split(d: Dual<Dual<T>>) -> (Self, Self) {
        (d.re, d.eps)
    }
    fn to_f64(&self) -> f64 {
        self.re.to_f64()
    }
}

impl Scalar for Rational {
    type Dual = Jet<Rational>;
    fn int(n: i64) -> Self {
        Rational::from_integer(Int::from(n))
    }
    fn ratio(n: i64, d: i64) -> Self {
        Rational::new(Int::from(n), Int::from(d))
    }
    fn lift(re: Self, eps: Self) -> Jet<Rational> {
        Jet::new(re, eps)
    }
    fn split(d: Jet<Rational>) -> (Self, Self) {
        (d.re, d.eps)
    }
    fn to_f64(&self) -> f64 {
        num_traits::ToPrimitive::to_f64(self).unwrap_or(f64::NAN)
    }
}
